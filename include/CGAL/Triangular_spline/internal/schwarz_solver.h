// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/release.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// How a convex quadratic fit is minimised. Up to `direct_limit` unknowns: one sparse
// Cholesky factorization of the whole system. Beyond: multiplicative overlapping Schwarz
// (block Gauss-Seidel over windows): the domain's vertices are bucketed into grid cells of
// about `window_vertices` vertices; a window is a cell and `margin_rings` rings of
// vertices around it, its unknowns those owned by its vertices, and each window's
// quadratic is minimised exactly (sparse Cholesky) with every other unknown at its
// current value. Each window solve can only lower the objective, and the sweeps converge
// to the global minimiser.
//
// Windows are coloured: two windows have different colours when one solves for an unknown
// that the other's faces read (greedy colouring in cell order). A sweep solves each window
// after the windows of lower colours it conflicts with and before those of higher colours,
// as soon as those before it are done, on all cores: windows that conflict with none
// running run together, in any order, with the same result. Each window is factorized
// again (no factorization is kept: memory is one window's per core). Windows that couple
// beyond their neighbours are common: a vertex with a fan of slivers (a corner of the
// data's square, a hull vertex) couples windows along a whole side (the 196 windows of
// 10^5 random points of the unit square with its corners take 50 colours, 44 of them a
// window each: those along the sides). Margins cut off at a distance from their cell, so
// that such fans do not carry them along a side, left strongly coupled unknowns in
// different windows: 0.76 from the direct solve after 4 sweeps at 700 points. Sweeps
// pipelined so as to reuse each window's factorization (pass p of a window as soon as its
// neighbouring cells had pass p - 1) see such couplings about a column of cells per pass
// late: at 10^5 noisy points the control values stayed 6.8e-5 from the direct solve after
// 4 to 6 passes (sequential sweeps: 1.8e-3, 5.4e-8, 6.7e-10 after one, two and three).
//
// `sweeps` > 0: exactly that many. 0: until a sweep changes no unknown by more than
// `tolerance` times the data range (the `scale` of schwarz_minimise()), at most
// `max_sweeps`. A sweep after the first solves only the windows whose unknowns or
// surrounding unknowns moved by more than that since their last solve: the others would
// reproduce their values.
//
// `margin_rings` < 0 leaves the margin to the fit (schwarz_margin_rings()): a wider margin
// needs fewer sweeps but costs more per window. Measured at 10^5 random points, smooth /
// noisy data (fit stage, CPU s): energy with 3, 2, 1 rings 24.7 / 39.2, 23.2 / 36.0,
// 21.9 / 47.6. Smoothing keeps three.
//
// The least-squares fit uses no windows beyond `direct_limit`: conjugate gradients
// (least_squares_conjugate_gradients()), until the residual, a bound on the error, is
// within `tolerance` times the data range, at most `max_iterations` iterations. (Its
// windows, with one ring, took 6.7 / 11.3 CPU s at 10^5 points.)
struct Schwarz_options {
  std::size_t direct_limit = 40000;
  std::size_t window_vertices = 500;
  int margin_rings = -1;
  int sweeps = 0;
  double tolerance = 1e-8;
  int max_sweeps = 8;
  int max_iterations = 1000;
  std::size_t threads = 0; // 0: one per core (the result does not depend on it)
  // Not the solver's: the rings around the Adaptive fit's untrusted vertices that its energy
  // region takes in (< 0: adaptive_energy_margin_rings, fit_vertex_data.h; tests compare).
  int adaptive_margin_rings = -1;
  // Nor this: the vertices whose local polynomials the local and Adaptive fits hold at once
  // (0: local_polynomial_block, fit_vertex_data.h; tests take a few to cross blocks).
  std::size_t local_block = 0;
};

// The margin of the fits' windows when Schwarz_options::margin_rings < 0.
constexpr int energy_margin_rings = 2;
// Smoothing converges more slowly with fewer rings (500 noisy points, 4 sweeps: 1.8e-4 from
// the direct solve with two, below 1e-7 with three).
constexpr int smoothing_margin_rings = 3;

// `options` with its margin set to `fit_margin` unless the caller chose one.
inline Schwarz_options schwarz_margin_rings(Schwarz_options options, int fit_margin) {
  if (options.margin_rings < 0)
    options.margin_rings = fit_margin;
  return options;
}

// The number of window solves that run at once (and of face_terms' scratch spaces).
inline std::size_t schwarz_workers(const Schwarz_options& options) {
  return options.threads > 0 ? options.threads
                             : std::size_t((std::max)(1u, std::thread::hardware_concurrency()));
}

// What the solver did (Fit_statistics, tests and benchmarks).
struct Schwarz_statistics {
  enum Method { NONE, DIRECT, WINDOWS, CONJUGATE_GRADIENTS };
  Method method = NONE;
  std::size_t windows = 0;       // windows per sweep; 0 for the direct solve
  std::size_t colours = 0;       // colours of the windows (0 for the direct solve)
  int sweeps = 0;                // sweeps done (1 for the direct solve and conjugate gradients)
  int iterations = 0;            // conjugate gradients' iterations (the most of a coordinate)
  std::size_t window_solves = 0; // windows factorized and solved, over all sweeps
  double last_change = 0;        // largest change of an unknown in the last sweep (conjugate
                                 // gradients: the residual's norm, which bounds the error)
  double scale = 0;              // the unit of `tolerance` (the data range)
  bool converged = true;         // false: stopped by max_sweeps
};

// A face's quadratic term in the unknowns it depends on: its gradient is H x - B over the
// sorted unknowns `columns` (H symmetric; only its lower triangle is read).
struct Face_terms {
  std::vector<int> columns;
  Eigen::MatrixXd H, B;
};

// Minimises sum over faces of quadratic terms in the unknowns x (unknowns x D, updated in
// place from its initial values).
//   owner[j]: the domain vertex owning unknown j (it decides the windows j belongs to);
//   unknowns_of(f, out): appends the unknowns that face f's terms depend on;
//   face_terms(f, terms, worker): face f's terms (Face_terms); worker < schwarz_workers()
//     names the scratch space of the calling thread. A window's system takes them with the
//     unknowns beyond it at their values in x.
// `vertices`: the number of domain vertices, `neighbours(v, out)` their adjacency and
// `position(v)` their coordinates (std::array<double, 2>), for the windows; `scale` the
// unit of options.tolerance. A negative options.margin_rings means energy_margin_rings.
template <class Unknowns_of, class Compute_face_terms, class Neighbours, class Position>
Schwarz_statistics
schwarz_minimise(std::size_t vertices, const std::vector<std::uint32_t>& owner, std::size_t faces,
                 const Unknowns_of& unknowns_of, const Compute_face_terms& face_terms,
                 const Neighbours& neighbours, const Position& position, Eigen::MatrixXd& x,
                 const Schwarz_options& chosen, double scale, const char* what) {
  const Schwarz_options options = schwarz_margin_rings(chosen, energy_margin_rings);
  const std::size_t n = owner.size();
  Schwarz_statistics statistics;
  statistics.scale = scale;
  if (n == 0)
    return statistics;
  const Eigen::Index D = x.cols();
  // vertex -> the unknowns it owns (CSR)
  std::vector<std::size_t> unknown_start(vertices + 1, 0);
  for (std::uint32_t v : owner)
    ++unknown_start[v + 1];
  for (std::size_t v = 0; v < vertices; ++v)
    unknown_start[v + 1] += unknown_start[v];
  std::vector<std::uint32_t> owned(n);
  {
    std::vector<std::size_t> next(unknown_start.begin(), unknown_start.end() - 1);
    for (std::size_t j = 0; j < n; ++j)
      owned[next[owner[j]]++] = std::uint32_t(j);
  }
  // Buffers kept from window to window, one set per worker (each of a window's size: a
  // worker per core on a large machine must not cost an array of all unknowns).
  struct Worker {
    std::vector<std::uint32_t> unknowns;
    std::vector<std::pair<std::uint32_t, int>> sorted; // (unknown, local index), increasing
    std::vector<int> columns; // the local indices of a face's columns, -1 beyond the window
    std::vector<Eigen::Triplet<double>> triplets;
    Face_terms terms;
    Eigen::SparseMatrix<double> matrix;
    // The upper triangle, ordered by approximate minimum degree. (Ordering the graph of the
    // vertices instead, each vertex's unknowns together, was slower:
    // 10^5 random points, 86 against 64 ms per window of the energy fit.)
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> factor;
    Eigen::MatrixXd rhs, y;
    double change = 0;
    std::size_t solves = 0;
  };
  const std::size_t workers = schwarz_workers(options);
  std::vector<Worker> worker(workers);
  std::vector<std::uint32_t> involved;
  // Minimises over the unknowns owned by `window_vertices` (faces `window_faces`: those
  // whose terms involve them), the others at their values in x; returns the largest change
  // of an unknown, calling moved(j) after unknown j is written. Writes only the unknowns it
  // solves for (and what moved(j) keeps for them). The local unknowns are numbered in the
  // order of the window's vertices.
  auto solve = [&](std::size_t w, const std::uint32_t* window_vertices, std::size_t vertex_count,
                   const std::uint32_t* window_faces, std::size_t face_count, const auto& moved) {
    Worker& k = worker[w];
    auto& unknowns = k.unknowns;
    unknowns.clear();
    k.sorted.clear();
    for (std::size_t i = 0; i < vertex_count; ++i) {
      const std::uint32_t v = window_vertices[i];
      for (std::size_t u = unknown_start[v]; u < unknown_start[v + 1]; ++u) {
        k.sorted.emplace_back(owned[u], int(unknowns.size()));
        unknowns.push_back(owned[u]);
      }
    }
    std::sort(k.sorted.begin(), k.sorted.end());
    auto local_index = [&](int j) {
      const auto at = std::lower_bound(k.sorted.begin(), k.sorted.end(),
                                       std::pair<std::uint32_t, int>(std::uint32_t(j), -1));
      return at != k.sorted.end() && at->first == std::uint32_t(j) ? at->second : -1;
    };
    const Eigen::Index size = Eigen::Index(unknowns.size());
    k.rhs.setZero(size, D);
    k.triplets.clear();
    for (std::size_t i = 0; i < face_count; ++i) {
      face_terms(window_faces[i], k.terms, w);
      const auto& columns = k.terms.columns;
      const Eigen::Index m = Eigen::Index(columns.size());
      k.columns.resize(columns.size());
      for (std::size_t a = 0; a < columns.size(); ++a)
        k.columns[a] = local_index(columns[a]);
      for (Eigen::Index a = 0; a < m; ++a) {
        const int la = k.columns[std::size_t(a)];
        if (la < 0)
          continue;
        k.rhs.row(la) += k.terms.B.row(a);
        for (Eigen::Index b = 0; b < m; ++b) {
          const double h = b <= a ? k.terms.H(a, b) : k.terms.H(b, a);
          if (h == 0)
            continue;
          const int lb = k.columns[std::size_t(b)];
          if (lb < 0) // beyond the window: at its current value
            k.rhs.row(la) -= h * x.row(Eigen::Index(columns[std::size_t(b)]));
          else if (la <= lb)
            k.triplets.emplace_back(la, lb, h);
        }
      }
    }
    k.matrix.resize(size, size);
    k.matrix.setFromTriplets(k.triplets.begin(), k.triplets.end());
    k.factor.compute(k.matrix);
    if (k.factor.info() != Eigen::Success)
      throw Invalid_input(std::string("fit: the ") + what + " system could not be factorized");
    k.y = k.factor.solve(k.rhs);
    double change = 0;
    for (Eigen::Index i = 0; i < size; ++i) {
      const auto j = std::size_t(unknowns[std::size_t(i)]);
      for (Eigen::Index d = 0; d < D; ++d) {
        if (!std::isfinite(k.y(i, d)))
          throw Invalid_input(std::string("fit: the ") + what + " system is singular");
        change = (std::max)(change, std::abs(k.y(i, d) - x(Eigen::Index(j), d)));
        x(Eigen::Index(j), d) = k.y(i, d);
      }
      moved(j);
    }
    return change;
  };
  if (n <= options.direct_limit) {
    std::vector<std::uint32_t> all_vertices(vertices), all_faces(faces);
    for (std::size_t v = 0; v < vertices; ++v)
      all_vertices[v] = std::uint32_t(v);
    for (std::size_t f = 0; f < faces; ++f)
      all_faces[f] = std::uint32_t(f);
    statistics.last_change = solve(0, all_vertices.data(), all_vertices.size(), all_faces.data(),
                                   all_faces.size(), [](std::size_t) {});
    statistics.method = Schwarz_statistics::DIRECT;
    statistics.sweeps = 1;
    statistics.window_solves = 1;
    return statistics;
  }
  // vertex -> faces whose terms involve the unknowns it owns (CSR)
  std::vector<std::size_t> face_start(vertices + 1, 0);
  std::vector<std::uint32_t> owners;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_face;
  for (std::size_t f = 0; f < faces; ++f) {
    involved.clear();
    unknowns_of(std::uint32_t(f), involved);
    owners.clear();
    for (std::uint32_t j : involved)
      owners.push_back(owner[j]);
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    for (std::uint32_t v : owners)
      vertex_face.emplace_back(v, std::uint32_t(f));
  }
  std::sort(vertex_face.begin(), vertex_face.end());
  std::vector<std::uint32_t> vertex_faces(vertex_face.size());
  for (std::size_t i = 0; i < vertex_face.size(); ++i) {
    ++face_start[vertex_face[i].first + 1];
    vertex_faces[i] = vertex_face[i].second;
  }
  vertex_face.clear();
  vertex_face.shrink_to_fit();
  for (std::size_t v = 0; v < vertices; ++v)
    face_start[v + 1] += face_start[v];
  // Grid cells of about window_vertices vertices over the bounding box.
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto p = position(std::uint32_t(v));
    for (int c = 0; c < 2; ++c) {
      lo[c] = (std::min)(lo[c], p[std::size_t(c)]);
      hi[c] = (std::max)(hi[c], p[std::size_t(c)]);
    }
  }
  const double cells_wanted = (std::max)(
      1.0, double(vertices) / double((std::max)(options.window_vertices, std::size_t(1))));
  const double aspect =
      (hi[0] - lo[0]) / (std::max)(hi[1] - lo[1], 1e-300 * (hi[0] - lo[0]) + 1e-300);
  const int nx = (std::max)(1, int(std::lround(std::sqrt(cells_wanted * aspect))));
  const int ny = (std::max)(1, int(std::lround(cells_wanted / nx)));
  std::vector<std::vector<std::uint32_t>> cells(std::size_t(nx) * std::size_t(ny));
  for (std::size_t v = 0; v < vertices; ++v) {
    if (unknown_start[v + 1] == unknown_start[v] && face_start[v + 1] == face_start[v])
      continue;
    const auto p = position(std::uint32_t(v));
    auto cell = [](double t, double a, double b, int k) {
      const int i = b > a ? int((t - a) / (b - a) * k) : 0;
      return (std::min)(k - 1, (std::max)(0, i));
    };
    cells[std::size_t(cell(p[0], lo[0], hi[0], nx)) * std::size_t(ny) +
          std::size_t(cell(p[1], lo[1], hi[1], ny))]
        .push_back(std::uint32_t(v));
  }
  // The windows, once: window c's vertices (its cell and margin_rings rings) and its faces
  // (those whose terms involve the unknowns of its vertices), increasing, in flat arrays;
  // cells without unknowns make no window.
  std::vector<std::size_t> vertex_begin{0}, face_begin{0};
  std::vector<std::uint32_t> window_vertex, window_face;
  {
    std::vector<int> ring(vertices, -1);
    std::vector<char> face_mark(faces, 0);
    std::vector<std::uint32_t> around, faces_of, adjacent;
    for (const auto& core : cells) {
      if (core.empty())
        continue;
      around = core;
      for (std::uint32_t v : core)
        ring[v] = 0;
      std::size_t begin = 0;
      for (int r = 1; r <= options.margin_rings; ++r) {
        const std::size_t end = around.size();
        for (std::size_t i = begin; i < end; ++i) {
          adjacent.clear();
          neighbours(around[i], adjacent);
          for (std::uint32_t w : adjacent)
            if (ring[w] < 0) {
              ring[w] = r;
              around.push_back(w);
            }
        }
        begin = end;
      }
      bool any = false;
      faces_of.clear();
      for (std::uint32_t v : around) {
        ring[v] = -1;
        any = any || unknown_start[v + 1] > unknown_start[v];
        for (std::size_t i = face_start[v]; i < face_start[v + 1]; ++i)
          if (!face_mark[vertex_faces[i]]) {
            face_mark[vertex_faces[i]] = 1;
            faces_of.push_back(vertex_faces[i]);
          }
      }
      for (std::uint32_t f : faces_of)
        face_mark[f] = 0;
      if (!any)
        continue;
      // faces in increasing order: the same sums whatever the order of the rings
      std::sort(faces_of.begin(), faces_of.end());
      window_vertex.insert(window_vertex.end(), around.begin(), around.end());
      window_face.insert(window_face.end(), faces_of.begin(), faces_of.end());
      vertex_begin.push_back(window_vertex.size());
      face_begin.push_back(window_face.size());
    }
  }
  const std::size_t windows = vertex_begin.size() - 1;
  statistics.windows = windows;
  // Colours: window b conflicts with every window holding a vertex that owns an unknown b's
  // faces read (that window writes what b reads), and conversely.
  std::vector<std::uint32_t> colour(windows, 0);
  std::size_t colours = 0;
  std::vector<std::vector<std::uint32_t>> conflicts(windows);
  {
    std::vector<std::size_t> containing_start(vertices + 1, 0);
    for (std::uint32_t v : window_vertex)
      ++containing_start[v + 1];
    for (std::size_t v = 0; v < vertices; ++v)
      containing_start[v + 1] += containing_start[v];
    std::vector<std::uint32_t> containing(window_vertex.size());
    {
      std::vector<std::size_t> next(containing_start.begin(), containing_start.end() - 1);
      for (std::size_t c = 0; c < windows; ++c)
        for (std::size_t i = vertex_begin[c]; i < vertex_begin[c + 1]; ++i)
          containing[next[window_vertex[i]]++] = std::uint32_t(c);
    }
    // (each pair listed at most twice)
    std::vector<std::size_t> seen(vertices, windows), met(windows, windows);
    for (std::size_t c = 0; c < windows; ++c) {
      auto reach = [&](std::uint32_t v) {
        if (seen[v] == c)
          return;
        seen[v] = c;
        for (std::size_t k = containing_start[v]; k < containing_start[v + 1]; ++k) {
          const std::uint32_t b = containing[k];
          if (b != c && met[b] != c) {
            met[b] = c;
            conflicts[c].push_back(b);
            conflicts[b].push_back(std::uint32_t(c));
          }
        }
      };
      for (std::size_t i = vertex_begin[c]; i < vertex_begin[c + 1]; ++i)
        reach(window_vertex[i]);
      for (std::size_t i = face_begin[c]; i < face_begin[c + 1]; ++i) {
        involved.clear();
        unknowns_of(window_face[i], involved);
        for (std::uint32_t j : involved)
          reach(owner[j]);
      }
    }
    std::vector<char> taken;
    for (std::size_t c = 0; c < windows; ++c) {
      taken.assign(colours + 1, 0);
      for (std::uint32_t b : conflicts[c])
        if (b < c)
          taken[colour[b]] = 1;
      std::uint32_t k = 0;
      while (taken[k])
        ++k;
      colour[c] = k;
      colours = (std::max)(colours, std::size_t(k) + 1);
    }
  }
  statistics.colours = colours;
  // A sweep solves every window after the windows of lower colours it conflicts with, and
  // before those of higher colours: the order of a colour by colour sweep, and so its
  // result, bit for bit, whichever windows run at the same time. A window starts as soon
  // as those before it are done, the one with the costliest chain of windows after it
  // first (a barrier after each colour left a core idle through the colours of a single
  // window).
  std::vector<std::vector<std::uint32_t>> later(windows);
  std::vector<std::size_t> earlier(windows, 0);
  for (std::size_t c = 0; c < windows; ++c) {
    auto& list = conflicts[c];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (std::uint32_t b : list)
      if (colour[b] > colour[c])
        later[c].push_back(b);
      else
        ++earlier[c];
  }
  release(conflicts);
  std::vector<double> chain(windows, 0);
  {
    std::vector<std::uint32_t> order(windows);
    for (std::size_t c = 0; c < windows; ++c)
      order[c] = std::uint32_t(c);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return colour[a] > colour[b]; });
    for (std::uint32_t c : order) {
      double longest = 0;
      for (std::uint32_t b : later[c])
        longest = (std::max)(longest, chain[b]);
      chain[c] = double(face_begin[c + 1] - face_begin[c]) + longest;
    }
  }
  // The tolerance: a window is solved again when, since its last solve, an unknown it
  // solves for or reads moved by more than `threshold` (moved_at[j]: the colour phase in
  // which x_j last left the ball of that radius around anchor[j], its value then; the phase
  // of window c in sweep s is s colours + colour[c] + 1). Windows that run at the same time
  // read nothing the others write.
  const double threshold = options.tolerance * scale;
  const bool fixed_sweeps = options.sweeps > 0;
  const int most = fixed_sweeps ? options.sweeps : (std::max)(1, options.max_sweeps);
  std::vector<std::uint64_t> moved_at(fixed_sweeps ? 0 : n, 0), solved_at(windows, 0);
  Eigen::MatrixXd anchor;
  if (!fixed_sweeps)
    anchor = x;
  statistics.method = Schwarz_statistics::WINDOWS;
  std::vector<std::vector<std::uint32_t>> read(workers);
  const std::size_t threads = (std::min)(workers, windows);
  for (int sweep = 0; sweep < most; ++sweep) {
    for (Worker& k : worker)
      k.change = 0;
    auto run = [&](std::size_t w, std::size_t c) {
      const std::uint64_t phase = std::uint64_t(sweep) * colours + colour[c] + 1;
      bool stale = sweep == 0 || fixed_sweeps;
      for (std::size_t v = vertex_begin[c]; v < vertex_begin[c + 1] && !stale; ++v) {
        const std::uint32_t u = window_vertex[v];
        for (std::size_t o = unknown_start[u]; o < unknown_start[u + 1]; ++o)
          stale = stale || moved_at[owned[o]] > solved_at[c];
      }
      for (std::size_t f = face_begin[c]; f < face_begin[c + 1] && !stale; ++f) {
        read[w].clear();
        unknowns_of(window_face[f], read[w]);
        for (std::uint32_t j : read[w])
          stale = stale || moved_at[j] > solved_at[c];
      }
      if (!stale)
        return;
      solved_at[c] = phase;
      auto moved = [&](std::size_t j) {
        if (fixed_sweeps)
          return;
        const auto i = Eigen::Index(j);
        if ((x.row(i) - anchor.row(i)).cwiseAbs().maxCoeff() > threshold) {
          anchor.row(i) = x.row(i);
          moved_at[j] = phase;
        }
      };
      Worker& k = worker[w];
      k.change = (std::max)(k.change, solve(w, window_vertex.data() + vertex_begin[c],
                                            vertex_begin[c + 1] - vertex_begin[c],
                                            window_face.data() + face_begin[c],
                                            face_begin[c + 1] - face_begin[c], moved));
      ++k.solves;
    };
    // the ready windows, costliest chain first (ties: lower index)
    auto first = [&](std::uint32_t a, std::uint32_t b) {
      return chain[a] < chain[b] || (chain[a] == chain[b] && a > b);
    };
    std::vector<std::uint32_t> ready;
    std::vector<std::size_t> waiting(earlier);
    for (std::size_t c = 0; c < windows; ++c)
      if (waiting[c] == 0)
        ready.push_back(std::uint32_t(c));
    std::make_heap(ready.begin(), ready.end(), first);
    std::size_t done = 0;
    bool failed = false;
    std::exception_ptr error;
    std::mutex lock;
    std::condition_variable wake;
    auto work = [&](std::size_t w) {
      std::unique_lock<std::mutex> guard(lock);
      for (;;) {
        wake.wait(guard, [&] { return failed || done == windows || !ready.empty(); });
        if (failed || done == windows)
          return;
        std::pop_heap(ready.begin(), ready.end(), first);
        const std::uint32_t c = ready.back();
        ready.pop_back();
        guard.unlock();
        try {
          run(w, c);
        } catch (...) {
          guard.lock();
          if (!failed)
            error = std::current_exception();
          failed = true;
          wake.notify_all();
          return;
        }
        guard.lock();
        ++done;
        for (std::uint32_t b : later[c])
          if (--waiting[b] == 0) {
            ready.push_back(b);
            std::push_heap(ready.begin(), ready.end(), first);
          }
        wake.notify_all();
      }
    };
    {
      std::vector<std::thread> helpers;
      for (std::size_t w = 1; w < threads; ++w)
        helpers.emplace_back(work, w);
      work(0);
      for (std::thread& helper : helpers)
        helper.join();
    }
    if (error)
      std::rethrow_exception(error);
    double change = 0;
    statistics.window_solves = 0;
    for (const Worker& k : worker) {
      change = (std::max)(change, k.change);
      statistics.window_solves += k.solves;
    }
    statistics.sweeps = sweep + 1;
    statistics.last_change = change;
    if (!fixed_sweeps && change <= threshold)
      break;
  }
  statistics.converged = fixed_sweeps || statistics.last_change <= threshold;
  return statistics;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H

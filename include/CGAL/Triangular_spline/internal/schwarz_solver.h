// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H

#include <CGAL/Triangular_spline/exceptions.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
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
// The sweeps visit the windows one after the other in the same order, each factorized
// again (no factorization is kept: memory is one window's). Windows that couple beyond
// their neighbours are common: a vertex with a fan of slivers (a corner of the data's
// square, a hull vertex) couples windows along a whole side. Sweeps pipelined so as to
// reuse each window's factorization (pass p of a window as soon as its neighbouring
// cells had pass p - 1) see such couplings about a column of cells per pass late: at
// 10^5 noisy points the control values stayed 6.8e-5 from the direct solve after 4 to 6
// passes (sequential sweeps: 1.8e-3, 5.4e-8, 6.7e-10 after one, two and three).
//
// `sweeps` > 0: exactly that many. 0: until a sweep changes no unknown by more than
// `tolerance` times the data range (the `scale` of schwarz_minimise()), at most
// `max_sweeps`. A sweep after the first solves only the windows whose unknowns or
// surrounding unknowns moved by more than that since their last solve: the others would
// reproduce their values.
struct Schwarz_options {
  std::size_t direct_limit = 40000;
  std::size_t window_vertices = 500;
  int margin_rings = 3;
  int sweeps = 0;
  double tolerance = 1e-8;
  int max_sweeps = 8;
};

// What the solver did (Fit_statistics, tests and benchmarks).
struct Schwarz_statistics {
  enum Method { NONE, DIRECT, WINDOWS };
  Method method = NONE;
  std::size_t windows = 0;       // windows per sweep; 0 for the direct solve
  int sweeps = 0;                // sweeps done (1 for the direct solve)
  std::size_t window_solves = 0; // windows factorized and solved, over all sweeps
  double last_change = 0;        // largest change of an unknown in the last sweep
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
//   face_terms(f, terms): face f's terms (Face_terms). A window's system takes them with
//     the unknowns beyond it at their values in x.
// `vertices`: the number of domain vertices, `neighbours(v, out)` their adjacency and
// `position(v)` their coordinates (std::array<double, 2>), for the windows; `scale` the
// unit of options.tolerance.
template <class Unknowns_of, class Compute_face_terms, class Neighbours, class Position>
Schwarz_statistics
schwarz_minimise(std::size_t vertices, const std::vector<std::uint32_t>& owner, std::size_t faces,
                 const Unknowns_of& unknowns_of, const Compute_face_terms& face_terms,
                 const Neighbours& neighbours, const Position& position, Eigen::MatrixXd& x,
                 const Schwarz_options& options, double scale, const char* what) {
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
  // Buffers kept from window to window.
  std::vector<int> local(n, -1);
  std::vector<std::uint32_t> unknowns, involved;
  std::vector<Eigen::Triplet<double>> triplets;
  Face_terms terms;
  Eigen::SparseMatrix<double> matrix;
  // The upper triangle, ordered by approximate minimum degree. (Ordering the graph of the
  // vertices instead, each vertex's unknowns together, was slower:
  // 10^5 random points, 86 against 64 ms per window of the energy fit.)
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> factor;
  Eigen::MatrixXd rhs, y;
  // Minimises over the unknowns owned by `window_vertices` (faces `window_faces`: those
  // whose terms involve them), the others at their values in x; returns the largest change
  // of an unknown, calling moved(j) after unknown j is written.
  auto solve = [&](const std::vector<std::uint32_t>& window_vertices,
                   const std::vector<std::uint32_t>& window_faces, const auto& moved) {
    unknowns.clear();
    for (std::uint32_t v : window_vertices)
      for (std::size_t i = unknown_start[v]; i < unknown_start[v + 1]; ++i) {
        local[owned[i]] = int(unknowns.size());
        unknowns.push_back(owned[i]);
      }
    const Eigen::Index size = Eigen::Index(unknowns.size());
    rhs.setZero(size, D);
    triplets.clear();
    for (std::uint32_t f : window_faces) {
      face_terms(f, terms);
      const auto& columns = terms.columns;
      const Eigen::Index k = Eigen::Index(columns.size());
      for (Eigen::Index i = 0; i < k; ++i) {
        const int li = local[std::size_t(columns[std::size_t(i)])];
        if (li < 0)
          continue;
        rhs.row(li) += terms.B.row(i);
        for (Eigen::Index j = 0; j < k; ++j) {
          const double h = j <= i ? terms.H(i, j) : terms.H(j, i);
          if (h == 0)
            continue;
          const int lj = local[std::size_t(columns[std::size_t(j)])];
          if (lj < 0) // beyond the window: at its current value
            rhs.row(li) -= h * x.row(Eigen::Index(columns[std::size_t(j)]));
          else if (li <= lj)
            triplets.emplace_back(li, lj, h);
        }
      }
    }
    matrix.resize(size, size);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    factor.compute(matrix);
    if (factor.info() != Eigen::Success)
      throw Invalid_input(std::string("fit: the ") + what + " system could not be factorized");
    y = factor.solve(rhs);
    double change = 0;
    for (Eigen::Index i = 0; i < size; ++i) {
      const auto j = std::size_t(unknowns[std::size_t(i)]);
      for (Eigen::Index d = 0; d < D; ++d) {
        if (!std::isfinite(y(i, d)))
          throw Invalid_input(std::string("fit: the ") + what + " system is singular");
        change = (std::max)(change, std::abs(y(i, d) - x(Eigen::Index(j), d)));
        x(Eigen::Index(j), d) = y(i, d);
      }
      local[j] = -1;
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
    statistics.last_change = solve(all_vertices, all_faces, [](std::size_t) {});
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
  // The tolerance: a window is solved again when, since its last solve, an unknown it
  // solves for or reads moved by more than `threshold` (moved_at[j]: the window solve after
  // which x_j last left the ball of that radius around anchor[j], its value then).
  const double threshold = options.tolerance * scale;
  const bool fixed_sweeps = options.sweeps > 0;
  const int most = fixed_sweeps ? options.sweeps : (std::max)(1, options.max_sweeps);
  std::vector<std::uint64_t> moved_at(fixed_sweeps ? 0 : n, 0), solved_at(cells.size(), 0);
  Eigen::MatrixXd anchor;
  if (!fixed_sweeps)
    anchor = x;
  std::uint64_t clock = 0;
  auto moved = [&](std::size_t j) {
    if (fixed_sweeps)
      return;
    const auto i = Eigen::Index(j);
    if ((x.row(i) - anchor.row(i)).cwiseAbs().maxCoeff() > threshold) {
      anchor.row(i) = x.row(i);
      moved_at[j] = clock;
    }
  };
  std::vector<int> ring(vertices, -1);
  std::vector<char> face_mark(faces, 0);
  std::vector<std::uint32_t> window_vertices, window_faces, adjacent;
  statistics.method = Schwarz_statistics::WINDOWS;
  for (int sweep = 0; sweep < most; ++sweep) {
    double change = 0;
    statistics.windows = 0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto& core = cells[c];
      if (core.empty())
        continue;
      window_vertices = core;
      for (std::uint32_t v : core)
        ring[v] = 0;
      std::size_t begin = 0;
      for (int r = 1; r <= options.margin_rings; ++r) {
        const std::size_t end = window_vertices.size();
        for (std::size_t i = begin; i < end; ++i) {
          adjacent.clear();
          neighbours(window_vertices[i], adjacent);
          for (std::uint32_t w : adjacent)
            if (ring[w] < 0) {
              ring[w] = r;
              window_vertices.push_back(w);
            }
        }
        begin = end;
      }
      for (std::uint32_t v : window_vertices)
        ring[v] = -1;
      window_faces.clear();
      bool any = false, stale = sweep == 0 || fixed_sweeps;
      for (std::uint32_t v : window_vertices) {
        for (std::size_t i = unknown_start[v]; i < unknown_start[v + 1]; ++i) {
          any = true;
          stale = stale || moved_at[owned[i]] > solved_at[c];
        }
        for (std::size_t i = face_start[v]; i < face_start[v + 1]; ++i)
          if (!face_mark[vertex_faces[i]]) {
            face_mark[vertex_faces[i]] = 1;
            window_faces.push_back(vertex_faces[i]);
          }
      }
      for (std::uint32_t f : window_faces)
        face_mark[f] = 0;
      if (!any)
        continue;
      ++statistics.windows;
      for (std::size_t i = 0; i < window_faces.size() && !stale; ++i) {
        involved.clear();
        unknowns_of(window_faces[i], involved);
        for (std::uint32_t j : involved)
          stale = stale || moved_at[j] > solved_at[c];
      }
      if (!stale)
        continue;
      // faces in increasing order: the same sums whatever the order of the rings
      std::sort(window_faces.begin(), window_faces.end());
      solved_at[c] = ++clock;
      change = (std::max)(change, solve(window_vertices, window_faces, moved));
      ++statistics.window_solves;
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

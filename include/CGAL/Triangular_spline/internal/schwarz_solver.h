// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H

#include <CGAL/Triangular_spline/exceptions.h>

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
// to the global minimiser; measured on 5000 random points (noisy data, thin-plate energy):
// the largest deviation of a control value from the direct solution after one sweep from
// the local-polynomial values is 4e-5, after two 6e-10; on 20000 points 6e-4 and 1.2e-8
// (thin-plate energy), 6.6e-3 and 3e-5 (smoothing 0.1), 1.3e-12 after one sweep (least
// squares, which couples less). Cost: linear in the number of vertices (about 0.13 ms per
// vertex and sweep for the energy, the windows' factorizations dominating), memory bounded
// by a window. `sweeps` 0 means the fit's default: one for least squares, two otherwise.
struct Schwarz_options {
  std::size_t direct_limit = 40000;
  std::size_t window_vertices = 500;
  int margin_rings = 3;
  int sweeps = 0;
};

// What the solver did (tests and benchmarks).
struct Schwarz_statistics {
  std::size_t windows = 0; // per sweep; 0 for the direct solve
  int sweeps = 0;
  double last_change = 0; // largest change of an unknown in the last sweep
};

// Minimises sum over faces of quadratic terms in the unknowns x (unknowns x D, updated in
// place from its initial values).
//   owner[j]: the domain vertex owning unknown j (it decides the windows j belongs to);
//   unknowns_of(f, out): appends the unknowns that face f's terms depend on;
//   assemble(f, local, x, triplets, rhs): adds face f's terms to the system of the
//     unknowns j with local[j] >= 0 (at local index local[j]), the others at their values
//     in x; triplets may hold both triangles of the symmetric matrix.
// `vertices`: the number of domain vertices, `neighbours(v, out)` their adjacency and
// `position(v)` their coordinates (std::array<double, 2>), for the windows;
// `default_sweeps` the sweeps when options.sweeps is 0.
template <class Unknowns_of, class Assemble, class Neighbours, class Position>
Schwarz_statistics
schwarz_minimise(std::size_t vertices, const std::vector<std::uint32_t>& owner, std::size_t faces,
                 const Unknowns_of& unknowns_of, const Assemble& assemble,
                 const Neighbours& neighbours, const Position& position, Eigen::MatrixXd& x,
                 const Schwarz_options& options, int default_sweeps, const char* what) {
  const std::size_t n = owner.size();
  Schwarz_statistics statistics;
  if (n == 0)
    return statistics;
  std::vector<int> local(n, -1);
  std::vector<Eigen::Triplet<double>> triplets;
  // Solves for the unknowns `window` (local numbering set), faces `window_faces`.
  auto solve = [&](const std::vector<std::uint32_t>& window,
                   const std::vector<std::uint32_t>& window_faces) {
    const Eigen::Index size = Eigen::Index(window.size());
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(size, x.cols());
    triplets.clear();
    for (std::uint32_t f : window_faces)
      assemble(f, local, x, triplets, rhs);
    Eigen::SparseMatrix<double> matrix(size, size);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    if (solver.info() != Eigen::Success)
      throw Invalid_input(std::string("fit: the ") + what + " system could not be factorized");
    const Eigen::MatrixXd y = solver.solve(rhs);
    double change = 0;
    for (Eigen::Index i = 0; i < size; ++i)
      for (Eigen::Index d = 0; d < x.cols(); ++d) {
        if (!std::isfinite(y(i, d)))
          throw Invalid_input(std::string("fit: the ") + what + " system is singular");
        change = (std::max)(change, std::abs(y(i, d) - x(window[std::size_t(i)], d)));
        x(window[std::size_t(i)], d) = y(i, d);
      }
    return change;
  };
  if (n <= options.direct_limit) {
    std::vector<std::uint32_t> all(n), all_faces(faces);
    for (std::size_t j = 0; j < n; ++j) {
      all[j] = std::uint32_t(j);
      local[j] = int(j);
    }
    for (std::size_t f = 0; f < faces; ++f)
      all_faces[f] = std::uint32_t(f);
    triplets.reserve(faces * 1024);
    statistics.last_change = solve(all, all_faces);
    statistics.sweeps = 1;
    return statistics;
  }
  // vertex -> unknowns it owns, vertex -> faces whose terms involve them (CSR)
  std::vector<std::size_t> unknown_start(vertices + 1, 0), face_start(vertices + 1, 0);
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
  std::vector<std::uint32_t> involved, owners;
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
  std::vector<int> ring(vertices, -1);
  std::vector<char> face_mark(faces, 0);
  std::vector<std::uint32_t> window_vertices, window, window_faces, adjacent;
  const int sweeps = options.sweeps > 0 ? options.sweeps : default_sweeps;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    double change = 0;
    statistics.windows = 0;
    for (const auto& core : cells) {
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
      window.clear();
      window_faces.clear();
      for (std::uint32_t v : window_vertices) {
        for (std::size_t i = unknown_start[v]; i < unknown_start[v + 1]; ++i) {
          local[owned[i]] = int(window.size());
          window.push_back(owned[i]);
        }
        for (std::size_t i = face_start[v]; i < face_start[v + 1]; ++i)
          if (!face_mark[vertex_faces[i]]) {
            face_mark[vertex_faces[i]] = 1;
            window_faces.push_back(vertex_faces[i]);
          }
      }
      // faces in increasing order: the same sums whatever the order of the rings
      std::sort(window_faces.begin(), window_faces.end());
      if (!window.empty()) {
        change = (std::max)(change, solve(window, window_faces));
        ++statistics.windows;
      }
      for (std::uint32_t j : window)
        local[j] = -1;
      for (std::uint32_t f : window_faces)
        face_mark[f] = 0;
      for (std::uint32_t v : window_vertices)
        ring[v] = -1;
    }
    statistics.sweeps = sweep + 1;
    statistics.last_change = change;
  }
  return statistics;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SCHWARZ_SOLVER_H

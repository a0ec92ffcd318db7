// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_AG1_VERTEX_SOLVE_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_AG1_VERTEX_SOLVE_H

// The umbrella of one vertex in walk_AG1_system() (Xu/AG1_system.h): the projected star, the
// equations the solved neighbours impose, and their least-squares solution, exact or in double.

#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/Xu/Umbrella.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class FT>
constexpr bool ag1_is_exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;

template <class FT>
FT ag1_det(const std::array<FT, 2>& a, const std::array<FT, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

// The projected star of `v` in the basis (P_0, P_1) of its first two projected spokes; false
// if the area-weighted normal vanishes or P_0, P_1 are parallel. Everything is rational.
template <class Point_3>
bool ag1_projected_umbrella(const CGAL::Surface_mesh<Point_3>& mesh,
                            typename CGAL::Surface_mesh<Point_3>::Vertex_index v,
                            Umbrella<typename CGAL::Kernel_traits<Point_3>::Kernel::FT>& out) {
  using K = typename CGAL::Kernel_traits<Point_3>::Kernel;
  using KFT = typename K::FT;
  using Vector_3 = typename K::Vector_3;
  const auto ring = outgoing_ring(v, mesh);
  const std::size_t n = ring.size();
  std::vector<Vector_3> d;
  for (auto h : ring)
    d.push_back(mesh.point(mesh.target(h)) - mesh.point(v));
  Vector_3 normal(0, 0, 0);
  for (std::size_t i = 0; i < n; ++i)
    normal = normal + CGAL::cross_product(d[i], d[(i + 1) % n]);
  const KFT nn = normal * normal;
  if (CGAL::is_zero(nn))
    return false;
  std::vector<Vector_3> p;
  for (const Vector_3& di : d) {
    const KFT t = (di * normal) / nn;
    p.push_back(di - t * normal);
  }
  const KFT g00 = p[0] * p[0], g01 = p[0] * p[1], g11 = p[1] * p[1];
  const KFT det = g00 * g11 - g01 * g01;
  if (CGAL::is_zero(det))
    return false;
  out.assign(n, {{KFT(0), KFT(0)}});
  for (std::size_t i = 0; i < n; ++i) {
    const KFT r0 = p[0] * p[i], r1 = p[1] * p[i];
    out[i] = {{KFT((g11 * r0 - g01 * r1) / det), KFT((g00 * r1 - g01 * r0) / det)}};
  }
  return true;
}

template <class FT, class From>
FT ag1_convert(const From& x) {
  if constexpr (std::is_same<FT, From>::value)
    return x;
  else
    return FT(CGAL::to_double(x));
}

// One scalar equation per coordinate: sum_j coefficient[j] * u_{index[j]} = 0.
template <class FT>
struct AG1_equation {
  std::array<std::size_t, 3> index;
  std::array<FT, 3> coefficient;
};

template <class FT>
struct AG1_vertex_solution {
  Umbrella<FT> umbrella;
  double residual = 0;
  bool consistent = true;
  bool under_determined = false;
  bool gauge_degenerate = false; // the equations force u_{w_0}, u_{w_1} to be parallel
};

// Reduced row echelon form of the first `pivot_columns` columns, in place; the pivot columns.
template <class FT>
std::vector<std::size_t> ag1_rref(std::vector<std::vector<FT>>& m, std::size_t pivot_columns) {
  std::vector<std::size_t> pivots;
  std::size_t row = 0;
  for (std::size_t col = 0; col < pivot_columns && row < m.size(); ++col) {
    std::size_t r = row;
    while (r < m.size() && CGAL::is_zero(m[r][col]))
      ++r;
    if (r == m.size())
      continue;
    std::swap(m[r], m[row]);
    const FT pivot = m[row][col];
    for (FT& x : m[row])
      x /= pivot;
    for (std::size_t i = 0; i < m.size(); ++i)
      if (i != row && !CGAL::is_zero(m[i][col])) {
        const FT f = m[i][col];
        for (std::size_t j = col; j < m[i].size(); ++j)
          m[i][j] -= f * m[row][j];
      }
    pivots.push_back(col);
    ++row;
  }
  return pivots;
}

// The system of the unknown spokes 2..n-1 in the gauge u_0 = (1,0), u_1 = (0,1): A X = B with
// A (m x k), B (m x 2); x and y decouple with the same matrix.
template <class FT>
void ag1_gauge_system(std::size_t n, const std::vector<AG1_equation<FT>>& equations,
                      std::vector<std::vector<FT>>& a, std::vector<std::array<FT, 2>>& b) {
  const std::size_t k = n - 2;
  a.assign(equations.size(), std::vector<FT>(k, FT(0)));
  b.assign(equations.size(), {{FT(0), FT(0)}});
  for (std::size_t i = 0; i < equations.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t c = equations[i].index[j];
      const FT& w = equations[i].coefficient[j];
      if (c == 0)
        b[i][0] -= w;
      else if (c == 1)
        b[i][1] -= w;
      else
        a[i][c - 2] += w;
    }
}

// Exact number types: least squares through the (consistent) normal equations, the solution
// closest to the reference by projecting onto the null space, all by exact elimination.
template <class FT>
AG1_vertex_solution<FT> ag1_solve_exact(std::size_t n,
                                        const std::vector<AG1_equation<FT>>& equations,
                                        const Umbrella<FT>& reference) {
  const std::size_t k = n - 2, m = equations.size();
  std::vector<std::vector<FT>> a;
  std::vector<std::array<FT, 2>> b;
  ag1_gauge_system(n, equations, a, b);
  std::vector<std::vector<FT>> normal(k, std::vector<FT>(k + 2, FT(0)));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t r = 0; r < m; ++r) {
      if (CGAL::is_zero(a[r][i]))
        continue;
      for (std::size_t j = 0; j < k; ++j)
        normal[i][j] += a[r][i] * a[r][j];
      normal[i][k] += a[r][i] * b[r][0];
      normal[i][k + 1] += a[r][i] * b[r][1];
    }
  const std::vector<std::size_t> pivots = ag1_rref(normal, k);
  std::vector<std::array<FT, 2>> x(k, {{FT(0), FT(0)}});
  std::vector<bool> is_pivot(k, false);
  for (std::size_t i = 0; i < pivots.size(); ++i) {
    is_pivot[pivots[i]] = true;
    x[pivots[i]] = {{normal[i][k], normal[i][k + 1]}};
  }
  AG1_vertex_solution<FT> result;
  result.under_determined = pivots.size() < k;
  if (result.under_determined) {
    // Null space basis z_f (one per free column); move x to the closest point of
    // x + span(z) to the reference: solve (Z^T Z) t = Z^T (ref - x).
    std::vector<std::vector<FT>> z;
    for (std::size_t f = 0; f < k; ++f) {
      if (is_pivot[f])
        continue;
      std::vector<FT> zf(k, FT(0));
      zf[f] = FT(1);
      for (std::size_t i = 0; i < pivots.size(); ++i)
        zf[pivots[i]] = -normal[i][f];
      z.push_back(zf);
    }
    const std::size_t fcount = z.size();
    std::vector<std::vector<FT>> g(fcount, std::vector<FT>(fcount + 2, FT(0)));
    for (std::size_t i = 0; i < fcount; ++i) {
      for (std::size_t j = 0; j < fcount; ++j)
        for (std::size_t c = 0; c < k; ++c)
          g[i][j] += z[i][c] * z[j][c];
      for (std::size_t c = 0; c < k; ++c)
        for (std::size_t d = 0; d < 2; ++d)
          g[i][fcount + d] += z[i][c] * (reference[c + 2][d] - x[c][d]);
    }
    ag1_rref(g, fcount); // Z has full column rank: g is the identity afterwards
    for (std::size_t i = 0; i < fcount; ++i)
      for (std::size_t c = 0; c < k; ++c)
        for (std::size_t d = 0; d < 2; ++d)
          x[c][d] += g[i][fcount + d] * z[i][c];
  }
  FT squared(0);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t d = 0; d < 2; ++d) {
      FT e = -b[r][d];
      for (std::size_t c = 0; c < k; ++c)
        e += a[r][c] * x[c][d];
      squared += e * e;
    }
  result.consistent = CGAL::is_zero(squared);
  result.residual = std::sqrt(CGAL::to_double(squared));
  if (!result.consistent) {
    // Is there an umbrella at all? The homogeneous system in all n spokes has a kernel of
    // dimension >= 2 iff one exists; then only the gauge is at fault.
    std::vector<std::vector<FT>> full(m, std::vector<FT>(n, FT(0)));
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t j = 0; j < 3; ++j)
        full[r][equations[r].index[j]] += equations[r].coefficient[j];
    result.gauge_degenerate = n - ag1_rref(full, n).size() >= 2;
  }
  result.umbrella.assign(n, {{FT(0), FT(0)}});
  result.umbrella[0] = {{FT(1), FT(0)}};
  result.umbrella[1] = {{FT(0), FT(1)}};
  for (std::size_t c = 0; c < k; ++c)
    result.umbrella[c + 2] = x[c];
  return result;
}

// Inexact number types: the same in double with Eigen's complete orthogonal decomposition
// (minimum-norm least squares); ranks with a relative threshold.
template <class FT>
AG1_vertex_solution<FT> ag1_solve_double(std::size_t n,
                                         const std::vector<AG1_equation<FT>>& equations,
                                         const Umbrella<FT>& reference, double tolerance) {
  const std::size_t k = n - 2, m = equations.size();
  std::vector<std::vector<FT>> a;
  std::vector<std::array<FT, 2>> b;
  ag1_gauge_system(n, equations, a, b);
  Eigen::MatrixXd am(m, k), bm(m, 2), xref(k, 2);
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t c = 0; c < k; ++c)
      am(r, c) = CGAL::to_double(a[r][c]);
    bm(r, 0) = CGAL::to_double(b[r][0]);
    bm(r, 1) = CGAL::to_double(b[r][1]);
  }
  for (std::size_t c = 0; c < k; ++c)
    for (std::size_t d = 0; d < 2; ++d)
      xref(c, d) = CGAL::to_double(reference[c + 2][d]);
  const double rank_threshold = 1e-10;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  cod.setThreshold(rank_threshold);
  cod.compute(am);
  const Eigen::MatrixXd x = xref + cod.solve(bm - am * xref);
  AG1_vertex_solution<FT> result;
  result.under_determined = std::size_t(cod.rank()) < k;
  result.residual = (am * x - bm).norm();
  result.consistent = result.residual <= tolerance;
  if (!result.consistent) {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(m, n);
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t j = 0; j < 3; ++j)
        full(r, equations[r].index[j]) += CGAL::to_double(equations[r].coefficient[j]);
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> full_cod;
    full_cod.setThreshold(rank_threshold);
    full_cod.compute(full);
    result.gauge_degenerate = n - std::size_t(full_cod.rank()) >= 2;
  }
  result.umbrella.assign(n, {{FT(0), FT(0)}});
  result.umbrella[0] = {{FT(1), FT(0)}};
  result.umbrella[1] = {{FT(0), FT(1)}};
  for (std::size_t c = 0; c < k; ++c)
    result.umbrella[c + 2] = {{FT(x(c, 0)), FT(x(c, 1))}};
  return result;
}

// A corner triangle (u_v, u_i, u_{i+1}) is degenerate: exactly collinear for exact number
// types, |sin| <= tolerance otherwise.
template <class FT>
bool ag1_has_degenerate_corner(const Umbrella<FT>& u, double tolerance) {
  const std::size_t n = u.size();
  for (std::size_t i = 0; i < n; ++i) {
    const FT d = ag1_det(u[i], u[(i + 1) % n]);
    if constexpr (ag1_is_exact<FT>) {
      if (CGAL::is_zero(d))
        return true;
    } else {
      const double li = std::hypot(CGAL::to_double(u[i][0]), CGAL::to_double(u[i][1]));
      const double lj =
          std::hypot(CGAL::to_double(u[(i + 1) % n][0]), CGAL::to_double(u[(i + 1) % n][1]));
      if (!(std::abs(CGAL::to_double(d)) > tolerance * li * lj))
        return true;
    }
  }
  return false;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_AG1_VERTEX_SOLVE_H

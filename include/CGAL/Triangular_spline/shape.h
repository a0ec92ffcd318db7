// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_SHAPE_H
#define CGAL_TRIANGULAR_SPLINE_SHAPE_H

#include <CGAL/Triangular_spline/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/local_polynomial_fit.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief how the free control points of a `C1_quintic_spline` are set from data at the
  vertices.
*/
enum class Fit {
  /// every free point is the polar-value blend of its patch's corner data,
  /// \f$f(a^i b^j c^k) \approx (i z_a + j z_b + k z_c)/5\f$ (Xu §7.3, §6.2.4); with
  /// `Corner_frame::Symmetric_stars` the corners are propagated: the spline approximates
  Approximate,
  /// as `Approximate`, and every corner point is prescribed to the data value (Xu §4.4.2);
  /// needs `Corner_frame::Corner_and_two_stars`
  Interpolate,
  /// interpolation of values and of gradients estimated at every vertex (least squares over
  /// its neighbours): each free point takes the tangent-plane value of its nearest corner
  /// (averaged on ties), at its domain point, the degree-1 case of Mann's nearest-vertex
  /// rule; this tilts the corner frames along the data (Xu §4.4.5) instead of
  /// flattening them. Needs `Corner_frame::Corner_and_two_stars`
  Tangent_planes,
  /// interpolation of the values; the other free points are chosen so that ALL control
  /// points (free and propagated) are as close as possible, in least squares, to the
  /// `Tangent_planes` targets: every control value is a linear function of the free ones,
  /// and the normal equations are solved with a sparse Cholesky factorization (Eigen). This
  /// is the remedy for the amplification of Xu §4.4.5: thin frames propagate with large
  /// weights, and the least-squares choice keeps the propagated points near the data
  /// instead of letting them overshoot. The solve runs in `double`; the free values are
  /// then converted to `FT` and propagated in `FT`, so an exact spline is still exactly C^1
  /// (linear data is then reproduced up to the solve's rounding). The targets are those of
  /// `Local_polynomial`. Needs `Corner_frame::Corner_and_two_stars`
  Least_squares,
  /// interpolation of the values; every free point takes the polar value of the local
  /// polynomial (`Local_polynomials`, degree 3 by default) of its nearest corner, averaged
  /// on ties. All points of a corner region, and every corner-inner and edge-middle point,
  /// then come from one polynomial, so propagation through them reproduces it whatever its
  /// weights; only flip points and re-routed edge points mix the polynomials of
  /// neighbouring vertices. Data
  /// from a polynomial of degree at most the local degree are reproduced exactly (exactly
  /// with an exact number type); local in time and memory. Needs
  /// `Corner_frame::Corner_and_two_stars`
  Local_polynomial
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the least-squares gradient at every vertex of the data `values`: the
  plane through \f$(v, z_v)\f$ closest to the neighbours' data (exact arithmetic with an
  exact number type; a vertex whose neighbours are collinear with it has no gradient and
  gets the zero vector).
*/
template <class GeomTraits, class Value>
std::vector<std::array<Value, 2>> estimate_gradients(const Planar_domain<GeomTraits>& domain,
                                                     const std::vector<Value>& values) {
  using FT = typename GeomTraits::FT;
  std::vector<std::array<Value, 2>> gradients(domain.number_of_vertices());
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
    // Normal equations of min sum |z_v + g.(w - v) - z_w|^2: 2x2, per coordinate of Value.
    FT a(0), b(0), c(0);
    Value rx = Value_traits<Value>::zero(), ry = Value_traits<Value>::zero();
    const auto [nb, ne] = domain.neighbours(v);
    for (auto w = nb; w != ne; ++w) {
      const FT dx = domain.point(*w).x() - domain.point(v).x();
      const FT dy = domain.point(*w).y() - domain.point(v).y();
      a = a + dx * dx;
      b = b + dx * dy;
      c = c + dy * dy;
      const Value dz = values[*w] - values[v];
      rx = rx + dx * dz;
      ry = ry + dy * dz;
    }
    const FT det = a * c - b * b;
    if (CGAL::is_zero(det)) {
      gradients[v] = {{Value_traits<Value>::zero(), Value_traits<Value>::zero()}};
      continue;
    }
    const Value gx = (c / det) * rx - (b / det) * ry;
    const Value gy = (a / det) * ry - (b / det) * rx;
    gradients[v] = {{gx, gy}};
  }
  return gradients;
}

namespace internal {

// Least-squares choice of the free values (Fit::Least_squares): corners fixed to the data,
// every slot's value written as a sparse linear combination of the free slots by running the
// rules symbolically, then min sum_s |value(s) - target(s)|^2 by the normal equations.
template <class GeomTraits, class Value, class Target>
void least_squares_free_values(C1_quintic_spline<GeomTraits, Value>& spline,
                               const std::vector<Value>& values, const Target& target) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  constexpr int D = Traits::dimension;
  const std::size_t n = spline.number_of_slots();
  const std::size_t V = spline.domain().number_of_vertices();
  // Unknowns: the free slots that are not corners (corners interpolate the data).
  std::vector<int> column(n, -1);
  std::size_t unknowns = 0;
  for (Slot s : spline.free_slots())
    if (s >= V)
      column[s] = static_cast<int>(unknowns++);
  // rows[s]: value(s) = sum rows[s] x + constant[s]
  std::vector<std::vector<std::pair<int, double>>> rows(n);
  std::vector<std::array<double, D>> constant(n);
  for (auto& c : constant)
    c.fill(0);
  for (Slot s : spline.free_slots()) {
    if (s < V)
      for (int c = 0; c < D; ++c)
        constant[s][std::size_t(c)] = CGAL::to_double(Traits::coordinate(values[s], c));
    else
      rows[s] = {{column[s], 1.0}};
  }
  std::vector<std::pair<int, double>> merged;
  for (const auto& rule : spline.rules()) {
    merged.clear();
    std::array<double, D> k;
    k.fill(0);
    for (int i = 0; i < rule.size; ++i) {
      const double w = CGAL::to_double(rule.weights[std::size_t(i)]);
      const Slot src = rule.sources[std::size_t(i)];
      for (const auto& [j, a] : rows[src])
        merged.emplace_back(j, w * a);
      for (int c = 0; c < D; ++c)
        k[std::size_t(c)] += w * constant[src][std::size_t(c)];
    }
    std::sort(merged.begin(), merged.end());
    auto& row = rows[rule.target];
    row.clear();
    for (const auto& [j, a] : merged) {
      if (!row.empty() && row.back().first == j)
        row.back().second += a;
      else
        row.emplace_back(j, a);
    }
    constant[rule.target] = k;
  }
  // Normal equations (M^T M) x = M^T (t - constant).
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(unknowns), D);
  for (std::size_t s = 0; s < n; ++s) {
    const Value t = target(static_cast<Slot>(s));
    for (const auto& [i, a] : rows[s]) {
      for (const auto& [j, b] : rows[s])
        triplets.emplace_back(i, j, a * b);
      for (int c = 0; c < D; ++c)
        rhs(i, c) += a * (CGAL::to_double(Traits::coordinate(t, c)) - constant[s][std::size_t(c)]);
    }
  }
  const Eigen::Index size = static_cast<Eigen::Index>(unknowns);
  Eigen::SparseMatrix<double> normal(size, size);
  normal.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success)
    throw Invalid_input("fit: the least-squares system could not be factorized");
  const Eigen::MatrixXd x = solver.solve(rhs);
  for (Slot s : spline.free_slots()) {
    if (s < V) {
      spline.set_free_value(s, values[s]);
      continue;
    }
    std::array<FT, std::size_t(D)> c;
    for (int d = 0; d < D; ++d)
      c[std::size_t(d)] = FT(x(column[s], d));
    spline.set_free_value(s, Traits::from_coordinates(c));
  }
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief what `fit_vertex_data()` did: the degrees of the local polynomials
  (`Local_polynomial` and `Least_squares` fits; all zero otherwise).
*/
struct Fit_statistics {
  /// `vertices_by_degree[d]`: the number of vertices whose local polynomial has degree `d`
  std::array<std::size_t, 6> vertices_by_degree{};
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief sets every free control point of `spline` from the data `values` (one per domain
  vertex) according to `fit`, then propagates, and returns what it did.

  Every mode reproduces data sampled from a linear function exactly (every prescribed point
  is then the linear function's polar value, and propagation preserves it; for
  `Local_polynomial` and `Least_squares` with `local_degree` at least 1).
  `local_degree` is the largest degree of the local polynomials of `Local_polynomial` and
  `Least_squares` (0..5).
  \throws Invalid_input if `values` has the wrong size or a non-finite value, or if a fit
  other than `Approximate` is asked of a spline whose corner points are not free.
*/
template <class GeomTraits, class Value>
Fit_statistics fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline,
                               const std::vector<Value>& values, Fit fit, int local_degree = 3,
                               Degree_selection selection = Degree_selection::Cross_validation) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  const auto& domain = spline.domain();
  if (values.size() != domain.number_of_vertices())
    throw Invalid_input("fit: " + std::to_string(values.size()) + " data values for " +
                        std::to_string(domain.number_of_vertices()) + " vertices");
  for (const Value& v : values)
    if (!is_finite_value(v))
      throw Invalid_input("fit: non-finite data value");
  if (fit != Fit::Approximate && spline.corner_frame() != Corner_frame::Corner_and_two_stars)
    throw Invalid_input("fit: interpolation needs corner points to be prescribed "
                        "(build the spline with Corner_frame::Corner_and_two_stars)");
  std::vector<std::array<Value, 2>> gradients;
  if (fit == Fit::Tangent_planes)
    gradients = estimate_gradients(domain, values);
  std::optional<Local_polynomials<GeomTraits, Value>> local;
  if (fit == Fit::Local_polynomial || fit == Fit::Least_squares)
    local.emplace(domain, values, local_degree, selection);
  Fit_statistics statistics;
  if (local)
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
      ++statistics.vertices_by_degree[std::size_t(local->degree(v))];
  // The value a slot should take from the data: polar blend, or tangent plane of the
  // nearest corner(s) at the slot's domain point.
  auto target = [&](Slot s) {
    const auto label = spline.polar_label(s);
    Value v = Value_traits<Value>::zero();
    if (fit == Fit::Approximate || fit == Fit::Interpolate) {
      for (const auto& [vertex, multiplicity] : label)
        v = v + (FT(multiplicity) / FT(5)) * values[vertex];
      return v;
    }
    int largest = 0;
    for (const auto& entry : label)
      largest = (std::max)(largest, entry.second);
    if (local) {
      std::array<std::pair<const typename GeomTraits::Point_2*, int>, 3> arguments;
      std::size_t count = 0;
      for (const auto& [vertex, multiplicity] : label)
        arguments[count++] = {&domain.point(vertex), multiplicity};
      int ties = 0;
      for (const auto& entry : label) {
        if (entry.second != largest)
          continue;
        v = v + local->polar_value(entry.first, arguments.begin(), arguments.begin() + count, 5);
        ++ties;
      }
      return ties == 1 ? v : Value((FT(1) / FT(ties)) * v);
    }
    const auto x = spline.domain_point(s);
    int ties = 0;
    for (const auto& [vertex, multiplicity] : label) {
      if (multiplicity != largest)
        continue;
      const FT dx = x.x() - domain.point(vertex).x(), dy = x.y() - domain.point(vertex).y();
      v = v + values[vertex] + dx * gradients[vertex][0] + dy * gradients[vertex][1];
      ++ties;
    }
    return Value((FT(1) / FT(ties)) * v);
  };
  if (fit == Fit::Least_squares) {
    internal::least_squares_free_values(spline, values, target);
  } else {
    for (Slot s : spline.free_slots())
      spline.set_free_value(s, target(s));
  }
  spline.propagate();
  return statistics;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_SHAPE_H

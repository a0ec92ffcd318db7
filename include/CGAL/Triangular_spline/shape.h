// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_SHAPE_H
#define CGAL_TRIANGULAR_SPLINE_SHAPE_H

#include <CGAL/Triangular_spline/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <algorithm>
#include <array>
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
  Tangent_planes
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

/*!
  \ingroup PkgTriangularSplineSplines
  \brief sets every free control point of `spline` from the data `values` (one per domain
  vertex) according to `fit`, then propagates.

  Every mode reproduces data sampled from a linear function exactly (every prescribed point
  is then the linear function's polar value, and propagation preserves it).
  \throws Invalid_input if `values` has the wrong size or a non-finite value, or if
  `Interpolate`/`Tangent_planes` is asked of a spline whose corner points are not free.
*/
template <class GeomTraits, class Value>
void fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline, const std::vector<Value>& values,
                     Fit fit) {
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
  for (Slot s : spline.free_slots()) {
    const auto label = spline.polar_label(s);
    Value v = Value_traits<Value>::zero();
    if (fit != Fit::Tangent_planes) {
      for (const auto& [vertex, multiplicity] : label)
        v = v + (FT(multiplicity) / FT(5)) * values[vertex];
    } else {
      // Tangent plane of the corner(s) with the largest multiplicity, at the slot's point.
      int largest = 0;
      for (const auto& entry : label)
        largest = (std::max)(largest, entry.second);
      const auto x = spline.domain_point(s);
      int ties = 0;
      for (const auto& [vertex, multiplicity] : label) {
        if (multiplicity != largest)
          continue;
        const FT dx = x.x() - domain.point(vertex).x(), dy = x.y() - domain.point(vertex).y();
        v = v + values[vertex] + dx * gradients[vertex][0] + dy * gradients[vertex][1];
        ++ties;
      }
      v = (FT(1) / FT(ties)) * v;
    }
    spline.set_free_value(s, v);
  }
  spline.propagate();
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_SHAPE_H

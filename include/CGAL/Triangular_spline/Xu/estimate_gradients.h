// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_ESTIMATE_GRADIENTS_H
#define CGAL_TRIANGULAR_SPLINE_XU_ESTIMATE_GRADIENTS_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the least-squares gradient at every vertex of the data `values`: the
  plane through \f$(v, z_v)\f$ closest to the neighbours' data (exact arithmetic with an
  exact number type; a vertex whose neighbours are collinear with it has no gradient and
  gets the zero vector).
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param domain the triangulated planar domain
  \param values the data values, one per domain vertex
  \returns the least-squares gradient at every vertex of the data `values`
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
    // Summed from the neighbour with the lexicographically smallest point on, around v: the
    // rounded sums then do not depend on the vertex numbering, which sets where the
    // rotation starts.
    const auto n = ne - nb;
    auto first = nb;
    for (auto w = nb + 1; w != ne; ++w) {
      const auto &p = domain.point(*w), &q = domain.point(*first);
      if (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()))
        first = w;
    }
    for (auto i = decltype(n)(0); i < n; ++i) {
      const auto w = nb + (first - nb + i) % n;
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

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_ESTIMATE_GRADIENTS_H

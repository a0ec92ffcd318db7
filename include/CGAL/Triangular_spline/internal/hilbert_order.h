// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H

// The Hilbert order in which domain_from_triangulation_2() numbers the vertices.

#include <CGAL/enum.h>

#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Hilbert sorting of (point, handle) pairs with ties broken by the other coordinate: a strict
// total order on distinct points, so the numbering does not depend on the input order.
template <class GeomTraits, class Handle>
struct Lexicographic_hilbert_traits {
  using Point_2 = std::pair<typename GeomTraits::Point_2, Handle>;
  struct Less_x_2 {
    bool operator()(const Point_2& a, const Point_2& b) const {
      return GeomTraits().compare_xy_2_object()(a.first, b.first) == CGAL::SMALLER;
    }
  };
  struct Less_y_2 {
    bool operator()(const Point_2& a, const Point_2& b) const {
      return GeomTraits().compare_yx_2_object()(a.first, b.first) == CGAL::SMALLER;
    }
  };
  Less_x_2 less_x_2_object() const { return Less_x_2(); }
  Less_y_2 less_y_2_object() const { return Less_y_2(); }
};

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_VALUES_AS_3D_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_VALUES_AS_3D_H

// A spline value (a height or a vector) as a point of space in double, for the derivatives
// of differential_geometry.h and tessellate.h.

#include <CGAL/Triangular_spline/Value_traits.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class Value>
std::array<double, 3> as_3d(const Value& v, bool is_graph_value, double graph_x, double graph_y) {
  using Traits = Value_traits<Value>;
  if (is_graph_value)
    return {{graph_x, graph_y, CGAL::to_double(Traits::coordinate(v, 0))}};
  std::array<double, 3> r{{0, 0, 0}};
  for (int c = 0; c < Traits::dimension && c < 3; ++c)
    r[static_cast<std::size_t>(c)] = CGAL::to_double(Traits::coordinate(v, c));
  return r;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_VALUES_AS_3D_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_SCATTERED_DATA_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_SCATTERED_DATA_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineDomain
  \brief scattered height data \f$(x_i, y_i, z_i)\f$: distinct points of the plane, not all
  collinear, with one height each, as returned by `read_xyz()`.
  \tparam GeomTraits a model of `Kernel`
*/
template <class GeomTraits>
struct Scattered_data {
  /// the points \f$(x_i, y_i)\f$
  std::vector<typename GeomTraits::Point_2> points;
  /// the heights \f$z_i\f$, one per point
  std::vector<typename GeomTraits::FT> values;
  /// the gradients \f$(\partial z/\partial x, \partial z/\partial y)\f$, one per point when
  /// read with gradients, else empty
  std::vector<std::array<typename GeomTraits::FT, 2>> gradients;
  /// the number of input lines dropped because they repeated an earlier line's point and
  /// height
  std::size_t merged_duplicates = 0;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_SCATTERED_DATA_H

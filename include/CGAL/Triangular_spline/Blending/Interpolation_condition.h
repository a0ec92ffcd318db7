// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_INTERPOLATION_CONDITION_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_INTERPOLATION_CONDITION_H

#include <array>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief an interpolation condition on a bivariate function: its value, or one of its first
  partial derivatives, at a point.
*/
struct Interpolation_condition {
  /// which functional
  enum Kind {
    VALUE, ///< \f$F(p)\f$
    DX,    ///< \f$\partial_x F(p)\f$
    DY     ///< \f$\partial_y F(p)\f$
  };
  Kind kind = VALUE;                ///< the functional
  std::array<double, 2> at{{0, 0}}; ///< the point \f$p\f$
  double value = 0;                 ///< the prescribed value
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_INTERPOLATION_CONDITION_H

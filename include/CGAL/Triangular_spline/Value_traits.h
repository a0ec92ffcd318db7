// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_VALUE_TRAITS_H
#define CGAL_TRIANGULAR_SPLINE_VALUE_TRAITS_H

#include <CGAL/Triangular_spline/internal/integer_log10.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Fraction_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineConcepts
  \brief describes the control values a patch may carry.

  A control value is an element of a vector space over the number type `FT`: the
  algorithms only form affine (and, for derivatives, linear) combinations `a + b`,
  `a - b` and `FT * a`, so the Bézier core stays rational. Specialisations exist for

  - the number type itself (functional patches, heights over the plane): dimension 1;
  - `CGAL::Vector_2` and `CGAL::Vector_3` of any kernel (parametric patches; a point
    \f$p\f$ is stored as the position vector \f$p - O\f$): dimensions 2 and 3.

  Users add a value type by specialising this template with the members below.
  \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
  \tparam Enable `void`, used to select the specializations
*/
template <class Value, class Enable = void>
struct Value_traits {
  /// the number type the values are built from
  using FT = Value;
  /// the number of coordinates
  static constexpr int dimension = 1;
  /// returns the zero value (needed for derivatives, which are linear combinations)
  /// \returns the zero value (needed for derivatives, which are linear combinations)
  static Value zero() { return Value(0); }
  /// returns coordinate `c` of `v`
  /// \param v the value
  /// \returns coordinate `c` of `v`
  static const FT& coordinate(const Value& v, int) { return v; }
  /// returns the value with the given coordinates
  /// \param c the coordinates
  /// \returns the value with the given coordinates
  static Value from_coordinates(const std::array<FT, 1>& c) { return c[0]; }
};

/// the value traits of `CGAL::Vector_3` (parametric patches in space).
/// \tparam Vector a CGAL vector type
template <class Vector>
struct Value_traits<Vector, std::enable_if_t<std::is_same<
                                typename Kernel_traits<Vector>::Kernel::Vector_3, Vector>::value>> {
  /// the number type of the vector's kernel
  using FT = typename Kernel_traits<Vector>::Kernel::FT;
  /// the number of coordinates
  static constexpr int dimension = 3;
  /// returns the null vector
  /// \returns the null vector
  static Vector zero() { return Vector(NULL_VECTOR); }
  /// returns coordinate `c` (0, 1 or 2) of `v`
  /// \param v the value
  /// \param c the index of the coordinate
  /// \returns coordinate `c` (0, 1 or 2) of `v`
  static FT coordinate(const Vector& v, int c) { return v[c]; }
  /// returns the vector with the given coordinates
  /// \param c the coordinates
  /// \returns the vector with the given coordinates
  static Vector from_coordinates(const std::array<FT, 3>& c) { return Vector(c[0], c[1], c[2]); }
};

/// the value traits of `CGAL::Vector_2` (parametric patches in the plane).
/// \tparam Vector a CGAL vector type
template <class Vector>
struct Value_traits<Vector, std::enable_if_t<std::is_same<
                                typename Kernel_traits<Vector>::Kernel::Vector_2, Vector>::value>> {
  /// the number type of the vector's kernel
  using FT = typename Kernel_traits<Vector>::Kernel::FT;
  /// the number of coordinates
  static constexpr int dimension = 2;
  /// returns the null vector
  /// \returns the null vector
  static Vector zero() { return Vector(NULL_VECTOR); }
  /// returns coordinate `c` (0 or 1) of `v`
  /// \param v the value
  /// \param c the index of the coordinate
  /// \returns coordinate `c` (0 or 1) of `v`
  static FT coordinate(const Vector& v, int c) { return v[c]; }
  /// returns the vector with the given coordinates
  /// \param c the coordinates
  /// \returns the vector with the given coordinates
  static Vector from_coordinates(const std::array<FT, 2>& c) { return Vector(c[0], c[1]); }
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the largest absolute coordinate of `v`, converted to `double`
  (the norm used for residuals).
  \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
  \param v the value
  \returns the largest absolute coordinate of `v`, converted to `double` (the norm used for
  residuals)
*/
template <class Value>
double max_abs_coordinate(const Value& v) {
  using Traits = Value_traits<Value>;
  double result = 0;
  for (int c = 0; c < Traits::dimension; ++c) {
    const double x = std::abs(CGAL::to_double(Traits::coordinate(v, c)));
    // NaN must not hide behind a max.
    if (!(x <= result))
      result = x;
  }
  return result;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns `true` iff every coordinate of `v` is zero (an exact test for exact
  number types).
  \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
  \param v the value
  \returns `true` iff every coordinate of `v` is zero (an exact test for exact number types)
*/
template <class Value>
bool is_zero_value(const Value& v) {
  using Traits = Value_traits<Value>;
  for (int c = 0; c < Traits::dimension; ++c)
    if (!CGAL::is_zero(Traits::coordinate(v, c)))
      return false;
  return true;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns \f$\log_{10} |x|\f$ without underflow or overflow: \f$-\infty\f$ iff `x` is
  zero.

  `CGAL::to_double()` turns an exact rational below \f$10^{-308}\f$ into 0 and one above
  \f$10^{308}\f$ into infinity; for exact fraction types (`Gmpq`, `mpq_class`, ...) the
  magnitude is taken from the numerator and the denominator instead, so a residual of
  \f$10^{-500}\f$ reads \f$-500\f$, not \f$-\infty\f$. Accurate to about 15 digits.
  \tparam FT a number type
  \param x the number
  \returns \f$\log_{10} |x|\f$ without underflow or overflow
*/
template <class FT>
double log10_magnitude(const FT& x) {
  if (CGAL::is_zero(x))
    return -std::numeric_limits<double>::infinity();
  const double d = std::abs(CGAL::to_double(x));
  using Fractions = CGAL::Fraction_traits<FT>;
  if constexpr (std::is_same<typename Fractions::Is_fraction, CGAL::Tag_true>::value) {
    if (!(d >= 1e-300 && d <= 1e300)) {
      typename Fractions::Numerator_type numerator;
      typename Fractions::Denominator_type denominator;
      typename Fractions::Decompose()(x, numerator, denominator);
      return internal::log10_of_integer(numerator) - internal::log10_of_integer(denominator);
    }
  }
  return std::log10(d);
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns \f$\log_{10}\f$ of the largest absolute coordinate of `v`, without underflow
  (`log10_magnitude()`): \f$-\infty\f$ iff `v` is zero.
  \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
  \param v the value
  \returns \f$\log_{10}\f$ of the largest absolute coordinate of `v`, without underflow
  (`log10_magnitude()`)
*/
template <class Value>
double max_abs_coordinate_log10(const Value& v) {
  using Traits = Value_traits<Value>;
  double result = -std::numeric_limits<double>::infinity();
  for (int c = 0; c < Traits::dimension; ++c) {
    const double x = log10_magnitude(Traits::coordinate(v, c));
    if (!(x <= result))
      result = x;
  }
  return result;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns `true` iff every coordinate of `v` is at most `tolerance` in absolute value,
  compared exactly in the number type (the `double` tolerance converts exactly).
  \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
  \param v the value
  \param tolerance the bound on the absolute value of each coordinate
  \returns `true` iff every coordinate of `v` is at most `tolerance` in absolute value, compared
  exactly in the number type (the `double` tolerance converts exactly)
*/
template <class Value>
bool is_within_tolerance(const Value& v, double tolerance) {
  using Traits = Value_traits<Value>;
  using FT = typename Traits::FT;
  const FT bound(tolerance);
  for (int c = 0; c < Traits::dimension; ++c) {
    const FT x = Traits::coordinate(v, c);
    if (!(CGAL::abs(x) <= bound))
      return false;
  }
  return true;
}

/// returns `true` iff every coordinate of `v` is finite (always true for exact types).
/// \tparam Value a number type, or a CGAL `Vector_2` or `Vector_3`
/// \param v the value
/// \returns `true` iff every coordinate of `v` is finite (always true for exact types)
template <class Value>
bool is_finite_value(const Value& v) {
  using Traits = Value_traits<Value>;
  for (int c = 0; c < Traits::dimension; ++c)
    if (!CGAL::is_finite(Traits::coordinate(v, c)))
      return false;
  return true;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_VALUE_TRAITS_H

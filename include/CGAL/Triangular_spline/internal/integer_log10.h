// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_INTEGER_LOG10_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_INTEGER_LOG10_H

// The magnitude of huge integers, for log10_magnitude() (Value_traits.h).

#include <CGAL/number_utils.h>

#include <cmath>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// log10 |z| of an integer of any size: to_double() overflows beyond 1e308, so huge integers
// are divided by 2^960 first (each division is exact enough for a magnitude).
template <class Integer>
double log10_of_integer(Integer z) {
  if (CGAL::is_negative(z))
    z = -z;
  const Integer step(std::ldexp(1.0, 960));
  double exponent = 0;
  while (!(CGAL::to_double(z) <= 1e300)) {
    z = z / step;
    exponent += 960;
  }
  return std::log10(CGAL::to_double(z)) + exponent * std::log10(2.0);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_INTEGER_LOG10_H

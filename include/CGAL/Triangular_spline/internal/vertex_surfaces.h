// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_SURFACES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_SURFACES_H

// Interpolation conditions applied to monomials and polynomials: the matrices of
// least_interpolant() and least_squares_polynomial() (Blending/vertex_surfaces.h).

#include <CGAL/Triangular_spline/Blending/Interpolation_condition.h>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

inline double factorial(int n) {
  double r = 1;
  for (int i = 2; i <= n; ++i)
    r *= i;
  return r;
}

inline double power(double x, int e) {
  double r = 1;
  for (int i = 0; i < e; ++i)
    r *= x;
  return r;
}

// lambda(x^h y^k) for one condition
inline double apply_to_monomial(const Interpolation_condition& c, int h, int k) {
  const double x = c.at[0], y = c.at[1];
  switch (c.kind) {
  case Interpolation_condition::VALUE:
    return power(x, h) * power(y, k);
  case Interpolation_condition::DX:
    return h == 0 ? 0.0 : h * power(x, h - 1) * power(y, k);
  case Interpolation_condition::DY:
    return k == 0 ? 0.0 : k * power(x, h) * power(y, k - 1);
  }
  return 0;
}

// any polynomial class with degree() and coefficient(h, k)
template <class Polynomial>
double apply(const Interpolation_condition& c, const Polynomial& p) {
  double r = 0;
  for (int h = 0; h <= p.degree(); ++h)
    for (int k = 0; h + k <= p.degree(); ++k)
      r += p.coefficient(h, k) * apply_to_monomial(c, h, k);
  return r;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_SURFACES_H

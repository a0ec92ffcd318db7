// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FILTERED_ORIENTATION_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FILTERED_ORIENTATION_H

// The orientation predicate of a kernel, with an interval filter in front of it for GMP's
// rationals: the exact kernel of the package (Simple_cartesian<mpq_class>) is not filtered,
// and each of its orientation tests costs some twenty reduced rational operations. The
// filter decides from enclosures of the coordinates; only where the interval determinant
// contains zero is the exact test run, so the answer is still the exact one.

#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <cmath>
#include <type_traits>

#ifdef __GMP_PLUSPLUS__
#include <gmp.h>
#endif

namespace CGAL {
namespace Triangular_spline {
namespace internal {

#ifdef __GMP_PLUSPLUS__
// An interval that contains x, or false. mpq_get_d() truncates towards zero, so x lies
// within one ulp of the result; values whose conversion is system dependent (beyond
// double's range, or near its subnormals) are not enclosed.
inline bool enclose_rational(const mpq_class& x, double& low, double& high) {
  const double d = mpq_get_d(x.get_mpq_t());
  if (!(std::abs(d) >= 1e-290 && std::abs(d) <= 1e290)) {
    if (d != 0 || mpq_sgn(x.get_mpq_t()) != 0)
      return false;
    low = high = 0; // exactly zero
    return true;
  }
  low = std::nextafter(d, -HUGE_VAL);
  high = std::nextafter(d, HUGE_VAL);
  return true;
}
#endif

// traits.orientation_2_object()(p, q, r), decided by intervals first for mpq_class.
template <class Traits>
CGAL::Orientation filtered_orientation(const Traits& traits, const typename Traits::Point_2& p,
                                       const typename Traits::Point_2& q,
                                       const typename Traits::Point_2& r) {
#ifdef __GMP_PLUSPLUS__
  if constexpr (std::is_same_v<std::decay_t<decltype(p.x())>, mpq_class>) {
    double c[6][2];
    const mpq_class* x[6] = {&p.x(), &p.y(), &q.x(), &q.y(), &r.x(), &r.y()};
    bool enclosed = true;
    for (int i = 0; i < 6 && enclosed; ++i)
      enclosed = enclose_rational(*x[i], c[i][0], c[i][1]);
    if (enclosed) {
      using I = CGAL::Interval_nt<false>;
      CGAL::Protect_FPU_rounding<true> upwards;
      const I px(c[0][0], c[0][1]), py(c[1][0], c[1][1]), qx(c[2][0], c[2][1]),
          qy(c[3][0], c[3][1]), rx(c[4][0], c[4][1]), ry(c[5][0], c[5][1]);
      const I det = (qx - px) * (ry - py) - (qy - py) * (rx - px);
      if (det.inf() > 0)
        return CGAL::LEFT_TURN;
      if (det.sup() < 0)
        return CGAL::RIGHT_TURN;
    }
  }
#endif
  return traits.orientation_2_object()(p, q, r);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FILTERED_ORIENTATION_H

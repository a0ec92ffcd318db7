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

// Enclosures of a point's two coordinates, for the interval filter below. `enclosed` false:
// no enclosure (a number type without the filter, or a coordinate outside double's safe
// range), the exact test decides.
struct Point_enclosure {
  double x_low = 0, x_high = 0, y_low = 0, y_high = 0;
  bool enclosed = false;
};

// Whether filtered_orientation() converts the coordinates of FT (GMP's rationals) at all:
// only then are enclosures worth computing and storing.
template <class FT>
constexpr bool has_orientation_filter() {
#ifdef __GMP_PLUSPLUS__
  return std::is_same_v<std::decay_t<FT>, mpq_class>;
#else
  return false;
#endif
}

// The enclosures of p's coordinates (each costs a division: a domain converts its points
// once and passes the enclosures in).
template <class Point_2>
Point_enclosure enclose_point(const Point_2& p) {
  Point_enclosure e;
#ifdef __GMP_PLUSPLUS__
  if constexpr (has_orientation_filter<decltype(p.x())>())
    e.enclosed =
        enclose_rational(p.x(), e.x_low, e.x_high) && enclose_rational(p.y(), e.y_low, e.y_high);
#else
  (void)p;
#endif
  return e;
}

// traits.orientation_2_object()(p, q, r), decided first by intervals from the enclosures of
// the three points where they have them.
template <class Traits>
CGAL::Orientation filtered_orientation(const Traits& traits, const typename Traits::Point_2& p,
                                       const typename Traits::Point_2& q,
                                       const typename Traits::Point_2& r, const Point_enclosure& ep,
                                       const Point_enclosure& eq, const Point_enclosure& er) {
  if (ep.enclosed && eq.enclosed && er.enclosed) {
    using I = CGAL::Interval_nt<false>;
    CGAL::Protect_FPU_rounding<true> upwards;
    const I px(ep.x_low, ep.x_high), py(ep.y_low, ep.y_high), qx(eq.x_low, eq.x_high),
        qy(eq.y_low, eq.y_high), rx(er.x_low, er.x_high), ry(er.y_low, er.y_high);
    const I det = (qx - px) * (ry - py) - (qy - py) * (rx - px);
    if (det.inf() > 0)
      return CGAL::LEFT_TURN;
    if (det.sup() < 0)
      return CGAL::RIGHT_TURN;
  }
  return traits.orientation_2_object()(p, q, r);
}

// traits.orientation_2_object()(p, q, r), decided by intervals first for mpq_class.
template <class Traits>
CGAL::Orientation filtered_orientation(const Traits& traits, const typename Traits::Point_2& p,
                                       const typename Traits::Point_2& q,
                                       const typename Traits::Point_2& r) {
  if constexpr (has_orientation_filter<decltype(p.x())>())
    return filtered_orientation(traits, p, q, r, enclose_point(p), enclose_point(q),
                                enclose_point(r));
  else
    return traits.orientation_2_object()(p, q, r);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FILTERED_ORIENTATION_H

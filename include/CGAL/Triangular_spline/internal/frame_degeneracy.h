// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FRAME_DEGENERACY_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FRAME_DEGENERACY_H

// The double-precision tests of degenerate_frames.h: near-collinear frames and the size of
// a frame's propagation weights.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// |(x, y)| without overflow or underflow: sqrt(x^2 + y^2) while the sum of squares is a
// normal double far from the limits (then within about an ulp of std::hypot, whose
// correct rounding cost 6% of a 10^6-point approximate build in the frame tests), hypot
// beyond (coordinates up to 1e150 must not overflow to inf; NaN takes hypot too).
inline double length_2(double x, double y) {
  const double squares = x * x + y * y;
  return squares > 1e-290 && squares < 1e290 ? std::sqrt(squares) : std::hypot(x, y);
}

// For inexact kernels: are p, r, q collinear up to the rounding of their coordinates? True
// when the sine of the angle at r is below 1e-12. Such frames come from data that is
// collinear in decimal but not in binary (0.1, 1/3, ...): solving them exactly would need
// weights of 1e16 and more, re-routing them leaves a C^1 defect of the same tiny relative
// size, which the certificate reports.
template <class Point_2>
bool numerically_collinear(const Point_2& p, const Point_2& r, const Point_2& q) {
  const double ax = CGAL::to_double(p.x()) - CGAL::to_double(r.x());
  const double ay = CGAL::to_double(p.y()) - CGAL::to_double(r.y());
  const double bx = CGAL::to_double(q.x()) - CGAL::to_double(r.x());
  const double by = CGAL::to_double(q.y()) - CGAL::to_double(r.y());
  const double cross = ax * by - ay * bx;
  const double dot = ax * bx + ay * by;
  // Opposite directions only: apexes on the two sides with r between them.
  // Lengths, not a product of squares: coordinates up to 1e150 must not overflow to inf.
  return dot < 0 && std::abs(cross) <= 1e-12 * length_2(ax, ay) * length_2(bx, by);
}

// The largest weight of the regular propagation at end r of edge (r, other) with apexes p
// and q: the largest barycentric coordinate of `other` in (p, r, q), in double.
template <class Point_2>
double frame_weight(const Point_2& other, const Point_2& p, const Point_2& r, const Point_2& q) {
  auto orient = [](const Point_2& a, const Point_2& b, const Point_2& c) {
    return (CGAL::to_double(b.x()) - CGAL::to_double(a.x())) *
               (CGAL::to_double(c.y()) - CGAL::to_double(a.y())) -
           (CGAL::to_double(b.y()) - CGAL::to_double(a.y())) *
               (CGAL::to_double(c.x()) - CGAL::to_double(a.x()));
  };
  const double d = orient(p, r, q);
  if (d == 0)
    return std::numeric_limits<double>::infinity();
  return (std::max)({std::abs(orient(other, r, q) / d), std::abs(orient(p, other, q) / d),
                     std::abs(orient(p, r, other) / d)});
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FRAME_DEGENERACY_H

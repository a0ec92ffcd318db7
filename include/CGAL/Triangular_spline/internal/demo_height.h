// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_DEMO_HEIGHT_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_DEMO_HEIGHT_H

// The height function of demo_data.h.

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The demo heights: a cubic polynomial plus a rational bump, all coefficients rational, so
// an exact FT evaluates them exactly.
template <class FT>
FT demo_height(const FT& x, const FT& y) {
  const FT cubic = FT(1) / FT(2) + x / FT(3) - y / FT(5) + x * x * y / FT(8) - x * y * y / FT(12) +
                   x * x * x / FT(24);
  const FT dx = x - FT(9) / FT(4), dy = y - FT(3) / FT(4);
  const FT bump = FT(1) / (FT(1) + FT(4) * (dx * dx + dy * dy));
  return cubic + bump;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_DEMO_HEIGHT_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_RELEASE_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_RELEASE_H

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Frees a container's storage now, where a large temporary array must not stay through the
// rest of a run. `c = {}` does not: for std::vector it assigns an empty initializer list,
// which keeps the capacity (10^6 points: a 12 MB array of frames held through the fit).
template <class Container>
void release(Container& c) {
  Container().swap(c);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_RELEASE_H

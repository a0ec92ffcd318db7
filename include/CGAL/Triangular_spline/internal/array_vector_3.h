// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_ARRAY_VECTOR_3_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_ARRAY_VECTOR_3_H

#include <array>
#include <cmath>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Vectors of space as std::array<double, 3>: the package's vocabulary for quantities that
// need square roots (normals, curvatures, Fang's frames), the same type as
// Surface_derivatives, Surface_curvature and Surface_sample. A kernel's Vector_3 is not used
// there because the same formulas also run componentwise on Taylor_jet coordinates, which
// no CGAL kernel can hold. One set of helpers for the whole package.

inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

inline double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline std::array<double, 3> difference(const std::array<double, 3>& a,
                                        const std::array<double, 3>& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}

inline double norm(const std::array<double, 3>& a) {
  return std::sqrt(dot(a, a));
}

inline std::array<double, 3> scaled(const std::array<double, 3>& a, double s) {
  return {{a[0] * s, a[1] * s, a[2] * s}};
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_ARRAY_VECTOR_3_H

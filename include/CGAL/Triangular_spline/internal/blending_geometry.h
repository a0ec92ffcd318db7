// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_GEOMETRY_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_GEOMETRY_H

// Plane maps and jet measurements of Fang's mesh blending (Blending/Mesh_blending_surface.h,
// Blending/blending_continuity.h).

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/array_vector_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// An affine map of the plane: (a, b) -> (m0 a + m1 b + m2, m3 a + m4 b + m5), applied to
// numbers or jets.
struct Affine_2 {
  std::array<double, 6> m{{1, 0, 0, 0, 1, 0}};

  template <class T>
  std::array<T, 2> operator()(const T& a, const T& b) const {
    const T x = a * m[0] + b * m[1] + m[2];
    const T y = a * m[3] + b * m[4] + m[5];
    return {{x, y}};
  }
  double determinant() const { return m[0] * m[4] - m[1] * m[3]; }

  // the affine map sending p_i to q_i
  static Affine_2 from_points(const std::array<std::array<double, 2>, 3>& p,
                              const std::array<std::array<double, 2>, 3>& q) {
    const double a = p[1][0] - p[0][0], b = p[2][0] - p[0][0], c = p[1][1] - p[0][1],
                 d = p[2][1] - p[0][1];
    const double det = a * d - b * c;
    if (det == 0)
      throw Invalid_input("blending: degenerate triangle in a face domain");
    const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
    const double qa = q[1][0] - q[0][0], qb = q[2][0] - q[0][0], qc = q[1][1] - q[0][1],
                 qd = q[2][1] - q[0][1];
    Affine_2 r;
    r.m[0] = qa * ia + qb * ic;
    r.m[1] = qa * ib + qb * id;
    r.m[3] = qc * ia + qd * ic;
    r.m[4] = qc * ib + qd * id;
    r.m[2] = q[0][0] - r.m[0] * p[0][0] - r.m[1] * p[0][1];
    r.m[5] = q[0][1] - r.m[3] * p[0][0] - r.m[4] * p[0][1];
    return r;
  }

  Affine_2 inverse() const {
    const double det = determinant();
    if (det == 0)
      throw Invalid_input("blending: singular affine map");
    Affine_2 r;
    r.m[0] = m[4] / det;
    r.m[1] = -m[1] / det;
    r.m[3] = -m[3] / det;
    r.m[4] = m[0] / det;
    r.m[2] = -(r.m[0] * m[2] + r.m[1] * m[5]);
    r.m[5] = -(r.m[3] * m[2] + r.m[4] * m[5]);
    return r;
  }
};

// The largest norm of the difference of the order-k partial derivatives of two jet points.
template <class Jet>
double jet_jump(const std::array<Jet, 3>& a, const std::array<Jet, 3>& b, int k) {
  double worst = 0;
  for (int j = 0; j <= k; ++j) {
    double s = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const double d = a[c].derivative(k - j, j) - b[c].derivative(k - j, j);
      s += d * d;
    }
    worst = (std::max)(worst, std::sqrt(s));
  }
  return worst;
}

// The unit normal of a jet point (zero where singular).
template <class Jet>
std::array<double, 3> jet_normal(const std::array<Jet, 3>& p) {
  const std::array<double, 3> u{
      {p[0].derivative(1, 0), p[1].derivative(1, 0), p[2].derivative(1, 0)}};
  const std::array<double, 3> v{
      {p[0].derivative(0, 1), p[1].derivative(0, 1), p[2].derivative(0, 1)}};
  std::array<double, 3> n = cross(u, v);
  const double l = std::sqrt(dot(n, n));
  if (l > 0)
    for (double& x : n)
      x /= l;
  return n;
}

inline double angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const std::array<double, 3> c = cross(a, b);
  const double s = std::sqrt(dot(c, c)), co = dot(a, b);
  return std::atan2(s, co) * 180.0 / 3.14159265358979323846;
}

// The bounding-box diagonal of the vertices of a Mesh_blending_surface.
template <class Surface>
double mesh_size(const Surface& surface) {
  std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
  for (std::size_t v = 0; v < surface.number_of_vertices(); ++v)
    for (std::size_t c = 0; c < 3; ++c) {
      lo[c] = (std::min)(lo[c], surface.vertex_position(v)[c]);
      hi[c] = (std::max)(hi[c], surface.vertex_position(v)[c]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

// The sides of face f of a Mesh_blending_surface that contain corner c.
template <class Surface>
std::array<std::size_t, 2> sides_at_corner(const Surface& s, std::size_t f, std::size_t c) {
  const std::size_t n = s.face_size(f);
  if (n == 3)
    return {{(c + 1) % 3, (c + 2) % 3}};
  return {{(c + n - 1) % n, c}};
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_GEOMETRY_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_CLOSED_SURFACE_GEOMETRY_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_CLOSED_SURFACE_GEOMETRY_H

// Angles between normals and points on mesh edges, for the measurements of closed_surface.h.

#include <CGAL/number_type_config.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

inline double closed_angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const std::array<double, 3> c{
      {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) *
         180 / CGAL_PI;
}

// Barycentric weights, in vertices_around_face order of face(h), of the point of edge(h) at
// fraction t from source(h) to target(h).
template <class Mesh>
std::array<double, 3> weights_on_halfedge(const Mesh& mesh, typename Mesh::Halfedge_index h,
                                          double t) {
  const auto h0 = mesh.halfedge(mesh.face(h));
  // corner 0 = target(h0) = source(next(h0)), corner 1 = source(next(next(h0))), 2 = source(h0)
  const std::array<typename Mesh::Vertex_index, 3> c{
      {mesh.target(h0), mesh.target(mesh.next(h0)), mesh.source(h0)}};
  std::array<double, 3> w{{0, 0, 0}};
  for (std::size_t a = 0; a < 3; ++a) {
    if (c[a] == mesh.source(h))
      w[a] += 1 - t;
    if (c[a] == mesh.target(h))
      w[a] += t;
  }
  return w;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_CLOSED_SURFACE_GEOMETRY_H

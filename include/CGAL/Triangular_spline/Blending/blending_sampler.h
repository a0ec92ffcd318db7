// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SAMPLER_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SAMPLER_H

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/differential_geometry.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief a `Mesh_blending_surface` over a triangle mesh as a sampler of
  `measure_closed_surface()` and `tessellate_closed_surface()`: called with a face of
  `surface.mesh()` and barycentric weights of its corners in `vertices_around_face` order,
  it returns the point, the unit normal and the Gaussian curvature (from jets) there. This
  is how Fang's blend is measured like the other piecewise surfaces (Nielson's, PN
  triangles, pseudo-\f$AG^1\f$).
  \tparam Point_3 the point type of the surface's mesh
*/
template <class Point_3>
class Mesh_blending_sampler {
public:
  /// the sampler of `surface` (kept by reference)
  /// \param surface the blended surface, over a triangle mesh
  explicit Mesh_blending_sampler(const Mesh_blending_surface<Point_3>& surface)
      : m_surface(surface) {}

  /// \param f a face of `surface.mesh()`, a triangle
  /// \param w barycentric weights of the face's corners
  /// \returns the sample of face `f` at `w`
  Surface_sample operator()(typename Mesh_blending_surface<Point_3>::face_descriptor f,
                            const std::array<double, 3>& w) const {
    const auto& mesh = m_surface.mesh();
    const std::size_t face = std::size_t(f);
    CGAL_precondition(m_surface.face_size(face) == 3);
    // the face parameter: the weights applied to the corners' parameters
    std::array<double, 2> ab{{0, 0}};
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      for (std::size_t c = 0; c < 3; ++c)
        if (m_surface.face_vertex(face, c) == std::size_t(v))
          for (std::size_t x = 0; x < 2; ++x)
            ab[x] += w[k] * m_surface.corner_parameter(face, c)[x];
      ++k;
    }
    Surface_sample s;
    const Point_3 p = m_surface.evaluate(f, ab[0], ab[1]);
    s.point = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    const Surface_curvature c = surface_curvature(m_surface.derivatives(face, ab[0], ab[1]));
    s.normal = c.normal;
    s.gaussian = c.gaussian;
    s.regular = c.regular;
    return s;
  }

private:
  const Mesh_blending_surface<Point_3>& m_surface;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SAMPLER_H

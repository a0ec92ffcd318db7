// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SAMPLER_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SAMPLER_H

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief a `Mesh_blending_surface` over a triangle mesh as a sampler of
  `measure_closed_surface()` and `tessellate_closed_surface()`: called with a face of the
  mesh the surface was built from and barycentric weights of its corners in
  `vertices_around_face` order,
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
  /// \throws Invalid_input if a face of `surface` is not a triangle
  explicit Mesh_blending_sampler(const Mesh_blending_surface<Point_3>& surface)
      : m_surface(surface) {
    // checked once here, not at every sample (a quad mesh is bad input, not a programming error)
    for (std::size_t f = 0; f < m_surface.number_of_faces(); ++f)
      if (m_surface.face_size(f) != 3)
        throw Invalid_input("blending sampler: face " + std::to_string(f) + " has " +
                            std::to_string(m_surface.face_size(f)) +
                            " sides; the sampler needs a triangle mesh");
  }

  /// \tparam Face `std::size_t` or a face descriptor convertible to the face's index (that
  /// of a `Surface_mesh` without removed elements)
  /// \param f a face of the surface
  /// \pre the index of `f` is below the surface's `number_of_faces()`
  /// \param w barycentric weights of the face's corners
  /// \returns the sample of face `f` at `w`
  template <class Face>
  Surface_sample operator()(Face f, const std::array<double, 3>& w) const {
    const std::size_t face = static_cast<std::size_t>(f);
    CGAL_precondition(face < m_surface.number_of_faces());
    // the face parameter: the weights applied to the corners' parameters (the surface's
    // corners are in vertices_around_face order)
    std::array<double, 2> ab{{0, 0}};
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t x = 0; x < 2; ++x)
        ab[x] += w[k] * m_surface.corner_parameter(face, k)[x];
    Surface_sample s;
    const Point_3 p = m_surface.evaluate(face, ab[0], ab[1]);
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

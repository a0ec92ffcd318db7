// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_THESIS_POLYHEDRA_H
#define CGAL_TRIANGULAR_SPLINE_XU_THESIS_POLYHEDRA_H

#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/thesis_polyhedra.h>

#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns the names accepted by `thesis_polyhedron()`.
  \returns tetrahedron, sato, octahedron, cube, cube-centres, icosahedron, pentakis, torus,
  torus9, star, v-arm
*/
inline std::vector<std::string> thesis_polyhedron_names() {
  return {"tetrahedron", "sato",  "octahedron", "cube", "cube-centres", "icosahedron",
          "pentakis",    "torus", "torus9",     "star", "v-arm"};
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns the closed triangle mesh `name` of the pseudo-\f$AG^1\f$ tests (SPEC_AG1
  §8), faces counter-clockwise seen from outside.

  - `tetrahedron` (4 / 6 / 4 vertices / edges / faces): regular, a = (1,1,1), b = (1,−1,−1),
    c = (−1,1,−1), d = (−1,−1,1); faces abc, adb, bdc, cda in this order (Xu §6.1.1).
  - `sato` (4 / 6 / 4): Sato's tetrahedron (0,0,0), (1,0,0), (1,2,0), (2,3,4) (Xu Fig. 5.3).
  - `octahedron` (6 / 12 / 8): \f$\pm e_i\f$.
  - `cube` (8 / 18 / 12): \f$\{-1,1\}^3\f$, vertex number \f$4[x>0] + 2[y>0] + [z>0]\f$, each
    square cut by the diagonal through its smallest vertex number.
  - `cube-centres` (14 / 36 / 24): the cube's corners (numbered as above), then the face
    centres \f$+e_1, -e_1, +e_2, \dots\f$; each square cut into 4 triangles.
  - `icosahedron` (12 / 30 / 20): radius 1 (Fang's generator, rounded coordinates).
  - `pentakis` (42 / 120 / 80): the icosahedron 4-split on the unit sphere
    (`blending_test_mesh_data("pentakis")`).
  - `torus` (72 / 216 / 144): Fang's torus R = 1.3, r = 0.7, 12×6
    (`blending_test_mesh_data("torus")`).
  - `torus9` (9 / 27 / 18): the 3×3 grid torus of Xu Fig. 5.5, vertex (i, j) at the angles
    \f$2\pi i/3\f$ about the axis and \f$2\pi j/3\f$ about the tube, R = 2, r = 1.
  - `star` (14 / 36 / 24): 12 points at angles \f$2\pi k/12\f$, radii 1 and 2/5 alternating, in
    z = 0, coned to \f$(0,0,\pm 3/5)\f$.
  - `v-arm` (10 / 24 / 16): the ring (10,0), (10,1), (1/2,1/2), (1,10), (0,10), (−1/10,1/10),
    (−1/10,−1/10), (1/10,−1/10) in z = 0, coned to \f$(0,0,\pm 1)\f$.

  Rational coordinates are built as quotients of integers, so they are exact with an exact
  number type; the irrational ones (icosahedron, pentakis, torus, torus9, the star's
  oblique points) are computed in `double` and converted.
  \tparam K a CGAL kernel
  \throws Invalid_input for an unknown name (the message lists the names)
  \param name one of `thesis_polyhedron_names()`
  \returns the mesh
*/
template <class K>
CGAL::Surface_mesh<typename K::Point_3> thesis_polyhedron(const std::string& name) {
  using Mesh = CGAL::Surface_mesh<typename K::Point_3>;
  const internal::Thesis_polyhedron_data<K> data = internal::thesis_polyhedron_data<K>(name);
  Mesh mesh;
  std::vector<typename Mesh::Vertex_index> v;
  for (const typename K::Point_3& p : data.points)
    v.push_back(mesh.add_vertex(p));
  for (const std::array<std::size_t, 3>& f : data.faces)
    if (mesh.add_face(v[f[0]], v[f[1]], v[f[2]]) == Mesh::null_face())
      throw Invalid_input("polyhedron '" + name + "': a face cannot be added"); // a bug here
  return mesh;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_THESIS_POLYHEDRA_H

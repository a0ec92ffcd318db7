// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_COMPARATORS_PN_TRIANGLES_H
#define CGAL_TRIANGULAR_SPLINE_COMPARATORS_PN_TRIANGLES_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/pn_triangles.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the curved PN triangles of a triangle mesh (Vlachos, Peters, Boyd, Mitchell 2001),
  a comparator for the pseudo-\f$AG^1\f$ surfaces: one cubic patch per face from the
  vertex positions and normals only.

  For the face \f$(P_1, P_2, P_3)\f$ with normals \f$N_i\f$: \f$b_{300} = P_1\f$, ...;
  \f$b_{210} = (2P_1 + P_2 - w_{12} N_1)/3\f$ with \f$w_{ij} = (P_j - P_i)\cdot N_i /
  (N_i \cdot N_i)\f$ (the paper's formula for unit normals; the division makes any nonzero
  length give the same point, so exact normals need no square root), and so on around the
  face; \f$b_{111} = E + (E - V)/2\f$, \f$E\f$ the average of the six edge points and
  \f$V\f$ that of the corners. Each edge point depends only on its edge's end data, so the
  patches join \f$C^0\f$; the corner tangent plane is the plane normal to \f$N_i\f$ (only
  \f$G^0\f$ along the edges).

  Patch `f.idx()` is over the unit triangle (0,0), (1,0), (0,1) whose corners are the
  face's vertices in the order of `vertices_around_face(halfedge(f, mesh), mesh)`;
  \f$b_{ijk}\f$ is its control point (i, j, k) (see `linear_index()`).
  \tparam K a CGAL kernel
  \tparam NormalMap a readable property map from the mesh's vertex index to
  `K::Vector_3` (nonzero, not necessarily unit)
  \throws Invalid_input if a face is not a triangle, the mesh has garbage, or a normal is zero
  \param mesh a triangle mesh
  \param normals the vertex normals
  \returns one cubic patch per face, indexed by face index
*/
template <class K, class NormalMap>
std::vector<Bezier_triangle<K, typename K::Vector_3>>
pn_triangles(const CGAL::Surface_mesh<typename K::Point_3>& mesh, const NormalMap& normals) {
  internal::pn_check_mesh<K>(mesh);
  std::vector<typename K::Vector_3> n(mesh.number_of_vertices());
  for (auto v : mesh.vertices()) {
    n[static_cast<std::size_t>(v.idx())] = get(normals, v);
    if (n[static_cast<std::size_t>(v.idx())] == CGAL::NULL_VECTOR)
      throw Invalid_input("PN triangles: zero normal at vertex " + std::to_string(v.idx()));
  }
  return internal::pn_triangles_impl<K>(mesh, n);
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the curved PN triangles of `mesh` with the area-weighted vertex normals: the sum of
  the incident faces' normals weighted by their areas, normalised in `double` (so not exact
  with an exact kernel). See `pn_triangles(const CGAL::Surface_mesh<typename K::Point_3>&,
  const NormalMap&)`.
  \tparam K a CGAL kernel
  \throws Invalid_input if a face is not a triangle, the mesh has garbage, or a vertex
  normal vanishes
  \param mesh a triangle mesh
  \returns one cubic patch per face, indexed by face index
*/
template <class K>
std::vector<Bezier_triangle<K, typename K::Vector_3>>
pn_triangles(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  internal::pn_check_mesh<K>(mesh);
  for (auto f : mesh.faces())
    if (degree(f, mesh) != 3)
      throw Invalid_input("PN triangles: face " + std::to_string(f.idx()) + " is not a triangle");
  return internal::pn_triangles_impl<K>(mesh, internal::pn_default_normals<K>(mesh));
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_COMPARATORS_PN_TRIANGLES_H

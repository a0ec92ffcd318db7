// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_COMPARATORS_PN_TRIANGLES_H
#define CGAL_TRIANGULAR_SPLINE_COMPARATORS_PN_TRIANGLES_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/exceptions.h>

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

namespace internal {

// The PN control point of the edge p -> q next to p: (2p + q)/3 projected along n onto the
// tangent plane at p. Dividing by n.n makes it depend only on the direction of n, so that
// exact (rational, not unit) normals give exact points. Both faces of an edge call this
// with the same arguments, so their boundary points are equal even in double.
template <class K>
typename K::Vector_3 pn_edge_point(const typename K::Vector_3& p, const typename K::Vector_3& q,
                                   const typename K::Vector_3& n) {
  using FT = typename K::FT;
  const typename K::Vector_3 d = q - p;
  const FT w = (d * n) / (n * n);
  return (FT(2) * p + q - w * n) / FT(3);
}

// The area-weighted vertex normals (the sum of the faces' cross products, whose lengths are
// twice the areas), normalised in double and converted, one per vertex index.
template <class K>
std::vector<typename K::Vector_3>
pn_default_normals(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  using Vector_3 = typename K::Vector_3;
  std::vector<std::array<double, 3>> sum(mesh.number_of_vertices(), {{0, 0, 0}});
  std::vector<bool> used(mesh.number_of_vertices(), false);
  for (auto f : mesh.faces()) {
    std::vector<typename K::Point_3> p;
    std::vector<std::size_t> v;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
      p.push_back(mesh.point(x));
      v.push_back(static_cast<std::size_t>(x.idx()));
    }
    const Vector_3 c = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const std::array<double, 3> cd{
        {CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z())}};
    for (std::size_t i : v) {
      used[i] = true;
      for (std::size_t k = 0; k < 3; ++k)
        sum[i][k] += cd[k];
    }
  }
  std::vector<Vector_3> normals;
  normals.reserve(sum.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    if (!used[i]) { // an isolated vertex: no patch uses its normal
      normals.emplace_back(0, 0, 1);
      continue;
    }
    const std::array<double, 3>& s = sum[i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(length > 0) || !std::isfinite(length))
      throw Invalid_input("PN triangles: the faces around vertex " + std::to_string(i) +
                          " have a zero (or non-finite) area-weighted normal");
    normals.emplace_back(s[0] / length, s[1] / length, s[2] / length);
  }
  return normals;
}

template <class K>
std::vector<Bezier_triangle<K, typename K::Vector_3>>
pn_triangles_impl(const CGAL::Surface_mesh<typename K::Point_3>& mesh,
                  const std::vector<typename K::Vector_3>& normals) {
  using FT = typename K::FT;
  using Vector_3 = typename K::Vector_3;
  using Point_2 = typename K::Point_2;
  std::vector<Bezier_triangle<K, Vector_3>> patches;
  patches.reserve(mesh.number_of_faces());
  const Point_2 r(0, 0), s(1, 0), t(0, 1);
  for (auto f : mesh.faces()) {
    std::vector<Vector_3> P, N;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
      P.push_back(mesh.point(x) - CGAL::ORIGIN);
      N.push_back(normals[static_cast<std::size_t>(x.idx())]);
    }
    if (P.size() != 3)
      throw Invalid_input("PN triangles: face " + std::to_string(f.idx()) + " has " +
                          std::to_string(P.size()) + " vertices, not 3");
    // b_ijk, i/j/k counting P[0]/P[1]/P[2] (Vlachos et al. 2001, with b_300 = P_1 ...)
    std::vector<Vector_3> net(number_of_control_points(3));
    auto b = [&net](int i, int j, int k) -> Vector_3& {
      return net[linear_index(i, j, i + j + k)];
    };
    b(3, 0, 0) = P[0];
    b(0, 3, 0) = P[1];
    b(0, 0, 3) = P[2];
    b(2, 1, 0) = pn_edge_point<K>(P[0], P[1], N[0]);
    b(1, 2, 0) = pn_edge_point<K>(P[1], P[0], N[1]);
    b(0, 2, 1) = pn_edge_point<K>(P[1], P[2], N[1]);
    b(0, 1, 2) = pn_edge_point<K>(P[2], P[1], N[2]);
    b(1, 0, 2) = pn_edge_point<K>(P[2], P[0], N[2]);
    b(2, 0, 1) = pn_edge_point<K>(P[0], P[2], N[0]);
    // b_111 = E + (E - V)/2: the average E of the six edge points pushed away from the
    // vertex centroid V, which reproduces quadratics (Vlachos et al., §3.1)
    const Vector_3 E =
        (b(2, 1, 0) + b(1, 2, 0) + b(0, 2, 1) + b(0, 1, 2) + b(1, 0, 2) + b(2, 0, 1)) / FT(6);
    const Vector_3 V = (P[0] + P[1] + P[2]) / FT(3);
    b(1, 1, 1) = E + (E - V) / FT(2);
    patches.emplace_back(3, r, s, t, std::move(net));
  }
  return patches;
}

template <class K>
void pn_check_mesh(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  if (mesh.has_garbage())
    throw Invalid_input("PN triangles: the mesh has removed elements (collect the garbage)");
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
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
  \ingroup PkgTriangularSplineSplines
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

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_CLOSED_TRIANGLE_MESH_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_CLOSED_TRIANGLE_MESH_H

#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief one connected component of a closed triangle mesh (Xu §5.2: a triangulated
  polyhedron when the mesh is connected).
*/
struct Closed_mesh_component {
  std::size_t vertices = 0; ///< number of vertices
  std::size_t edges = 0;    ///< number of edges
  std::size_t faces = 0;    ///< number of faces
  long euler = 0;           ///< Euler characteristic \f$V - E + F\f$
  long genus = 0;           ///< \f$(2 - \chi)/2\f$
  bool reoriented = false;  ///< its faces were reversed to make it outward
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief what `prepare_closed_triangle_mesh()` found and changed.
*/
struct Closed_mesh_summary {
  std::size_t vertices = 0;                      ///< number of vertices
  std::size_t edges = 0;                         ///< number of edges
  std::size_t faces = 0;                         ///< number of faces
  std::vector<Closed_mesh_component> components; ///< in the order of `connected_components()`
  std::size_t reoriented = 0;                    ///< number of components reversed
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the halfedge of `e` with the lower index: the orientation every per-edge quantity of
  the package refers to.

  `Surface_mesh` keeps the halfedge an edge descriptor was made from, so `halfedge(edge(h))` is
  `h` itself; per-edge data need one orientation whatever descriptor is at hand.
  \tparam Point_3 the point type
  \param e the edge
  \param mesh the mesh
  \returns the halfedge of `e` with the lower index
*/
template <class Point_3>
typename CGAL::Surface_mesh<Point_3>::Halfedge_index
canonical_halfedge(typename CGAL::Surface_mesh<Point_3>::Edge_index e,
                   const CGAL::Surface_mesh<Point_3>& mesh) {
  const auto h = mesh.halfedge(e), o = mesh.opposite(h);
  return std::size_t(h) < std::size_t(o) ? h : o;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the outgoing halfedges of `v` in counter-clockwise order about the outward normal.

  \f$h_0\f$ is `opposite(halfedge(v))` and \f$h_{i+1} = \f$ `opposite(prev(h_i))`, so that
  `face(h_i)` is the triangle \f$(v, w_i, w_{i+1})\f$ with \f$w_i\f$ = `target(h_i)`: the
  ring order every per-vertex construction of the package uses (Xu §6.2.1).
  \pre `v` is an interior manifold vertex of a triangle mesh
  \tparam Mesh a model of `FaceGraph`
  \param v the vertex
  \param mesh the mesh
  \returns the outgoing halfedges of `v`
*/
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor>
outgoing_ring(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& mesh) {
  // a border vertex would put a border halfedge (no face) into the ring; manifoldness is not
  // cheap to check
  CGAL_precondition(!CGAL::is_border(v, mesh));
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> ring;
  const auto first = opposite(halfedge(v, mesh), mesh);
  auto h = first;
  do {
    ring.push_back(h);
    h = opposite(prev(h, mesh), mesh);
  } while (h != first);
  return ring;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief checks that `mesh` is a closed manifold triangle mesh (Xu §5.2, (D1) and (D2)) with
  finite coordinates and no zero-area face, and orients every connected component outward
  (positive signed volume), reversing the faces of those that are not.

  The predicates are those of the point's kernel: with a kernel with exact predicates the
  verdicts (zero area, orientation) are exact. Several components are accepted; each is
  reported.
  \tparam Point_3 a CGAL point type
  \param mesh the mesh, changed only by the reorientation
  \param context the prefix of error messages (e.g. "pseudo-AG1")
  \param orient reverse the faces of inward components (otherwise they are left as they are,
  and not counted as reoriented)
  \throws Invalid_input naming the first offending element: no face, a non-triangle face, a
  border edge, a non-manifold or isolated vertex, a vertex of valence below 3, a non-finite
  coordinate, a face of zero area, a component of zero volume
  \returns the summary
*/
template <class Point_3>
Closed_mesh_summary prepare_closed_triangle_mesh(CGAL::Surface_mesh<Point_3>& mesh,
                                                 const std::string& context, bool orient = true) {
  using Mesh = CGAL::Surface_mesh<Point_3>;
  using K = typename CGAL::Kernel_traits<Point_3>::Kernel;
  using FT = typename K::FT;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::string prefix = context.empty() ? std::string() : context + ": ";
  if (mesh.has_garbage())
    mesh.collect_garbage();
  if (mesh.number_of_faces() == 0)
    throw Invalid_input(prefix + "the mesh has no face");
  for (auto f : mesh.faces())
    if (CGAL::halfedges_around_face(mesh.halfedge(f), mesh).size() != 3)
      throw Invalid_input(prefix + "face " + std::to_string(std::size_t(f)) + " is not a triangle");
  for (auto v : mesh.vertices())
    if (mesh.is_isolated(v))
      throw Invalid_input(prefix + "vertex " + std::to_string(std::size_t(v)) + " is isolated");
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h))
      throw Invalid_input(prefix + "the mesh is not closed: edge " +
                          std::to_string(std::size_t(mesh.source(h))) + "-" +
                          std::to_string(std::size_t(mesh.target(h))) +
                          " has a single face (meshes with border are not supported)");
  if (!CGAL::is_valid_polygon_mesh(mesh))
    throw Invalid_input(prefix + "the mesh is not a valid polygon mesh");
  // A vertex is manifold iff circulating around it meets every halfedge pointing to it
  // (PMP::is_non_manifold_vertex() costs O(V) per call in CGAL 5.5: quadratic here).
  std::vector<std::size_t> incoming(mesh.number_of_vertices(), 0);
  for (auto h : mesh.halfedges())
    ++incoming[mesh.target(h)];
  for (auto v : mesh.vertices()) {
    const std::string name = "vertex " + std::to_string(std::size_t(v));
    if (incoming[v] != std::size_t(mesh.degree(v)))
      throw Invalid_input(prefix + "the mesh is not manifold at " + name);
    if (mesh.degree(v) < 3)
      throw Invalid_input(prefix + name + " has valence " + std::to_string(mesh.degree(v)) +
                          " (at least 3 needed)");
    const Point_3& p = mesh.point(v);
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(CGAL::to_double(p[i])))
        throw Invalid_input(prefix + name + " has a non-finite coordinate");
  }
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    if (CGAL::collinear(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                        mesh.point(mesh.target(mesh.next(h)))))
      throw Invalid_input(prefix + "face " + std::to_string(std::size_t(f)) +
                          " has zero area (vertices " +
                          std::to_string(std::size_t(mesh.source(h))) + ", " +
                          std::to_string(std::size_t(mesh.target(h))) + ", " +
                          std::to_string(std::size_t(mesh.target(mesh.next(h)))) + ")");
  }

  Closed_mesh_summary summary;
  summary.vertices = mesh.number_of_vertices();
  summary.edges = mesh.number_of_edges();
  summary.faces = mesh.number_of_faces();
  auto component = mesh.template add_property_map<typename Mesh::Face_index, std::size_t>(
                           "f:triangular_spline_component", 0)
                       .first;
  const std::size_t count = PMP::connected_components(mesh, component);
  summary.components.resize(count);
  std::vector<FT> volume(count, FT(0));
  std::vector<std::vector<typename Mesh::Face_index>> faces(count);
  const Point_3 origin = mesh.point(*mesh.vertices().begin());
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    // Six times the signed volume of the tetrahedron (origin, a, b, c); the origin is a mesh
    // vertex so that the terms stay small for meshes far from (0,0,0).
    const auto a = mesh.point(mesh.source(h)) - origin;
    const auto b = mesh.point(mesh.target(h)) - origin;
    const auto c = mesh.point(mesh.target(mesh.next(h))) - origin;
    volume[component[f]] += CGAL::cross_product(a, b) * c;
    faces[component[f]].push_back(f);
    ++summary.components[component[f]].faces;
  }
  std::vector<bool> vertex_seen(mesh.number_of_vertices(), false);
  for (auto e : mesh.edges())
    ++summary.components[component[mesh.face(mesh.halfedge(e))]].edges;
  for (auto v : mesh.vertices())
    ++summary.components[component[mesh.face(mesh.halfedge(v))]].vertices;
  for (std::size_t c = 0; c < count; ++c) {
    auto& info = summary.components[c];
    info.euler = long(info.vertices) - long(info.edges) + long(info.faces);
    info.genus = (2 - info.euler) / 2;
    if (volume[c] == FT(0))
      throw Invalid_input(prefix + "connected component " + std::to_string(c) +
                          " encloses no volume (flat or self-overlapping)");
    if (orient && volume[c] < FT(0)) {
      PMP::reverse_face_orientations(faces[c], mesh);
      info.reoriented = true;
      ++summary.reoriented;
    }
  }
  mesh.remove_property_map(component);
  return summary;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_CLOSED_TRIANGLE_MESH_H

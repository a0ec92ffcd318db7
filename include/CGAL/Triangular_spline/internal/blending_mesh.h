// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_MESH_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_MESH_H

// A polygon mesh read once, through its property maps, into the index arrays that Fang's
// construction (Blending/Mesh_blending_surface.h) and Nielson's comparator need, so that
// neither keeps a copy of the mesh; and the vertex normals both use.

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/array_vector_3.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class Mesh>
struct Is_surface_mesh : std::false_type {};
template <class P>
struct Is_surface_mesh<CGAL::Surface_mesh<P>> : std::true_type {};

// A point or vector with x(), y(), z() of any CGAL kernel, in double.
template <class P>
std::array<double, 3> to_array_3(const P& p) {
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

// The combinatorics and geometry of a polygon mesh, by the indices of its index maps.
struct Blending_mesh {
  std::vector<std::array<double, 3>> position;  // by vertex
  std::vector<std::vector<std::size_t>> around; // vertices_around_target(halfedge(v))
  std::vector<std::array<std::size_t, 2>> ends; // source and target of halfedge(e)
  // corners in vertices_around_face(halfedge(f)) order, and [k] the edge from corner k to
  // corner k + 1
  std::vector<std::vector<std::size_t>> corners, sides;
  std::vector<std::array<double, 3>> given_normal; // empty: none given
};

// Newell's normal of a polygon (corners in order): twice its vector area, exact for planar
// polygons. The terms are summed over the halfedges of the face from halfedge(f), i.e.
// (corner n-1, corner 0), (corner 0, corner 1), ...
template <class Corners>
std::array<double, 3> newell_normal(const std::vector<std::array<double, 3>>& position,
                                    const Corners& corner) {
  std::array<double, 3> n{{0, 0, 0}};
  const std::size_t size = corner.size();
  for (std::size_t k = 0; k < size; ++k) {
    const std::array<double, 3>& p = position[corner[(k + size - 1) % size]];
    const std::array<double, 3>& q = position[corner[k]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

// The unit vertex normals of the mesh blending constructions, by vertex index: the given
// ones normalised (they must agree with the orientation of the faces), otherwise the
// normalised mean of the unit normals of the incident faces (Fang §8.2). `degree[v]` is the
// number of halfedges around v (the scale of the cancellation test); `who` prefixes the
// error messages.
template <class Faces>
std::vector<std::array<double, 3>>
blending_vertex_normals(const std::vector<std::array<double, 3>>& position, const Faces& faces,
                        const std::vector<std::size_t>& degree,
                        const std::vector<std::array<double, 3>>& given, const std::string& who) {
  auto name = [](std::size_t v) { return "vertex " + std::to_string(v); };
  const std::size_t V = position.size();
  // the orientation reference: mean unit face normal
  std::vector<std::array<double, 3>> sum(V, std::array<double, 3>{{0, 0, 0}});
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<double, 3> n = newell_normal(position, faces[f]);
    const double length = norm(n);
    if (!(length > 0))
      throw Invalid_input(who + ": face " + std::to_string(f) + " has zero area");
    n = scaled(n, 1 / length);
    for (std::size_t v : faces[f])
      for (std::size_t c = 0; c < 3; ++c)
        sum[v][c] += n[c];
  }
  std::vector<std::array<double, 3>> normals(V, std::array<double, 3>{{0, 0, 1}});
  for (std::size_t v = 0; v < V; ++v) {
    const double le = norm(sum[v]);
    std::array<double, 3> n = sum[v];
    if (!given.empty()) {
      n = given[v];
      const double length = norm(n);
      if (!std::isfinite(length) || !(length > 0))
        throw Invalid_input(who + ": the normal of " + name(v) + " is zero or not finite");
      n = scaled(n, 1 / length);
      if (le > 0 && !(dot(n, sum[v]) > 0))
        throw Invalid_input(who + ": the normal of " + name(v) +
                            " points against the orientation of its faces");
    } else {
      if (!(le > 1e-12 * std::sqrt(double(degree[v]))))
        throw Invalid_input(who + ": the estimated normal of " + name(v) +
                            " vanishes (its face normals cancel)");
      n = scaled(n, 1 / le);
    }
    normals[v] = n;
  }
  return normals;
}

// Indices 0, ..., n - 1, each once: what the arrays above are indexed by.
template <class Range, class IndexMap>
bool is_index_range(const Range& range, IndexMap index, std::size_t n) {
  std::vector<char> seen(n, 0);
  std::size_t count = 0;
  for (auto x : range) {
    const std::size_t i = static_cast<std::size_t>(get(index, x));
    if (i >= n || seen[i])
      return false;
    seen[i] = 1;
    ++count;
  }
  return count == n;
}

// The property "v:normal" (the kernel's Vector_3) of a Surface_mesh by the vertex indices
// of `index`, or nothing if it has none: the package's convention for normals read from
// files.
template <class P, class VertexIndexMap>
std::vector<std::array<double, 3>> surface_mesh_normals(const CGAL::Surface_mesh<P>& mesh,
                                                        VertexIndexMap index) {
  using Mesh = CGAL::Surface_mesh<P>;
  using Vector_3 = typename CGAL::Kernel_traits<P>::Kernel::Vector_3;
  std::vector<std::array<double, 3>> normals;
  const auto given = mesh.template property_map<typename Mesh::Vertex_index, Vector_3>("v:normal");
  if (given.second) {
    normals.resize(mesh.number_of_vertices());
    for (auto v : mesh.vertices())
      normals[static_cast<std::size_t>(get(index, v))] = to_array_3(get(given.first, v));
  }
  return normals;
}

// The edge_index_map of `np`, or the edges numbered in the order of edges(mesh) (the index
// of a Surface_mesh without removed elements). Not get_initialized_edge_index_map(): in
// CGAL 5.5 it picks the internal map of a Polyhedron_3 even when its halfedges have no id().
template <class PolygonMesh, class NamedParameters>
auto edge_index_map(const PolygonMesh& mesh, const NamedParameters& np) {
  using Edge = typename boost::graph_traits<PolygonMesh>::edge_descriptor;
  if constexpr (!parameters::is_default_parameter<NamedParameters,
                                                  CGAL::internal_np::edge_index_t>::value) {
    return parameters::get_parameter(np, CGAL::internal_np::edge_index);
  } else {
    auto index = get(CGAL::dynamic_edge_property_t<std::size_t>(), mesh);
    std::size_t i = 0;
    for (Edge e : edges(mesh))
      put(index, e, i++);
    return index;
  }
}

// Reads `mesh` through the maps of `np` (vertex_point_map, vertex_normal_map,
// vertex/edge/face_index_map), after the checks of Mesh_blending_surface; a Surface_mesh
// without a vertex_normal_map gives its property "v:normal" if it has one.
template <class PolygonMesh, class NamedParameters>
Blending_mesh read_blending_mesh(const PolygonMesh& mesh, const NamedParameters& np,
                                 const std::string& who) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  using Traits = boost::graph_traits<PolygonMesh>;
  auto vertex_name = [](std::size_t v) { return "vertex " + std::to_string(v); };

  if constexpr (Is_surface_mesh<PolygonMesh>::value)
    if (mesh.has_garbage())
      throw Invalid_input(who + ": the mesh has removed elements (collect the garbage first)");
  if (faces(mesh).first == faces(mesh).second)
    throw Invalid_input(who + ": the mesh has no face");
  if (!CGAL::is_valid_polygon_mesh(mesh))
    throw Invalid_input(who + ": the mesh is not a valid polygon mesh");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const auto eim = edge_index_map(mesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  const std::size_t V = static_cast<std::size_t>(num_vertices(mesh));
  const std::size_t E = static_cast<std::size_t>(num_edges(mesh));
  const std::size_t F = static_cast<std::size_t>(num_faces(mesh));
  if (!is_index_range(vertices(mesh), vim, V) || !is_index_range(edges(mesh), eim, E) ||
      !is_index_range(faces(mesh), fim, F))
    throw Invalid_input(who + ": the vertex, edge or face indices are not 0, ..., n - 1");
  for (auto v : vertices(mesh)) {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if (halfedge(v, mesh) == Traits::null_halfedge())
      throw Invalid_input(who + ": " + vertex_name(i) + " has no incident face");
    if (CGAL::Polygon_mesh_processing::is_non_manifold_vertex(v, mesh))
      throw Invalid_input(who + ": the mesh is not manifold at " + vertex_name(i) +
                          " (several umbrellas of faces meet there)");
  }

  Blending_mesh m;
  m.position.resize(V);
  m.around.resize(V);
  for (auto v : vertices(mesh)) {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    m.position[i] = to_array_3(get(vpm, v));
    for (double x : m.position[i])
      if (!std::isfinite(x))
        throw Invalid_input(who + ": " + vertex_name(i) + " has a coordinate that is not finite");
    for (auto w : CGAL::vertices_around_target(halfedge(v, mesh), mesh))
      m.around[i].push_back(static_cast<std::size_t>(get(vim, w)));
  }
  m.ends.resize(E);
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    m.ends[static_cast<std::size_t>(get(eim, e))] = {
        {static_cast<std::size_t>(get(vim, source(h, mesh))),
         static_cast<std::size_t>(get(vim, target(h, mesh)))}};
  }
  m.corners.resize(F);
  m.sides.resize(F);
  for (auto f : faces(mesh)) {
    const std::size_t i = static_cast<std::size_t>(get(fim, f));
    // corner k is target(h_k), h_k = next^k(halfedge(f)); the side from corner k to k + 1 is
    // h_{k+1}
    for (auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      m.corners[i].push_back(static_cast<std::size_t>(get(vim, target(h, mesh))));
      m.sides[i].push_back(static_cast<std::size_t>(get(eim, edge(next(h, mesh), mesh))));
    }
  }

  constexpr bool has_normals =
      !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value;
  if constexpr (has_normals) {
    const auto normals = get_parameter(np, CGAL::internal_np::vertex_normal_map);
    m.given_normal.resize(V);
    for (auto v : vertices(mesh))
      m.given_normal[static_cast<std::size_t>(get(vim, v))] = to_array_3(get(normals, v));
  } else if constexpr (Is_surface_mesh<PolygonMesh>::value) {
    m.given_normal = surface_mesh_normals(mesh, vim);
  }
  return m;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_MESH_H

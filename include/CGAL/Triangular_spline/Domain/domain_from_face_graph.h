// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_FACE_GRAPH_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_FACE_GRAPH_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the planar domain of a triangulated face graph (a `CGAL::Surface_mesh`,
  `CGAL::Polyhedron_3`, ... through CGAL's BGL interface) whose vertex points give the
  domain by their \f$(x, y)\f$ coordinates, and, for 3D points, their \f$z\f$ as data
  values (empty for 2D points).

  Coordinates are converted to `GeomTraits` exactly (`Cartesian_converter`), so an exact
  kernel sees the mesh's numbers as they are. Domain vertex `i` is the `i`-th vertex of
  `vertices(graph)`.
  \tparam FaceGraph a model of `FaceGraph`
  \tparam VertexPointMap a readable property map from vertices to 2D or 3D CGAL points
  \tparam GeomTraits a model of `Kernel`, the kernel of the domain
  \throws Invalid_input if a face is not a triangle, or the projection violates the
  `Planar_domain` rules (duplicate points, zero-area or folded triangles, non-manifold)
  \param graph the triangulated face graph
  \param vpm the vertex point property map of `graph`
  \returns the domain and the data values
*/
template <class GeomTraits, class FaceGraph, class VertexPointMap>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
domain_from_face_graph(const FaceGraph& graph, VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Input_kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Index = typename Planar_domain<GeomTraits>::Index;
  constexpr int dimension = CGAL::Ambient_dimension<Point>::value;
  const CGAL::Cartesian_converter<Input_kernel, GeomTraits> convert;

  std::map<vertex_descriptor, Index> index;
  std::vector<typename GeomTraits::Point_2> points;
  std::vector<typename GeomTraits::FT> values;
  for (vertex_descriptor v : vertices(graph)) {
    const Point& p = get(vpm, v);
    index.emplace(v, static_cast<Index>(points.size()));
    points.emplace_back(convert(p.x()), convert(p.y()));
    if constexpr (dimension == 3)
      values.push_back(convert(p.z()));
  }
  std::vector<std::array<Index, 3>> triangles;
  std::size_t face_number = 0;
  for (auto f : faces(graph)) {
    std::vector<Index> corners;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, graph), graph))
      corners.push_back(index.at(v));
    if (corners.size() != 3)
      throw Invalid_input("face graph: face " + std::to_string(face_number) + " has " +
                          std::to_string(corners.size()) +
                          " vertices; only triangles are supported");
    triangles.push_back({{corners[0], corners[1], corners[2]}});
    ++face_number;
  }
  return {Planar_domain<GeomTraits>(std::move(points), std::move(triangles)), std::move(values)};
}

/// returns `domain_from_face_graph(graph, get(CGAL::vertex_point, graph))`.
/// \tparam GeomTraits a model of `Kernel`, the kernel of the domain
/// \tparam FaceGraph a model of `FaceListGraph`
/// \param graph the triangulated face graph
/// \returns the domain and the data values
template <class GeomTraits, class FaceGraph>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
domain_from_face_graph(const FaceGraph& graph) {
  return domain_from_face_graph<GeomTraits>(graph, get(CGAL::vertex_point, graph));
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_FACE_GRAPH_H

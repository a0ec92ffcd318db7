// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/internal/hilbert_order.h>

#include <CGAL/Unique_hash_map.h>
#include <CGAL/hilbert_sort.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the domain made of the finite faces of a CGAL 2D triangulation for which
  `in_domain(face_handle)` is `true` (e.g. the faces inside a constrained triangulation's
  polygon, marked by nesting level), and writes into `vertex_map` the triangulation vertex
  handle of each domain vertex.
  \tparam Triangulation a `CGAL::Triangulation_2` (Delaunay, constrained, ...) whose
  points are `GeomTraits::Point_2`
  \tparam GeomTraits a model of `Kernel`
  \tparam InDomain a predicate on the triangulation's face handles
  \tparam VertexHandles a `std::vector` of the triangulation's vertex handles
  \param triangulation the CGAL 2D triangulation
  \param in_domain the predicate on face handles selecting the faces of the domain
  \param vertex_map receives the triangulation vertex handle of each domain vertex
  \returns the domain
*/
template <class GeomTraits, class Triangulation, class InDomain, class VertexHandles>
Planar_domain<GeomTraits> domain_from_triangulation_2(const Triangulation& triangulation,
                                                      const InDomain& in_domain,
                                                      VertexHandles& vertex_map) {
  return domain_from_triangulation_2<GeomTraits>(
      triangulation, in_domain, vertex_map,
      [](typename Triangulation::Vertex_handle v) -> const typename GeomTraits::Point_2& {
        return v->point();
      });
}

/*!
  \ingroup PkgTriangularSplineDomain
  \brief as above, with the domain's points given by `point_of(v)` for each vertex handle
  `v` (a triangulation of the same points in another kernel, its vertices carrying an
  index into the caller's points, as `delaunay_domain()` builds for exact number types).
  \tparam PointOf a function object from a vertex handle to a `GeomTraits::Point_2`
  \param triangulation the CGAL 2D triangulation
  \param in_domain the predicate on face handles selecting the faces of the domain
  \param vertex_map receives the triangulation vertex handle of each domain vertex
  \param point_of the point of each vertex handle
  \returns the domain
*/
template <class GeomTraits, class Triangulation, class InDomain, class VertexHandles, class PointOf>
Planar_domain<GeomTraits>
domain_from_triangulation_2(const Triangulation& triangulation, const InDomain& in_domain,
                            VertexHandles& vertex_map, const PointOf& point_of) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  constexpr Index none = Planar_domain<GeomTraits>::null_index;
  using Point_2 = typename GeomTraits::Point_2;
  // Vertices are numbered along a Hilbert curve: neighbours get near indices, which keeps
  // every later pass over the domain cache-friendly. A hash map by handle, not a std::map.
  CGAL::Unique_hash_map<Vertex_handle, Index> index(none, triangulation.number_of_vertices());
  std::vector<Point_2> points;
  vertex_map.clear();
  if constexpr (std::is_floating_point_v<typename GeomTraits::FT>) {
    std::vector<std::pair<Point_2, Vertex_handle>> used;
    for (auto f : triangulation.finite_face_handles())
      if (in_domain(f))
        for (int i = 0; i < 3; ++i)
          if (index[f->vertex(i)] == none) {
            index[f->vertex(i)] = 0;
            used.emplace_back(point_of(f->vertex(i)), f->vertex(i));
          }
    CGAL::hilbert_sort(used.begin(), used.end(),
                       internal::Lexicographic_hilbert_traits<GeomTraits, Vertex_handle>(),
                       CGAL::Hilbert_sort_median_policy());
    points.reserve(used.size());
    for (const auto& [point, v] : used) {
      index[v] = static_cast<Index>(points.size());
      points.push_back(point);
      vertex_map.push_back(v);
    }
  } else { // the same order, on indices, comparisons by intervals first
    std::vector<Point_2> used;
    std::vector<internal::Coordinate_intervals> intervals;
    std::vector<Vertex_handle> handles;
    for (auto f : triangulation.finite_face_handles())
      if (in_domain(f))
        for (int i = 0; i < 3; ++i)
          if (index[f->vertex(i)] == none) {
            index[f->vertex(i)] = 0;
            used.push_back(point_of(f->vertex(i)));
            intervals.push_back(internal::coordinate_intervals(used.back()));
            handles.push_back(f->vertex(i));
          }
    std::vector<std::uint32_t> order(used.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = static_cast<std::uint32_t>(i);
    CGAL::hilbert_sort(order.begin(), order.end(),
                       internal::Indexed_hilbert_traits<GeomTraits>{&used, &intervals},
                       CGAL::Hilbert_sort_median_policy());
    points.reserve(used.size());
    for (std::uint32_t i : order) {
      index[handles[i]] = static_cast<Index>(points.size());
      points.push_back(used[i]); // a copy: its limbs allocated in Hilbert order, near each other
      vertex_map.push_back(handles[i]);
    }
  }
  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(triangulation.number_of_faces());
  for (auto f : triangulation.finite_face_handles())
    if (in_domain(f))
      triangles.push_back({index[f->vertex(0)], index[f->vertex(1)], index[f->vertex(2)]});
  // Each face starts at its smallest vertex (the triangulation's rotation depends on the
  // insertion order), and faces are sorted: near faces get near indices too, and the order
  // is total (distinct faces differ as rotated triples), the same for every input order.
  for (auto& t : triangles)
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
  // A triangulation's faces are embedded: no overlap test needed.
  return Planar_domain<GeomTraits>(std::move(points), std::move(triangles), GeomTraits(), false);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H

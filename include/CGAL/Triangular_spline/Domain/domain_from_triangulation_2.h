// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/internal/hilbert_order.h>
#include <CGAL/Triangular_spline/internal/release.h>

#include <CGAL/Unique_hash_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

namespace internal {

// Each face made to start at its smallest vertex (a triangulation's rotation depends on the
// insertion order), and the faces sorted: near faces get near indices too, and the order is
// total (distinct faces differ as rotated triples), the same for every input order. Sorted
// by a counting sort on the first vertex, then each vertex's few faces by the other two
// (std::sort of the 2 million faces of 10^6 points: 0.2 s).
template <class Index>
void sort_faces(std::vector<std::array<Index, 3>>& triangles, std::size_t vertices) {
  for (auto& t : triangles)
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  // at[v + 1]: the start of the faces of first vertex v (counted, then summed); placing
  // them advances it to the start of v + 1's, so that at[v] ends as the start of v's
  std::vector<std::size_t> at(vertices + 2, 0);
  for (const auto& t : triangles)
    ++at[t[0] + 2];
  for (std::size_t v = 2; v < at.size(); ++v)
    at[v] += at[v - 1];
  std::vector<std::array<Index, 3>> sorted(triangles.size());
  for (const auto& t : triangles)
    sorted[at[t[0] + 1]++] = t;
  for (std::size_t v = 0; v < vertices; ++v)
    for (std::size_t i = at[v] + 1; i < at[v + 1]; ++i)
      for (std::size_t j = i; j > at[v] && sorted[j] < sorted[j - 1]; --j)
        std::swap(sorted[j], sorted[j - 1]);
  triangles = std::move(sorted);
}

// The domain of the faces of `triangulation` for which in_domain(face) is true, when its
// vertices are numbered already: index_of(v) is vertex v's index, points[index_of(v)] its
// point. The numbering of domain_from_triangulation_2() is that of the points sorted in its
// Hilbert order beforehand (delaunay_domain() inserts them in that order), and then neither
// its hash map of vertex handles nor its sort is needed. Empty (points untouched) if some
// point is on no face of the domain: that numbering then skips it.
template <class GeomTraits, class Triangulation, class InDomain, class IndexOf>
std::optional<Planar_domain<GeomTraits>>
domain_from_numbered_triangulation(const Triangulation& triangulation, const InDomain& in_domain,
                                   std::vector<typename GeomTraits::Point_2>& points,
                                   const IndexOf& index_of) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(triangulation.number_of_faces());
  std::vector<char> used(points.size(), 0);
  for (auto f : triangulation.finite_face_handles())
    if (in_domain(f)) {
      const std::array<Index, 3> t{{static_cast<Index>(index_of(f->vertex(0))),
                                    static_cast<Index>(index_of(f->vertex(1))),
                                    static_cast<Index>(index_of(f->vertex(2)))}};
      for (Index v : t)
        used[v] = 1;
      triangles.push_back(t);
    }
  if (std::find(used.begin(), used.end(), 0) != used.end())
    return std::nullopt;
  release(used);
  sort_faces(triangles, points.size());
  // (rotated, each face keeps its orientation: still counter-clockwise)
  return Planar_domain<GeomTraits>(Triangulation_faces_tag(), std::move(points),
                                   std::move(triangles));
}

} // namespace internal

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
  std::vector<Point_2> used;
  std::vector<Vertex_handle> handles;
  for (auto f : triangulation.finite_face_handles())
    if (in_domain(f))
      for (int i = 0; i < 3; ++i)
        if (index[f->vertex(i)] == none) {
          index[f->vertex(i)] = 0;
          used.push_back(point_of(f->vertex(i)));
          handles.push_back(f->vertex(i));
        }
  const std::vector<std::uint32_t> order = internal::hilbert_permutation<GeomTraits>(used);
  std::vector<Point_2> points;
  points.reserve(used.size());
  vertex_map.clear();
  for (std::uint32_t i : order) {
    index[handles[i]] = static_cast<Index>(points.size());
    points.push_back(used[i]); // a copy: exact limbs allocated in Hilbert order, near each other
    vertex_map.push_back(handles[i]);
  }
  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(triangulation.number_of_faces());
  for (auto f : triangulation.finite_face_handles())
    if (in_domain(f))
      triangles.push_back({index[f->vertex(0)], index[f->vertex(1)], index[f->vertex(2)]});
  internal::sort_faces(triangles, points.size());
  // A triangulation's faces are embedded: no overlap test needed.
  return Planar_domain<GeomTraits>(std::move(points), std::move(triangles), GeomTraits(), false);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_FROM_TRIANGULATION_2_H

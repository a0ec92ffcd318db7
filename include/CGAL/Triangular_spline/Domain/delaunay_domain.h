// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DELAUNAY_DOMAIN_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DELAUNAY_DOMAIN_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Domain/Scattered_data.h>
#include <CGAL/Triangular_spline/Domain/domain_from_triangulation_2.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/release.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Filtered_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Unique_hash_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <queue>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/// the largest sine of the angles at its boundary edge of a hull triangle that
/// `delaunay_domain()` removes as flat: half `Domain_locator::snap_edge_tolerance`, so that
/// a query in a removed triangle, within that sine times an edge's length of the new
/// boundary, is snapped
constexpr double flat_hull_sine = 5e-10;

namespace internal {

// The flat triangles closing the hull of `triangulation` (see delaunay_domain()): the faces
// removed, peeled from the outside in. A face is a candidate when exactly one of its
// neighbours is outside (infinite or removed) and its apex, the vertex opposite that edge,
// has no face outside: removing it keeps the domain a disc with every vertex. Candidates are
// taken smallest first by their points in lexicographic order, so the result depends only
// on the triangulation (which CGAL makes depend on the point set alone).
// point_of(v): the point of vertex handle v the decisions are taken on (the triangulation's
// own, or the caller's where it triangulates other points of the same values).
template <class Delaunay, class PointOf>
CGAL::Unique_hash_map<typename Delaunay::Face_handle, bool>
flat_hull_faces_of(const Delaunay& triangulation, double max_sine, const PointOf& point_of) {
  using Face_handle = typename Delaunay::Face_handle;
  using Point = std::decay_t<decltype(point_of(triangulation.infinite_vertex()))>;
  CGAL::Unique_hash_map<Face_handle, bool> removed;
  auto outside = [&](Face_handle f) {
    return triangulation.is_infinite(f) || removed.is_defined(f);
  };
  // The apex's index when f is a flat candidate, else -1.
  auto flat_apex = [&](Face_handle f) -> int {
    if (outside(f))
      return -1;
    int apex = -1;
    for (int i = 0; i < 3; ++i)
      if (outside(f->neighbor(i))) {
        if (apex >= 0)
          return -1;
        apex = i;
      }
    if (apex < 0)
      return -1;
    // Sines of the angles at the boundary edge (a, b), in double: for a nearly collinear
    // triple the cross product's error is about 1e-16 of |b - a| |c - a|, far below the bound.
    const Point &a = point_of(f->vertex(Delaunay::ccw(apex))),
                &b = point_of(f->vertex(Delaunay::cw(apex))), &c = point_of(f->vertex(apex));
    const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
    const double bx = CGAL::to_double(b.x()) - ax, by = CGAL::to_double(b.y()) - ay;
    const double cx = CGAL::to_double(c.x()) - ax, cy = CGAL::to_double(c.y()) - ay;
    const double cross = std::abs(bx * cy - by * cx), ab = std::hypot(bx, by);
    const double ac = std::hypot(cx, cy), bc = std::hypot(cx - bx, cy - by);
    if (!(cross <= max_sine * ab * ac && cross <= max_sine * ab * bc))
      return -1;
    auto faces = triangulation.incident_faces(f->vertex(apex)), end = faces;
    do {
      if (outside(faces))
        return -1;
    } while (++faces != end);
    return apex;
  };
  using Key = std::array<Point, 3>;
  auto key = [&](Face_handle f) {
    Key k{{point_of(f->vertex(0)), point_of(f->vertex(1)), point_of(f->vertex(2))}};
    std::sort(k.begin(), k.end(), [](const Point& p, const Point& q) {
      return CGAL::compare_xy(p, q) == CGAL::SMALLER;
    });
    return k;
  };
  auto later = [](const std::pair<Key, Face_handle>& x, const std::pair<Key, Face_handle>& y) {
    for (int i = 0; i < 3; ++i) {
      const CGAL::Comparison_result c = CGAL::compare_xy(x.first[i], y.first[i]);
      if (c != CGAL::EQUAL)
        return c == CGAL::LARGER;
    }
    return false;
  };
  std::priority_queue<std::pair<Key, Face_handle>, std::vector<std::pair<Key, Face_handle>>,
                      decltype(later)>
      queue(later);
  auto circulator = triangulation.incident_faces(triangulation.infinite_vertex()), end = circulator;
  do {
    const Face_handle inner =
        circulator->neighbor(circulator->index(triangulation.infinite_vertex()));
    if (flat_apex(inner) >= 0)
      queue.emplace(key(inner), inner);
  } while (++circulator != end);
  while (!queue.empty()) {
    const Face_handle f = queue.top().second;
    queue.pop();
    const int apex = flat_apex(f); // again: an earlier removal may have changed it
    if (apex < 0)
      continue;
    removed[f] = true;
    for (int i = 0; i < 3; ++i)
      if (i != apex && flat_apex(f->neighbor(i)) >= 0)
        queue.emplace(key(f->neighbor(i)), f->neighbor(i));
  }
  return removed;
}

// delaunay_domain() with the triangulation in kernel Traits over to_traits(p) of the data
// points; every decision after it (flat hull faces, numbering) reads the data's own points.
template <class Traits, class GeomTraits, class ToTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
delaunay_domain_in(const Scattered_data<GeomTraits>& data, std::vector<std::size_t>* input_index,
                   std::size_t* flat_hull_faces, const ToTraits& to_traits) {
  using FT = typename GeomTraits::FT;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Traits>;
  using Fb = CGAL::Triangulation_face_base_2<Traits>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Traits, Tds>;
  // The points are inserted in the Hilbert order in which domain_from_triangulation_2()
  // numbers the vertices, each vertex carrying its number: the domain then needs neither that
  // function's hash map of vertex handles nor its second sort, and CGAL's spatial sort of the
  // points (and copies of them) is not needed either (10^6 points, with the domain's edges
  // built vertex by vertex: 1.7 s instead of 2.5 to read and triangulate, paired runs). The
  // triangulation is the same in any insertion order: CGAL breaks cocircular ties by a
  // symbolic perturbation.
  if (data.points.size() >= std::size_t(Planar_domain<GeomTraits>::null_index))
    throw Invalid_input("scattered data: too many points (" + std::to_string(data.points.size()) +
                        ")");
  const std::vector<std::uint32_t> order = hilbert_permutation<GeomTraits>(data.points);
  Delaunay triangulation;
  {
    typename Delaunay::Face_handle hint;
    for (std::size_t r = 0; r < order.size(); ++r) {
      const typename Delaunay::Vertex_handle v =
          triangulation.insert(to_traits(data.points[order[r]]), hint);
      v->info() = r; // (a repeated point's vertex: the count below finds it)
      hint = v->face();
    }
  }
  if (triangulation.number_of_vertices() != data.points.size())
    throw Invalid_input("scattered data: " +
                        std::to_string(data.points.size() - triangulation.number_of_vertices()) +
                        " points repeat an earlier point");
  if (triangulation.dimension() < 2)
    throw Invalid_input("scattered data: all " + std::to_string(data.points.size()) +
                        " points are collinear: no triangle");
  auto point_of = [&](typename Delaunay::Vertex_handle v) -> const typename GeomTraits::Point_2& {
    return data.points[order[v->info()]];
  };
  const CGAL::Unique_hash_map<typename Delaunay::Face_handle, bool> removed =
      flat_hull_faces_of(triangulation, flat_hull_sine, point_of);
  if (flat_hull_faces) {
    *flat_hull_faces = 0;
    for (auto f : triangulation.finite_face_handles())
      *flat_hull_faces += removed.is_defined(f) ? 1 : 0;
  }
  auto in_domain = [&](typename Delaunay::Face_handle f) { return !removed.is_defined(f); };
  std::vector<typename GeomTraits::Point_2> points;
  points.reserve(order.size());
  for (std::uint32_t i : order)
    points.push_back(data.points[i]);
  std::optional<Planar_domain<GeomTraits>> numbered =
      domain_from_numbered_triangulation<GeomTraits>(
          triangulation, in_domain, points,
          [](typename Delaunay::Vertex_handle v) { return v->info(); });
  std::vector<std::size_t> index; // the data point of each domain vertex
  if (numbered) {
    index.assign(order.begin(), order.end());
  } else { // a point on no face (not seen: a removed flat face keeps its corners on others)
    std::vector<typename Delaunay::Vertex_handle> handles;
    numbered.emplace(
        domain_from_triangulation_2<GeomTraits>(triangulation, in_domain, handles, point_of));
    for (const auto& h : handles)
      index.push_back(order[h->info()]);
  }
  std::vector<FT> values;
  values.reserve(index.size());
  for (std::size_t i : index)
    values.push_back(data.values[i]);
  if (input_index)
    *input_index = std::move(index);
  return {std::move(*numbered), std::move(values)};
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineDomain
  \brief returns the Delaunay triangulation of the data points as a `Planar_domain`, with the
  data value of each domain vertex.

  The triangulation is `CGAL::Delaunay_triangulation_2` (for cocircular points CGAL's
  deterministic choice); its domain is the convex hull of the points, less the flat
  triangles that close it where hull points lie on a line only up to rounding (a grid
  jittered by round-off, rotated or reprojected): a boundary triangle whose two angles at
  its boundary edge both have sines of at most `flat_hull_sine` (\f$5 \cdot 10^{-10}\f$),
  and whose apex is an interior vertex, is removed, and so on inwards (each removal makes
  the apex a boundary vertex; candidates are taken in lexicographic order of their points,
  so the domain does not depend on the input order). Every point stays a vertex, and a
  query in a removed triangle lies within that sine times an edge's length of the new
  boundary, inside `Domain_locator`'s snapping tolerance. On a \f$129^2\f$ grid jittered
  by \f$10^{-9}\f$ of a cell, 429 such triangles had made the default fit's error
  \f$1.4 \cdot 10^{-5}\f$ and nine of their edges miss \f$C^1\f$ by up to
  \f$1.6 \cdot 10^{-4}\f$ in `double`; without them \f$10^{-11}\f$ and round-off.

  Domain vertex `v` is the input point carrying value `second[v]`; vertex indices follow a
  Hilbert curve through the points (ties broken by the other coordinate), so that neither
  the indices nor the triangles depend on the input order.
  \tparam GeomTraits a model of `DelaunayTriangulationTraits_2` and `Kernel`
  \throws Invalid_input if `points` and `values` differ in size, two points coincide, or all
  points are collinear (data from `read_xyz()` passes these checks)
  \param data the scattered data
  \param input_index if not null, receives the index in `data` of the point of each domain
  vertex
  \param flat_hull_faces if not null, receives the number of flat hull triangles removed
  \returns the Delaunay triangulation of the data points as a `Planar_domain`, with the data
  value of each domain vertex
*/
template <class GeomTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
delaunay_domain(const Scattered_data<GeomTraits>& data,
                std::vector<std::size_t>* input_index = nullptr,
                std::size_t* flat_hull_faces = nullptr) {
  using FT = typename GeomTraits::FT;
  if (data.points.size() != data.values.size())
    throw Invalid_input("scattered data: " + std::to_string(data.points.size()) + " points but " +
                        std::to_string(data.values.size()) + " values");
  // An exact kernel without filtered predicates (Simple_cartesian<Exact_rational>) triangulates
  // with filtered predicates: intervals first, rationals only where they cannot decide. The
  // points and the answers are the same, so is the triangulation. Points of Epeck's lazy
  // numbers carry their intervals, where a filtered adaptor converts every rational
  // coordinate again at each comparison and orientation test (2 10^4 decimal points: 0.04
  // against 1.0 s; 10^4: 0.54 s unfiltered); other exact types use the adaptor.
  constexpr bool exact_unfiltered = CGAL::Algebraic_structure_traits<FT>::Is_exact::value &&
                                    !std::is_floating_point_v<FT> &&
                                    !GeomTraits::Has_filtered_predicates;
  if constexpr (exact_unfiltered && std::is_same_v<FT, typename CGAL::Epeck::FT::ET>) {
    return internal::delaunay_domain_in<CGAL::Epeck>(
        data, input_index, flat_hull_faces, [&](const typename GeomTraits::Point_2& p) {
          return CGAL::Epeck::Point_2(CGAL::Epeck::FT(p.x()), CGAL::Epeck::FT(p.y()));
        });
  } else {
    using Traits = std::conditional_t<exact_unfiltered,
                                      CGAL::Filtered_kernel_adaptor<GeomTraits, false>, GeomTraits>;
    return internal::delaunay_domain_in<Traits>(
        data, input_index, flat_hull_faces,
        [](const typename GeomTraits::Point_2& p) -> const typename GeomTraits::Point_2& {
          return p;
        });
  }
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DELAUNAY_DOMAIN_H

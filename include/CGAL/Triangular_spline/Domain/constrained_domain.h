// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_CONSTRAINED_DOMAIN_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_CONSTRAINED_DOMAIN_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/Domain/domain_from_triangulation_2.h>
#include <CGAL/Triangular_spline/internal/polygon_checks.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>
#include <CGAL/box_intersection_d.h>

#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief triangulates a polygonal region with holes, and points inside it, by a constrained
  Delaunay triangulation.

  `polygons[0]` is the outer boundary and every further polygon a hole; each is a closed
  polygon given by its vertices (either orientation, collinear consecutive vertices allowed:
  they subdivide a straight boundary stretch). The triangulation is
  `CGAL::Constrained_Delaunay_triangulation_2` with every polygon edge as a constraint and
  `extra_points` inserted; its faces are marked by nesting level (breadth-first search
  across constrained edges, as in CGAL's `polygon_triangulation.cpp` example, since CGAL 5.5
  has no `mark_domain_in_triangulation()`) and the faces of odd level form the domain.
  Points are inserted one by one in input order, so the same input always gives the same
  triangulation, with any kernel whose predicates are exact, even for cocircular points.

  \tparam GeomTraits a model of `Kernel`
  \param polygons the outer boundary, then the holes
  \param extra_points points strictly inside the domain (neither outside nor on the
  boundary nor in a hole); a point repeated in this list becomes one vertex
  \return the domain, and for each domain vertex `v` the index `second[v]` of its point in
  the concatenation of the polygons' vertices (in order) and then `extra_points`, so that
  values given with the input points are easily attached to the domain vertices
  \throws Invalid_input if a polygon has fewer than 3 vertices, repeats a vertex, is not
  simple, or touches another one; if a hole is not inside the outer boundary or lies inside
  another hole; if an extra point is not strictly inside the domain (the message names the
  point and where it lies); and if `Planar_domain` rejects the result
*/
template <class GeomTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<std::size_t>>
constrained_domain(const std::vector<std::vector<typename GeomTraits::Point_2>>& polygons,
                   const std::vector<typename GeomTraits::Point_2>& extra_points) {
  using Vb = CGAL::Triangulation_vertex_base_2<GeomTraits>;
  using Fb_info = CGAL::Triangulation_face_base_with_info_2<int, GeomTraits>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<GeomTraits, Fb_info>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds>;
  using Vertex_handle = typename CDT::Vertex_handle;
  using Face_handle = typename CDT::Face_handle;
  using Edge = typename CDT::Edge;

  internal::check_polygons<GeomTraits>(polygons);

  CDT cdt;
  std::map<Vertex_handle, std::size_t> input_index;
  std::size_t next_index = 0;
  Face_handle hint;
  auto insert = [&](const typename GeomTraits::Point_2& p) {
    const Vertex_handle v = cdt.insert(p, hint);
    hint = v->face();
    input_index.emplace(v, next_index++);
    return v;
  };
  for (const auto& polygon : polygons) {
    std::vector<Vertex_handle> vertices;
    for (const auto& p : polygon)
      vertices.push_back(insert(p));
    for (std::size_t i = 0; i < vertices.size(); ++i)
      cdt.insert_constraint(vertices[i], vertices[(i + 1) % vertices.size()]);
  }
  std::vector<Vertex_handle> extra;
  for (const auto& p : extra_points)
    extra.push_back(insert(p));

  // Nesting levels: 0 for the faces reached from the infinite face without crossing a
  // constraint, +1 for each constrained edge crossed.
  for (Face_handle f : cdt.all_face_handles())
    f->info() = -1;
  std::deque<Edge> border;
  auto flood = [&](Face_handle start, int level) {
    std::deque<Face_handle> queue{start};
    while (!queue.empty()) {
      const Face_handle f = queue.front();
      queue.pop_front();
      if (f->info() != -1)
        continue;
      f->info() = level;
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (n->info() != -1)
          continue;
        if (cdt.is_constrained(Edge(f, i)))
          border.push_back(Edge(f, i));
        else
          queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const Edge e = border.front();
    border.pop_front();
    const Face_handle n = e.first->neighbor(e.second);
    if (n->info() == -1)
      flood(n, e.first->info() + 1);
  }

  // An extra point strictly inside has only domain faces around it and no constraint.
  for (std::size_t i = 0; i < extra.size(); ++i) {
    const Vertex_handle v = extra[i];
    bool on_boundary = false;
    int outside_level = -1;
    auto faces = cdt.incident_faces(v), done = faces;
    do {
      if (cdt.is_infinite(faces) || faces->info() % 2 == 0)
        outside_level = faces->info();
      // The two edges of the face at v are those opposite its other vertices.
      for (int j = 0; j < 3; ++j)
        if (j != faces->index(v) && cdt.is_constrained(Edge(faces, j)))
          on_boundary = true;
    } while (++faces != done);
    if (on_boundary || outside_level >= 0) {
      const std::string where = on_boundary          ? "on the boundary"
                                : outside_level == 0 ? "outside the outer boundary"
                                                     : "inside a hole";
      throw Invalid_input("constrained domain: extra point " + std::to_string(i) + " " +
                          internal::point_to_string(extra_points[i]) + " is " + where);
    }
  }

  std::vector<Vertex_handle> handles;
  Planar_domain<GeomTraits> domain = domain_from_triangulation_2<GeomTraits>(
      cdt, [](Face_handle f) { return f->info() % 2 == 1; }, handles);
  std::vector<std::size_t> indices;
  indices.reserve(handles.size());
  for (const Vertex_handle& v : handles)
    indices.push_back(input_index.at(v));
  return {std::move(domain), std::move(indices)};
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_CONSTRAINED_DOMAIN_H

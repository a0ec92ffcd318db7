// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_POLYGON_CHECKS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_POLYGON_CHECKS_H

// The validation of the boundary and hole polygons of constrained_domain.h, by exact
// predicates.

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

inline std::string polygon_name(std::size_t p) {
  return p == 0 ? std::string("polygon 0 (the outer boundary)")
                : "polygon " + std::to_string(p) + " (a hole)";
}

// Checks that the polygons are simple, pairwise disjoint (not even touching), that every
// hole lies inside the outer boundary and no hole inside another. Candidate edge pairs come
// from bounding boxes (CGAL's box intersection), the decision from exact predicates.
template <class GeomTraits>
void check_polygons(const std::vector<std::vector<typename GeomTraits::Point_2>>& polygons) {
  using Point_2 = typename GeomTraits::Point_2;
  using Segment_2 = typename GeomTraits::Segment_2;
  if (polygons.empty())
    throw Invalid_input("constrained domain: no boundary polygon");
  struct Edge {
    std::size_t polygon, index;
  };
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, Edge>;
  std::vector<Box> boxes;
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const std::vector<Point_2>& polygon = polygons[p];
    if (polygon.size() < 3)
      throw Invalid_input("constrained domain: " + polygon_name(p) + " has " +
                          std::to_string(polygon.size()) + " vertices, at least 3 are needed");
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point_2& a = polygon[i];
      const Point_2& b = polygon[(i + 1) % polygon.size()];
      if (a == b)
        throw Invalid_input("constrained domain: " + polygon_name(p) + " repeats vertex " +
                            std::to_string(i) + " " + point_to_string(a));
      boxes.emplace_back(a.bbox() + b.bbox(), Edge{p, i});
    }
  }
  auto segment = [&](const Edge& e) {
    const std::vector<Point_2>& polygon = polygons[e.polygon];
    return Segment_2(polygon[e.index], polygon[(e.index + 1) % polygon.size()]);
  };
  auto report = [&](const Box& x, const Box& y) {
    // Lower polygon first, so that messages do not depend on the order of the boxes.
    const bool swap = y.info().polygon < x.info().polygon ||
                      (y.info().polygon == x.info().polygon && y.info().index < x.info().index);
    const Edge e = swap ? y.info() : x.info(), f = swap ? x.info() : y.info();
    const std::string edges =
        "edges " + std::to_string(e.index) + " and " + std::to_string(f.index);
    if (e.polygon == f.polygon) {
      const std::size_t n = polygons[e.polygon].size();
      const bool f_follows = f.index == (e.index + 1) % n;
      const bool e_follows = e.index == (f.index + 1) % n;
      if (f_follows || e_follows) {
        // Consecutive edges share a vertex; they only overlap if they fold back.
        const Edge first = f_follows ? e : f;
        const std::vector<Point_2>& polygon = polygons[e.polygon];
        const Point_2& a = polygon[first.index];
        const Point_2& b = polygon[(first.index + 1) % n];
        const Point_2& c = polygon[(first.index + 2) % n];
        if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_strictly_ordered_along_line(a, b, c))
          throw Invalid_input("constrained domain: " + polygon_name(e.polygon) +
                              " is not simple: it folds back at vertex " +
                              std::to_string((first.index + 1) % n) + " " + point_to_string(b));
        return;
      }
      if (CGAL::do_intersect(segment(e), segment(f)))
        throw Invalid_input("constrained domain: " + polygon_name(e.polygon) +
                            " is not simple: its " + edges + " intersect");
      return;
    }
    if (CGAL::do_intersect(segment(e), segment(f)))
      throw Invalid_input("constrained domain: " + polygon_name(e.polygon) + " and " +
                          polygon_name(f.polygon) + " intersect or touch (their " + edges + ")");
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);

  // No boundaries meet, so one vertex tells on which side of another polygon a hole lies.
  const std::vector<Point_2>& outer = polygons[0];
  for (std::size_t h = 1; h < polygons.size(); ++h) {
    const Point_2& p = polygons[h][0];
    if (CGAL::bounded_side_2(outer.begin(), outer.end(), p, GeomTraits()) != CGAL::ON_BOUNDED_SIDE)
      throw Invalid_input("constrained domain: " + polygon_name(h) +
                          " lies outside the outer boundary");
    for (std::size_t g = 1; g < polygons.size(); ++g)
      if (g != h && CGAL::bounded_side_2(polygons[g].begin(), polygons[g].end(), p, GeomTraits()) ==
                        CGAL::ON_BOUNDED_SIDE)
        throw Invalid_input("constrained domain: " + polygon_name(h) + " lies inside " +
                            polygon_name(g));
  }
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_POLYGON_CHECKS_H

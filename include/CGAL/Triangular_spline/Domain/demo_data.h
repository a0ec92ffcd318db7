// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DEMO_DATA_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DEMO_DATA_H

#include <CGAL/Triangular_spline/Domain/constrained_domain.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/internal/demo_height.h>

#include <array>
#include <cstdlib>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief returns the embedded data set of `tspline demo`: a domain with a hole, a
  re-entrant corner and long straight boundary stretches, and a height per domain vertex.

  - Domain: the L-shaped region \f$[0,3]^2 \setminus (3/2,3]^2\f$ minus the square hole
    \f$[1/2,1]^2\f$. The outer boundary has vertices every 1/8 along its six straight
    sides, the hole every 1/4, and the interior points form the grid \f$(\mathbb{Z}/4)^2\f$.
    Triangulated with `constrained_domain()`: 180 vertices, 256 triangles. All coordinates
    are dyadic, hence exact in `double`, so every kernel with exact predicates builds the
    same triangulation.
  - Because the boundary is twice as dense as the grid, every boundary vertex on a grid
    column or row (e.g. \f$(1/2, 0)\f$) has exactly one interior edge, whose two apexes are
    its boundary neighbours, collinear with it: the degenerate-frame configuration of Xu
    §4.4.4.
  - Heights: \f$f(x,y) = \frac12 + \frac x3 - \frac y5 + \frac{x^2y}{8} - \frac{xy^2}{12} +
    \frac{x^3}{24} + \frac{1}{1 + 4((x-9/4)^2 + (y-3/4)^2)}\f$, evaluated in `FT` (exactly for
    an exact `FT`).

  \tparam GeomTraits a model of `Kernel`
  \return the domain and the height of each domain vertex
*/
template <class GeomTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>> demo_data() {
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  auto point = [](int x_num, int y_num, int den) {
    return Point_2(FT(x_num) / FT(den), FT(y_num) / FT(den));
  };
  // Corners in eighths, counter-clockwise; one boundary vertex every 1/8.
  const std::array<std::array<int, 2>, 6> corners{
      {{{0, 0}}, {{24, 0}}, {{24, 12}}, {{12, 12}}, {{12, 24}}, {{0, 24}}}};
  std::vector<Point_2> outer;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const std::array<int, 2>& a = corners[c];
    const std::array<int, 2>& b = corners[(c + 1) % corners.size()];
    const int steps = std::abs(b[0] - a[0]) + std::abs(b[1] - a[1]); // axis-parallel sides
    for (int i = 0; i < steps; ++i)
      outer.push_back(point(a[0] + i * (b[0] - a[0]) / steps, a[1] + i * (b[1] - a[1]) / steps, 8));
  }
  std::vector<Point_2> hole{point(2, 2, 4), point(3, 2, 4), point(4, 2, 4), point(4, 3, 4),
                            point(4, 4, 4), point(3, 4, 4), point(2, 4, 4), point(2, 3, 4)};
  // Grid points strictly inside the L and outside the closed hole.
  std::vector<Point_2> interior;
  for (int j = 1; j < 12; ++j)
    for (int i = 1; i < 12; ++i) {
      const bool in_cut_corner = i >= 6 && j >= 6;
      const bool in_hole = i >= 2 && i <= 4 && j >= 2 && j <= 4;
      if (!in_cut_corner && !in_hole)
        interior.push_back(point(i, j, 4));
    }
  Planar_domain<GeomTraits> domain =
      constrained_domain<GeomTraits>({std::move(outer), std::move(hole)}, interior).first;
  std::vector<FT> heights;
  heights.reserve(domain.number_of_vertices());
  for (const Point_2& p : domain.points())
    heights.push_back(internal::demo_height(p.x(), p.y()));
  return {std::move(domain), std::move(heights)};
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DEMO_DATA_H

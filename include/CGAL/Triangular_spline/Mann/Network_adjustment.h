// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_MANN_NETWORK_ADJUSTMENT_H
#define CGAL_TRIANGULAR_SPLINE_MANN_NETWORK_ADJUSTMENT_H

#include <CGAL/Triangular_spline/Multi_index.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineMann
  \brief a control point of a network: a face and a multi-index in that face's patch (in
  the patch's own vertex order).
*/
struct Touched_control_point {
  std::uint32_t face = 0; ///< the face whose patch holds the point
  Multi_index index;      ///< the point's multi-index in that patch
};

/*!
  \ingroup PkgTriangularSplineMann
  \brief what `adjust_network()` did across one interior edge.
*/
struct Edge_adjustment {
  std::uint32_t edge = 0;                        ///< the edge index in the domain
  std::array<std::uint32_t, 2> vertices{{0, 0}}; ///< its two vertices
  std::vector<Touched_control_point> touched;    ///< the points moved by the edge's averaging
};

/*!
  \ingroup PkgTriangularSplineMann
  \brief what `adjust_network()` did around one vertex whose corner regions violated the
  \f$C^k\f$ conditions.
*/
struct Vertex_adjustment {
  std::uint32_t vertex = 0; ///< the vertex index in the domain
  /// the largest residual of the conditions around the vertex before the projection
  double residual = 0;
  std::vector<Touched_control_point> touched; ///< the corner-region points moved
};

/*!
  \ingroup PkgTriangularSplineMann
  \brief the outcome of `adjust_network()`.
*/
struct Network_adjustment {
  int order = 0;      ///< the continuity order \f$k\f$ reached
  int degree = 0;     ///< the patch degree \f$n\f$
  bool exact = false; ///< computed with an exact number type
  /// one entry per interior edge, in edge order
  std::vector<Edge_adjustment> edges;
  /// one entry per vertex whose corner regions had to be projected (none for a network
  /// whose patches already meet the \f$C^k\f$ conditions near every vertex)
  std::vector<Vertex_adjustment> vertices;

  /// returns the number of interior edges across which some control point moved
  /// \returns the number of interior edges across which some control point moved
  std::size_t number_of_changed_edges() const {
    std::size_t count = 0;
    for (const Edge_adjustment& e : edges)
      count += e.touched.empty() ? 0 : 1;
    return count;
  }
  /// returns the total number of control points moved (a point moved twice counts twice)
  /// \returns the total number of control points moved (a point moved twice counts twice)
  std::size_t number_of_touched_points() const {
    std::size_t count = 0;
    for (const Edge_adjustment& e : edges)
      count += e.touched.size();
    for (const Vertex_adjustment& v : vertices)
      count += v.touched.size();
    return count;
  }
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_MANN_NETWORK_ADJUSTMENT_H

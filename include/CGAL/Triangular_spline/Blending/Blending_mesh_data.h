// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_MESH_DATA_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_MESH_DATA_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief a polygon mesh given as arrays: positions, optional unit normals, and faces as
  counter-clockwise vertex lists (seen from outside / from above).
*/
struct Blending_mesh_data {
  std::vector<std::array<double, 3>> points;   ///< vertex positions
  std::vector<std::array<double, 3>> normals;  ///< per-vertex normals, or empty (estimate them)
  std::vector<std::vector<std::size_t>> faces; ///< faces, counter-clockwise
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_MESH_DATA_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_MESH_DOMAIN_H
#define CGAL_TRIANGULAR_SPLINE_IO_MESH_DOMAIN_H

#include <CGAL/Triangular_spline/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a triangle mesh whose vertices \f$(x, y, z)\f$ are a height field over the
  plane: returns the triangulation of the points \f$(x, y)\f$ as a `Planar_domain` and the
  height \f$z\f$ of each domain vertex.

  The file is read with `CGAL::IO::read_polygon_soup()`, the format chosen by the extension
  (case-insensitive): `.off`, `.obj`, `.ply`, `.stl`. CGAL reads coordinates as `double`;
  they are converted exactly into `GeomTraits` (so an exact kernel sees exactly the file's
  `double` values). Domain vertex `v` is vertex `v` of the file and face `f` is polygon `f`
  (reoriented counter-clockwise if needed).

  \tparam GeomTraits a model of `Kernel`
  \param path the file to read
  \throws Invalid_input naming the file if it cannot be opened, has an unsupported
  extension, cannot be parsed, holds no polygon, has a polygon that is not a triangle (the
  message gives its index and size), refers to a missing vertex, or has a coordinate that
  is not finite or exceeds \f$10^{150}\f$; the `Planar_domain` checks (duplicate points,
  unused vertices, zero-area or folded triangles, non-manifold edges or vertices) apply to
  the projection to \f$(x, y)\f$ and their messages are prefixed with the file name.
*/
template <class GeomTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
read_mesh_domain(const std::string& path) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Index = typename Planar_domain<GeomTraits>::Index;

  // read_polygon_soup() only returns false: diagnose the common causes first.
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  std::string extension = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                              ? ""
                              : path.substr(dot);
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    throw Invalid_input(path + ": unsupported mesh file extension \"" + extension +
                        "\" (expected .off, .obj, .ply or .stl)");
  if (!std::ifstream(path))
    throw Invalid_input(path + ": cannot open the file");

  std::vector<Epick::Point_3> points3;
  std::vector<std::vector<std::size_t>> polygons;
  // CGAL's readers print their own diagnostics on std::cerr; ours is the one-line error
  // below, so theirs are silenced for the duration of the read.
  bool read = false;
  {
    std::ostringstream swallowed;
    std::streambuf* saved = std::cerr.rdbuf(swallowed.rdbuf());
    try {
      read = CGAL::IO::read_polygon_soup(path, points3, polygons);
    } catch (...) {
      std::cerr.rdbuf(saved);
      throw;
    }
    std::cerr.rdbuf(saved);
  }
  if (!read)
    throw Invalid_input(path + ": cannot read the file as a " + extension.substr(1) + " mesh");
  if (polygons.empty())
    throw Invalid_input(path + ": the mesh has no face");

  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(polygons.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const std::vector<std::size_t>& polygon = polygons[f];
    if (polygon.size() != 3)
      throw Invalid_input(path + ": face " + std::to_string(f) + " has " +
                          std::to_string(polygon.size()) +
                          " vertices; only triangles are supported");
    std::array<Index, 3> t;
    for (std::size_t i = 0; i < 3; ++i) {
      if (polygon[i] >= points3.size())
        throw Invalid_input(path + ": face " + std::to_string(f) + " refers to vertex " +
                            std::to_string(polygon[i]) + " but there are only " +
                            std::to_string(points3.size()));
      t[i] = static_cast<Index>(polygon[i]);
    }
    triangles.push_back(t);
  }

  std::vector<Point_2> points;
  std::vector<FT> heights;
  points.reserve(points3.size());
  heights.reserve(points3.size());
  for (std::size_t v = 0; v < points3.size(); ++v) {
    const Epick::Point_3& p = points3[v];
    for (int c = 0; c < 3; ++c)
      // Checked in double: a NaN must never reach an exact number type's constructor.
      if (!std::isfinite(p[c]) || std::fabs(p[c]) > 1e150)
        throw Invalid_input(path + ": vertex " + std::to_string(v) +
                            " has a coordinate that is not finite or exceeds 1e150");
    points.emplace_back(FT(p.x()), FT(p.y()));
    heights.push_back(FT(p.z()));
  }
  try {
    return {Planar_domain<GeomTraits>(std::move(points), std::move(triangles)), std::move(heights)};
  } catch (const Invalid_input& e) {
    throw Invalid_input(path + ": " + e.what());
  }
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_MESH_DOMAIN_H

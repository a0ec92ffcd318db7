// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_MESH_IO_H
#define CGAL_TRIANGULAR_SPLINE_IO_MESH_IO_H

#include <CGAL/Triangular_spline/internal/mesh_file_checks.h>
#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a polygon mesh file as a polygon soup, after checking it: the reader that
  every command uses for meshes.

  The format is chosen by the extension (case-insensitive): `.off`, `.obj`, `.ply`, `.stl`.
  Before `CGAL::IO::read_polygon_soup()` (or `CGAL::IO::read_OFF()` when `normals` is given)
  sees the file, its header counts are checked against the file size (each vertex and face
  takes a few bytes), and its face indices must be integers: CGAL's readers would reserve
  any count and truncate `1.5` to a valid index. After the read, every polygon must have at
  least 3 vertices, every index must name a vertex and every coordinate must be finite.

  \param path the file to read
  \param points the vertices, in file order
  \param polygons the faces, as indices into `points`
  \param normals if not null, receives the vertex normals of an `NOFF` file (else untouched)
  \throws Invalid_input naming the file (and the line, for the header and face checks) if it
  cannot be opened, has an unsupported extension, fails a check, cannot be parsed, or holds
  no polygon; error messages quote at most 40 characters of a token.
*/
inline void read_mesh_soup(
    const std::string& path,
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& points,
    std::vector<std::vector<std::size_t>>& polygons,
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>* normals = nullptr) {
  const std::string extension = internal::mesh_extension(path);
  if (extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    throw Invalid_input(path + ": unsupported mesh file extension " + internal::quoted(extension) +
                        " (expected .off, .obj, .ply or .stl)");
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw Invalid_input(path + ": cannot open the file");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    if (size >= 0) {
      const auto bytes = static_cast<std::uint64_t>(size);
      if (extension == ".off")
        internal::check_off_file(path, in, bytes);
      else if (extension == ".ply")
        internal::check_ply_file(path, in, bytes);
      else if (extension == ".obj")
        internal::check_obj_file(path, in);
    }
  }

  points.clear();
  polygons.clear();
  // CGAL's readers print their own diagnostics on std::cerr; ours is the one-line error
  // below, so theirs are silenced for the duration of the read.
  bool read = false;
  {
    std::ostringstream swallowed;
    std::streambuf* saved = std::cerr.rdbuf(swallowed.rdbuf());
    try {
      if (normals != nullptr && extension == ".off") {
        std::ifstream in(path);
        read = CGAL::IO::read_OFF(
            in, points, polygons,
            CGAL::parameters::vertex_normal_output_iterator(std::back_inserter(*normals)));
      } else {
        read = CGAL::IO::read_polygon_soup(path, points, polygons);
      }
    } catch (const std::exception& e) {
      // CGAL's readers may throw their own exceptions (std::length_error, CGAL's assertion
      // failures in debug builds): every reader error is an Invalid_input naming the file.
      std::cerr.rdbuf(saved);
      std::string what = e.what();
      if (what.size() > 80)
        what = what.substr(0, 80) + "...";
      throw Invalid_input(path + ": cannot read the file as a " + extension.substr(1) + " mesh (" +
                          what + ")");
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
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() < 3)
      throw Invalid_input(path + ": face " + std::to_string(f) + " has " +
                          std::to_string(polygons[f].size()) +
                          " vertices; a face needs at least 3");
    for (std::size_t v : polygons[f])
      if (v >= points.size())
        throw Invalid_input(path + ": face " + std::to_string(f) + " refers to vertex " +
                            std::to_string(v) + " but there are only " +
                            std::to_string(points.size()));
  }
  for (std::size_t v = 0; v < points.size(); ++v)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(points[v][c]))
        throw Invalid_input(path + ": vertex " + std::to_string(v) +
                            " has a coordinate that is not finite");
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a triangle mesh whose vertices \f$(x, y, z)\f$ are a height field over the
  plane: returns the triangulation of the points \f$(x, y)\f$ as a `Planar_domain` and the
  height \f$z\f$ of each domain vertex.

  The file is read with `read_mesh_soup()`, the format chosen by the extension
  (case-insensitive): `.off`, `.obj`, `.ply`, `.stl`. CGAL reads coordinates as `double`;
  they are converted exactly into `GeomTraits` (so an exact kernel sees exactly the file's
  `double` values). Domain vertex `v` is vertex `v` of the file and face `f` is polygon `f`
  (reoriented counter-clockwise if needed).

  \tparam GeomTraits a model of `Kernel`
  \param path the file to read
  \throws Invalid_input naming the file for every error of `read_mesh_soup()`, a polygon
  that is not a triangle (the message gives its index and size), or a coordinate that
  exceeds \f$10^{150}\f$; the `Planar_domain` checks (duplicate points, unused vertices,
  zero-area or folded triangles, non-manifold edges or vertices) apply to the projection to
  \f$(x, y)\f$ and their messages are prefixed with the file name.
  \returns the triangulation of the points \f$(x, y)\f$ as a `Planar_domain` and the height \f$z\f$
  of each domain vertex
*/
template <class GeomTraits>
std::pair<Planar_domain<GeomTraits>, std::vector<typename GeomTraits::FT>>
read_mesh_domain(const std::string& path) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Index = typename Planar_domain<GeomTraits>::Index;

  std::vector<Epick::Point_3> points3;
  std::vector<std::vector<std::size_t>> polygons;
  read_mesh_soup(path, points3, polygons);

  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(polygons.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const std::vector<std::size_t>& polygon = polygons[f];
    if (polygon.size() != 3)
      throw Invalid_input(path + ": face " + std::to_string(f) + " has " +
                          std::to_string(polygon.size()) +
                          " vertices; only triangles are supported");
    triangles.push_back({static_cast<Index>(polygon[0]), static_cast<Index>(polygon[1]),
                         static_cast<Index>(polygon[2])});
  }

  std::vector<Point_2> points;
  std::vector<FT> heights;
  points.reserve(points3.size());
  heights.reserve(points3.size());
  for (std::size_t v = 0; v < points3.size(); ++v) {
    const Epick::Point_3& p = points3[v];
    for (int c = 0; c < 3; ++c)
      // Checked in double: a huge value must never reach an exact number type.
      if (std::fabs(p[c]) > 1e150)
        throw Invalid_input(path + ": vertex " + std::to_string(v) +
                            " has a coordinate that exceeds 1e150");
    points.emplace_back(FT(p.x()), FT(p.y()));
    heights.push_back(FT(p.z()));
  }
  try {
    return {Planar_domain<GeomTraits>(std::move(points), std::move(triangles)), std::move(heights)};
  } catch (const Invalid_input& e) {
    throw Invalid_input(path + ": " + e.what());
  }
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief writes a surface mesh to a file, the format chosen by the extension of `path`
  (letter case ignored):

  - `.ply`: binary little-endian PLY with the vertex normals `"v:normal"` (`nx ny nz`) and
    every other vertex property of a simple type, such as the curvatures written by
    `tessellate()` (CGAL's `Surface_mesh` PLY writer);
  - `.off`: ASCII OFF, as `NOFF` with normals when `"v:normal"` exists, 17 digits;
  - `.obj`: ASCII Wavefront OBJ, with `vn` lines (one per vertex, in vertex order) when
    `"v:normal"` exists, 17 digits.

  \tparam Point the point type of the mesh (a CGAL 3D point)
  \throws Invalid_input if the extension is not one of the above
  \throws std::runtime_error (naming `path`) if the file cannot be opened or written
  \param path the file path
  \param mesh the mesh to write
*/
template <class Point>
void write_mesh(const std::string& path, const CGAL::Surface_mesh<Point>& mesh) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Vector_3 = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  std::string extension;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    extension = path.substr(dot + 1);
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != "ply" && extension != "off" && extension != "obj")
    throw Invalid_input("write_mesh: cannot choose a format for '" + path +
                        "' (use the extension .ply, .off or .obj)");

  std::ofstream out(path, extension == "ply" ? std::ios::out | std::ios::binary : std::ios::out);
  if (!out)
    throw std::runtime_error("write_mesh: cannot open '" + path + "' for writing");
  bool written = false;
  if (extension == "ply") {
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    written = CGAL::IO::write_PLY(out, mesh);
  } else if (extension == "off") {
    written = CGAL::IO::write_OFF(out, mesh, CGAL::parameters::stream_precision(17));
  } else {
    // CGAL's OBJ writer has no Surface_mesh overload: normals only through the parameter.
    const auto [normals, has_normals] =
        mesh.template property_map<typename Mesh::Vertex_index, Vector_3>("v:normal");
    if (has_normals)
      written = CGAL::IO::write_OBJ(
          out, mesh, CGAL::parameters::stream_precision(17).vertex_normal_map(normals));
    else
      written = CGAL::IO::write_OBJ(out, mesh, CGAL::parameters::stream_precision(17));
  }
  out.close();
  // The PLY writer reports success without checking the stream: check it here.
  if (!written || out.fail())
    throw std::runtime_error("write_mesh: writing '" + path + "' failed");
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_MESH_IO_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_SURFACE_FILE_H
#define CGAL_TRIANGULAR_SPLINE_IO_SURFACE_FILE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/spline_file_format.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief a piecewise polynomial surface over a closed triangle mesh, as read by
  `read_surface_file()`: the mesh and one parametric Bézier net per face.

  Like `Pseudo_AG1_surface`, `patch(f)` is over the unit triangle with its corners at the
  vertices of `vertices_around_face(halfedge(f))`, in that order, so the same samplers,
  measures and writers apply.
  \tparam Kernel the kernel of the control points
*/
template <class Kernel>
class Surface_file {
public:
  /// the kernel
  using Geom_traits = Kernel;
  /// the mesh
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  /// face index
  using Face_index = typename Mesh::Face_index;
  /// the patches
  using Patch = Bezier_triangle<Kernel, typename Kernel::Vector_3>;

  /// the surface from a mesh and its nets (by face index, in `vertices_around_face` order)
  /// \param mesh the closed mesh
  /// \param degree the degree of every net
  /// \param nets the nets
  /// \param exact the numbers were written exactly
  Surface_file(Mesh mesh, int degree, std::vector<std::vector<typename Kernel::Vector_3>> nets,
               bool exact)
      : m_mesh(std::move(mesh)), m_degree(degree), m_nets(std::move(nets)), m_exact(exact) {}

  /// \returns the mesh
  const Mesh& mesh() const { return m_mesh; }
  /// \returns the degree
  int degree() const { return m_degree; }
  /// \returns `true` iff the file said `number_type exact`
  bool exact_numbers() const { return m_exact; }
  /// \param f a face
  /// \returns the net of `f`
  const std::vector<typename Kernel::Vector_3>& control_net(Face_index f) const {
    return m_nets[f];
  }
  /// \param f a face
  /// \returns the patch of `f` over the unit triangle
  Patch patch(Face_index f) const {
    return Patch(m_degree, typename Kernel::Point_2(0, 0), typename Kernel::Point_2(1, 0),
                 typename Kernel::Point_2(0, 1), m_nets[f]);
  }

private:
  Mesh m_mesh;
  int m_degree;
  std::vector<std::vector<typename Kernel::Vector_3>> m_nets;
  bool m_exact;
};

/*!
  \ingroup PkgTriangularSplineIO
  \brief writes a piecewise polynomial surface over a closed triangle mesh in the
  `tspline-surface` text format (version 1).

  Lines, comments and numbers as in `write_spline_file()`:
  \code
  tspline-surface 1
  degree m
  number_type exact      or double
  vertices N
  x y z                  N lines: the mesh vertices 0..N-1
  faces F
  a b c                  F lines: counter-clockwise seen from outside
  patches
  x y z x y z ...        F lines: the (m+1)(m+2)/2 control points of face f over (a, b, c)
  end
  \endcode
  in Xu's Table 2.3 order (see `linear_index()`), the point with index \f$(i,j,k)\f$ being
  \f$f(a^i b^j c^k)\f$.
  \tparam Surface a class with `mesh()` (a `Surface_mesh`), `degree()` and `control_net(f)`
  (in `vertices_around_face` order), e.g. `Pseudo_AG1_surface` or `Surface_file`
  \param output the stream
  \param surface the surface
  \throws std::runtime_error if the stream fails
*/
template <class Surface>
void write_surface_file(std::ostream& output, const Surface& surface) {
  using FT = typename Surface::Geom_traits::FT;
  const auto& mesh = surface.mesh();
  const bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  output << internal::surface_file_magic << " " << internal::surface_file_version << "\n"
         << "# a piecewise polynomial surface over a closed triangle mesh, written by "
            "CGAL::Triangular_spline\n"
         << "degree " << surface.degree() << "\n"
         << "number_type " << (exact ? "exact" : "double") << "\n"
         << "vertices " << mesh.number_of_vertices() << "\n";
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    output << format_number<FT>(p.x()) << " " << format_number<FT>(p.y()) << " "
           << format_number<FT>(p.z()) << "\n";
  }
  output << "faces " << mesh.number_of_faces() << "\n";
  for (auto f : mesh.faces()) {
    const auto c = internal::face_corners(mesh, f);
    output << std::size_t(c[0]) << " " << std::size_t(c[1]) << " " << std::size_t(c[2]) << "\n";
  }
  output << "patches\n";
  for (auto f : mesh.faces()) {
    bool first = true;
    for (const auto& p : surface.control_net(f)) {
      for (int i = 0; i < 3; ++i) {
        output << (first ? "" : " ") << format_number<FT>(p[i]);
        first = false;
      }
    }
    output << "\n";
  }
  output << "end\n";
  if (!output)
    throw std::runtime_error("write_surface_file: the output stream failed");
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a surface in the `tspline-surface` format (see `write_surface_file()`).

  Parsing is as strict as `read_spline_file()`'s: sections in order, counts checked against
  the bytes left before anything is allocated, numbers converted exactly where the file and
  `Kernel` allow. The faces must form a closed, manifold, consistently oriented triangle mesh
  (`prepare_closed_triangle_mesh()` without reorientation: the nets refer to the file's
  orientation).
  \tparam Kernel the kernel to read into
  \param input the stream
  \param source the name used in error messages
  \returns the surface
  \throws Invalid_input whose message starts with `source:line` (or `source:` for mesh
  errors)
*/
template <class Kernel>
Surface_file<Kernel> read_surface_file(std::istream& input, const std::string& source) {
  using FT = typename Kernel::FT;
  using Vector_3 = typename Kernel::Vector_3;
  using Mesh = typename Surface_file<Kernel>::Mesh;
  internal::Spline_line_reader reader(input, source);
  std::vector<std::string> tokens =
      reader.expect("\"" + std::string(internal::surface_file_magic) + " 1\"");
  if (tokens[0] != internal::surface_file_magic || tokens.size() != 2)
    reader.fail("not a tspline-surface file (expected \"tspline-surface 1\", found " +
                reader.text() + ")");
  if (tokens[1] != "1")
    reader.fail("unsupported tspline-surface version " + internal::quoted(tokens[1]) +
                " (this reader knows version 1)");
  const std::size_t m = reader.count(reader.keyword_value("degree"), "degree", 20);
  const std::string type = reader.keyword_value("number_type");
  if (type != "exact" && type != "double")
    reader.fail("number_type must be exact or double, not " + internal::quoted(type));
  const bool exact_file = type == "exact";
  const std::size_t V =
      reader.count(reader.keyword_value("vertices"), "vertex count", std::size_t(1) << 32);
  reader.check_fits(V, 6, "vertex count");
  Mesh mesh;
  mesh.reserve(typename Mesh::size_type(std::min(V, internal::spline_file_reserve_limit)), 0, 0);
  for (std::size_t i = 0; i < V; ++i) {
    const auto t = reader.data_line(
        "3 numbers (x y z) for vertex " + std::to_string(i) + " of " + std::to_string(V), 3);
    mesh.add_vertex(typename Kernel::Point_3(reader.template number<FT>(t[0], exact_file),
                                             reader.template number<FT>(t[1], exact_file),
                                             reader.template number<FT>(t[2], exact_file)));
  }
  const std::size_t F =
      reader.count(reader.keyword_value("faces"), "face count", std::size_t(1) << 32);
  reader.check_fits(F, 6, "face count");
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(std::min(F, internal::spline_file_reserve_limit));
  for (std::size_t f = 0; f < F; ++f) {
    const auto t = reader.data_line(
        "3 vertex indices for face " + std::to_string(f) + " of " + std::to_string(F), 3);
    std::array<std::size_t, 3> face;
    for (std::size_t i = 0; i < 3; ++i)
      face[i] = reader.count(t[i], "vertex index", V == 0 ? 0 : V - 1);
    if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
      reader.fail("face " + std::to_string(f) + " repeats a vertex");
    const auto added =
        mesh.add_face(typename Mesh::Vertex_index(typename Mesh::size_type(face[0])),
                      typename Mesh::Vertex_index(typename Mesh::size_type(face[1])),
                      typename Mesh::Vertex_index(typename Mesh::size_type(face[2])));
    if (added == Mesh::null_face())
      reader.fail("face " + std::to_string(f) +
                  " cannot be added (non-manifold or inconsistently oriented mesh)");
    faces.push_back(face);
  }
  reader.keyword("patches");
  const std::size_t n = number_of_control_points(int(m));
  reader.check_fits(F, 6 * n, "face count");
  std::vector<std::vector<Vector_3>> nets(F);
  const std::vector<Multi_index> indices = multi_indices(int(m));
  for (std::size_t f = 0; f < F; ++f) {
    const auto t = reader.data_line(std::to_string(3 * n) + " numbers for patch " +
                                        std::to_string(f) + " of " + std::to_string(F),
                                    3 * n);
    std::vector<Vector_3> file_net(n);
    for (std::size_t i = 0; i < n; ++i)
      file_net[i] = Vector_3(reader.template number<FT>(t[3 * i], exact_file),
                             reader.template number<FT>(t[3 * i + 1], exact_file),
                             reader.template number<FT>(t[3 * i + 2], exact_file));
    // re-index from the file's (a, b, c) to the mesh's vertices_around_face order
    const auto corners =
        internal::face_corners(mesh, typename Mesh::Face_index(typename Mesh::size_type(f)));
    int shift = 0;
    while (std::size_t(corners[0]) != faces[f][std::size_t(shift)])
      ++shift;
    nets[f].resize(n);
    for (const Multi_index& index : indices) {
      Multi_index in_file;
      for (int a = 0; a < 3; ++a)
        in_file[(a + shift) % 3] = index[a];
      nets[f][linear_index(index)] = file_net[linear_index(in_file)];
    }
  }
  reader.keyword("end");
  if (reader.next(tokens))
    reader.fail("unexpected content after \"end\": " + reader.text());
  try {
    prepare_closed_triangle_mesh(mesh, "", false);
  } catch (const Invalid_input& e) {
    throw Invalid_input(source + ": " + e.what());
  }
  return Surface_file<Kernel>(std::move(mesh), int(m), std::move(nets), exact_file);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_SURFACE_FILE_H

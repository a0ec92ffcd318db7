// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_SPLINE_FILE_H
#define CGAL_TRIANGULAR_SPLINE_IO_SPLINE_FILE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/internal/network_evaluation.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/internal/spline_file_format.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Patch_network.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Exact_rational.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief the contents of a spline file: the domain triangulation and one Bézier patch per
  face (`patch(f)` is over the face's vertices in the file's order, which may differ from
  `domain().face(f)` by a reorientation), as returned by `read_spline_file()`.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or `GeomTraits::Vector_3` (parametric)
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
struct Spline_file : Patch_network<GeomTraits, Value> {
  /// takes the domain and the patches (see `Patch_network`) and the file's number type
  /// \param domain the triangulated planar domain
  /// \param patches the patches, `patches[f]` being the patch of face `f`
  /// \param exact `true` if the file declares `number_type exact`
  Spline_file(Planar_domain<GeomTraits> domain,
              std::vector<Bezier_triangle<GeomTraits, Value>> patches, bool exact)
      : Patch_network<GeomTraits, Value>(std::move(domain), std::move(patches)),
        exact_values(exact) {}
  /// the file declares `number_type exact` (else `double`: the values of a double build,
  /// whose continuity holds up to round-off only)
  bool exact_values = true;
};

/*!
  \ingroup PkgTriangularSplineIO
  \brief writes a spline, given as a domain and one Bézier patch per face, in the
  `tspline-spline` text format (version 1).

  The format is line-based; blank lines and lines starting with `#` (after optional
  blanks) may appear anywhere, and tokens are separated by blanks:
  \code
  tspline-spline 1
  degree m
  dimension d            1: functional (heights), 3: parametric (points x y z)
  number_type exact      or double
  vertices N
  x y                    N lines: the domain vertices 0..N-1
  faces F
  a b c                  F lines: vertex indices (0-based) of the domain triangles
  patches
  v_0 ... v_{n-1}        F lines, one per face, in the order of the faces
  end
  \endcode
  Patch line `f` holds the \f$n = (m+1)(m+2)/2\f$ control values of face `f` over its
  vertices in the order `(a, b, c)` written on the face line, in Xu's Table 2.3 order:
  \f$b_{i,j,k}\f$ is the blossom value \f$f(a^i b^j c^k)\f$, listed by rows \f$i = 0..m\f$, within
  a row \f$j = 0..m-i\f$ (see `linear_index()`). A value of dimension 3 is 3 numbers.

  With `number_type exact` every number is an integer `p`, a fraction `p/q` or an exact
  decimal (`0.1` means 1/10); with `number_type double` every number is a decimal, and
  the shortest decimal that reads back to a `double` (which this writer uses) round-trips it.
  Numbers are written by `format_number()`: reduced fractions for an exact `FT` (nothing is
  lost), the shortest round-tripping decimal for `double`.

  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork` whose `FT` is `double`
  or exact and whose values are `FT` (dimension 1) or `Vector_3` (dimension 3)
  \param output the stream to write to
  \param network the spline: the patch of face `f` must be over the vertices of
  `domain().face(f)`, in any order; the face line records the patch's order.
  \throws Invalid_input if the degrees differ or a patch is not over the vertices of its face
  \throws std::runtime_error if the stream fails
*/
template <class TriangularSplineNetwork>
void write_spline_file(std::ostream& output, const TriangularSplineNetwork& network) {
  using GeomTraits = typename TriangularSplineNetwork::Geom_traits;
  using FT = typename GeomTraits::FT;
  using Index = typename Planar_domain<GeomTraits>::Index;
  using Patch = std::decay_t<decltype(network.patch(Index(0)))>;
  using Value = typename Patch::Value_type;
  using Traits = Value_traits<Value>;
  static_assert(Traits::dimension == 1 || Traits::dimension == 3,
                "the spline file format holds dimension 1 or 3 control values");
  const Planar_domain<GeomTraits>& domain = network.domain();
  const std::size_t F = domain.number_of_faces();
  const int m = F == 0 ? 0 : network.patch(0).degree();
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  // A network that exposes its nets (face f's patch over face(f), in order) is written from
  // references to its values: a patch built per face, twice (order, then values), copied
  // its 21 values and ran an exact orientation test (10^5 17-digit points, --exact: the save
  // takes 0.57-0.61 times the wall time; 10^6 double: 0.87-0.93).
  using Net = boost::container::small_vector<std::reference_wrapper<const Value>, 28>;
  constexpr bool by_nets = internal::Has_face_net<TriangularSplineNetwork, Net>::value;
  // The patch's vertex order, as domain vertex indices (exact point comparison), checked on
  // all cores (the error of the first bad face, as a serial loop).
  std::vector<std::array<Index, 3>> ordered(F);
  if constexpr (by_nets)
    for (std::size_t f = 0; f < F; ++f)
      ordered[f] = domain.face(static_cast<Index>(f));
  else
    internal::parallel_for_index(
        F, internal::thread_count(F, exact ? 2000 : 20000), [&](std::size_t f) {
          // binds to a stored patch, or extends the life of a computed one
          const Patch& patch = network.patch(static_cast<Index>(f));
          if (patch.degree() != m)
            throw Invalid_input("write_spline_file: patch " + std::to_string(f) + " has degree " +
                                std::to_string(patch.degree()) + ", patch 0 has degree " +
                                std::to_string(m));
          const std::array<Index, 3>& face = domain.face(static_cast<Index>(f));
          std::array<bool, 3> used{{false, false, false}};
          for (int i = 0; i < 3; ++i) {
            int match = -1;
            for (int j = 0; j < 3 && match < 0; ++j)
              if (!used[static_cast<std::size_t>(j)] &&
                  domain.point(face[static_cast<std::size_t>(j)]) == patch.vertex(i))
                match = j;
            if (match < 0)
              throw Invalid_input("write_spline_file: patch " + std::to_string(f) + " vertex " +
                                  std::to_string(i) + " " +
                                  internal::point_to_string(patch.vertex(i)) +
                                  " is not a vertex of face " + std::to_string(f));
            used[static_cast<std::size_t>(match)] = true;
            ordered[f][static_cast<std::size_t>(i)] = face[static_cast<std::size_t>(match)];
          }
        });

  output << internal::spline_file_magic << " " << internal::spline_file_version << "\n"
         << "# a piecewise polynomial over a planar triangulation, written by "
            "CGAL::Triangular_spline\n"
         << "degree " << m << "\n"
         << "dimension " << Traits::dimension << "\n"
         << "number_type " << (exact ? "exact" : "double") << "\n"
         << "vertices " << domain.number_of_vertices() << "\n";
  // Text is built in buffers and written a megabyte at a time, not number by number into
  // the stream (with %.17g and stream insertion the save was 12.7 of the 33 s of a c1 run
  // on 10^6 points; 2.4 s now).
  std::string text;
  text.reserve(std::size_t(1) << 21);
  auto append = [](std::string& out, const FT& x) {
    if constexpr (exact)
      out += format_number(x);
    else
      internal::append_double(out, CGAL::to_double(x));
  };
  auto index = [&text](Index i) {
    char buffer[24];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, i).ptr);
  };
  auto flush = [&](bool always) {
    if (always || text.size() >= (std::size_t(1) << 20)) {
      output.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  };
  for (const auto& p : domain.points()) {
    append(text, p.x());
    text += ' ';
    append(text, p.y());
    text += '\n';
    flush(false);
  }
  text += "faces " + std::to_string(F) + "\n";
  for (const auto& t : ordered) {
    index(t[0]);
    text += ' ';
    index(t[1]);
    text += ' ';
    index(t[2]);
    text += '\n';
    flush(false);
  }
  text += "patches\n";
  flush(true);
  // The patches, most of the file, are formatted on all cores, a batch of faces at a time,
  // each block of faces into its own buffer, and written in face order: the file does not
  // depend on the number of threads.
  constexpr std::size_t block = internal::parallel_block;
  // (exact values can take kilobytes each: a smaller batch bounds the buffers)
  const std::size_t batch = (exact ? 4 : 64) * block;
  std::vector<std::string> pieces(batch / block);
  for (std::size_t first = 0; first < F; first += batch) {
    const std::size_t count = (std::min)(batch, F - first);
    for (std::string& piece : pieces)
      piece.clear();
    internal::parallel_for_index(
        count, internal::thread_count(count, exact ? 64 : 4 * block), [&](std::size_t i) {
          std::string& piece = pieces[i / block];
          auto write = [&](const auto& values) {
            bool first_number = true;
            for (const Value& v : values)
              for (int c = 0; c < Traits::dimension; ++c) {
                if (!first_number)
                  piece += ' ';
                first_number = false;
                append(piece, Traits::coordinate(v, c));
              }
            piece += '\n';
          };
          if constexpr (by_nets) {
            Net net;
            network.face_net(static_cast<Index>(first + i), net);
            write(net);
          } else {
            write(network.patch(static_cast<Index>(first + i)).control_points());
          }
        });
    for (const std::string& piece : pieces)
      output.write(piece.data(), static_cast<std::streamsize>(piece.size()));
  }
  output << "end\n";
  if (!output)
    throw std::runtime_error("write_spline_file: the output stream failed");
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a spline in the `tspline-spline` text format (see `write_spline_file()`).

  Parsing is strict: the sections must come in the documented order, each with the
  announced number of lines and of numbers per line, and nothing but comments may follow
  `end`. Numbers are converted as follows:
  - `exact` file, exact `FT`: exactly (`parse_number()`);
  - `exact` file, `double`: the exact value rounded to the nearest `double`;
  - `double` file, either `FT`: `std::strtod`, then converted exactly into `FT`.

  \tparam GeomTraits a model of `Kernel` whose `FT` is `double` or exact
  \tparam Value `GeomTraits::FT` (reads dimension 1 files) or `GeomTraits::Vector_3`
  (reads dimension 3 files)
  \param input the stream to read
  \param source the name used in error messages (usually the file name)
  \return the domain and the patches; `patches[f]` is over the vertices of face `f` in the
  file's order
  \throws Invalid_input whose message starts with `source:line` for a bad first line
  (not a spline file, or an unsupported version), a missing or misplaced section, a count
  that does not match, a dimension that differs from `Value`'s, an invalid number, a vertex
  index out of range, or anything after `end`; the `Planar_domain` checks apply to the
  vertices and faces and their messages are prefixed with `source`.
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
Spline_file<GeomTraits, Value> read_spline_file(std::istream& input, const std::string& source) {
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Index = typename Planar_domain<GeomTraits>::Index;
  constexpr int dimension = Value_traits<Value>::dimension;
  static_assert(dimension == 1 || dimension == 3,
                "the spline file format holds dimension 1 or 3 control values");
  internal::Spline_line_reader reader(input, source);

  std::vector<std::string> tokens =
      reader.expect("\"" + std::string(internal::spline_file_magic) + " 1\"");
  if (tokens[0] != internal::spline_file_magic || tokens.size() != 2)
    reader.fail("not a tspline spline file (expected \"" +
                std::string(internal::spline_file_magic) + " 1\", found " + reader.text() + ")");
  if (tokens[1] != std::to_string(internal::spline_file_version))
    reader.fail("unsupported version " + internal::quoted(tokens[1]) +
                " (this reader supports version " + std::to_string(internal::spline_file_version) +
                ")");

  const int m = static_cast<int>(reader.count(reader.keyword_value("degree"), "degree", 100));
  const std::size_t values_per_patch = number_of_control_points(m);
  const std::string dimension_token = reader.keyword_value("dimension");
  if (dimension_token != "1" && dimension_token != "3")
    reader.fail("invalid dimension " + internal::quoted(dimension_token) + " (expected 1 or 3)");
  if (dimension_token != std::to_string(dimension))
    reader.fail("the file holds dimension " + dimension_token + " control values (" +
                (dimension_token == "1" ? "functional" : "parametric") + ") but dimension " +
                std::to_string(dimension) + " values were requested");
  const std::string number_type = reader.keyword_value("number_type");
  if (number_type != "exact" && number_type != "double")
    reader.fail("invalid number_type " + internal::quoted(number_type) +
                " (expected exact or double)");
  const bool exact_file = number_type == "exact";

  const std::size_t max_index = Planar_domain<GeomTraits>::null_index - 1;
  const std::size_t N = reader.count(reader.keyword_value("vertices"), "vertex count", max_index);
  reader.check_fits(N, 4, "vertex count"); // "x y\n"
  std::vector<Point_2> points;
  points.reserve((std::min)(N, internal::spline_file_reserve_limit));
  for (std::size_t v = 0; v < N; ++v) {
    tokens = reader.data_line(
        "2 numbers (x y) for vertex " + std::to_string(v) + " of " + std::to_string(N), 2);
    const FT x = reader.number<FT>(tokens[0], exact_file);
    const FT y = reader.number<FT>(tokens[1], exact_file);
    points.emplace_back(x, y);
  }

  const std::size_t F = reader.count(reader.keyword_value("faces"), "face count", max_index);
  const std::size_t numbers_per_line = values_per_patch * static_cast<std::size_t>(dimension);
  // A face line "a b c\n" and a patch line of one-digit numbers and blanks.
  reader.check_fits(F, 6 + 2 * numbers_per_line, "face count");
  std::vector<std::array<Index, 3>> faces;
  faces.reserve((std::min)(F, internal::spline_file_reserve_limit));
  for (std::size_t f = 0; f < F; ++f) {
    tokens = reader.data_line(
        "3 vertex indices (a b c) for face " + std::to_string(f) + " of " + std::to_string(F), 3);
    std::array<Index, 3> t;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t v = reader.count(tokens[i], "vertex index", max_index);
      if (v >= N)
        reader.fail("face " + std::to_string(f) + " uses vertex " + tokens[i] +
                    " but there are only " + std::to_string(N) + " vertices");
      t[i] = static_cast<Index>(v);
    }
    faces.push_back(t);
  }

  reader.keyword("patches");
  std::vector<std::vector<Value>> nets;
  nets.reserve((std::min)(F, internal::spline_file_reserve_limit));
  for (std::size_t f = 0; f < F; ++f) {
    tokens = reader.data_line(
        std::to_string(numbers_per_line) + " numbers (" + std::to_string(values_per_patch) +
            " control values of dimension " + std::to_string(dimension) +
            ") for the patch of face " + std::to_string(f) + " of " + std::to_string(F),
        numbers_per_line);
    std::vector<Value> net;
    net.reserve(values_per_patch);
    for (std::size_t c = 0; c < values_per_patch; ++c) {
      if constexpr (dimension == 1) {
        net.push_back(reader.number<FT>(tokens[c], exact_file));
      } else {
        const FT x = reader.number<FT>(tokens[3 * c], exact_file);
        const FT y = reader.number<FT>(tokens[3 * c + 1], exact_file);
        const FT z = reader.number<FT>(tokens[3 * c + 2], exact_file);
        net.push_back(Value(x, y, z));
      }
    }
    nets.push_back(std::move(net));
  }
  reader.keyword("end");
  if (reader.next(tokens))
    reader.fail("unexpected content after \"end\": " + reader.text());

  // The patches use the file's vertex order; the domain may reorient its copy of the faces.
  std::vector<std::array<Index, 3>> file_faces = faces;
  try {
    Planar_domain<GeomTraits> domain(std::move(points), std::move(faces));
    std::vector<Bezier_triangle<GeomTraits, Value>> patches;
    patches.reserve(F);
    for (std::size_t f = 0; f < F; ++f) {
      const std::array<Index, 3>& t = file_faces[f];
      patches.emplace_back(m, domain.point(t[0]), domain.point(t[1]), domain.point(t[2]),
                           std::move(nets[f]));
    }
    return Spline_file<GeomTraits, Value>(std::move(domain), std::move(patches), exact_file);
  } catch (const Invalid_input& e) {
    throw Invalid_input(source + ": " + e.what());
  }
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief returns the `dimension` declared in the header of a spline file (1 or 3), so that a
  caller can choose the `Value` type of `read_spline_file()`; 1 when the header declares
  none (`read_spline_file()` then reports the missing line). The stream is rewound.
  \param input the input stream
  \returns the `dimension` declared in the header of a spline file (1 or 3), so that a caller can
  choose the `Value` type of `read_spline_file()`
*/
inline int spline_file_dimension(std::istream& input) {
  std::string line;
  int dimension = 1;
  while (std::getline(input, line)) {
    const std::vector<std::string> words = internal::split_tokens(line.substr(0, line.find('#')));
    if (words.size() == 2 && words[0] == "dimension") {
      dimension = words[1] == "3" ? 3 : 1;
      break;
    }
    if (!words.empty() && (words[0] == "vertices" || words[0] == "faces"))
      break; // past the header
  }
  input.clear();
  input.seekg(0);
  return dimension;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_SPLINE_FILE_H

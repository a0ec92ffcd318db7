// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_FILE_FORMAT_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_FILE_FORMAT_H

// The text formats of IO/spline_file.h and IO/surface_file.h: their first lines, the limit on
// what a count may reserve, the line reader both use, and the corner order of a surface
// file's faces.

#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/decimal_parsing.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <istream>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

constexpr const char* spline_file_magic = "tspline-spline";
constexpr int spline_file_version = 1;
// Keeps a corrupt count from reserving gigabytes before the file runs out.
constexpr std::size_t spline_file_reserve_limit = std::size_t(1) << 20;

// Reads the non-blank, non-comment lines of a spline file as tokens, counting lines.
class Spline_line_reader {
public:
  Spline_line_reader(std::istream& input, const std::string& source)
      : m_input(input), m_source(source) {}

  // Returns false at the end of the input.
  bool next(std::vector<std::string>& tokens) {
    std::string line;
    while (std::getline(m_input, line)) {
      ++m_line;
      tokens = split_tokens(line);
      if (tokens.empty() || tokens[0][0] == '#')
        continue;
      m_text = line.substr(line.find_first_not_of(blank_characters));
      return true;
    }
    if (m_input.bad())
      fail("read error");
    return false;
  }

  // Reads the next line, which must exist; `expected` describes it for the error message.
  std::vector<std::string> expect(const std::string& expected) {
    std::vector<std::string> tokens;
    if (!next(tokens))
      fail("unexpected end of file, expected " + expected);
    return tokens;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw Invalid_input(m_source + ":" + std::to_string(m_line) + ": " + message);
  }

  // The current line, for messages (trimmed, at most 60 characters).
  std::string text() const {
    return "\"" + (m_text.size() > 60 ? m_text.substr(0, 57) + "..." : m_text) + "\"";
  }

  // Reads a data line of `size` tokens; `what` describes it ("2 numbers (x y) for vertex
  // 3 of 5"). A section keyword in its place means that a count was wrong: say so.
  std::vector<std::string> data_line(const std::string& what, std::size_t size) {
    std::vector<std::string> tokens = expect(what);
    static const char* const keywords[] = {"degree", "dimension", "number_type", "vertices",
                                           "faces",  "patches",   "end"};
    const bool keyword =
        std::find(std::begin(keywords), std::end(keywords), tokens[0]) != std::end(keywords);
    if (keyword || tokens.size() != size)
      fail("expected " + what + ", found " + text());
    return tokens;
  }

  // Reads "keyword value"; returns the value token.
  std::string keyword_value(const std::string& keyword) {
    const std::vector<std::string> tokens = expect("\"" + keyword + " ...\"");
    if (tokens[0] != keyword)
      fail("expected \"" + keyword + " ...\", found " + text());
    if (tokens.size() != 2)
      fail("expected one value after \"" + keyword + "\", found " + text());
    return tokens[1];
  }

  void keyword(const std::string& keyword) {
    const std::vector<std::string> tokens = expect("\"" + keyword + "\"");
    if (tokens.size() != 1 || tokens[0] != keyword)
      fail("expected \"" + keyword + "\", found " + text());
  }

  // A non-negative decimal integer no larger than `max`.
  std::size_t count(const std::string& token, const std::string& what, std::size_t max) const {
    if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos)
      fail("invalid " + what + " " + internal::quoted(token) +
           " (expected a non-negative integer)");
    // Twelve digits exceed every `max`; stoull cannot overflow below that.
    if (token.size() > 12 || static_cast<std::size_t>(std::stoull(token)) > max)
      fail(what + " " + internal::quoted(token) + " is out of range (at most " +
           std::to_string(max) + ")");
    return static_cast<std::size_t>(std::stoull(token));
  }

  // Fails unless `count` lines of at least `line_bytes` bytes each fit in what is left of a
  // seekable input, so that a corrupt count is reported at its line, not after reading on.
  void check_fits(std::size_t count, std::size_t line_bytes, const std::string& what) {
    const std::istream::pos_type here = m_input.tellg();
    if (here == std::istream::pos_type(-1) || !m_input.seekg(0, std::ios::end)) {
      m_input.clear(); // not seekable (or at its end): the read itself will fail
      return;
    }
    const std::istream::pos_type end = m_input.tellg();
    m_input.seekg(here);
    const auto left = static_cast<std::size_t>(end - here);
    if (count > left / line_bytes)
      fail(what + " " + std::to_string(count) + " cannot fit in the " + std::to_string(left) +
           " bytes left in the file (each needs a line of at least " + std::to_string(line_bytes) +
           " bytes)");
  }

  template <class FT>
  FT number(const std::string& token, bool exact_file) const {
    try {
      if (!exact_file)
        return FT(parse_double(token)); // exact conversion for an exact FT
      if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value)
        return parse_number<FT>(token);
      else
        return FT(nearest_double(parse_number<CGAL::Exact_rational>(token)));
    } catch (const Invalid_input& e) {
      fail(e.what());
    }
  }

private:
  std::istream& m_input;
  std::string m_source;
  std::size_t m_line = 0;
  std::string m_text;
};

constexpr const char* surface_file_magic = "tspline-surface";
constexpr int surface_file_version = 1;

// The corners of f in vertices_around_face order.
template <class Mesh>
std::array<typename Mesh::Vertex_index, 3> face_corners(const Mesh& mesh,
                                                        typename Mesh::Face_index f) {
  const auto h = mesh.halfedge(f);
  return {{mesh.target(h), mesh.target(mesh.next(h)), mesh.source(h)}};
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_FILE_FORMAT_H

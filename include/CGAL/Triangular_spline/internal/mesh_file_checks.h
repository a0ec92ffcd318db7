// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_MESH_FILE_CHECKS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_MESH_FILE_CHECKS_H

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

namespace internal {

// Checks of a mesh file before CGAL's readers see it: they trust the counts of a header
// (OFF and PLY reserve them: 2e9 faces cost gigabytes before the file runs out, a negative
// count wraps to 2^64), convert face indices from double (OFF: "1.5" becomes 1, "3e9"
// vertices per face are allocated) or stop at the first character that is not a digit
// (OBJ: "f 1 2.5 3" is the face 1 2 3). Each check reads the file once, without storing it.

[[noreturn]] inline void fail_at(const std::string& path, std::size_t line,
                                 const std::string& message) {
  throw Invalid_input(path + ":" + std::to_string(line) + ": " + message);
}

// Plain decimal digits, at most 18 of them (no sign, fraction or exponent).
inline bool parse_unsigned(const std::string& token, std::uint64_t& value) {
  if (token.empty() || token.size() > 18 ||
      token.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoull(token);
  return true;
}

// An optionally signed integer literal, as an integer property of a PLY file.
inline bool is_integer_literal(const std::string& token) {
  const std::size_t sign = !token.empty() && (token[0] == '+' || token[0] == '-') ? 1 : 0;
  return token.size() > sign && token.find_first_not_of("0123456789", sign) == std::string::npos;
}

// A decimal floating-point literal, which every reader of doubles reads whole.
inline bool is_decimal_literal(const std::string& token) {
  std::size_t i = !token.empty() && (token[0] == '+' || token[0] == '-') ? 1 : 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < token.size() && std::isdigit(static_cast<unsigned char>(token[i])))
      ++i;
    return i - start;
  };
  std::size_t mantissa = digits();
  if (i < token.size() && token[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0)
    return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-'))
      ++i;
    if (digits() == 0)
      return false;
  }
  return i == token.size();
}

inline std::uint64_t header_count(const std::string& path, std::size_t line,
                                  const std::string& token, const std::string& what) {
  std::uint64_t count = 0;
  if (!parse_unsigned(token, count)) {
    if (is_integer_literal(token) && token[0] != '-')
      fail_at(path, line, what + " " + internal::quoted(token) + " is out of range");
    fail_at(path, line,
            "invalid " + what + " " + internal::quoted(token) +
                " (expected a non-negative integer)");
  }
  return count;
}

// Fails unless `count` items of at least `item_bytes` bytes fit in the `left` bytes not yet
// claimed by earlier counts; returns the bytes still unclaimed.
inline std::uint64_t claim_bytes(const std::string& path, std::size_t line,
                                 std::uint64_t file_bytes, std::uint64_t left, std::uint64_t count,
                                 std::uint64_t item_bytes, const std::string& what) {
  if (count > left / item_bytes)
    fail_at(path, line,
            "the header announces " + std::to_string(count) + " " + what + ", more than the " +
                std::to_string(file_bytes) + "-byte file can hold (each needs at least " +
                std::to_string(item_bytes) + " bytes)");
  return left - count * item_bytes;
}

// Reads a text file as lines of tokens, `#` comments removed if `comments`.
class Token_lines {
public:
  // `line` lines of the input have already been read.
  Token_lines(std::istream& input, bool comments, std::size_t line = 0)
      : m_input(input), m_comments(comments), m_line(line) {}
  // The next line with a token; false at the end of the file.
  bool next(std::vector<std::string>& tokens) {
    while (std::getline(m_input, m_text)) {
      ++m_line;
      tokens = m_comments ? tokens_of_line(m_text) : split_tokens(m_text);
      if (!tokens.empty())
        return true;
    }
    return false;
  }
  std::size_t line() const { return m_line; }
  // The text of the line last returned, comments included.
  const std::string& text() const { return m_text; }

private:
  std::istream& m_input;
  bool m_comments;
  std::size_t m_line;
  std::string m_text;
};

// The keyword of an OFF file as CGAL's File_header_OFF reads it: the first character and
// the letters and digits after it, so "OFF~3" is the keyword OFF and then the count 3.
struct Off_keyword {
  std::size_t length = 1;     // of the keyword within the token
  std::string base;           // what follows the prefixes [ST][C][N][4][n]: CGAL wants OFF or SKEL
  bool n_dimensional = false; // nOFF: the dimension precedes the counts
  bool homogeneous = false;   // 4OFF: x y z w, CGAL divides by w
  bool decorated = false;     // ST (texture) or C (colour) prefix: refused
};

// CGAL's OFF header computes twice the edge count in an int.
constexpr std::uint64_t max_edge_count = 0x3fffffff;

inline Off_keyword off_keyword(const std::string& token) {
  Off_keyword k;
  while (k.length < token.size() && std::isalnum(static_cast<unsigned char>(token[k.length])))
    ++k.length;
  std::size_t j = k.length >= 2 && token.compare(0, 2, "ST") == 0 ? 2 : 0;
  k.decorated = j == 2;
  for (const char prefix : {'C', 'N', '4', 'n'})
    if (j < k.length && token[j] == prefix) {
      k.decorated = k.decorated || prefix == 'C';
      k.n_dimensional = prefix == 'n';
      k.homogeneous = k.homogeneous || prefix == '4';
      ++j;
    }
  k.base = token.substr(j, k.length - j);
  return k;
}

// OFF, as CGAL reads it: a header "[ST][C][N][4][n]OFF" (optional), the counts V F E (after
// the dimension for nOFF), then one vertex per line and one face "n i_1 ... i_n [colour]"
// per line. Every header CGAL accepts is checked: a keyword it would read differently from
// us, or a skeleton (SKEL, read by the same scanner), is refused here.
inline void check_off_file(const std::string& path, std::istream& input, std::uint64_t file_bytes) {
  Token_lines lines(input, true);
  std::vector<std::string> tokens;
  std::vector<std::string> header; // keyword and counts, over as many lines as they take
  std::size_t used = 0;            // tokens of the current line taken by the header
  std::size_t needed = 3;
  bool n_dimensional = false, homogeneous = false;
  while (header.size() < needed) {
    if (!lines.next(tokens)) {
      // Too short for CGAL's reader too, unless a token glues numbers ("3-10" is 3, -10).
      for (std::size_t i = 1; needed > 3 && i < header.size(); ++i)
        header_count(path, lines.line(), header[i], "header count");
      return;
    }
    for (used = 0; used < tokens.size() && header.size() < needed; ++used) {
      header.push_back(tokens[used]);
      const std::string& t = header.back();
      const Off_keyword keyword = header.size() == 1 ? off_keyword(t) : Off_keyword();
      if (keyword.base == "SKEL")
        fail_at(path, lines.line(),
                "SKEL (a skeleton of polylines) is not a supported mesh format");
      if (keyword.base == "OFF") {
        if (keyword.length != t.size())
          fail_at(path, lines.line(), "invalid OFF keyword " + internal::quoted(t));
        // CGAL 5.5 reads colour and texture entries without any check (heap overflows on
        // fuzzed files); a height field needs neither.
        if (keyword.decorated)
          fail_at(path, lines.line(),
                  internal::quoted(t) + ": OFF files with colours or textures (C, ST) are not "
                                        "supported; write plain OFF");
        // CGAL's scanner eats the character after the keyword: a '#' glued to it does not
        // start a comment there, and "OFF#BINARY" is a binary header (found by fuzzing).
        const std::size_t start = lines.text().find_first_not_of(blank_characters);
        if (start + t.size() < lines.text().size() && lines.text()[start + t.size()] == '#')
          fail_at(path, lines.line(),
                  "a comment glued to the OFF keyword; separate them with a space");
        n_dimensional = keyword.n_dimensional;
        homogeneous = keyword.homogeneous;
        needed = n_dimensional ? 5 : 4;
      } else if (header.size() == 2 && t.compare(0, 6, "BINARY") == 0) {
        // Binary OFF: CGAL's reading of its header and body differed from every check the
        // fuzzers met (6 GB allocations); a height field is written in ASCII.
        fail_at(path, lines.line(), "binary OFF is not supported; write the mesh as ASCII OFF");
      }
    }
  }
  if (needed == 3 && !is_integer_literal(header[0]))
    return; // neither a keyword nor a count: not an OFF file, CGAL's reader says so
  const std::size_t at = lines.line();
  const std::uint64_t V = header_count(path, at, header[needed - 3], "vertex count");
  const std::uint64_t F = header_count(path, at, header[needed - 2], "face count");
  // CGAL reads the header numbers with operator>>, which stops inside a token: "0-1-2-3"
  // is the edge count 0 and then the vertex (-1, -2, -3). Plain counts keep its lines and
  // ours the same.
  // CGAL doubles the edge count in an int.
  if (header_count(path, at, header[needed - 1], "edge count") > max_edge_count)
    fail_at(path, at, "edge count " + internal::quoted(header[needed - 1]) + " is out of range");
  if (n_dimensional)
    header_count(path, at, header[1], "dimension");
  // A vertex line "x y z\n" takes at least 6 bytes, a face line "n\n" at least 2.
  std::uint64_t left = claim_bytes(path, at, file_bytes, file_bytes, V, 6, "vertices");
  claim_bytes(path, at, file_bytes, left, F, 2, "faces");

  // CGAL divides x, y and z by w, asserting w != 0 (a debug build throws, not Invalid_input).
  auto check_w = [&](std::uint64_t v, std::size_t first) {
    const char* w = tokens.size() > first + 3 ? tokens[first + 3].c_str() : nullptr;
    char* end = nullptr;
    if (homogeneous && !n_dimensional && w != nullptr && std::strtod(w, &end) == 0 && end != w)
      fail_at(path, lines.line(), "vertex " + std::to_string(v) + ": w = 0");
  };
  // CGAL reads the rest of the counts' line as the first vertex line, or as the first face
  // line when there is no vertex (a face "-10 ..." then, undefined behaviour): refused.
  if (used < tokens.size())
    fail_at(path, at,
            "values after the counts on their line (" + internal::quoted(tokens[used]) +
                "): vertices and faces go on lines of their own");
  if (V == 0)
    fail_at(path, at, "the mesh has no vertex");
  std::uint64_t vertex_lines = 0;
  for (; vertex_lines < V; ++vertex_lines) {
    if (!lines.next(tokens))
      return;
    check_w(vertex_lines, 0);
  }
  for (std::uint64_t f = 0; f < F && lines.next(tokens); ++f) {
    const std::string face = "face " + std::to_string(f) + ": ";
    std::uint64_t n = 0;
    if (!parse_unsigned(tokens[0], n))
      fail_at(path, lines.line(),
              face + "invalid vertex count " + internal::quoted(tokens[0]) +
                  " (expected an integer)");
    if (n > tokens.size() - 1)
      fail_at(path, lines.line(),
              face + "announces " + std::to_string(n) + " vertices but lists " +
                  std::to_string(tokens.size() - 1));
    // What follows the indices is a face colour to CGAL, read without checks: only none,
    // a colour-map index 0..148, or 3-4 components all integers 0..255 or all in [0, 1].
    const std::size_t colour = tokens.size() - 1 - n;
    bool colour_ok = colour == 0 || colour == 1 || colour == 3 || colour == 4;
    bool integers = true, unit = true;
    for (std::size_t i = n + 1; i < tokens.size() && colour_ok; ++i) {
      std::uint64_t c = 0;
      const bool integer = parse_unsigned(tokens[i], c);
      integers = integers && integer && c <= (colour == 1 ? 148u : 255u);
      char* end = nullptr;
      const double x = std::strtod(tokens[i].c_str(), &end);
      unit = unit && end != tokens[i].c_str() && *end == '\0' && x >= 0 && x <= 1;
    }
    if (!colour_ok || (colour > 0 && !integers && (colour == 1 || !unit)))
      fail_at(path, lines.line(),
              face + "invalid face colour after the " + std::to_string(n) +
                  " vertex indices (expected nothing, an index 0..148, or 3 or 4 components)");
    for (std::size_t i = 1; i <= n; ++i) {
      std::uint64_t v = 0;
      if (!parse_unsigned(tokens[i], v))
        fail_at(path, lines.line(),
                face + "invalid vertex index " + internal::quoted(tokens[i]) +
                    " (expected a non-negative integer below " + std::to_string(V) + ")");
      if (v >= V)
        fail_at(path, lines.line(),
                face + "vertex index " + tokens[i] + " is out of range (there are " +
                    std::to_string(V) + " vertices)");
    }
  }
}

// OBJ: only "v" and "f" lines matter; a face corner is "v[/vt[/vn]]", v counted from 1, or
// from the end if negative.
inline void check_obj_file(const std::string& path, std::istream& input) {
  Token_lines lines(input, true);
  std::vector<std::string> tokens;
  std::uint64_t vertices = 0, largest = 0;
  std::size_t largest_line = 0;
  while (lines.next(tokens)) {
    if (tokens[0] == "v") {
      ++vertices;
      continue;
    }
    if (tokens[0] != "f")
      continue;
    for (std::size_t i = 1; i < tokens.size(); ++i) {
      const std::string index = tokens[i].substr(0, tokens[i].find('/'));
      const bool negative = !index.empty() && index[0] == '-';
      std::uint64_t v = 0;
      // Nine digits: CGAL reads an int, and silently ends the face at a larger one.
      if (!parse_unsigned(index.substr(negative ? 1 : 0), v) || v == 0 || v > 999999999)
        fail_at(path, lines.line(),
                "invalid face corner " + internal::quoted(tokens[i]) +
                    " (expected a vertex number from 1, or negative from the end)");
      if (negative && v > vertices)
        fail_at(path, lines.line(),
                "face corner " + tokens[i] + " refers back past the first vertex (" +
                    std::to_string(vertices) + " vertices so far)");
      if (!negative && v > largest) {
        largest = v;
        largest_line = lines.line();
      }
    }
  }
  if (largest > vertices)
    fail_at(path, largest_line,
            "face corner " + std::to_string(largest) + " is out of range (there are " +
                std::to_string(vertices) + " vertices)");
}

struct Ply_property {
  std::string name;
  bool list = false;
  int size_bytes = 0; // a list's count, or the scalar
  bool size_signed = false;
  int value_bytes = 0; // a list's values
  bool value_integer = false;
};

struct Ply_element {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> properties;
};

// Bytes of a PLY scalar type and whether it is an integer (signed); 0 bytes if unknown.
inline int ply_type(const std::string& type, bool& integer, bool& is_signed) {
  static const struct {
    const char *name, *alias;
    int bytes;
    bool integer, is_signed;
  } types[] = {{"char", "int8", 1, true, true},      {"uchar", "uint8", 1, true, false},
               {"short", "int16", 2, true, true},    {"ushort", "uint16", 2, true, false},
               {"int", "int32", 4, true, true},      {"uint", "uint32", 4, true, false},
               {"float", "float32", 4, false, true}, {"double", "float64", 8, false, true}};
  for (const auto& t : types)
    if (type == t.name || type == t.alias) {
      integer = t.integer;
      is_signed = t.is_signed;
      return t.bytes;
    }
  return 0;
}

// PLY: the element counts against the size of the body; then the body itself, element by
// element, so that no list announces more values than the file holds and an integer
// property (a face's vertex index) is not written as a fraction.
inline void check_ply_file(const std::string& path, std::istream& input, std::uint64_t file_bytes) {
  std::string text;
  std::size_t line = 0;
  bool ascii = true, big_endian = false;
  std::vector<Ply_element> elements;
  for (bool end = false; !end;) {
    if (!std::getline(input, text)) {
      if (line == 0)
        return; // empty: CGAL's reader says so
      // CGAL's reader takes the end of the file for the end of the header, then reads as
      // many elements as announced, from nothing (10^8 vertices: seconds, gigabytes).
      fail_at(path, line, "the PLY header has no end_header line");
    }
    const std::vector<std::string> tokens = split_tokens(text);
    ++line;
    if (line == 1 && (tokens.empty() || tokens[0] != "ply"))
      return; // not a PLY file: CGAL's reader says so (it ignores what follows "ply")
    // The header is read strictly: every line one of the standard forms, in printable
    // ASCII. CGAL's reader is lenient in ways that differ from any imitation of it (fuzzing
    // found a new difference per run); a header it could read otherwise is refused.
    for (const char c : text)
      if ((static_cast<unsigned char>(c) < 32 && c != '\t' && c != '\r') ||
          static_cast<unsigned char>(c) > 126)
        fail_at(path, line, "the PLY header holds a byte that is not printable ASCII");
    const bool comment = !tokens.empty() && (tokens[0] == "comment" || tokens[0] == "obj_info");
    const bool standard =
        comment || (line == 1 && tokens.size() == 1) ||
        (line == 2 && tokens.size() == 3 && tokens[0] == "format" &&
         (tokens[1] == "ascii" || tokens[1] == "binary_little_endian" ||
          tokens[1] == "binary_big_endian") &&
         tokens[2] == "1.0") ||
        (line > 2 && ((tokens.size() == 3 && (tokens[0] == "element" || tokens[0] == "property") &&
                       tokens[1] != "list") ||
                      (tokens.size() == 5 && tokens[0] == "property" && tokens[1] == "list") ||
                      (tokens.size() == 1 && tokens[0] == "end_header")));
    if (!standard)
      fail_at(path, line,
              "invalid PLY header line " + internal::quoted(text) +
                  " (expected ply, format ascii|binary_little_endian|binary_big_endian 1.0, "
                  "comment, element NAME COUNT, property TYPE NAME, property list TYPE TYPE "
                  "NAME or end_header)");
    if (line == 1 || comment)
      continue;
    if (line == 2) {
      ascii = tokens[1] == "ascii";
      big_endian = tokens[1] == "binary_big_endian";
    } else if (tokens[0] == "element" && tokens.size() >= 3) {
      for (const Ply_element& e : elements)
        if (e.name == tokens[1])
          fail_at(path, line, "PLY element " + internal::quoted(tokens[1]) + " declared twice");
      elements.push_back(
          {tokens[1], header_count(path, line, tokens[2], "element count"), line, {}});
    } else if (tokens[0] == "property" && elements.empty()) {
      // CGAL's reader adds a property to the last element, here to none: undefined behaviour.
      fail_at(path, line, "PLY property before the first element");
    } else if (tokens[0] == "property" && tokens.size() >= 3) {
      Ply_property p;
      bool integer = false, is_signed = false;
      p.list = tokens[1] == "list";
      const std::string& type = p.list ? tokens[2] : tokens[1];
      p.size_bytes = ply_type(type, integer, p.size_signed);
      if (p.size_bytes == 0 || (p.list && !integer))
        fail_at(path, line, "invalid PLY property type " + internal::quoted(type));
      p.value_integer = integer;
      if (p.list) {
        if (tokens.size() < 5 ||
            (p.value_bytes = ply_type(tokens[3], p.value_integer, is_signed)) == 0)
          fail_at(path, line, "invalid PLY list property " + internal::quoted(text));
      }
      p.name = tokens[p.list ? 4 : 2]; // as CGAL reads it: what follows is ignored
      // CGAL's point reader takes x, y and z as float or double, with no check in a
      // release build (a null dereference).
      const std::string& element = elements.back().name;
      if ((element == "vertex" || element == "vertices") &&
          (p.name == "x" || p.name == "y" || p.name == "z") && (p.list || integer))
        fail_at(path, line,
                "the vertex coordinate " + internal::quoted(p.name) +
                    " must be a float or double property, not " + internal::quoted(text));
      elements.back().properties.push_back(p);
    } else if (tokens[0] == "end_header") {
      end = true;
    }
  }
  const std::streamoff header_bytes = input.tellg();
  if (header_bytes < 0)
    return;
  const std::uint64_t body_bytes = file_bytes - static_cast<std::uint64_t>(header_bytes);
  std::uint64_t left = body_bytes;
  for (const Ply_element& e : elements) {
    // An ASCII value takes at least a digit and a blank; a binary one its size (a list at
    // least its count).
    std::uint64_t item_bytes = 0;
    for (const Ply_property& p : e.properties)
      item_bytes += ascii ? 2 : static_cast<std::uint64_t>(p.size_bytes);
    left = claim_bytes(path, e.line, file_bytes, left, e.count,
                       (std::max)(item_bytes, std::uint64_t(1)), "\"" + e.name + "\" elements");
  }

  if (ascii) {
    // CGAL reads the body token by token, whatever the lines.
    Token_lines lines(input, false, line);
    std::vector<std::string> tokens;
    std::size_t next = 0;
    auto token = [&]() -> const std::string* {
      while (next == tokens.size()) {
        if (!lines.next(tokens))
          return nullptr;
        next = 0;
      }
      return &tokens[next++];
    };
    for (const Ply_element& e : elements)
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (const Ply_property& p : e.properties) {
          const std::string where = e.name + " " + std::to_string(i) + ", " + p.name + ": ";
          const std::string* t = token();
          // At the end of the file CGAL's reader returns an uninitialised number (the
          // stream's sentry fails before operator>> writes), a list's length included.
          auto fail_short = [&] {
            fail_at(path, lines.line(),
                    where + "the file ends before the elements its header announces");
          };
          if (t == nullptr)
            fail_short();
          std::uint64_t values = 1;
          if (p.list && !parse_unsigned(*t, values))
            fail_at(path, lines.line(),
                    where + "invalid list length " + internal::quoted(*t) +
                        " (expected a non-negative integer)");
          if (p.list && values > body_bytes / 2)
            fail_at(path, lines.line(),
                    where + "a list of " + *t + " values cannot fit in the file");
          for (std::uint64_t k = 0; k < (p.list ? values : 1); ++k) {
            if (p.list && (t = token()) == nullptr)
              fail_short();
            if (p.value_integer && !is_integer_literal(*t))
              fail_at(path, lines.line(), where + internal::quoted(*t) + " is not an integer");
            // CGAL reads "1.5-7" as 1.5 and then -7: one token, two values for it.
            if (!p.value_integer && !is_decimal_literal(*t))
              fail_at(path, lines.line(), where + internal::quoted(*t) + " is not a number");
          }
        }
    return;
  }
  // Binary: walk the lists, reading their lengths.
  left = body_bytes;
  for (const Ply_element& e : elements)
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const Ply_property& p : e.properties) {
        unsigned char bytes[8] = {0};
        // CGAL's reader would resize a list to a length read past the end of the file
        // (uninitialised bytes), before it looks at the stream.
        if (left < static_cast<std::uint64_t>(p.size_bytes) ||
            !input.read(reinterpret_cast<char*>(bytes), p.size_bytes))
          throw Invalid_input(path + ": " + e.name + " " + std::to_string(i) + ", " + p.name +
                              ": the file ends before the elements its header announces");
        left -= static_cast<std::uint64_t>(p.size_bytes);
        if (!p.list)
          continue;
        std::uint64_t length = 0;
        for (int b = 0; b < p.size_bytes; ++b)
          length |= std::uint64_t(bytes[big_endian ? b : p.size_bytes - 1 - b])
                    << (8 * (p.size_bytes - 1 - b));
        const bool negative = p.size_signed && (length >> (8 * p.size_bytes - 1)) != 0;
        if (negative || length > left / static_cast<std::uint64_t>(p.value_bytes))
          throw Invalid_input(path + ": " + e.name + " " + std::to_string(i) + ", " + p.name +
                              ": a list of " +
                              (negative ? "negative length" : std::to_string(length) + " values") +
                              " does not fit in the file");
        left -= length * static_cast<std::uint64_t>(p.value_bytes);
        input.ignore(static_cast<std::streamsize>(length) * p.value_bytes);
      }
}

// Lower-case extension of `path` with its dot, or "".
inline std::string mesh_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  std::string extension = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                              ? ""
                              : path.substr(dot);
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

} // namespace internal

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_MESH_FILE_CHECKS_H

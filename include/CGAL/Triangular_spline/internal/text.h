// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_TEXT_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_TEXT_H

#include <CGAL/number_utils.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The characters that separate tokens in every text format the package reads: those of
// std::isspace in the "C" locale but '\n', which std::getline() has already taken. Every
// reader splits with split_tokens(), so that a line of blanks is empty for all of them (a
// reader that tested fewer characters than its tokenizer skipped read a token that was not
// there).
constexpr const char* blank_characters = " \t\r\f\v";

// The blank-separated tokens of `text`.
inline std::vector<std::string> split_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  std::size_t begin = text.find_first_not_of(blank_characters);
  while (begin != std::string::npos) {
    const std::size_t end = text.find_first_of(blank_characters, begin);
    tokens.push_back(text.substr(begin, end == std::string::npos ? end : end - begin));
    begin = end == std::string::npos ? end : text.find_first_not_of(blank_characters, end);
  }
  return tokens;
}

// The tokens of a line of a format where `#` starts a comment that runs to the end of the line.
inline std::vector<std::string> tokens_of_line(const std::string& line) {
  return split_tokens(line.substr(0, line.find('#')));
}

// Longest part of a token that error messages quote: a corrupt file may hold a token of
// megabytes, and the message must stay one readable line.
constexpr std::size_t max_quoted_length = 40;

// `token` in double quotes for an error message; a long token is cut, marked with "..."
// and followed by its length.
inline std::string quoted(const std::string& token) {
  if (token.size() <= max_quoted_length)
    return "\"" + token + "\"";
  return "\"" + token.substr(0, max_quoted_length) + "...\" (" + std::to_string(token.size()) +
         " characters)";
}

// Appends the shortest decimal that reads back to `x` (std::to_chars), "nan" for a NaN.
// It is the writers' hot path: %.17g took 12.7 of the 33 s that `tspline c1` spent on 10^6
// points, most of it in saving the spline; this is about ten times faster and the numbers
// are shorter.
inline void append_double(std::string& text, double x) {
  if (std::isnan(x)) {
    text += "nan";
    return;
  }
  char buffer[32];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, x);
  text.append(buffer, result.ptr);
}

// A point for error messages, in double with 17 digits.
template <class Point_2>
std::string point_to_string(const Point_2& p) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << ")";
  return out.str();
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_TEXT_H

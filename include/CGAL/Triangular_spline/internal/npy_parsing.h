// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_NPY_PARSING_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_NPY_PARSING_H

// The pieces of read_npy() and scattered_data_from_npy() (IO/npy.h): the header grammar
// that np.save writes, little-endian values, and the check of a value as a coordinate.

#include <CGAL/Triangular_spline/IO/Npy_array.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// numpy's own limit on the header (np.load's max_header_size): a longer one is not a file
// that np.save wrote, and parsing it would only cost time.
constexpr std::size_t npy_max_header_size = 10000;

// The header is a Python dict literal: {'descr': '<f8', 'fortran_order': False,
// 'shape': (n, k), } padded with spaces and a newline. This is the grammar np.save writes
// (and np.load's safe literal_eval accepts for these three keys), nothing more.
class Npy_header_parser {
public:
  Npy_header_parser(const std::string& text, const std::string& source)
      : m_text(text), m_source(source) {}

  void parse(std::string& descr, bool& fortran_order, std::vector<std::size_t>& shape) {
    bool has_descr = false, has_order = false, has_shape = false;
    expect('{');
    while (true) {
      skip_blanks();
      if (peek() == '}')
        break;
      const std::string key = quoted_string();
      expect(':');
      skip_blanks();
      if (key == "descr") {
        if (peek() != '\'' && peek() != '"')
          fail("unsupported dtype: structured arrays are not read; save a plain (n, k) array");
        descr = quoted_string();
        has_descr = true;
      } else if (key == "fortran_order") {
        fortran_order = boolean();
        has_order = true;
      } else if (key == "shape") {
        shape = tuple();
        has_shape = true;
      } else {
        fail("unexpected key '" + key + "' in the header");
      }
      skip_blanks();
      if (peek() == ',') {
        ++m_pos;
        continue;
      }
      if (peek() != '}')
        fail("malformed header (expected ',' or '}')");
    }
    ++m_pos;
    skip_blanks();
    if (m_pos != m_text.size())
      fail("malformed header (text after the closing '}')");
    if (!has_descr || !has_order || !has_shape)
      fail("malformed header (it needs 'descr', 'fortran_order' and 'shape')");
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Invalid_input(m_source + ": not a readable .npy file: " + what);
  }
  char peek() const { return m_pos < m_text.size() ? m_text[m_pos] : '\0'; }
  void skip_blanks() {
    while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos])))
      ++m_pos;
  }
  void expect(char c) {
    skip_blanks();
    if (peek() != c)
      fail(std::string("malformed header (expected '") + c + "')");
    ++m_pos;
  }
  std::string quoted_string() {
    skip_blanks();
    const char quote = peek();
    if (quote != '\'' && quote != '"')
      fail("malformed header (expected a quoted key or string)");
    const std::size_t end = m_text.find(quote, m_pos + 1);
    if (end == std::string::npos || end - m_pos > 64)
      fail("malformed header (unterminated string)");
    std::string s = m_text.substr(m_pos + 1, end - m_pos - 1);
    m_pos = end + 1;
    return s;
  }
  bool boolean() {
    if (m_text.compare(m_pos, 4, "True") == 0) {
      m_pos += 4;
      return true;
    }
    if (m_text.compare(m_pos, 5, "False") == 0) {
      m_pos += 5;
      return false;
    }
    fail("malformed header ('fortran_order' must be True or False)");
  }
  std::vector<std::size_t> tuple() {
    expect('(');
    std::vector<std::size_t> dims;
    while (true) {
      skip_blanks();
      if (peek() == ')')
        break;
      if (!std::isdigit(static_cast<unsigned char>(peek())))
        fail("malformed header (the shape must be a tuple of non-negative integers)");
      std::size_t value = 0;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        const std::size_t digit = static_cast<std::size_t>(peek() - '0');
        if (value > (std::numeric_limits<std::size_t>::max() - digit) / 10)
          fail("the shape's dimensions are too large");
        value = 10 * value + digit;
        ++m_pos;
      }
      dims.push_back(value);
      if (dims.size() > 32) // numpy's own limit on dimensions
        fail("malformed header (more than 32 dimensions)");
      skip_blanks();
      if (peek() == ',') {
        ++m_pos;
        continue;
      }
      if (peek() != ')')
        fail("malformed header (expected ',' or ')' in the shape)");
    }
    ++m_pos;
    return dims;
  }

  const std::string& m_text;
  const std::string& m_source;
  std::size_t m_pos = 0;
};

// Little-endian bytes to a value, whatever the host's byte order.
inline std::uint64_t npy_little_endian(const unsigned char* p, std::size_t bytes) {
  std::uint64_t u = 0;
  for (std::size_t i = bytes; i-- > 0;)
    u = (u << 8) | p[i];
  return u;
}

inline double npy_float(const unsigned char* p, std::size_t size) {
  const std::uint64_t u = npy_little_endian(p, size);
  if (size == 8) {
    double d;
    std::memcpy(&d, &u, 8);
    return d;
  }
  const std::uint32_t u32 = static_cast<std::uint32_t>(u);
  float f;
  std::memcpy(&f, &u32, 4);
  return static_cast<double>(f);
}

inline std::int64_t npy_integer(const unsigned char* p, std::size_t size) {
  const std::uint64_t u = npy_little_endian(p, size);
  // two's complement, without the implementation-defined unsigned-to-signed conversion
  const std::uint64_t sign = std::uint64_t(1) << (8 * size - 1);
  if (!(u & sign))
    return static_cast<std::int64_t>(u);
  // negative: -(magnitude), magnitude = ~u + 1 within `size` bytes, which reaches 2^63
  const std::uint64_t magnitude_minus_1 = ~u & (sign | (sign - 1));
  return -static_cast<std::int64_t>(magnitude_minus_1) - 1;
}

// A value of a .npy array as a coordinate: finite and within the magnitudes the text readers
// accept (parse_number(): above 1e150 a product of two coordinates overflows in double).
inline double npy_coordinate(const Npy_array& array, std::size_t row, std::size_t column,
                             const std::string& source) {
  const double v = array(row, column);
  if (!std::isfinite(v) || std::fabs(v) > 1e150)
    throw Invalid_input(source + ": row " + std::to_string(row) + ", column " +
                        std::to_string(column) + ": " +
                        (std::isnan(v)   ? std::string("NaN")
                         : std::isinf(v) ? std::string("infinity")
                                         : std::string("magnitude above 1e150")) +
                        " is not a coordinate");
  return v;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_NPY_PARSING_H

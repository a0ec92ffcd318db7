// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_NPY_H
#define CGAL_TRIANGULAR_SPLINE_IO_NPY_H

#include <CGAL/Triangular_spline/IO/Npy_array.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/npy_parsing.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads a two-dimensional array from a NumPy `.npy` file (format versions 1, 2 and 3,
  as written by `numpy.save`).

  Accepted element types: little-endian `float64` (`<f8`), `float32` (`<f4`), `int32` (`<i4`)
  and `int64` (`<i8`, values of magnitude up to \f$2^{53}\f$, which a double holds exactly), in C
  or Fortran order. Values are returned as they are: NaN and infinities are left to the caller.

  The size that the header announces is checked against the bytes the stream holds before
  anything is allocated, so a header claiming a huge shape in a small file costs nothing.

  \param input the stream, opened in binary mode
  \param source the name used in error messages (usually the file name)
  \throws Invalid_input whose message starts with `source` for a bad magic string, an
  unknown version, a malformed or oversized header, a big-endian or unsupported element type,
  a shape that is not two-dimensional, or data shorter or longer than the shape says.
  \returns the array, row-major
*/
inline Npy_array read_npy(std::istream& input, const std::string& source) {
  auto fail = [&source](const std::string& what) -> Invalid_input {
    return Invalid_input(source + ": not a readable .npy file: " + what);
  };
  unsigned char preamble[12];
  input.read(reinterpret_cast<char*>(preamble), 8);
  if (input.gcount() < 8 || std::memcmp(preamble, "\x93NUMPY", 6) != 0)
    throw fail("bad magic string (a .npy file starts with \\x93NUMPY, as numpy.save writes)");
  const int major = preamble[6];
  if (major < 1 || major > 3)
    throw fail("format version " + std::to_string(major) + "." + std::to_string(preamble[7]) +
               " (versions 1, 2 and 3 are read)");
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  input.read(reinterpret_cast<char*>(preamble + 8), static_cast<std::streamsize>(length_bytes));
  if (static_cast<std::size_t>(input.gcount()) < length_bytes)
    throw fail("truncated header");
  const std::size_t header_size =
      static_cast<std::size_t>(internal::npy_little_endian(preamble + 8, length_bytes));
  if (header_size > internal::npy_max_header_size)
    throw fail("header of " + std::to_string(header_size) + " bytes (numpy writes at most " +
               std::to_string(internal::npy_max_header_size) + ")");
  std::string header(header_size, '\0');
  input.read(&header[0], static_cast<std::streamsize>(header_size));
  if (static_cast<std::size_t>(input.gcount()) < header_size)
    throw fail("truncated header");

  std::string descr;
  bool fortran_order = false;
  std::vector<std::size_t> shape;
  internal::Npy_header_parser(header, source).parse(descr, fortran_order, shape);

  const bool little = descr.size() == 3 && (descr[0] == '<' || descr[0] == '|');
  const char kind = descr.size() == 3 ? descr[1] : '\0';
  const std::size_t item = descr.size() == 3 ? static_cast<std::size_t>(descr[2] - '0') : 0;
  const bool known = (kind == 'f' || kind == 'i') && (item == 4 || item == 8);
  if (descr.size() == 3 && descr[0] == '>' && known)
    throw fail("big-endian dtype '" + descr +
               "' is not read; save a.astype('<f8') (little-endian float64) instead");
  if (!little || !known)
    throw fail("unsupported dtype '" + descr +
               "' (float64 '<f8', float32 '<f4', int32 '<i4' or int64 '<i8' are read)");
  if (shape.size() != 2) {
    std::string dims;
    for (std::size_t d : shape)
      dims += (dims.empty() ? "" : ", ") + std::to_string(d);
    throw fail("shape (" + dims + (shape.size() == 1 ? "," : "") +
               ") is not two-dimensional (expected (n, k): one row per point)");
  }

  Npy_array array;
  array.rows = shape[0];
  array.columns = shape[1];
  array.dtype = descr;
  const std::string shape_text =
      "(" + std::to_string(shape[0]) + ", " + std::to_string(shape[1]) + ")";
  // Overflow-checked byte count, then compared with what the stream holds: no allocation
  // follows a header that promises more than the file has.
  const std::size_t max = std::numeric_limits<std::size_t>::max();
  if (shape[1] != 0 && shape[0] > max / shape[1] / item)
    throw fail("shape " + shape_text + " is too large");
  const std::size_t count = shape[0] * shape[1];
  const std::size_t bytes = count * item;
  const std::streampos here = input.tellg();
  if (here != std::streampos(-1)) {
    input.seekg(0, std::ios::end);
    const std::streampos end = input.tellg();
    input.clear(); // a stream that cannot seek to its end is read in blocks below
    input.seekg(here);
    if (end != std::streampos(-1) && input) {
      const std::size_t available = static_cast<std::size_t>(end - here);
      if (available < bytes)
        throw fail("truncated data: shape " + shape_text + " of '" + descr + "' needs " +
                   std::to_string(bytes) + " bytes, the file holds only " +
                   std::to_string(available) + " after the header");
      if (available > bytes)
        throw fail(std::to_string(available - bytes) + " bytes after the data of shape " +
                   shape_text);
    }
  }
  input.clear(input.rdstate() & ~std::ios::eofbit);

  // Read in blocks, so that a stream of unknown size (a pipe) is never trusted with the
  // allocation either: memory grows only with the bytes actually read.
  constexpr std::size_t block = std::size_t(1) << 16; // elements
  std::vector<unsigned char> buffer;
  array.values.reserve(std::min(count, block));
  for (std::size_t done = 0; done < count;) {
    const std::size_t n = std::min(block, count - done);
    buffer.resize(n * item);
    input.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(n * item));
    if (static_cast<std::size_t>(input.gcount()) < n * item)
      throw fail("truncated data: shape " + shape_text + " of '" + descr + "' needs " +
                 std::to_string(bytes) + " bytes, the data end after " +
                 std::to_string(done * item + static_cast<std::size_t>(input.gcount())));
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* p = buffer.data() + i * item;
      if (kind == 'f') {
        array.values.push_back(internal::npy_float(p, item));
        continue;
      }
      const std::int64_t v = internal::npy_integer(p, item);
      constexpr std::int64_t exact = std::int64_t(1) << 53; // doubles hold integers up to 2^53
      if (v > exact || v < -exact)
        throw fail("integer " + std::to_string(v) + " at element " + std::to_string(done + i) +
                   " is not exactly a double (|value| > 2^53)");
      array.values.push_back(static_cast<double>(v));
    }
    done += n;
  }
  if (input.bad())
    throw Invalid_input(source + ": read error");
  if (fortran_order && array.rows > 1 && array.columns > 1) {
    // column after column in the file: transposed into rows
    std::vector<double> rows(count);
    for (std::size_t c = 0; c < array.columns; ++c)
      for (std::size_t r = 0; r < array.rows; ++r)
        rows[r * array.columns + c] = array.values[c * array.rows + r];
    array.values.swap(rows);
  }
  return array;
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief the scattered data held in columns of an array read by `read_npy()`: `x y z` (and
  `zx zy` with gradients) from the columns `columns` of each row, checked as `read_xyz()`
  checks a text file.

  Rows are numbered from 0, as in numpy. The values convert exactly to `GeomTraits::FT`.

  \tparam GeomTraits a model of `Kernel`
  \param array the array
  \param source the name used in error messages
  \param columns the column indices of x, y, z (and zx, zy): 3 of them, or 5 for gradients
  \throws Invalid_input naming `source` and the row for a NaN, an infinity or a magnitude
  above \f$10^{150}\f$, or a column index out of range; then as `read_xyz()` for duplicates,
  fewer than three distinct points and collinear points.
  \returns the scattered data (with gradients if `columns` has 5 entries)
*/
template <class GeomTraits>
Scattered_data<GeomTraits> scattered_data_from_npy(const Npy_array& array,
                                                   const std::string& source,
                                                   const std::vector<std::size_t>& columns) {
  using FT = typename GeomTraits::FT;
  if (columns.size() != 3 && columns.size() != 5)
    throw Invalid_input(source + ": 3 columns (x, y, z) or 5 (x, y, z, zx, zy) are read, not " +
                        std::to_string(columns.size()));
  for (std::size_t c : columns)
    if (c >= array.columns)
      throw Invalid_input(source + ": no column " + std::to_string(c) + " in an array of shape (" +
                          std::to_string(array.rows) + ", " + std::to_string(array.columns) +
                          ") (columns are numbered from 0)");
  std::vector<typename GeomTraits::Point_2> points;
  std::vector<FT> values;
  std::vector<std::array<FT, 2>> gradients;
  points.reserve(array.rows);
  values.reserve(array.rows);
  for (std::size_t r = 0; r < array.rows; ++r) {
    double c[5];
    for (std::size_t k = 0; k < columns.size(); ++k)
      c[k] = internal::npy_coordinate(array, r, columns[k], source);
    points.emplace_back(FT(c[0]), FT(c[1]));
    values.push_back(FT(c[2]));
    if (columns.size() == 5)
      gradients.push_back({{FT(c[3]), FT(c[4])}});
  }
  return internal::finish_scattered_data<GeomTraits>(
      points, values, gradients, source,
      [&](std::size_t i) { return source + ": row " + std::to_string(i); });
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief query points from an array read by `read_npy()`: columns 0 and 1 of each row (more
  columns, e.g. the heights of an `(n, 3)` array, are ignored, as in `read_query_points()`).
  \tparam GeomTraits a model of `Kernel`
  \throws Invalid_input naming `source` for an array of fewer than two columns, and the row
  for a NaN, an infinity or a magnitude above \f$10^{150}\f$
  \param array the array
  \param source the name used in error messages
  \returns the query points
*/
template <class GeomTraits>
std::vector<typename GeomTraits::Point_2> query_points_from_npy(const Npy_array& array,
                                                                const std::string& source) {
  using FT = typename GeomTraits::FT;
  if (array.columns < 2)
    throw Invalid_input(source + ": query points need 2 columns (x, y), the array has " +
                        std::to_string(array.columns));
  std::vector<typename GeomTraits::Point_2> points;
  points.reserve(array.rows);
  for (std::size_t r = 0; r < array.rows; ++r)
    points.emplace_back(FT(internal::npy_coordinate(array, r, 0, source)),
                        FT(internal::npy_coordinate(array, r, 1, source)));
  return points;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_NPY_H

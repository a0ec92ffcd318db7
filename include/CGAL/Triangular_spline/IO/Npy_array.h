// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_NPY_ARRAY_H
#define CGAL_TRIANGULAR_SPLINE_IO_NPY_ARRAY_H

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief a two-dimensional array read from a NumPy `.npy` file, as doubles in row-major
  order (whatever the file's order).
*/
struct Npy_array {
  std::size_t rows = 0;       ///< the first dimension of the shape
  std::size_t columns = 0;    ///< the second dimension of the shape
  std::string dtype;          ///< the file's type description, e.g. `<f8`
  std::vector<double> values; ///< `rows * columns` values, row after row

  /// returns the value in row `r`, column `c`
  /// \param r the row, less than `rows`
  /// \param c the column, less than `columns`
  /// \returns the value in row `r`, column `c`
  double operator()(std::size_t r, std::size_t c) const { return values[r * columns + c]; }
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_NPY_ARRAY_H

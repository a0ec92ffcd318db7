// Tabular input of tspline c1 (--columns). CSV: a header line naming the columns, comma-separated
// fields. The chosen columns are handed to the library's .xyz reader, so that numbers,
// duplicates and degenerate sets are checked (and worded) as for .xyz files.

#ifndef TSPLINE_CSV_INPUT_H
#define TSPLINE_CSV_INPUT_H

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace tspline {

// The CSV text `in` as 'x y z[ zx zy]' lines, one per CSV line (the header becomes a comment,
// so line numbers carry over to the reader's messages). `columns`: the header names of x, y,
// z (and zx, zy with `gradients`), comma-separated; empty: the columns named x, y, z (zx, zy),
// case-insensitive. Throws CGAL::Triangular_spline::Invalid_input naming `source` and the line.
std::string csv_as_xyz(std::istream& in, const std::string& source, const std::string& columns,
                       bool gradients);

// The column indices of x, y, z (and zx, zy with `gradients`) in a .npy array of shape (rows,
// array_columns): `columns` lists them ("0,1,2", numbered from 0); empty: all the columns of an
// (n, 3) array ((n, 5) with gradients). Throws Invalid_input naming `source`.
std::vector<std::size_t> npy_column_indices(const std::string& columns, std::size_t rows,
                                            std::size_t array_columns, bool gradients,
                                            const std::string& source);

} // namespace tspline

#endif // TSPLINE_CSV_INPUT_H

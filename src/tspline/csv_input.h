// CSV input of tspline c1 (--columns): a header line naming the columns, comma-separated
// fields. The chosen columns are handed to the library's .xyz reader, so that numbers,
// duplicates and degenerate sets are checked (and worded) as for .xyz files.

#ifndef TSPLINE_CSV_INPUT_H
#define TSPLINE_CSV_INPUT_H

#include <istream>
#include <string>

namespace tspline {

// The CSV text `in` as 'x y z[ zx zy]' lines, one per CSV line (the header becomes a comment,
// so line numbers carry over to the reader's messages). `columns`: the header names of x, y,
// z (and zx, zy with `gradients`), comma-separated; empty: the columns named x, y, z (zx, zy),
// case-insensitive. Throws CGAL::Triangular_spline::Invalid_input naming `source` and the line.
std::string csv_as_xyz(std::istream& in, const std::string& source, const std::string& columns,
                       bool gradients);

} // namespace tspline

#endif // TSPLINE_CSV_INPUT_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_SCATTERED_DATA_H
#define CGAL_TRIANGULAR_SPLINE_IO_SCATTERED_DATA_H

#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Domain/Scattered_data.h>
#include <CGAL/Triangular_spline/Domain/delaunay_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/scattered_data_checks.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <istream>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads scattered height data, one point `x y z` per line (`x y z zx zy` with
  `with_gradients`: the gradient of the height too).

  Numbers are read with `parse_number<FT>()`, so with an exact kernel decimals are exact
  (`0.1` is 1/10). Blank lines are skipped, and `#` starts a comment that runs to the end of
  the line. Points with the same \f$(x,y)\f$ (exact comparison) and the same height are
  merged into the first of them and counted in `merged_duplicates`.

  \tparam GeomTraits a model of `Kernel`
  \param input the stream to read
  \param source the name used in error messages (usually the file name)
  \throws Invalid_input whose message starts with `source:line` for a line without exactly
  three numbers (five with gradients) or with an invalid number (garbage, NaN, infinity, magnitude
  above \f$10^{150}\f$), and names both lines for two points with the same \f$(x,y)\f$ and different
  heights (or gradients); also thrown if fewer than three distinct points remain or if all points
  are collinear (no triangle can be built).
  \param with_gradients `true` if each line also holds the gradient `zx zy`
  \returns the scattered data
*/
template <class GeomTraits>
Scattered_data<GeomTraits> read_xyz(std::istream& input, const std::string& source,
                                    bool with_gradients = false) {
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  const std::size_t columns = with_gradients ? 5 : 3;
  std::vector<Point_2> points;
  std::vector<FT> values;
  std::vector<std::array<FT, 2>> gradients;
  std::vector<std::size_t> lines;
  std::string line;
  for (std::size_t number = 1; std::getline(input, line); ++number) {
    const std::vector<std::string> tokens = internal::tokens_of_line(line);
    if (tokens.empty())
      continue;
    const std::string where = source + ":" + std::to_string(number) + ": ";
    if (tokens.size() != columns)
      throw Invalid_input(
          where + "expected " + (with_gradients ? "5 numbers (x y z zx zy)" : "3 numbers (x y z)") +
          ", found " + std::to_string(tokens.size()) + " fields" +
          (tokens.size() == 5 && !with_gradients ? " (gradients? see --gradients)" : ""));
    FT c[5];
    for (std::size_t i = 0; i < columns; ++i) {
      try {
        c[i] = parse_number<FT>(tokens[i]);
      } catch (const Invalid_input& e) {
        throw Invalid_input(where + e.what());
      }
    }
    points.emplace_back(c[0], c[1]);
    values.push_back(c[2]);
    if (with_gradients)
      gradients.push_back({{c[3], c[4]}});
    lines.push_back(number);
  }
  if (input.bad())
    throw Invalid_input(source + ": read error");
  return internal::finish_scattered_data<GeomTraits>(
      points, values, gradients, source,
      [&](std::size_t i) { return source + ":" + std::to_string(lines[i]); });
}

/*!
  \ingroup PkgTriangularSplineIO
  \brief reads query points, `x y` per line (a third column, as in `.xyz` files, is
  ignored; `#` starts a comment; blank lines are skipped), parsed as `GeomTraits::FT`
  (exactly for exact number types).
  \tparam GeomTraits a model of `Kernel`
  \throws Invalid_input naming `name` and the line for a malformed line or number
  \param in the input stream
  \param name the name used in error messages
  \returns the query points
*/
template <class GeomTraits>
std::vector<typename GeomTraits::Point_2> read_query_points(std::istream& in,
                                                            const std::string& name) {
  using FT = typename GeomTraits::FT;
  std::vector<typename GeomTraits::Point_2> points;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> tokens = internal::tokens_of_line(line);
    if (tokens.empty())
      continue;
    if (tokens.size() != 2 && tokens.size() != 3)
      throw Invalid_input(name + ":" + std::to_string(number) +
                          ": expected 'x y' (or 'x y z'), got " + std::to_string(tokens.size()) +
                          " fields");
    try {
      points.emplace_back(parse_number<FT>(tokens[0]), parse_number<FT>(tokens[1]));
    } catch (const Invalid_input& e) {
      throw Invalid_input(name + ":" + std::to_string(number) + ": " + e.what());
    }
  }
  if (in.bad())
    throw Invalid_input("read error on '" + name + "'");
  return points;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_SCATTERED_DATA_H

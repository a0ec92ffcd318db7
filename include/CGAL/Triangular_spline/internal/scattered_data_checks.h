// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SCATTERED_DATA_CHECKS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SCATTERED_DATA_CHECKS_H

// What every scattered-data reader does once the points are read (IO/scattered_data.h,
// IO/npy.h): duplicates merged or refused, and at least one triangle's worth of points.

#include <CGAL/Triangular_spline/Domain/Scattered_data.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/hilbert_order.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Exact duplicates merged (the first occurrence kept, in input order), contradicting ones
// refused: sorted exactly by (x, y), neighbours compared.
template <class GeomTraits, class Where>
Scattered_data<GeomTraits>
merge_duplicates(const std::vector<typename GeomTraits::Point_2>& points,
                 const std::vector<typename GeomTraits::FT>& values,
                 const std::vector<std::array<typename GeomTraits::FT, 2>>& gradients,
                 const Where& where) {
  const bool with_gradients = !gradients.empty();
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  if constexpr (std::is_floating_point_v<typename GeomTraits::FT>) {
    const auto less_xy = GeomTraits().less_xy_2_object();
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return less_xy(points[a], points[b]); });
  } else {
    // Exact coordinates: the same order, each comparison decided by the coordinates'
    // intervals where they are disjoint (rationals compare by cross-multiplying: 10^5
    // 17-digit points, 0.25 s).
    std::vector<Coordinate_intervals> intervals(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      intervals[i] = coordinate_intervals(points[i]);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const CGAL::Comparison_result x =
          interval_compare(points[a].x(), intervals[a][0], points[b].x(), intervals[b][0]);
      return x != CGAL::EQUAL ? x == CGAL::SMALLER
                              : interval_compare(points[a].y(), intervals[a][1], points[b].y(),
                                                 intervals[b][1]) == CGAL::SMALLER;
    });
  }
  std::vector<char> keep(points.size(), 1);
  Scattered_data<GeomTraits> data;
  data.points.reserve(points.size());
  data.values.reserve(points.size());
  for (std::size_t i = 1; i < order.size(); ++i) {
    const std::size_t first = order[i - 1], second = order[i];
    if (points[first] != points[second])
      continue;
    if (values[first] != values[second])
      throw Invalid_input(where(first) + " and " + where(second) + ": the same point " +
                          internal::point_to_string(points[first]) + " has different heights " +
                          format_number(values[first]) + " and " + format_number(values[second]));
    if (with_gradients && gradients[first] != gradients[second])
      throw Invalid_input(where(first) + " and " + where(second) + ": the same point " +
                          internal::point_to_string(points[first]) + " has different gradients");
    keep[second] = 0;
    order[i] = first; // later copies compare with the kept one
    ++data.merged_duplicates;
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (keep[i]) {
      data.points.push_back(points[i]);
      data.values.push_back(values[i]);
      if (with_gradients)
        data.gradients.push_back(gradients[i]);
    }
  return data;
}

// Whether two of the points may be equal (double coordinates; -0 equals 0): an
// open-addressing table of indices by the coordinates' bits, in linear time. `false` is
// certain; `true` also where the table's probes run long (the sort then decides).
template <class Point_2>
bool may_repeat_a_point(const std::vector<Point_2>& points) {
  if (points.size() >= std::numeric_limits<std::uint32_t>::max() / 2)
    return true;
  auto mix = [](std::uint64_t h) { // splitmix64's finaliser
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  };
  std::size_t size = 16;
  while (size < 2 * points.size())
    size *= 2;
  std::vector<std::uint32_t> table(size, 0); // index + 1, 0 empty
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x() + 0.0, y = points[i].y() + 0.0; // -0 to +0
    std::uint64_t bx, by;
    std::memcpy(&bx, &x, sizeof bx);
    std::memcpy(&by, &y, sizeof by);
    std::size_t at = std::size_t(mix(bx ^ mix(by))) & (size - 1);
    for (int probe = 0;; ++probe, at = (at + 1) & (size - 1)) {
      const std::uint32_t j = table[at];
      if (j == 0) {
        table[at] = static_cast<std::uint32_t>(i + 1);
        break;
      }
      if (points[j - 1] == points[i] || probe == 64)
        return true;
    }
  }
  return false;
}

// What every scattered-data reader checks once the points are read (read_xyz(), and
// scattered_data_from_npy() in npy.h): exact duplicates merged (the first occurrence kept,
// in input order), contradicting duplicates refused, at least one triangle's worth of points.
// `where(i)` names point i in messages ("file:line", "file: row r").
template <class GeomTraits, class Where>
Scattered_data<GeomTraits>
finish_scattered_data(const std::vector<typename GeomTraits::Point_2>& points,
                      const std::vector<typename GeomTraits::FT>& values,
                      const std::vector<std::array<typename GeomTraits::FT, 2>>& gradients,
                      const std::string& source, Where where) {
  // Most inputs repeat no point: a hash table tells in linear time, and every point is then
  // kept as it is (10^6 points: 0.04 s, against 0.15 s for merge_duplicates()'s sort).
  bool distinct = false;
  if constexpr (std::is_floating_point_v<typename GeomTraits::FT>)
    distinct = !may_repeat_a_point(points);
  Scattered_data<GeomTraits> data;
  if (distinct) {
    data.points = points;
    data.values = values;
    data.gradients = gradients;
  } else {
    data = merge_duplicates<GeomTraits>(points, values, gradients, where);
  }
  const std::size_t n = data.points.size();
  if (n < 3)
    throw Invalid_input(source + ": " + std::to_string(n) + " distinct point" +
                        (n == 1 ? "" : "s") + ", at least 3 are needed for a triangle");
  const auto collinear = GeomTraits().collinear_2_object();
  bool all_collinear = true;
  for (std::size_t i = 2; i < n && all_collinear; ++i)
    all_collinear = collinear(data.points[0], data.points[1], data.points[i]);
  if (all_collinear)
    throw Invalid_input(source + ": all " + std::to_string(n) +
                        " points are collinear: no triangle");
  return data;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SCATTERED_DATA_CHECKS_H

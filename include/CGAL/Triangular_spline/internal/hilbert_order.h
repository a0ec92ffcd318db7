// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H

// The Hilbert order in which domain_from_triangulation_2() numbers the vertices.

#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/Hilbert_sort_median_2.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <CGAL/Hilbert_sort_base.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Hilbert sorting of (point, handle) pairs with ties broken by the other coordinate: a strict
// total order on distinct points, so the numbering does not depend on the input order.
// Double coordinates are compared directly: the same exact answers, without Epick's
// interval filter around compare_yx_2 (2% of a c1 run at 10^6 points).
template <class GeomTraits, class Handle>
struct Lexicographic_hilbert_traits {
  using Point_2 = std::pair<typename GeomTraits::Point_2, Handle>;
  static constexpr bool double_coordinates = std::is_same_v<typename GeomTraits::FT, double>;
  struct Less_x_2 {
    bool operator()(const Point_2& a, const Point_2& b) const {
      if constexpr (double_coordinates)
        return a.first.x() < b.first.x() ||
               (a.first.x() == b.first.x() && a.first.y() < b.first.y());
      else
        return GeomTraits().compare_xy_2_object()(a.first, b.first) == CGAL::SMALLER;
    }
  };
  struct Less_y_2 {
    bool operator()(const Point_2& a, const Point_2& b) const {
      if constexpr (double_coordinates)
        return a.first.y() < b.first.y() ||
               (a.first.y() == b.first.y() && a.first.x() < b.first.x());
      else
        return GeomTraits().compare_yx_2_object()(a.first, b.first) == CGAL::SMALLER;
    }
  };
  Less_x_2 less_x_2_object() const { return Less_x_2(); }
  Less_y_2 less_y_2_object() const { return Less_y_2(); }
};

// Enclosing intervals of a point's coordinates (CGAL::to_interval()), for comparisons of exact
// coordinates that decide by intervals where they can (interval_compare()).
using Coordinate_intervals = std::array<std::pair<double, double>, 2>;
template <class Point_2>
Coordinate_intervals coordinate_intervals(const Point_2& p) {
  return {{CGAL::to_interval(p.x()), CGAL::to_interval(p.y())}};
}
// compare(a, b) for a in the interval ia and b in ib: the intervals decide when disjoint.
template <class FT>
CGAL::Comparison_result interval_compare(const FT& a, const std::pair<double, double>& ia,
                                         const FT& b, const std::pair<double, double>& ib) {
  if (ia.second < ib.first)
    return CGAL::SMALLER;
  if (ia.first > ib.second)
    return CGAL::LARGER;
  return CGAL::compare(a, b);
}

// The order of Lexicographic_hilbert_traits for points of an exact number type, on indices
// into `points`: each coordinate's comparison decided by its enclosing intervals (computed
// once) where they are disjoint, exactly only where they overlap. Comparing rationals
// cross-multiplies them, and the sort moved (point, handle) pairs, two rationals each (10^5
// 17-digit points: 0.35 s of the domain's numbering). Every comparison has the exact answer,
// so the sort's permutation is the same.
template <class GeomTraits>
struct Indexed_hilbert_traits {
  using Point_2 = std::uint32_t;
  using Points = std::vector<typename GeomTraits::Point_2>;
  using Intervals = std::vector<Coordinate_intervals>;
  const Points* points;
  const Intervals* intervals;
  static CGAL::Comparison_result compare(const Points& p, const Intervals& i, Point_2 a, Point_2 b,
                                         int c) {
    return c == 0 ? interval_compare(p[a].x(), i[a][0], p[b].x(), i[b][0])
                  : interval_compare(p[a].y(), i[a][1], p[b].y(), i[b][1]);
  }
  template <int First>
  struct Less {
    const Points* points;
    const Intervals* intervals;
    bool operator()(Point_2 a, Point_2 b) const {
      const CGAL::Comparison_result r = compare(*points, *intervals, a, b, First);
      return r != CGAL::EQUAL ? r == CGAL::SMALLER
                              : compare(*points, *intervals, a, b, 1 - First) == CGAL::SMALLER;
    }
  };
  using Less_x_2 = Less<0>;
  using Less_y_2 = Less<1>;
  Less_x_2 less_x_2_object() const { return {points, intervals}; }
  Less_y_2 less_y_2_object() const { return {points, intervals}; }
};

// CGAL::hilbert_sort(begin, end, traits, Hilbert_sort_median_policy()) with its first level on
// the cores: the median split by x, then the two splits by y side by side, then the four
// quarters' sorts side by side. The same splits of the same ranges in another order, so the
// same result; what CGAL's Parallel_tag does with TBB, which the package does not link (the
// sort was a serial 0.3 s of a c1 run at 10^6 points).
template <class Traits, class Iterator>
void hilbert_sort_on_cores(Iterator begin, Iterator end, const Traits& traits) {
  const CGAL::Hilbert_sort_median_2<Traits, CGAL::Sequential_tag> sort(traits);
  const std::size_t threads = thread_count(std::size_t(end - begin), std::size_t(1) << 15);
  if (threads < 2) {
    sort(begin, end);
    return;
  }
  // Hilbert_sort_median_2::recursive_sort<0, false, false>(begin, end), unrolled once
  using CGAL::internal::Hilbert_cmp_2;
  const Iterator m2 =
      CGAL::internal::hilbert_split(begin, end, Hilbert_cmp_2<Traits, 0, false>(traits));
  Iterator m1 = begin, m3 = m2;
  parallel_for_index(
      2, threads,
      [&](std::size_t i) {
        if (i == 0)
          m1 = CGAL::internal::hilbert_split(begin, m2, Hilbert_cmp_2<Traits, 1, false>(traits));
        else
          m3 = CGAL::internal::hilbert_split(m2, end, Hilbert_cmp_2<Traits, 1, true>(traits));
      },
      1);
  parallel_for_index(
      4, threads,
      [&](std::size_t i) {
        if (i == 0)
          sort.template recursive_sort<1, false, false>(begin, m1);
        else if (i == 1)
          sort.template recursive_sort<0, false, false>(m1, m2);
        else if (i == 2)
          sort.template recursive_sort<0, false, false>(m2, m3);
        else
          sort.template recursive_sort<1, true, true>(m3, end);
      },
      1);
}

// The permutation that puts distinct `points` in the order above: order[r] is the index of
// the r-th point. The order is strict and total and CGAL's median Hilbert sort splits down
// to single points, so it depends on the points alone, not on their order in the input.
template <class GeomTraits>
std::vector<std::uint32_t>
hilbert_permutation(const std::vector<typename GeomTraits::Point_2>& points) {
  std::vector<std::uint32_t> order(points.size());
  if constexpr (std::is_floating_point_v<typename GeomTraits::FT>) {
    // (point, index) pairs: the sort's passes read them in sequence
    std::vector<std::pair<typename GeomTraits::Point_2, std::uint32_t>> pairs;
    pairs.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      pairs.emplace_back(points[i], static_cast<std::uint32_t>(i));
    hilbert_sort_on_cores(pairs.begin(), pairs.end(),
                          Lexicographic_hilbert_traits<GeomTraits, std::uint32_t>());
    for (std::size_t r = 0; r < pairs.size(); ++r)
      order[r] = pairs[r].second;
  } else {
    std::vector<Coordinate_intervals> intervals;
    intervals.reserve(points.size());
    for (const auto& p : points)
      intervals.push_back(coordinate_intervals(p));
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = static_cast<std::uint32_t>(i);
    hilbert_sort_on_cores(order.begin(), order.end(),
                          Indexed_hilbert_traits<GeomTraits>{&points, &intervals});
  }
  return order;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_HILBERT_ORDER_H

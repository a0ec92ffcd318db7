// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_JOIN_CHECKS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_JOIN_CHECKS_H

// The pieces of check_join() (continuity.h) that the continuity adjustment shares: the shared
// edge of two patches, and the residuals of the conditions.

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Join_report.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/enum.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Finds the shared edge: returns {p, r, s} local indices in A and {q, r, s} in B, where
// r and s are the same points in both. Exact point comparison and orientation decide.
template <class GeomTraits, class Value>
std::pair<std::array<int, 3>, std::array<int, 3>>
shared_edge(const Bezier_triangle<GeomTraits, Value>& A,
            const Bezier_triangle<GeomTraits, Value>& B) {
  std::vector<std::pair<int, int>> common;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (A.vertex(a) == B.vertex(b))
        common.emplace_back(a, b);
  if (common.size() != 2)
    throw Invalid_input("join test: the domain triangles share " + std::to_string(common.size()) +
                        " vertices, adjacent triangles share exactly 2");
  const int p = 3 - common[0].first - common[1].first;
  const int q = 3 - common[0].second - common[1].second;
  const auto orientation = A.geom_traits().orientation_2_object();
  const auto& r = A.vertex(common[0].first);
  const auto& s = A.vertex(common[1].first);
  const CGAL::Orientation op = orientation(r, s, A.vertex(p));
  const CGAL::Orientation oq = orientation(r, s, B.vertex(q));
  if (op == oq)
    throw Invalid_input("join test: the domain triangles overlap (both apexes " +
                        point_to_string(A.vertex(p)) + " and " + point_to_string(B.vertex(q)) +
                        " lie on the same side of the shared edge)");
  return {{{p, common[0].first, common[1].first}}, {{q, common[0].second, common[1].second}}};
}

// Fills the residual and the verdict of one condition from its difference. The tolerance is
// compared exactly in the number type, and log10 of a residual outside double's normal
// range is taken from the exact difference (folded into the report's max_residual_log10).
template <class Value>
void record_difference(Join_condition& c, const Value& difference, double tolerance,
                       Join_report& report) {
  c.residual = max_abs_coordinate(difference);
  c.zero = is_zero_value(difference);
  c.satisfied = c.zero || (tolerance > 0 && is_within_tolerance(difference, tolerance));
  if (!c.zero && !(c.residual >= 1e-300 && c.residual <= 1e300)) {
    const double magnitude = max_abs_coordinate_log10(difference);
    if (!(magnitude <= report.max_residual_log10))
      report.max_residual_log10 = magnitude;
  }
}

// The largest residual and the achieved order, once every condition is recorded.
inline void summarize_conditions(Join_report& report) {
  double normal_max = 0;
  for (const Join_condition& c : report.conditions) {
    if (!(c.residual <= report.max_residual))
      report.max_residual = c.residual;
    if (!c.zero && c.residual >= 1e-300 && c.residual <= 1e300 && c.residual > normal_max)
      normal_max = c.residual;
    if (!c.satisfied && c.order - 1 < report.achieved_order)
      report.achieved_order = c.order - 1;
  }
  if (normal_max > 0 && !(std::log10(normal_max) <= report.max_residual_log10))
    report.max_residual_log10 = std::log10(normal_max);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_JOIN_CHECKS_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_CONDITIONS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_CONDITIONS_H

// The C^1 conditions of a quintic spline as sparse rows over its control-point slots, for the
// dimension count of Spline_space.h.

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/internal/spline_plan.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Calls row(r) for each C^1 condition (3.5) of each interior edge of the exact `domain`,
// written on the shared control-point slots (which build in C^0): r holds (slot,
// coefficient) pairs sorted by slot, zero coefficients dropped. Returns the slot count.
template <class Domain>
std::size_t c1_slot_count(const Domain& domain) {
  return domain.number_of_vertices() + 4 * domain.number_of_edges() + 6 * domain.number_of_faces();
}

template <class Exact, class RowCallback>
std::size_t for_each_c1_condition(const Planar_domain<Exact>& domain, RowCallback row_callback) {
  using FT = typename Exact::FT;
  using Index = typename Planar_domain<Exact>::Index;
  const std::size_t slots = c1_slot_count(domain);
  for (Index e = 0; e < domain.number_of_edges(); ++e) {
    if (domain.is_boundary_edge(e))
      continue;
    const auto& ef = domain.edge_faces(e);
    const Index A = ef[0], B = ef[1];
    const Index p = domain.opposite_vertex(A, e), q = domain.opposite_vertex(B, e);
    const Index r = domain.edge(e)[0], s = domain.edge(e)[1];
    // q = l p + u r + n s
    const auto& P = domain.point(p);
    const auto& Q = domain.point(q);
    const auto& R = domain.point(r);
    const auto& S = domain.point(s);
    const FT d = (R.x() - P.x()) * (S.y() - P.y()) - (R.y() - P.y()) * (S.x() - P.x());
    const FT u = ((Q.x() - P.x()) * (S.y() - P.y()) - (Q.y() - P.y()) * (S.x() - P.x())) / d;
    const FT n = ((R.x() - P.x()) * (Q.y() - P.y()) - (R.y() - P.y()) * (Q.x() - P.x())) / d;
    const FT l = FT(1) - u - n;
    auto slot_in = [&](Index f, Index apex, int g, int i) {
      // the control point of face f with g copies of apex, i of r, 5-g-i of s
      const auto& t = domain.face(f);
      Multi_index index;
      for (int c = 0; c < 3; ++c)
        index[c] = t[std::size_t(c)] == apex ? g : (t[std::size_t(c)] == r ? i : 5 - g - i);
      return internal::quintic_slot(domain, f, index);
    };
    for (int i = 0; i <= 4; ++i) {
      std::vector<std::pair<std::uint32_t, FT>> row{{slot_in(B, q, 1, i), FT(1)},
                                                    {slot_in(A, p, 1, i), -l},
                                                    {slot_in(A, p, 0, i + 1), -u},
                                                    {slot_in(A, p, 0, i), -n}};
      std::sort(row.begin(), row.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      // Zero coefficients (u or n vanish when q is on a line through p) are dropped.
      row.erase(std::remove_if(row.begin(), row.end(),
                               [](const auto& x) { return CGAL::is_zero(x.second); }),
                row.end());
      row_callback(std::move(row));
    }
  }
  return slots;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_CONDITIONS_H

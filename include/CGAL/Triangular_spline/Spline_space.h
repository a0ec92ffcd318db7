// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_SPLINE_SPACE_H
#define CGAL_TRIANGULAR_SPLINE_SPLINE_SPACE_H

#include <CGAL/Triangular_spline/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Planar_domain.h>
#include <CGAL/Triangular_spline/degenerate_frames.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns Xu's free-parameter count \f$3V + 3F + E_I + 3E_B + \sigma\f$ of the
  quintic C^1 scheme with re-routed degenerate frames (\f$\sigma\f$: interior singular
  vertices).
*/
template <class GeomTraits>
std::size_t free_parameter_count(const Planar_domain<GeomTraits>& domain) {
  return 3 * domain.number_of_vertices() + 3 * domain.number_of_faces() +
         domain.number_of_interior_edges() + 3 * domain.number_of_boundary_edges() +
         find_degenerate_frames(domain).singular_vertices.size();
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns Morgan and Scott's dimension of \f$S^1_5\f$,
  \f$12 V_I + 10 V_B - 9 + \sigma\f$, or nothing when the domain is not simply connected
  (the formula holds for triangulated disks only).
*/
template <class GeomTraits>
std::optional<long long> morgan_scott_dimension(const Planar_domain<GeomTraits>& domain) {
  if (!domain.is_simply_connected())
    return std::nullopt;
  return 12 * static_cast<long long>(domain.number_of_interior_vertices()) +
         10 * static_cast<long long>(domain.number_of_boundary_vertices()) - 9 +
         static_cast<long long>(find_degenerate_frames(domain).singular_vertices.size());
}

namespace internal {

// Rank of a sparse matrix over an exact field, by incremental elimination: each new row is
// reduced by the stored pivot rows (leading entry 1, all other entries to its right) until
// it vanishes or starts a new pivot.
template <class FT>
class Sparse_rank {
public:
  using Row = std::vector<std::pair<std::uint32_t, FT>>; // sorted by column

  explicit Sparse_rank(std::size_t columns) : m_pivot(columns, -1) {}

  void add(Row row) {
    Row scratch;
    while (!row.empty()) {
      const std::uint32_t column = row.front().first;
      const int p = m_pivot[column];
      if (p < 0) {
        const FT lead = row.front().second;
        for (auto& entry : row)
          entry.second = entry.second / lead;
        m_pivot[column] = static_cast<int>(m_rows.size());
        m_rows.push_back(std::move(row));
        return;
      }
      // row -= row[column] * pivot, merging the two sorted rows.
      const FT factor = row.front().second;
      const Row& pivot = m_rows[static_cast<std::size_t>(p)];
      scratch.clear();
      std::size_t a = 1, b = 1;
      while (a < row.size() || b < pivot.size()) {
        if (b == pivot.size() || (a < row.size() && row[a].first < pivot[b].first)) {
          scratch.push_back(row[a++]);
        } else if (a == row.size() || pivot[b].first < row[a].first) {
          const FT v = -factor * pivot[b].second;
          scratch.emplace_back(pivot[b].first, v);
          ++b;
        } else {
          const FT v = row[a].second - factor * pivot[b].second;
          if (!CGAL::is_zero(v))
            scratch.emplace_back(row[a].first, v);
          ++a;
          ++b;
        }
      }
      std::swap(row, scratch);
    }
  }

  std::size_t rank() const { return m_rows.size(); }

private:
  std::vector<int> m_pivot;
  std::vector<Row> m_rows;
};

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the dimension of the space \f$S^1_5\f$ of C^1 piecewise quintics over
  `domain`, computed independently of the prescription scheme: the exact rank of the C^1
  conditions (3.5) of every interior edge, written on the shared control-point slots (which
  build in C^0), subtracted from the number of slots.

  The domain is converted to exact rationals first (exactly), so the result is exact for
  any kernel. The elimination is sparse; its fill-in depends on the triangulation, and on
  jittered grids it stays near-linear (measured: 0.2 s for 9800 triangles, 2.6 s for
  100352 triangles).
*/
template <class GeomTraits>
std::size_t exact_spline_dimension(const Planar_domain<GeomTraits>& input) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  using FT = Exact::FT;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  using Index = typename Planar_domain<Exact>::Index;
  const std::size_t slots =
      domain.number_of_vertices() + 4 * domain.number_of_edges() + 6 * domain.number_of_faces();
  internal::Sparse_rank<FT> rank(slots);
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
      rank.add(std::move(row));
    }
  }
  return slots - rank.rank();
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_SPLINE_SPACE_H

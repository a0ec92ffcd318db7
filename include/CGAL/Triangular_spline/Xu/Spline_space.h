// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H
#define CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Xu/degenerate_frames.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Fraction_traits.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdint>
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
  \tparam GeomTraits a model of `Kernel`
  \param domain the triangulated planar domain
  \returns Xu's free-parameter count \f$3V + 3F + E_I + 3E_B + \sigma\f$ of the quintic C^1 scheme
  with re-routed degenerate frames (\f$\sigma\f$: interior singular vertices)
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
  \tparam GeomTraits a model of `Kernel`
  \param domain the triangulated planar domain
  \returns Morgan and Scott's dimension of \f$S^1_5\f$, \f$12 V_I + 10 V_B - 9 + \sigma\f$, or
  nothing when the domain is not simply connected (the formula holds for triangulated disks only)
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

// Exact rational arithmetic, as the field of Sparse_rank.
template <class FT>
struct Rational_field {
  FT multiply(const FT& a, const FT& b) const { return a * b; }
  FT subtract(const FT& a, const FT& b) const { return a - b; }
  FT inverse(const FT& a) const { return FT(1) / a; }
  bool is_zero(const FT& a) const { return CGAL::is_zero(a); }
};

// Rank of a sparse matrix over an exact field, by incremental elimination: each new row is
// reduced by the stored pivot rows (leading entry 1, all other entries to its right) until
// it vanishes or starts a new pivot.
template <class Entry, class Field = Rational_field<Entry>>
class Sparse_rank {
public:
  using Row = std::vector<std::pair<std::uint32_t, Entry>>; // sorted by column, no zeros

  explicit Sparse_rank(std::size_t columns, const Field& field = Field())
      : m_field(field), m_pivot(columns, -1) {}

  void add(Row row) {
    Row scratch;
    while (!row.empty()) {
      const std::uint32_t column = row.front().first;
      const int p = m_pivot[column];
      if (p < 0) {
        const Entry inverse = m_field.inverse(row.front().second);
        for (auto& entry : row)
          entry.second = m_field.multiply(entry.second, inverse);
        m_pivot[column] = static_cast<int>(m_rows.size());
        m_rows.push_back(std::move(row));
        return;
      }
      // row -= row[column] * pivot, merging the two sorted rows.
      const Entry factor = row.front().second;
      const Row& pivot = m_rows[static_cast<std::size_t>(p)];
      scratch.clear();
      std::size_t a = 1, b = 1;
      while (a < row.size() || b < pivot.size()) {
        if (b == pivot.size() || (a < row.size() && row[a].first < pivot[b].first)) {
          scratch.push_back(row[a++]);
        } else if (a == row.size() || pivot[b].first < row[a].first) {
          scratch.emplace_back(
              pivot[b].first,
              m_field.subtract(Entry(0), m_field.multiply(factor, pivot[b].second)));
          ++b;
        } else {
          const Entry v =
              m_field.subtract(row[a].second, m_field.multiply(factor, pivot[b].second));
          if (!m_field.is_zero(v))
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
  Field m_field;
  std::vector<int> m_pivot;
  std::vector<Row> m_rows;
};

} // namespace internal

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

// Arithmetic modulo a prime below 2^31 (products fit in 64 bits).
class Modular_field {
public:
  explicit Modular_field(std::uint64_t prime) : m_p(prime) {}
  std::uint64_t prime() const { return m_p; }
  std::uint64_t multiply(std::uint64_t a, std::uint64_t b) const { return a * b % m_p; }
  std::uint64_t subtract(std::uint64_t a, std::uint64_t b) const {
    return a >= b ? a - b : a + m_p - b;
  }
  bool is_zero(std::uint64_t a) const { return a == 0; }
  std::uint64_t inverse(std::uint64_t a) const { // a^(p-2), a != 0
    std::uint64_t result = 1, base = a, e = m_p - 2;
    for (; e > 0; e >>= 1, base = multiply(base, base))
      if (e & 1)
        result = multiply(result, base);
    return result;
  }
  // x mod p for an exact rational x; false when p divides its denominator.
  template <class FT>
  bool reduce(const FT& x, std::uint64_t& result) const {
    using Fractions = CGAL::Fraction_traits<FT>;
    typename Fractions::Numerator_type numerator;
    typename Fractions::Denominator_type denominator;
    typename Fractions::Decompose()(x, numerator, denominator);
    const std::uint64_t n = reduce_integer(numerator), d = reduce_integer(denominator);
    if (d == 0)
      return false;
    result = multiply(n, inverse(d));
    return true;
  }

private:
  template <class Integer>
  std::uint64_t reduce_integer(const Integer& z) const {
    const Integer prime(static_cast<double>(m_p)); // exact: p < 2^31
    Integer r = z % prime;                         // sign of z (truncating division)
    if (CGAL::is_negative(r))
      r = r + prime;
    return static_cast<std::uint64_t>(CGAL::to_double(r));
  }
  std::uint64_t m_p;
};

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the dimension of the space \f$S^1_5\f$ of C^1 piecewise quintics over
  `domain`, computed independently of the prescription scheme: the exact rank of the C^1
  conditions (3.5) of every interior edge, written on the shared control-point slots (which
  build in C^0), subtracted from the number of slots.

  The domain is converted to exact rationals first (exactly), so the result is exact for
  any kernel. The elimination is sparse and exact; its fill-in depends on the
  triangulation. On jittered grids it stays near-linear (measured: 0.2 s for 9800
  triangles, 2.6 s for 100352 triangles); on scattered points with decimal coordinates
  the rationals grow without bound (16 s for 30 points, 11 min for 50): use
  `spline_dimension_upper_bound()` there.
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \returns the dimension of the space \f$S^1_5\f$ of C^1 piecewise quintics over `domain`, computed
  independently of the prescription scheme
*/
template <class GeomTraits>
std::size_t exact_spline_dimension(const Planar_domain<GeomTraits>& input) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  const std::size_t slots = internal::c1_slot_count(domain);
  internal::Sparse_rank<Exact::FT> rank(slots);
  internal::for_each_c1_condition(domain, [&](auto row) { rank.add(std::move(row)); });
  return slots - rank.rank();
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the result of `spline_dimension_upper_bound()`.
*/
struct Dimension_bound {
  std::size_t upper_bound = 0; ///< \f$\dim S^1_5 \le\f$ this
  std::uint64_t prime = 0;     ///< the prime the rank was computed modulo
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns an upper bound of \f$\dim S^1_5\f$ over `domain`: the number of slots minus
  the rank of the C^1 conditions of `exact_spline_dimension()` modulo a prime \f$p <
  2^{31}\f$.

  Reducing modulo \f$p\f$ (a prime dividing no denominator of the conditions) can only lower
  a rank, so the bound is rigorous; it is the dimension unless \f$p\f$ divides one of the
  finitely many minors that make the rational rank, which for a prime near \f$2^{31}\f$
  practically never happens. Together with a lower bound it proves the dimension: every
  assignment of the scheme's free values is a C^1 spline, distinct assignments give
  distinct splines, so \f$\dim S^1_5 \ge\f$ `free_parameter_count()`, and an upper bound
  equal to that count proves both equal. Linear in practice: the elimination runs in
  machine integers, with columns ordered by the vertex each slot belongs to so that the
  fill-in stays near the diagonal (measured on random points: 0.11 s for 10^3, 1.1 s for
  10^4, 12 s for 10^5; grouping the columns by kind instead took 11 s for 10^3 and 265 s
  for 3000).
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \returns an upper bound of \f$\dim S^1_5\f$ over `domain`
*/
template <class GeomTraits>
Dimension_bound spline_dimension_upper_bound(const Planar_domain<GeomTraits>& input) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  using Index = typename Planar_domain<Exact>::Index;
  // Columns in the order of the vertex each slot belongs to (an edge's or a face's smallest
  // vertex): with spatially numbered vertices the matrix is nearly banded, and the
  // elimination's fill-in stays near the diagonal (slots grouped by kind, vertices first,
  // filled it far more: 1000 points took 11 s).
  const std::size_t V = domain.number_of_vertices(), E = domain.number_of_edges();
  const std::size_t slots = internal::c1_slot_count(domain);
  std::vector<std::uint32_t> column(slots);
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(slots);
    for (std::size_t s = 0; s < slots; ++s) {
      std::uint64_t owner;
      if (s < V)
        owner = s;
      else if (s < V + 4 * E)
        owner = domain.edge(Index((s - V) / 4))[0]; // the smaller index first
      else {
        const auto& t = domain.face(Index((s - V - 4 * E) / 6));
        owner = (std::min)({t[0], t[1], t[2]});
      }
      keys[s] = {owner * slots + s, std::uint32_t(s)};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < slots; ++i)
      column[keys[i].second] = std::uint32_t(i);
  }
  // Primes just below 2^31: the first that divides no denominator is used.
  for (std::uint64_t prime : {2147483629ull, 2147483587ull, 2147483579ull, 2147483563ull}) {
    const internal::Modular_field field(prime);
    internal::Sparse_rank<std::uint64_t, internal::Modular_field> rank(slots, field);
    bool reducible = true;
    internal::for_each_c1_condition(domain, [&](const auto& row) {
      if (!reducible)
        return;
      internal::Sparse_rank<std::uint64_t, internal::Modular_field>::Row reduced;
      for (const auto& [c, value] : row) {
        std::uint64_t v = 0;
        if (!field.reduce(value, v)) {
          reducible = false;
          return;
        }
        if (v != 0)
          reduced.emplace_back(column[c], v);
      }
      std::sort(reduced.begin(), reduced.end());
      rank.add(std::move(reduced));
    });
    if (reducible)
      return {slots - rank.rank(), prime};
  }
  throw Invalid_input("spline dimension: every prime tried divides a denominator of the C^1 "
                      "conditions");
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H

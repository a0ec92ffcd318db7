// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SPARSE_RANK_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SPARSE_RANK_H

// The rank of a sparse matrix over an exact field, and the two fields of Spline_space.h:
// exact rationals, and integers modulo a prime.

#include <CGAL/Fraction_traits.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
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
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SPARSE_RANK_H

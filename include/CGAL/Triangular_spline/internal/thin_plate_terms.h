// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_THIN_PLATE_TERMS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_THIN_PLATE_TERMS_H

// The pieces of thin_plate_energy(): positions of multi-indices, the Bernstein Gram table
// (computed once per number type and degree), and the frame of a triangle.

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

// Declared here, defined (and documented) in Xu/thin_plate_energy.h, which includes this
// header.
inline std::vector<Multi_index> bernstein_indices(int degree);

namespace internal {

// Position of a multi-index of degree m in bernstein_indices(m): rows i = m .. a.i + 1 first.
inline std::size_t bernstein_position(int m, const Multi_index& a) {
  const int before = (m - a.i) * (m - a.i + 1) / 2;
  return static_cast<std::size_t>(before + (m - a.i - a.j));
}

// The Gram matrix of the Bernstein polynomials of degree d over a triangle of area
// (2d+1)(2d+2)/2, in the order of bernstein_indices(d): C(d,a) C(d,b) / C(2d,a+b), with C the
// multinomial coefficients (integers, exact up to d = 10 in 64 bits). It does not depend on
// the triangle, so it is computed once per number type and degree (the energy of 10^6
// patches recomputed it from factorials every time).
template <class FT>
std::vector<FT> compute_bernstein_gram_table(int d) {
  auto factorial = [](int k) -> FT {
    FT f(1);
    for (int i = 2; i <= k; ++i)
      f = f * FT(i);
    return f;
  };
  auto multinomial = [&](int m, const Multi_index& a) -> FT {
    return factorial(m) / (factorial(a.i) * factorial(a.j) * factorial(a.k));
  };
  const auto coarse = bernstein_indices(d);
  const std::size_t c = coarse.size();
  std::vector<FT> table(c * c);
  for (std::size_t a = 0; a < c; ++a)
    for (std::size_t b = 0; b < c; ++b) {
      const Multi_index sum{coarse[a].i + coarse[b].i, coarse[a].j + coarse[b].j,
                            coarse[a].k + coarse[b].k};
      table[a * c + b] =
          multinomial(d, coarse[a]) * multinomial(d, coarse[b]) / multinomial(2 * d, sum);
    }
  return table;
}

template <class FT>
const std::vector<FT>& bernstein_gram_table(int d) {
  // Degrees below 8 without a lock (tspline c1 reads the table for every face, on all cores;
  // the mutex cost more than the table's use), the others cached under the mutex.
  constexpr int small = 8;
  if (0 <= d && d < small) {
    static const std::array<std::vector<FT>, small> tables = [] {
      std::array<std::vector<FT>, small> t;
      for (int k = 0; k < small; ++k)
        t[std::size_t(k)] = compute_bernstein_gram_table<FT>(k);
      return t;
    }();
    return tables[std::size_t(d)];
  }
  static std::mutex mutex;
  static std::vector<std::unique_ptr<const std::vector<FT>>> tables;
  const std::lock_guard<std::mutex> lock(mutex);
  if (tables.size() <= std::size_t(d))
    tables.resize(std::size_t(d) + 1);
  if (!tables[std::size_t(d)])
    tables[std::size_t(d)] =
        std::make_unique<const std::vector<FT>>(compute_bernstein_gram_table<FT>(d));
  return *tables[std::size_t(d)];
}

// The barycentric coordinates of the unit vectors e_x, e_y in the triangle (r, s, t) and the
// scale of the Gram matrix of degree m - 2 (area and the factor m(m-1) of the second
// derivatives); throws on a collinear triangle.
template <class Point_2, class FT>
void thin_plate_frame(int degree, const Point_2& r, const Point_2& s, const Point_2& t,
                      std::array<FT, 3>& ex, std::array<FT, 3>& ey, FT& scale) {
  const FT ux = s.x() - r.x(), uy = s.y() - r.y(), vx = t.x() - r.x(), vy = t.y() - r.y();
  const FT det = ux * vy - uy * vx;
  if (CGAL::is_zero(det))
    throw Invalid_input("thin_plate_energy: degenerate triangle");
  ex = {{(uy - vy) / det, vy / det, -uy / det}};
  ey = {{(vx - ux) / det, -vx / det, ux / det}};
  const FT area = CGAL::abs(det) / FT(2);
  const int d = degree - 2;
  scale = FT(degree * (degree - 1)) * FT(degree * (degree - 1)) * area /
          (FT((2 * d + 1) * (2 * d + 2)) / FT(2));
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_THIN_PLATE_TERMS_H

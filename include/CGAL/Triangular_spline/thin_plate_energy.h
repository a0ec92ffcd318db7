// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_THIN_PLATE_ENERGY_H
#define CGAL_TRIANGULAR_SPLINE_THIN_PLATE_ENERGY_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the multi-indices of degree `degree` in the order used by
  `thin_plate_energy_matrix()`: \f$i\f$ decreasing, then \f$j\f$ decreasing
  (\f$(m,0,0), (m-1,1,0), (m-1,0,1), (m-2,2,0), \dots\f$).
*/
inline std::vector<Multi_index> bernstein_indices(int degree) {
  std::vector<Multi_index> indices;
  for (int i = degree; i >= 0; --i)
    for (int j = degree - i; j >= 0; --j)
      indices.push_back({i, j, degree - i - j});
  return indices;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the Gram matrix of the thin-plate energy of a polynomial of degree `degree`
  in Bernstein–Bézier form over the triangle \f$(r,s,t)\f$: the symmetric matrix \f$G\f$,
  of size \f$\binom{m+2}{2}\f$ in the order of `bernstein_indices()`, with

  \f[ \int_{rst} f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2 \, dA \;=\; b^T G\, b \f]

  for the control values \f$b\f$ of \f$f\f$. Exact in `FT`: the second derivatives are
  differences of the control values with the barycentric coordinates of the unit vectors
  (Farin's directional derivative formula), and the products of Bernstein polynomials of
  degree \f$m-2\f$ integrate in closed form,
  \f$\int B_\alpha B_\beta = |T| \binom{m-2}{\alpha}\binom{m-2}{\beta} /
  \left(\binom{2m-4}{\alpha+\beta}\binom{2m-2}{2}\right)\f$. The energy is invariant under
  rotations and vanishes exactly on linear functions; it is the quadratic form of the
  `Fit::Minimal_energy` fit.
  \pre `degree >= 2` and \f$(r,s,t)\f$ not collinear
  \returns the matrix row by row (`G[a * n + b]`, n the number of indices)
*/
template <class Point_2>
auto thin_plate_energy_matrix(int degree, const Point_2& r, const Point_2& s, const Point_2& t) {
  using FT = std::decay_t<decltype(r.x())>;
  if (degree < 2)
    throw Invalid_input("thin_plate_energy_matrix: the degree must be at least 2");
  const FT ux = s.x() - r.x(), uy = s.y() - r.y(), vx = t.x() - r.x(), vy = t.y() - r.y();
  const FT det = ux * vy - uy * vx;
  if (CGAL::is_zero(det))
    throw Invalid_input("thin_plate_energy_matrix: degenerate triangle");
  // Barycentric coordinates of the unit vectors e_x and e_y.
  const std::array<FT, 3> ex{{(uy - vy) / det, vy / det, -uy / det}};
  const std::array<FT, 3> ey{{(vx - ux) / det, -vx / det, ux / det}};
  const FT area = CGAL::abs(det) / FT(2);
  const auto fine = bernstein_indices(degree);
  const auto coarse = bernstein_indices(degree - 2);
  const std::size_t n = fine.size(), c = coarse.size();
  auto index_of = [degree](const Multi_index& a) {
    // position in bernstein_indices(degree): rows i = degree .. a.i come first
    const int before = (degree - a.i) * (degree - a.i + 1) / 2;
    return static_cast<std::size_t>(before + (degree - a.i - a.j));
  };
  // L[p] (c x n): the Bernstein coefficients of degree m-2 of the p-th second derivative
  // (xx, xy, yy), without the factor m(m-1).
  auto second = [&](const std::array<FT, 3>& u, const std::array<FT, 3>& w) {
    std::vector<FT> l(c * n, FT(0));
    for (std::size_t g = 0; g < c; ++g)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Multi_index a = coarse[g];
          ++a[i];
          ++a[j];
          l[g * n + index_of(a)] += u[std::size_t(i)] * w[std::size_t(j)];
        }
    return l;
  };
  const std::array<std::vector<FT>, 3> L{{second(ex, ex), second(ex, ey), second(ey, ey)}};
  const std::array<FT, 3> factor{{FT(1), FT(2), FT(1)}};
  // Bernstein Gram matrix of degree m-2 (without |T|).
  auto factorial = [](int k) -> FT {
    FT f(1);
    for (int i = 2; i <= k; ++i)
      f = f * FT(i);
    return f;
  };
  auto multinomial = [&](int m, const Multi_index& a) -> FT {
    return factorial(m) / (factorial(a.i) * factorial(a.j) * factorial(a.k));
  };
  const int d = degree - 2;
  const FT scale = FT(degree * (degree - 1)) * FT(degree * (degree - 1)) * area /
                   (FT((2 * d + 1) * (2 * d + 2)) / FT(2));
  std::vector<FT> M(c * c);
  for (std::size_t a = 0; a < c; ++a)
    for (std::size_t b = 0; b < c; ++b) {
      const Multi_index sum{coarse[a].i + coarse[b].i, coarse[a].j + coarse[b].j,
                            coarse[a].k + coarse[b].k};
      M[a * c + b] =
          scale * multinomial(d, coarse[a]) * multinomial(d, coarse[b]) / multinomial(2 * d, sum);
    }
  std::vector<FT> G(n * n, FT(0));
  std::vector<FT> ML(c * n);
  for (int p = 0; p < 3; ++p) {
    const auto& l = L[std::size_t(p)];
    for (std::size_t a = 0; a < c; ++a)
      for (std::size_t j = 0; j < n; ++j) {
        FT sum(0);
        for (std::size_t b = 0; b < c; ++b)
          if (!CGAL::is_zero(l[b * n + j]))
            sum = sum + M[a * c + b] * l[b * n + j];
        ML[a * n + j] = sum;
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t a = 0; a < c; ++a) {
        if (CGAL::is_zero(l[a * n + i]))
          continue;
        const FT li = factor[std::size_t(p)] * l[a * n + i];
        for (std::size_t j = 0; j < n; ++j)
          G[i * n + j] = G[i * n + j] + li * ML[a * n + j];
      }
  }
  return G;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the thin-plate energy \f$\int f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2\f$ of a
  functional patch over its domain triangle, exactly in `FT`
  (`thin_plate_energy_matrix()`). Sum it over the patches of a spline for the spline's
  energy: the measure of fairness the `Fit::Minimal_energy` fit minimises.
*/
template <class GeomTraits>
typename GeomTraits::FT thin_plate_energy(const Bezier_triangle<GeomTraits>& patch) {
  using FT = typename GeomTraits::FT;
  const int m = patch.degree();
  if (m < 2)
    return FT(0);
  const auto G = thin_plate_energy_matrix(m, patch.vertex(0), patch.vertex(1), patch.vertex(2));
  const auto indices = bernstein_indices(m);
  const std::size_t n = indices.size();
  std::vector<FT> b(n);
  for (std::size_t i = 0; i < n; ++i)
    b[i] = patch.control_point(indices[i]);
  FT energy(0);
  for (std::size_t i = 0; i < n; ++i) {
    FT row(0);
    for (std::size_t j = 0; j < n; ++j)
      row = row + G[i * n + j] * b[j];
    energy = energy + b[i] * row;
  }
  return energy;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_THIN_PLATE_ENERGY_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_THIN_PLATE_ENERGY_H
#define CGAL_TRIANGULAR_SPLINE_XU_THIN_PLATE_ENERGY_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/thin_plate_terms.h>

#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the multi-indices of degree `degree` in the order used by
  `thin_plate_energy_matrix()`: \f$i\f$ decreasing, then \f$j\f$ decreasing
  (\f$(m,0,0), (m-1,1,0), (m-1,0,1), (m-2,2,0), \dots\f$).
  \param degree the degree
  \returns the multi-indices of degree `degree` in the order used by `thin_plate_energy_matrix()`
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
  \brief the thin-plate energy of a polynomial of degree \f$m\f$ in Bernstein–Bézier form
  over a triangle, in factored form: \f$E(b) = \sum_{p} w_p\, (L_p b)^T M (L_p b)\f$, with
  \f$L_p b\f$ the Bernstein coefficients of degree \f$m-2\f$ of \f$f_{xx}, f_{xy}, f_{yy}\f$
  (\f$p\f$ = 0, 1, 2; weights \f$w\f$ = 1, 2, 1) and \f$M\f$ the Gram matrix of the Bernstein
  polynomials of degree \f$m-2\f$ over the triangle. Differences first, then squares: in
  floating point this keeps the energy of thin triangles accurate, where forming
  \f$G = \sum_p w_p L_p^T M L_p\f$ first loses it to cancellation (its entries grow as
  the inverse fourth power of the triangle's height).
  \tparam FT a field number type
*/
template <class FT>
struct Thin_plate_energy_factors {
  /// the number of control values, \f$\binom{m+2}{2}\f$
  std::size_t fine = 0;
  /// the number of coefficients of a second derivative, \f$\binom{m}{2}\f$
  std::size_t coarse = 0;
  /// `second[p]`: \f$L_p\f$, `coarse` x `fine`, row by row (control values in the order of
  /// `bernstein_indices()`)
  std::array<std::vector<FT>, 3> second;
  /// \f$M\f$, `coarse` x `coarse`, row by row
  std::vector<FT> gram;
  /// the weights \f$w_p\f$
  static constexpr std::array<int, 3> weight{{1, 2, 1}};
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the factors of the thin-plate energy of degree `degree` over the triangle
  \f$(r,s,t)\f$, exact in `FT`: the second derivatives are differences of the control
  values with the barycentric coordinates of the unit vectors (Farin's directional
  derivative formula), and products of Bernstein polynomials of degree \f$m-2\f$ integrate
  in closed form, \f$\int B_\alpha B_\beta = |T| \binom{m-2}{\alpha}\binom{m-2}{\beta} /
  \left(\binom{2m-4}{\alpha+\beta}\binom{2m-2}{2}\right)\f$.
  \tparam Point_2 a CGAL 2D point type
  \throws Invalid_input if `degree < 2` or \f$(r,s,t)\f$ is collinear
  \param degree the degree
  \param r the first corner of the domain triangle
  \param s the second corner of the domain triangle
  \param t the third corner of the domain triangle
  \returns the factors of the thin-plate energy of degree `degree` over the triangle \f$(r,s,t)\f$,
  exact in `FT`
*/
template <class Point_2>
auto thin_plate_energy_factors(int degree, const Point_2& r, const Point_2& s, const Point_2& t) {
  using FT = std::decay_t<decltype(r.x())>;
  if (degree < 2)
    throw Invalid_input("thin_plate_energy: the degree must be at least 2");
  std::array<FT, 3> ex, ey;
  FT scale;
  internal::thin_plate_frame(degree, r, s, t, ex, ey, scale);
  const auto coarse = bernstein_indices(degree - 2);
  Thin_plate_energy_factors<FT> factors;
  factors.fine = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
  factors.coarse = coarse.size();
  const std::size_t n = factors.fine, c = factors.coarse;
  // The factor m(m-1) of the second derivatives goes into M.
  auto second = [&](const std::array<FT, 3>& u, const std::array<FT, 3>& w) {
    std::vector<FT> l(c * n, FT(0));
    for (std::size_t g = 0; g < c; ++g)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Multi_index a = coarse[g];
          ++a[i];
          ++a[j];
          l[g * n + internal::bernstein_position(degree, a)] +=
              u[std::size_t(i)] * w[std::size_t(j)];
        }
    return l;
  };
  factors.second = {{second(ex, ex), second(ex, ey), second(ey, ey)}};
  const std::vector<FT>& table = internal::bernstein_gram_table<FT>(degree - 2);
  factors.gram.resize(c * c);
  for (std::size_t k = 0; k < c * c; ++k)
    factors.gram[k] = scale * table[k];
  return factors;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the Gram matrix of the thin-plate energy of a polynomial of degree `degree`
  in Bernstein–Bézier form over the triangle \f$(r,s,t)\f$: the symmetric matrix \f$G\f$,
  of size \f$\binom{m+2}{2}\f$ in the order of `bernstein_indices()`, with

  \f[ \int_{rst} f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2 \, dA \;=\; b^T G\, b \f]

  for the control values \f$b\f$ of \f$f\f$, exact in `FT`
  (\f$G = \sum_p w_p L_p^T M L_p\f$, `thin_plate_energy_factors()`). The energy is invariant
  under rotations and vanishes exactly on linear functions; it is the quadratic form of the
  `Fit::MINIMAL_ENERGY` fit. In floating point prefer the factors: \f$b^T G b\f$ cancels
  catastrophically on thin triangles.
  \tparam Point_2 a CGAL 2D point type
  \throws Invalid_input if `degree < 2` or \f$(r,s,t)\f$ is collinear
  \returns the matrix row by row (`G[a * n + b]`, n the number of indices)
  \param degree the degree
  \param r the first corner of the domain triangle
  \param s the second corner of the domain triangle
  \param t the third corner of the domain triangle
*/
template <class Point_2>
auto thin_plate_energy_matrix(int degree, const Point_2& r, const Point_2& s, const Point_2& t) {
  const auto factors = thin_plate_energy_factors(degree, r, s, t);
  using FT = std::decay_t<decltype(factors.gram.front())>;
  const std::size_t n = factors.fine, c = factors.coarse;
  std::vector<FT> G(n * n, FT(0));
  std::vector<FT> ML(c * n);
  for (int p = 0; p < 3; ++p) {
    const auto& l = factors.second[std::size_t(p)];
    for (std::size_t a = 0; a < c; ++a)
      for (std::size_t j = 0; j < n; ++j) {
        FT sum(0);
        for (std::size_t b = 0; b < c; ++b)
          if (!CGAL::is_zero(l[b * n + j]))
            sum = sum + factors.gram[a * c + b] * l[b * n + j];
        ML[a * n + j] = sum;
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t a = 0; a < c; ++a) {
        if (CGAL::is_zero(l[a * n + i]))
          continue;
        const FT li = FT(factors.weight[std::size_t(p)]) * l[a * n + i];
        for (std::size_t j = 0; j < n; ++j)
          G[i * n + j] = G[i * n + j] + li * ML[a * n + j];
      }
  }
  return G;
}

namespace internal {

// Where the differences of thin_plate_energy_of_net() read, per degree m: for each index of
// degree m - 1 (fine) the three indices of degree m it adds e_i to, with their positions in
// bernstein_indices() order; for each index of degree m - 2 (coarse) the positions of its
// three neighbours of degree m - 1. The same positions in the same order as computing them
// per call, which took a third of the energy's time.
struct Thin_plate_difference_tables {
  std::vector<std::array<Multi_index, 3>> fine;
  std::vector<std::array<std::size_t, 3>> fine_from;
  std::vector<Multi_index> coarse;
  std::vector<std::array<std::size_t, 3>> coarse_from;
};
inline Thin_plate_difference_tables make_thin_plate_difference_tables(int m) {
  auto indices = [](int degree) {
    std::vector<Multi_index> out;
    for (int i = degree; i >= 0; --i) // the order of bernstein_indices()
      for (int j = degree - i; j >= 0; --j)
        out.push_back({i, j, degree - i - j});
    return out;
  };
  Thin_plate_difference_tables t;
  for (const Multi_index& to : indices(m - 1)) {
    std::array<Multi_index, 3> from;
    std::array<std::size_t, 3> position;
    for (int i = 0; i < 3; ++i) {
      from[std::size_t(i)] = to;
      ++from[std::size_t(i)][i];
      position[std::size_t(i)] = bernstein_position(m, from[std::size_t(i)]);
    }
    t.fine.push_back(from);
    t.fine_from.push_back(position);
  }
  t.coarse = indices(m - 2);
  for (const Multi_index& to : t.coarse) {
    std::array<std::size_t, 3> position;
    for (int i = 0; i < 3; ++i) {
      Multi_index a = to;
      ++a[i];
      position[std::size_t(i)] = bernstein_position(m - 1, a);
    }
    t.coarse_from.push_back(position);
  }
  return t;
}
// Degrees 2 to 8 once (thread-safe), higher ones per call.
inline const Thin_plate_difference_tables& thin_plate_difference_tables(int m) {
  constexpr int most = 8;
  static const std::array<Thin_plate_difference_tables, most - 1> cached = [] {
    std::array<Thin_plate_difference_tables, most - 1> t;
    for (int k = 2; k <= most; ++k)
      t[std::size_t(k - 2)] = make_thin_plate_difference_tables(k);
    return t;
  }();
  if (m <= most)
    return cached[std::size_t(m - 2)];
  thread_local Thin_plate_difference_tables other;
  other = make_thin_plate_difference_tables(m);
  return other;
}

// thin_plate_energy() of the degree-m net that at(position, index) reads, over the triangle
// (r, s, t): the one implementation, so that the patch and the net without a patch
// (face_energy_and_centroid_value()) give the same bits.
template <class FT, class Point_2, class At>
FT thin_plate_energy_of_net(int m, const Point_2& r, const Point_2& s, const Point_2& t,
                            const At& at) {
  if (m < 2)
    return FT(0);
  std::array<FT, 3> ex, ey;
  FT scale;
  internal::thin_plate_frame(m, r, s, t, ex, ey, scale);
  // Differences first (Farin's directional derivatives, one degree at a time), then squares:
  // D_x b and D_y b of degree m - 1, then D_xx, D_xy, D_yy of degree m - 2. Up to degree 6
  // the nets stay on the stack: tspline c1 takes the energy of every patch.
  using Net = boost::container::small_vector<FT, 28>;
  const Thin_plate_difference_tables& tables = thin_plate_difference_tables(m);
  const std::size_t fine = tables.fine.size(), coarse = tables.coarse.size();
  auto first = [&](const std::array<FT, 3>& e) {
    Net out(fine, FT(0));
    for (std::size_t g = 0; g < fine; ++g)
      for (std::size_t i = 0; i < 3; ++i)
        out[g] = out[g] + e[i] * at(tables.fine_from[g][i], tables.fine[g][i]);
    return out;
  };
  auto second = [&](const std::array<FT, 3>& e, const Net& v) {
    Net out(coarse, FT(0));
    for (std::size_t g = 0; g < coarse; ++g)
      for (std::size_t i = 0; i < 3; ++i)
        out[g] = out[g] + e[i] * v[tables.coarse_from[g][i]];
    return out;
  };
  const Net dx = first(ex);
  const Net dy = first(ey);
  const std::array<Net, 3> second_differences{{second(ex, dx), second(ey, dx), second(ey, dy)}};
  const std::vector<FT>& table = internal::bernstein_gram_table<FT>(m - 2);
  const std::size_t c = coarse;
  FT energy(0);
  for (int p = 0; p < 3; ++p) {
    const Net& d = second_differences[std::size_t(p)];
    FT quadratic(0);
    for (std::size_t a = 0; a < c; ++a) {
      FT row(0);
      for (std::size_t e = 0; e < c; ++e)
        row = row + table[a * c + e] * d[e];
      quadratic = quadratic + d[a] * row;
    }
    energy = energy + FT(Thin_plate_energy_factors<FT>::weight[std::size_t(p)]) * quadratic;
  }
  return scale * energy;
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the thin-plate energy \f$\int f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2\f$ of a
  functional patch over its domain triangle, exactly in `FT`, differences first
  (`thin_plate_energy_factors()`). Sum it over the patches of a spline for the spline's
  energy: the measure of fairness the `Fit::MINIMAL_ENERGY` fit minimises.
  \tparam GeomTraits a model of `Kernel`
  \param patch the Bézier patch
  \returns the thin-plate energy \f$\int f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2\f$ of a functional patch
  over its domain triangle, exactly in `FT`, differences first (`thin_plate_energy_factors()`)
*/
template <class GeomTraits>
typename GeomTraits::FT thin_plate_energy(const Bezier_triangle<GeomTraits>& patch) {
  using FT = typename GeomTraits::FT;
  return internal::thin_plate_energy_of_net<FT>(
      patch.degree(), patch.vertex(0), patch.vertex(1), patch.vertex(2),
      [&](std::size_t, const Multi_index& a) -> const FT& { return patch.control_point(a); });
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_THIN_PLATE_ENERGY_H

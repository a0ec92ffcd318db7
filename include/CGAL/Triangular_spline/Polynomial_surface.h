// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_POLYNOMIAL_SURFACE_H
#define CGAL_TRIANGULAR_SPLINE_POLYNOMIAL_SURFACE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief a bivariate polynomial \f$F(x,y) = \sum_{h+k\le n} c_{h,k}\, x^h y^k\f$ in the
  monomial basis, with its symmetric polar form of any degree \f$m \ge n\f$ (Xu §2.7.2).

  This is the bridge between closed-form surfaces (Enneper's surface, test polynomials,
  polynomial-precision data) and Bézier nets: `to_bezier()` gives the control net over any
  domain triangle exactly. It is also the package's one monomial-basis polynomial class
  elsewhere: the heights of Fang's vertex surfaces are `Bivariate_polynomial`, this class
  with `double` coefficients, evaluated on jets by `operator()`.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric), see `Value_traits`
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
class Polynomial_surface {
public:
  /// the kernel
  using Geom_traits = GeomTraits;
  /// the number type
  using FT = typename Geom_traits::FT;
  /// the point type of the plane
  using Point_2 = typename Geom_traits::Point_2;

  /// creates the zero polynomial of degree at most `degree`.
  /// \param degree the degree
  explicit Polynomial_surface(int degree) : m_degree(degree) {
    if (degree < 0)
      throw Invalid_input("polynomial: negative degree " + std::to_string(degree));
    m_coefficients.assign(number_of_control_points(degree), Value_traits<Value>::zero());
  }

  /// returns the degree bound `n`.
  /// \returns the degree bound `n`
  int degree() const { return m_degree; }

  /// returns \f$c_{h,k}\f$, the coefficient of \f$x^h y^k\f$.
  /// \param h the exponent \f$h\f$ of \f$x\f$
  /// \param k the exponent \f$k\f$ of \f$y\f$
  /// \returns \f$c_{h,k}\f$, the coefficient of \f$x^h y^k\f$
  const Value& coefficient(int h, int k) const { return m_coefficients[position(h, k)]; }

  /// sets \f$c_{h,k}\f$.
  /// \param h the exponent \f$h\f$ of \f$x\f$
  /// \param k the exponent \f$k\f$ of \f$y\f$
  /// \param c the new coefficient
  void set_coefficient(int h, int k, const Value& c) { m_coefficients[position(h, k)] = c; }

  /// returns \f$F(a)\f$.
  /// \param a the point of the plane
  /// \returns \f$F(a)\f$
  Value evaluate(const Point_2& a) const {
    Value sum = Value_traits<Value>::zero();
    for (int h = 0; h <= m_degree; ++h)
      for (int k = 0; h + k <= m_degree; ++k) {
        FT monomial(1);
        for (int e = 0; e < h; ++e)
          monomial = monomial * a.x();
        for (int e = 0; e < k; ++e)
          monomial = monomial * a.y();
        sum = sum + monomial * coefficient(h, k);
      }
    return sum;
  }

  /*!
    returns \f$F(x, y)\f$ of a functional polynomial by the nested Horner scheme, on numbers
    or on `Taylor_jet`s (the jet of \f$F\f$ then comes with it): this is how Fang's vertex
    surfaces are evaluated with their derivatives. The rounding differs from `evaluate()`,
    which sums the monomials; both are exact with an exact `FT`.
    \tparam T `FT`, or a type whose values multiply and add with `FT` such as
    `Taylor_jet<FT>`
    \param x the \f$x\f$ coordinate
    \param y the \f$y\f$ coordinate
    \returns \f$F(x, y)\f$
  */
  template <class T>
  T operator()(const T& x, const T& y) const {
    static_assert(std::is_same<Value, FT>::value, "Horner evaluation of a functional polynomial");
    // x * 0 carries the truncation order of a jet x
    T result = x * FT(0);
    for (int h = m_degree; h >= 0; --h) {
      T inner = x * FT(0);
      for (int k = m_degree - h; k >= 0; --k)
        inner = inner * y + m_coefficients[linear_index(h, k, m_degree)];
      result = result * x + inner;
    }
    return result;
  }

  /// returns the partial derivative \f$\partial^{p+q}F/\partial x^p\partial y^q\f$ as a
  /// polynomial.
  /// \param p the order of differentiation in \f$x\f$
  /// \param q the order of differentiation in \f$y\f$
  /// \returns the derivative, as a polynomial
  Polynomial_surface derivative(int p, int q) const {
    if (p < 0 || q < 0)
      throw Invalid_input("polynomial: negative derivative order");
    Polynomial_surface result(m_degree);
    for (int h = p; h <= m_degree; ++h)
      for (int k = q; h + k <= m_degree; ++k) {
        FT factor(1);
        for (int e = 0; e < p; ++e)
          factor = factor * FT(h - e);
        for (int e = 0; e < q; ++e)
          factor = factor * FT(k - e);
        result.set_coefficient(h - p, k - q, factor * coefficient(h, k));
      }
    return result;
  }

  /*!
    returns the polar form of degree `arguments.size()` (at least `degree()`) at the given
    points: for the monomial \f$x^h y^k\f$ it is the sum over disjoint index sets
    \f$I,J\f$, \f$|I|=h, |J|=k\f$, of \f$\prod_I u_i \prod_J v_j\f$ divided by the number
    of terms (Xu §2.7.2). The sums are the coefficients of
    \f$\prod_l (1 + u_l X + v_l Y)\f$, built in \f$O(m n^2)\f$.
    \param arguments the blossom arguments, one per degree
    \returns the value of the polar form
  */
  Value blossom(const std::vector<Point_2>& arguments) const {
    const int m = static_cast<int>(arguments.size());
    if (m < m_degree)
      throw Invalid_input("polynomial: a degree " + std::to_string(m_degree) +
                          " polynomial has no polar form with " + std::to_string(m) + " arguments");
    // e[h][k]: coefficient of X^h Y^k, truncated at total degree n.
    std::vector<std::vector<FT>> e(static_cast<std::size_t>(m_degree + 1),
                                   std::vector<FT>(static_cast<std::size_t>(m_degree + 1), FT(0)));
    e[0][0] = FT(1);
    for (const Point_2& a : arguments)
      for (int total = m_degree; total >= 1; --total)
        for (int h = 0; h <= total; ++h) {
          const int k = total - h;
          FT add(0);
          if (h > 0)
            add = add + a.x() * e[h - 1][k];
          if (k > 0)
            add = add + a.y() * e[h][k - 1];
          e[h][k] = e[h][k] + add;
        }
    Value sum = Value_traits<Value>::zero();
    for (int h = 0; h <= m_degree; ++h)
      for (int k = 0; h + k <= m_degree; ++k) {
        // multinomial(m; h, k, m-h-k) = C(m,h) C(m-h,k)
        const FT count = binomial(m, h) * binomial(m - h, k);
        sum = sum + (e[h][k] / count) * coefficient(h, k);
      }
    return sum;
  }

  /// returns the sum of two polynomials (degree bound: the larger one).
  friend Polynomial_surface operator+(const Polynomial_surface& a, const Polynomial_surface& b) {
    Polynomial_surface result((std::max)(a.degree(), b.degree()));
    for (const Polynomial_surface* term : {&a, &b})
      for (int h = 0; h <= term->degree(); ++h)
        for (int k = 0; h + k <= term->degree(); ++k)
          result.set_coefficient(h, k, result.coefficient(h, k) + term->coefficient(h, k));
    return result;
  }

  /// returns the product of the scalar polynomial `a` and this polynomial (degree bound:
  /// the sum of the bounds).
  /// \param a the scalar polynomial
  /// \returns the product
  Polynomial_surface multiplied_by(const Polynomial_surface<Geom_traits, FT>& a) const {
    Polynomial_surface result(degree() + a.degree());
    for (int h1 = 0; h1 <= a.degree(); ++h1)
      for (int k1 = 0; h1 + k1 <= a.degree(); ++k1)
        for (int h2 = 0; h2 <= degree(); ++h2)
          for (int k2 = 0; h2 + k2 <= degree(); ++k2)
            result.set_coefficient(h1 + h2, k1 + k2,
                                   result.coefficient(h1 + h2, k1 + k2) +
                                       a.coefficient(h1, k1) * coefficient(h2, k2));
    return result;
  }

  /// returns the Bézier patch of degree `m` (at least `degree()`) over `(r, s, t)` that
  /// equals this polynomial.
  /// \param m the degree
  /// \param r the first corner of the domain triangle
  /// \param s the second corner of the domain triangle
  /// \param t the third corner of the domain triangle
  /// \returns the Bézier patch
  Bezier_triangle<Geom_traits, Value> to_bezier(int m, const Point_2& r, const Point_2& s,
                                                const Point_2& t) const {
    return Bezier_triangle<Geom_traits, Value>::from_blossom(
        m, r, s, t, [this](const std::vector<Point_2>& args) { return blossom(args); });
  }

private:
  static FT binomial(int n, int k) {
    FT result(1);
    for (int i = 1; i <= k; ++i)
      result = result * FT(n - k + i) / FT(i);
    return result;
  }

  std::size_t position(int h, int k) const {
    if (h < 0 || k < 0 || h + k > m_degree)
      throw Invalid_input("polynomial: no monomial x^" + std::to_string(h) + " y^" +
                          std::to_string(k) + " in degree " + std::to_string(m_degree));
    return linear_index(h, k, m_degree);
  }

  int m_degree;
  std::vector<Value> m_coefficients;
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns Enneper's surface \f$F(u,v) = (u - u^3/3 + uv^2,\; v - v^3/3 + u^2v,\;
  u^2 - v^2)\f$ (Xu §2.7.1), a cubic minimal surface; over the frame \f$r=(1,0)\f$,
  \f$s=(0,1)\f$, \f$t=(0,0)\f$ its control net is Xu's Table 2.2.
  \tparam GeomTraits a model of `Kernel`
  \returns Enneper's surface \f$F(u,v) = (u - u^3/3 + uv^2,\; v - v^3/3 + u^2v,\; u^2 - v^2)\f$ (Xu
  §2.7.1), a cubic minimal surface
*/
template <class GeomTraits>
Polynomial_surface<GeomTraits, typename GeomTraits::Vector_3> enneper_surface() {
  using FT = typename GeomTraits::FT;
  using Vector_3 = typename GeomTraits::Vector_3;
  Polynomial_surface<GeomTraits, Vector_3> surface(3);
  const FT third = FT(1) / FT(3);
  surface.set_coefficient(1, 0, Vector_3(1, 0, 0));
  surface.set_coefficient(3, 0, Vector_3(-third, 0, 0));
  surface.set_coefficient(1, 2, Vector_3(1, 0, 0));
  surface.set_coefficient(0, 1, Vector_3(0, 1, 0));
  surface.set_coefficient(0, 3, Vector_3(0, -third, 0));
  surface.set_coefficient(2, 1, Vector_3(0, 1, 0));
  surface.set_coefficient(2, 0, Vector_3(0, 0, 1));
  surface.set_coefficient(0, 2, Vector_3(0, 0, -1));
  return surface;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_POLYNOMIAL_SURFACE_H

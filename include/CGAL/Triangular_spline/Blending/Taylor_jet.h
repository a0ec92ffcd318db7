// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_TAYLOR_JET_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_TAYLOR_JET_H

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/taylor_jet.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief a truncated bivariate Taylor polynomial (a "jet"): the value and all partial
  derivatives up to order `order()` of a function of two variables at one point.

  A jet stores the Taylor coefficients \f$c_{a,b} = \frac{1}{a!\,b!}
  \partial_x^a\partial_y^b F\f$ for \f$a + b \le K\f$, \f$K\f$ = `order()`. Sums, products,
  quotients and (for number types with a square root) square roots of jets are the jets of
  the sums, products, quotients and square roots of the functions, so running any formula
  on jets instead of numbers differentiates it exactly (forward-mode automatic
  differentiation with truncated power series). With an exact `FT` every derivative is
  exact: this is how the blending code checks the inheritance of derivatives of any order
  (Fang, Props. 3.9 and 3.16) without finite differences.

  A jet built from a number alone (`Taylor_jet(c)`) is a constant, known to every order; an
  operation on jets of orders \f$K_1, K_2\f$ is known to order \f$\min(K_1, K_2)\f$.

  \tparam FT a field number type (`double`, `CGAL::Exact_rational`, ...)
  \tparam MaxOrder the largest order a jet can hold (storage is fixed, no allocation)
*/
template <class FT, int MaxOrder = 8>
class Taylor_jet {
  static_assert(MaxOrder >= 0, "the order of a jet is non-negative");

public:
  /// the number type of the coefficients
  using Number_type = FT;
  /// the largest order a jet of this type can hold
  static constexpr int max_order = MaxOrder;
  /// the number of stored coefficients, \f$(K+1)(K+2)/2\f$ for \f$K\f$ = `MaxOrder`
  static constexpr int capacity = (MaxOrder + 1) * (MaxOrder + 2) / 2;

  /// creates the constant 0, known to every order.
  Taylor_jet() : m_order(MaxOrder) { m_c.fill(FT(0)); }

  /// creates the constant `c`, known to every order.
  /// \param c the constant value
  Taylor_jet(const FT& c) : m_order(MaxOrder) { // NOLINT: implicit on purpose, like a number
    m_c.fill(FT(0));
    m_c[0] = c;
  }

  /// creates the constant `c` truncated at order `order`.
  /// \param c the constant value
  /// \param order the order of the jet
  Taylor_jet(const FT& c, int order) : m_order(checked(order)) {
    m_c.fill(FT(0));
    m_c[0] = c;
  }

  /// returns the jet of the coordinate function \f$x\f$ (`which == 0`) or \f$y\f$
  /// (`which == 1`) at a point whose coordinate is `value`, to order `order`.
  /// \param value the coordinate of the expansion point
  /// \param which 0 for \f$x\f$, 1 for \f$y\f$
  /// \param order the order
  /// \returns the jet of the coordinate function
  static Taylor_jet variable(const FT& value, int which, int order) {
    Taylor_jet j(value, order);
    if (order >= 1)
      j.m_c[static_cast<std::size_t>(which == 0 ? index(1, 0) : index(0, 1))] = FT(1);
    return j;
  }

  /// returns the jet of the affine function \f$c + a\,x + b\,y\f$ (variables relative to the
  /// expansion point) to order `order`.
  /// \param c the constant term
  /// \param a the coefficient of \f$x\f$
  /// \param b the coefficient of \f$y\f$
  /// \param order the order
  /// \returns the jet of the affine function
  static Taylor_jet affine(const FT& c, const FT& a, const FT& b, int order) {
    Taylor_jet j(c, order);
    if (order >= 1) {
      j.m_c[static_cast<std::size_t>(index(1, 0))] = a;
      j.m_c[static_cast<std::size_t>(index(0, 1))] = b;
    }
    return j;
  }

  /// returns the order \f$K\f$ to which this jet is known.
  /// \returns the order \f$K\f$ to which this jet is known
  int order() const { return m_order; }

  /// returns the value \f$c_{0,0}\f$.
  /// \returns the value \f$c_{0,0}\f$
  const FT& value() const { return m_c[0]; }

  /// returns the Taylor coefficient \f$c_{a,b}\f$ (zero above the order).
  /// \param a the exponent of \f$x\f$
  /// \param b the exponent of \f$y\f$
  /// \returns the Taylor coefficient \f$c_{a,b}\f$ (zero above the order)
  FT coefficient(int a, int b) const {
    if (a < 0 || b < 0 || a + b > m_order)
      return FT(0);
    return m_c[static_cast<std::size_t>(index(a, b))];
  }

  /// sets the Taylor coefficient \f$c_{a,b}\f$, \f$a + b \le\f$ `order()`.
  /// \param a the exponent of \f$x\f$
  /// \param b the exponent of \f$y\f$
  /// \param c the new coefficient
  void set_coefficient(int a, int b, const FT& c) {
    if (a < 0 || b < 0 || a + b > m_order)
      throw Invalid_input("Taylor_jet: no coefficient (" + std::to_string(a) + ", " +
                          std::to_string(b) + ") in a jet of order " + std::to_string(m_order));
    m_c[static_cast<std::size_t>(index(a, b))] = c;
  }

  /// returns the partial derivative \f$\partial_x^a\partial_y^b F = a!\,b!\,c_{a,b}\f$.
  /// \param a the exponent of \f$x\f$
  /// \param b the exponent of \f$y\f$
  /// \returns the partial derivative \f$\partial_x^a\partial_y^b F = a!\,b!\,c_{a,b}\f$
  FT derivative(int a, int b) const {
    FT factor(1);
    for (int i = 2; i <= a; ++i)
      factor = factor * FT(i);
    for (int i = 2; i <= b; ++i)
      factor = factor * FT(i);
    FT result = factor * coefficient(a, b);
    return result;
  }

  /// returns this jet truncated to order `order` (at most the current order).
  /// \param order the order of the result
  /// \returns this jet truncated to order `order` (at most the current order)
  Taylor_jet truncated(int order) const {
    Taylor_jet r(*this);
    r.m_order = (std::min)(m_order, checked(order));
    for (int i = size(r.m_order); i < capacity; ++i)
      r.m_c[static_cast<std::size_t>(i)] = FT(0);
    return r;
  }

  /// returns the linear index of \f$c_{a,b}\f$: by total degree, then by \f$b\f$.
  /// \param a the exponent of \f$x\f$
  /// \param b the exponent of \f$y\f$
  /// \returns the linear index of \f$c_{a,b}\f$
  static constexpr int index(int a, int b) { return (a + b) * (a + b + 1) / 2 + b; }
  /// returns the number of coefficients of a jet of order `order`.
  /// \param order the order of the jet
  /// \returns the number of coefficients of a jet of order `order`
  static constexpr int size(int order) { return (order + 1) * (order + 2) / 2; }

  /// \name Arithmetic
  /// @{

  /// returns the negated jet.
  /// \returns the negated jet
  Taylor_jet operator-() const {
    Taylor_jet r(*this);
    for (int i = 0; i < size(m_order); ++i)
      r.m_c[static_cast<std::size_t>(i)] = -m_c[static_cast<std::size_t>(i)];
    return r;
  }
  /// adds `b`; the order becomes the smaller of both orders.
  /// \param b the other jet
  /// \returns `*this`
  Taylor_jet& operator+=(const Taylor_jet& b) {
    m_order = (std::min)(m_order, b.m_order);
    for (int i = 0; i < size(m_order); ++i)
      m_c[static_cast<std::size_t>(i)] =
          m_c[static_cast<std::size_t>(i)] + b.m_c[static_cast<std::size_t>(i)];
    clear_above();
    return *this;
  }
  /// subtracts `b`; the order becomes the smaller of both orders.
  /// \param b the other jet
  /// \returns `*this`
  Taylor_jet& operator-=(const Taylor_jet& b) {
    m_order = (std::min)(m_order, b.m_order);
    for (int i = 0; i < size(m_order); ++i)
      m_c[static_cast<std::size_t>(i)] =
          m_c[static_cast<std::size_t>(i)] - b.m_c[static_cast<std::size_t>(i)];
    clear_above();
    return *this;
  }
  /// multiplies every coefficient by `s`.
  /// \param s the scalar factor
  /// \returns `*this`
  Taylor_jet& operator*=(const FT& s) {
    for (int i = 0; i < size(m_order); ++i)
      m_c[static_cast<std::size_t>(i)] = m_c[static_cast<std::size_t>(i)] * s;
    return *this;
  }
  /// divides every coefficient by `s`.
  /// \throws Invalid_input if `s` is zero
  /// \param s the scalar factor
  /// \returns `*this`
  Taylor_jet& operator/=(const FT& s) {
    if (s == FT(0))
      throw Invalid_input("Taylor_jet: division by zero");
    for (int i = 0; i < size(m_order); ++i)
      m_c[static_cast<std::size_t>(i)] = m_c[static_cast<std::size_t>(i)] / s;
    return *this;
  }
  /// multiplies by `b` (truncated Cauchy product).
  /// \param b the other jet
  /// \returns `*this`
  Taylor_jet& operator*=(const Taylor_jet& b) {
    *this = *this * b;
    return *this;
  }
  /// divides by `b`.
  /// \throws Invalid_input if the value of `b` is zero
  /// \param b the other jet
  /// \returns `*this`
  Taylor_jet& operator/=(const Taylor_jet& b) {
    *this = *this / b;
    return *this;
  }

  /// returns the sum of two jets.
  friend Taylor_jet operator+(Taylor_jet a, const Taylor_jet& b) { return a += b; }
  /// returns the difference of two jets.
  friend Taylor_jet operator-(Taylor_jet a, const Taylor_jet& b) { return a -= b; }
  /// returns `a` with `s` added to its value.
  friend Taylor_jet operator+(Taylor_jet a, const FT& s) {
    a.m_c[0] = a.m_c[0] + s;
    return a;
  }
  /// returns `a` with `s` added to its value.
  friend Taylor_jet operator+(const FT& s, Taylor_jet a) { return a + s; }
  /// returns `a` with `s` subtracted from its value.
  friend Taylor_jet operator-(Taylor_jet a, const FT& s) {
    a.m_c[0] = a.m_c[0] - s;
    return a;
  }
  /// returns the jet of `s` minus `a`.
  friend Taylor_jet operator-(const FT& s, const Taylor_jet& a) { return (-a) + s; }
  /// returns `a` with every coefficient multiplied by `s`.
  friend Taylor_jet operator*(Taylor_jet a, const FT& s) { return a *= s; }
  /// returns `a` with every coefficient multiplied by `s`.
  friend Taylor_jet operator*(const FT& s, Taylor_jet a) { return a *= s; }
  /// returns `a` with every coefficient divided by `s`; throws `Invalid_input` if `s` is zero.
  friend Taylor_jet operator/(Taylor_jet a, const FT& s) { return a /= s; }
  /// returns the jet of `s` divided by `a`; throws `Invalid_input` if the value of `a` is zero.
  friend Taylor_jet operator/(const FT& s, const Taylor_jet& a) { return Taylor_jet(s) / a; }

  /// the truncated Cauchy product.
  friend Taylor_jet operator*(const Taylor_jet& a, const Taylor_jet& b) {
    const int K = (std::min)(a.m_order, b.m_order);
    Taylor_jet r(FT(0), K);
    for (int k1 = 0; k1 <= K; ++k1)
      for (int b1 = 0; b1 <= k1; ++b1) {
        const FT& x = a.m_c[static_cast<std::size_t>(index(k1 - b1, b1))];
        if (x == FT(0))
          continue;
        for (int k2 = 0; k1 + k2 <= K; ++k2)
          for (int b2 = 0; b2 <= k2; ++b2) {
            FT& target = r.m_c[static_cast<std::size_t>(index(k1 - b1 + k2 - b2, b1 + b2))];
            target = target + x * b.m_c[static_cast<std::size_t>(index(k2 - b2, b2))];
          }
      }
    return r;
  }

  /// the quotient; throws `Invalid_input` if the value of `b` is zero.
  friend Taylor_jet operator/(const Taylor_jet& a, const Taylor_jet& b) {
    if (b.m_c[0] == FT(0))
      throw Invalid_input("Taylor_jet: division by a jet whose value is zero");
    const int K = (std::min)(a.m_order, b.m_order);
    Taylor_jet r(FT(0), K);
    // b * r = a, solved degree by degree.
    for (int k = 0; k <= K; ++k)
      for (int bb = 0; bb <= k; ++bb) {
        const int aa = k - bb;
        FT s = a.m_c[static_cast<std::size_t>(index(aa, bb))];
        for (int k1 = 1; k1 <= k; ++k1)
          for (int b1 = (std::max)(0, bb - (k - k1)); b1 <= (std::min)(k1, bb); ++b1) {
            const int a1 = k1 - b1;
            if (a1 > aa)
              continue;
            s = s - b.m_c[static_cast<std::size_t>(index(a1, b1))] *
                        r.m_c[static_cast<std::size_t>(index(aa - a1, bb - b1))];
          }
        r.m_c[static_cast<std::size_t>(index(aa, bb))] = s / b.m_c[0];
      }
    return r;
  }

  /// the jet of \f$\sqrt{F}\f$ (found by argument-dependent lookup); needs \f$F > 0\f$ at
  /// the point and a number type with a square root (`double`).
  /// \throws Invalid_input if the value of `a` is not positive
  friend Taylor_jet sqrt(const Taylor_jet& a) {
    using std::sqrt;
    if (!(a.value() > FT(0)))
      throw Invalid_input("Taylor_jet: square root of a jet whose value is not positive");
    const int K = a.m_order;
    Taylor_jet r(FT(sqrt(a.value())), K);
    const FT twice = FT(2) * r.m_c[0];
    for (int k = 1; k <= K; ++k)
      for (int bb = 0; bb <= k; ++bb) {
        const int aa = k - bb;
        FT s = a.m_c[static_cast<std::size_t>(index(aa, bb))];
        // r * r = a: the splits with neither factor the constant term
        for (int k1 = 1; k1 < k; ++k1)
          for (int b1 = (std::max)(0, bb - (k - k1)); b1 <= (std::min)(k1, bb); ++b1) {
            const int a1 = k1 - b1;
            if (a1 > aa)
              continue;
            s = s - r.m_c[static_cast<std::size_t>(index(a1, b1))] *
                        r.m_c[static_cast<std::size_t>(index(aa - a1, bb - b1))];
          }
        r.m_c[static_cast<std::size_t>(index(aa, bb))] = s / twice;
      }
    return r;
  }
  /// @}

private:
  static int checked(int order) {
    if (order < 0 || order > MaxOrder)
      throw Invalid_input("Taylor_jet: order " + std::to_string(order) + " outside [0, " +
                          std::to_string(MaxOrder) + "]");
    return order;
  }
  void clear_above() {
    for (int i = size(m_order); i < capacity; ++i)
      m_c[static_cast<std::size_t>(i)] = FT(0);
  }

  int m_order;
  std::array<FT, static_cast<std::size_t>(capacity)> m_c;
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns \f$F^e\f$ for an integer \f$e \ge 1\f$ (numbers or jets).
  \tparam T a number type or a `Taylor_jet`
  \throws Invalid_input if \f$e < 1\f$
  \param base the number or jet \f$F\f$
  \param exponent the exponent \f$e\f$
  \returns \f$F^e\f$ for an integer \f$e \ge 1\f$ (numbers or jets)
*/
template <class T>
T integer_power(const T& base, int exponent) {
  if (exponent < 1)
    throw Invalid_input("integer_power: exponent " + std::to_string(exponent) + " < 1");
  T result = base;
  for (int e = 1; e < exponent; ++e)
    result = result * base;
  return result;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief inverts a map of the plane given by its jets: returns the jets \f$(Q_u, Q_v)\f$ in
  new variables \f$(s, t)\f$, without constant terms, such that
  \f$R(p + Q(s,t)) = R(p) + (s, t)\f$ up to the order of the jets.

  `rx`, `ry` are the jets of the two components of \f$R\f$ at \f$p\f$ (in the variables of
  \f$p\f$). Used to express a surface in the coordinate system of an adjacent element
  (Fang §5.3: \f$S^F\f$ reparameterized by \f$r^{E,F} = (r^{F,E})^{-1}\f$).
  \tparam FT the number type of the jets
  \tparam K the maximal order of the jets (`MaxOrder` of `Taylor_jet`)
  \throws Invalid_input if the Jacobian of \f$R\f$ at \f$p\f$ is singular
  \param rx the jet of the first component of \f$R\f$
  \param ry the jet of the second component of \f$R\f$
  \returns the jets \f$(Q_u, Q_v)\f$
*/
template <class FT, int K>
std::array<Taylor_jet<FT, K>, 2> inverse_map_jet(const Taylor_jet<FT, K>& rx,
                                                 const Taylor_jet<FT, K>& ry) {
  using J = Taylor_jet<FT, K>;
  const int order = (std::min)(rx.order(), ry.order());
  const FT a = rx.coefficient(1, 0), b = rx.coefficient(0, 1), c = ry.coefficient(1, 0),
           d = ry.coefficient(0, 1);
  const FT det = a * d - b * c;
  if (det == FT(0))
    throw Invalid_input("inverse_map_jet: the map has a singular Jacobian");
  // J^{-1} = [d -b; -c a] / det
  const FT i00 = d / det, i01 = -b / det, i10 = -c / det, i11 = a / det;
  const J s = J::variable(FT(0), 0, order), t = J::variable(FT(0), 1, order);
  // the nonlinear parts of R (no constant, no linear term)
  J nx = rx.truncated(order), ny = ry.truncated(order);
  nx.set_coefficient(0, 0, FT(0));
  ny.set_coefficient(0, 0, FT(0));
  if (order >= 1) {
    nx.set_coefficient(1, 0, FT(0));
    nx.set_coefficient(0, 1, FT(0));
    ny.set_coefficient(1, 0, FT(0));
    ny.set_coefficient(0, 1, FT(0));
  }
  // Q = J^{-1} ((s,t) - N(Q)), iterated: each pass fixes one more order.
  J qu = s * i00 + t * i01, qv = s * i10 + t * i11;
  for (int pass = 1; pass < order; ++pass) {
    const J ex = s - internal::compose(nx, qu, qv), ey = t - internal::compose(ny, qu, qv);
    qu = ex * i00 + ey * i01;
    qv = ex * i10 + ey * i11;
  }
  return {{qu, qv}};
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_TAYLOR_JET_H

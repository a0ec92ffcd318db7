// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_FUNCTIONS_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_FUNCTIONS_H

#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/blending_arithmetic.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the inherited terms \f$q^p\f$ (Fang, Def. 3.2): the number of indicators
  whose value is zero.
  \tparam T a number type or a `Taylor_jet` (its value is tested)
  \param indicators the values of the indicators
  \returns the inherited terms \f$q^p\f$ (Fang, Def. 3.2)
*/
template <class T>
int inherited_terms(const std::vector<T>& indicators) {
  return static_cast<int>(internal::zero_indices(indicators).size());
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the intermediate functions \f$g_i^{n,d}(v)\f$ of Fang's Def. 3.3, by the
  formula itself:
  \f[ g_i^{n,d}(v) = \Big(\prod_{j \ne i} w_j\Big)\Big(\sum_{j \ne i}
  \frac{1}{w_i + w_j}\Big) \Big/ \sum_{\{j,k\},\, j \ne k}\; \prod_{l \ne j,k} w_l,
  \qquad w_i = v_i^{d+1}. \f]
  The denominator sums over unordered pairs \f$\{j, k\}\f$: with ordered pairs the
  \f$g_i\f$ would sum to \f$1/2\f$, not 1 (the proof of Prop. 3.2 and Def. 4.3 use
  unordered pairs).

  The formula has no limit handling: it is defined where no \f$w_i + w_j\f$ and not the
  denominator vanish, i.e. where at most one \f$v_i\f$ is zero (when the \f$v_i\f$ are
  non-negative). Use `blending_functions()` for the blending functions with their limits.

  \tparam T a field number type (`double`, `CGAL::Exact_rational`) or a `Taylor_jet`; with
  an exact type the result is exact
  \param v the values \f$v_0, \dots, v_{n-1}\f$, \f$n \ge 2\f$
  \param order the blending order \f$d \ge 0\f$
  \throws Invalid_input if \f$d < 0\f$, \f$n < 2\f$, or a denominator vanishes
  \returns the intermediate functions \f$g_i^{n,d}(v)\f$ of Fang's Def. 3.3, by the formula itself
*/
template <class T>
std::vector<T> intermediate_functions(const std::vector<T>& v, int order) {
  using B = internal::Base_number<T>;
  internal::check_order(order, "intermediate_functions");
  const std::size_t n = v.size();
  if (n < 2)
    throw Invalid_input("intermediate_functions: need at least two values, got " +
                        std::to_string(n));
  const std::vector<T> w = internal::powers(v, order);
  const T one = internal::one_like(w[0]);
  T D = internal::zero_like(w[0]);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j + 1; k < n; ++k)
      D = D + internal::product_without(w, j, k, one);
  if (internal::value_of(D) == B(0))
    throw Invalid_input("intermediate_functions: the denominator of g^{n,d} vanishes");
  std::vector<T> g;
  g.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    T sum = internal::zero_like(w[0]);
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) {
        const T s = w[i] + w[j];
        if (internal::value_of(s) == B(0))
          throw Invalid_input("intermediate_functions: w_" + std::to_string(i) + " + w_" +
                              std::to_string(j) + " = 0; g^{n,d} is undefined there");
        sum = sum + one / s;
      }
    const T gi = internal::product_without(w, i, i, one) * sum / D;
    g.push_back(gi);
  }
  return g;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns Fang's blending functions \f$f_i^{n,d,p}\f$ (Def. 3.4) at a point, given
  the values \f$p_i\f$ of the inheritance indicators there, with the limits where
  indicators vanish.

  - No indicator is zero: \f$f_i = g_i^{n,d}(p)\f$, evaluated in the stable form
    \f$f_i = \sum_{j \ne i} \frac{w_j}{w_i + w_j} \prod_{k \ne i,j} w_k \big/ D\f$.
  - One indicator \f$p_i\f$ is zero: the same formula is defined (Prop. 3.4) and gives
    \f$f_i = 1\f$, \f$f_k = 0\f$ exactly; with jets, \f$f_i - 1\f$ and the \f$f_k\f$
    vanish to order \f$d\f$ (Props. 3.5–3.7).
  - Two indicators \f$p_i = p_j = 0\f$: the \f$f_k\f$, \f$k \ne i, j\f$, are defined by
    the formula and vanish to order \f$d\f$ (Prop. 3.12); \f$f_i\f$ and \f$f_j\f$ alone
    have no limit (it depends on the direction: \f$f_i \to w_j/(w_i + w_j)\f$), only
    their sum does, \f$1 - \sum_{k \ne i,j} f_k\f$ (Props. 3.11, 3.13, 3.14). The
    function returns half of it for each: the limit along \f$w_i = w_j\f$. Any blend
    \f$\sum f_k S_k\f$ is then exact wherever it is defined, i.e. where \f$S_i\f$ and
    \f$S_j\f$ agree (to order \f$d\f$ for derivatives, Props. 3.15, 3.16).
  - More than two indicators zero: undefined, `Invalid_input` is thrown.

  The functions sum to one exactly with an exact number type (Prop. 3.3). In floating
  point the indicators are first divided by the largest magnitude (the functions are
  homogeneous of degree 0), so tiny indicators do not underflow, and indicators below
  \f$10^{-15}\f$ times the largest are taken as zero: a point computed on a side or at a
  corner is off by round-off, and at a corner two tiny indicators would give unstable,
  direction-dependent values.

  \tparam T a field number type or a `Taylor_jet` of one: with jets of the indicators
  (as functions of the domain point), the result is the jets of the \f$f_i\f$
  \param indicators \f$p_0(x,y), \dots, p_{n-1}(x,y)\f$, \f$n \ge 1\f$ (they must satisfy
  Def. 3.1: \f$p_i + p_j = 0\f$ only where both vanish; true for non-negative indicators)
  \param order the blending order \f$d \ge 0\f$
  \throws Invalid_input if \f$d < 0\f$, \f$n = 0\f$, more than two indicators vanish, two
  non-zero indicators violate Def. 3.1, or (floating point) the denominator underflows
  \returns Fang's blending functions \f$f_i^{n,d,p}\f$ (Def. 3.4) at a point, given the values
  \f$p_i\f$ of the inheritance indicators there, with the limits where indicators vanish
*/
template <class T>
std::vector<T> blending_functions(const std::vector<T>& indicators, int order) {
  internal::check_order(order, "blending_functions");
  return internal::fang_from_powers(
      internal::powers(internal::snapped(internal::normalized(indicators)), order),
      "blending_functions");
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns Fang's blending functions from the powers \f$w_i = p_i^{d+1}\f$ instead of
  the indicators; see `blending_functions()`.

  For indicators whose power is smoother than the indicator itself: a Euclidean distance
  \f$p = \sqrt{q}\f$ has \f$p^{d+1} = q^{(d+1)/2}\f$, a polynomial when \f$d\f$ is odd, whose
  jet exists where \f$p = 0\f$ (Fang, eq. 7.8).
  \tparam T a number type or a `Taylor_jet`
  \param powers the powers of the indicators
  \returns Fang's blending functions from the powers \f$w_i = p_i^{d+1}\f$ instead of the indicators
*/
template <class T>
std::vector<T> blending_functions_of_powers(const std::vector<T>& powers) {
  return internal::fang_from_powers(powers, "blending_functions_of_powers");
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the extended Nielson blending functions (Fang, eq. 9.1, "special side
  blending functions"):
  \f$f_i = \prod_{j \ne i} w_j \big/ \sum_{j} \prod_{k \ne j} w_k\f$,
  \f$w_i = v_i^{d+1}\f$.

  For \f$n = 3\f$ this is eq. 4.8; \f$d = 0\f$ gives Nielson's functions (Def. 2.3) and
  \f$d = 1\f$ Hagen and Pottmann's (eq. 2.9). They inherit derivatives up to order \f$d\f$
  where one indicator vanishes, like Fang's, but are undefined where two vanish (the
  corners of a triangle): there all terms of the denominator vanish.
  \tparam T a number type or a `Taylor_jet`
  \throws Invalid_input if \f$d < 0\f$, \f$n = 0\f$ or two or more indicators vanish
  \param indicators the values of the indicators
  \param order the order
  \returns the extended Nielson blending functions (Fang, eq. 9.1, "special side blending
  functions")
*/
template <class T>
std::vector<T> extended_nielson_functions(const std::vector<T>& indicators, int order) {
  using B = internal::Base_number<T>;
  internal::check_order(order, "extended_nielson_functions");
  const std::size_t n = indicators.size();
  if (n == 0)
    throw Invalid_input("extended_nielson_functions: no indicator");
  const std::vector<T> w = internal::powers(internal::normalized(indicators), order);
  const std::vector<std::size_t> zeros = internal::zero_indices(w);
  if (zeros.size() >= 2 && n >= 2)
    throw Invalid_input("extended_nielson_functions: indicators " + internal::index_list(zeros) +
                        " vanish; Nielson-type functions are undefined where two vanish");
  const T one = internal::one_like(w[0]);
  std::vector<T> numerators;
  numerators.reserve(n);
  T D = internal::zero_like(w[0]);
  for (std::size_t i = 0; i < n; ++i) {
    numerators.push_back(internal::product_without(w, i, i, one));
    D = D + numerators.back();
  }
  if (internal::value_of(D) == B(0))
    throw Invalid_input("extended_nielson_functions: the denominator vanishes");
  for (T& x : numerators)
    x = x / D;
  return numerators;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns Nielson's blending functions (Fang, Def. 2.3):
  \f$f_0 = vw/(uv + vw + wu)\f$ and cyclically; undefined at the corners.
  \tparam T a number type or a `Taylor_jet`
  \throws Invalid_input at a corner (two of \f$u, v, w\f$ zero)
  \param u the first indicator
  \param v the second indicator
  \param w the third indicator
  \returns Nielson's blending functions (Fang, Def. 2.3)
*/
template <class T>
std::array<T, 3> nielson_functions(const T& u, const T& v, const T& w) {
  const std::vector<T> f = extended_nielson_functions(std::vector<T>{u, v, w}, 0);
  return {{f[0], f[1], f[2]}};
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns Hagen and Pottmann's blending functions (Fang, eq. 2.9):
  \f$f_0 = v^2w^2/(u^2v^2 + v^2w^2 + w^2u^2)\f$ and cyclically; undefined at the corners.
  \tparam T a number type or a `Taylor_jet`
  \throws Invalid_input at a corner
  \param u the first indicator
  \param v the second indicator
  \param w the third indicator
  \returns Hagen and Pottmann's blending functions (Fang, eq. 2.9)
*/
template <class T>
std::array<T, 3> hagen_pottmann_functions(const T& u, const T& v, const T& w) {
  const std::vector<T> f = extended_nielson_functions(std::vector<T>{u, v, w}, 1);
  return {{f[0], f[1], f[2]}};
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns Shepard's functions (Fang, eq. 9.2):
  \f$s_i = w_i^{-1} \big/ \sum_j w_j^{-1}\f$, \f$w_i = v_i^{d+1}\f$, and their limit
  (\f$s_i = 1\f$, the others 0, with derivatives) where one indicator vanishes.

  Where no indicator vanishes they are computed from the reciprocals, an independent
  formula; they equal `extended_nielson_functions()` (multiply numerator and denominator
  by \f$\prod w\f$), which the tests check exactly.
  \tparam T a number type or a `Taylor_jet`
  \throws Invalid_input if \f$d < 0\f$, \f$n = 0\f$ or two or more indicators vanish
  \param indicators the values of the indicators
  \param order the order
  \returns Shepard's functions (Fang, eq. 9.2)
*/
template <class T>
std::vector<T> shepard_functions(const std::vector<T>& indicators, int order) {
  using B = internal::Base_number<T>;
  internal::check_order(order, "shepard_functions");
  if (indicators.empty())
    throw Invalid_input("shepard_functions: no indicator");
  const std::vector<T> w = internal::powers(internal::normalized(indicators), order);
  if (!internal::zero_indices(w).empty())
    return extended_nielson_functions(indicators, order); // the continuous extension
  const T one = internal::one_like(w[0]);
  std::vector<T> r;
  r.reserve(w.size());
  T sum = internal::zero_like(w[0]);
  for (const T& x : w) {
    r.push_back(one / x);
    sum = sum + r.back();
  }
  if (internal::value_of(sum) == B(0))
    throw Invalid_input("shepard_functions: the sum of the reciprocals vanishes");
  for (T& x : r)
    x = x / sum;
  return r;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the blending-function policy of Fang (Def. 3.4), the default of the blending
  schemes; see `blending_functions()`.

  A blending-function policy is a class with a `name()` and a call operator
  `std::vector<T> operator()(const std::vector<T>& indicators, int d) const` for numbers
  and `Taylor_jet`s; optionally `of_powers(w)` for indicators given as powers.
*/
struct Fang_blending_functions {
  /// returns the name of the policy, `"fang"`.
  /// \returns the name of the policy, `"fang"`
  static const char* name() { return "fang"; }
  /// returns the blending functions of order `order` of `indicators` (`blending_functions()`).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param indicators the values of the indicators
  /// \param order the order
  /// \returns the blending functions of order `order` of `indicators` (`blending_functions()`)
  template <class T>
  std::vector<T> operator()(const std::vector<T>& indicators, int order) const {
    return blending_functions(indicators, order);
  }
  /// returns the blending functions of indicators given as powers
  /// (`blending_functions_of_powers()`).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param powers the powers of the indicators
  /// \returns the blending functions of indicators given as powers
  /// (`blending_functions_of_powers()`)
  template <class T>
  std::vector<T> of_powers(const std::vector<T>& powers) const {
    return blending_functions_of_powers(powers);
  }
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the blending-function policy of the extended Nielson functions (eq. 9.1); the
  schemes using it are undefined at points where two indicators vanish.
*/
struct Extended_nielson_blending_functions {
  /// returns the name of the policy, `"extended-nielson"`.
  /// \returns the name of the policy, `"extended-nielson"`
  static const char* name() { return "extended-nielson"; }
  /// returns the extended Nielson functions of order `order` of `indicators`.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param indicators the values of the indicators
  /// \param order the order
  /// \returns the extended Nielson functions of order `order` of `indicators`
  template <class T>
  std::vector<T> operator()(const std::vector<T>& indicators, int order) const {
    return extended_nielson_functions(indicators, order);
  }
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the blending-function policy of Shepard's functions (eq. 9.2).
*/
struct Shepard_blending_functions {
  /// returns the name of the policy, `"shepard"`.
  /// \returns the name of the policy, `"shepard"`
  static const char* name() { return "shepard"; }
  /// returns Shepard's functions of order `order` of `indicators`.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param indicators the values of the indicators
  /// \param order the order
  /// \returns Shepard's functions of order `order` of `indicators`
  template <class T>
  std::vector<T> operator()(const std::vector<T>& indicators, int order) const {
    return shepard_functions(indicators, order);
  }
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_FUNCTIONS_H

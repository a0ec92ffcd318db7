// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_ARITHMETIC_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_ARITHMETIC_H

// The arithmetic behind Fang's blending functions and schemes, on numbers and Taylor jets
// alike (Blending/blending_functions.h, Blending/blending_schemes.h,
// Blending/Mesh_blending_surface.h).

#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class T>
using Base_number = typename Jet_value<T>::Type;

template <class T>
constexpr bool is_exact_number() {
  return CGAL::Algebraic_structure_traits<Base_number<T>>::Is_exact::value;
}

// 1 with the truncation order of `x` (a number, or a jet of the order of `x`).
template <class T>
T one_like(const T& x) {
  using B = Base_number<T>;
  T r = x * B(0) + B(1);
  return r;
}

template <class T>
T zero_like(const T& x) {
  using B = Base_number<T>;
  T r = x * B(0);
  return r;
}

inline void check_order(int order, const char* who) {
  if (order < 0)
    throw Invalid_input(std::string(who) + ": the blending order d must be non-negative, got " +
                        std::to_string(order));
}

// In floating point the formulas are homogeneous of degree 0 in the indicators: dividing
// them by the largest magnitude avoids underflow of the products w_i = p_i^{d+1} (and of
// their products). Exact number types are left alone.
template <class T>
std::vector<T> normalized(const std::vector<T>& v) {
  if constexpr (is_exact_number<T>()) {
    return v;
  } else {
    using B = Base_number<T>;
    B largest(0);
    for (const T& x : v) {
      const B a = CGAL::abs(value_of(x));
      if (a > largest)
        largest = a;
    }
    if (!(largest > B(0)) || largest == B(1))
      return v;
    std::vector<T> r;
    r.reserve(v.size());
    for (const T& x : v)
      r.push_back(x / largest);
    return r;
  }
}

// Sets the value (constant term) of a number or a jet.
template <class T>
void set_value(T& x, const Base_number<T>& value) {
  if constexpr (std::is_same<T, Base_number<T>>::value)
    x = value;
  else
    x.set_coefficient(0, 0, value);
}

// In floating point, indicators within round-off of zero (relative to the largest) are
// zero: a point computed on a side or at a corner is off by a few ulps, and at a corner
// two such tiny indicators would otherwise give direction-dependent, unstable values
// (and for even d, p_i^{d+1} + p_j^{d+1} = 0 with opposite signs).
template <class T>
std::vector<T> snapped(std::vector<T> v) {
  if constexpr (!is_exact_number<T>()) {
    using B = Base_number<T>;
    B largest(0);
    for (const T& x : v)
      largest = (std::max)(largest, B(CGAL::abs(value_of(x))));
    const B threshold = largest * B(1e-15);
    for (T& x : v)
      if (CGAL::abs(value_of(x)) <= threshold)
        set_value(x, B(0));
  }
  return v;
}

template <class T>
std::vector<T> powers(const std::vector<T>& v, int order) {
  std::vector<T> w;
  w.reserve(v.size());
  for (const T& x : v)
    w.push_back(integer_power(x, order + 1));
  return w;
}

template <class T>
std::vector<std::size_t> zero_indices(const std::vector<T>& w) {
  using B = Base_number<T>;
  std::vector<std::size_t> zeros;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (value_of(w[i]) == B(0))
      zeros.push_back(i);
  return zeros;
}

inline std::string index_list(const std::vector<std::size_t>& indices) {
  std::string s;
  for (std::size_t k = 0; k < indices.size(); ++k)
    s += (k ? ", " : "") + std::to_string(indices[k]);
  return s;
}

// prod_{k != i, j} w_k (i == j: prod_{k != i}); `one` carries the order of the jets.
template <class T>
T product_without(const std::vector<T>& w, std::size_t i, std::size_t j, const T& one) {
  T p = one;
  for (std::size_t k = 0; k < w.size(); ++k)
    if (k != i && k != j)
      p = p * w[k];
  return p;
}

// Fang's f^{n,d,p} (Def. 3.4) from the powers w_i = p_i^{d+1}, with the limits of §3.3.
template <class T>
std::vector<T> fang_from_powers(const std::vector<T>& w_in, const char* who) {
  using B = Base_number<T>;
  const std::size_t n = w_in.size();
  if (n == 0)
    throw Invalid_input(std::string(who) + ": no inheritance indicator (n = 0)");
  if (n == 1)
    return {one_like(w_in[0])};
  const std::vector<T> w = normalized(w_in);
  const std::vector<std::size_t> zeros = zero_indices(w);
  if (zeros.size() > 2)
    throw Invalid_input(std::string(who) + ": " + std::to_string(zeros.size()) +
                        " inheritance indicators vanish at the point (indices " +
                        index_list(zeros) +
                        "); f^{n,d,p} is defined where at most two vanish (Fang, §3.3)");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (value_of(w[i]) + value_of(w[j]) == B(0) && value_of(w[i]) != B(0))
        throw Invalid_input(std::string(who) + ": indicators " + std::to_string(i) + " and " +
                            std::to_string(j) +
                            " have p_i^{d+1} + p_j^{d+1} = 0 without vanishing (Fang, Def. 3.1)");
  const T one = one_like(w[0]);
  // P[i][j] = prod_{k != i, j} w_k, and D = sum_{i<j} P[i][j]
  std::vector<T> P(n * n, one); // P[i * n + j]
  T D = zero_like(w[0]);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      P[i * n + j] = product_without(w, i, j, one);
      P[j * n + i] = P[i * n + j];
      D = D + P[i * n + j];
    }
  if (value_of(D) == B(0))
    throw Invalid_input(std::string(who) +
                        ": the denominator of f^{n,d,p} vanishes (indicators too close to zero "
                        "for the number type)");
  std::vector<T> f(n, zero_like(w[0]));
  const bool pair = zeros.size() == 2;
  for (std::size_t i = 0; i < n; ++i) {
    if (pair && (i == zeros[0] || i == zeros[1]))
      continue;
    T numerator = zero_like(w[0]);
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) {
        // w_j / (w_i + w_j) * prod_{k != i,j} w_k: the stable form of
        // (prod_{k != i} w_k) / (w_i + w_j)
        const T ratio = w[j] / (w[i] + w[j]);
        numerator = numerator + ratio * P[i * n + j];
      }
    f[i] = numerator / D;
  }
  if (pair) {
    // Only f_i + f_j is defined where p_i = p_j = 0 (Prop. 3.11); it is 1 minus the others
    // (Prop. 3.3). Each gets half: the limit along w_i = w_j.
    T rest = one;
    for (std::size_t k = 0; k < n; ++k)
      if (k != zeros[0] && k != zeros[1])
        rest = rest - f[k];
    const T half = rest / B(2);
    f[zeros[0]] = half;
    f[zeros[1]] = half;
  }
  return f;
}

// d + 1-th power of a Euclidean distance given by its square q: a polynomial in q when
// d + 1 is even; where q = 0 and d + 1 is odd its jet vanishes to order d (the higher
// derivatives do not exist there and are returned as zero).
template <class T>
T power_of_distance(const T& q, int order) {
  const int e = order + 1;
  if (e % 2 == 0)
    return integer_power(q, e / 2);
  if (!(value_of(q) > 0))
    return zero_like(q);
  using std::sqrt;
  return integer_power(T(sqrt(q)), e);
}

template <class T>
struct Is_std_array : std::false_type {};
template <class T, std::size_t D>
struct Is_std_array<std::array<T, D>> : std::true_type {};

// sum_i f_i * values_i for scalar values (T) or vector values (std::array<T, D>).
template <class T, class Value>
Value weighted_sum(const std::vector<T>& f, const std::vector<Value>& values) {
  if (f.size() != values.size() || f.empty())
    throw Invalid_input("blend: " + std::to_string(values.size()) + " sub-surface values for " +
                        std::to_string(f.size()) + " blending functions");
  if constexpr (Is_std_array<Value>::value) {
    Value r = values[0];
    for (std::size_t c = 0; c < r.size(); ++c)
      r[c] = f[0] * values[0][c];
    for (std::size_t i = 1; i < f.size(); ++i)
      for (std::size_t c = 0; c < r.size(); ++c)
        r[c] = r[c] + f[i] * values[i][c];
    return r;
  } else {
    Value r = f[0] * values[0];
    for (std::size_t i = 1; i < f.size(); ++i)
      r = r + f[i] * values[i];
    return r;
  }
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_ARITHMETIC_H

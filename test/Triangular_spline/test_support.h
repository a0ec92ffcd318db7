// Shared fixtures of the Triangular_spline tests: the two kernels every templated test runs
// on, seeded random rationals, and comparisons that are exact for exact number types and
// use a stated tolerance for double.
#ifndef TRIANGULAR_SPLINE_TEST_SUPPORT_H
#define TRIANGULAR_SPLINE_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace ts_test {

namespace TS = CGAL::Triangular_spline;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact_kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Kernels = ::testing::Types<Epick, Exact_kernel>;

// Readable names for typed tests ("Double", "Exact") instead of mangled gmpxx types.
struct Kernel_names {
  template <class K>
  static std::string GetName(int) {
    return std::is_same<K, Epick>::value ? "Double" : "Exact";
  }
};

template <class K>
constexpr bool is_exact = CGAL::Algebraic_structure_traits<typename K::FT>::Is_exact::value;

// Random rationals num/den with small integers: exact in Exact_rational, and for double the
// same values rounded once, so both kernels test the same configurations.
class Random_rationals {
public:
  explicit Random_rationals(unsigned seed) : m_engine(seed) {}

  template <class FT>
  FT rational(int max_num = 20, int max_den = 7) {
    std::uniform_int_distribution<int> num(-max_num, max_num), den(1, max_den);
    return FT(num(m_engine)) / FT(den(m_engine));
  }

  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_engine); }

  template <class K>
  typename K::Point_2 point() {
    return typename K::Point_2(rational<typename K::FT>(), rational<typename K::FT>());
  }

  // A triangle with random rational corners, counter-clockwise, not degenerate.
  template <class K>
  std::array<typename K::Point_2, 3> triangle() {
    for (;;) {
      std::array<typename K::Point_2, 3> t{{point<K>(), point<K>(), point<K>()}};
      const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2]);
      if (o == CGAL::COLLINEAR)
        continue;
      if (o == CGAL::CLOCKWISE)
        std::swap(t[1], t[2]);
      return t;
    }
  }

  template <class K, class Value>
  Value value();

  template <class K, class Value = typename K::FT>
  TS::Polynomial_surface<K, Value> polynomial(int degree) {
    TS::Polynomial_surface<K, Value> p(degree);
    for (int h = 0; h <= degree; ++h)
      for (int k = 0; h + k <= degree; ++k)
        p.set_coefficient(h, k, value<K, Value>());
    return p;
  }

  std::mt19937& engine() { return m_engine; }

private:
  std::mt19937 m_engine;
};

template <class K, class Value>
Value Random_rationals::value() {
  using FT = typename K::FT;
  if constexpr (std::is_same<Value, FT>::value)
    return rational<FT>();
  else
    return Value(rational<FT>(), rational<FT>(), rational<FT>());
}

// Exact kernels: the values must be identical. Double: |a - b| <= tolerance * scale, with
// the tolerance stated by the caller (default 1e-9: de Casteljau on O(10) data loses a few
// ulps per level, far below this).
template <class Value>
::testing::AssertionResult same_value(const Value& a, const Value& b, bool exact,
                                      double tolerance = 1e-9, double scale = 1) {
  const Value difference = a - b; // a named Value, never `auto` (gmpxx expressions)
  if (exact ? TS::is_zero_value(difference)
            : TS::max_abs_coordinate(difference) <= tolerance * scale)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "values differ by " << TS::max_abs_coordinate(difference)
         << (exact ? " (exact comparison)"
                   : " (tolerance " + std::to_string(tolerance * scale) + ")");
}

// The largest absolute control value (at least 1): double tolerances are relative to it.
template <class K, class Value>
double scale_of(const TS::Bezier_triangle<K, Value>& patch) {
  double s = 1;
  for (const Value& v : patch.control_points())
    s = (std::max)(s, TS::max_abs_coordinate(v));
  return s;
}

// Expects the spline's propagation-weight statistics (largest weight and count above the
// bound, by slot kind) to be those of its rules; returns the counts above the bound by kind.
template <class Spline>
std::array<std::size_t, 6>
expect_weight_statistics_of_rules(const Spline& spline,
                                  const std::vector<typename Spline::Rule>& rules) {
  using Kind = decltype(spline.kind(typename Spline::Slot{})); // Slot_kind
  std::array<double, 6> largest{};
  std::array<std::size_t, 6> above{};
  for (const auto& r : rules) {
    double w = 0;
    for (int i = 0; i < r.size(); ++i)
      w = (std::max)(w, std::abs(r.weights[std::size_t(i)]));
    const std::size_t k = std::size_t(spline.kind(r.target));
    largest[k] = (std::max)(largest[k], w);
    above[k] += w > Spline::propagation_weight_bound ? 1 : 0;
  }
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(spline.max_propagation_weight(Kind(k)), largest[k]) << k;
    EXPECT_EQ(spline.number_of_rules_above_weight_bound(Kind(k)), above[k]) << k;
  }
  EXPECT_EQ(spline.max_propagation_weight(), *std::max_element(largest.begin(), largest.end()));
  return above;
}

} // namespace ts_test

#endif

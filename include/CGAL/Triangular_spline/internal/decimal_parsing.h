// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_DECIMAL_PARSING_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_DECIMAL_PARSING_H

// The grammar and the range checks behind parse_number() (IO/number_parsing.h): decimal and
// p/q tokens read exactly or as correctly rounded doubles, and exact values rounded to the
// nearest double.

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#if __has_include(<gmpxx.h>)
#include <gmpxx.h>
#endif

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Accepted magnitudes: above 1e150 a product of two coordinates overflows in double; below
// 1e-400 (far under the smallest subnormal double) only to bound the work of an exact
// power of ten. Zero is always accepted.
constexpr int max_decimal_exponent = 150;
constexpr int min_decimal_exponent = -400;

// A decimal token [+-]digits[.digits][(e|E)[+-]digits] as sign * digits * 10^exponent, the
// digits without leading zeros (empty for zero).
struct Decimal_token {
  bool negative = false;
  std::string digits;
  long long exponent = 0;
};

inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Returns false if `token` is not a decimal number; never throws.
inline bool split_decimal(const std::string& token, Decimal_token& out) {
  std::size_t p = 0;
  const std::size_t n = token.size();
  out = Decimal_token();
  if (p < n && (token[p] == '+' || token[p] == '-'))
    out.negative = token[p++] == '-';
  std::string mantissa;
  std::size_t fraction_digits = 0;
  while (p < n && is_digit(token[p]))
    mantissa += token[p++];
  if (p < n && token[p] == '.') {
    ++p;
    while (p < n && is_digit(token[p])) {
      mantissa += token[p++];
      ++fraction_digits;
    }
  }
  if (mantissa.empty())
    return false;
  long long exponent = 0;
  if (p < n && (token[p] == 'e' || token[p] == 'E')) {
    ++p;
    bool negative_exponent = false;
    if (p < n && (token[p] == '+' || token[p] == '-'))
      negative_exponent = token[p++] == '-';
    if (p == n || !is_digit(token[p]))
      return false;
    while (p < n && is_digit(token[p])) {
      // Saturate: any exponent beyond 10^9 is out of range anyway.
      if (exponent < 1000000000LL)
        exponent = 10 * exponent + (token[p] - '0');
      ++p;
    }
    if (negative_exponent)
      exponent = -exponent;
  }
  if (p != n)
    return false;
  const std::size_t first = mantissa.find_first_not_of('0');
  if (first == std::string::npos)
    return true; // zero, whatever the exponent
  out.digits = mantissa.substr(first);
  out.exponent = exponent - static_cast<long long>(fraction_digits);
  return true;
}

// Rejects values certainly outside [1e-400, 1e150] from the digit count alone, before any
// arithmetic; the caller decides the borderline case 10^150 < |x| < 10^151 exactly.
inline void check_decimal_range(const std::string& token, const Decimal_token& d) {
  if (d.digits.empty())
    return;
  // |x| lies in [10^(L-1+e), 10^(L+e)) with L significant digits.
  const long long L = static_cast<long long>(d.digits.size());
  if (L - 1 + d.exponent > max_decimal_exponent)
    throw Invalid_input("number " + quoted(token) + " is too large (magnitude above 1e150)");
  if (L + d.exponent < min_decimal_exponent)
    throw Invalid_input("number " + quoted(token) +
                        " is too close to zero (non-zero magnitude below 1e-400)");
}

[[noreturn]] inline void throw_not_a_number(const std::string& token, bool exact) {
  if (token.empty())
    throw Invalid_input("empty number");
  std::string body = token.substr(token[0] == '+' || token[0] == '-' ? 1 : 0);
  for (char& c : body)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (body.compare(0, 3, "nan") == 0 || body.compare(0, 3, "inf") == 0)
    throw Invalid_input("number " + quoted(token) + " is not finite");
  if (!exact && token.find('/') != std::string::npos)
    throw Invalid_input(quoted(token) +
                        " is not a decimal number (fractions p/q are only read as exact numbers)");
  throw Invalid_input(quoted(token) + " is not a number");
}

// FT from a string of decimal digits, nine digits per step (exact for exact FT).
template <class FT>
FT integer_from_digits(const std::string& digits) {
  FT value(0);
  const FT billion(1000000000);
  std::size_t p = 0;
  const std::size_t head = digits.size() % 9;
  if (head != 0) {
    value = FT(std::stoi(digits.substr(0, head)));
    p = head;
  }
  for (; p < digits.size(); p += 9) {
    FT next = value * billion + FT(std::stoi(digits.substr(p, 9)));
    value = next;
  }
  return value;
}

template <class FT>
FT power_of_ten(long long e) {
  FT result(1), base(10);
  for (; e > 0; e >>= 1) {
    if (e & 1) {
      FT next = result * base;
      result = next;
    }
    FT square = base * base;
    base = square;
  }
  return result;
}

template <class FT>
FT parse_exact(const std::string& token) {
  // 10^150 is only built for the rare tokens whose digit counts leave the range open.
  auto above_limit = [](const FT& magnitude) {
    return magnitude > power_of_ten<FT>(max_decimal_exponent);
  };
  const std::size_t slash = token.find('/');
  if (slash != std::string::npos) {
    // p/q: a signed integer over a positive integer, both plain digit strings.
    const std::string p = token.substr(0, slash), q = token.substr(slash + 1);
    const std::size_t sign = (!p.empty() && (p[0] == '+' || p[0] == '-')) ? 1 : 0;
    auto all_digits = [](const std::string& s, std::size_t from) {
      if (s.size() <= from)
        return false;
      for (std::size_t i = from; i < s.size(); ++i)
        if (!is_digit(s[i]))
          return false;
      return true;
    };
    if (!all_digits(p, sign) || !all_digits(q, 0))
      throw_not_a_number(token, true);
    const FT denominator = integer_from_digits<FT>(q);
    if (CGAL::is_zero(denominator))
      throw Invalid_input("number " + quoted(token) + " has a zero denominator");
    const FT numerator = integer_from_digits<FT>(p.substr(sign));
    // |p/q| < 10^(digits(p) - digits(q) + 1), with q's leading zeros not counted (p's
    // only widen the bound).
    const long long digits = static_cast<long long>(p.size() - sign) -
                             static_cast<long long>(q.size() - q.find_first_not_of('0'));
    if (digits + 1 > max_decimal_exponent && above_limit(numerator / denominator))
      throw Invalid_input("number " + quoted(token) + " is too large (magnitude above 1e150)");
    FT value = numerator / denominator;
    if (sign == 1 && p[0] == '-') {
      FT negated = -value;
      value = negated;
    }
    return value;
  }
  Decimal_token d;
  if (!split_decimal(token, d))
    throw_not_a_number(token, true);
  check_decimal_range(token, d);
  if (d.digits.empty())
    return FT(0);
  FT value;
#ifdef __GMP_PLUSPLUS__
  if constexpr (std::is_same_v<FT, mpq_class>) {
    // In GMP directly: the digits as the numerator, times 10^e or over 10^-e, reduced by one
    // gcd. (Rational products reduce by gcds at each step, nine digits at a time and for
    // every square of 10: 10^5 17-digit points, 0.4 s of reading.)
    const mpq_ptr q = value.get_mpq_t();
    mpz_set_str(mpq_numref(q), d.digits.c_str(), 10);
    if (d.exponent > 0) {
      mpz_class power;
      mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(d.exponent));
      mpz_mul(mpq_numref(q), mpq_numref(q), power.get_mpz_t());
    } else if (d.exponent < 0) {
      mpz_ui_pow_ui(mpq_denref(q), 10, static_cast<unsigned long>(-d.exponent));
      mpq_canonicalize(q);
    }
  } else
#endif
  {
    const FT mantissa = integer_from_digits<FT>(d.digits);
    value = d.exponent >= 0 ? FT(mantissa * power_of_ten<FT>(d.exponent))
                            : FT(mantissa / power_of_ten<FT>(-d.exponent));
  }
  // |x| < 10^(L + e); check_decimal_range() excluded |x| >= 10^151.
  if (static_cast<long long>(d.digits.size()) + d.exponent > max_decimal_exponent &&
      above_limit(value))
    throw Invalid_input("number " + quoted(token) + " is too large (magnitude above 1e150)");
  if (d.negative) {
    FT negated = -value;
    value = negated;
  }
  return value;
}

inline double parse_double(const std::string& token) {
  // The decimal grammar is checked first, so that both kinds of number types accept the
  // same tokens (strtod alone would also take "0x1p3", "infinity" or "nan(1)").
  Decimal_token d;
  if (!split_decimal(token, d))
    throw_not_a_number(token, false);
  check_decimal_range(token, d);
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  if (end != token.c_str() + token.size())
    throw_not_a_number(token, false);
  if (!std::isfinite(value) || std::fabs(value) > 1e150)
    throw Invalid_input("number " + quoted(token) + " is too large (magnitude above 1e150)");
  return value;
}

// Returns the double nearest to `x` (ties to even), from CGAL's tight enclosing interval
// and one exact comparison: `to_double` of gmpxx rationals truncates instead of rounding.
template <class FT>
double nearest_double(const FT& x) {
  const std::pair<double, double> bounds = CGAL::to_interval(x);
  if (bounds.first == bounds.second)
    return bounds.first;
  const FT below = x - FT(bounds.first);
  const FT above = FT(bounds.second) - x;
  if (below < above)
    return bounds.first;
  if (above < below)
    return bounds.second;
  // A tie: take the neighbour whose last mantissa bit is zero. Adjacent doubles of one
  // sign have adjacent bit patterns, so the parity of the pattern is that of the mantissa.
  std::uint64_t bits = 0;
  std::memcpy(&bits, &bounds.first, sizeof bits);
  return (bits & 1u) == 0 ? bounds.first : bounds.second;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_DECIMAL_PARSING_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_IO_NUMBER_PARSING_H
#define CGAL_TRIANGULAR_SPLINE_IO_NUMBER_PARSING_H

#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/internal/decimal_parsing.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Fraction_traits.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#if __has_include(<gmp.h>)
#include <gmp.h>
#define CGAL_TRIANGULAR_SPLINE_HAS_GMP_H 1
#endif

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineIO
  \brief parses one number token of a text file into the number type `FT`.

  Accepted tokens are decimals `[+-]digits[.digits][(e|E)[+-]digits]` (at least one digit,
  so `.5` and `5.` are valid) and, for exact number types only, rationals `p/q` (an
  optionally signed integer over a positive integer, no spaces).

  - If `FT` is exact (`CGAL::Algebraic_structure_traits<FT>::Is_exact`, e.g.
    `CGAL::Exact_rational`), the value is the exact rational the token denotes:
    `"0.1"` is exactly 1/10 and `"1/3"` exactly one third.
  - Otherwise the token is converted with `std::strtod` (correctly rounded) and `FT` is
    built from the `double`.

  \tparam FT `double`, or an exact number type that is a model of `FieldNumberType`
  constructible from `int`, such as `CGAL::Exact_rational`
  \throws Invalid_input quoting the token if it is empty or not a number (garbage, hex
  floats, `nan`, `inf`, a fraction for an inexact `FT`), if its magnitude exceeds
  \f$10^{150}\f$ (products of two such numbers would overflow a `double`), or if it is non-zero
  with a magnitude below \f$10^{-400}\f$ (a bound on the exact work; it is below every
  `double`). Both kinds of number types accept exactly the same decimal tokens.
  \param token the token to parse
  \returns the number
*/
template <class FT>
FT parse_number(const std::string& token) {
  if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value)
    return internal::parse_exact<FT>(token);
  else
    return FT(internal::parse_double(token));
}

namespace internal {
// Whether FT is GMP's C++ rational (mpq_class, CGAL::Exact_rational with GMPXX).
template <class FT, class = void>
struct Is_gmpxx_rational : std::false_type {};
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMP_H
template <class FT>
struct Is_gmpxx_rational<
    FT,
    std::enable_if_t<std::is_same_v<decltype(std::declval<const FT&>().get_mpq_t()), mpq_srcptr>>>
    : std::true_type {};

// appends the decimal digits of z (with its sign)
inline void append_mpz(std::string& out, mpz_srcptr z) {
  const std::size_t at = out.size();
  out.resize(at + mpz_sizeinbase(z, 10) + 2); // the size may be one too large, and a sign
  mpz_get_str(out.data() + at, 10, z);
  out.resize(at + std::strlen(out.data() + at));
}
#endif

// format_number() of GMP's rationals, which are kept reduced: their parts are written
// straight from GMP (the decomposition's copies and a string stream were most of the time
// of saving an exact spline).
template <class FT>
std::string format_gmpxx_rational(const FT& x) {
  std::string out;
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMP_H
  const mpq_srcptr q = x.get_mpq_t();
  append_mpz(out, mpq_numref(q));
  if (mpz_cmp_ui(mpq_denref(q), 1) != 0) {
    out += '/';
    append_mpz(out, mpq_denref(q));
  }
#else
  CGAL_USE(x);
#endif
  return out;
}
} // namespace internal

/*!
  \ingroup PkgTriangularSplineIO
  \brief formats `x` as a token that `parse_number<FT>()` reads back to the same value.

  An exact `FT` is written as the reduced fraction `p/q`, or `p` when it is an integer; an
  inexact one is converted to `double` and written as the shortest decimal that reads back to
  the same `double` (`std::to_chars`).
  \tparam FT `double`, or an exact number type with a `CGAL::Fraction_traits`
  decomposition (e.g. `CGAL::Exact_rational`)
  \param x the number to format
  \returns the token
*/
template <class FT>
std::string format_number(const FT& x) {
  if constexpr (internal::Is_gmpxx_rational<FT>::value) {
    return internal::format_gmpxx_rational(x);
  } else if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
    using Traits = CGAL::Fraction_traits<FT>;
    static_assert(std::is_same<typename Traits::Is_fraction, CGAL::Tag_true>::value,
                  "format_number needs an exact number type that is a fraction");
    typename Traits::Numerator_type numerator;
    typename Traits::Denominator_type denominator;
    typename Traits::Decompose decompose;
    decompose(x, numerator, denominator);
    std::ostringstream out;
    out << numerator;
    if (denominator != typename Traits::Denominator_type(1))
      out << "/" << denominator;
    return out.str();
  } else {
    std::string text;
    internal::append_double(text, CGAL::to_double(x));
    return text;
  }
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_IO_NUMBER_PARSING_H

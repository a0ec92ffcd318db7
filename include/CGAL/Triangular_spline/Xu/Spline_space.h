// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H
#define CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Xu/degenerate_frames.h>
#include <CGAL/Triangular_spline/internal/continuity_conditions.h>
#include <CGAL/Triangular_spline/internal/plan_certificate.h>
#include <CGAL/Triangular_spline/internal/sparse_rank.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Fraction_traits.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns Xu's free-parameter count \f$3V + 3F + E_I + 3E_B + \sigma\f$ of the
  quintic C^1 scheme with re-routed degenerate frames (\f$\sigma\f$: interior singular
  vertices).
  \tparam GeomTraits a model of `Kernel`
  \param domain the triangulated planar domain
  \returns Xu's free-parameter count \f$3V + 3F + E_I + 3E_B + \sigma\f$ of the quintic C^1 scheme
  with re-routed degenerate frames (\f$\sigma\f$: interior singular vertices)
*/
template <class GeomTraits>
std::size_t free_parameter_count(const Planar_domain<GeomTraits>& domain) {
  return 3 * domain.number_of_vertices() + 3 * domain.number_of_faces() +
         domain.number_of_interior_edges() + 3 * domain.number_of_boundary_edges() +
         find_degenerate_frames(domain).singular_vertices.size();
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns Morgan and Scott's dimension of \f$S^1_5\f$,
  \f$12 V_I + 10 V_B - 9 + \sigma\f$, or nothing when the domain is not simply connected
  (the formula holds for triangulated disks only).
  \tparam GeomTraits a model of `Kernel`
  \param domain the triangulated planar domain
  \returns Morgan and Scott's dimension of \f$S^1_5\f$, \f$12 V_I + 10 V_B - 9 + \sigma\f$, or
  nothing when the domain is not simply connected (the formula holds for triangulated disks only)
*/
template <class GeomTraits>
std::optional<long long> morgan_scott_dimension(const Planar_domain<GeomTraits>& domain) {
  if (!domain.is_simply_connected())
    return std::nullopt;
  return 12 * static_cast<long long>(domain.number_of_interior_vertices()) +
         10 * static_cast<long long>(domain.number_of_boundary_vertices()) - 9 +
         static_cast<long long>(find_degenerate_frames(domain).singular_vertices.size());
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns `morgan_scott_dimension(spline.domain())`, counting the singular vertices the
  spline's plan found instead of searching the domain again (for an exact domain of 10^5
  points that search takes half a second).
  \tparam GeomTraits a model of `Kernel`
  \tparam Value the spline's value type
  \param spline a spline over a planar domain
  \returns Morgan and Scott's dimension of \f$S^1_5\f$ over the spline's domain, or nothing when
  that domain is not simply connected
*/
template <class GeomTraits, class Value>
std::optional<long long>
morgan_scott_dimension(const C1_quintic_spline<GeomTraits, Value>& spline) {
  const Planar_domain<GeomTraits>& domain = spline.domain();
  if (!domain.is_simply_connected())
    return std::nullopt;
  return 12 * static_cast<long long>(domain.number_of_interior_vertices()) +
         10 * static_cast<long long>(domain.number_of_boundary_vertices()) - 9 +
         static_cast<long long>(spline.singular_vertices().size());
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the dimension of the space \f$S^1_5\f$ of C^1 piecewise quintics over
  `domain`, computed independently of the prescription scheme: the exact rank of the C^1
  conditions (3.5) of every interior edge, written on the shared control-point slots (which
  build in C^0), subtracted from the number of slots.

  The domain is converted to exact rationals first (exactly), so the result is exact for
  any kernel. The elimination is sparse and exact; its fill-in depends on the
  triangulation. On jittered grids it stays near-linear (measured: 0.2 s for 9800
  triangles, 2.6 s for 100352 triangles); on scattered points with decimal coordinates
  the rationals grow without bound (16 s for 30 points, 11 min for 50): use
  `spline_dimension()` there.
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \returns the dimension of the space \f$S^1_5\f$ of C^1 piecewise quintics over `domain`, computed
  independently of the prescription scheme
*/
template <class GeomTraits>
std::size_t exact_spline_dimension(const Planar_domain<GeomTraits>& input) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  const std::size_t slots = internal::c1_slot_count(domain);
  internal::Sparse_rank<Exact::FT> rank(slots);
  internal::for_each_c1_condition(domain, [&](auto row) { rank.add(std::move(row)); });
  return slots - rank.rank();
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the result of `spline_dimension_upper_bound()`.
*/
struct Dimension_bound {
  std::size_t upper_bound = 0; ///< \f$\dim S^1_5 \le\f$ this
  std::uint64_t prime = 0;     ///< the prime the rank was computed modulo
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns an upper bound of \f$\dim S^1_5\f$ over `domain`: the number of slots minus
  the rank of the C^1 conditions of `exact_spline_dimension()` modulo a prime \f$p <
  2^{31}\f$.

  Reducing modulo \f$p\f$ (a prime dividing no denominator of the conditions) can only lower
  a rank, so the bound is rigorous; it is the dimension unless \f$p\f$ divides one of the
  finitely many minors that make the rational rank, which for a prime near \f$2^{31}\f$
  practically never happens. Together with a lower bound it proves the dimension: every
  assignment of the scheme's free values is a C^1 spline, distinct assignments give
  distinct splines, so \f$\dim S^1_5 \ge\f$ `free_parameter_count()`, and an upper bound
  equal to that count proves both equal. Linear in practice: the elimination runs in
  machine integers, with columns ordered by the vertex each slot belongs to so that the
  fill-in stays near the diagonal (measured on random points: 0.11 s for 10^3, 1.1 s for
  10^4, 12 s for 10^5; grouping the columns by kind instead took 11 s for 10^3 and 265 s
  for 3000).
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \returns an upper bound of \f$\dim S^1_5\f$ over `domain`
*/
namespace internal {

// Primes just below 2^31 for the modular ranks, tried in this order.
constexpr std::uint64_t dimension_primes[] = {2147483629ull, 2147483587ull, 2147483579ull,
                                              2147483563ull, 2147483549ull, 2147483543ull};

// The nullity of the C^1 conditions of the exact `domain` modulo `prime`, or nothing when the
// prime divides a denominator of the conditions (the reduction is then undefined).
template <class Exact>
std::optional<std::size_t> c1_nullity_modulo(const Planar_domain<Exact>& domain,
                                             std::uint64_t prime) {
  using Index = typename Planar_domain<Exact>::Index;
  // Columns in the order of the vertex each slot belongs to (an edge's or a face's smallest
  // vertex): with spatially numbered vertices the matrix is nearly banded, and the
  // elimination's fill-in stays near the diagonal (slots grouped by kind, vertices first,
  // filled it far more: 1000 points took 11 s).
  const std::size_t V = domain.number_of_vertices(), E = domain.number_of_edges();
  const std::size_t slots = c1_slot_count(domain);
  std::vector<std::uint32_t> column(slots);
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(slots);
    for (std::size_t s = 0; s < slots; ++s) {
      std::uint64_t owner;
      if (s < V)
        owner = s;
      else if (s < V + 4 * E)
        owner = domain.edge(Index((s - V) / 4))[0]; // the smaller index first
      else {
        const auto& t = domain.face(Index((s - V - 4 * E) / 6));
        owner = (std::min)({t[0], t[1], t[2]});
      }
      keys[s] = {owner * slots + s, std::uint32_t(s)};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < slots; ++i)
      column[keys[i].second] = std::uint32_t(i);
  }
  const Modular_field field(prime);
  Sparse_rank<std::uint64_t, Modular_field> rank(slots, field);
  bool reducible = true;
  for_each_c1_condition(domain, [&](const auto& row) {
    if (!reducible)
      return;
    typename Sparse_rank<std::uint64_t, Modular_field>::Row reduced;
    for (const auto& [c, value] : row) {
      std::uint64_t v = 0;
      if (!field.reduce(value, v)) {
        reducible = false;
        return;
      }
      if (v != 0)
        reduced.emplace_back(column[c], v);
    }
    std::sort(reduced.begin(), reduced.end());
    rank.add(std::move(reduced));
  });
  if (!reducible)
    return std::nullopt;
  return slots - rank.rank();
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns an upper bound of \f$\dim S^1_5\f$ over `domain`: the number of slots minus
  the rank of the C^1 conditions of `exact_spline_dimension()` modulo a prime \f$p <
  2^{31}\f$.

  Reducing modulo \f$p\f$ (a prime dividing no denominator of the conditions) can only lower
  a rank, so the bound is rigorous; it is the dimension unless \f$p\f$ divides one of the
  finitely many minors that make the rational rank, which for a prime near \f$2^{31}\f$
  practically never happens. `spline_dimension()` pairs it with the proven lower bound.
  Linear in practice: the elimination runs in machine integers, with columns ordered by the
  vertex each slot belongs to so that the fill-in stays near the diagonal (measured on random
  points: 0.11 s for 10^3, 1.1 s for 10^4, 12 s for 10^5; grouping the columns by kind
  instead took 11 s for 10^3 and 265 s for 3000).
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \returns an upper bound of \f$\dim S^1_5\f$ over `domain`
  \throws Invalid_input if every prime tried divides a denominator of the conditions
*/
template <class GeomTraits>
Dimension_bound spline_dimension_upper_bound(const Planar_domain<GeomTraits>& input) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  for (std::uint64_t prime : internal::dimension_primes)
    if (const auto nullity = internal::c1_nullity_modulo(domain, prime))
      return {*nullity, prime};
  throw Invalid_input("spline dimension: every prime tried divides a denominator of the C^1 "
                      "conditions");
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the result of `spline_dimension()`: the two bounds and the arguments that prove them.
*/
struct Dimension_certificate {
  /// the free count of the plan over the exact domain: a lower bound when
  /// `lower_bound_proven`
  std::size_t free_parameters = 0;
  /// every C^1 condition is, exactly, a linear combination of the plan's rules, and the plan
  /// computes every other slot from the free ones: the plan's splines are a space of
  /// C^1 splines of dimension `free_parameters`
  bool lower_bound_proven = false;
  std::size_t upper_bound = 0; ///< \f$\dim S^1_5 \le\f$ this
  /// the prime whose rank gave `upper_bound`, 0 when it is the exact rational rank
  std::uint64_t prime = 0;
  std::size_t primes_tried = 0; ///< moduli tried (a prime can be unlucky, about 1 in \f$p\f$)
  bool rational_rank = false;   ///< `upper_bound` is the exact rank over the rationals
  /// the dimension, when proven: the bounds meet, or the exact rational rank gave it
  std::optional<std::size_t> dimension;
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief proves the dimension of \f$S^1_5\f$ over `domain`, exactly and fast.

  <b>Lower bound.</b> The plan of `C1_quintic_spline` over the exact domain is checked: every
  slot that is not free is computed by exactly one rule from earlier slots, so the splines
  it produces form a space of dimension `free_parameters` (the free values are read back
  unchanged), and every C^1 condition reduces to exactly zero when its slots are replaced by
  their rules, latest first, so each of those splines is C^1. This checks the weights the
  plan computed, in exact rationals; each condition needs a handful of substitutions.

  <b>Upper bound.</b> The rank of the C^1 conditions modulo a prime \f$p\f$ is at most their
  rational rank, so the nullity modulo \f$p\f$ bounds the dimension from above
  (`spline_dimension_upper_bound()`). When it exceeds the proven lower bound, \f$p\f$ may be
  unlucky (it divides a minor of the rank) and the next prime is tried; after
  `internal::dimension_primes` are used up, `rational_fallback` computes the exact rational
  rank (`exact_spline_dimension()`: minutes from 50 scattered points on), whose nullity is the
  dimension.

  Measured on random points (CPU seconds, 2 cores): 10^3 points 0.3 s, 10^4 points 3 s.
  \tparam GeomTraits a model of `Kernel`
  \param input the domain
  \param rational_fallback whether to compute the exact rational rank when no prime proves it
  \returns the bounds, how they were proven, and the dimension when proven
  \throws std::logic_error if a modular upper bound is below the proven lower bound (a bug)
*/
template <class GeomTraits>
Dimension_certificate spline_dimension(const Planar_domain<GeomTraits>& input,
                                       bool rational_fallback = true) {
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  Dimension_certificate result;
  const Planar_domain<Exact> domain = convert_domain<Exact>(input);
  {
    const C1_quintic_spline<Exact> plan(domain);
    result.free_parameters = plan.number_of_free_parameters();
    const internal::Plan_check check = internal::check_plan_implies_c1(plan);
    result.lower_bound_proven = check.valid && check.implies_c1;
  }
  bool bounded = false;
  for (std::uint64_t prime : internal::dimension_primes) {
    ++result.primes_tried;
    const auto nullity = internal::c1_nullity_modulo(domain, prime);
    if (!nullity)
      continue;
    if (!bounded || *nullity < result.upper_bound) {
      result.upper_bound = *nullity;
      result.prime = prime;
      bounded = true;
    }
    if (result.lower_bound_proven && *nullity < result.free_parameters)
      throw std::logic_error("spline dimension: the rank modulo " + std::to_string(prime) +
                             " leaves " + std::to_string(*nullity) +
                             " dimensions, fewer than the proven " +
                             std::to_string(result.free_parameters));
    if (result.lower_bound_proven && *nullity == result.free_parameters) {
      result.dimension = result.free_parameters;
      return result;
    }
  }
  if (rational_fallback) {
    result.upper_bound = exact_spline_dimension(domain);
    result.prime = 0;
    result.rational_rank = true;
    result.dimension = result.upper_bound;
  }
  return result;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_SPLINE_SPACE_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_CERTIFY_H
#define CGAL_TRIANGULAR_SPLINE_CERTIFY_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/continuity.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/exact_join.h>
#include <CGAL/Triangular_spline/internal/named_parameters.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief the named parameters of `certify_continuity()`: `residual_tolerance(double)`,
  `join_conditions(Join_conditions)` and `edge_verdicts(bool)`, each as `f(value)` (starts a
  pack) or `f(value, np)` (appends to `np`), e.g.
  \code
  namespace TSP = CGAL::Triangular_spline::parameters;
  certify_continuity(spline, 1, TSP::residual_tolerance(1e-10));
  certify_continuity(network, 2, TSP::join_conditions(Join_conditions::LAI));
  \endcode
*/
namespace parameters {
#ifndef DOXYGEN_RUNNING // documented in the namespace and in certify_continuity()
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(residual_tolerance, double)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(join_conditions, Join_conditions)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(edge_verdicts, bool)
#endif
} // namespace parameters

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief the verdict on one interior edge of a network.
*/
struct Edge_certificate {
  std::uint32_t edge = 0;                        ///< edge index in the domain
  std::array<std::uint32_t, 2> vertices{{0, 0}}; ///< its two vertices
  /// the largest order \f$l \le k\f$ whose conditions (and those below) hold; -1: not even
  /// \f$C^0\f$ (the boundary curves differ)
  int achieved_order = -1;
  bool holds = false; ///< every condition of order \f$\le k\f$ holds (up to the tolerance)
  /// every difference is zero in the number type (a proof only with an exact number type)
  bool zero = false;
  double residual = 0; ///< largest residual of the conditions, rounded to `double`
  /// \f$\log_{10}\f$ of the largest residual, exact in magnitude even where `residual`
  /// under- or overflows; \f$-\infty\f$ iff `zero`
  double residual_log10 = -std::numeric_limits<double>::infinity();
};

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief a \f$C^k\f$ certificate of a whole network: one verdict per interior edge, as
  returned by `certify_continuity()`.

  `verdict` says what was established: `Certificate_verdict::PROOF` only when the number
  type is exact and every condition holds exactly; `within_tolerance` when every residual
  is at most the tolerance (compared exactly in the number type), and always for `double`
  arithmetic, where a zero residual may be cancelled round-off; `failed` otherwise.
  `certified` is true for the first two.
*/
struct Continuity_certificate {
  int order = 0;      ///< the order \f$k\f$ checked
  bool exact = false; ///< decided with exact arithmetic
  /// which conditions were checked
  Join_conditions conditions = Join_conditions::EXTENSION;
  Certificate_verdict verdict = Certificate_verdict::FAILED; ///< what was established
  bool certified = false;  ///< every interior edge meets \f$C^k\f$ up to the tolerance
  double tolerance = 0;    ///< absolute residual tolerance used (0: only exact zeros)
  double max_residual = 0; ///< largest residual over all edges, rounded to `double`
  /// \f$\log_{10}\f$ of the largest residual (see `Edge_certificate::residual_log10`)
  double max_residual_log10 = -std::numeric_limits<double>::infinity();
  /// the lowest order met by an edge (\f$k\f$ when certified, -1 if some edge is not even
  /// \f$C^0\f$); \f$k\f$ for a domain without interior edges
  int lowest_order = 0;
  std::size_t interior_edges = 0;      ///< number of interior edges checked
  std::size_t failed_edges = 0;        ///< number of interior edges below \f$C^k\f$
  std::size_t nonzero_edges = 0;       ///< number of interior edges with a nonzero residual
  std::vector<Edge_certificate> edges; ///< per interior edge, in edge order
};

namespace internal {
// The edges certify_continuity() checks at a time without edge verdicts (10 MB of them;
// tests take fewer).
inline std::size_t& certificate_block() {
  static std::size_t edges = std::size_t(1) << 18;
  return edges;
}
} // namespace internal

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief certifies that the patches of `network` join with \f$C^k\f$ continuity across every
  interior edge of its domain.

  Each interior edge is checked with `check_join()` (for \f$k = 1\f$ with the default
  conditions: `check_C1_join()`, Xu's conditions (3.4) and (3.5) read directly on the
  control points, the same conditions and residuals at a fraction of the cost, written in the
  frame of the larger of the two triangles: the two forms are equivalent, but in a sliver's
  frame the weights grow like the inverse of its relative height and multiply the round-off
  of its control values). With an exact number type and every condition exactly zero the
  verdict is a proof; a positive tolerance accepts residuals up to it (compared exactly in
  the number type) but never makes a proof; `double` arithmetic never proves. To certify a
  `double` network exactly, convert its patches with `convert_patch()` (exact) and certify
  those.

  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork`
  \tparam NamedParameters a sequence of named parameters
  \param network the patches and their domain
  \param k the order, \f$0 \le k \le\f$ the degree of the patches
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{residual_tolerance}
      \cgalParamDescription{the largest absolute residual accepted (0: only exact zeros)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{join_conditions}
      \cgalParamDescription{which blossom conditions are compared (they differ in what the
      residuals mean, not in the verdict of an exact check)}
      \cgalParamType{`Join_conditions`}
      \cgalParamDefault{`Join_conditions::EXTENSION`}
    \cgalParamNEnd
    \cgalParamNBegin{edge_verdicts}
      \cgalParamDescription{whether the certificate keeps one verdict per interior edge; if
      `false`, `edges` stays empty and the edges are checked a block at a time (the verdicts
      take 40 bytes per edge: 120 MB for \f$10^6\f$ scattered points), the totals the same}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \returns the certificate, one entry per interior edge in edge order (none if
  `edge_verdicts` is `false`)
  \throws Invalid_input if `k` is negative, or two patches across an edge differ in degree or
  `k` exceeds it
*/
template <class TriangularSplineNetwork,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Continuity_certificate
certify_continuity(const TriangularSplineNetwork& network, int k,
                   const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto& domain = network.domain();
  using Index = typename std::decay_t<decltype(domain)>::Index;
  using Geom_traits = typename std::decay_t<decltype(domain)>::Geom_traits;
  // Checked here, not only by check_join(): a network without interior edges calls it never.
  if (k < 0)
    throw Invalid_input("certify: continuity order " + std::to_string(k) + " is negative");
  const double tolerance =
      choose_parameter(get_parameter(np, internal_np::residual_tolerance), 0.0);
  const Join_conditions conditions =
      choose_parameter(get_parameter(np, internal_np::join_conditions), Join_conditions::EXTENSION);

  Continuity_certificate certificate;
  certificate.order = k;
  certificate.conditions = conditions;
  certificate.exact = CGAL::Algebraic_structure_traits<typename Geom_traits::FT>::Is_exact::value;
  certificate.tolerance = tolerance > 0 ? tolerance : 0;
  certificate.lowest_order = k;
  // Slot networks of degree 5 (C1_quintic_spline) with heights: exact ones are decided on
  // the slots by internal::fast_exact_C1_join(), an exact test without patches or gcds (its
  // determinants in integers where internal::integer_points() can scale the coordinates);
  // double ones get the full check's residuals read on the slots
  // (internal::fast_double_C1_join()). Only the edges these leave open go through
  // check_C1_join() on two patches.
  using Network = TriangularSplineNetwork;
  constexpr bool slot_values = [] {
    if constexpr (internal::has_slot_values<Network>::value)
      return std::is_same_v<std::decay_t<decltype(std::declval<const Network&>().value(0u))>,
                            typename Geom_traits::FT>;
    else
      return false;
  }();
  constexpr bool exact_type =
      CGAL::Algebraic_structure_traits<typename Geom_traits::FT>::Is_exact::value;
  constexpr bool fast_exact = slot_values && exact_type;
  constexpr bool fast_double = slot_values && !exact_type;
  bool use_fast = false;
  if constexpr (fast_exact || fast_double)
    use_fast = k == 1 && conditions == Join_conditions::EXTENSION && network.degree() == 5;
  // The points in integers for the fast exact test, where their denominators allow.
  internal::Integer_points points;
  if constexpr (fast_exact)
    if (use_fast)
      points = internal::integer_points(domain);
  // The edges are independent: checked on all cores (exact checks only on the fast path, the
  // others allocate), the verdicts collected in edge order.
  auto check = [&](Index e, Edge_certificate& c) {
    const auto& ef = domain.edge_faces(e);
    if constexpr (fast_exact) {
      if (use_fast &&
          internal::fast_exact_C1_join(network, e, &points) == internal::Fast_join::ZERO) {
        c.edge = e;
        c.vertices = {{domain.edge(e)[0], domain.edge(e)[1]}};
        c.achieved_order = 1;
        c.holds = c.zero = true;
        return;
      }
    }
    if constexpr (fast_double) {
      if (use_fast && internal::fast_double_C1_join(network, e, certificate.tolerance, c))
        return;
    }
    const Join_report report =
        k == 1 && conditions == Join_conditions::EXTENSION
            ? internal::check_C1_join_in_larger_frame(network.patch(ef[0]), network.patch(ef[1]),
                                                      certificate.tolerance)
            : check_join(network.patch(ef[0]), network.patch(ef[1]), k, conditions,
                         certificate.tolerance);
    c.edge = e;
    c.vertices = {{domain.edge(e)[0], domain.edge(e)[1]}};
    c.achieved_order = report.achieved_order;
    c.holds = report.holds;
    c.residual = report.max_residual;
    c.residual_log10 = report.max_residual_log10;
    c.zero = std::all_of(report.conditions.begin(), report.conditions.end(),
                         [](const Join_condition& j) { return j.zero; });
  };
  auto count = [&](const Edge_certificate& c) {
    if (!(c.residual <= certificate.max_residual))
      certificate.max_residual = c.residual;
    if (!(c.residual_log10 <= certificate.max_residual_log10))
      certificate.max_residual_log10 = c.residual_log10;
    certificate.lowest_order = (std::min)(certificate.lowest_order, c.achieved_order);
    if (!c.holds)
      ++certificate.failed_edges;
    if (!c.zero)
      ++certificate.nonzero_edges;
    ++certificate.interior_edges;
  };
  // Exact edges cost a thousand times a double one, more with the long fractions of the
  // local fits (half a millisecond an edge at 3000 points): all cores from 500 edges, in
  // blocks of 64 (a block of 1024 left one core idle for most of a small spline).
  const std::size_t threads = certificate.exact && !use_fast
                                  ? 1
                                  : internal::thread_count(domain.number_of_interior_edges(),
                                                           certificate.exact ? 500 : 20000);
  const std::size_t parallel_block = certificate.exact ? 64 : internal::parallel_block;
  // All verdicts at once, or blocks of edges (counted in edge order all the same).
  const bool keep = choose_parameter(get_parameter(np, internal_np::edge_verdicts), true);
  const std::size_t block = keep ? domain.number_of_edges() : internal::certificate_block();
  std::vector<Index> interior;
  std::vector<Edge_certificate> verdicts;
  for (std::size_t first = 0; first < domain.number_of_edges(); first += block) {
    const std::size_t last = (std::min)(domain.number_of_edges(), first + block);
    interior.clear();
    for (std::size_t e = first; e < last; ++e)
      if (!domain.is_boundary_edge(static_cast<Index>(e)))
        interior.push_back(static_cast<Index>(e));
    std::vector<Edge_certificate>& out = keep ? certificate.edges : verdicts;
    out.assign(interior.size(), Edge_certificate());
    internal::parallel_for_index(
        interior.size(), threads, [&](std::size_t i) { check(interior[i], out[i]); },
        parallel_block);
    for (const Edge_certificate& c : out)
      count(c);
  }
  certificate.certified = certificate.failed_edges == 0;
  certificate.verdict =
      certificate_verdict(certificate.exact, certificate.failed_edges, certificate.nonzero_edges);
  return certificate;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_CERTIFY_H

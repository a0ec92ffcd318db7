// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_CERTIFY_H
#define CGAL_TRIANGULAR_SPLINE_CERTIFY_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

namespace internal {

// A residual for people: the double, or 10^x when the double under- or overflowed.
inline std::string residual_text(double residual, double log10) {
  std::ostringstream out;
  if (std::isinf(log10) && log10 < 0)
    out << 0;
  else if (!(residual >= 1e-300 && residual <= 1e300) && std::isfinite(log10)) {
    // mantissa and exponent from the exact magnitude: 2e-500, not 0
    const double exponent = std::floor(log10);
    out << std::setprecision(3) << std::pow(10.0, log10 - exponent) << "e" << exponent
        << " (outside double's range)";
  } else
    out << residual;
  return out.str();
}

inline std::string json_number(double x) {
  if (!std::isfinite(x))
    return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the verdict on one interior edge of a spline.
*/
struct Edge_certificate {
  std::uint32_t edge = 0;    ///< edge index in the domain
  std::uint32_t vertices[2]; ///< its two vertices
  bool c0 = false;           ///< the boundary curves agree (Xu 3.4)
  bool c1 = false;           ///< the C^1 conditions (3.4) and (3.5) hold (up to the tolerance)
  /// every difference is zero in the number type (a proof only with an exact number type)
  bool zero = false;
  double residual = 0; ///< largest residual of those conditions, rounded to `double`
  /// \f$\log_{10}\f$ of the largest residual, exact in magnitude even where `residual`
  /// under- or overflows; \f$-\infty\f$ iff `zero`
  double residual_log10 = -std::numeric_limits<double>::infinity();
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief a C^1 certificate of a whole spline: one verdict per interior edge.

  `verdict` says what was established: `Certificate_verdict::proof` only when the number
  type is exact and every condition holds exactly; `within_tolerance` when every residual
  is at most the tolerance given to `certify_C1()` (compared exactly in the number type),
  and always for `double` arithmetic, where a zero residual may be cancelled round-off;
  `failed` otherwise. `certified` is true for the first two.
*/
struct C1_certificate {
  bool exact = false;                                        ///< decided with exact arithmetic
  Certificate_verdict verdict = Certificate_verdict::failed; ///< what was established
  bool certified = false;  ///< every interior edge is C^1 up to the tolerance
  double tolerance = 0;    ///< tolerance used (0: only exact zeros)
  double max_residual = 0; ///< largest residual over all edges, rounded to `double`
  /// \f$\log_{10}\f$ of the largest residual (see `Edge_certificate::residual_log10`)
  double max_residual_log10 = -std::numeric_limits<double>::infinity();
  std::size_t interior_edges = 0;      ///< number of interior edges checked
  std::size_t failed_edges = 0;        ///< number of interior edges that are not C^1
  std::size_t nonzero_edges = 0;       ///< number of interior edges with a nonzero residual
  double seconds = 0;                  ///< time taken
  std::vector<Edge_certificate> edges; ///< per interior edge, in edge order

  /// returns a short human-readable summary (several lines), naming up to 10 failing edges
  std::string summary() const {
    std::ostringstream out;
    if (verdict == Certificate_verdict::proof)
      out << "C^1 certificate (exact rational arithmetic): PASSED (a proof: every condition "
             "holds exactly)\n";
    else if (!exact)
      out << "C^1 check (double, residual tolerance " << tolerance
          << ", not a proof): " << (certified ? "passed" : "FAILED") << "\n";
    else if (certified)
      out << "C^1 check (exact residuals, tolerance " << tolerance
          << "): within the tolerance, NOT a proof (" << nonzero_edges << " of " << interior_edges
          << " edges are not exactly C^1)\n";
    else {
      out << "C^1 certificate (exact rational arithmetic";
      if (tolerance > 0)
        out << ", tolerance " << tolerance;
      out << "): FAILED\n";
    }
    out << "  verdict: " << verdict_name(verdict) << "; interior edges checked: " << interior_edges
        << ", failed: " << failed_edges << "\n"
        << "  largest residual: " << internal::residual_text(max_residual, max_residual_log10)
        << "\n";
    std::size_t named = 0;
    for (const Edge_certificate& e : edges)
      if (!e.c1 && named++ < 10)
        out << "  edge " << e.edge << " (" << e.vertices[0] << ", " << e.vertices[1]
            << "): " << (e.c0 ? "C^0 holds, C^1 fails" : "not even C^0") << ", residual "
            << internal::residual_text(e.residual, e.residual_log10) << "\n";
    return out.str();
  }

  /// returns the certificate as a JSON object; per-edge results are listed for all edges
  /// when `all_edges`, otherwise for the failing ones only. `certified_c1` is true only for
  /// a proof; `residual_log10` is null for an exact zero.
  std::string json(bool all_edges = false) const {
    using internal::json_number;
    std::ostringstream out;
    out << "{\"exact\": " << (exact ? "true" : "false") << ", \"verdict\": \""
        << verdict_name(verdict)
        << "\", \"certified_c1\": " << (verdict == Certificate_verdict::proof ? "true" : "false")
        << ", \"within_tolerance\": " << (certified ? "true" : "false")
        << ", \"tolerance\": " << json_number(tolerance)
        << ", \"max_c1_residual\": " << json_number(max_residual)
        << ", \"max_c1_residual_log10\": " << json_number(max_residual_log10)
        << ", \"interior_edges\": " << interior_edges << ", \"failed_edges\": " << failed_edges
        << ", \"nonzero_edges\": " << nonzero_edges << ", \"seconds\": " << json_number(seconds)
        << ", \"edges\": [";
    bool first = true;
    for (const Edge_certificate& e : edges) {
      if (!all_edges && e.c1)
        continue;
      out << (first ? "" : ", ") << "{\"edge\": " << e.edge << ", \"vertices\": [" << e.vertices[0]
          << ", " << e.vertices[1] << "], \"c0\": " << (e.c0 ? "true" : "false")
          << ", \"c1\": " << (e.c1 ? "true" : "false")
          << ", \"zero\": " << (e.zero ? "true" : "false")
          << ", \"residual\": " << json_number(e.residual)
          << ", \"residual_log10\": " << json_number(e.residual_log10) << "}";
      first = false;
    }
    out << "]}";
    return out.str();
  }
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief certifies that the patches over `domain` join with C^1 continuity across every
  interior edge, checking Xu's conditions (3.4) and (3.5) on the control points
  (`check_C1_join()`).

  Works for any source of patches: a `C1_quintic_spline`, patches read from a file, or
  patches built by other means (any degree). With an exact number type and every condition
  exactly zero the verdict is a proof (`Certificate_verdict::proof`); a positive `tolerance`
  accepts residuals up to it (compared exactly) but never makes a proof. To certify a
  `double` spline exactly, convert its patches with `convert_patch()` (exact) and certify
  those.

  \param domain the triangulated domain of the patches
  \param patch a callable `patch(f)` returning the `Bezier_triangle` of face `f`
  \param tolerance largest absolute residual accepted (0: only exact zeros)
*/
template <class GeomTraits, class PatchSource>
C1_certificate certify_C1(const Planar_domain<GeomTraits>& domain, const PatchSource& patch,
                          double tolerance = 0) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  const auto start = std::chrono::steady_clock::now();
  C1_certificate certificate;
  certificate.exact = CGAL::Algebraic_structure_traits<typename GeomTraits::FT>::Is_exact::value;
  certificate.tolerance = tolerance > 0 ? tolerance : 0;
  certificate.edges.reserve(domain.number_of_interior_edges());
  for (Index e = 0; e < domain.number_of_edges(); ++e) {
    if (domain.is_boundary_edge(e))
      continue;
    const auto& ef = domain.edge_faces(e);
    const Join_report report = check_C1_join(patch(ef[0]), patch(ef[1]), certificate.tolerance);
    Edge_certificate c;
    c.edge = e;
    c.vertices[0] = domain.edge(e)[0];
    c.vertices[1] = domain.edge(e)[1];
    c.c0 = report.achieved_order >= 0;
    c.c1 = report.holds;
    c.residual = report.max_residual;
    c.residual_log10 = report.max_residual_log10;
    c.zero = std::all_of(report.conditions.begin(), report.conditions.end(),
                         [](const Join_condition& j) { return j.zero; });
    if (!(c.residual <= certificate.max_residual))
      certificate.max_residual = c.residual;
    if (!(c.residual_log10 <= certificate.max_residual_log10))
      certificate.max_residual_log10 = c.residual_log10;
    if (!c.c1)
      ++certificate.failed_edges;
    if (!c.zero)
      ++certificate.nonzero_edges;
    certificate.edges.push_back(c);
  }
  certificate.interior_edges = certificate.edges.size();
  certificate.certified = certificate.failed_edges == 0;
  certificate.verdict =
      certificate_verdict(certificate.exact, certificate.failed_edges, certificate.nonzero_edges);
  certificate.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return certificate;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_CERTIFY_H

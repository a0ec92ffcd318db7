// Reports for people: the text summary of a continuity certificate. The library returns
// the numbers (CGAL::Triangular_spline::certify_continuity()); wording lives here.

#ifndef TSPLINE_REPORT_H
#define TSPLINE_REPORT_H

#include "cli.h"

#include <CGAL/Triangular_spline/certify.h>

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>

namespace tspline {

// A residual: the double, or its magnitude as 10^x when the double under- or overflowed
// (printed as 2e-500, not 0).
inline std::string residual_text(double residual, double log10) {
  std::ostringstream out;
  if (std::isinf(log10) && log10 < 0)
    out << 0;
  else if (!(residual >= 1e-300 && residual <= 1e300) && std::isfinite(log10)) {
    const double exponent = std::floor(log10);
    out << std::setprecision(3) << std::pow(10.0, log10 - exponent) << "e" << exponent
        << " (outside double's range)";
  } else
    out << residual;
  return out.str();
}

// Several lines: what was established, the counts, the largest residual, and up to 10
// failing edges.
inline std::string certificate_summary(const CGAL::Triangular_spline::Continuity_certificate& c) {
  using CGAL::Triangular_spline::Certificate_verdict;
  const std::string order = "C^" + std::to_string(c.order);
  std::ostringstream out;
  if (c.verdict == Certificate_verdict::PROOF)
    out << order
        << " certificate (exact rational arithmetic): PASSED (a proof: every condition "
           "holds exactly)\n";
  else if (!c.exact)
    out << order << " check (double, residual tolerance " << c.tolerance
        << ", not a proof): " << (c.certified ? "passed" : "FAILED") << "\n";
  else if (c.certified)
    out << order << " check (exact residuals, tolerance " << c.tolerance
        << "): within the tolerance, NOT a proof (" << c.nonzero_edges << " of " << c.interior_edges
        << " edges are not exactly " << order << ")\n";
  else {
    out << order << " certificate (exact rational arithmetic";
    if (c.tolerance > 0)
      out << ", tolerance " << c.tolerance;
    out << "): FAILED\n";
  }
  out << "  verdict: " << CGAL::Triangular_spline::verdict_name(c.verdict)
      << "; interior edges checked: " << c.interior_edges << ", failed: " << c.failed_edges << "\n"
      << "  largest residual: " << residual_text(c.max_residual, c.max_residual_log10) << "\n";
  std::size_t named = 0;
  for (const auto& e : c.edges)
    if (!e.holds && named++ < 10) {
      out << "  edge " << e.edge << " (" << e.vertices[0] << ", " << e.vertices[1] << "): ";
      if (e.achieved_order < 0)
        out << "not even C^0";
      else
        out << "C^" << e.achieved_order << " holds, " << order << " fails";
      out << ", residual " << residual_text(e.residual, e.residual_log10) << "\n";
    }
  return out.str();
}

// The C^1 verdict of a built spline in a report. `certified_c1` is a proof: exact builds
// only; double builds report the tolerance check.
inline void set_c1_certificate(Json& report,
                               const CGAL::Triangular_spline::Continuity_certificate& c) {
  report["verdict"] = CGAL::Triangular_spline::verdict_name(c.verdict);
  report["certified_c1"] = c.verdict == CGAL::Triangular_spline::Certificate_verdict::PROOF;
  report["certificate_exact"] = c.exact;
  report["c1_within_tolerance"] = c.certified;
  report["c1_tolerance"] = c.tolerance;
  report["max_c1_residual"] = c.max_residual;
  report["failed_edges"] = c.failed_edges;
}

} // namespace tspline

#endif // TSPLINE_REPORT_H

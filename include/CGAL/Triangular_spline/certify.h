// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_CERTIFY_H
#define CGAL_TRIANGULAR_SPLINE_CERTIFY_H

#include <CGAL/Triangular_spline/Planar_domain.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the verdict on one interior edge of a spline.
*/
struct Edge_certificate {
  std::uint32_t edge = 0;    ///< edge index in the domain
  std::uint32_t vertices[2]; ///< its two vertices
  bool c0 = false;           ///< the boundary curves agree (Xu 3.4)
  bool c1 = false;           ///< the C^1 conditions (3.4) and (3.5) hold
  double residual = 0;       ///< largest residual of those conditions
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief a C^1 certificate of a whole spline: one verdict per interior edge.

  With an exact number type `certified` is a proof (every condition holds exactly); with
  `double` a condition holds when its residual is at most the tolerance given to
  `certify_C1()` (0 by default, so round-off shows as failure: read `max_residual`).
*/
struct C1_certificate {
  bool exact = false;                  ///< decided with exact arithmetic
  bool certified = false;              ///< every interior edge is C^1
  double tolerance = 0;                ///< tolerance used (0 for exact)
  double max_residual = 0;             ///< largest residual over all edges
  std::size_t interior_edges = 0;      ///< number of interior edges checked
  std::size_t failed_edges = 0;        ///< number of interior edges that are not C^1
  double seconds = 0;                  ///< time taken
  std::vector<Edge_certificate> edges; ///< per interior edge, in edge order

  /// returns a short human-readable summary (several lines), naming up to 10 failing edges
  std::string summary() const {
    std::ostringstream out;
    if (exact)
      out << "C^1 certificate (exact rational arithmetic): " << (certified ? "PASSED" : "FAILED")
          << "\n";
    else
      out << "C^1 check (double, residual tolerance " << tolerance
          << ", not a proof): " << (certified ? "passed" : "FAILED") << "\n";
    out << "  interior edges checked: " << interior_edges << ", failed: " << failed_edges << "\n"
        << "  largest residual: " << max_residual << "\n";
    std::size_t named = 0;
    for (const Edge_certificate& e : edges)
      if (!e.c1 && named++ < 10)
        out << "  edge " << e.edge << " (" << e.vertices[0] << ", " << e.vertices[1]
            << "): " << (e.c0 ? "C^0 holds, C^1 fails" : "not even C^0") << ", residual "
            << e.residual << "\n";
    return out.str();
  }

  /// returns the certificate as a JSON object; per-edge results are listed for all edges
  /// when `all_edges`, otherwise for the failing ones only
  std::string json(bool all_edges = false) const {
    std::ostringstream out;
    out << "{\"exact\": " << (exact ? "true" : "false")
        << ", \"certified_c1\": " << (certified ? "true" : "false")
        << ", \"tolerance\": " << number(tolerance)
        << ", \"max_c1_residual\": " << number(max_residual)
        << ", \"interior_edges\": " << interior_edges << ", \"failed_edges\": " << failed_edges
        << ", \"seconds\": " << number(seconds) << ", \"edges\": [";
    bool first = true;
    for (const Edge_certificate& e : edges) {
      if (!all_edges && e.c1)
        continue;
      out << (first ? "" : ", ") << "{\"edge\": " << e.edge << ", \"vertices\": [" << e.vertices[0]
          << ", " << e.vertices[1] << "], \"c0\": " << (e.c0 ? "true" : "false")
          << ", \"c1\": " << (e.c1 ? "true" : "false") << ", \"residual\": " << number(e.residual)
          << "}";
      first = false;
    }
    out << "]}";
    return out.str();
  }

private:
  static std::string number(double x) {
    if (!std::isfinite(x))
      return "null";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
  }
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief certifies that the patches over `domain` join with C^1 continuity across every
  interior edge, checking Xu's conditions (3.4) and (3.5) on the control points
  (`check_C1_join()`).

  Works for any source of patches: a `C1_quintic_spline`, patches read from a file, or
  patches built by other means (any degree). With an exact number type the verdict is a
  proof; to certify a `double` spline exactly, convert its patches with `convert_patch()`
  (exact) and certify those.

  \param domain the triangulated domain of the patches
  \param patch a callable `patch(f)` returning the `Bezier_triangle` of face `f`
  \param tolerance for inexact number types: residual accepted as zero
*/
template <class GeomTraits, class PatchSource>
C1_certificate certify_C1(const Planar_domain<GeomTraits>& domain, const PatchSource& patch,
                          double tolerance = 0) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  const auto start = std::chrono::steady_clock::now();
  C1_certificate certificate;
  certificate.exact = CGAL::Algebraic_structure_traits<typename GeomTraits::FT>::Is_exact::value;
  certificate.tolerance = certificate.exact ? 0 : tolerance;
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
    if (!(c.residual <= certificate.max_residual))
      certificate.max_residual = c.residual;
    if (!c.c1)
      ++certificate.failed_edges;
    certificate.edges.push_back(c);
  }
  certificate.interior_edges = certificate.edges.size();
  certificate.certified = certificate.failed_edges == 0;
  certificate.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return certificate;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_CERTIFY_H

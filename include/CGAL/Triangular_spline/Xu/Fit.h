// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_FIT_H
#define CGAL_TRIANGULAR_SPLINE_XU_FIT_H

#include <array>
#include <string>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief how the free control points of a `C1_quintic_spline` are set from data at the
  vertices.
*/
enum class Fit {
  /// every free point is the polar-value blend of its patch's corner data,
  /// \f$f(a^i b^j c^k) \approx (i z_a + j z_b + k z_c)/5\f$ (Xu §7.3, §6.2.4); with
  /// `Corner_frame::SYMMETRIC_STARS` the corners are propagated: the spline approximates
  APPROXIMATE,
  /// as `APPROXIMATE`, and every corner point is prescribed to the data value (Xu §4.4.2);
  /// needs `Corner_frame::CORNER_AND_TWO_STARS`
  INTERPOLATE,
  /// interpolation of values and of gradients estimated at every vertex (least squares over
  /// its neighbours): each free point takes the tangent-plane value of its nearest corner
  /// (averaged on ties), at its domain point, the degree-1 case of Mann's nearest-vertex
  /// rule; this tilts the corner frames along the data (Xu §4.4.5) instead of
  /// flattening them. Needs `Corner_frame::CORNER_AND_TWO_STARS`
  TANGENT_PLANES,
  /// interpolation of the values; the other free points are chosen so that ALL control
  /// points (free and propagated) are as close as possible, in least squares, to the
  /// `TANGENT_PLANES` targets: every control value is a linear function of the free ones.
  /// This is the remedy for the amplification of Xu §4.4.5: thin frames propagate with large
  /// weights, and the least-squares choice keeps the propagated points near the data
  /// instead of letting them overshoot. The targets are those of `LOCAL_POLYNOMIAL`. The
  /// minimiser is global: one sparse Cholesky factorization (Eigen) up to 40000 unknowns
  /// (about 3600 vertices), beyond conjugate gradients on the normal equations
  /// \f$N x = b\f$ (preconditioned by the inverses of \f$N\f$'s blocks of the unknowns of
  /// one vertex, starting from the targets) until the residual \f$|b - N x|_2\f$ is within
  /// 1e-8 of the data range; since \f$N \succeq I\f$ that bounds every free value's distance
  /// from the minimiser. Linear time (10 to 40 iterations at \f$10^5\f$ random points) and
  /// memory. The solve runs in `double`; the free values are then converted to `FT` and
  /// propagated in `FT`, so an exact spline is still exactly C^1 (linear data is then
  /// reproduced up to the solve's rounding). Needs `Corner_frame::CORNER_AND_TWO_STARS`
  LEAST_SQUARES,
  /// interpolation of the values; every free point takes the polar value of the local
  /// polynomial (`Local_polynomials`, degree 3 by default) of its nearest corner, averaged
  /// on ties. All points of a corner region, and every corner-inner and edge-middle point,
  /// then come from one polynomial, so propagation through them reproduces it whatever its
  /// weights; only flip points and re-routed edge points mix the polynomials of
  /// neighbouring vertices. A polynomial is not read far from its data: where a label's
  /// vertex lies more than four fit radii (`Local_polynomials::radius()`) from the
  /// polynomial's vertex and the polynomial misses its data value by more than
  /// \f$10^{-2}\f$ of the data range, the target moves toward the polar value of the
  /// piecewise linear interpolant, wholly at eight radii and \f$10^{-1}\f$ (the slivers
  /// under the long hull edges of random points read polynomials of radius 0.01 at 0.5:
  /// `Fit_statistics::vertices_beyond_reach`; smooth and polynomial data keep theirs). Data
  /// from a polynomial of degree at most the local degree are reproduced exactly (exactly
  /// with an exact number type); local in time and memory. Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  LOCAL_POLYNOMIAL,
  /// interpolation of the values with the least thin-plate energy
  /// \f$\int f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2\f$ over the whole spline space (exact Bernstein
  /// Gram matrices, `thin_plate_energy_matrix()`; the sparse normal equations are solved in
  /// `double` and the free values converted to `FT`, as for `LEAST_SQUARES`): the fairest
  /// interpolant, Xu §8.3's open problem; the spline analogue of a thin-plate spline. Thin
  /// triangles (shape quality \f$q = 4\sqrt{3}\,\mathrm{area} / \sum \mathrm{edge}^2 < 0.1\f$)
  /// count with weight \f$(q/0.1)^3\f$: their energy grows as the inverse cube of their
  /// thinness, and at full weight the thin triangles along the hull of scattered data would
  /// dominate the solve and bend the surface around them. With
  /// a positive `smoothing` \f$\lambda\f$ it no longer interpolates but minimises
  /// \f$\sum_v (s(v) - z_v)^2 + \lambda h^2 E(s)\f$, \f$h^2\f$ the domain's area per
  /// vertex, for noisy data. Reproduces linear data exactly (up to the solve's rounding in
  /// exact builds). The global minimiser: one sparse Cholesky factorization up to 40000
  /// unknowns (about 3600 vertices); beyond, sweeps of overlapping windows (block
  /// Gauss-Seidel: cells of about 500 vertices with two rings of margin, three with
  /// smoothing, each window's energy minimised exactly with the other unknowns at their
  /// current values, the first sweep starting from the `LOCAL_POLYNOMIAL` values). Every
  /// window solve lowers the energy and the sweeps converge to the global minimiser; they
  /// stop when one moves no control value by more than 1e-8 of the data range (with three
  /// rings, two sweeps were
  /// 1.2e-8 from the direct solve on 20000 noisy random points, 3e-5 with smoothing 0.1;
  /// two rings to the tolerance are 4.2e-10 from three at \f$10^5\f$ random points).
  /// Linear time (about 0.13 ms per vertex and sweep), memory bounded by a window. Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  MINIMAL_ENERGY,
  /// interpolation of the values; `LOCAL_POLYNOMIAL` where the local polynomials resolve the
  /// data, `MINIMAL_ENERGY` where they do not, blended in between: the most accurate fit on
  /// dense smooth data and on sparse or rough data alike. Each vertex's resolution
  /// \f$\rho_v\f$ (`Local_polynomials::resolution()`, the leave-one-out residual of its
  /// polynomial relative to a plane's) gives a trust \f$\tau_v\f$: 1 for \f$\rho_v \le 0.1\f$,
  /// 0 for \f$\rho_v \ge 0.5\f$, linear between; where some vertex is below 1 (an energy
  /// solve runs), at most 1 minus the pull of its targets along its edges (see
  /// `LOCAL_POLYNOMIAL`: 0 within four fit radii, 1 beyond eight where the polynomial misses
  /// the data), so that the slivers under long hull edges are decided by the energy solve,
  /// not by polynomials read far from their data
  /// (`benchmark/hull_strip.py`, \f$10^5\f$ random points of a terrain-like function:
  /// largest error within \f$10^{-3}\f$ of the sides 4.90 before, 0.80 now, scipy CT
  /// 1.05). Free points whose nearest vertices are all
  /// trusted take their local value (exactly as `LOCAL_POLYNOMIAL`); the others are chosen by
  /// least energy over the untrusted vertices and one ring around them: the thin-plate
  /// energy plus a tension \f$(2 (1 - \bar\tau_f) / h^2) \int_f |\nabla s - \nabla g|^2\f$
  /// per face \f$f\f$ (\f$\bar\tau_f\f$ its vertices' mean trust, \f$h^2\f$ the area per
  /// vertex, \f$g\f$ the piecewise linear interpolant of the data), which pulls data that no
  /// polynomial resolves toward \f$g\f$ and vanishes on linear data (TOMS 792's sparse node
  /// sets: 3% to 7% lower SSE/SSM than the thin plate alone). With
  /// the local values beyond as boundary values (the margin keeps the kinks of local values
  /// in thin boundary triangles, tiny in value but huge in energy, from bending the surface
  /// next to them), then each nearest vertex's share
  /// becomes \f$\tau_v\f$ times its polynomial's value plus \f$1-\tau_v\f$ times the energy
  /// value. Data from a polynomial of degree at most the local degree leave every vertex
  /// trusted and are reproduced exactly, as by `LOCAL_POLYNOMIAL`. The energy solve is that
  /// of `MINIMAL_ENERGY` over the untrusted region (direct, or two sweeps of windows beyond
  /// 40000 unknowns), linear in its size and never skipped. Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  ADAPTIVE
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief what `fit_vertex_data()` did: the degrees of the local polynomials
  (`LOCAL_POLYNOMIAL`, `LEAST_SQUARES` and `ADAPTIVE` fits, and `MINIMAL_ENERGY` beyond
  40000 unknowns, whose windows start from them; all zero otherwise).
*/
struct Fit_statistics {
  /// `vertices_by_degree[d]`: the number of vertices whose local polynomial has degree `d`
  std::array<std::size_t, 6> vertices_by_degree{};
  /// `ADAPTIVE` fit: the number of vertices whose polynomial is trusted fully (`[0]`),
  /// blended with the minimal-energy values (`[1]`), or not used at all (`[2]`)
  std::array<std::size_t, 3> vertices_by_trust{};
  /// `LOCAL_POLYNOMIAL`, `LEAST_SQUARES` and `ADAPTIVE` fits: the number of vertices with an
  /// edge more than four times as long as their local polynomial's fit radius
  /// (`Local_polynomials::radius()`) at whose far end the polynomial misses the data (see
  /// `Fit::LOCAL_POLYNOMIAL`): the targets it gives there move to the piecewise linear
  /// interpolant, and where the `ADAPTIVE` fit runs an energy solve it distrusts the vertex
  /// as much (the slivers under the long hull edges of random points)
  std::size_t vertices_beyond_reach = 0;
  /// always `false` (kept for compatibility): the `ADAPTIVE` fit's energy solve used to be
  /// skipped beyond \f$10^4\f$ untrusted vertices; it is now linear in their number and
  /// always done
  bool energy_skipped = false;
  /// The global solve of the `MINIMAL_ENERGY` and `LEAST_SQUARES` fits, smoothing, and the
  /// `ADAPTIVE` fit's energy solve: how it was solved (`"direct"`: one sparse Cholesky
  /// factorization, `"windows"`: sweeps of overlapping windows, `"conjugate_gradients"`:
  /// the large least-squares fits; empty when nothing was solved), the sweeps (1 for the
  /// direct solve and conjugate gradients, 0 when there was no solve), the windows per sweep,
  /// the window solves over all sweeps, the conjugate gradients' iterations, the largest
  /// change of a control value in the last sweep (conjugate gradients: the norm of the
  /// residual, a bound on the error of every control value), and whether that met the
  /// solver's tolerance (else the sweeps or iterations stopped at their limit)
  std::string solver_method;
  int solver_sweeps = 0;
  std::size_t solver_windows = 0;
  std::size_t solver_window_solves = 0;
  int solver_iterations = 0;
  double solver_last_change = 0;
  bool solver_converged = true;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_FIT_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H
#define CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/Fit.h>
#include <CGAL/Triangular_spline/Xu/estimate_gradients.h>
#include <CGAL/Triangular_spline/Xu/local_polynomial_fit.h>
#include <CGAL/Triangular_spline/Xu/thin_plate_energy.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/fit_vertex_data.h>
#include <CGAL/Triangular_spline/internal/free_value_solves.h>
#include <CGAL/Triangular_spline/internal/schwarz_solver.h>

#include <array>
#include <optional>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief sets every free control point of `spline` from the data `values` (one per domain
  vertex) according to `fit`, then propagates, and returns what it did.

  Every mode reproduces data sampled from a linear function exactly (every prescribed point
  is then the linear function's polar value, and propagation preserves it; for
  `LOCAL_POLYNOMIAL` and `LEAST_SQUARES` with `local_degree` at least 1).
  `local_degree` is the largest degree of the local polynomials of `LOCAL_POLYNOMIAL`,
  `LEAST_SQUARES` and `ADAPTIVE` (0..5); `selection` how they choose it. `smoothing` (at least
  0) is the \f$\lambda\f$ of `MINIMAL_ENERGY`; 0 interpolates. `given_gradients` (one per
  vertex, or empty to estimate them) are interpolated by every fit but `APPROXIMATE`: each
  star point \f$f(v^4 w)\f$ becomes \f$z_v + \nabla z_v \cdot (w - v)/5\f$, so the spline's
  gradient at every vertex is the given one (exactly with an exact number type); the other
  free points follow the fit. `tension` \f$\tau \ge 0\f$ adds \f$(\tau / h^2) \int |\nabla s -
  \nabla g|^2\f$ to the energy of `MINIMAL_ENERGY` and of `ADAPTIVE`'s energy solve (there
  times each face's mean distrust), \f$g\f$ the piecewise linear interpolant of the data and
  \f$h^2\f$ the area per vertex: larger values pull the surface toward \f$g\f$ (less overshoot,
  less smoothness), 0 is the thin plate alone; it vanishes on linear data. Unset: 2 for
  `ADAPTIVE` (the most accurate on the TOMS 792 tests), 0 for `MINIMAL_ENERGY`.
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \throws Invalid_input if `values` or `given_gradients` has the wrong size or a non-finite
  value, if `smoothing` is negative or not finite or given to another fit than
  `MINIMAL_ENERGY` or with gradients, if `tension` is negative or not finite or given to
  another fit than `ADAPTIVE` and `MINIMAL_ENERGY` (0 is accepted by all) or given
  (positive) with smoothing, if
  gradients are given to `APPROXIMATE`, or if a fit
  other than `APPROXIMATE` is asked of a spline whose corner points are not free.
  \param spline the spline whose free control points are set
  \param values the data values, one per domain vertex
  \param fit the fitting mode
  \param local_degree the largest degree of the local polynomials
  \param selection the rule choosing the degree of each local polynomial
  \param smoothing the weight of the smoothing term
  \param given_gradients the gradients at the vertices, one pair per domain vertex, if given
  \param tension the weight of the tension term, if given
  \returns statistics of what the fit did
*/
template <class GeomTraits, class Value>
Fit_statistics fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline,
                               const std::vector<Value>& values, Fit fit, int local_degree = 3,
                               Degree_selection selection = Degree_selection::CROSS_VALIDATION,
                               double smoothing = 0,
                               const std::vector<std::array<Value, 2>>& given_gradients = {},
                               std::optional<double> tension = std::nullopt) {
  return internal::fit_vertex_data(spline, values, fit, local_degree, selection, smoothing,
                                   given_gradients, internal::Schwarz_options(), nullptr, tension);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_MAKE_C1_QUINTIC_SPLINE_H
#define CGAL_TRIANGULAR_SPLINE_XU_MAKE_C1_QUINTIC_SPLINE_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>
#include <CGAL/Triangular_spline/Xu/local_polynomial_fit.h>
#include <CGAL/Triangular_spline/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <atomic>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the named parameters of `make_c1_quintic_spline()`: `data_fit(Fit)`,
  `local_degree(int)`, `degree_selection(Degree_selection)`, `smoothing(double)`,
  `tension(double)`,
  `vertex_gradients(gradients)` and `fit_statistics(statistics)`, each as `f(value)`
  (starts a pack) or `f(value, np)` (appends to `np`), e.g.
  \code
  namespace TSP = CGAL::Triangular_spline::parameters;
  auto spline = make_c1_quintic_spline(domain, z, TSP::data_fit(Fit::MINIMAL_ENERGY,
                                                                TSP::smoothing(0.1)));
  \endcode
  `vertex_gradients()` and `fit_statistics()` keep a reference to their argument, which must
  outlive the call.
*/
namespace parameters {
#ifndef DOXYGEN_RUNNING // documented in the namespace and in make_c1_quintic_spline()
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(data_fit, Fit)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(local_degree, int)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(degree_selection, Degree_selection)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(smoothing, double)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(tension, double)

// The gradients are large: the pack keeps a reference, as CGAL's own maps are kept.
template <class Value>
Named_function_parameters<std::reference_wrapper<const std::vector<std::array<Value, 2>>>,
                          internal_np::vertex_gradients_t>
vertex_gradients(const std::vector<std::array<Value, 2>>& gradients) {
  return Named_function_parameters<std::reference_wrapper<const std::vector<std::array<Value, 2>>>,
                                   internal_np::vertex_gradients_t>(std::cref(gradients));
}
template <class Value, class T, class Tag, class Base>
Named_function_parameters<std::reference_wrapper<const std::vector<std::array<Value, 2>>>,
                          internal_np::vertex_gradients_t, Named_function_parameters<T, Tag, Base>>
vertex_gradients(const std::vector<std::array<Value, 2>>& gradients,
                 const Named_function_parameters<T, Tag, Base>& np) {
  return Named_function_parameters<std::reference_wrapper<const std::vector<std::array<Value, 2>>>,
                                   internal_np::vertex_gradients_t,
                                   Named_function_parameters<T, Tag, Base>>(std::cref(gradients),
                                                                            np);
}

inline Named_function_parameters<std::reference_wrapper<Fit_statistics>,
                                 internal_np::fit_statistics_t>
fit_statistics(Fit_statistics& statistics) {
  return Named_function_parameters<std::reference_wrapper<Fit_statistics>,
                                   internal_np::fit_statistics_t>(std::ref(statistics));
}
template <class T, class Tag, class Base>
Named_function_parameters<std::reference_wrapper<Fit_statistics>, internal_np::fit_statistics_t,
                          Named_function_parameters<T, Tag, Base>>
fit_statistics(Fit_statistics& statistics, const Named_function_parameters<T, Tag, Base>& np) {
  return Named_function_parameters<std::reference_wrapper<Fit_statistics>,
                                   internal_np::fit_statistics_t,
                                   Named_function_parameters<T, Tag, Base>>(std::ref(statistics),
                                                                            np);
}
#endif
} // namespace parameters

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the \f$C^1\f$ quintic spline over `domain` fitted to the data `values`
  (one per domain vertex): the one call from a triangulation and heights to a certified
  surface.

  The corner frame follows from the fit: `Fit::APPROXIMATE` propagates the corner points
  (`Corner_frame::SYMMETRIC_STARS`, Xu's scheme), every other fit interpolates them
  (`Corner_frame::CORNER_AND_TWO_STARS`). The free control points are then set by
  `fit_vertex_data()` and propagated. With an exact number type the result is exactly
  \f$C^1\f$ (`certify_continuity(spline, 1)` proves it). The result is that of building the
  spline and calling `fit_vertex_data()`, bit for bit; for the local and adaptive fits one
  more thread fits the first local polynomials while the plan is built, on the time its
  serial stretches leave (`values` must not change during the call).

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (heights) or `GeomTraits::Vector_3` (parametric data)
  \tparam NamedParameters a sequence of named parameters
  \param domain the triangulated domain, copied into the spline
  \param values the data value at each domain vertex
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{data_fit}
      \cgalParamDescription{how the free control points are set (see `Fit`)}
      \cgalParamType{`Fit`}
      \cgalParamDefault{`Fit::ADAPTIVE`, the most accurate}
    \cgalParamNEnd
    \cgalParamNBegin{local_degree}
      \cgalParamDescription{the largest degree of the local polynomials of
      `LOCAL_POLYNOMIAL`, `LEAST_SQUARES` and `ADAPTIVE`}
      \cgalParamType{`int`}
      \cgalParamDefault{`5`}
      \cgalParamExtra{0 to 5; lowered where a neighbourhood does not determine it}
    \cgalParamNEnd
    \cgalParamNBegin{degree_selection}
      \cgalParamDescription{how each vertex's degree is chosen}
      \cgalParamType{`Degree_selection`}
      \cgalParamDefault{`Degree_selection::CROSS_VALIDATION`}
    \cgalParamNEnd
    \cgalParamNBegin{smoothing}
      \cgalParamDescription{the \f$\lambda\f$ of `Fit::MINIMAL_ENERGY` (0 interpolates)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{tension}
      \cgalParamDescription{the weight \f$\tau\f$ of the tension toward the piecewise linear
      interpolant in the energy of `Fit::ADAPTIVE` and `Fit::MINIMAL_ENERGY`
      (`fit_vertex_data()`)}
      \cgalParamType{`double`}
      \cgalParamDefault{2 for `Fit::ADAPTIVE`, 0 for `Fit::MINIMAL_ENERGY`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_gradients}
      \cgalParamDescription{a gradient per vertex to interpolate instead of estimated ones}
      \cgalParamType{`std::vector<std::array<Value, 2>>`}
      \cgalParamDefault{none: estimated where the fit needs them}
    \cgalParamNEnd
    \cgalParamNBegin{fit_statistics}
      \cgalParamDescription{receives what the fit did (degrees, trust)}
      \cgalParamType{`Fit_statistics&`}
      \cgalParamDefault{none}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \returns the fitted and propagated spline
  \throws Invalid_input as `fit_vertex_data()` (wrong sizes, non-finite values, parameters
  that do not apply to the fit)
*/
template <class GeomTraits, class Value,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
C1_quintic_spline<GeomTraits, Value>
make_c1_quintic_spline(Planar_domain<GeomTraits> domain, const std::vector<Value>& values,
                       const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Fit fit = choose_parameter(get_parameter(np, internal_np::data_fit), Fit::ADAPTIVE);
  const int degree = choose_parameter(get_parameter(np, internal_np::local_degree), 5);
  const Degree_selection selection = choose_parameter(
      get_parameter(np, internal_np::degree_selection), Degree_selection::CROSS_VALIDATION);
  const double lambda = choose_parameter(get_parameter(np, internal_np::smoothing), 0.0);
  const auto given_tension = get_parameter(np, internal_np::tension);
  std::optional<double> tension;
  if constexpr (!std::is_same_v<std::decay_t<decltype(given_tension)>,
                                CGAL::internal_np::Param_not_found>)
    tension = given_tension;

  // The local polynomials that the fit reads first are fitted while the plan is built.
  internal::Prefitted_polynomials<GeomTraits, Value> prefit;
  C1_quintic_spline<GeomTraits, Value> spline(
      std::move(domain),
      fit == Fit::APPROXIMATE ? Corner_frame::SYMMETRIC_STARS : Corner_frame::CORNER_AND_TWO_STARS,
      internal::while_planning(
          [&](const Planar_domain<GeomTraits>& d, const std::atomic<bool>& planned) {
            internal::prefit_local_polynomials(d, values, fit, degree, selection,
                                               internal::prefit_vertices(d.number_of_vertices()),
                                               planned, prefit);
          }));
  const auto gradients = get_parameter(np, internal_np::vertex_gradients);
  const auto statistics = get_parameter(np, internal_np::fit_statistics);
  const auto run = [&](const std::vector<std::array<Value, 2>>& given) {
    const Fit_statistics s =
        internal::fit_vertex_data(spline, values, fit, degree, selection, lambda, given,
                                  internal::Schwarz_options(), nullptr, tension, &prefit);
    if constexpr (!std::is_same_v<std::decay_t<decltype(statistics)>,
                                  CGAL::internal_np::Param_not_found>)
      statistics.get() = s;
  };
  if constexpr (std::is_same_v<std::decay_t<decltype(gradients)>,
                               CGAL::internal_np::Param_not_found>)
    run({});
  else
    run(gradients.get());
  return spline;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_MAKE_C1_QUINTIC_SPLINE_H

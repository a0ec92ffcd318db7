// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Triangular_spline {
namespace parameters {

// so that `parameters::default_values()` (and any CGAL parameter) still resolves inside
// CGAL::Triangular_spline, where this namespace hides CGAL::parameters
using namespace CGAL::parameters;

} // namespace parameters

// The tags of our parameters, all in one place as CGAL's are in
// CGAL/STL_Extension/internal/parameters_interface.h: CGAL 5.5's list of parameter names is
// closed, so ours live here and are looked up with CGAL::parameters::get_parameter() like
// CGAL's.
namespace internal_np {

// certify_continuity() (certify.h)
enum residual_tolerance_t { residual_tolerance };
enum join_conditions_t { join_conditions };
enum edge_verdicts_t { edge_verdicts };

// make_c1_quintic_spline() (Xu/make_c1_quintic_spline.h)
enum data_fit_t { data_fit };
enum local_degree_t { local_degree };
enum degree_selection_t { degree_selection };
enum smoothing_t { smoothing };
enum tension_t { tension };
enum vertex_gradients_t { vertex_gradients };
enum fit_statistics_t { fit_statistics };

// Mesh_blending_surface (Blending/blending_parameters.h)
enum blending_order_t { blending_order };
enum blending_variant_t { blending_variant };
enum vertex_surface_method_t { vertex_surface_method };
enum least_squares_degree_t { least_squares_degree };
enum normals_degree_t { normals_degree };
enum least_interpolant_tolerance_t { least_interpolant_tolerance };

} // namespace internal_np
} // namespace Triangular_spline
} // namespace CGAL

// Both forms of a parameter of ours, defined inside CGAL::Triangular_spline::parameters with
// its tag `internal_np::NAME_t`: `NAME(value)` starts a pack, `NAME(value, np)` appends to `np`
// (CGAL 5.5's list of member parameters is closed, so ours cannot be members).
#define CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(NAME, TYPE)                                         \
  inline Named_function_parameters<TYPE, internal_np::NAME##_t> NAME(TYPE value) {                 \
    return Named_function_parameters<TYPE, internal_np::NAME##_t>(value);                          \
  }                                                                                                \
  template <class T, class Tag, class Base>                                                        \
  Named_function_parameters<TYPE, internal_np::NAME##_t, Named_function_parameters<T, Tag, Base>>  \
  NAME(TYPE value, const Named_function_parameters<T, Tag, Base>& np) {                            \
    return Named_function_parameters<TYPE, internal_np::NAME##_t,                                  \
                                     Named_function_parameters<T, Tag, Base>>(value, np);          \
  }

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_NAMED_PARAMETERS_H

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

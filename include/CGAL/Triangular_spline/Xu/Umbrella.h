// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_UMBRELLA_H
#define CGAL_TRIANGULAR_SPLINE_XU_UMBRELLA_H

#include <array>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the umbrella of a vertex \f$v\f$ (AG1.md §2): the in-plane coordinates
  \f$u_{v\to w_i}\f$ of its stars, in the order of `outgoing_ring()`; its centre \f$u_v\f$ is the
  origin and is not stored.

  An umbrella matters only up to a linear map: the relations it induces are invariant.
*/
template <class FT>
using Umbrella = std::vector<std::array<FT, 2>>;

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_UMBRELLA_H

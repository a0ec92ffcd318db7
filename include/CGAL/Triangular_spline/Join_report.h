// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_JOIN_REPORT_H
#define CGAL_TRIANGULAR_SPLINE_JOIN_REPORT_H

#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief one compared pair of blossom values \f$f_B(p^g q^h r^i s^j) - f_A(p^g q^h r^i s^j)\f$.
*/
struct Join_condition {
  int order = 0;       ///< \f$g+h\f$: the number of arguments off the shared edge
  int p_count = 0;     ///< \f$g\f$, copies of A's apex \f$p\f$
  int q_count = 0;     ///< \f$h\f$, copies of B's apex \f$q\f$
  int r_count = 0;     ///< \f$i\f$, copies of the first shared vertex \f$r\f$
  int s_count = 0;     ///< \f$j\f$, copies of the second shared vertex \f$s\f$
  double residual = 0; ///< largest absolute coordinate of the difference (in `double`)
  /// the difference is zero in the number type: a proof with an exact number type, only a
  /// cancellation of rounded values with `double`
  bool zero = false;
  bool satisfied = false; ///< `zero`, or every coordinate within the tolerance
};

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief the outcome of `check_join()`.
*/
struct Join_report {
  int requested_order = 0; ///< the \f$k\f$ asked for
  /// the largest \f$l \le k\f$ such that every condition of order \f$\le l\f$ is satisfied;
  /// -1 if even \f$C^0\f$ fails
  int achieved_order = -1;
  bool holds = false;      ///< `achieved_order >= requested_order`
  double max_residual = 0; ///< largest residual over all conditions checked
  /// \f$\log_{10}\f$ of the largest residual, from the exact differences where `double`
  /// under- or overflows (`log10_magnitude()`): \f$-\infty\f$ iff every difference is zero
  double max_residual_log10 = -std::numeric_limits<double>::infinity();
  bool exact = false; ///< the verdict was decided with an exact number type
  /// local indices (0, 1, 2) in patch A of \f$p, r, s\f$ and in patch B of \f$q, r, s\f$
  std::array<int, 3> a_vertices{{0, 1, 2}}, b_vertices{{0, 1, 2}};
  std::vector<Join_condition> conditions; ///< every condition checked, by increasing order
  /// \var b_vertices
  /// local indices (0, 1, 2) in patch B of \f$q, r, s\f$
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_JOIN_REPORT_H

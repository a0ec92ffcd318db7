// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_CONTINUITY_H
#define CGAL_TRIANGULAR_SPLINE_CONTINUITY_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Join_report.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/join_checks.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/enum.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief which blossom conditions decide a \f$C^k\f$ join of two patches \f$F_A\f$ over
  \f$(p,r,s)\f$ and \f$F_B\f$ over \f$(q,r,s)\f$ (shared edge \f$rs\f$).

  All three sets are necessary and sufficient (Xu, Lemma 3.1.4); they differ in which
  blossom values are compared, i.e. in what the residuals mean.
*/
enum class Join_conditions {
  /// for each order \f$l \le k\f$ and \f$i+j = m-l\f$: \f$f_B(q^l r^i s^j) = f_A(q^l r^i s^j)\f$,
  /// i.e.\ the control points of B next to the edge equal those of A's polynomial extended
  /// over B's triangle. Order 0 is Xu's (3.4), order 1 is (3.5). \f$\sum_l (m-l+1)\f$
  /// conditions, the minimal number.
  EXTENSION,
  /// Lai's construction as rephrased by Mann (eqs. (1), (2)): the same count, but at order
  /// \f$l\f$ the compared blossom values carry \f$\lceil l/2\rceil\f$ copies of \f$q\f$ and
  /// \f$\lfloor l/2\rfloor\f$ of \f$p\f$, the balanced points the averaging adjustment uses.
  LAI,
  /// every multiset \f$p^g q^h r^i s^j\f$ with \f$i + j \ge m - k\f$ (Lemma 3.1.4 verbatim);
  /// redundant, meant for cross-checking.
  COMPLETE
};

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief what a certificate establishes.
*/
enum class Certificate_verdict {
  /// every condition holds exactly, decided in an exact number type: a proof
  PROOF,
  /// every condition holds up to the tolerance (or `double` arithmetic was used): not a proof
  WITHIN_TOLERANCE,
  /// some condition fails, even with the tolerance
  FAILED
};

/// returns `"proof"`, `"within_tolerance"` or `"failed"`
/// \param verdict the verdict
/// \returns `"proof"`, `"within_tolerance"` or `"failed"`
inline const char* verdict_name(Certificate_verdict verdict) {
  switch (verdict) {
  case Certificate_verdict::PROOF:
    return "proof";
  case Certificate_verdict::WITHIN_TOLERANCE:
    return "within_tolerance";
  default:
    return "failed";
  }
}

/// the verdict of a check in which `failed` conditions failed and `nonzero` were not exactly
/// zero; only an exact number type with every condition zero makes a proof
/// \param exact `true` iff the number type is exact
/// \param failed the number of failed conditions
/// \param nonzero the number of conditions not exactly zero
/// \returns the verdict
inline Certificate_verdict certificate_verdict(bool exact, std::size_t failed,
                                               std::size_t nonzero) {
  if (failed > 0)
    return Certificate_verdict::FAILED;
  return exact && nonzero == 0 ? Certificate_verdict::PROOF : Certificate_verdict::WITHIN_TOLERANCE;
}

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief checks whether the patches `A` and `B` over adjacent domain triangles join with
  \f$C^k\f$ continuity along their shared edge (Xu, Lemma 3.1.4; Lai/Mann eqs. (1), (2)).

  The shared edge is found by exact comparison of the domain vertices, and the two apexes
  must lie strictly on opposite sides of it (exact orientation test). Each condition
  compares the blossoms of both patches at the same multiset of points. A condition is
  satisfied when its difference is zero or, for `tolerance > 0`, when every coordinate of
  the difference is at most `tolerance` in absolute value (compared exactly in the number
  type). With an exact number type and `tolerance = 0` the verdict is therefore a proof;
  `Join_condition::zero` tells a proven condition from one accepted by the tolerance.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param A the first patch
  \param B the second patch, of the same degree \f$m\f$ as `A`
  \param k the continuity order, \f$0 \le k \le m\f$
  \param conditions which equivalent set of conditions to evaluate
  \param tolerance absolute tolerance on each coordinate of a difference (0: only zero
  differences satisfy a condition)
  \throws Invalid_input if the degrees differ, `k` is out of range, or the triangles are
  not adjacent across one edge.
  \returns the join report
*/
template <class GeomTraits, class Value>
Join_report
check_join(const Bezier_triangle<GeomTraits, Value>& A, const Bezier_triangle<GeomTraits, Value>& B,
           int k, Join_conditions conditions = Join_conditions::EXTENSION, double tolerance = 0) {
  using FT = typename GeomTraits::FT;
  using Weights = typename Bezier_triangle<GeomTraits, Value>::Weights;
  const int m = A.degree();
  if (B.degree() != m)
    throw Invalid_input("join test: degree mismatch (" + std::to_string(m) + " and " +
                        std::to_string(B.degree()) + ")");
  if (k < 0 || k > m)
    throw Invalid_input("join test: continuity order " + std::to_string(k) + " outside 0.." +
                        std::to_string(m));
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  Join_report report;
  report.requested_order = k;
  report.exact = exact;
  std::tie(report.a_vertices, report.b_vertices) = internal::shared_edge(A, B);
  const auto& p = A.vertex(report.a_vertices[0]);
  const auto& q = B.vertex(report.b_vertices[0]);
  const auto& r = A.vertex(report.a_vertices[1]);
  const auto& s = A.vertex(report.a_vertices[2]);
  // Barycentric weights of p, q, r, s in each patch's own frame, computed once.
  const std::array<Weights, 4> wa{{A.barycentric_coordinates(p), A.barycentric_coordinates(q),
                                   A.barycentric_coordinates(r), A.barycentric_coordinates(s)}};
  const std::array<Weights, 4> wb{{B.barycentric_coordinates(p), B.barycentric_coordinates(q),
                                   B.barycentric_coordinates(r), B.barycentric_coordinates(s)}};

  auto evaluate = [&](int g, int h, int i) {
    Join_condition c;
    c.order = g + h;
    c.p_count = g;
    c.q_count = h;
    c.r_count = i;
    c.s_count = m - g - h - i;
    const std::array<int, 4> counts{{g, h, c.r_count, c.s_count}};
    std::vector<Weights> args_a, args_b;
    for (int point = 0; point < 4; ++point)
      for (int n = 0; n < counts[point]; ++n) {
        args_a.push_back(wa[point]);
        args_b.push_back(wb[point]);
      }
    const Value difference = B.blossom_barycentric(args_b) - A.blossom_barycentric(args_a);
    internal::record_difference(c, difference, tolerance, report);
    return c;
  };

  for (int l = 0; l <= k; ++l) {
    for (int i = 0; i <= m - l; ++i) {
      switch (conditions) {
      case Join_conditions::EXTENSION:
        report.conditions.push_back(evaluate(0, l, i));
        break;
      case Join_conditions::LAI:
        report.conditions.push_back(evaluate(l / 2, l - l / 2, i));
        break;
      case Join_conditions::COMPLETE:
        for (int g = 0; g <= l; ++g)
          report.conditions.push_back(evaluate(g, l - g, i));
        break;
      }
    }
  }

  report.achieved_order = k;
  internal::summarize_conditions(report);
  report.holds = report.achieved_order >= k;
  return report;
}

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief checks the \f$C^1\f$ join of `A` and `B` directly on their control points:
  Xu's conditions (3.4) \f$f_A(r^i s^{m-i}) = f_B(r^i s^{m-i})\f$ and (3.5)
  \f$f_B(q r^i s^{m-1-i}) = \lambda f_A(p r^i s^{m-1-i}) + \mu f_A(r^{i+1} s^{m-1-i}) +
  \nu f_A(r^i s^{m-i})\f$ with \f$q = \lambda p + \mu r + \nu s\f$.

  The conditions and residuals are those of `check_join(A, B, 1, Join_conditions::EXTENSION)`
  but no blossom is evaluated: about \f$3m\f$ multiplications per edge, which is what makes
  exact certification of large splines affordable.
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param A the first patch
  \param B the second patch, over a triangle adjacent to that of `A`
  \param tolerance absolute tolerance on each coordinate of a difference (0: exact zero)
  \returns the join report
*/
template <class GeomTraits, class Value>
Join_report check_C1_join(const Bezier_triangle<GeomTraits, Value>& A,
                          const Bezier_triangle<GeomTraits, Value>& B, double tolerance = 0) {
  using FT = typename GeomTraits::FT;
  const int m = A.degree();
  if (B.degree() != m)
    throw Invalid_input("join test: degree mismatch (" + std::to_string(m) + " and " +
                        std::to_string(B.degree()) + ")");
  if (m < 1)
    throw Invalid_input("join test: C^1 needs degree at least 1");
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  Join_report report;
  report.requested_order = 1;
  report.exact = exact;
  std::tie(report.a_vertices, report.b_vertices) = internal::shared_edge(A, B);
  const auto& av = report.a_vertices;
  const auto& bv = report.b_vertices;
  // Control point with g copies of the apex, i of r and m-g-i of s, in either patch.
  auto point = [m](const Bezier_triangle<GeomTraits, Value>& P, const std::array<int, 3>& local,
                   int g, int i) -> const Value& {
    Multi_index index;
    index[local[0]] = g;
    index[local[1]] = i;
    index[local[2]] = m - g - i;
    return P.control_point(index);
  };
  // q = w[av[0]] p + w[av[1]] r + w[av[2]] s: the weights come in A's vertex order.
  const auto local = A.barycentric_coordinates(B.vertex(bv[0]));
  const std::array<FT, 3> w{
      {local[std::size_t(av[0])], local[std::size_t(av[1])], local[std::size_t(av[2])]}};
  auto record = [&](int order, int i, const Value& difference) {
    Join_condition c;
    c.order = order;
    c.q_count = order;
    c.r_count = i;
    c.s_count = m - order - i;
    internal::record_difference(c, difference, tolerance, report);
    report.conditions.push_back(c);
  };
  for (int i = 0; i <= m; ++i) {
    const Value difference = point(B, bv, 0, i) - point(A, av, 0, i);
    record(0, i, difference);
  }
  for (int i = 0; i <= m - 1; ++i) {
    const Value extension =
        w[0] * point(A, av, 1, i) + w[1] * point(A, av, 0, i + 1) + w[2] * point(A, av, 0, i);
    const Value difference = point(B, bv, 1, i) - extension;
    record(1, i, difference);
  }
  report.achieved_order = 1;
  internal::summarize_conditions(report);
  report.holds = report.achieved_order >= 1;
  return report;
}

namespace internal {

// check_C1_join() in the frame of the larger of the two triangles. Conditions (3.5) written
// in A's frame and in B's are equivalent (once (3.4) holds, each residual of one form is the
// other's times -1/lambda, q = lambda p + ...), so exact verdicts and zeros do not depend on
// the choice; but in a sliver A the weights of q are about 1/(its relative height), and the
// round-off of A's control values comes back multiplied by them (a 129^2 grid jittered by
// 1e-9 of a cell: 377 edges beyond round-off, 9 in the larger frame, those between two
// slivers). In the larger triangle's frame every weight is bounded by the same numerators
// over the larger area.
template <class GeomTraits, class Value>
Join_report check_C1_join_in_larger_frame(const Bezier_triangle<GeomTraits, Value>& A,
                                          const Bezier_triangle<GeomTraits, Value>& B,
                                          double tolerance) {
  const auto area = [](const Bezier_triangle<GeomTraits, Value>& P) {
    return CGAL::abs(GeomTraits().compute_area_2_object()(P.vertex(0), P.vertex(1), P.vertex(2)));
  };
  return area(B) > area(A) ? check_C1_join(B, A, tolerance) : check_C1_join(A, B, tolerance);
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief returns `true` iff `A` and `B` join with \f$C^k\f$ continuity: an exact verdict.
  \tparam GeomTraits a kernel with an exact number type (e.g.
  `CGAL::Simple_cartesian<CGAL::Exact_rational>`); with `double`, use `check_join()` and
  read the residuals, or convert the patches exactly with `convert_patch()` first.
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param A the first patch
  \param B the second patch, over a triangle adjacent to that of `A`
  \param k the order of continuity
  \returns `true` iff `A` and `B` join with \f$C^k\f$ continuity
*/
template <class GeomTraits, class Value>
bool is_Ck_join(const Bezier_triangle<GeomTraits, Value>& A,
                const Bezier_triangle<GeomTraits, Value>& B, int k) {
  static_assert(CGAL::Algebraic_structure_traits<typename GeomTraits::FT>::Is_exact::value,
                "is_Ck_join() needs an exact number type; use check_join() for residuals");
  return check_join(A, B, k).holds;
}

/*!
  \ingroup PkgTriangularSplineContinuity
  \brief returns the largest residual of the \f$C^k\f$ conditions between `A` and `B`
  (absolute, largest coordinate; zero iff they join \f$C^k\f$ up to the arithmetic).
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param A the first patch
  \param B the second patch, over a triangle adjacent to that of `A`
  \param k the order of continuity
  \returns the largest residual of the \f$C^k\f$ conditions between `A` and `B` (absolute, largest
  coordinate; zero iff they join \f$C^k\f$ up to the arithmetic)
*/
template <class GeomTraits, class Value>
double join_residual(const Bezier_triangle<GeomTraits, Value>& A,
                     const Bezier_triangle<GeomTraits, Value>& B, int k) {
  return check_join(A, B, k).max_residual;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_CONTINUITY_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_MANN_CONTINUITY_ADJUSTMENT_H
#define CGAL_TRIANGULAR_SPLINE_MANN_CONTINUITY_ADJUSTMENT_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Mann/Network_adjustment.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/continuity.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/continuity_adjustment.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineMann
  \brief the control points moved by `adjust_join()`.
*/
struct Join_adjustment {
  int order = 0; ///< the order \f$k\f$ of the conditions that were enforced
  /// the moved control points of the first patch `A` (its multi-indices, in `A`'s vertex
  /// order); each has \f$k\f$ copies of `A`'s apex
  std::vector<Multi_index> first_touched;
  /// the moved control points of the second patch `B`; each has \f$k\f$ copies of `B`'s apex
  std::vector<Multi_index> second_touched;
  /// the largest absolute coordinate of a correction, converted to `double`
  double max_correction = 0;
  /// returns `true` iff some control point was moved
  /// \returns `true` iff some control point was moved
  bool changed() const { return !first_touched.empty() || !second_touched.empty(); }
};

/*!
  \ingroup PkgTriangularSplineMann
  \brief returns \f$4k+1\f$, the smallest degree for which `adjust_network()` raises a whole
  network to \f$C^k\f$ (Mann §3.1, Ženíšek).

  In a patch of degree \f$n\f$ the control points within distance \f$2k\f$ of a corner
  (multiplicity of that corner at least \f$n-2k\f$) are exactly the ones the \f$C^k\f$
  conditions near that corner involve, on every edge around it. The three corner regions
  of a patch are disjoint if and only if \f$n \ge 4k+1\f$: only then can the conditions
  around each vertex be met independently, and the points the averaging moves for one
  edge lie outside every corner region and off the other edges' conditions.
  \param k the order of continuity
  \returns \f$4k+1\f$, the smallest degree for which `adjust_network()` raises a whole network to
  \f$C^k\f$ (Mann §3.1, Ženíšek)
*/
constexpr int minimum_degree_for_network_continuity(int k) {
  return 4 * k + 1;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief raises the join of two patches over adjacent domain triangles from \f$C^{k-1}\f$
  to \f$C^k\f$ by Mann's averaging adjustment (eqs. (3), (4), Fig. 9), in place.

  Let `A` be over \f$(V_0, V_1, V_2)\f$ and `B` over \f$(D_0, V_2, V_1)\f$ (the vertices may
  be listed in any order: the shared edge \f$V_1V_2\f$ is found by exact point comparison).
  For each \f$i + j = n - k\f$ the blossoms of both patches are evaluated at Lai's balanced
  point \f$(V_1^i V_2^j D_0^{\lceil k/2\rceil} V_0^{\lfloor k/2\rfloor})\f$ (the values
  `check_join(A, B, k, Join_conditions::LAI)` compares), and the one control point of `A`
  with \f$k\f$ copies of \f$V_0\f$, \f$A(V_0^k V_1^i V_2^j)\f$, and the one of `B` with
  \f$k\f$ copies of \f$D_0\f$ are moved so that both values become their average. Given
  \f$C^{k-1}\f$, the blossom value of `A` involves \f$A(V_0^k V_1^i V_2^j)\f$ with coefficient
  \f$d_0^{\lceil k/2\rceil}\f$, where \f$(d_0, d_1, d_2)\f$ are the barycentric coordinates
  of \f$D_0\f$ with respect to `A`'s triangle, and no other point with \f$k\f$ copies of
  \f$V_0\f$; symmetrically `B`'s value involves \f$B(D_0^k V_1^i V_2^j)\f$ with coefficient
  \f$v_0^{\lfloor k/2\rfloor}\f$. The moves are therefore explicit, and:

  - the result meets \f$C^k\f$ (exactly with an exact number type);
  - only the \f$n-k+1\f$ rows-\f$k\f$ points of each patch can move; the conditions of lower
    order are untouched;
  - a condition that already holds gives a correction that is exactly zero and is skipped,
    so a pair that already meets \f$C^k\f$ is unchanged (bit for bit with exact types);
  - the result does not depend on the split of the \f$k\f$ off-edge arguments: it equals
    Floater's view, the row-\f$k\f$ points of the average polynomial \f$(F_A + F_B)/2\f$.

  \f$k = 0\f$ averages the shared boundary points (Mann §2.1), \f$k = 1\f$ is the
  Foley–Opitz \f$C^1\f$ adjustment. To raise an arbitrary pair to \f$C^k\f$, call the
  function for orders \f$0, 1, \dots, k\f$ in turn.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` or a vector type (see `Value_traits`)
  \param A,B the patches, modified in place
  \param k the order to reach, \f$0 \le k < n\f$
  \param tolerance with an inexact number type, the precondition \f$C^{k-1}\f$ is accepted
  when every condition of order below \f$k\f$ has a residual (see `check_join()`) of at
  most `tolerance` times the largest absolute control coordinate of the two patches (at
  least 1); ignored with an exact number type, where the check is exact
  \return the moved control points
  \throws Invalid_input if the degrees differ, the domain triangles are not adjacent across
  one edge (or overlap), \f$k\f$ is outside \f$[0, n)\f$, or the pair does not meet
  \f$C^{k-1}\f$; the patches are then unchanged.
*/
template <class GeomTraits, class Value>
Join_adjustment adjust_join(Bezier_triangle<GeomTraits, Value>& A,
                            Bezier_triangle<GeomTraits, Value>& B, int k, double tolerance = 1e-9) {
  const int n = A.degree();
  const std::string where = "continuity adjustment: ";
  if (B.degree() != n)
    throw Invalid_input(where + "the patches have different degrees (" + std::to_string(n) +
                        " and " + std::to_string(B.degree()) + ")");
  if (k < 0 || k >= n)
    throw Invalid_input(where + "continuity order " + std::to_string(k) + " outside 0.." +
                        std::to_string(n - 1) + " for degree " + std::to_string(n) + " patches");
  std::pair<std::array<int, 3>, std::array<int, 3>> local;
  try {
    local = internal::shared_edge(A, B);
  } catch (const Invalid_input& e) {
    throw Invalid_input(where + e.what());
  }
  if (k > 0) {
    const double scale = (std::max)(internal::control_scale(A), internal::control_scale(B));
    const Join_report report = check_join(A, B, k - 1, Join_conditions::LAI, tolerance * scale);
    if (!report.holds)
      throw Invalid_input(where + "the patches must meet C^" + std::to_string(k - 1) +
                          " before the C^" + std::to_string(k) + " adjustment, but " +
                          (report.achieved_order < 0
                               ? std::string("they do not even meet C^0")
                               : "they only meet C^" + std::to_string(report.achieved_order)) +
                          " (largest residual " + internal::short_number(report.max_residual) +
                          "); adjust orders 0.." + std::to_string(k - 1) + " first");
  }
  Join_adjustment result;
  result.order = k;
  internal::adjust_order(A, local.first, B, local.second, k, 0, n - k, &result.first_touched,
                         &result.second_touched, result.max_correction);
  return result;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief raises a whole network of patches (one per face of `domain`) to \f$C^k\f$ across
  every interior edge, in place, by Mann's averaging adjustment.

  The patches must have one degree \f$n \ge 4k+1\f$ (`minimum_degree_for_network_continuity()`);
  patch `f` is over the corners of face `f` in any order. Two steps:

  1. <b>Vertices.</b> Around each vertex \f$v\f$, the control points with at least
     \f$n-2k\f$ copies of \f$v\f$ (the corner regions of the incident patches; disjoint
     within a patch because \f$n \ge 4k+1\f$) are checked against the \f$C^k\f$ conditions
     of the edges around \f$v\f$ that involve only them (for edge \f$vw\f$: order
     \f$l \le k\f$, at most \f$2k - l\f$ copies of \f$w\f$). These conditions form a cycle
     around an interior vertex, which edge-by-edge averaging cannot close, so when they do
     not hold the corner regions are replaced by their least-squares projection onto the
     conditions (an exact linear solve with an exact number type). The projection does not
     change points that meet them: a network that is already \f$C^k\f$, that is cut from
     one polynomial, or that was set from common vertex data as Mann's interpolant is
     (`mann_interpolant()`), is untouched here.
  2. <b>Edges.</b> For \f$l = 0, 1, \dots, k\f$ in turn, across every interior edge, the
     order-\f$l\f$ conditions outside both corner regions (\f$i\f$ copies of the first edge
     vertex and \f$j = n-l-i\f$ of the second with \f$l + i > 2k\f$ and \f$l + j > 2k\f$)
     are enforced as in `adjust_join()`. The points moved lie outside every corner region
     and at distance more than \f$k\f$ from the other two edges of their patch, so they
     disturb no other condition of order \f$\le k\f$: after the sweep over order \f$l\f$ the
     network meets \f$C^l\f$ everywhere, and finally \f$C^k\f$, exactly with an exact number
     type (with `double`, up to round-off that grows with the order and the aspect ratio of
     the triangles).

  As for pairs, a correction that is exactly zero is skipped: a network that already meets
  \f$C^k\f$ is returned unchanged (bit for bit with exact types), and so data from one
  polynomial keeps its polynomial precision. For Mann's quintic interpolant (\f$k = 1\f$)
  step 1 does nothing and step 2 moves one point per patch and edge, \f$(1, 2, 2)\f$ in the
  edge's frame.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` or a vector type (see `Value_traits`)
  \param domain the domain triangulation
  \param patches `patches[f]` is the patch of face `f`; modified in place
  \param k the order to reach, \f$k \ge 0\f$
  \param tolerance with an inexact number type, the corner regions of a vertex are left
  unchanged when every condition residual is at most `tolerance` times the largest
  absolute control coordinate there (at least 1); ignored with exact types
  \return per edge and per projected vertex, the control points moved
  \throws Invalid_input if `patches` does not hold one patch per face, a patch is not over
  its face, the degrees differ, \f$k < 0\f$, or the degree is below \f$4k+1\f$ (the
  message says why); the patches are then unchanged.
*/
template <class GeomTraits, class Value>
Network_adjustment adjust_network(const Planar_domain<GeomTraits>& domain,
                                  std::vector<Bezier_triangle<GeomTraits, Value>>& patches, int k,
                                  double tolerance = 1e-9) {
  using Index = std::uint32_t;
  using FT = typename GeomTraits::FT;
  const std::string where = "network adjustment: ";
  const std::vector<std::array<int, 3>> local =
      internal::face_to_patch_vertices(domain, patches, where);
  const int n = patches.front().degree();
  if (k < 0)
    throw Invalid_input(where + "negative continuity order " + std::to_string(k));
  if (n < minimum_degree_for_network_continuity(k))
    throw Invalid_input(
        where + "C^" + std::to_string(k) + " on a network needs degree at least 4k+1 = " +
        std::to_string(minimum_degree_for_network_continuity(k)) + " (Mann 3.1, Zenisek), got " +
        std::to_string(n) +
        ": below it the corner regions of radius 2k of a patch overlap, so "
        "the points moved for one edge would break the conditions of another; elevate the "
        "degree first or ask for C^" +
        std::to_string((std::max)(0, (n - 1) / 4)));

  Network_adjustment report;
  report.order = k;
  report.degree = n;
  report.exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  internal::Vertex_workspace<FT, Value> workspace;
  for (Index v = 0; v < domain.number_of_vertices(); ++v)
    internal::project_vertex(domain, patches, local, v, k, tolerance, workspace, report);

  std::vector<std::size_t> position(domain.number_of_edges(), 0);
  for (Index e = 0; e < domain.number_of_edges(); ++e) {
    if (domain.is_boundary_edge(e))
      continue;
    position[e] = report.edges.size();
    Edge_adjustment entry;
    entry.edge = e;
    entry.vertices = domain.edge(e);
    report.edges.push_back(std::move(entry));
  }
  std::vector<Multi_index> touched_a, touched_b;
  double max_correction = 0;
  for (int l = 0; l <= k; ++l)
    for (Index e = 0; e < domain.number_of_edges(); ++e) {
      if (domain.is_boundary_edge(e))
        continue;
      const int i_lo = 2 * k - l + 1, i_hi = n - 2 * k - 1;
      if (i_lo > i_hi)
        continue;
      const auto& ef = domain.edge_faces(e);
      const Index r = domain.edge(e)[0], s = domain.edge(e)[1];
      const int ar = internal::corner_in_patch(domain, local, ef[0], r);
      const int as = internal::corner_in_patch(domain, local, ef[0], s);
      const int br = internal::corner_in_patch(domain, local, ef[1], r);
      const int bs = internal::corner_in_patch(domain, local, ef[1], s);
      touched_a.clear();
      touched_b.clear();
      internal::adjust_order(patches[ef[0]], {{3 - ar - as, ar, as}}, patches[ef[1]],
                             {{3 - br - bs, br, bs}}, l, i_lo, i_hi, &touched_a, &touched_b,
                             max_correction);
      Edge_adjustment& entry = report.edges[position[e]];
      for (const Multi_index& index : touched_a)
        entry.touched.push_back({ef[0], index});
      for (const Multi_index& index : touched_b)
        entry.touched.push_back({ef[1], index});
    }
  return report;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_MANN_CONTINUITY_ADJUSTMENT_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_MULTI_INDEX_H
#define CGAL_TRIANGULAR_SPLINE_MULTI_INDEX_H

#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief a multi-index \f$(i,j,k)\f$ of \f$\Delta_m = \{(i,j,k)\in\mathbb{N}^3 : i+j+k=m\}\f$.

  Over a domain triangle \f$(r,s,t)\f$ the control point \f$b_{i,j,k}\f$ is the blossom value
  \f$f(r^i s^j t^k)\f$ (Xu, Lemma 2.7.1): `i` counts the first domain vertex, `j` the
  second and `k` the third.
*/
struct Multi_index {
  int i = 0; ///< multiplicity of the first domain vertex
  int j = 0; ///< multiplicity of the second domain vertex
  int k = 0; ///< multiplicity of the third domain vertex

  /// returns `i+j+k`, the degree the index belongs to.
  /// \returns `i+j+k`
  int degree() const { return i + j + k; }
  /// returns the multiplicity of domain vertex `v` (0, 1 or 2).
  /// \param v the domain vertex, 0, 1 or 2
  /// \returns `i`, `j` or `k`
  int operator[](int v) const { return v == 0 ? i : (v == 1 ? j : k); }
  /// returns a mutable reference to the multiplicity of domain vertex `v`.
  /// \param v the domain vertex, 0, 1 or 2
  /// \returns a reference to `i`, `j` or `k`
  int& operator[](int v) { return v == 0 ? i : (v == 1 ? j : k); }

  /// returns `true` iff `a` and `b` are equal.
  friend bool operator==(const Multi_index& a, const Multi_index& b) {
    return a.i == b.i && a.j == b.j && a.k == b.k;
  }
  /// returns `true` iff `a` and `b` differ.
  friend bool operator!=(const Multi_index& a, const Multi_index& b) { return !(a == b); }
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief the role of a control point in a patch, the vocabulary of Xu's prescription and
  propagation scheme (SPEC §3), generalised to any degree `m`.

  For a quintic: corner (5,0,0); star (4,1,0), (4,0,1); edge-middle (3,2,0), (2,3,0);
  corner-inner (3,1,1); middle-inner (2,2,1). For other degrees the rules are: a corner has
  one index equal to `m`; a star lies on an edge next to a corner (indices `m-1`, `1`, `0`);
  every other boundary point is edge-middle; an interior point (all indices positive) next
  to an edge (some index equal to 1) is corner-inner when its largest index is `m-2` and
  middle-inner otherwise; interior points farther from every edge (degree \f$\ge 6\f$) are
  `Deep_interior`. The earlier rule wins, so for `m = 2` the edge midpoints are stars and
  for `m = 3` the centre (1,1,1) is corner-inner.
*/
enum class Control_point_role {
  CORNER,
  STAR,
  EDGE_MIDDLE,
  CORNER_INNER,
  MIDDLE_INNER,
  DEEP_INTERIOR
};

/// returns a lowercase name of `role` ("corner", "star", "edge-middle", ...).
/// \param role the role of a control point
/// \returns a lowercase name of `role` ("corner", "star", "edge-middle", ...)
inline std::string role_name(Control_point_role role) {
  switch (role) {
  case Control_point_role::CORNER:
    return "corner";
  case Control_point_role::STAR:
    return "star";
  case Control_point_role::EDGE_MIDDLE:
    return "edge-middle";
  case Control_point_role::CORNER_INNER:
    return "corner-inner";
  case Control_point_role::MIDDLE_INNER:
    return "middle-inner";
  case Control_point_role::DEEP_INTERIOR:
    return "deep-interior";
  }
  return "unknown";
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the number \f$(m+1)(m+2)/2\f$ of control points of a degree `m` patch.
  \param m the degree
  \returns the number \f$(m+1)(m+2)/2\f$ of control points of a degree `m` patch.
  \throws Invalid_input if `m < 0`
*/
inline std::size_t number_of_control_points(int m) {
  if (m < 0)
    throw Invalid_input("negative degree " + std::to_string(m));
  return static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(m + 2) / 2;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the position of `(i, j, m-i-j)` in Xu's Table 2.3 order.

  The net is stored row by row, row `i = 0..m` holding \f$b_{i,0,m-i}, b_{i,1,m-i-1},
  \dots, b_{i,m-i,0}\f$ (Xu §2.7.4): the bottom row of Table 2.3 (005, 014, ..., 050)
  comes first and the apex 500 last.
  \pre `0 <= i`, `0 <= j`, `i + j <= m`
  \param i the first component of the multi-index
  \param j the second component of the multi-index
  \param m the degree
  \returns the position of `(i, j, m-i-j)` in Xu's Table 2.3 order
*/
inline std::size_t linear_index(int i, int j, int m) {
  CGAL_precondition(0 <= i && 0 <= j && i + j <= m);
  // Rows 0..i-1 hold (m+1) + m + ... + (m-i+2) entries.
  return static_cast<std::size_t>(i * (m + 1) - i * (i - 1) / 2 + j);
}

/// returns the position of `index` in Xu's Table 2.3 order (see `linear_index(int,int,int)`).
/// \param index the multi-index of a control point
/// \returns the position of `index` in Xu's Table 2.3 order (see `linear_index(int,int,int)`)
inline std::size_t linear_index(const Multi_index& index) {
  return linear_index(index.i, index.j, index.degree());
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the multi-index stored at position `position` of a degree `m` net
  (inverse of `linear_index()`).
  \throws Invalid_input if `position >= number_of_control_points(m)` or `m < 0`
  \param position the linear position in the net
  \param m the degree
  \returns the multi-index stored at position `position` of a degree `m` net (inverse of
  `linear_index()`)
*/
inline Multi_index multi_index(std::size_t position, int m) {
  if (position >= number_of_control_points(m))
    throw Invalid_input("control point position " + std::to_string(position) +
                        " out of range for degree " + std::to_string(m));
  int i = 0;
  std::size_t row_start = 0;
  while (row_start + static_cast<std::size_t>(m - i + 1) <= position) {
    row_start += static_cast<std::size_t>(m - i + 1);
    ++i;
  }
  const int j = static_cast<int>(position - row_start);
  return Multi_index{i, j, m - i - j};
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns all multi-indices of \f$\Delta_m\f$ in Xu's Table 2.3 order.
  \param m the degree
  \returns all multi-indices of \f$\Delta_m\f$ in Xu's Table 2.3 order
*/
inline std::vector<Multi_index> multi_indices(int m) {
  std::vector<Multi_index> result;
  result.reserve(number_of_control_points(m));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m - i; ++j)
      result.push_back(Multi_index{i, j, m - i - j});
  return result;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the role of the control point `index` (see `Control_point_role`).
  \param index the multi-index of a control point
  \returns the role of the control point `index` (see `Control_point_role`)
*/
inline Control_point_role role(const Multi_index& index) {
  const int m = index.degree();
  const int largest = (std::max)({index.i, index.j, index.k});
  const int smallest = (std::min)({index.i, index.j, index.k});
  if (largest == m)
    return Control_point_role::CORNER;
  if (smallest == 0) {
    // On an edge: a star touches a corner.
    return largest == m - 1 ? Control_point_role::STAR : Control_point_role::EDGE_MIDDLE;
  }
  if (smallest == 1)
    return largest == m - 2 ? Control_point_role::CORNER_INNER : Control_point_role::MIDDLE_INNER;
  return Control_point_role::DEEP_INTERIOR;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the local vertex (0, 1 or 2) a corner, star or corner-inner point belongs
  to, and -1 for the other roles.
  \param index the multi-index of a control point
  \returns the local vertex (0, 1 or 2) a corner, star or corner-inner point belongs to, and -1 for
  the other roles
*/
inline int owning_vertex(const Multi_index& index) {
  const Control_point_role r = role(index);
  if (r != Control_point_role::CORNER && r != Control_point_role::STAR &&
      r != Control_point_role::CORNER_INNER)
    return -1;
  for (int v = 0; v < 3; ++v)
    if (index[v] == (std::max)({index.i, index.j, index.k}))
      return v;
  return -1;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the local edge (the index of the opposite vertex, 0, 1 or 2) an
  edge-middle or middle-inner point belongs to, and -1 for the other roles.

  Edge-middle points lie on the edge; a middle-inner point is the interior point next to
  the middle of that edge (the "flip point" of Xu §4.1.3 for quintics).
  \param index the multi-index of a control point
  \returns the local edge (the index of the opposite vertex, 0, 1 or 2) an edge-middle or
  middle-inner point belongs to, and -1 for the other roles
*/
inline int owning_edge(const Multi_index& index) {
  const Control_point_role r = role(index);
  if (r == Control_point_role::EDGE_MIDDLE) {
    for (int v = 0; v < 3; ++v)
      if (index[v] == 0)
        return v;
  }
  if (r == Control_point_role::MIDDLE_INNER) {
    for (int v = 0; v < 3; ++v)
      if (index[v] == 1)
        return v;
  }
  return -1;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_MULTI_INDEX_H

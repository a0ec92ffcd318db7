// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_RECENTERING_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_RECENTERING_H

// Re-centering of a corner point inside its projected star polygon (Xu, Fig. 6.5; SPEC_AG1
// §4.2 S5, resolutions R-6..R-9): cut the polygon at its reflex vertices until it is convex
// and take the vertex centroid of what is left.

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

/// The outcome of `recenter()`.
template <class K>
struct Recentering_result {
  bool simple_ccw = false; ///< P is a simple counter-clockwise polygon (else nothing is done)
  bool recentred = false;  ///< z0 was not strictly inside P and the centre was moved
  int cuts = 0;            ///< number of reflex cuts made
  std::vector<typename K::Point_2> polygon; ///< the final polygon (P itself if not re-centred)
  typename K::Point_2 center;               ///< z0, or the vertex centroid of the final polygon
};

// Where a ray first meets the polygon: the point, and its position on the boundary as edge
// `edge` (from P[edge] to P[edge+1]) at a parameter in [0, 1). `at_vertex` means the point
// is P[edge] itself (parameter 0), so that it is not inserted twice.
template <class K>
struct Recentering_hit {
  typename K::Point_2 point;
  typename K::FT t;         // ray parameter, > 0: the hit is origin + t (origin - back)
  typename K::FT parameter; // on the edge, in [0, 1)
  std::size_t edge = 0;
  bool at_vertex = false;
};

// Simple: a non-degenerate triangle, or (n >= 4) non-adjacent edges pairwise disjoint. The
// latter also excludes repeated consecutive vertices and spikes folding an edge back onto
// its neighbour: both make the edges on either side of them meet. Decided with the kernel's
// predicates only, so exactly with Epick and exact kernels.
template <class K>
bool recentering_is_simple(const std::vector<typename K::Point_2>& P, const K& k) {
  const std::size_t n = P.size();
  if (n < 3)
    return false;
  if (n == 3)
    return k.orientation_2_object()(P[0], P[1], P[2]) != CGAL::COLLINEAR;
  auto do_intersect = k.do_intersect_2_object();
  auto segment = k.construct_segment_2_object();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1)
        continue; // adjacent through the closing edge
      if (do_intersect(segment(P[i], P[(i + 1) % n]), segment(P[j], P[(j + 1) % n])))
        return false;
    }
  return true;
}

// The first point where the ray from P[i] in direction P[i] - P[back] meets the boundary,
// the two edges at P[i] excluded. Whether and where a segment is hit is decided by
// orientations of polygon vertices only; just the ordering of the hits along the ray uses
// the ray parameter computed in FT (exact for exact number types).
template <class K>
std::optional<Recentering_hit<K>> recentering_first_hit(const std::vector<typename K::Point_2>& P,
                                                        std::size_t i, std::size_t back,
                                                        const K& k) {
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  using Vector_2 = typename K::Vector_2;
  auto orientation = k.orientation_2_object();
  auto strictly_ordered = k.collinear_are_strictly_ordered_along_line_2_object();
  const std::size_t n = P.size();
  const Point_2 &o = P[i], &q = P[back];
  const Vector_2 d = o - q;
  // explicit FT results: gmpxx expression templates must not outlive their operands
  auto cross = [](const Vector_2& u, const Vector_2& v) -> FT {
    return u.x() * v.y() - u.y() * v.x();
  };
  // the ray parameter of a point known to lie on the ray
  auto parameter_on_ray = [&](const Point_2& x) -> FT {
    const Vector_2 u = x - o;
    return (u.x() * d.x() + u.y() * d.y()) / (d.x() * d.x() + d.y() * d.y());
  };
  std::optional<Recentering_hit<K>> best;
  auto consider = [&](Recentering_hit<K> hit) {
    if (!best || hit.t < best->t)
      best = std::move(hit);
  };
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t j1 = (j + 1) % n;
    if (j == i || j1 == i)
      continue;
    const Point_2 &a = P[j], &b = P[j1];
    const CGAL::Orientation sa = orientation(q, o, a), sb = orientation(q, o, b);
    if (sa == CGAL::COLLINEAR || sb == CGAL::COLLINEAR) {
      // an endpoint on the supporting line: it is the hit if it lies ahead of o (for an edge
      // along the line, its nearer endpoint ahead is the first point of it that is met)
      if (sa == CGAL::COLLINEAR && strictly_ordered(q, o, a))
        consider({a, parameter_on_ray(a), FT(0), j, true});
      if (sb == CGAL::COLLINEAR && strictly_ordered(q, o, b))
        consider({b, parameter_on_ray(b), FT(0), j1, true});
      continue;
    }
    if (sa == sb)
      continue; // both endpoints strictly on one side of the line
    // a and b strictly on opposite sides: the crossing is ahead of o iff o is to the right
    // of the segment directed from its left endpoint to its right endpoint
    const Point_2 &left = sa == CGAL::LEFT_TURN ? a : b, &right = sa == CGAL::LEFT_TURN ? b : a;
    if (orientation(left, right, o) != CGAL::RIGHT_TURN)
      continue;
    const Vector_2 e = b - a, ao = a - o;
    const FT denominator = cross(d, e);
    const FT t = cross(ao, e) / denominator, s = cross(ao, d) / denominator;
    // the crossing is strictly inside the edge (both endpoints are off the line)
    consider({a + s * e, t, s, j, false});
  }
  return best;
}

/*
  The re-centering of SPEC_AG1 §4.2 S5 (Xu Fig. 6.5) for a polygon `P` (chart coordinates
  of the projected stars) and a candidate centre `z0`:
  - `P` not simple, clockwise, or with fewer than 3 vertices: nothing is done
    (`simple_ccw` false, `center` = `z0`);
  - `z0` strictly inside `P`: `center` = `z0`;
  - otherwise, while the polygon has a reflex vertex, cut at the first one p_i (walking
    counter-clockwise from index 0): shoot the rays p_i + t(p_i - p_{i-1}) and
    p_i + t(p_i - p_{i+1}), t > 0, to their first boundary hits v_1, v_2 (edges at p_i
    excluded, vertex hits allowed) and keep the polygon p_i, v_1, (boundary from v_1
    counter-clockwise to v_2), v_2, which starts at p_i; `center` is the vertex centroid of
    the final convex polygon.
  Each cut turns p_i convex and leaves the other vertices' angles unchanged or smaller, so
  the number of reflex vertices drops by at least one per cut: at most n - 3 cuts. The
  final polygon has positive area and lies in `P`, so its vertex centroid (all weights
  positive) lies strictly inside `P`. Predicates are the kernel's; the ray hits are
  computed in FT (exact for an exact number type).
*/
template <class K>
Recentering_result<K> recenter(const std::vector<typename K::Point_2>& P,
                               const typename K::Point_2& z0, const K& k = K()) {
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  Recentering_result<K> result;
  result.center = z0;
  result.polygon = P;
  if (!recentering_is_simple(P, k))
    return result;
  // the lexicographically smallest vertex is convex in a simple polygon, and its
  // neighbours are not collinear with it (that would be an overlap, excluded above)
  std::size_t lowest = 0;
  auto less_xy = k.less_xy_2_object();
  for (std::size_t i = 1; i < P.size(); ++i)
    if (less_xy(P[i], P[lowest]))
      lowest = i;
  const std::size_t n0 = P.size();
  if (k.orientation_2_object()(P[(lowest + n0 - 1) % n0], P[lowest], P[(lowest + 1) % n0]) !=
      CGAL::LEFT_TURN)
    return result;
  result.simple_ccw = true;
  if (CGAL::bounded_side_2(P.begin(), P.end(), z0, k) == CGAL::ON_BOUNDED_SIDE)
    return result;
  result.recentred = true;

  auto orientation = k.orientation_2_object();
  std::vector<Point_2> polygon = P;
  for (;;) {
    const std::size_t n = polygon.size();
    std::size_t i = n;
    for (std::size_t v = 0; v < n; ++v)
      if (orientation(polygon[(v + n - 1) % n], polygon[v], polygon[(v + 1) % n]) ==
          CGAL::RIGHT_TURN) {
        i = v;
        break;
      }
    if (i == n)
      break; // convex
    const std::size_t previous = (i + n - 1) % n, next = (i + 1) % n;
    // In a simple polygon both rays enter the interior at a reflex vertex and leave it
    // through an edge not incident to p_i, so both hits exist.
    const std::optional<Recentering_hit<K>> h1 = recentering_first_hit(polygon, i, previous, k);
    const std::optional<Recentering_hit<K>> h2 = recentering_first_hit(polygon, i, next, k);
    CGAL_assertion(h1 && h2);
    if (!h1 || !h2)
      break;
    std::vector<Point_2> cut{polygon[i], h1->point};
    // v_2 follows v_1 counter-clockwise; on the same edge it lies after v_1
    if (!(h1->edge == h2->edge && h1->parameter < h2->parameter)) {
      for (std::size_t j = (h1->edge + 1) % n; j != h2->edge; j = (j + 1) % n)
        cut.push_back(polygon[j]);
      if (!h2->at_vertex)
        cut.push_back(polygon[h2->edge]);
    }
    cut.push_back(h2->point);
    polygon = std::move(cut);
    ++result.cuts;
    CGAL_assertion(result.cuts <= static_cast<int>(n0));
    if (result.cuts > static_cast<int>(n0))
      break; // cannot happen (see above); never loop forever
  }
  FT x(0), y(0);
  for (const Point_2& p : polygon) {
    x += p.x();
    y += p.y();
  }
  const FT count(static_cast<int>(polygon.size()));
  result.center = Point_2(x / count, y / count);
  result.polygon = std::move(polygon);
  return result;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_RECENTERING_H

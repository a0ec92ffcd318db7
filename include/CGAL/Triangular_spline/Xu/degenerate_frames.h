// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_DEGENERATE_FRAMES_H
#define CGAL_TRIANGULAR_SPLINE_XU_DEGENERATE_FRAMES_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/filtered_orientation.h>
#include <CGAL/Triangular_spline/internal/frame_degeneracy.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/Algebraic_structure_traits.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief a degenerate frame (Xu §4.4.4): at the end `vertex` of the interior edge `edge`,
  the apexes of the two faces of the edge are collinear with `vertex`.

  There the C^1 diamond of the edge next to `vertex` cannot be solved for its edge-middle
  point (the barycentric weight it divides by is zero), so the propagation must be
  re-routed or the vertex moved.
  \tparam Index an unsigned integer type of vertex indices
*/
template <class Index>
struct Degenerate_frame_t {
  Index edge;       ///< the interior edge
  Index vertex;     ///< the end of the edge where the apexes are collinear with it
  Index apex_left;  ///< apex of the face on the left of the edge (lo -> hi)
  Index apex_right; ///< apex of the face on the right
  /// `false`: exactly collinear; `true`: collinear only up to double rounding (inexact
  /// kernels only, see `find_degenerate_frames()`)
  bool numerical = false;
  /// `true`: not collinear, but re-routed by `C1_quintic_spline` because the regular rule's
  /// weights would exceed its `propagation_weight_bound` (never set by
  /// `find_degenerate_frames()`)
  bool thin = false;
  /// the largest absolute weight of the regular rule at this end (infinite if collinear)
  double regular_weight = std::numeric_limits<double>::infinity();
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the degenerate frames of a domain and its singular vertices.
  \tparam Index an unsigned integer type of vertex indices
*/
template <class Index>
struct Degenerate_frame_analysis {
  std::vector<Degenerate_frame_t<Index>> frames; ///< every degenerate edge end
  /// interior vertices all of whose edges are degenerate at them: degree 4 with the edges
  /// on two lines (the vertices counted by \f$\sigma\f$ in the dimension of \f$S^1_5\f$)
  std::vector<Index> singular_vertices;
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief finds every degenerate frame of `domain` with the kernel's exact collinearity test.

  At most one end of an edge can be degenerate: if both were, the four vertices of the two
  faces would be collinear. With an inexact number type, frames whose apexes are collinear
  with the end up to rounding (sine of the angle below \f$10^{-12}\f$) are reported too,
  flagged `numerical`: the double build re-routes them instead of dividing by a weight that
  is zero but for rounding.
  \tparam GeomTraits a model of `Kernel`
  \param domain the triangulated planar domain
  \returns the degenerate frames found
*/
template <class GeomTraits>
Degenerate_frame_analysis<typename Planar_domain<GeomTraits>::Index>
find_degenerate_frames(const Planar_domain<GeomTraits>& domain) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  constexpr bool exact = CGAL::Algebraic_structure_traits<typename GeomTraits::FT>::Is_exact::value;
  Degenerate_frame_analysis<Index> result;
  // The orientation predicate, not collinear_2: the same exact test, but Epick filters it
  // statically (collinear_2 went through interval arithmetic: 4% of a c1 run at 10^6 points),
  // and for GMP rationals Planar_domain::orientation() decides by intervals first.
  // The tests edge by edge on all cores (2 bits per end: degenerate, numerically so), then
  // the frames listed in edge order.
  const std::size_t E = domain.number_of_edges();
  std::vector<unsigned char> ends(E, 0);
  internal::parallel_for_index(
      E, internal::thread_count(E, exact ? 1000 : 20000), [&](std::size_t i) {
        const Index e = static_cast<Index>(i);
        if (domain.is_boundary_edge(e))
          return;
        const auto& ef = domain.edge_faces(e);
        const Index pv = domain.opposite_vertex(ef[0], e), qv = domain.opposite_vertex(ef[1], e);
        const auto &p = domain.point(pv), &q = domain.point(qv);
        for (std::size_t side = 0; side < 2; ++side) {
          const Index rv = domain.edge(e)[side];
          const auto& r = domain.point(rv);
          bool numerical = false;
          if (domain.orientation(pv, rv, qv) != CGAL::COLLINEAR) {
            if (exact || !internal::numerically_collinear(p, r, q))
              continue;
            numerical = true;
          }
          ends[i] |= static_cast<unsigned char>((numerical ? 3 : 1) << (2 * side));
        }
      });
  std::vector<unsigned> degenerate_ends(domain.number_of_vertices(), 0);
  for (Index e = 0; e < E; ++e) {
    if (!ends[e])
      continue;
    const auto& ef = domain.edge_faces(e);
    const Index left = domain.opposite_vertex(ef[0], e);
    const Index right = domain.opposite_vertex(ef[1], e);
    for (std::size_t side = 0; side < 2; ++side) {
      const unsigned bits = (ends[e] >> (2 * side)) & 3u;
      if (!bits)
        continue;
      const Index end = domain.edge(e)[side];
      result.frames.push_back({e, end, left, right, bits == 3});
      ++degenerate_ends[end];
    }
  }
  for (Index v = 0; v < domain.number_of_vertices(); ++v)
    if (!domain.is_boundary_vertex(v) && degenerate_ends[v] == domain.degree(v))
      result.singular_vertices.push_back(v);
  return result;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief one vertex moved by `perturb_degenerate_vertices()`.
  \tparam Point_2 a CGAL 2D point type
  \tparam Index an unsigned integer type of vertex indices
*/
template <class Point_2, class Index>
struct Vertex_move {
  Index vertex;        ///< the vertex index (unchanged by the move)
  Point_2 from, to;    ///< old and new position
  double distance = 0; ///< Euclidean length of the move (in double)
  /// \var from
  /// the old position
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns a copy of `domain` in which the vertices with degenerate frames are moved
  just enough that no frame is degenerate, and reports the moves (Xu §4.4.4, second fix).

  Each offending vertex is tried at distances \f$2^{-k} \ell\f$ (\f$\ell\f$ its shortest
  incident edge, \f$k = 20, 19, \dots, 3\f$, smallest first) in eight directions. A position
  is admissible when every incident triangle keeps its orientation and no edge end whose
  frame involves the vertex is degenerate, all decided with exact orientation tests; the
  first admissible position whose frames propagate with weights at most 16 (the bound of
  `C1_quintic_spline`) is kept, else the first admissible one: a tiny move off a collinear
  frame leaves it nearly degenerate, with weights in the millions.
  The scan is repeated until no degenerate frame is left.

  The domain's region is kept: a boundary vertex between two collinear boundary edges moves
  only along their line (candidates off the line by rounding are rejected, exactly), and a
  boundary corner does not move at all. Frames that no admissible move removes stay
  degenerate: `C1_quintic_spline` re-routes them (`find_degenerate_frames()` lists them).
  Vertex indices are unchanged, so data attached to vertices stays valid.
  \tparam GeomTraits a model of `Kernel`
  \throws Invalid_input if an interior vertex has no admissible move (not observed).
  \param domain the triangulated planar domain
  \param moves receives the vertex moves made
  \returns a copy of `domain` in which the vertices with degenerate frames are moved just enough
  that no frame is degenerate, and reports the moves (Xu §4.4.4, second fix)
*/
template <class GeomTraits>
Planar_domain<GeomTraits> perturb_degenerate_vertices(
    const Planar_domain<GeomTraits>& domain,
    std::vector<Vertex_move<typename GeomTraits::Point_2,
                            typename Planar_domain<GeomTraits>::Index>>& moves) {
  using Index = typename Planar_domain<GeomTraits>::Index;
  using Point_2 = typename GeomTraits::Point_2;
  using FT = typename GeomTraits::FT;
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  moves.clear();
  // C1_quintic_spline's bound: frames above it would be re-routed as thin ones.
  constexpr double weight_bound = 16;
  Planar_domain<GeomTraits> current = domain;
  std::set<Index> stuck; // boundary vertices that cannot move without changing the domain
  for (int round = 0; round < 8; ++round) {
    const auto analysis = find_degenerate_frames(current);
    std::set<Index> offenders;
    for (const auto& f : analysis.frames)
      if (!stuck.count(f.vertex))
        offenders.insert(f.vertex);
    if (offenders.empty())
      return current;
    std::vector<Point_2> points = current.points();
    auto orientation = current.geom_traits().orientation_2_object();
    auto collinear = current.geom_traits().collinear_2_object();
    // Calls frame(left, end, other end, right) for both ends of every interior edge of a
    // face around v, with v at `p` (this covers v as an end and v as an apex).
    auto for_each_frame = [&](Index v, const Point_2& p, const auto& frame) {
      auto at = [&](Index w) -> const Point_2& { return w == v ? p : points[w]; };
      const auto [fb, fe] = current.star_faces(v);
      for (auto f = fb; f != fe; ++f)
        for (int i = 0; i < 3; ++i) {
          const Index e = current.face_edge(*f, i);
          if (current.is_boundary_edge(e))
            continue;
          const auto& ef = current.edge_faces(e);
          const Index left = current.opposite_vertex(ef[0], e);
          const Index right = current.opposite_vertex(ef[1], e);
          const auto& ends = current.edge(e);
          for (int side = 0; side < 2; ++side)
            frame(at(left), at(ends[side]), at(ends[1 - side]), at(right));
        }
    };
    // Is every frame and triangle involving v fine with v at `p`?
    auto admissible = [&](Index v, const Point_2& p) {
      auto at = [&](Index w) -> const Point_2& { return w == v ? p : points[w]; };
      const auto [fb, fe] = current.star_faces(v);
      for (auto f = fb; f != fe; ++f) {
        const auto& t = current.face(*f);
        if (orientation(at(t[0]), at(t[1]), at(t[2])) != CGAL::LEFT_TURN)
          return false;
      }
      bool degenerate = false;
      for_each_frame(v, p,
                     [&](const Point_2& l, const Point_2& end, const Point_2&, const Point_2& r) {
                       degenerate = degenerate || collinear(l, end, r) ||
                                    (!exact && internal::numerically_collinear(l, end, r));
                     });
      return !degenerate;
    };
    // The largest regular propagation weight of the frames around v with v at `p`: moves
    // that leave every one below `weight_bound` are preferred (a tiny move off a collinear
    // frame leaves it nearly degenerate, with weights in the millions).
    auto largest_weight = [&](Index v, const Point_2& p) {
      double largest = 0;
      for_each_frame(
          v, p, [&](const Point_2& l, const Point_2& end, const Point_2& other, const Point_2& r) {
            largest = (std::max)(largest, internal::frame_weight(other, l, end, r));
          });
      return largest;
    };
    bool any_moved = false;
    for (Index v : offenders) {
      if (stuck.count(v))
        continue;
      double shortest = std::numeric_limits<double>::infinity();
      const auto [nb, ne] = current.neighbours(v);
      // A boundary vertex keeps the domain only by sliding along a straight boundary.
      const bool boundary = current.is_boundary_vertex(v);
      if (boundary && !collinear(points[nb[0]], points[v], points[*(ne - 1)])) {
        stuck.insert(v);
        continue;
      }
      for (auto w = nb; w != ne; ++w) {
        const double dx = CGAL::to_double(points[*w].x() - points[v].x());
        const double dy = CGAL::to_double(points[*w].y() - points[v].y());
        shortest = (std::min)(shortest, std::hypot(dx, dy));
      }
      // A power of two below the shortest edge keeps the steps exact multiples in binary.
      const double unit = std::exp2(std::floor(std::log2(shortest)));
      static const int directions[8][2] = {{1, 0}, {0, 1},  {-1, 0},  {0, -1},
                                           {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
      bool moved = false;
      // Along the boundary line: steps of the boundary direction scaled to the unit.
      const Point_2& a = points[nb[0]];
      const Point_2& b = points[*(ne - 1)];
      const double length =
          std::hypot(CGAL::to_double(b.x() - a.x()), CGAL::to_double(b.y() - a.y()));
      std::optional<Point_2> fallback; // the smallest admissible move
      for (int k = 20; k >= 3 && !moved; --k) {
        const FT step = FT(std::ldexp(unit, -k));
        for (const auto& d : directions) {
          if (boundary && (d[1] != 0 || d[0] == 0))
            continue; // two directions along the line: +-(b - a)
          const FT along = FT(d[0]) * FT(std::ldexp(unit, -k) / length);
          const Point_2 candidate =
              boundary ? Point_2(points[v].x() + along * (b.x() - a.x()),
                                 points[v].y() + along * (b.y() - a.y()))
                       : Point_2(points[v].x() + FT(d[0]) * step, points[v].y() + FT(d[1]) * step);
          if (candidate == points[v] || (boundary && !collinear(a, candidate, b)) ||
              !admissible(v, candidate))
            continue;
          if (!fallback)
            fallback = candidate;
          if (largest_weight(v, candidate) > weight_bound)
            continue;
          moved = true;
          fallback = candidate;
          break;
        }
      }
      if (fallback) {
        const double dx = CGAL::to_double(fallback->x() - points[v].x());
        const double dy = CGAL::to_double(fallback->y() - points[v].y());
        moves.push_back({v, points[v], *fallback, std::hypot(dx, dy)});
        points[v] = *fallback;
        moved = true;
        any_moved = true;
      }
      if (!moved && boundary)
        stuck.insert(v); // left to re-routing
      else if (!moved)
        throw Invalid_input("perturbation: no small move of vertex " + std::to_string(v) + " " +
                            internal::point_to_string(points[v]) +
                            " removes its degenerate frames");
    }
    if (!any_moved)
      return current;
    current = Planar_domain<GeomTraits>(std::move(points), current.faces(), current.geom_traits());
  }
  for (const auto& frame : find_degenerate_frames(current).frames)
    if (!stuck.count(frame.vertex) && !current.is_boundary_vertex(frame.vertex))
      throw Invalid_input("perturbation: degenerate frames remain after 8 rounds");
  return current;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_DEGENERATE_FRAMES_H

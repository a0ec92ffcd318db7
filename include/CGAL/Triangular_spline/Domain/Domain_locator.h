// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_LOCATOR_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_LOCATOR_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief locates points of the plane in the triangles of a `Planar_domain`.

  The bounding box of the domain is cut into a uniform grid of buckets, about one bucket
  per two triangles, and every triangle is registered in each bucket that its bounding box
  overlaps. Bounding boxes are computed in `double` with `CGAL::to_double()`, which is
  exact for `double` and monotone for `CGAL::Exact_rational`, so a point of a triangle
  always falls in one of the triangle's buckets; for other number types (e.g. the lazy
  numbers of `CGAL::Exact_predicates_exact_constructions_kernel`) the boxes are widened by
  a small relative margin. Only the choice of candidates uses `double`: whether a point
  lies in a triangle is decided by the kernel's `Orientation_2` predicate, which is exact
  for `CGAL::Exact_predicates_inexact_constructions_kernel` and for exact kernels.

  Points on an edge or at a vertex belong to one of the incident triangles (the first
  candidate found); points outside the domain, inside a hole, or with a non-finite
  coordinate have no location with `locate()`.

  <b>Snapping.</b> A query computed or printed in floating point that should lie on a
  boundary edge often lies a rounding error outside it. `locate_snapped()` (used by the
  evaluation functions of `evaluate.h`) accepts such a point: if `p` is outside the
  domain, its nearest boundary point \f$q\f$ on a boundary edge of length \f$\ell\f$ is
  used instead when
  \f[ |p - q|^2 \le (10^{-9}\,\ell)^2 + (10^{-13} M)^2, \f]
  where \f$M\f$ is the largest absolute vertex coordinate of the domain (the second term
  covers a few hundred units in the last place of large coordinates, e.g. UTM). The test is
  done in `FT` (exact for exact number types) and \f$q\f$, the orthogonal projection onto
  the edge, is a rational construction. `nearest_boundary_point()` finds the nearest point
  of the boundary (outer boundaries and holes) at any distance, for extrapolation.

  <b>Complexity.</b> Construction takes \f$O(F + B)\f$ time and memory for \f$F\f$
  triangles and \f$B \approx F/2\f$ buckets, plus the bucket entries, which are
  \f$O(F)\f$ when the triangles have comparable sizes. If long thin triangles (a fan, a
  strip) would register in too many buckets, the grid is coarsened until the entries are at
  most about \f$8F\f$, so memory stays linear. A query inspects the triangles of one
  bucket: \f$O(1)\f$ expected for evenly sized triangles, \f$O(F)\f$ in the worst case of
  a very uneven triangulation.

  The locator keeps a reference to the domain, which must outlive it and not change.

  \tparam GeomTraits a model of `Kernel`, the kernel of the domain
*/
template <class GeomTraits>
class Domain_locator {
public:
  /// \name Types
  /// @{

  /// the kernel
  using Geom_traits = GeomTraits;
  /// the number type
  using FT = typename Geom_traits::FT;
  /// the point type of the domain plane
  using Point_2 = typename Geom_traits::Point_2;
  /// the triangulated domain
  using Domain = Planar_domain<Geom_traits>;
  /// index of a face of the domain
  using Index = typename Domain::Index;

  /// where a point lies: a triangle of the domain and the barycentric coordinates of the
  /// point with respect to the triangle's vertices in `Planar_domain::face()` order.
  struct Location {
    /// the triangle containing the point (in its interior or on its border)
    Index face;
    /// barycentric coordinates, non-negative and summing to one; a coordinate is exactly
    /// zero when the point lies on the line of the opposite edge (exact predicate), so
    /// vertices get exactly `(1, 0, 0)` up to order. With an exact `FT` they are exact;
    /// with `double` they are rounded.
    std::array<FT, 3> barycentric;
  };

  /// the nearest point of the domain boundary to a query, as returned by
  /// `nearest_boundary_point()`.
  struct Boundary_point {
    /// the boundary edge on which the nearest point lies
    Index edge;
    /// where the nearest point lies: the face of `edge`, barycentric coordinates of the
    /// point (one of them exactly zero)
    Location location;
    /// the nearest point, the orthogonal projection of the query onto `edge` (clamped to
    /// its endpoints)
    Point_2 point;
    /// the squared distance from the query to `point`
    FT squared_distance;
  };

  /// the relative snapping tolerance along an edge (see the class description)
  static constexpr double snap_edge_tolerance = 1e-9;
  /// the snapping tolerance relative to the largest vertex coordinate
  static constexpr double snap_coordinate_tolerance = 1e-13;
  /// @}

  /// \name Creation
  /// @{

  /// builds the bucket grid of `domain` (see the class description for the cost).
  /// \param domain the triangulated planar domain
  explicit Domain_locator(const Domain& domain) : m_domain(domain) { build(); }

  /// a locator over a temporary domain would dangle.
  Domain_locator(const Domain&&) = delete;
  /// @}

  /// \name Queries
  /// @{

  /// returns the triangle containing `p` and the barycentric coordinates of `p` in it, or
  /// `std::nullopt` if `p` is outside the domain (including holes) or not finite.
  /// \param p the query point
  /// \returns the location of `p`, or `std::nullopt`
  std::optional<Location> locate(const Point_2& p) const {
    if (!CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y()))
      return std::nullopt;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    // The grid box holds every rounded triangle box: a rounded point outside it is outside.
    if (!(x >= m_xmin && x <= m_xmax && y >= m_ymin && y <= m_ymax))
      return std::nullopt;
    const std::size_t bucket = cell(x, y);
    for (std::size_t i = m_offsets[bucket]; i < m_offsets[bucket + 1]; ++i) {
      std::optional<Location> location = locate_in(m_entries[i], p);
      if (location)
        return location;
    }
    return std::nullopt;
  }

  /// returns the location of `p` as `locate()` does, or, for a point outside the domain by
  /// at most the snapping tolerance (see the class description), the location of its
  /// nearest boundary point; `std::nullopt` otherwise.
  /// \param p the query point
  /// \returns the location, or `std::nullopt`
  std::optional<Location> locate_snapped(const Point_2& p) const {
    std::optional<Location> location = locate(p);
    if (location || !CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y()))
      return location;
    // Only edges whose box widened by the tolerance holds p are candidates: one bucket.
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    const Edge_grid& g = m_boundary;
    if (g.offsets.empty() || !(x >= g.xmin && x <= g.xmax && y >= g.ymin && y <= g.ymax))
      return std::nullopt;
    // each edge has its own tolerance: keep the nearest edge within its tolerance
    std::optional<Boundary_point> best;
    const FT a(snap_edge_tolerance), b(snap_coordinate_tolerance * m_largest_coordinate);
    const std::size_t bucket = g.row(y) * g.nx + g.column(x);
    for (std::size_t i = g.offsets[bucket]; i < g.offsets[bucket + 1]; ++i) {
      const Index e = g.entries[i];
      std::optional<Boundary_point> candidate;
      consider_edge(e, p, candidate);
      const auto& ends = m_domain.edge(e);
      const FT length2 = squared_length(m_domain.point(ends[0]), m_domain.point(ends[1]));
      if (candidate->squared_distance <= a * a * length2 + b * b &&
          (!best || candidate->squared_distance < best->squared_distance))
        best = std::move(candidate);
    }
    if (!best)
      return std::nullopt;
    return best->location;
  }

  /// returns `locate_snapped(p)`, trying the triangle `hint` first (the triangle of a
  /// previous, nearby query; `Domain::null_index` for none), then a few of the triangles a
  /// walk from it toward `p` crosses. Consecutive queries of a grid or of spatially sorted
  /// points often fall in the same triangle or a neighbour (Hilbert-sorted random queries:
  /// half in the same, a third in a neighbour), which then costs a test or two instead of
  /// a bucket's. A point on an edge or at a vertex of `hint` is located in `hint`, which is
  /// one of its incident triangles as `locate()` promises; a point on an edge the walk
  /// crosses is located in the triangle the walk reaches first.
  /// \param p the query point
  /// \param hint a face index, or `Domain::null_index`
  /// \returns the location, or `std::nullopt`
  std::optional<Location> locate_snapped(const Point_2& p, Index hint) const {
    if (hint < m_domain.number_of_faces() && CGAL::is_finite(p.x()) && CGAL::is_finite(p.y())) {
      // Across the first edge that has p on its right, at most walk_steps triangles: the
      // walk could circle in a triangulation that is not Delaunay, or stop at the boundary
      // of a non-convex domain; then the buckets decide.
      Index f = hint;
      for (int step = 0; step <= walk_steps; ++step) {
        int outside_edge = -1;
        if (std::optional<Location> location = locate_in(f, p, &outside_edge))
          return location;
        const auto& across = m_domain.edge_faces(m_domain.face_edge(f, outside_edge));
        f = across[0] == f ? across[1] : across[0];
        if (f == Domain::null_index)
          break;
      }
    }
    return locate_snapped(p);
  }

  /// returns the point of the domain boundary (outer boundaries and holes) nearest to `p`,
  /// whether `p` is inside the domain or not, or `std::nullopt` if `p` is not finite or the
  /// domain is empty. Distances are compared in `FT` (exactly for exact number types);
  /// the search visits rings of buckets around `p` and stops once no closer edge can lie
  /// in the next ring (\f$O(1)\f$ expected near the domain, \f$O(B)\f$ for far away
  /// points or very uneven boundaries, \f$B\f$ the number of boundary edges).
  /// \param p the query point
  /// \returns the nearest boundary point, or `std::nullopt`
  std::optional<Boundary_point> nearest_boundary_point(const Point_2& p) const {
    std::optional<Boundary_point> best;
    if (!CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y()) || m_boundary.offsets.empty())
      return best;
    const Edge_grid& g = m_boundary;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    // |p - z|^2 >= |p' - z|^2 + |p - p'|^2 for z in the grid box and p' the clamped p.
    const double cx = (std::min)((std::max)(x, g.xmin), g.xmax);
    const double cy = (std::min)((std::max)(y, g.ymin), g.ymax);
    const double outside2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
    const double cell =
        (std::min)((g.xmax - g.xmin) / double(g.nx), (g.ymax - g.ymin) / double(g.ny));
    const std::ptrdiff_t c0 = static_cast<std::ptrdiff_t>(g.column(cx));
    const std::ptrdiff_t r0 = static_cast<std::ptrdiff_t>(g.row(cy));
    const std::ptrdiff_t nx = static_cast<std::ptrdiff_t>(g.nx),
                         ny = static_cast<std::ptrdiff_t>(g.ny);
    const std::ptrdiff_t rings = (std::max)(nx, ny);
    for (std::ptrdiff_t r = 0; r <= rings; ++r) {
      for (std::ptrdiff_t j = r0 - r; j <= r0 + r; ++j) {
        if (j < 0 || j >= ny)
          continue;
        const bool full_row = j == r0 - r || j == r0 + r;
        for (std::ptrdiff_t i = c0 - r; i <= c0 + r;
             i += full_row ? 1 : 2 * (std::max)(r, std::ptrdiff_t(1))) {
          if (i < 0 || i >= nx)
            continue;
          const std::size_t bucket = static_cast<std::size_t>(j * nx + i);
          for (std::size_t k = g.offsets[bucket]; k < g.offsets[bucket + 1]; ++k)
            consider_edge(g.entries[k], p, best);
        }
      }
      // Cells of ring r + 1 are at least r cells away from p'. The slack covers the rounding
      // of the double bound (relative 1e-15), small enough that far queries still stop early.
      if (best) {
        const double bound = double(r) * cell;
        if (CGAL::to_double(best->squared_distance) * (1 + 1e-9) <= bound * bound + outside2)
          break;
      }
    }
    return best;
  }

  /// returns `true` iff `p` lies in the closed domain.
  /// \param p the query point
  /// \returns `true` iff `p` lies in the closed domain
  bool contains(const Point_2& p) const { return locate(p).has_value(); }

  /// returns the domain.
  /// \returns the domain
  const Domain& domain() const { return m_domain; }
  /// returns the number of buckets of the grid.
  /// \returns the number of buckets of the grid
  std::size_t number_of_buckets() const { return m_nx * m_ny; }
  /// returns the bucket of the grid that `p` falls in (row-major, in
  /// [0, `number_of_buckets()`)), or `number_of_buckets()` for a point outside the grid's box
  /// or not finite: a key for ordering queries so that neighbours come together.
  /// \param p the point
  /// \returns the bucket index, or `number_of_buckets()`
  std::size_t bucket(const Point_2& p) const {
    if (!CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y()))
      return number_of_buckets();
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    if (!(x >= m_xmin && x <= m_xmax && y >= m_ymin && y <= m_ymax))
      return number_of_buckets();
    return cell(x, y);
  }
  /// returns the number of (bucket, triangle) registrations.
  /// \returns the number of (bucket, triangle) registrations
  std::size_t number_of_entries() const { return m_entries.size(); }
  /// @}

private:
  // The triangles locate_snapped(p, hint) walks through beyond the hint before the buckets
  // decide (measured on Hilbert-sorted random queries: 84% are in the hint or a neighbour).
  static constexpr int walk_steps = 4;

  struct Box {
    double xmin, ymin, xmax, ymax;
  };

  // Inside-or-on test with exact orientations, then barycentric coordinates d_i / sum d_j
  // where d_i is twice the signed area of (p, opposite edge): exact for exact FT, and for
  // double each coordinate is in [0, 1] and a vertex gets exactly 1.
  // Outside, *outside_edge (if given) is the position of the vertex opposite the first edge
  // found to have p on its right (the face_edge() to cross toward p).
  std::optional<Location> locate_in(Index f, const Point_2& p, int* outside_edge = nullptr) const {
    const std::array<Index, 3>& t = m_domain.face(f);
    const Point_2& a = m_domain.point(t[0]);
    const Point_2& b = m_domain.point(t[1]);
    const Point_2& c = m_domain.point(t[2]);
    // the face is counter-clockwise: p is inside or on iff it is on no edge's right side
    std::array<FT, 3> d;
    const int outside = side(b, c, p, d[0]) == CGAL::RIGHT_TURN   ? 0
                        : side(c, a, p, d[1]) == CGAL::RIGHT_TURN ? 1
                        : side(a, b, p, d[2]) == CGAL::RIGHT_TURN ? 2
                                                                  : -1;
    if (outside >= 0) {
      if (outside_edge)
        *outside_edge = outside;
      return std::nullopt;
    }
    const FT sum = d[0] + d[1] + d[2];
    Location location{f, {{FT(0), FT(0), FT(0)}}};
    for (std::size_t i = 0; i < 3; ++i) {
      // rounding may make a positive area negative for a point almost on an edge
      if (d[i] > FT(0))
        location.barycentric[i] = d[i] / sum;
    }
    return location;
  }

  // The orientation of (a, b, p), and in `area` area2(a, b, p), or 0 if they are collinear.
  // In double, area2() is the determinant CGAL's static filter of Orientation_2 computes
  // (the same operations): its error bound decides the sign where it can (the exact
  // predicate where it cannot), and the orientation is not computed a second time (the
  // predicates were a quarter of the time of Hilbert-sorted queries).
  CGAL::Orientation side(const Point_2& a, const Point_2& b, const Point_2& p, FT& area) const {
    if constexpr (std::is_same_v<FT, double>) {
      const double pqx = b.x() - a.x(), pqy = b.y() - a.y(), prx = p.x() - a.x(),
                   pry = p.y() - a.y();
      area = pqx * pry - pqy * prx;
      double maxx = (std::max)(std::abs(pqx), std::abs(prx));
      double maxy = (std::max)(std::abs(pqy), std::abs(pry));
      if (maxx > maxy)
        std::swap(maxx, maxy);
      // (CGAL's bounds: no underflow below 1e-146, no overflow from 1e153)
      if (maxx >= 1e-146 && maxy < 1e153) {
        const double eps = 8.8872057372592798e-16 * maxx * maxy;
        if (area > eps)
          return CGAL::LEFT_TURN;
        if (area < -eps)
          return CGAL::RIGHT_TURN;
      }
    }
    const CGAL::Orientation o = m_domain.geom_traits().orientation_2_object()(a, b, p);
    if (o == CGAL::COLLINEAR)
      area = FT(0);
    else if constexpr (!std::is_same_v<FT, double>)
      area = area2(a, b, p);
    return o;
  }

  static FT squared_length(const Point_2& a, const Point_2& b) {
    const FT dx = b.x() - a.x(), dy = b.y() - a.y();
    const FT l2 = dx * dx + dy * dy;
    return l2;
  }

  // Keeps in `best` the nearer of it and the projection of p onto boundary edge e.
  void consider_edge(Index e, const Point_2& p, std::optional<Boundary_point>& best) const {
    const auto& ends = m_domain.edge(e);
    const Point_2& a = m_domain.point(ends[0]);
    const Point_2& b = m_domain.point(ends[1]);
    const FT ux = b.x() - a.x(), uy = b.y() - a.y();
    const FT dot = (p.x() - a.x()) * ux + (p.y() - a.y()) * uy;
    const FT length2 = ux * ux + uy * uy;
    // parameter t of the projection a + t (b - a), clamped to the edge
    FT t(0);
    if (dot >= length2)
      t = FT(1);
    else if (dot > FT(0))
      t = dot / length2;
    const FT qx = a.x() + t * ux, qy = a.y() + t * uy;
    const FT dx = p.x() - qx, dy = p.y() - qy;
    const FT d2 = dx * dx + dy * dy;
    if (best && !(d2 < best->squared_distance))
      return;
    const auto& faces = m_domain.edge_faces(e);
    const Index f = faces[0] != Domain::null_index ? faces[0] : faces[1];
    Location location{f, {{FT(0), FT(0), FT(0)}}};
    const auto& t3 = m_domain.face(f);
    for (std::size_t i = 0; i < 3; ++i) {
      if (t3[i] == ends[0])
        location.barycentric[i] = FT(1) - t;
      else if (t3[i] == ends[1])
        location.barycentric[i] = t;
    }
    best = Boundary_point{e, location, Point_2(qx, qy), d2};
  }

  static FT area2(const Point_2& a, const Point_2& b, const Point_2& c) {
    const FT area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    return area;
  }

  Box face_box(Index f) const {
    Box box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (Index v : m_domain.face(f)) {
      const double x = CGAL::to_double(m_domain.point(v).x());
      const double y = CGAL::to_double(m_domain.point(v).y());
      box.xmin = (std::min)(box.xmin, x);
      box.xmax = (std::max)(box.xmax, x);
      box.ymin = (std::min)(box.ymin, y);
      box.ymax = (std::max)(box.ymax, y);
    }
    return box;
  }

  std::size_t column(double x) const {
    const double c = std::floor((x - m_xmin) * m_inverse_width);
    if (!(c > 0))
      return 0;
    return (std::min)(static_cast<std::size_t>(c), m_nx - 1);
  }
  std::size_t row(double y) const {
    const double r = std::floor((y - m_ymin) * m_inverse_height);
    if (!(r > 0))
      return 0;
    return (std::min)(static_cast<std::size_t>(r), m_ny - 1);
  }
  std::size_t cell(double x, double y) const { return row(y) * m_nx + column(x); }

  void set_grid(std::size_t nx, std::size_t ny) {
    m_nx = (std::max)(nx, std::size_t(1));
    m_ny = (std::max)(ny, std::size_t(1));
    m_inverse_width = double(m_nx) / (m_xmax - m_xmin);
    m_inverse_height = double(m_ny) / (m_ymax - m_ymin);
  }

  std::size_t count_entries(const std::vector<Box>& boxes) const {
    std::size_t total = 0;
    for (const Box& b : boxes)
      total += (column(b.xmax) - column(b.xmin) + 1) * (row(b.ymax) - row(b.ymin) + 1);
    return total;
  }

  void build() {
    const std::size_t faces = m_domain.number_of_faces();
    std::vector<Box> boxes(faces);
    m_xmin = m_ymin = HUGE_VAL;
    m_xmax = m_ymax = -HUGE_VAL;
    for (std::size_t f = 0; f < faces; ++f) {
      boxes[f] = face_box(static_cast<Index>(f));
      m_xmin = (std::min)(m_xmin, boxes[f].xmin);
      m_xmax = (std::max)(m_xmax, boxes[f].xmax);
      m_ymin = (std::min)(m_ymin, boxes[f].ymin);
      m_ymax = (std::max)(m_ymax, boxes[f].ymax);
    }
    // If to_double is monotone (exact for double, truncation for Exact_rational), a point
    // in a triangle rounds into the rounded box of the triangle and the bucket computation
    // (monotone too) finds it: no widening. Otherwise (e.g. lazy numbers, whose to_double
    // is the midpoint of an interval) widen every box by far more than the rounding, so
    // that a triangle containing a query is registered in the bucket of the rounded query.
    // Widening registers the triangles of an axis-aligned grid in the neighbouring buckets
    // too, which costs a factor of about 3 in entries and query time.
    constexpr bool monotone =
        std::is_floating_point<FT>::value || std::is_same<FT, CGAL::Exact_rational>::value;
    const double size = (std::max)(m_xmax - m_xmin, m_ymax - m_ymin);
    const double largest =
        (std::max)({std::abs(m_xmin), std::abs(m_xmax), std::abs(m_ymin), std::abs(m_ymax)});
    const double margin =
        monotone ? 0.0 : size * 1e-12 + largest * 1e-13 + (std::numeric_limits<double>::min)();
    for (Box& b : boxes) {
      b.xmin -= margin;
      b.ymin -= margin;
      b.xmax += margin;
      b.ymax += margin;
    }
    m_xmin -= margin;
    m_ymin -= margin;
    m_xmax += margin;
    m_ymax += margin;

    // About two triangles per bucket, cells roughly square. (Rounding to double may flatten
    // the box of a tiny exact domain: then one row or column, and column() and row() map
    // the NaN of 0 * infinity to 0.)
    const double width = (std::max)(m_xmax - m_xmin, (std::numeric_limits<double>::min)());
    const double height = (std::max)(m_ymax - m_ymin, (std::numeric_limits<double>::min)());
    const double buckets = (std::max)(1.0, double(faces) / 2);
    double nx = std::sqrt(buckets * width / height);
    double ny = std::sqrt(buckets * height / width);
    nx = (std::min)((std::max)(1.0, std::round(nx)), buckets);
    ny = (std::min)((std::max)(1.0, std::round(ny)), buckets);
    set_grid(static_cast<std::size_t>(nx), static_cast<std::size_t>(ny));
    // Long thin triangles cover many buckets: coarsen until the entries stay linear.
    const std::size_t limit = 8 * faces + 16;
    while (m_nx * m_ny > 1 && count_entries(boxes) > limit)
      set_grid(m_nx / 2, m_ny / 2);

    // Two passes (count, fill) into flat arrays: no per-bucket allocation.
    m_offsets.assign(m_nx * m_ny + 1, 0);
    for (const Box& b : boxes)
      for (std::size_t r = row(b.ymin), r1 = row(b.ymax); r <= r1; ++r)
        for (std::size_t c = column(b.xmin), c1 = column(b.xmax); c <= c1; ++c)
          ++m_offsets[r * m_nx + c + 1];
    for (std::size_t i = 1; i < m_offsets.size(); ++i)
      m_offsets[i] += m_offsets[i - 1];
    m_entries.resize(m_offsets.back());
    std::vector<std::size_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for (std::size_t f = 0; f < faces; ++f) {
      const Box& b = boxes[f];
      for (std::size_t r = row(b.ymin), r1 = row(b.ymax); r <= r1; ++r)
        for (std::size_t c = column(b.xmin), c1 = column(b.xmax); c <= c1; ++c)
          m_entries[fill[r * m_nx + c]++] = static_cast<Index>(f);
    }
    build_boundary_grid(margin);
  }

  // A bucket grid of the boundary edges alone, each registered with its box widened by
  // more than the snapping tolerance, so that snapping looks at one bucket.
  void build_boundary_grid(double margin) {
    std::vector<Index> edges;
    m_largest_coordinate = 0;
    for (const Point_2& p : m_domain.points())
      m_largest_coordinate = (std::max)({m_largest_coordinate, std::abs(CGAL::to_double(p.x())),
                                         std::abs(CGAL::to_double(p.y()))});
    for (std::size_t e = 0; e < m_domain.number_of_edges(); ++e)
      if (m_domain.is_boundary_edge(static_cast<Index>(e)))
        edges.push_back(static_cast<Index>(e));
    if (edges.empty())
      return;
    Edge_grid& g = m_boundary;
    std::vector<Box> boxes(edges.size());
    g.xmin = g.ymin = HUGE_VAL;
    g.xmax = g.ymax = -HUGE_VAL;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const auto& ends = m_domain.edge(edges[k]);
      const double x0 = CGAL::to_double(m_domain.point(ends[0]).x());
      const double y0 = CGAL::to_double(m_domain.point(ends[0]).y());
      const double x1 = CGAL::to_double(m_domain.point(ends[1]).x());
      const double y1 = CGAL::to_double(m_domain.point(ends[1]).y());
      // twice the tolerance (the sum bounds the root of the sum of squares), plus rounding
      const double widen = 2 * snap_edge_tolerance * std::hypot(x1 - x0, y1 - y0) +
                           2 * snap_coordinate_tolerance * m_largest_coordinate + margin +
                           (std::numeric_limits<double>::min)();
      Box& b = boxes[k];
      b = Box{(std::min)(x0, x1) - widen, (std::min)(y0, y1) - widen, (std::max)(x0, x1) + widen,
              (std::max)(y0, y1) + widen};
      g.xmin = (std::min)(g.xmin, b.xmin);
      g.ymin = (std::min)(g.ymin, b.ymin);
      g.xmax = (std::max)(g.xmax, b.xmax);
      g.ymax = (std::max)(g.ymax, b.ymax);
    }
    const double width = g.xmax - g.xmin, height = g.ymax - g.ymin;
    const double buckets = (std::max)(1.0, double(edges.size()));
    double nx = std::sqrt(buckets * width / height), ny = std::sqrt(buckets * height / width);
    nx = (std::min)((std::max)(1.0, std::round(nx)), buckets);
    ny = (std::min)((std::max)(1.0, std::round(ny)), buckets);
    g.set_grid(static_cast<std::size_t>(nx), static_cast<std::size_t>(ny));
    const auto count = [&]() {
      std::size_t total = 0;
      for (const Box& b : boxes)
        total += (g.column(b.xmax) - g.column(b.xmin) + 1) * (g.row(b.ymax) - g.row(b.ymin) + 1);
      return total;
    };
    // A boundary edge spans about one bucket; long diagonal edges span many: stay linear.
    while (g.nx * g.ny > 1 && count() > 8 * edges.size() + 16)
      g.set_grid(g.nx / 2, g.ny / 2);
    g.offsets.assign(g.nx * g.ny + 1, 0);
    for (const Box& b : boxes)
      for (std::size_t r = g.row(b.ymin), r1 = g.row(b.ymax); r <= r1; ++r)
        for (std::size_t c = g.column(b.xmin), c1 = g.column(b.xmax); c <= c1; ++c)
          ++g.offsets[r * g.nx + c + 1];
    for (std::size_t i = 1; i < g.offsets.size(); ++i)
      g.offsets[i] += g.offsets[i - 1];
    g.entries.resize(g.offsets.back());
    std::vector<std::size_t> fill(g.offsets.begin(), g.offsets.end() - 1);
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const Box& b = boxes[k];
      for (std::size_t r = g.row(b.ymin), r1 = g.row(b.ymax); r <= r1; ++r)
        for (std::size_t c = g.column(b.xmin), c1 = g.column(b.xmax); c <= c1; ++c)
          g.entries[fill[r * g.nx + c]++] = edges[k];
    }
  }

  // The grid of boundary edges (its own extent and size: snapping and nearest points).
  struct Edge_grid {
    double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
    double inverse_width = 0, inverse_height = 0;
    std::size_t nx = 1, ny = 1;
    std::vector<std::size_t> offsets; // empty: no boundary
    std::vector<Index> entries;

    std::size_t column(double x) const {
      const double c = std::floor((x - xmin) * inverse_width);
      return !(c > 0) ? 0 : (std::min)(static_cast<std::size_t>(c), nx - 1);
    }
    std::size_t row(double y) const {
      const double r = std::floor((y - ymin) * inverse_height);
      return !(r > 0) ? 0 : (std::min)(static_cast<std::size_t>(r), ny - 1);
    }
    void set_grid(std::size_t x, std::size_t y) {
      nx = (std::max)(x, std::size_t(1));
      ny = (std::max)(y, std::size_t(1));
      inverse_width = double(nx) / (xmax - xmin);
      inverse_height = double(ny) / (ymax - ymin);
    }
  };

  const Domain& m_domain;
  Edge_grid m_boundary;
  double m_largest_coordinate = 0;
  double m_xmin = 0, m_ymin = 0, m_xmax = 0, m_ymax = 0;
  double m_inverse_width = 0, m_inverse_height = 0;
  std::size_t m_nx = 1, m_ny = 1;
  std::vector<std::size_t> m_offsets;
  std::vector<Index> m_entries;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_DOMAIN_LOCATOR_H

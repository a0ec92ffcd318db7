// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_CERTIFICATE_H
#define CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_CERTIFICATE_H

#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineXu
  \brief the continuity of one edge of a pseudo-AG\f$^1\f$ surface (AG1.md §6 M3).

  Diamond \f$D_i\f$ has \f$i\f$ copies of \f$r\f$ (the source of `canonical_halfedge(e)`); \f$D_0\f$
  and \f$D_4\f$ are the end diamonds of the corner regions, \f$D_1..D_3\f$ the middle diamonds.
*/
struct Pseudo_AG1_edge_certificate {
  bool c0 = false; ///< the six boundary control points agree (3.4)
  std::array<bool, 5> diamonds{{false, false, false, false, false}}; ///< \f$D_i\f$ meets \f$R_e\f$
  bool middle = false; ///< \f$D_1, D_2, D_3\f$ meet \f$R_e\f$: pseudo-AG\f$^1\f$
  bool ag1 = false;    ///< all five meet \f$R_e\f$: AG\f$^1\f$ (tangent planes agree)
  /// \f$\lambda_e < 0\f$: an affine reparameterization puts the apexes on opposite sides of the
  /// edge (Xu Def. 5.3.2 (2)); only then is `join_order` computed
  bool admissible = false;
  /// the order achieved by `check_C1_join()` on the reparameterized pair (-1: not \f$C^0\f$;
  /// -2: not computed, the edge is inadmissible)
  int join_order = -2;
  double max_residual = 0; ///< the largest coordinate of any difference
};

/*!
  \ingroup PkgTriangularSplineXu
  \brief the certificate of a pseudo-AG\f$^1\f$ surface: exact verdicts when the surface is
  exact (`Pseudo_AG1_surface::is_exact()`), residuals against a tolerance otherwise.
*/
struct Pseudo_AG1_certificate {
  bool exact = false;                 ///< the verdicts are exact (a proof)
  double tolerance = 0;               ///< absolute tolerance of the verdicts (0 when exact)
  std::size_t edges = 0;              ///< number of edges
  std::size_t c0_edges = 0;           ///< edges where (3.4) holds
  std::size_t middle_edges = 0;       ///< edges whose three middle diamonds share \f$R_e\f$
  std::size_t ag1_edges = 0;          ///< edges whose five diamonds share \f$R_e\f$
  std::size_t inadmissible_edges = 0; ///< edges with \f$\lambda_e \ge 0\f$
  std::size_t vertices = 0;           ///< number of vertices
  std::size_t coplanar_vertices = 0;  ///< corner point and stars on the corner plane
  /// vertices where every corner normal is a positive multiple of \f$N_v\f$: the patches
  /// share the tangent plane there, consistently oriented (\f$G^1\f$ at the vertex)
  std::size_t g1_vertices = 0;
  double max_edge_residual = 0; ///< largest diamond or \f$C^0\f$ residual
  double max_coplanarity = 0;   ///< largest \f$|\langle S - z_v, \hat N_v\rangle|\f$
  std::vector<Pseudo_AG1_edge_certificate> per_edge; ///< by edge index

  /// `true` iff every edge is \f$C^0\f$ with its middle diamonds on one relation and every
  /// vertex is \f$G^1\f$: the surface is pseudo-AG\f$^1\f$ (AG1.md R-3)
  bool pseudo_AG1() const {
    return c0_edges == edges && middle_edges == edges && g1_vertices == vertices &&
           coplanar_vertices == vertices;
  }
};

/*!
  \ingroup PkgTriangularSplineXu
  \brief certifies a pseudo-AG\f$^1\f$ surface from the control nets of its patches (`patch(f)`),
  not from the construction's internal slots, so that an assembly error would show.

  Per edge: the order-0 conditions (3.4) and the five diamonds (3.5) with the edge's relation;
  for admissible edges also `check_C1_join()` on the pair reparameterized over
  \f$r = (0,0), s = (1,0), p = (0,1), q^* = (\nu, \lambda)\f$ (Lemma 5.3.3: the nets stay
  unchanged). Per vertex: coplanarity and the orientation of every corner normal.
  \tparam Surface `Pseudo_AG1_surface<Kernel>`, or any class with its `mesh()`, `control_net()`,
  `edge_relation()`, `corner_plane()`, `star()` and `is_exact()` (e.g. a wrapper that edits
  a surface)
  \param surface the surface
  \param tolerance the absolute tolerance for inexact surfaces; negative: \f$10^{-10}\f$ times
  the bounding-box diagonal of the input. Ignored (0) for exact surfaces.
  \returns the certificate
*/
template <class Surface>
Pseudo_AG1_certificate certify_pseudo_AG1(const Surface& surface, double tolerance = -1) {
  using Kernel = typename Surface::Geom_traits;
  using FT = typename Kernel::FT;
  using Vector_3 = typename Kernel::Vector_3;
  using Point_2 = typename Kernel::Point_2;
  const auto& mesh = surface.mesh();
  Pseudo_AG1_certificate c;
  c.exact = surface.is_exact();
  if (c.exact) {
    tolerance = 0;
  } else if (tolerance < 0) {
    const auto box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
    const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
                 dz = box.zmax() - box.zmin();
    tolerance = 1e-10 * std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  c.tolerance = tolerance;
  c.edges = mesh.number_of_edges();
  c.vertices = mesh.number_of_vertices();
  c.per_edge.resize(c.edges);
  auto size = [](const Vector_3& d) {
    double m = 0;
    for (int i = 0; i < 3; ++i)
      m = std::max(m, std::abs(CGAL::to_double(d[i])));
    return m;
  };
  auto is_zero = [&](const Vector_3& d) {
    return c.exact ? d == CGAL::NULL_VECTOR : size(d) <= tolerance;
  };
  // local index of vertex v in face f (vertices_around_face order)
  auto local = [&](typename Surface::Face_index f, typename Surface::Vertex_index v) {
    const auto h0 = mesh.halfedge(f);
    if (mesh.target(h0) == v)
      return 0;
    return mesh.target(mesh.next(h0)) == v ? 1 : 2;
  };
  for (auto e : mesh.edges()) {
    Pseudo_AG1_edge_certificate& E = c.per_edge[e];
    const auto h = canonical_halfedge(e, mesh), o = mesh.opposite(h);
    const auto r = mesh.source(h), s = mesh.target(h);
    const auto p = mesh.target(mesh.next(h)), q = mesh.target(mesh.next(o));
    const auto A = mesh.face(h), B = mesh.face(o);
    const std::vector<Vector_3> netA = surface.control_net(A), netB = surface.control_net(B);
    const std::array<int, 3> la{{local(A, p), local(A, r), local(A, s)}},
        lb{{local(B, q), local(B, r), local(B, s)}};
    auto point = [](const std::vector<Vector_3>& net, const std::array<int, 3>& l, int g, int i) {
      Multi_index index;
      index[l[0]] = g;
      index[l[1]] = i;
      index[l[2]] = 5 - g - i;
      return net[linear_index(index)];
    };
    const auto& R = surface.edge_relation(e).relation;
    E.c0 = true;
    for (int i = 0; i <= 5; ++i) {
      const Vector_3 d = point(netB, lb, 0, i) - point(netA, la, 0, i);
      E.max_residual = std::max(E.max_residual, size(d));
      E.c0 = E.c0 && is_zero(d);
    }
    for (int i = 0; i <= 4; ++i) {
      const Vector_3 d =
          point(netB, lb, 1, i) - (R[0] * point(netA, la, 1, i) + R[1] * point(netA, la, 0, i + 1) +
                                   R[2] * point(netA, la, 0, i));
      E.max_residual = std::max(E.max_residual, size(d));
      E.diamonds[std::size_t(i)] = is_zero(d);
    }
    E.middle = E.c0 && E.diamonds[1] && E.diamonds[2] && E.diamonds[3];
    E.ag1 = E.middle && E.diamonds[0] && E.diamonds[4];
    E.admissible = R[0] < FT(0);
    if (E.admissible) {
      // the pair over r = (0,0), s = (1,0), p = (0,1), q* = (nu, lambda)
      std::array<Point_2, 3> da, db;
      const std::array<typename Surface::Vertex_index, 3> ca{
          {mesh.target(mesh.halfedge(A)), mesh.target(mesh.next(mesh.halfedge(A))),
           mesh.source(mesh.halfedge(A))}},
          cb{{mesh.target(mesh.halfedge(B)), mesh.target(mesh.next(mesh.halfedge(B))),
              mesh.source(mesh.halfedge(B))}};
      auto where = [&](typename Surface::Vertex_index v) {
        if (v == r)
          return Point_2(0, 0);
        if (v == s)
          return Point_2(1, 0);
        if (v == p)
          return Point_2(0, 1);
        return Point_2(R[2], R[0]);
      };
      for (std::size_t a = 0; a < 3; ++a) {
        da[a] = where(ca[a]);
        db[a] = where(cb[a]);
      }
      const Bezier_triangle<Kernel, Vector_3> PA(5, da[0], da[1], da[2], netA),
          PB(5, db[0], db[1], db[2], netB);
      E.join_order = check_C1_join(PA, PB, tolerance).achieved_order;
    } else {
      ++c.inadmissible_edges;
    }
    c.c0_edges += E.c0;
    c.middle_edges += E.middle;
    c.ag1_edges += E.ag1;
    c.max_edge_residual = std::max(c.max_edge_residual, E.max_residual);
  }
  for (auto v : mesh.vertices()) {
    const auto& plane = surface.corner_plane(v);
    const Vector_3& N = plane.normal;
    const double unit = std::sqrt(CGAL::to_double(N.squared_length()));
    bool coplanar = true, g1 = true;
    const auto ring = outgoing_ring(v, mesh);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vector_3 a = surface.star(ring[i]) - plane.corner;
      const Vector_3 b = surface.star(ring[(i + 1) % ring.size()]) - plane.corner;
      const FT d = a * N;
      c.max_coplanarity = std::max(c.max_coplanarity, std::abs(CGAL::to_double(d)) / unit);
      coplanar =
          coplanar && (c.exact ? d == FT(0) : std::abs(CGAL::to_double(d)) / unit <= tolerance);
      const Vector_3 n = CGAL::cross_product(a, b);
      const bool parallel = c.exact
                                ? CGAL::cross_product(n, N) == CGAL::NULL_VECTOR
                                : size(CGAL::cross_product(n, N)) <=
                                      1e-9 * std::sqrt(CGAL::to_double(n.squared_length())) * unit;
      g1 = g1 && parallel && n * N > FT(0);
    }
    c.coplanar_vertices += coplanar;
    c.g1_vertices += g1;
  }
  return c;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_CERTIFICATE_H

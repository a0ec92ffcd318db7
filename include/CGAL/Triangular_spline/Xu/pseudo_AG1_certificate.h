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
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
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
  double max_residual = 0;    ///< the largest coordinate of any difference (all five diamonds)
  double middle_residual = 0; ///< the same over the \f$C^0\f$ conditions and middle diamonds
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
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

  /// \returns `true` iff every edge is \f$C^0\f$ with its middle diamonds on one relation and
  /// every vertex is \f$G^1\f$: the surface is pseudo-AG\f$^1\f$ (AG1.md R-3)
  bool pseudo_AG1() const {
    return c0_edges == edges && middle_edges == edges && g1_vertices == vertices &&
           coplanar_vertices == vertices;
  }
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
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
  \param tolerance the absolute tolerance; negative: exact verdicts for exact surfaces and
  \f$10^{-10}\f$ times the bounding-box diagonal of the input otherwise. A positive tolerance
  makes every verdict a tolerance verdict, never a proof.
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
  c.exact = surface.is_exact() && tolerance <= 0;
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
      E.middle_residual = std::max(E.middle_residual, size(d));
      E.c0 = E.c0 && is_zero(d);
    }
    for (int i = 0; i <= 4; ++i) {
      const Vector_3 d =
          point(netB, lb, 1, i) - (R[0] * point(netA, la, 1, i) + R[1] * point(netA, la, 0, i + 1) +
                                   R[2] * point(netA, la, 0, i));
      E.max_residual = std::max(E.max_residual, size(d));
      if (i >= 1 && i <= 3)
        E.middle_residual = std::max(E.middle_residual, size(d));
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

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief a quintic surface over a closed mesh (e.g. a `Surface_file`) seen through the
  quantities `certify_pseudo_AG1()` reads, all recovered from the control nets alone: the edge
  relations from the middle diamonds, the corner points and planes from the corner regions.

  The relation of an edge is solved exactly from its first non-degenerate middle diamond
  (\f$D_3\f$, then \f$D_1\f$, then \f$D_2\f$); the certificate then checks every diamond against
  it, so a verdict on a file does not trust anything the file does not contain.
  \tparam Surface a class with `mesh()`, `degree()` and `control_net(f)` (in
  `vertices_around_face` order) over a kernel `Geom_traits`
*/
template <class Surface>
class Pseudo_AG1_view {
public:
  /// the kernel
  using Geom_traits = typename Surface::Geom_traits;
  /// the mesh
  using Mesh = std::decay_t<decltype(std::declval<const Surface&>().mesh())>;
  /// face index
  using Face_index = typename Mesh::Face_index;
  /// vertex index
  using Vertex_index = typename Mesh::Vertex_index;
  /// halfedge index
  using Halfedge_index = typename Mesh::Halfedge_index;
  /// edge index
  using Edge_index = typename Mesh::Edge_index;

  /// the view of `surface` (kept by reference)
  /// \param surface the surface
  /// \throws Invalid_input if the patches are not quintic
  explicit Pseudo_AG1_view(const Surface& surface) : m_surface(surface) {
    using FT = typename Geom_traits::FT;
    using Vector_3 = typename Geom_traits::Vector_3;
    if (surface.degree() != 5)
      throw Invalid_input("pseudo-AG1 certificate: the patches have degree " +
                          std::to_string(surface.degree()) + ", not 5");
    const Mesh& mesh = surface.mesh();
    m_edges.resize(mesh.number_of_edges());
    m_relation_found.assign(mesh.number_of_edges(), false);
    auto local = [&](Face_index f, Vertex_index v) {
      const auto h0 = mesh.halfedge(f);
      if (mesh.target(h0) == v)
        return 0;
      return mesh.target(mesh.next(h0)) == v ? 1 : 2;
    };
    for (auto e : mesh.edges()) {
      const auto h = canonical_halfedge(e, mesh), o = mesh.opposite(h);
      const auto A = mesh.face(h), B = mesh.face(o);
      const std::array<int, 3> la{{local(A, mesh.target(mesh.next(h))), local(A, mesh.source(h)),
                                   local(A, mesh.target(h))}},
          lb{{local(B, mesh.target(mesh.next(o))), local(B, mesh.source(h)),
              local(B, mesh.target(h))}};
      const auto& netA = surface.control_net(A);
      const auto& netB = surface.control_net(B);
      auto point = [](const auto& net, const std::array<int, 3>& l, int g, int i) {
        Multi_index index;
        index[l[0]] = g;
        index[l[1]] = i;
        index[l[2]] = 5 - g - i;
        return net[linear_index(index)];
      };
      m_edges[e].relation = {{FT(-1), FT(1), FT(1)}};
      for (int i : {3, 1, 2}) {
        const Vector_3 base = point(netA, la, 0, i);
        const Vector_3 u = point(netA, la, 1, i) - base, v = point(netA, la, 0, i + 1) - base,
                       y = point(netB, lb, 1, i) - base;
        // y = lambda u + mu v, solved on the coordinate pair of largest determinant: for
        // consistent exact data every nonzero one gives the same answer; for rounded data
        // the largest is the best conditioned
        int best = -1;
        FT best_det(0);
        for (int a = 0; a < 3; ++a) {
          const int b = (a + 1) % 3;
          const FT det = u[a] * v[b] - u[b] * v[a];
          if (CGAL::abs(det) > CGAL::abs(best_det))
            best = a, best_det = det;
        }
        if (best >= 0) {
          const int a = best, b = (a + 1) % 3;
          const FT lambda = (y[a] * v[b] - y[b] * v[a]) / best_det;
          const FT mu = (u[a] * y[b] - u[b] * y[a]) / best_det;
          m_edges[e].relation = {{lambda, mu, FT(1) - lambda - mu}};
          m_relation_found[e] = true;
        }
        if (m_relation_found[e])
          break;
      }
    }
    m_planes.resize(mesh.number_of_vertices());
    m_star.resize(mesh.number_of_halfedges());
    for (auto h : mesh.halfedges()) {
      const Face_index f = mesh.face(h);
      Multi_index index;
      index[local(f, mesh.source(h))] = 4;
      index[local(f, mesh.target(h))] = 1;
      m_star[h] = surface.control_net(f)[linear_index(index)];
      Multi_index corner;
      corner[local(f, mesh.source(h))] = 5;
      m_planes[mesh.source(h)].corner = surface.control_net(f)[linear_index(corner)];
    }
    for (auto v : mesh.vertices()) {
      const auto ring = outgoing_ring(v, mesh);
      auto& plane = m_planes[v];
      plane.normal = CGAL::NULL_VECTOR;
      for (std::size_t i = 0; i < ring.size() && plane.normal == CGAL::NULL_VECTOR; ++i)
        plane.normal = CGAL::cross_product(m_star[ring[i]] - plane.corner,
                                           m_star[ring[(i + 1) % ring.size()]] - plane.corner);
    }
  }

  /// \returns the mesh
  const Mesh& mesh() const { return m_surface.mesh(); }
  /// \param f a face
  /// \returns the net of `f`
  decltype(auto) control_net(Face_index f) const { return m_surface.control_net(f); }
  /// \param e an edge
  /// \returns the relation solved from the middle diamonds of `e`
  const Pseudo_AG1_edge<typename Geom_traits::FT>& edge_relation(Edge_index e) const {
    return m_edges[e];
  }
  /// \param e an edge
  /// \returns `false` if every middle diamond of `e` is degenerate (no relation determined)
  bool relation_determined(Edge_index e) const { return m_relation_found[e]; }
  /// \param v a vertex
  /// \returns the corner point and a normal of the corner triangle at `v`
  const Corner_plane<Geom_traits>& corner_plane(Vertex_index v) const { return m_planes[v]; }
  /// \param h a halfedge
  /// \returns the star point of `h`
  const typename Geom_traits::Vector_3& star(Halfedge_index h) const { return m_star[h]; }
  /// \returns `true` iff the number type is exact (the verdicts are then exact)
  bool is_exact() const {
    return CGAL::Algebraic_structure_traits<typename Geom_traits::FT>::Is_exact::value;
  }

private:
  const Surface& m_surface;
  std::vector<Pseudo_AG1_edge<typename Geom_traits::FT>> m_edges;
  std::vector<bool> m_relation_found;
  std::vector<Corner_plane<Geom_traits>> m_planes;
  std::vector<typename Geom_traits::Vector_3> m_star;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_CERTIFICATE_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_AG1_SYSTEM_H
#define CGAL_TRIANGULAR_SPLINE_XU_AG1_SYSTEM_H

// The global AG^1 system of Xu §6.1 in the (3.5) form of AG1.md §5.2 (Resolution R-27), and
// the walking solver of §6.1.2: the first umbrella fixes the relations of its edges, which fix
// the next umbrellas, and so on.

#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/Xu/Umbrella.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/ag1_vertex_solve.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the affine relation \f$q = \lambda p + \mu r + \nu s\f$, \f$\lambda + \mu + \nu = 1\f$, of
  the domain diamond of an edge after reparameterization (Xu (3.5), AG1.md §1.2).

  For edge `e` the orientation is that of `mesh.halfedge(e, 0)` (see
  `is_reference_halfedge()`): \f$r\f$ = its source, \f$s\f$ = its
  target, \f$p\f$ = the apex of its face, \f$q\f$ = the apex of the opposite face. Def. 5.3.2 (2)
  (the reparameterized faces lie on opposite sides of the edge) is \f$\lambda < 0\f$.
  \tparam FT a field number type
*/
template <class FT>
struct Edge_relation {
  FT lambda; ///< coefficient of the apex \f$p\f$
  FT mu;     ///< coefficient of the source \f$r\f$
  FT nu;     ///< coefficient of the target \f$s\f$
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the result of `walk_AG1_system()`.

  Vertices and edges are indexed by `std::size_t(v)` / `std::size_t(e)`. Vertices the walk did
  not solve (after a degenerate stop, or in another connected component) have an empty
  umbrella and a NaN residual; edges without a relation have `has_relation[e] == false`.
  \tparam FT the number type of the umbrellas and relations
*/
template <class FT>
struct AG1_walk {
  /// by vertex: the umbrella (in the gauge of the walk, see `walk_AG1_system()`)
  std::vector<Umbrella<FT>> umbrellas;
  /// by edge: the relation, in the orientation of `mesh.halfedge(e, 0)`
  std::vector<Edge_relation<FT>> relations;
  /// by edge: whether `relations[e]` was set
  std::vector<bool> has_relation;
  /// by vertex: the least-squares residual (Frobenius norm) of its equations (E); 0 exactly
  /// when they are consistent and the number type is exact; NaN if not solved
  std::vector<double> residuals;
  /// the vertices in the order they were solved (breadth first); a degenerate vertex is last
  std::vector<std::size_t> order;
  /// every solved vertex satisfies its equations (exactly, or within the tolerance for
  /// inexact number types)
  bool consistent = true;
  /// every vertex of the start's connected component was solved (no degenerate stop)
  bool complete = true;
  /// the vertex where the walk stopped: a corner triangle of its umbrella is degenerate,
  /// or every solution of its equations makes the gauge spokes collinear (at most one)
  std::vector<std::size_t> degenerate_vertices;
  /// vertices whose equations left freedom after the gauge (closest to the reference chosen)
  std::vector<std::size_t> under_determined_vertices;
  /// vertices whose equations have no exact solution (least-squares solution used)
  std::vector<std::size_t> inconsistent_vertices;
  /// edges with \f$\lambda \ge 0\f$: they violate Def. 5.3.2 (2)
  std::vector<std::size_t> inadmissible_edges;
  /// edges whose domain diamond \f$(p, r, q, s)\f$ is not strictly convex, i.e. not
  /// (\f$\lambda < 0\f$, \f$\mu > 0\f$, \f$\nu > 0\f$); contains the inadmissible edges
  std::vector<std::size_t> non_convex_edges;
  /// edges with \f$\mu = 0\f$ or \f$\nu = 0\f$ (the apexes collinear with one end in the
  /// domain, a degenerate frame of Xu §4.4.4): the propagation of the edge diamonds
  /// \f$D_1, D_3\f$ (AG1.md §1.3) divides by them, so a surface cannot be built on them as is.
  /// Inexact number types: \f$|\mu|\f$ or \f$|\nu|\f$ at most `tolerance` times the largest
  /// \f$|\text{coefficient}|\f$ (at least 1); the signs of the two lists above are not filtered
  std::vector<std::size_t> degenerate_frame_edges;
  /// solved vertices whose umbrella is folded (see `is_folded_umbrella()`): the corner
  /// region cannot be a G^1 fan around the corner point (AG1.md §2)
  std::vector<std::size_t> folded_vertices;
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns the relation of the same diamond read in the opposite orientation of its edge.

  Swapping \f$r \leftrightarrow s\f$ swaps the apexes: \f$p = (q - \mu r - \nu s)/\lambda\f$, so
  \f$(\lambda, \mu, \nu) \mapsto (1/\lambda, -\nu/\lambda, -\mu/\lambda)\f$ (an involution).
  \tparam FT a field number type
  \param relation the relation in one orientation
  \throws Invalid_input if \f$\lambda = 0\f$ (\f$q\f$ on the line \f$rs\f$: no relation back)
  \returns the relation in the other orientation
*/
template <class FT>
Edge_relation<FT> reversed_relation(const Edge_relation<FT>& relation) {
  if (CGAL::is_zero(relation.lambda))
    throw Invalid_input("AG1 system: a relation with lambda = 0 cannot be reversed");
  const FT inverse = FT(1) / relation.lambda;
  return Edge_relation<FT>{inverse, FT(-relation.nu * inverse), FT(-relation.mu * inverse)};
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief tells whether `h` is the halfedge that orients its edge: `halfedge(e, 0)`, i.e. the
  halfedge of `e` as enumerated by `mesh.edges()`.

  Beware: in CGAL 5.5 `Surface_mesh::edge(h)` keeps `h` inside the edge index, so that
  `mesh.halfedge(mesh.edge(h)) == h` for *both* halfedges of an edge; comparing with
  `halfedge(edge(h))` therefore does not tell the orientation. All relations of this file are
  in the orientation of `halfedge(e, 0)`.
  \tparam Point_3 the point type of the mesh
  \param mesh the mesh
  \param h a halfedge
  \returns whether the source of `h` is \f$r\f$ of its edge
*/
template <class Point_3>
bool is_reference_halfedge(const CGAL::Surface_mesh<Point_3>& mesh,
                           typename CGAL::Surface_mesh<Point_3>::Halfedge_index h) {
  return mesh.halfedge(mesh.edge(h), 0) == h;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns the relation of the edge of `h` in the orientation of `h` (source of `h` =
  \f$r\f$).
  \tparam FT a field number type
  \tparam Point_3 the point type of the mesh
  \param mesh the mesh
  \param relations the relations by edge index, in the orientation of `mesh.halfedge(e, 0)`
  \param h a halfedge
  \returns `relations[edge(h)]`, reversed unless `is_reference_halfedge(mesh, h)`
*/
template <class FT, class Point_3>
Edge_relation<FT> oriented_relation(const CGAL::Surface_mesh<Point_3>& mesh,
                                    const std::vector<Edge_relation<FT>>& relations,
                                    typename CGAL::Surface_mesh<Point_3>::Halfedge_index h) {
  const auto e = mesh.edge(h);
  const Edge_relation<FT>& relation = relations.at(std::size_t(e));
  return is_reference_halfedge(mesh, h) ? relation : reversed_relation(relation);
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief computes the affine (barycentric) coordinates of `x` with respect to the triangle
  (`a`, `b`, `c`) by 2×2 determinants (Xu §4.2).
  \tparam FT a field number type
  \param x the point
  \param a,b,c the triangle
  \returns \f$(\alpha, \beta, \gamma)\f$ with \f$x = \alpha a + \beta b + \gamma c\f$,
  \f$\alpha + \beta + \gamma = 1\f$, or nothing if the triangle is degenerate (exactly)
*/
template <class FT>
std::optional<std::array<FT, 3>>
affine_coordinates(const std::array<FT, 2>& x, const std::array<FT, 2>& a,
                   const std::array<FT, 2>& b, const std::array<FT, 2>& c) {
  const FT d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (CGAL::is_zero(d))
    return std::nullopt;
  const FT beta = ((x[0] - a[0]) * (c[1] - a[1]) - (x[1] - a[1]) * (c[0] - a[0])) / d;
  const FT gamma = ((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / d;
  return std::array<FT, 3>{{FT(FT(1) - beta - gamma), beta, gamma}};
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief tells whether an umbrella is folded: its corner triangles
  \f$(u_v, u_{v\to w_i}, u_{v\to w_{i+1}})\f$ are not all of one orientation, or the spokes
  wind more than once around the centre.

  An unfolded umbrella is a star-shaped fan around \f$u_v\f$, as the domain star of a vertex
  of a triangulation is; the corner triangles of a folded one overlap. The signs are exact for
  exact number types. A degenerate corner triangle counts as folded.
  \tparam FT a field number type
  \param u the umbrella
  \returns whether `u` is folded
*/
template <class FT>
bool is_folded_umbrella(const Umbrella<FT>& u) {
  const std::size_t n = u.size();
  auto det = [](const std::array<FT, 2>& a, const std::array<FT, 2>& b) {
    return CGAL::sign(FT(a[0] * b[1] - a[1] * b[0]));
  };
  const CGAL::Sign orientation = det(u[0], u[1 % n]);
  if (orientation == CGAL::ZERO)
    return true;
  for (std::size_t i = 1; i < n; ++i)
    if (det(u[i], u[(i + 1) % n]) != orientation)
      return true;
  // Each step turns by less than pi in the same direction: count the steps that reach the
  // direction of u_0 (sector (u_i, u_{i+1}]); the last one does, any other is a second turn.
  std::size_t turns = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (det(u[i], u[0]) == orientation && det(u[0], u[(i + 1) % n]) != -orientation)
      ++turns;
  return turns != 1;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns an umbrella of valence `n` whose centre is the vertex centroid of its stars: a
  convex polygon (the unit circle's points at angles \f$2\pi i/n\f$, rounded to multiples of
  \f$2^{-20}\f$, exact in any number type constructible from `double`) shifted by its centroid.

  For `n == 3` it is the triangle \f$(1,0), (0,1), (-1,-1)\f$, whose centroid is the origin
  (the start of Xu (6.4)).
  \tparam FT a field number type constructible from `double`
  \param n the valence, at least 3
  \throws Invalid_input if `n < 3`
  \returns the umbrella
*/
template <class FT>
Umbrella<FT> centroid_umbrella(std::size_t n) {
  if (n < 3)
    throw Invalid_input("AG1 system: an umbrella needs at least 3 spokes");
  if (n == 3)
    return Umbrella<FT>{{{FT(1), FT(0)}}, {{FT(0), FT(1)}}, {{FT(-1), FT(-1)}}};
  const double pi = std::acos(-1.0), unit = 1048576.0; // 2^20: exact in double
  Umbrella<FT> u(n);
  FT sx(0), sy(0);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2 * pi * double(i) / double(n);
    u[i] = {{FT(std::round(std::cos(angle) * unit) / unit),
             FT(std::round(std::sin(angle) * unit) / unit)}};
    sx += u[i][0];
    sy += u[i][1];
  }
  const FT count(static_cast<double>(n));
  const FT cx = sx / count, cy = sy / count;
  for (auto& p : u) {
    p[0] -= cx;
    p[1] -= cy;
  }
  return u;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief returns the projected star of `v` as an umbrella: the neighbours of `v` projected onto
  the plane through `v` perpendicular to its area-weighted normal
  \f$\sum_i (w_i - v) \times (w_{i+1} - v)\f$, in the coordinates of the basis made of the first
  two projected spokes (so \f$u_{v\to w_0} = (1,0)\f$, \f$u_{v\to w_1} = (0,1)\f$).

  A linear image of the orthogonal projection, computed rationally (exact for an exact
  kernel); it induces the same relations as the projection itself. It is the reference
  umbrella of `walk_AG1_system()` (AG1.md §5.2 names the S6 umbrella; this is its simplest
  stand-in: no angle or length rescaling).
  \tparam Point_3 the point type of the mesh
  \param mesh a closed triangle mesh
  \param v a vertex
  \throws Invalid_input if the normal vanishes or the first two projected spokes are parallel
  \returns the umbrella, in `outgoing_ring()` order
*/
template <class Point_3>
Umbrella<typename CGAL::Kernel_traits<Point_3>::Kernel::FT>
projected_umbrella(const CGAL::Surface_mesh<Point_3>& mesh,
                   typename CGAL::Surface_mesh<Point_3>::Vertex_index v) {
  Umbrella<typename CGAL::Kernel_traits<Point_3>::Kernel::FT> u;
  if (!internal::ag1_projected_umbrella(mesh, v, u))
    throw Invalid_input("AG1 system: the projected star of vertex " +
                        std::to_string(std::size_t(v)) + " is degenerate");
  return u;
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief solves the global AG^1 system of Xu §6.1 by the walking solver of AG1.md §5.2: the
  start umbrella fixes the relations of the start's edges; the other vertices follow in
  breadth-first order (neighbours in `outgoing_ring()` order, so the walk is deterministic).

  At each vertex \f$x\f$ with ring \f$w_0, \dots, w_{n-1}\f$, the gauge
  \f$u_{x\to w_0} = (1,0)\f$, \f$u_{x\to w_1} = (0,1)\f$ fixes the linear freedom, and the
  equations (E) of the edges of \f$x\f$ that already have a relation are solved for the other
  \f$n - 2\f$ spokes (the \f$x\f$ and \f$y\f$ coordinates decouple: one matrix, two right-hand
  sides). For each edge \f$e = (r, s)\f$ (orientation of `mesh.halfedge(e, 0)`), (E_r) is
  \f$u_{r\to q} = \lambda u_{r\to p} + \nu u_{r\to s}\f$ and (E_s) is
  \f$u_{s\to q} = \lambda u_{s\to p} + \mu u_{s\to r}\f$. Then the relations of the other edges of
  \f$x\f$ are read off \f$U_x\f$ (2×2 determinants). Each relation is set by the first of its
  ends to be solved, so all the inconsistency of the system shows in the residuals of the
  second ends.

  - Exact number types (`Algebraic_structure_traits<FT>::Is_exact`): exact elimination; a
    vertex is consistent iff its residual is exactly 0; an inconsistent vertex gets the exact
    least-squares solution.
  - Other number types: double precision, Eigen's complete orthogonal decomposition (ranks
    with relative threshold 1e-10); consistent iff the residual is at most `tolerance`.
  - Under-determined (fewer independent equations than unknowns, e.g. a valence-4 vertex with
    one solved neighbour): the solution closest, in the gauge coordinates, to the mesh's
    `projected_umbrella()` of \f$x\f$ (which is already in the same gauge); the origin if that
    is degenerate.
  - Degenerate: a corner triangle \f$(u_x, u_{x\to w_i}, u_{x\to w_{i+1}})\f$ of the solution is
    collinear (so some relation would divide by zero), or every solution of the equations makes
    \f$u_{x\to w_0}\f$ and \f$u_{x\to w_1}\f$ parallel (the gauge cannot be fixed): the vertex is
    reported, its (degenerate) umbrella kept, and the walk stops (`complete == false`). A
    degenerate start umbrella stops the walk at once.

  The inconsistent case keeps walking with the least-squares umbrella, so that the report
  covers the whole mesh. Folded umbrellas (`is_folded_umbrella()`: a linear solution need not
  be a fan) and relations with \f$\mu = 0\f$ or \f$\nu = 0\f$ are reported, not stopped on:
  the walk solves the linear system of §6.1; whether a surface can be built on the solution is
  what these lists tell. The geometry of the mesh is used only for the reference umbrellas;
  the relations refer to the mesh's orientation (outward after
  `prepare_closed_triangle_mesh()`).
  \tparam FT the number type of the umbrellas and relations (deduced from `start_umbrella`);
  mesh coordinates are converted to it (exactly when it is the kernel's `FT`, otherwise through
  `double`)
  \tparam Point_3 the point type of the mesh
  \param mesh a closed manifold triangle mesh without garbage, consistently oriented
  \param start the start vertex \f$v_0\f$
  \param start_umbrella its umbrella, in `outgoing_ring(start)` order
  \param tolerance for inexact number types: the largest residual counted as consistent, the
  largest \f$|\sin|\f$ of a corner angle counted as degenerate, and the relative size of a
  \f$\mu\f$ or \f$\nu\f$ counted as 0 (unused for exact types)
  \throws Invalid_input if the mesh has garbage, a border, a non-triangle face or a
  non-manifold vertex, if `start` is not a vertex of the mesh, or if `start_umbrella` does not
  have one spoke per neighbour of `start`
  \returns the walk
*/
template <class FT, class Point_3>
AG1_walk<FT> walk_AG1_system(const CGAL::Surface_mesh<Point_3>& mesh,
                             typename CGAL::Surface_mesh<Point_3>::Vertex_index start,
                             const Umbrella<FT>& start_umbrella, double tolerance = 1e-9) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::string prefix = "AG1 system: ";
  if (mesh.has_garbage())
    throw Invalid_input(prefix + "the mesh has removed elements (collect the garbage first)");
  if (mesh.number_of_faces() == 0)
    throw Invalid_input(prefix + "the mesh has no face");
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h))
      throw Invalid_input(prefix + "the mesh is not closed: edge " +
                          std::to_string(std::size_t(mesh.source(h))) + "-" +
                          std::to_string(std::size_t(mesh.target(h))) + " has a single face");
  for (auto f : mesh.faces())
    if (mesh.next(mesh.next(mesh.next(mesh.halfedge(f)))) != mesh.halfedge(f))
      throw Invalid_input(prefix + "face " + std::to_string(std::size_t(f)) + " is not a triangle");
  for (auto v : mesh.vertices())
    if (mesh.is_isolated(v) || PMP::is_non_manifold_vertex(v, mesh))
      throw Invalid_input(prefix + "the mesh is not manifold at vertex " +
                          std::to_string(std::size_t(v)));
  if (std::size_t(start) >= mesh.number_of_vertices())
    throw Invalid_input(prefix + "the start vertex " + std::to_string(std::size_t(start)) +
                        " is not a vertex of the mesh");
  const std::size_t start_valence = mesh.degree(start);
  if (start_umbrella.size() != start_valence)
    throw Invalid_input(prefix + "the start umbrella has " + std::to_string(start_umbrella.size()) +
                        " spokes, vertex " + std::to_string(std::size_t(start)) + " has " +
                        std::to_string(start_valence) + " neighbours");

  using Vertex_index = typename CGAL::Surface_mesh<Point_3>::Vertex_index;
  const std::size_t nv = mesh.number_of_vertices(), ne = mesh.number_of_edges();
  AG1_walk<FT> walk;
  walk.umbrellas.assign(nv, Umbrella<FT>());
  walk.relations.assign(ne, Edge_relation<FT>{FT(0), FT(0), FT(0)});
  walk.has_relation.assign(ne, false);
  walk.residuals.assign(nv, std::numeric_limits<double>::quiet_NaN());

  // Sets the relations of the edges of x that have none from U_x (barycentrics, Cramer).
  auto set_relations = [&](Vertex_index x, const Umbrella<FT>& u) {
    const auto ring = outgoing_ring(x, mesh);
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = std::size_t(mesh.edge(ring[k]));
      if (walk.has_relation[e])
        continue;
      const auto& prev = u[(k + n - 1) % n];
      const auto& here = u[k];
      const auto& next = u[(k + 1) % n];
      Edge_relation<FT> relation;
      if (is_reference_halfedge(mesh, ring[k])) {
        // x = r, s = w_k, p = w_{k+1}, q = w_{k-1}: u_q = lambda u_p + nu u_s
        const FT d = internal::ag1_det(next, here);
        relation.lambda = internal::ag1_det(prev, here) / d;
        relation.nu = internal::ag1_det(next, prev) / d;
        relation.mu = FT(1) - relation.lambda - relation.nu;
      } else {
        // x = s, r = w_k, q = w_{k+1}, p = w_{k-1}: u_q = lambda u_p + mu u_r
        const FT d = internal::ag1_det(prev, here);
        relation.lambda = internal::ag1_det(next, here) / d;
        relation.mu = internal::ag1_det(prev, next) / d;
        relation.nu = FT(1) - relation.lambda - relation.mu;
      }
      walk.relations[e] = relation;
      walk.has_relation[e] = true;
    }
  };

  std::vector<bool> queued(nv, false);
  std::deque<Vertex_index> queue;
  auto enqueue_neighbours = [&](Vertex_index x) {
    for (auto h : outgoing_ring(x, mesh)) {
      const Vertex_index w = mesh.target(h);
      if (!queued[std::size_t(w)]) {
        queued[std::size_t(w)] = true;
        queue.push_back(w);
      }
    }
  };

  queued[std::size_t(start)] = true;
  walk.order.push_back(std::size_t(start));
  walk.umbrellas[std::size_t(start)] = start_umbrella;
  walk.residuals[std::size_t(start)] = 0;
  if (internal::ag1_has_degenerate_corner(start_umbrella, tolerance)) {
    walk.degenerate_vertices.push_back(std::size_t(start));
    walk.complete = false;
  } else {
    set_relations(start, start_umbrella);
    enqueue_neighbours(start);
  }

  while (walk.complete && !queue.empty()) {
    const Vertex_index x = queue.front();
    queue.pop_front();
    const auto ring = outgoing_ring(x, mesh);
    const std::size_t n = ring.size();
    std::vector<internal::AG1_equation<FT>> equations;
    for (std::size_t k = 0; k < n; ++k) {
      const auto e = mesh.edge(ring[k]);
      if (!walk.has_relation[std::size_t(e)])
        continue;
      const Edge_relation<FT>& rel = walk.relations[std::size_t(e)];
      const std::size_t prev = (k + n - 1) % n, next = (k + 1) % n;
      if (is_reference_halfedge(mesh, ring[k])) // x = r: u_q - lambda u_p - nu u_s = 0
        equations.push_back({{{prev, next, k}}, {{FT(1), FT(-rel.lambda), FT(-rel.nu)}}});
      else // x = s: u_q - lambda u_p - mu u_r = 0
        equations.push_back({{{next, prev, k}}, {{FT(1), FT(-rel.lambda), FT(-rel.mu)}}});
    }
    Umbrella<FT> reference(n, {{FT(0), FT(0)}});
    {
      Umbrella<typename CGAL::Kernel_traits<Point_3>::Kernel::FT> projected;
      if (internal::ag1_projected_umbrella(mesh, x, projected))
        for (std::size_t i = 0; i < n; ++i)
          reference[i] = {{internal::ag1_convert<FT>(projected[i][0]),
                           internal::ag1_convert<FT>(projected[i][1])}};
    }
    internal::AG1_vertex_solution<FT> solution;
    if constexpr (internal::ag1_is_exact<FT>)
      solution = internal::ag1_solve_exact(n, equations, reference);
    else
      solution = internal::ag1_solve_double(n, equations, reference, tolerance);

    const std::size_t xi = std::size_t(x);
    walk.order.push_back(xi);
    walk.umbrellas[xi] = solution.umbrella;
    walk.residuals[xi] = solution.residual;
    if (solution.under_determined)
      walk.under_determined_vertices.push_back(xi);
    if (solution.gauge_degenerate ||
        internal::ag1_has_degenerate_corner(solution.umbrella, tolerance)) {
      walk.degenerate_vertices.push_back(xi);
      walk.complete = false;
      if (!solution.consistent && !solution.gauge_degenerate)
        walk.inconsistent_vertices.push_back(xi);
      break;
    }
    if (!solution.consistent)
      walk.inconsistent_vertices.push_back(xi);
    set_relations(x, solution.umbrella);
    enqueue_neighbours(x);
  }
  walk.consistent = walk.inconsistent_vertices.empty();
  for (std::size_t v : walk.order)
    if (is_folded_umbrella(walk.umbrellas[v]))
      walk.folded_vertices.push_back(v);
  std::sort(walk.folded_vertices.begin(), walk.folded_vertices.end());
  for (std::size_t e = 0; e < ne; ++e) {
    if (!walk.has_relation[e])
      continue;
    const Edge_relation<FT>& r = walk.relations[e];
    if (!CGAL::is_negative(r.lambda))
      walk.inadmissible_edges.push_back(e);
    if (!(CGAL::is_negative(r.lambda) && CGAL::is_positive(r.mu) && CGAL::is_positive(r.nu)))
      walk.non_convex_edges.push_back(e);
    bool frame_degenerate = CGAL::is_zero(r.mu) || CGAL::is_zero(r.nu);
    if constexpr (!internal::ag1_is_exact<FT>) {
      // rounding leaves ~1e-16 where the exact value is 0
      const double size =
          (std::max)({1.0, std::abs(CGAL::to_double(r.lambda)), std::abs(CGAL::to_double(r.mu)),
                      std::abs(CGAL::to_double(r.nu))});
      frame_degenerate = std::abs(CGAL::to_double(r.mu)) <= tolerance * size ||
                         std::abs(CGAL::to_double(r.nu)) <= tolerance * size;
    }
    if (frame_degenerate)
      walk.degenerate_frame_edges.push_back(e);
  }
  return walk;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_AG1_SYSTEM_H

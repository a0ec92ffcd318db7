// Tests of the global AG^1 system of Xu §6.1 and its walking solver (AG1.md §5, checks
// C8-C13 and C15): the regular tetrahedron exactly, the icosahedron and octahedron in double.

#include "test_support.h"

#include <CGAL/Surface_mesh.h>
#include <CGAL/exceptions.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/Xu/AG1_system.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <vector>

using namespace ts_test;
using TS::Edge_relation;
using TS::Umbrella;

namespace {

using FT = Exact_kernel::FT;
using Point = Exact_kernel::Point_3;
using Vector = Exact_kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Coordinates = std::array<FT, 2>;

// The regular tetrahedron of Xu §6.1.1 with faces abc, adb, bdc, cda (outward).
struct Tetrahedron {
  Mesh mesh;
  Vertex a, b, c, d;
  Tetrahedron() {
    a = mesh.add_vertex(Point(1, 1, 1));
    b = mesh.add_vertex(Point(1, -1, -1));
    c = mesh.add_vertex(Point(-1, 1, -1));
    d = mesh.add_vertex(Point(-1, -1, 1));
    mesh.add_face(a, b, c);
    mesh.add_face(a, d, b);
    mesh.add_face(b, d, c);
    mesh.add_face(c, d, a);
  }
  std::size_t edge(Vertex r, Vertex s) const { return std::size_t(mesh.edge(mesh.halfedge(r, s))); }
};

// The position of w in the ring of v.
template <class M>
std::size_t spoke(const M& mesh, typename M::Vertex_index v, typename M::Vertex_index w) {
  const auto ring = TS::outgoing_ring(v, mesh);
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (mesh.target(ring[i]) == w)
      return i;
  ADD_FAILURE() << "not a neighbour";
  return 0;
}

// AG1.md §5.3's reading of edge (r, s): p = apex of the face containing r->s.
template <class M, class F>
Edge_relation<F> relation_from(const M& mesh, const TS::AG1_walk<F>& walk,
                               typename M::Vertex_index r, typename M::Vertex_index s) {
  return TS::oriented_relation(mesh, walk.relations, mesh.halfedge(r, s));
}

// Independent check of a walk: every relation satisfies (E) at both of its ends with the final
// umbrellas, the apexes found from the faces (not from ring positions). Returns the sum of
// the absolute errors over all edges whose two ends are solved.
template <class M, class F>
F equation_error(const M& mesh, const TS::AG1_walk<F>& walk) {
  F error(0);
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e);
    const auto r = mesh.source(h), s = mesh.target(h), p = mesh.target(mesh.next(h)),
               q = mesh.target(mesh.next(mesh.opposite(h)));
    const auto &ur = walk.umbrellas[r], &us = walk.umbrellas[s];
    if (!walk.has_relation[e] || ur.empty() || us.empty())
      continue;
    const Edge_relation<F>& rel = walk.relations[e];
    for (int i = 0; i < 2; ++i) {
      error += CGAL::abs(F(ur[spoke(mesh, r, q)][i] - rel.lambda * ur[spoke(mesh, r, p)][i] -
                           rel.nu * ur[spoke(mesh, r, s)][i]));
      error += CGAL::abs(F(us[spoke(mesh, s, q)][i] - rel.lambda * us[spoke(mesh, s, p)][i] -
                           rel.mu * us[spoke(mesh, s, r)][i]));
    }
  }
  return error;
}

bool same(const Edge_relation<FT>& x, const Edge_relation<FT>& y) {
  return x.lambda == y.lambda && x.mu == y.mu && x.nu == y.nu;
}

std::string to_string(const Edge_relation<FT>& r) {
  return "(" + std::to_string(CGAL::to_double(r.lambda)) + ", " +
         std::to_string(CGAL::to_double(r.mu)) + ", " + std::to_string(CGAL::to_double(r.nu)) + ")";
}

// First-approximation star S_{v->w} = (4v + w)/5 (Xu §5.4.1), as a vector from the origin.
Vector star(const Mesh& mesh, Vertex v, Vertex w) {
  return (FT(4) * (mesh.point(v) - CGAL::ORIGIN) + (mesh.point(w) - CGAL::ORIGIN)) / FT(5);
}

// The corner z_y computed from the end diamond of every edge at y (D_4 with y = r, (3.5)):
// S_{r->q} = lambda S_{r->p} + mu z_r + nu S_{r->s}. All of them must agree.
Vector corner_from_relations(const Mesh& mesh, const TS::AG1_walk<FT>& walk, Vertex y) {
  std::vector<Vector> corners;
  for (auto h : TS::outgoing_ring(y, mesh)) {
    const Edge_relation<FT> rel = TS::oriented_relation(mesh, walk.relations, h);
    const Vertex s = mesh.target(h), p = mesh.target(mesh.next(h)),
                 q = mesh.target(mesh.next(mesh.opposite(h)));
    EXPECT_NE(rel.mu, FT(0));
    corners.push_back(
        (star(mesh, y, q) - rel.lambda * star(mesh, y, p) - rel.nu * star(mesh, y, s)) / rel.mu);
  }
  for (const Vector& z : corners)
    EXPECT_EQ(z, corners.front()) << "the end diamonds of vertex " << y << " disagree";
  return corners.front();
}

// Exact 120 degrees: cos = -1/2 <=> 4 (x.y)^2 = |x|^2 |y|^2 and x.y < 0.
bool is_120_degrees(const Vector& x, const Vector& y) {
  const FT dot = x * y;
  return dot < FT(0) && FT(4) * dot * dot == (x * x) * (y * y);
}

std::vector<std::size_t> sorted(std::vector<std::size_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TS::AG1_walk<FT> centroid_walk(const Tetrahedron& t) {
  return TS::walk_AG1_system(t.mesh, t.a, TS::centroid_umbrella<FT>(3));
}

} // namespace

// The orientation change of a relation: derived by hand as (1/l, -n/l, -m/l); checked on
// random diamonds, and it is an involution.
// outgoing_ring() checks the cheap half of its precondition: not a border vertex.
TEST(AG1System, OutgoingRingRefusesABorderVertex) {
  Mesh triangle;
  const Vertex a = triangle.add_vertex(Point(0, 0, 0)), b = triangle.add_vertex(Point(1, 0, 0)),
               c = triangle.add_vertex(Point(0, 1, 0));
  triangle.add_face(a, b, c);
  EXPECT_THROW(TS::outgoing_ring(a, triangle), CGAL::Failure_exception);
  const Tetrahedron t;
  EXPECT_EQ(TS::outgoing_ring(t.a, t.mesh).size(), 3u);
}

TEST(AG1System, ReversedRelationSwapsTheEnds) {
  Random_rationals random(11);
  for (int trial = 0; trial < 200; ++trial) {
    const FT lambda = random.rational<FT>(), mu = random.rational<FT>();
    if (lambda == FT(0))
      continue;
    const Edge_relation<FT> rel{lambda, mu, FT(FT(1) - lambda - mu)};
    const Coordinates p{{random.rational<FT>(), random.rational<FT>()}},
        r{{random.rational<FT>(), random.rational<FT>()}},
        s{{random.rational<FT>(), random.rational<FT>()}};
    Coordinates q;
    for (int i = 0; i < 2; ++i)
      q[i] = rel.lambda * p[i] + rel.mu * r[i] + rel.nu * s[i];
    const Edge_relation<FT> back = TS::reversed_relation(rel);
    // In the orientation s -> r the apexes swap: p = lambda' q + mu' s + nu' r.
    for (int i = 0; i < 2; ++i)
      ASSERT_EQ(p[i], back.lambda * q[i] + back.mu * s[i] + back.nu * r[i]);
    ASSERT_EQ(back.lambda + back.mu + back.nu, FT(1));
    ASSERT_TRUE(same(TS::reversed_relation(back), rel));
  }
  EXPECT_TRUE(same(TS::reversed_relation(Edge_relation<FT>{FT(-1), FT(3), FT(-1)}),
                   Edge_relation<FT>{FT(-1), FT(-1), FT(3)}));
  EXPECT_THROW(TS::reversed_relation(Edge_relation<FT>{FT(0), FT(1), FT(0)}), TS::Invalid_input);
}

TEST(AG1System, AffineCoordinatesByDeterminants) {
  const Coordinates a{{FT(0), FT(0)}}, b{{FT(2), FT(0)}}, c{{FT(0), FT(4)}};
  const auto w = TS::affine_coordinates(Coordinates{{FT(1), FT(1)}}, a, b, c);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ((*w)[0], FT(1) / FT(4));
  EXPECT_EQ((*w)[1], FT(1) / FT(2));
  EXPECT_EQ((*w)[2], FT(1) / FT(4));
  EXPECT_FALSE(TS::affine_coordinates(a, a, b, Coordinates{{FT(4), FT(0)}}).has_value());
}

TEST(AG1System, FoldedUmbrellas) {
  const Umbrella<FT> centred = TS::centroid_umbrella<FT>(5);
  EXPECT_FALSE(TS::is_folded_umbrella(centred));
  Umbrella<FT> clockwise(centred.rbegin(), centred.rend()); // a mirror image is not a fold
  EXPECT_FALSE(TS::is_folded_umbrella(clockwise));
  // the pentagram order turns 144 degrees per step, always the same way, but winds twice
  const Umbrella<FT> pentagram{centred[0], centred[2], centred[4], centred[1], centred[3]};
  EXPECT_TRUE(TS::is_folded_umbrella(pentagram));
  // centre outside the triangle: the corner triangles change orientation
  EXPECT_TRUE(
      TS::is_folded_umbrella(Umbrella<FT>{{{FT(1), FT(0)}}, {{FT(0), FT(1)}}, {{FT(-1), FT(3)}}}));
  // a degenerate corner triangle
  EXPECT_TRUE(
      TS::is_folded_umbrella(Umbrella<FT>{{{FT(1), FT(0)}}, {{FT(-1), FT(0)}}, {{FT(0), FT(1)}}}));
}

// The per-vertex solver on hand-made equations sum_j c_j u_{i_j} = 0, gauge u_0 = (1,0),
// u_1 = (0,1): inconsistent (least squares), forced-collinear gauge, under-determined.
template <class F>
void check_vertex_solver(bool exact) {
  using Equation = TS::internal::AG1_equation<F>;
  const Umbrella<F> reference{{{F(1), F(0)}}, {{F(0), F(1)}}, {{F(-1), F(0)}}, {{F(0), F(-1)}}};
  auto solve = [&](std::size_t n, const std::vector<Equation>& equations) {
    const Umbrella<F> ref(reference.begin(), reference.begin() + n);
    if constexpr (CGAL::Algebraic_structure_traits<F>::Is_exact::value)
      return TS::internal::ag1_solve_exact(n, equations, ref);
    else
      return TS::internal::ag1_solve_double(n, equations, ref, 1e-9);
  };
  auto near = [exact](const F& x, double y) {
    return exact ? x == F(y) : std::abs(CGAL::to_double(x) - y) <= 1e-12;
  };
  // u_2 = u_0 and u_2 = u_1: least squares u_2 = (1/2, 1/2), residual 1
  const auto lsq = solve(3, {Equation{{{2, 0, 1}}, {{F(1), F(-1), F(0)}}},
                             Equation{{{2, 1, 0}}, {{F(1), F(-1), F(0)}}}});
  EXPECT_FALSE(lsq.consistent);
  EXPECT_FALSE(lsq.gauge_degenerate);
  EXPECT_FALSE(lsq.under_determined);
  EXPECT_NEAR(lsq.residual, 1.0, 1e-14);
  EXPECT_TRUE(near(lsq.umbrella[2][0], 0.5) && near(lsq.umbrella[2][1], 0.5));
  // u_1 = 2 u_0: an umbrella exists, but never with u_0, u_1 independent
  const auto collinear = solve(3, {Equation{{{1, 0, 2}}, {{F(1), F(-2), F(0)}}}});
  EXPECT_FALSE(collinear.consistent);
  EXPECT_TRUE(collinear.gauge_degenerate);
  // valence 4, the one equation u_0 + u_2 + u_3 = 0: under-determined. The reference
  // (1,0) + (-1,0) + (0,-1) misses it by (0,-1): the closest solution moves u_2 and u_3 by
  // the same (0, 1/2)
  const auto free = solve(4, {Equation{{{2, 3, 0}}, {{F(1), F(1), F(1)}}}});
  EXPECT_TRUE(free.consistent);
  EXPECT_TRUE(free.under_determined);
  EXPECT_LE(free.residual, exact ? 0.0 : 1e-15);
  EXPECT_TRUE(near(free.umbrella[2][0], -1) && near(free.umbrella[2][1], 0.5));
  EXPECT_TRUE(near(free.umbrella[3][0], 0) && near(free.umbrella[3][1], -0.5));
}

TEST(AG1System, VertexSolverExact) {
  check_vertex_solver<FT>(true);
}
TEST(AG1System, VertexSolverDouble) {
  check_vertex_solver<double>(false);
}

// C8, C15: the symmetric solution. Consistent, no freedom after U_a, and with the
// first-approximation stars z_a = (12a + b + c + d)/15 = (11/15)(1,1,1).
TEST(AG1System, TetrahedronCentroidStartIsConsistent) {
  const Tetrahedron t;
  const auto walk = centroid_walk(t);
  EXPECT_TRUE(walk.consistent);
  EXPECT_TRUE(walk.complete);
  EXPECT_TRUE(walk.degenerate_vertices.empty());
  EXPECT_TRUE(walk.inconsistent_vertices.empty());
  EXPECT_TRUE(walk.under_determined_vertices.empty()); // C15
  std::vector<std::size_t> order{0};                   // breadth first, in the ring order of a
  for (auto h : TS::outgoing_ring(t.a, t.mesh))
    order.push_back(t.mesh.target(h));
  EXPECT_EQ(walk.order, order);
  for (double r : walk.residuals)
    EXPECT_EQ(r, 0.0);
  for (bool set : walk.has_relation)
    EXPECT_TRUE(set);
  EXPECT_EQ(equation_error(t.mesh, walk), FT(0));
  // z_b, z_c, z_d lie outside their star triangles (6.8): those umbrellas fold
  EXPECT_EQ(walk.folded_vertices, (std::vector<std::size_t>{t.b, t.c, t.d}));
  EXPECT_TRUE(walk.degenerate_frame_edges.empty());
  const Vector za = corner_from_relations(t.mesh, walk, t.a);
  EXPECT_EQ(za, Vector(FT(11) / FT(15), FT(11) / FT(15), FT(11) / FT(15)));
  EXPECT_EQ(za, ((t.mesh.point(t.a) - CGAL::ORIGIN) * FT(12) + (t.mesh.point(t.b) - CGAL::ORIGIN) +
                 (t.mesh.point(t.c) - CGAL::ORIGIN) + (t.mesh.point(t.d) - CGAL::ORIGIN)) /
                    FT(15));
  // (6.4): z_a is the centroid of its stars
  EXPECT_EQ(za, (star(t.mesh, t.a, t.b) + star(t.mesh, t.a, t.c) + star(t.mesh, t.a, t.d)) / FT(3));
}

// C9: (6.8) z_y = 3 S_{y->a} - (the other two stars of y) for y = b, c, d.
TEST(AG1System, TetrahedronOtherCornersFollowXu68) {
  const Tetrahedron t;
  const auto walk = centroid_walk(t);
  const std::array<Vertex, 4> v{{t.a, t.b, t.c, t.d}};
  for (std::size_t i = 1; i < 4; ++i) {
    Vector expected = FT(3) * star(t.mesh, v[i], t.a);
    for (std::size_t j = 1; j < 4; ++j)
      if (j != i)
        expected = expected - star(t.mesh, v[i], v[j]);
    EXPECT_EQ(corner_from_relations(t.mesh, walk, v[i]), expected) << "vertex " << i;
  }
  const FT fifth = FT(1) / FT(5);
  EXPECT_EQ(corner_from_relations(t.mesh, walk, t.b), Vector(FT(9) * fifth, -fifth, -fifth));
  EXPECT_EQ(corner_from_relations(t.mesh, walk, t.c), Vector(-fifth, FT(9) * fifth, -fifth));
  EXPECT_EQ(corner_from_relations(t.mesh, walk, t.d), Vector(-fifth, -fifth, FT(9) * fifth));
}

// C10, C11 and the (3.5)-form pattern of AG1.md §5.3 (edges read r < s).
TEST(AG1System, TetrahedronRelationPatterns) {
  const Tetrahedron t;
  const auto walk = centroid_walk(t);
  const Edge_relation<FT> arrow{FT(-1), FT(3), FT(-1)}, bad{FT(3), FT(-1), FT(-1)},
      third{FT(1) / FT(3), FT(1) / FT(3), FT(1) / FT(3)};
  for (Vertex s : {t.b, t.c, t.d})
    EXPECT_TRUE(same(relation_from(t.mesh, walk, t.a, s), arrow))
        << "a" << s << ": " << to_string(relation_from(t.mesh, walk, t.a, s));
  EXPECT_TRUE(same(relation_from(t.mesh, walk, t.b, t.c), bad));
  EXPECT_TRUE(same(relation_from(t.mesh, walk, t.c, t.d), bad));
  EXPECT_TRUE(same(relation_from(t.mesh, walk, t.b, t.d), third));
  // The same relations in the other orientation (the stored one may be either).
  EXPECT_TRUE(same(relation_from(t.mesh, walk, t.b, t.a), TS::reversed_relation(arrow)));
  for (std::size_t e = 0; e < 6; ++e)
    EXPECT_EQ(walk.relations[e].lambda + walk.relations[e].mu + walk.relations[e].nu, FT(1));

  // C10, the thesis's own forms: (6.1)-(6.3) z_a = (z_1 + z_2 + z_3)/3, i.e. u_a has
  // coordinates 1/3 w.r.t. its spokes; (6.5)/(6.6) z_y = 3 S_{y->a} - ... for y = b, c, d;
  // (6.7) S_{b->a} = (S_{b->c} + z_b + S_{b->d})/3.
  const Coordinates origin{{FT(0), FT(0)}};
  const auto& ua = walk.umbrellas[t.a];
  const auto at_a = TS::affine_coordinates(origin, ua[0], ua[1], ua[2]);
  ASSERT_TRUE(at_a.has_value());
  for (const FT& x : *at_a)
    EXPECT_EQ(x, FT(1) / FT(3));
  const std::array<Vertex, 4> v{{t.a, t.b, t.c, t.d}};
  for (std::size_t i = 1; i < 4; ++i) {
    const auto& u = walk.umbrellas[v[i]];
    std::vector<Vertex> others;
    for (std::size_t j = 1; j < 4; ++j)
      if (j != i)
        others.push_back(v[j]);
    const auto& to_a = u[spoke(t.mesh, v[i], t.a)];
    const auto& to_1 = u[spoke(t.mesh, v[i], others[0])];
    const auto& to_2 = u[spoke(t.mesh, v[i], others[1])];
    const auto corner_form = TS::affine_coordinates(origin, to_a, to_1, to_2);
    ASSERT_TRUE(corner_form.has_value());
    EXPECT_EQ((*corner_form)[0], FT(3));
    EXPECT_EQ((*corner_form)[1], FT(-1));
    EXPECT_EQ((*corner_form)[2], FT(-1));
    const auto star_form = TS::affine_coordinates(to_a, to_1, origin, to_2);
    ASSERT_TRUE(star_form.has_value());
    for (const FT& x : *star_form)
      EXPECT_EQ(x, FT(1) / FT(3));
  }

  // C11: the relations of ab, ac, ad are non-convex (nu < 0); realized in the equilateral
  // corner region of a (the projected star of the regular tetrahedron, rational in 3D), both
  // triangles of each edge map have a 120 degree angle at u_a: an arrow (240 > 180 degrees).
  const auto non_convex = walk.non_convex_edges;
  const Vector normal = t.mesh.point(t.a) - CGAL::ORIGIN;
  auto projected = [&](Vertex w) {
    const Vector x = t.mesh.point(w) - t.mesh.point(t.a);
    return x - ((x * normal) / (normal * normal)) * normal;
  };
  for (Vertex s : {t.b, t.c, t.d}) {
    EXPECT_NE(std::find(non_convex.begin(), non_convex.end(), t.edge(t.a, s)), non_convex.end());
    const auto h = t.mesh.halfedge(t.a, s);
    const Vertex p = t.mesh.target(t.mesh.next(h)),
                 q = t.mesh.target(t.mesh.next(t.mesh.opposite(h)));
    const Edge_relation<FT> rel = relation_from(t.mesh, walk, t.a, s);
    EXPECT_LT(rel.nu, FT(0));
    // u_q = lambda u_p + mu u_a + nu u_s with u_a = 0: the equilateral umbrella satisfies it
    EXPECT_EQ(projected(q), rel.lambda * projected(p) + rel.nu * projected(s));
    EXPECT_TRUE(is_120_degrees(projected(s), projected(p)));
    EXPECT_TRUE(is_120_degrees(projected(s), projected(q)));
  }
}

// C12: the solution is not unique; beta = (1/2, 1/3, 1/6) is as consistent as the centroid,
// with the closed forms of AG1.md §5.3.
TEST(AG1System, TetrahedronBetaFamily) {
  const Tetrahedron t;
  const std::array<Vertex, 4> v{{t.a, t.b, t.c, t.d}};
  const std::array<FT, 4> beta{{FT(0), FT(1) / FT(2), FT(1) / FT(3), FT(1) / FT(6)}};
  // beta_b u_b + beta_c u_c + beta_d u_d = 0
  Umbrella<FT> start(3);
  start[spoke(t.mesh, t.a, t.b)] = {{FT(2), FT(0)}};
  start[spoke(t.mesh, t.a, t.c)] = {{FT(0), FT(3)}};
  start[spoke(t.mesh, t.a, t.d)] = {{FT(-6), FT(-6)}};
  const auto walk = TS::walk_AG1_system(t.mesh, t.a, start);
  EXPECT_TRUE(walk.consistent);
  EXPECT_TRUE(walk.complete);
  EXPECT_TRUE(walk.under_determined_vertices.empty());
  for (double r : walk.residuals)
    EXPECT_EQ(r, 0.0);
  Vector za = CGAL::NULL_VECTOR;
  for (std::size_t i = 1; i < 4; ++i)
    za = za + beta[i] * star(t.mesh, t.a, v[i]);
  EXPECT_EQ(corner_from_relations(t.mesh, walk, t.a), za);
  // corner_y = (1/beta_y) S_{y->a} - sum_{x not a, y} (beta_x / beta_y) S_{y->x}
  for (std::size_t y = 1; y < 4; ++y) {
    Vector expected = star(t.mesh, v[y], t.a) / beta[y];
    for (std::size_t x = 1; x < 4; ++x)
      if (x != y)
        expected = expected - (beta[x] / beta[y]) * star(t.mesh, v[y], v[x]);
    EXPECT_EQ(corner_from_relations(t.mesh, walk, v[y]), expected) << "vertex " << y;
  }
  // the printed coefficients: b (2, -2/3, -1/3) w.r.t. (a, c, d), c (3, -3/2, -1/2) w.r.t.
  // (a, b, d), d (6, -3, -2) w.r.t. (a, b, c)
  const Coordinates origin{{FT(0), FT(0)}};
  auto corner_form = [&](Vertex y, Vertex x1, Vertex x2) {
    const auto& u = walk.umbrellas[y];
    return *TS::affine_coordinates(origin, u[spoke(t.mesh, y, t.a)], u[spoke(t.mesh, y, x1)],
                                   u[spoke(t.mesh, y, x2)]);
  };
  EXPECT_EQ(corner_form(t.b, t.c, t.d),
            (std::array<FT, 3>{{FT(2), FT(-2) / FT(3), FT(-1) / FT(3)}}));
  EXPECT_EQ(corner_form(t.c, t.b, t.d),
            (std::array<FT, 3>{{FT(3), FT(-3) / FT(2), FT(-1) / FT(2)}}));
  EXPECT_EQ(corner_form(t.d, t.b, t.c), (std::array<FT, 3>{{FT(6), FT(-3), FT(-2)}}));
}

// C13: no admissible AG^1 surface over a tetrahedron: with the centroid start exactly bc,
// bd, cd have lambda >= 0, and no start umbrella does better than 3 such edges.
TEST(AG1System, TetrahedronHasAtLeastThreeInadmissibleEdges) {
  const Tetrahedron t;
  const auto walk = centroid_walk(t);
  std::vector<std::size_t> expected{t.edge(t.b, t.c), t.edge(t.b, t.d), t.edge(t.c, t.d)};
  EXPECT_EQ(walk.inadmissible_edges, sorted(expected));

  Random_rationals random(2026);
  std::size_t minimum = 6, walks = 0, degenerate = 0;
  std::set<std::size_t> counts;
  for (int trial = 0; trial < 2000; ++trial) {
    Umbrella<FT> start(3);
    for (auto& u : start)
      u = {{random.rational<FT>(), random.rational<FT>()}};
    const auto w = TS::walk_AG1_system(t.mesh, t.a, start);
    if (!w.complete) {
      ++degenerate;
      continue;
    }
    ++walks;
    ASSERT_TRUE(w.consistent);
    ASSERT_EQ(equation_error(t.mesh, w), FT(0));
    ASSERT_TRUE(w.under_determined_vertices.empty()); // C15
    minimum = std::min(minimum, w.inadmissible_edges.size());
    counts.insert(w.inadmissible_edges.size());
    // per vertex 0 or 2 inadmissible edges, and at most one vertex with 0 (K_4)
    std::size_t good = 0;
    for (Vertex x : t.mesh.vertices()) {
      std::size_t bad = 0;
      for (auto h : TS::outgoing_ring(x, t.mesh))
        bad += std::count(w.inadmissible_edges.begin(), w.inadmissible_edges.end(),
                          std::size_t(t.mesh.edge(h)));
      ASSERT_TRUE(bad == 0 || bad == 2) << "vertex " << x << ": " << bad;
      good += bad == 0;
    }
    ASSERT_LE(good, 1u);
    // lambda keeps its sign under reversal, so #inadmissible edges = (sum of bad) / 2 =
    // #vertices with the centre outside their star triangle = #folded umbrellas: 3 or 4
    ASSERT_EQ(w.inadmissible_edges.size(), 4 - good);
    ASSERT_EQ(w.folded_vertices.size(), 4 - good);
  }
  std::cout << "[ finding  ] tetrahedron: " << walks << " random starts walked, " << degenerate
            << " degenerate; numbers of inadmissible edges seen:";
  for (std::size_t c : counts)
    std::cout << ' ' << c;
  std::cout << std::endl;
  EXPECT_GT(walks, 1900u);
  EXPECT_EQ(minimum, 3u);
  EXPECT_EQ(counts, (std::set<std::size_t>{3, 4}));
}

TEST(AG1System, DegenerateStartUmbrellaStops) {
  const Tetrahedron t;
  const Umbrella<FT> start{{{FT(1), FT(0)}}, {{FT(2), FT(0)}}, {{FT(0), FT(1)}}};
  const auto walk = TS::walk_AG1_system(t.mesh, t.a, start);
  EXPECT_FALSE(walk.complete);
  EXPECT_EQ(walk.degenerate_vertices, (std::vector<std::size_t>{0}));
  for (bool set : walk.has_relation)
    EXPECT_FALSE(set);
}

TEST(AG1System, InvalidInputIsRejected) {
  const Tetrahedron t;
  EXPECT_THROW(TS::walk_AG1_system(t.mesh, t.a, TS::centroid_umbrella<FT>(4)), TS::Invalid_input);
  EXPECT_THROW(TS::walk_AG1_system(t.mesh, Vertex(7), TS::centroid_umbrella<FT>(3)),
               TS::Invalid_input);
  Mesh open;
  const Vertex a = open.add_vertex(Point(1, 1, 1)), b = open.add_vertex(Point(1, -1, -1)),
               c = open.add_vertex(Point(-1, 1, -1)), d = open.add_vertex(Point(-1, -1, 1));
  open.add_face(a, b, c);
  open.add_face(a, d, b);
  open.add_face(b, d, c);
  EXPECT_THROW(TS::walk_AG1_system(open, b, TS::centroid_umbrella<FT>(3)), TS::Invalid_input);
  EXPECT_THROW(TS::centroid_umbrella<FT>(2), TS::Invalid_input);
}

// The same walk in double reproduces the exact one.
TEST(AG1System, TetrahedronInDoubleMatchesExact) {
  using Point_d = Epick::Point_3;
  CGAL::Surface_mesh<Point_d> mesh;
  const auto a = mesh.add_vertex(Point_d(1, 1, 1)), b = mesh.add_vertex(Point_d(1, -1, -1)),
             c = mesh.add_vertex(Point_d(-1, 1, -1)), d = mesh.add_vertex(Point_d(-1, -1, 1));
  mesh.add_face(a, b, c);
  mesh.add_face(a, d, b);
  mesh.add_face(b, d, c);
  mesh.add_face(c, d, a);
  const auto walk = TS::walk_AG1_system(mesh, a, TS::centroid_umbrella<double>(3));
  const Tetrahedron t;
  const auto exact = centroid_walk(t);
  EXPECT_TRUE(walk.consistent);
  for (std::size_t e = 0; e < 6; ++e) {
    EXPECT_NEAR(walk.relations[e].lambda, CGAL::to_double(exact.relations[e].lambda), 1e-12);
    EXPECT_NEAR(walk.relations[e].mu, CGAL::to_double(exact.relations[e].mu), 1e-12);
    EXPECT_NEAR(walk.relations[e].nu, CGAL::to_double(exact.relations[e].nu), 1e-12);
  }
  EXPECT_EQ(walk.inadmissible_edges, exact.inadmissible_edges);
}

namespace {

template <class Walk>
void print_findings(const std::string& name, const Walk& walk) {
  double max_residual = 0, max_coefficient = 0;
  for (double r : walk.residuals)
    if (!std::isnan(r))
      max_residual = std::max(max_residual, r);
  std::size_t relations = 0;
  for (std::size_t e = 0; e < walk.relations.size(); ++e)
    if (walk.has_relation[e]) {
      ++relations;
      for (double x :
           {CGAL::to_double(walk.relations[e].lambda), CGAL::to_double(walk.relations[e].mu),
            CGAL::to_double(walk.relations[e].nu)})
        max_coefficient = std::max(max_coefficient, std::abs(x));
    }
  std::cout << "[ finding  ] " << name << ": solved " << walk.order.size() << " of "
            << walk.umbrellas.size() << " vertices, consistent " << walk.consistent << ", complete "
            << walk.complete << ", max residual " << max_residual << ", relations " << relations
            << " (convex " << relations - walk.non_convex_edges.size() << ", inadmissible "
            << walk.inadmissible_edges.size() << "), max |coefficient| " << max_coefficient
            << ", under-determined " << walk.under_determined_vertices.size() << ", inconsistent "
            << walk.inconsistent_vertices.size() << ", degenerate frames "
            << walk.degenerate_frame_edges.size() << ", folded";
  for (std::size_t v : walk.folded_vertices)
    std::cout << ' ' << v;
  std::cout << ", degenerate";
  for (std::size_t v : walk.degenerate_vertices)
    std::cout << ' ' << v;
  std::cout << ", order";
  for (std::size_t v : walk.order)
    std::cout << ' ' << v;
  std::cout << std::endl;
}

} // namespace

// AG1.md §5.4: the icosahedron's walk (start: vertex 0, its projected star) is consistent.
TEST(AG1System, IcosahedronWalkIsConsistent) {
  auto mesh = TS::blending_test_mesh<Epick::Point_3>("icosahedron");
  TS::prepare_closed_triangle_mesh(mesh, "test");
  const auto start = *mesh.vertices().begin();
  const auto walk = TS::walk_AG1_system(mesh, start, TS::projected_umbrella(mesh, start));
  print_findings("icosahedron", walk);
  EXPECT_TRUE(walk.complete);
  EXPECT_TRUE(walk.consistent);
  for (double r : walk.residuals)
    EXPECT_LE(r, 1e-12);
  EXPECT_LE(equation_error(mesh, walk), 1e-12);
}

// AG1.md §5.4 expects the octahedron's walk to stop at a degenerate umbrella. With the
// projected stars as references it does not stop: the linear system is solved exactly at
// every vertex, but the solution is folded at 4 of the 6 vertices and 10 of the 12 relations
// have mu = 0 or nu = 0 (the square start umbrella puts opposite spokes on one line), so no
// surface can be propagated from it. Pinned exactly; the double walk agrees.
TEST(AG1System, OctahedronWalkIsFoldedAndDegenerate) {
  auto mesh = TS::blending_test_mesh<Epick::Point_3>("octahedron");
  TS::prepare_closed_triangle_mesh(mesh, "test");
  Mesh exact; // the same octahedron (integer coordinates), exactly
  for (auto v : mesh.vertices())
    exact.add_vertex(Point(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()));
  for (auto f : mesh.faces()) {
    std::vector<Vertex> face;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      face.push_back(Vertex(std::size_t(v)));
    exact.add_face(face);
  }
  const Vertex start(0);
  const auto walk = TS::walk_AG1_system(exact, start, TS::projected_umbrella(exact, start));
  print_findings("octahedron (exact)", walk);
  EXPECT_TRUE(walk.complete);
  EXPECT_TRUE(walk.consistent);
  EXPECT_EQ(equation_error(exact, walk), FT(0));
  EXPECT_EQ(walk.under_determined_vertices.size(), 1u);
  EXPECT_EQ(walk.folded_vertices.size(), 4u);
  EXPECT_EQ(walk.degenerate_frame_edges.size(), 10u);
  EXPECT_EQ(walk.non_convex_edges.size(), 11u);
  // the start's four relations: u_q = -u_p, i.e. mu = 0 or nu = 0
  for (auto h : TS::outgoing_ring(start, exact)) {
    const Edge_relation<FT> rel = TS::oriented_relation(exact, walk.relations, h);
    EXPECT_TRUE(same(rel, Edge_relation<FT>{FT(-1), FT(2), FT(0)})) << to_string(rel);
  }

  const auto approximate = TS::walk_AG1_system(
      mesh, *mesh.vertices().begin(), TS::projected_umbrella(mesh, *mesh.vertices().begin()));
  print_findings("octahedron (double)", approximate);
  EXPECT_TRUE(approximate.consistent);
  EXPECT_LE(equation_error(mesh, approximate), 1e-12);
  EXPECT_EQ(approximate.folded_vertices, walk.folded_vertices);
  EXPECT_EQ(approximate.degenerate_frame_edges, walk.degenerate_frame_edges);
  for (std::size_t e = 0; e < walk.relations.size(); ++e) {
    EXPECT_NEAR(approximate.relations[e].lambda, CGAL::to_double(walk.relations[e].lambda), 1e-12);
    EXPECT_NEAR(approximate.relations[e].mu, CGAL::to_double(walk.relations[e].mu), 1e-12);
    EXPECT_NEAR(approximate.relations[e].nu, CGAL::to_double(walk.relations[e].nu), 1e-12);
  }
}

// A walk that is not consistent (AG1.md §5.4 reports a degenerate stop for the pentakis mesh;
// here the over-determined vertices have no exact solution): the inconsistent vertices are
// reported with their least-squares residuals and the walk goes on.
TEST(AG1System, PentakisWalkIsInconsistent) {
  auto mesh = TS::blending_test_mesh<Epick::Point_3>("pentakis");
  TS::prepare_closed_triangle_mesh(mesh, "test");
  const auto start = *mesh.vertices().begin();
  const double tolerance = 1e-9;
  const auto walk =
      TS::walk_AG1_system(mesh, start, TS::projected_umbrella(mesh, start), tolerance);
  print_findings("pentakis (double)", walk);
  EXPECT_TRUE(walk.complete);
  EXPECT_FALSE(walk.consistent);
  ASSERT_FALSE(walk.inconsistent_vertices.empty());
  for (std::size_t v = 0; v < walk.residuals.size(); ++v) {
    const bool reported =
        std::count(walk.inconsistent_vertices.begin(), walk.inconsistent_vertices.end(), v) != 0;
    EXPECT_EQ(walk.residuals[v] > tolerance, reported) << "vertex " << v;
  }
}

// Tests of Xu's pseudo-AG^1 surfaces (thesis ch. 5-6; AG1.md): the construction's golden
// values on the regular tetrahedron (exact), the certificate's verdicts, the measurements,
// invariances, local control and validation. The ids C1..C32 refer to AG1.md §8.
#include "test_support.h"

#include <CGAL/Triangular_spline/Comparators/PN_triangles.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Xu/AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>
#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace ts_test;
using TS::Pseudo_AG1_options;
using TS::Pseudo_AG1_surface;
using Exact = Exact_kernel;
using Double = CGAL::Simple_cartesian<double>;

template <class K>
using Mesh = CGAL::Surface_mesh<typename K::Point_3>;

template <class K>
typename K::Vector_3 vec(const typename K::FT& x, const typename K::FT& y,
                         const typename K::FT& z) {
  return typename K::Vector_3(x, y, z);
}

// The halfedge from vertex a to vertex b (indices).
template <class K>
typename Mesh<K>::Halfedge_index between(const Mesh<K>& m, std::size_t a, std::size_t b) {
  const auto h = m.halfedge(typename Mesh<K>::Vertex_index(a), typename Mesh<K>::Vertex_index(b));
  EXPECT_NE(h, Mesh<K>::null_halfedge());
  return h;
}

// --- golden values on the regular tetrahedron a, b, c, d = vertices 0..3 -------------------

TEST(PseudoAG1Golden, Chapter5ClosedFormsOnTheRegularTetrahedron) { // C16
  using FT = Exact::FT;
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("tetrahedron"),
                                    Pseudo_AG1_options::chapter5());
  ASSERT_TRUE(s.is_exact());
  const auto& m = s.mesh();
  const FT t(11, 15);
  EXPECT_EQ(s.corner_plane(typename Mesh<Exact>::Vertex_index(0)).corner, vec<Exact>(t, t, t));
  // S_{a->b} = (4a + b)/5, M_{a->b} = (2a + b + c + d)/5, I = (3a + b + c)/5
  EXPECT_EQ(s.star(between<Exact>(m, 0, 1)), vec<Exact>(1, FT(3, 5), FT(3, 5)));
  EXPECT_EQ(s.edge_middle(between<Exact>(m, 0, 1)), vec<Exact>(FT(1, 5), FT(1, 5), FT(1, 5)));
  const auto ab = between<Exact>(m, 0, 1); // in face abc
  EXPECT_EQ(m.target(m.next(ab)), typename Mesh<Exact>::Vertex_index(2));
  EXPECT_EQ(s.corner_inner(ab), vec<Exact>(FT(3, 5), FT(3, 5), FT(1, 5)));
  // L = (3r + 3s + 3p + q)/10 for the flip of face (r, s, p) next to rs
  EXPECT_EQ(s.flip(ab), vec<Exact>(FT(1, 5), FT(1, 5), FT(-1, 5)));
  // every control point is a convex combination of the vertices: inside the tetrahedron
  for (auto f : m.faces())
    for (const auto& p : s.control_net(f)) {
      // the regular tetrahedron is |x| + |y| + |z| <= ... : check the four face planes
      const std::array<std::array<int, 3>, 4> normals{
          {{{1, 1, 1}}, {{1, -1, -1}}, {{-1, 1, -1}}, {{-1, -1, 1}}}};
      for (const auto& n : normals)
        EXPECT_LE(-(n[0] * p.x() + n[1] * p.y() + n[2] * p.z()), FT(1));
    }
}

TEST(PseudoAG1Golden, SatoChapter5CornerIsTheStarCentroid) { // C16 on a skewed tetrahedron
  using FT = Exact::FT;
  const Mesh<Exact> mesh = TS::thesis_polyhedron<Exact>("sato");
  const Pseudo_AG1_surface<Exact> s(mesh, Pseudo_AG1_options::chapter5());
  ASSERT_TRUE(s.is_exact());
  for (auto v : s.mesh().vertices()) {
    typename Exact::Vector_3 sum(0, 0, 0);
    for (auto w : CGAL::vertices_around_target(s.mesh().halfedge(v), s.mesh()))
      sum = sum + (s.mesh().point(w) - CGAL::ORIGIN);
    const auto p = s.mesh().point(v) - CGAL::ORIGIN;
    if (!s.corner_plane(v).recentred) { // z = (12 v + sum of neighbours)/15
      EXPECT_EQ(s.corner_plane(v).corner, (FT(12) * p + sum) / FT(15));
    }
  }
}

TEST(PseudoAG1Golden, ExactPresetDipsOnEveryEdge) { // C23
  using FT = Exact::FT;
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("tetrahedron"),
                                    Pseudo_AG1_options::exact());
  const auto& m = s.mesh();
  const FT t(13, 15);
  EXPECT_EQ(s.corner_plane(typename Mesh<Exact>::Vertex_index(0)).corner, vec<Exact>(t, t, t));
  const auto ab = between<Exact>(m, 0, 1);
  EXPECT_EQ(s.star(ab), vec<Exact>(FT(17, 15), FT(11, 15), FT(11, 15)));
  EXPECT_EQ(s.edge_middle(ab), vec<Exact>(FT(1, 15), FT(1, 15), FT(1, 15)));
  EXPECT_EQ(s.flip(ab), vec<Exact>(FT(1, 15), FT(1, 5), FT(-1, 5)));
  for (auto e : m.edges())
    EXPECT_GT(s.dip(e), 0);
}

// --- the certificate ------------------------------------------------------------------------

TEST(PseudoAG1Certificate, RegularTetrahedronPatternIsExact) { // C4, C5 (exact pattern)
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("tetrahedron"),
                                    Pseudo_AG1_options::exact());
  const TS::Pseudo_AG1_certificate c = TS::certify_pseudo_AG1(s);
  EXPECT_TRUE(c.exact);
  EXPECT_TRUE(c.pseudo_AG1());
  EXPECT_EQ(c.c0_edges, 6u);
  EXPECT_EQ(c.middle_edges, 6u);
  EXPECT_EQ(c.ag1_edges, 0u);
  EXPECT_EQ(c.g1_vertices, 4u);
  for (const auto& E : c.per_edge) {
    EXPECT_TRUE(E.admissible);  // the parallelogram has lambda = -1
    EXPECT_EQ(E.join_order, 0); // C^0 holds, C^1 fails at the end diamonds
    EXPECT_FALSE(E.diamonds[0]);
    EXPECT_TRUE(E.diamonds[1] && E.diamonds[2] && E.diamonds[3]);
    EXPECT_FALSE(E.diamonds[4]);
  }
}

// Wraps a surface and moves one control point of one face: the certificate must notice.
template <class K>
struct Edited_surface {
  using Geom_traits = K;
  using Base = Pseudo_AG1_surface<K>;
  using Face_index = typename Base::Face_index;
  using Vertex_index = typename Base::Vertex_index;
  const Base& base;
  Face_index face;
  std::size_t slot;
  typename K::Vector_3 delta;
  const typename Base::Mesh& mesh() const { return base.mesh(); }
  std::vector<typename K::Vector_3> control_net(Face_index f) const {
    auto net = base.control_net(f);
    if (f == face)
      net[slot] = net[slot] + delta;
    return net;
  }
  decltype(auto) edge_relation(typename Base::Edge_index e) const { return base.edge_relation(e); }
  decltype(auto) corner_plane(Vertex_index v) const { return base.corner_plane(v); }
  decltype(auto) star(typename Base::Halfedge_index h) const { return base.star(h); }
  bool is_exact() const { return base.is_exact(); }
};

TEST(PseudoAG1Certificate, ATinyEditOfOneControlPointIsCaught) {
  using FT = Exact::FT;
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("octahedron"),
                                    Pseudo_AG1_options::exact());
  ASSERT_TRUE(TS::certify_pseudo_AG1(s).pseudo_AG1());
  const auto f = *s.mesh().faces().begin();
  const FT tiny = FT(1) / FT(1e30);
  // an edge-middle point (3,2,0): breaks C^0 on one edge
  const Edited_surface<Exact> middle{s, f, TS::linear_index(TS::Multi_index{3, 2, 0}),
                                     vec<Exact>(0, tiny, 0)};
  const auto c1 = TS::certify_pseudo_AG1(middle);
  EXPECT_FALSE(c1.pseudo_AG1());
  EXPECT_EQ(c1.c0_edges, c1.edges - 1);
  // a corner-inner point (3,1,1): C^0 stays, a middle diamond breaks on two edges
  const Edited_surface<Exact> inner{s, f, TS::linear_index(TS::Multi_index{3, 1, 1}),
                                    vec<Exact>(tiny, 0, 0)};
  const auto c2 = TS::certify_pseudo_AG1(inner);
  EXPECT_EQ(c2.c0_edges, c2.edges);
  EXPECT_EQ(c2.middle_edges, c2.edges - 2);
  EXPECT_FALSE(c2.pseudo_AG1());
}

TEST(PseudoAG1Certificate, ExactSurfacesArePseudoAG1OnEveryShape) { // C1, C2, C3, C31
  for (const std::string name :
       {"tetrahedron", "sato", "octahedron", "cube", "cube-centres", "star", "v-arm", "torus9"}) {
    SCOPED_TRACE(name);
    for (const auto& options : {Pseudo_AG1_options::exact(), Pseudo_AG1_options::chapter5()}) {
      const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>(name), options);
      ASSERT_TRUE(s.is_exact());
      const auto c = TS::certify_pseudo_AG1(s);
      EXPECT_EQ(c.c0_edges, c.edges);
      EXPECT_EQ(c.middle_edges, c.edges);
      EXPECT_EQ(c.coplanar_vertices, c.vertices);
      // G^1 at a vertex also needs the corner triangles consistently oriented; a folded
      // projection (very sharp vertex) is the documented exception
      std::size_t inverted = 0;
      for (auto v : s.mesh().vertices())
        inverted += s.corner_plane(v).inverted_corner;
      EXPECT_EQ(c.g1_vertices + inverted, c.vertices);
    }
  }
}

TEST(PseudoAG1Certificate, DoubleSurfacesHaveTinyResiduals) { // C2, C3 in double
  for (const std::string name : {"icosahedron", "pentakis", "torus", "cube"}) {
    SCOPED_TRACE(name);
    const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>(name));
    EXPECT_FALSE(s.is_exact());
    const auto c = TS::certify_pseudo_AG1(s);
    EXPECT_FALSE(c.exact);
    EXPECT_TRUE(c.pseudo_AG1());
    EXPECT_LT(c.max_coplanarity, 1e-12);
    const TS::Patch_sampler<Pseudo_AG1_surface<Double>> sampler(s);
    const auto m = TS::measure_closed_surface(s.mesh(), sampler, 9, 2, false);
    EXPECT_LT(m.vertex_max_jump_deg, 1e-9); // G^1 at the vertices
  }
}

// --- measurements -----------------------------------------------------------------------------

TEST(PseudoAG1Measures, RegularTetrahedronIsNotG1AlongEdges) { // C5 in double
  const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>("tetrahedron"));
  const TS::Patch_sampler<Pseudo_AG1_surface<Double>> sampler(s);
  const auto m = TS::measure_closed_surface(s.mesh(), sampler, 15, 3);
  for (double jump : m.edge_max_jump_deg)
    EXPECT_GT(jump, 10);
  EXPECT_LT(m.vertex_max_jump_deg, 1e-9);
  // sanity ranges of AG1.md Appendix A (prototype: 80 deg max, 53 mean, volume 0.22)
  EXPECT_GT(m.max_jump_deg, 60);
  EXPECT_LT(m.max_jump_deg, 100);
  EXPECT_GT(m.volume_ratio, 0.15);
  EXPECT_LT(m.volume_ratio, 0.3);
  EXPECT_EQ(m.inside_fraction, 1.0);
  EXPECT_FALSE(m.self_intersecting);
}

TEST(PseudoAG1Measures, Chapter5ShrinksTheInput) { // C17
  for (const std::string name : {"tetrahedron", "icosahedron"}) {
    const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>(name),
                                       Pseudo_AG1_options::chapter5());
    const TS::Patch_sampler<Pseudo_AG1_surface<Double>> sampler(s);
    const auto m = TS::measure_closed_surface(s.mesh(), sampler, 5, 2, false);
    EXPECT_LT(m.volume_ratio, 1) << name;
    EXPECT_EQ(m.inside_fraction, 1.0) << name;
  }
}

TEST(PseudoAG1Measures, OffsetsReduceJumpsOnSmoothMeshes) { // C24
  for (const std::string name : {"icosahedron", "pentakis", "torus"}) {
    Pseudo_AG1_options flat;
    flat.offsets = {{0, 0, 0}};
    const Pseudo_AG1_surface<Double> with(TS::thesis_polyhedron<Double>(name)),
        without(TS::thesis_polyhedron<Double>(name), flat);
    const TS::Patch_sampler<Pseudo_AG1_surface<Double>> a(with), b(without);
    const double jump_with = TS::measure_closed_surface(with.mesh(), a, 9, 1, false).max_jump_deg;
    const double jump_without =
        TS::measure_closed_surface(without.mesh(), b, 9, 1, false).max_jump_deg;
    EXPECT_LT(jump_with, jump_without) << name;
  }
}

// --- the steps ----------------------------------------------------------------------------

TEST(PseudoAG1Steps, UmbrellaKeepsLengthsAndAngleRatios) { // C21
  Pseudo_AG1_options o;
  o.offsets = {{0, 0, 0}}; // first stars (4v + w)/5: lengths |w - v|/5
  o.recentering = false;
  for (const std::string name : {"icosahedron", "pentakis", "cube"}) {
    const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>(name), o);
    const auto& m = s.mesh();
    for (auto v : m.vertices()) {
      const auto ring = TS::outgoing_ring(v, m);
      const auto& plane = s.corner_plane(v);
      if (plane.equalised)
        continue;
      std::vector<double> alpha, alpha_star;
      double sum = 0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto h = ring[i], g = ring[(i + 1) % ring.size()];
        const double spoke = std::sqrt((m.point(m.target(h)) - m.point(v)).squared_length()) / 5;
        const auto S = s.star(h) - plane.corner, T = s.star(g) - plane.corner;
        EXPECT_NEAR(std::sqrt(S.squared_length()), spoke, 1e-12 * spoke);
        const auto a = m.point(m.target(h)) - m.point(v), b = m.point(m.target(g)) - m.point(v);
        alpha.push_back(std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b));
        alpha_star.push_back(
            std::atan2(std::sqrt(CGAL::cross_product(S, T).squared_length()), S * T));
        sum += alpha_star.back();
      }
      EXPECT_NEAR(sum, 2 * CGAL_PI, 1e-12);
      for (std::size_t i = 1; i < alpha.size(); ++i)
        EXPECT_NEAR(alpha_star[i] / alpha_star[0], alpha[i] / alpha[0], 1e-10);
    }
  }
}

TEST(PseudoAG1Steps, UndulationGainLowersSharpAndRaisesFlatVertices) { // C25
  Pseudo_AG1_options off;
  off.undulation_gain = 0;
  for (const std::string name : {"tetrahedron", "star", "cube-centres"}) {
    const Pseudo_AG1_surface<Double> on(TS::thesis_polyhedron<Double>(name)),
        without(TS::thesis_polyhedron<Double>(name), off);
    for (auto v : on.mesh().vertices()) {
      const auto& a = on.corner_plane(v);
      const auto& b = without.corner_plane(v);
      const double unit = std::sqrt(a.normal.squared_length());
      const double d = (a.centroid - (on.mesh().point(v) - CGAL::ORIGIN)) * a.normal / unit;
      if (d == 0)
        continue;
      const double ha = a.offset / unit, hb = b.offset / unit;
      if (a.mean_dihedral < 4 * CGAL_PI / 5) {
        EXPECT_LT(ha, hb) << name << " vertex " << std::size_t(v);
      } else if (a.mean_dihedral > 4 * CGAL_PI / 5) {
        EXPECT_GT(ha, hb) << name << " vertex " << std::size_t(v);
      }
    }
  }
}

TEST(PseudoAG1Steps, DegenerateCasesAreFlaggedNotFatal) { // C32
  Pseudo_AG1_options centroid;
  centroid.normal = TS::Corner_plane_normal::CENTROID;
  centroid.offsets = {{0, 0, 0}};
  const Pseudo_AG1_surface<Exact> cube(TS::thesis_polyhedron<Exact>("cube-centres"), centroid);
  std::size_t fallbacks = 0;
  for (auto v : cube.mesh().vertices())
    fallbacks += cube.corner_plane(v).normal_fallback;
  EXPECT_EQ(fallbacks, 6u); // the flat face centres, where C = v

  // with the default offsets the projected stars fold: at 6 vertices of the V-arm bipyramid
  // and at 1 of Sato's tetrahedron (AG1.md C32)
  const Pseudo_AG1_surface<Double> folded_arm(TS::thesis_polyhedron<Double>("v-arm"));
  std::size_t folded_arm_count = 0;
  for (auto v : folded_arm.mesh().vertices())
    folded_arm_count += folded_arm.corner_plane(v).folded_projection;
  EXPECT_EQ(folded_arm_count, 6u);

  Pseudo_AG1_options flat;
  flat.offsets = {{0, 0, 0}};
  const Pseudo_AG1_surface<Double> arm(TS::thesis_polyhedron<Double>("v-arm"), flat);
  std::size_t recentred = 0;
  for (auto v : arm.mesh().vertices())
    recentred += arm.corner_plane(v).recentred;
  EXPECT_EQ(recentred, 2u); // both apexes

  const Pseudo_AG1_surface<Double> sato(TS::thesis_polyhedron<Double>("sato"));
  std::size_t folded = 0;
  for (auto v : sato.mesh().vertices())
    folded += sato.corner_plane(v).folded_projection;
  EXPECT_EQ(folded, 1u);
  EXPECT_TRUE(TS::certify_pseudo_AG1(sato).middle_edges == sato.mesh().number_of_edges());
}

// An octahedron whose top vertex sits eps above the midpoint of its neighbours +x and +y: the
// sliver face (+x, +y, top) has an angle pi - O(eps) at the top, so the proportional umbrella
// would get an angle of pi (a degenerate corner triangle) without R-13's equalisation.
Mesh<Double> octahedron_with_straight_angle(double eps) {
  Mesh<Double> m;
  const auto top = m.add_vertex({0.5, 0.5, eps});
  const auto px = m.add_vertex({1, 0, 0}), py = m.add_vertex({0, 1, 0});
  const auto mx = m.add_vertex({-1, 0, 0}), my = m.add_vertex({0, -1, 0});
  const auto bottom = m.add_vertex({0, 0, -1});
  for (auto [a, b] : {std::pair{px, py}, {py, mx}, {mx, my}, {my, px}}) {
    m.add_face(a, b, top);
    m.add_face(b, a, bottom);
  }
  return m;
}

TEST(PseudoAG1Steps, StraightUmbrellaAnglesAreEqualisedAndFlagged) { // C32, R-13
  for (const bool offsets : {true, false}) {
    Pseudo_AG1_options o;
    if (!offsets)
      o.offsets = {{0, 0, 0}};
    o.recentering = false;
    const Pseudo_AG1_surface<Double> s(octahedron_with_straight_angle(1e-12), o);
    const auto& m = s.mesh();
    std::size_t equalised = 0;
    for (auto v : m.vertices()) {
      const auto& plane = s.corner_plane(v);
      equalised += plane.equalised;
      EXPECT_FALSE(plane.inverted_corner) << std::size_t(v);
      // every corner triangle of the umbrella keeps a positive angle below pi
      const auto& u = plane.umbrella;
      for (std::size_t i = 0; i < u.size(); ++i) {
        const auto& a = u[i];
        const auto& b = u[(i + 1) % u.size()];
        const double cross = a.x() * b.y() - a.y() * b.x(), dot = a.x() * b.x() + a.y() * b.y();
        EXPECT_GT(std::atan2(cross, dot), 0.01) << std::size_t(v) << " " << i;
      }
    }
    // the top (angle pi) and +x, +y (angle 0); the default offsets lift the first stars off
    // the sliver, which opens its angles: nothing to equalise
    const std::size_t expected = offsets ? 0 : 3;
    EXPECT_EQ(equalised, expected) << offsets;
    for (std::size_t v : {0, 1, 2})
      EXPECT_EQ(s.corner_plane(Mesh<Double>::Vertex_index(v)).equalised, !offsets) << v;
    EXPECT_EQ(s.flags().equalised_umbrellas, expected);
    const TS::Pseudo_AG1_certificate c = TS::certify_pseudo_AG1(s);
    EXPECT_TRUE(c.pseudo_AG1()) << offsets;
  }
  // a clear angle is left alone
  EXPECT_EQ(
      Pseudo_AG1_surface<Double>(octahedron_with_straight_angle(0.3)).flags().equalised_umbrellas,
      0u);
}

TEST(PseudoAG1Steps, RecentredCornerLiesInsideTheProjectedStar) {
  Pseudo_AG1_options o = Pseudo_AG1_options::exact();
  const Pseudo_AG1_surface<Exact> arm(TS::thesis_polyhedron<Exact>("v-arm"), o);
  ASSERT_TRUE(arm.is_exact());
  std::size_t recentred = 0;
  for (auto v : arm.mesh().vertices()) {
    const auto& plane = arm.corner_plane(v);
    if (!plane.recentred)
      continue;
    ++recentred;
    // the umbrella of a projection placement is the projected star polygon around z: z (the
    // origin of the umbrella) must be strictly inside it
    typename Exact::Point_2 origin(0, 0);
    const auto& u = plane.umbrella;
    EXPECT_EQ(CGAL::bounded_side_2(u.begin(), u.end(), origin, Exact()), CGAL::ON_BOUNDED_SIDE);
  }
  EXPECT_EQ(recentred, 2u);
  EXPECT_TRUE(TS::certify_pseudo_AG1(arm).pseudo_AG1());
}

// --- invariances ----------------------------------------------------------------------------

TEST(PseudoAG1Invariance, ExactSurfaceCommutesWithRationalSimilarities) { // C28, exact
  using FT = Exact::FT;
  const Mesh<Exact> mesh = TS::thesis_polyhedron<Exact>("v-arm");
  // x -> s Q x + t with Q the rational rotation of the 3-4-5 triangle about z then x
  const FT sc(7, 3);
  auto map = [&](const typename Exact::Vector_3& x) {
    const FT a = (FT(3) * x.x() - FT(4) * x.y()) / FT(5),
             b = (FT(4) * x.x() + FT(3) * x.y()) / FT(5);
    const FT c = x.z();
    const FT b2 = (FT(5) * b - FT(12) * c) / FT(13), c2 = (FT(12) * b + FT(5) * c) / FT(13);
    return sc * typename Exact::Vector_3(a, b2, c2) + typename Exact::Vector_3(1, -2, FT(1, 3));
  };
  Mesh<Exact> moved = mesh;
  for (auto v : moved.vertices())
    moved.point(v) = CGAL::ORIGIN + map(mesh.point(v) - CGAL::ORIGIN);
  const Pseudo_AG1_surface<Exact> a(mesh, Pseudo_AG1_options::exact()),
      b(moved, Pseudo_AG1_options::exact());
  for (auto f : a.mesh().faces()) {
    const auto na = a.control_net(f), nb = b.control_net(f);
    for (std::size_t i = 0; i < na.size(); ++i)
      EXPECT_EQ(map(na[i]), nb[i]);
  }
}

TEST(PseudoAG1Invariance, ThesisSurfaceCommutesWithSimilarities) { // C28, double
  const Mesh<Double> mesh = TS::thesis_polyhedron<Double>("pentakis");
  const double sc = 3.7, c = std::cos(0.7), s = std::sin(0.7);
  auto map = [&](const Double::Vector_3& x) {
    return Double::Vector_3(sc * (c * x.x() - s * x.y()) + 1, sc * (s * x.x() + c * x.y()) - 2,
                            sc * x.z() + 0.5);
  };
  Mesh<Double> moved = mesh;
  for (auto v : moved.vertices())
    moved.point(v) = CGAL::ORIGIN + map(mesh.point(v) - CGAL::ORIGIN);
  Pseudo_AG1_options o;
  o.edge_map = TS::Edge_map::AVERAGED_DIAMOND;
  const Pseudo_AG1_surface<Double> a(mesh, o), b(moved, o);
  double worst = 0;
  for (auto f : a.mesh().faces()) {
    const auto na = a.control_net(f), nb = b.control_net(f);
    for (std::size_t i = 0; i < na.size(); ++i)
      worst = std::max(worst, std::sqrt((map(na[i]) - nb[i]).squared_length()));
  }
  EXPECT_LT(worst, 1e-12 * sc * 4); // diagonal of the input about 4 after scaling
}

TEST(PseudoAG1Invariance, RelabellingVerticesAndFacesChangesNothing) { // C27
  const Mesh<Double> mesh = TS::thesis_polyhedron<Double>("pentakis");
  const std::size_t n = mesh.number_of_vertices();
  std::vector<std::size_t> perm(n);
  for (std::size_t i = 0; i < n; ++i)
    perm[i] = (i * 17 + 5) % n; // 17 is prime to 42
  Mesh<Double> relabelled;
  std::vector<Mesh<Double>::Vertex_index> inverse(n);
  std::vector<std::size_t> old_of(n);
  for (std::size_t i = 0; i < n; ++i)
    old_of[perm[i]] = i;
  for (std::size_t j = 0; j < n; ++j)
    inverse[old_of[j]] = relabelled.add_vertex(mesh.point(Mesh<Double>::Vertex_index(old_of[j])));
  std::vector<std::array<std::size_t, 3>> faces;
  for (auto f : mesh.faces()) {
    std::array<std::size_t, 3> t;
    std::size_t i = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[i++] = std::size_t(v);
    faces.push_back(t);
  }
  std::reverse(faces.begin(), faces.end());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const auto& t = faces[k];
    const std::size_t r = k % 3; // rotate the vertex order
    relabelled.add_face(inverse[t[r]], inverse[t[(r + 1) % 3]], inverse[t[(r + 2) % 3]]);
  }
  const Pseudo_AG1_surface<Double> a(mesh), b(relabelled);
  double worst = 0;
  for (auto h : a.mesh().halfedges()) {
    const auto g = b.mesh().halfedge(inverse[std::size_t(a.mesh().source(h))],
                                     inverse[std::size_t(a.mesh().target(h))]);
    ASSERT_NE(g, Mesh<Double>::null_halfedge());
    for (const auto& d : {a.star(h) - b.star(g), a.edge_middle(h) - b.edge_middle(g),
                          a.corner_inner(h) - b.corner_inner(g), a.flip(h) - b.flip(g)})
      worst = std::max(worst, std::sqrt(d.squared_length()));
  }
  EXPECT_LT(worst, 1e-12);
}

// --- local control ----------------------------------------------------------------------

TEST(PseudoAG1LocalControl, EditsChangeOnlyTheListedFacesAndKeepTheCertificate) { // C26
  Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("cube"), Pseudo_AG1_options::exact());
  const auto before = s;
  const auto h = *s.mesh().halfedges().begin();
  const auto changed = s.edit_corner_inner(h, s.corner_inner(h) + vec<Exact>(1, 2, 3));
  EXPECT_EQ(changed.size(), 3u);
  for (auto f : s.mesh().faces()) {
    const bool listed = std::find(changed.begin(), changed.end(), f) != changed.end();
    EXPECT_EQ(s.control_net(f) != before.control_net(f), listed) << std::size_t(f);
  }
  EXPECT_TRUE(TS::certify_pseudo_AG1(s).pseudo_AG1());
  const auto g = s.mesh().next(h);
  const auto flips = s.edit_flip(g, vec<Exact>(5, 5, 5));
  EXPECT_EQ(flips.size(), 2u);
  EXPECT_EQ(s.flip(g), vec<Exact>(5, 5, 5));
  EXPECT_TRUE(TS::certify_pseudo_AG1(s).pseudo_AG1());
}

TEST(PseudoAG1LocalControl, MovingAVertexChangesOnlyItsTwoRing) { // C26, last bullet
  const Mesh<Double> mesh = TS::thesis_polyhedron<Double>("pentakis");
  Mesh<Double> moved = mesh;
  const Mesh<Double>::Vertex_index v(7);
  moved.point(v) = moved.point(v) + Double::Vector_3(0.01, -0.02, 0.03);
  const Pseudo_AG1_surface<Double> a(mesh), b(moved);
  // faces touching the closed 1-ring of v
  std::vector<bool> near(mesh.number_of_vertices(), false);
  near[v] = true;
  for (auto w : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
    near[w] = true;
  std::size_t changed = 0, expected = 0;
  for (auto f : mesh.faces()) {
    bool touches = false;
    for (auto w : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      touches = touches || near[w];
    expected += touches;
    const bool differs = a.control_net(f) != b.control_net(f);
    changed += differs;
    if (differs) {
      EXPECT_TRUE(touches) << std::size_t(f);
    }
  }
  EXPECT_EQ(changed, expected);
}

// --- validation ---------------------------------------------------------------------------

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const TS::Invalid_input& e) {
    return e.what();
  }
  return "";
}

TEST(PseudoAG1Validation, BadMeshesAreRejectedNamingTheElement) { // C30
  Mesh<Double> open = TS::thesis_polyhedron<Double>("tetrahedron");
  CGAL::Euler::remove_face(open.halfedge(*open.faces().begin()), open);
  open.collect_garbage();
  EXPECT_NE(error_of([&] { Pseudo_AG1_surface<Double> s(open); }).find("not closed"),
            std::string::npos)
      << error_of([&] { Pseudo_AG1_surface<Double> s(open); });

  Mesh<Double> flat;
  auto a = flat.add_vertex({0, 0, 0}), b = flat.add_vertex({1, 0, 0}),
       c = flat.add_vertex({2, 0, 0}), d = flat.add_vertex({0, 1, 1});
  flat.add_face(a, b, c);
  flat.add_face(a, d, b);
  flat.add_face(b, d, c);
  flat.add_face(c, d, a);
  EXPECT_NE(error_of([&] { Pseudo_AG1_surface<Double> s(flat); }).find("face 0 has zero area"),
            std::string::npos);

  Mesh<Double> nan = TS::thesis_polyhedron<Double>("tetrahedron");
  nan.point(*nan.vertices().begin()) = Double::Point_3(std::nan(""), 0, 0);
  EXPECT_NE(error_of([&] { Pseudo_AG1_surface<Double> s(nan); }).find("non-finite"),
            std::string::npos);

  Mesh<Double> quad;
  auto p = quad.add_vertex({0, 0, 0}), q = quad.add_vertex({1, 0, 0}),
       r = quad.add_vertex({1, 1, 0}), t = quad.add_vertex({0, 1, 0});
  quad.add_face(p, q, r, t);
  quad.add_face(t, r, q, p);
  EXPECT_NE(error_of([&] { Pseudo_AG1_surface<Double> s(quad); }).find("not a triangle"),
            std::string::npos);

  EXPECT_NE(error_of([&] { Pseudo_AG1_surface<Double> s(Mesh<Double>{}); }).find("no face"),
            std::string::npos);

  Pseudo_AG1_options bad;
  bad.star_scale = 0;
  EXPECT_NE(error_of([&] {
              Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>("tetrahedron"), bad);
            }).find("star scale"),
            std::string::npos);
  EXPECT_NE(error_of([] { TS::pseudo_AG1_preset("fancy"); }).find("unknown preset"),
            std::string::npos);
}

TEST(PseudoAG1Validation, InwardComponentsAreReorientedAndCounted) { // R-5, C30
  Mesh<Exact> mesh = TS::thesis_polyhedron<Exact>("tetrahedron");
  Mesh<Exact> twice = mesh;
  // a second, inward copy far away
  std::vector<Mesh<Exact>::Vertex_index> map;
  for (auto v : mesh.vertices())
    map.push_back(twice.add_vertex(mesh.point(v) + typename Exact::Vector_3(10, 0, 0)));
  for (auto f : mesh.faces()) {
    std::vector<Mesh<Exact>::Vertex_index> t;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t.push_back(map[std::size_t(v)]);
    twice.add_face(t[2], t[1], t[0]);
  }
  const Pseudo_AG1_surface<Exact> s(twice, Pseudo_AG1_options::exact());
  EXPECT_EQ(s.mesh_summary().components.size(), 2u);
  EXPECT_EQ(s.mesh_summary().reoriented, 1u);
  EXPECT_EQ(s.mesh_summary().components[0].euler, 2);
  EXPECT_TRUE(TS::certify_pseudo_AG1(s).pseudo_AG1());
  // the copy's corners are the originals shifted
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(s.corner_plane(Mesh<Exact>::Vertex_index(i + 4)).corner,
              s.corner_plane(Mesh<Exact>::Vertex_index(i)).corner +
                  typename Exact::Vector_3(10, 0, 0));
}

TEST(PseudoAG1Validation, TorusNineHasEulerCharacteristicZero) { // C30, Fig. 5.5
  const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>("torus9"));
  ASSERT_EQ(s.mesh_summary().components.size(), 1u);
  EXPECT_EQ(s.mesh_summary().components[0].euler, 0);
  EXPECT_EQ(s.mesh_summary().components[0].genus, 1);
  EXPECT_TRUE(TS::certify_pseudo_AG1(s).pseudo_AG1());
}

} // namespace

// --- the tspline-surface file ---------------------------------------------------------------

namespace {

TEST(PseudoAG1SurfaceFile, ExactRoundTripKeepsEveryControlPointAndTheProof) {
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("v-arm"),
                                    Pseudo_AG1_options::exact());
  std::stringstream file;
  TS::write_surface_file(file, s);
  const TS::Surface_file<Exact> read = TS::read_surface_file<Exact>(file, "test.surface");
  EXPECT_TRUE(read.exact_numbers());
  ASSERT_EQ(read.mesh().number_of_faces(), s.mesh().number_of_faces());
  for (auto f : s.mesh().faces())
    EXPECT_EQ(read.control_net(f), s.control_net(f));
  // certified from the nets alone: the relations are solved, not read
  const TS::Pseudo_AG1_view<TS::Surface_file<Exact>> view(read);
  const auto c = TS::certify_pseudo_AG1(view);
  EXPECT_TRUE(c.exact);
  EXPECT_TRUE(c.pseudo_AG1());
  EXPECT_EQ(c.ag1_edges, TS::certify_pseudo_AG1(s).ag1_edges);
  for (auto e : s.mesh().edges())
    EXPECT_EQ(view.edge_relation(e).relation, s.edge_relation(e).relation);
}

TEST(PseudoAG1SurfaceFile, RotatedFaceLinesAreReindexed) {
  const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>("octahedron"),
                                    Pseudo_AG1_options::exact());
  std::stringstream file;
  TS::write_surface_file(file, s);
  // rotate every face line (a b c) -> (b c a) and its patch accordingly
  std::string text = file.str(), out;
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line))
    lines.push_back(line);
  std::size_t faces_at = 0, patches_at = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("faces ", 0) == 0)
      faces_at = i;
    if (lines[i] == "patches")
      patches_at = i;
  }
  const std::size_t F = patches_at - faces_at - 1;
  for (std::size_t f = 0; f < F; ++f) {
    std::istringstream face(lines[faces_at + 1 + f]);
    std::string a, b, c;
    face >> a >> b >> c;
    lines[faces_at + 1 + f] = b + " " + c + " " + a;
    std::istringstream patch(lines[patches_at + 1 + f]);
    std::vector<std::string> numbers(63);
    for (auto& x : numbers)
      patch >> x;
    std::string rotated;
    for (const auto& index : TS::multi_indices(5)) {
      // new order (b, c, a): the point of index (i, j, k) over (b, c, a) is (k, i, j) over (a, b,
      // c)
      const std::size_t old = TS::linear_index(TS::Multi_index{index[2], index[0], index[1]});
      for (int d = 0; d < 3; ++d)
        rotated += (rotated.empty() ? "" : " ") + numbers[3 * old + std::size_t(d)];
    }
    lines[patches_at + 1 + f] = rotated;
  }
  for (const auto& l : lines)
    out += l + "\n";
  std::istringstream rotated_file(out);
  const TS::Surface_file<Exact> read = TS::read_surface_file<Exact>(rotated_file, "rotated");
  // the read faces start at b: compare the points with the same powers of the same vertices
  auto corners = [](const Mesh<Exact>& m, Mesh<Exact>::Face_index f) {
    const auto h = m.halfedge(f);
    return std::array<Mesh<Exact>::Vertex_index, 3>{
        {m.target(h), m.target(m.next(h)), m.source(h)}};
  };
  std::size_t rotated_faces = 0;
  for (auto f : s.mesh().faces()) {
    const auto cs = corners(s.mesh(), f), cr = corners(read.mesh(), f);
    rotated_faces += cs[0] != cr[0];
    for (const auto& index : TS::multi_indices(5)) {
      TS::Multi_index in_s;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          if (cr[std::size_t(a)] == cs[std::size_t(b)])
            in_s[b] = index[a];
      EXPECT_EQ(read.control_net(f)[TS::linear_index(index)],
                s.control_net(f)[TS::linear_index(in_s)]);
    }
  }
  EXPECT_EQ(rotated_faces, s.mesh().number_of_faces());
}

TEST(PseudoAG1SurfaceFile, MalformedFilesGiveOneLineErrors) {
  const std::string head = "tspline-surface 1\ndegree 5\nnumber_type exact\n";
  const std::string tetra = "vertices 4\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n";
  auto error = [](const std::string& text) {
    std::istringstream in(text);
    try {
      TS::read_surface_file<Exact>(in, "bad.surface");
    } catch (const TS::Invalid_input& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("tspline-spline 1\n").find("bad.surface:1: not a tspline-surface file"),
            std::string::npos);
  EXPECT_NE(error(head + "vertices 99999999\n0 0 0\n").find("cannot fit"), std::string::npos);
  EXPECT_NE(error(head + tetra + "faces 1\n0 1 1\n").find("repeats a vertex"), std::string::npos);
  EXPECT_NE(error(head + tetra + "faces 1\n0 1 7\n").find("out of range"), std::string::npos);
  // an open mesh (one face) with its patch
  std::string one = head + tetra + "faces 1\n0 1 2\npatches\n";
  for (int i = 0; i < 63; ++i)
    one += (i ? " 0" : "0");
  one += "\nend\n";
  EXPECT_NE(error(one).find("bad.surface: vertex 3 is isolated"), std::string::npos) << error(one);
  std::string short_patch = head + tetra + "faces 1\n0 1 2\npatches\n";
  for (int i = 0; i < 62; ++i)
    short_patch += (i ? " 10" : "10");
  EXPECT_NE(error(short_patch + "\nend\n").find(":12: expected 63 numbers for patch 0 of 1"),
            std::string::npos)
      << error(short_patch + "\nend\n");
  EXPECT_NE(error(head + tetra + "faces 1\n0 1 2\npatches\n1 2 3\nend\n").find("cannot fit"),
            std::string::npos);
  EXPECT_NE(error(head + tetra + "faces 0\npatches\nend\nmore\n").find("after \"end\""),
            std::string::npos);
}

} // namespace

namespace {

TEST(PseudoAG1Measures, SmoothPresetBeatsPNTrianglesOnSmoothMeshes) { // issue 11: comparison
  for (const std::string name : {"icosahedron", "pentakis", "torus"}) {
    SCOPED_TRACE(name);
    const auto mesh = TS::thesis_polyhedron<Epick>(name);
    const Pseudo_AG1_surface<Epick> thesis(mesh), smooth(mesh, Pseudo_AG1_options::smooth());
    EXPECT_TRUE(TS::certify_pseudo_AG1(smooth).pseudo_AG1());
    struct PN {
      std::vector<TS::Bezier_triangle<Epick, Epick::Vector_3>> patches;
      const auto& patch(CGAL::Surface_mesh<Epick::Point_3>::Face_index f) const {
        return patches[f];
      }
    } pn{TS::pn_triangles<Epick>(mesh)};
    const TS::Patch_sampler<Pseudo_AG1_surface<Epick>> a(thesis), b(smooth);
    const TS::Patch_sampler<PN> c(pn);
    const double jump_thesis = TS::measure_closed_surface(mesh, a, 9, 0, false).mean_jump_deg;
    const double jump_smooth = TS::measure_closed_surface(mesh, b, 9, 0, false).mean_jump_deg;
    const double jump_pn = TS::measure_closed_surface(mesh, c, 9, 0, false).mean_jump_deg;
    // the icosahedron's end diamonds are not convex: the averaged map falls back to the
    // parallelogram on every edge, and the surfaces agree up to round-off
    if (name == "icosahedron") {
      EXPECT_NEAR(jump_smooth, jump_thesis, 1e-9);
    } else {
      EXPECT_LT(jump_smooth, 0.8 * jump_thesis);
    }
    EXPECT_LT(jump_smooth, jump_pn);
    EXPECT_LT(jump_thesis, jump_pn);
  }
}

} // namespace

namespace {

TEST(PseudoAG1Global, TetrahedronAG1SurfaceExistsAndFolds) { // C14
  using FT = Exact::FT;
  const auto mesh = TS::thesis_polyhedron<Exact>("tetrahedron");
  const auto a = Mesh<Exact>::Vertex_index(0);
  const TS::AG1_walk<FT> walk = TS::walk_AG1_system(mesh, a, TS::centroid_umbrella<FT>(3));
  ASSERT_TRUE(walk.consistent && walk.complete);
  const TS::Surface_file<Exact> s = TS::ag1_surface_from_walk<Exact>(mesh, walk);
  // corners (11/15)(1,1,1), (9/5,-1/5,-1/5), (-1/5,9/5,-1/5), (-1/5,-1/5,9/5)
  auto corner = [&](std::size_t v) {
    for (auto f : s.mesh().faces()) {
      const auto h = s.mesh().halfedge(f);
      const std::array<Mesh<Exact>::Vertex_index, 3> c{
          {s.mesh().target(h), s.mesh().target(s.mesh().next(h)), s.mesh().source(h)}};
      for (int i = 0; i < 3; ++i)
        if (std::size_t(c[std::size_t(i)]) == v) {
          TS::Multi_index index;
          index[i] = 5;
          return s.control_net(f)[TS::linear_index(index)];
        }
    }
    return Exact::Vector_3(CGAL::NULL_VECTOR);
  };
  EXPECT_EQ(corner(0), vec<Exact>(FT(11, 15), FT(11, 15), FT(11, 15)));
  EXPECT_EQ(corner(1), vec<Exact>(FT(9, 5), FT(-1, 5), FT(-1, 5)));
  EXPECT_EQ(corner(2), vec<Exact>(FT(-1, 5), FT(9, 5), FT(-1, 5)));
  EXPECT_EQ(corner(3), vec<Exact>(FT(-1, 5), FT(-1, 5), FT(9, 5)));
  // all five diamonds of every edge on one relation, solved from the nets alone
  const TS::Pseudo_AG1_view<TS::Surface_file<Exact>> view(s);
  const auto c = TS::certify_pseudo_AG1(view);
  ASSERT_TRUE(c.exact);
  EXPECT_EQ(c.c0_edges, 6u);
  EXPECT_EQ(c.ag1_edges, 6u);
  // ab, ac, ad admit a reparameterization and join C^1 there; bc, bd, cd do not (lambda >= 0)
  EXPECT_EQ(c.inadmissible_edges, 3u);
  for (auto e : s.mesh().edges()) {
    const auto h = TS::canonical_halfedge(e, s.mesh());
    const bool at_a = s.mesh().source(h) == a || s.mesh().target(h) == a;
    EXPECT_EQ(c.per_edge[e].admissible, at_a);
    if (at_a) {
      EXPECT_EQ(c.per_edge[e].join_order, 1);
    }
  }
  // in double: tangent planes agree along every edge, but the normals reverse across the
  // three inadmissible edges (the fold)
  const auto dmesh = TS::thesis_polyhedron<Epick>("tetrahedron");
  const auto dwalk =
      TS::walk_AG1_system(dmesh, Mesh<Epick>::Vertex_index(0), TS::centroid_umbrella<double>(3));
  const TS::Surface_file<Epick> ds = TS::ag1_surface_from_walk<Epick>(dmesh, dwalk);
  const TS::Patch_sampler<TS::Surface_file<Epick>> sampler(ds);
  const auto m = TS::measure_closed_surface(ds.mesh(), sampler, 9, 0, false);
  EXPECT_LT(m.max_unoriented_jump_deg, 1e-9);
  std::size_t reversed = 0;
  for (double jump : m.edge_max_jump_deg)
    reversed += jump > 179;
  EXPECT_EQ(reversed, 3u);
}

} // namespace

namespace {

TEST(PseudoAG1Lemmas, ReparameterizationKeepsTheControlPoints) { // C6, Lemma 5.3.3
  using FT = Exact::FT;
  Random_rationals random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const auto t = random.triangle<Exact>();
    std::vector<Exact::Vector_3> net;
    for (std::size_t i = 0; i < TS::number_of_control_points(5); ++i)
      net.push_back(
          Exact::Vector_3(random.rational<FT>(), random.rational<FT>(), random.rational<FT>()));
    // a random affine bijection rho
    FT a, b, c, d;
    do {
      a = random.rational<FT>(), b = random.rational<FT>(), c = random.rational<FT>(),
      d = random.rational<FT>();
    } while (a * d - b * c == FT(0));
    const FT e = random.rational<FT>(), f = random.rational<FT>();
    auto rho = [&](const Exact::Point_2& p) {
      return Exact::Point_2(a * p.x() + b * p.y() + e, c * p.x() + d * p.y() + f);
    };
    const TS::Bezier_triangle<Exact, Exact::Vector_3> F(5, t[0], t[1], t[2], net),
        G(5, rho(t[0]), rho(t[1]), rho(t[2]), net);
    for (int k = 0; k < 5; ++k) {
      const auto x = random.point<Exact>();
      EXPECT_EQ(G.evaluate(rho(x)), F.evaluate(x)); // G = F o rho^-1
    }
  }
}

TEST(PseudoAG1Lemmas, CornerRegionIsTheAffineImageOfTheUmbrella) { // C7, Lemma 3.3.2
  for (const std::string name : {"octahedron", "cube", "v-arm", "torus9"}) {
    SCOPED_TRACE(name);
    const Pseudo_AG1_surface<Exact> s(TS::thesis_polyhedron<Exact>(name),
                                      Pseudo_AG1_options::exact());
    for (auto v : s.mesh().vertices()) {
      const auto ring = TS::outgoing_ring(v, s.mesh());
      const auto& plane = s.corner_plane(v);
      const auto& u = plane.umbrella;
      ASSERT_EQ(u.size(), ring.size());
      // u_l = alpha u_0 + beta u_1 in the plane: then S_l - z = alpha (S_0 - z) + beta (S_1 - z)
      const Exact::FT d = u[0].x() * u[1].y() - u[0].y() * u[1].x();
      ASSERT_NE(d, Exact::FT(0));
      const auto S0 = s.star(ring[0]) - plane.corner, S1 = s.star(ring[1]) - plane.corner;
      for (std::size_t l = 2; l < ring.size(); ++l) {
        const Exact::FT alpha = (u[l].x() * u[1].y() - u[l].y() * u[1].x()) / d;
        const Exact::FT beta = (u[0].x() * u[l].y() - u[0].y() * u[l].x()) / d;
        EXPECT_EQ(s.star(ring[l]) - plane.corner, alpha * S0 + beta * S1);
      }
    }
  }
}

TEST(PseudoAG1Lemmas, Chapter5CornerRegionsAreRegular) { // C18, Fig. 5.13
  const Pseudo_AG1_surface<Exact> tetra(TS::thesis_polyhedron<Exact>("tetrahedron"),
                                        Pseudo_AG1_options::chapter5());
  for (auto v : tetra.mesh().vertices()) {
    const auto ring = TS::outgoing_ring(v, tetra.mesh());
    const auto z = tetra.corner_plane(v).corner;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto next = ring[(i + 1) % ring.size()];
      EXPECT_EQ((tetra.star(ring[i]) - z).squared_length(),
                (tetra.star(next) - z).squared_length());
      EXPECT_EQ((tetra.star(ring[i]) - tetra.star(next)).squared_length(),
                (tetra.star(ring[0]) - tetra.star(ring[1])).squared_length());
    }
  }
  const Pseudo_AG1_surface<Double> ico(TS::thesis_polyhedron<Double>("icosahedron"),
                                       Pseudo_AG1_options::chapter5());
  for (auto v : ico.mesh().vertices()) {
    const auto ring = TS::outgoing_ring(v, ico.mesh());
    ASSERT_EQ(ring.size(), 5u);
    const auto z = ico.corner_plane(v).corner;
    const double r = std::sqrt((ico.star(ring[0]) - z).squared_length());
    const double side = std::sqrt((ico.star(ring[0]) - ico.star(ring[1])).squared_length());
    for (std::size_t i = 0; i < 5; ++i) {
      EXPECT_NEAR(std::sqrt((ico.star(ring[i]) - z).squared_length()), r, 1e-12);
      EXPECT_NEAR(std::sqrt((ico.star(ring[i]) - ico.star(ring[(i + 1) % 5])).squared_length()),
                  side, 1e-12);
    }
  }
}

TEST(PseudoAG1RealMesh, ElephantIsPseudoAG1AndBeatsPNTriangles) { // issue 11, must show
  CGAL::Surface_mesh<Epick::Point_3> mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(TSPLINE_DATA_DIR) + "/elephant.off", mesh));
  ASSERT_EQ(mesh.number_of_faces(), 5558u);
  const Pseudo_AG1_surface<Epick> s(mesh, Pseudo_AG1_options::smooth());
  const auto c = TS::certify_pseudo_AG1(s);
  EXPECT_EQ(c.c0_edges, c.edges);
  EXPECT_EQ(c.middle_edges, c.edges);
  EXPECT_EQ(c.g1_vertices, c.vertices);
  struct PN {
    std::vector<TS::Bezier_triangle<Epick, Epick::Vector_3>> patches;
    const auto& patch(CGAL::Surface_mesh<Epick::Point_3>::Face_index f) const { return patches[f]; }
  } pn{TS::pn_triangles<Epick>(mesh)};
  const TS::Patch_sampler<Pseudo_AG1_surface<Epick>> a(s);
  const TS::Patch_sampler<PN> b(pn);
  const auto ours = TS::measure_closed_surface(s.mesh(), a, 5, 0, false);
  const auto theirs = TS::measure_closed_surface(mesh, b, 5, 0, false);
  EXPECT_LT(ours.vertex_max_jump_deg, 1e-9);
  EXPECT_LT(ours.mean_jump_deg, theirs.mean_jump_deg);
  EXPECT_LT(ours.hausdorff_rel, 0.01); // no spikes
}

} // namespace

namespace {

// The octahedron with the face (top, e0, e1) and the face below it split into k coplanar
// triangles along the equator edge e0-e1.
template <class K>
CGAL::Surface_mesh<typename K::Point_3> octahedron_with_thin_faces(int k) {
  using FT = typename K::FT;
  CGAL::Surface_mesh<typename K::Point_3> m;
  const auto top = m.add_vertex({0, 0, 1}), bottom = m.add_vertex({0, 0, -1});
  const auto e0 = m.add_vertex({1, 0, 0}), e1 = m.add_vertex({0, 1, 0}),
             e2 = m.add_vertex({-1, 0, 0}), e3 = m.add_vertex({0, -1, 0});
  std::vector<typename CGAL::Surface_mesh<typename K::Point_3>::Vertex_index> edge{e0};
  for (int j = 1; j < k; ++j)
    edge.push_back(m.add_vertex({FT(k - j) / FT(k), FT(j) / FT(k), 0}));
  edge.push_back(e1);
  for (std::size_t j = 0; j + 1 < edge.size(); ++j) {
    m.add_face(top, edge[j], edge[j + 1]);
    m.add_face(bottom, edge[j + 1], edge[j]);
  }
  m.add_face(top, e1, e2);
  m.add_face(top, e2, e3);
  m.add_face(top, e3, e0);
  m.add_face(bottom, e2, e1);
  m.add_face(bottom, e3, e2);
  m.add_face(bottom, e0, e3);
  return m;
}

TEST(PseudoAG1Steps, AverageNormalIsBiasedByThinFacesAreaWeightedIsNot) { // C19
  Pseudo_AG1_options area = Pseudo_AG1_options::exact(), average;
  average.normal = TS::Corner_plane_normal::AVERAGE;
  const Mesh<Exact>::Vertex_index top(0);
  const auto reference = Pseudo_AG1_surface<Exact>(octahedron_with_thin_faces<Exact>(1), area)
                             .corner_plane(top)
                             .normal;
  double previous = -1;
  for (int k : {1, 2, 4, 8}) {
    // area-weighted: the same vector whatever the subdivision (exact)
    const Pseudo_AG1_surface<Exact> a(octahedron_with_thin_faces<Exact>(k), area);
    EXPECT_EQ(a.corner_plane(top).normal, reference);
    // plain average: tilts towards the split face as k grows
    const Pseudo_AG1_surface<Double> b(octahedron_with_thin_faces<Double>(k), average);
    const auto n = b.corner_plane(Mesh<Double>::Vertex_index(0)).normal;
    const Double::Vector_3 r(CGAL::to_double(reference.x()), CGAL::to_double(reference.y()),
                             CGAL::to_double(reference.z()));
    const double angle = std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r);
    EXPECT_GT(angle, previous) << k;
    previous = angle;
  }
  EXPECT_GT(previous, 0.1); // radians: about 10 degrees at k = 8
}

TEST(PseudoAG1Steps, CentroidNormalTiltsOnSkewedStars) { // C20
  Pseudo_AG1_options centroid;
  centroid.normal = TS::Corner_plane_normal::CENTROID;
  centroid.offsets = {{0, 0, 0}};
  auto tilt = [&](const std::string& name, std::size_t vertex) {
    const auto mesh = TS::thesis_polyhedron<Double>(name);
    const Pseudo_AG1_surface<Double> c(mesh, centroid), a(mesh);
    const auto n = c.corner_plane(Mesh<Double>::Vertex_index(vertex)).normal;
    const auto r = a.corner_plane(Mesh<Double>::Vertex_index(vertex)).normal;
    return std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r);
  };
  EXPECT_LT(tilt("octahedron", 0), 1e-12); // symmetric star: no tilt
  // the V-arm bipyramid's apex (vertex 8): a skewed star
  EXPECT_GT(tilt("v-arm", 8), 0.1);
}

TEST(PseudoAG1Steps, AutomaticShrinkingReducesTheDips) { // S7, R-19
  Pseudo_AG1_options o;
  o.automatic_shrinking = true;
  const auto mesh = TS::thesis_polyhedron<Double>("tetrahedron");
  const Pseudo_AG1_surface<Double> plain(mesh), shrunk(mesh, o);
  EXPECT_GE(shrunk.shrinking_rounds(), 1u);
  double before = -1e300, after = -1e300;
  for (auto e : plain.mesh().edges()) {
    before = std::max(before, plain.dip(e));
    after = std::max(after, shrunk.dip(e));
  }
  EXPECT_LT(after, before);
  for (auto v : shrunk.mesh().vertices()) {
    EXPECT_LT(shrunk.corner_plane(v).star_scale, 1.0);
    EXPECT_GE(shrunk.corner_plane(v).star_scale, 0.5);
  }
  EXPECT_TRUE(TS::certify_pseudo_AG1(shrunk).pseudo_AG1());
}

} // namespace

namespace {

TEST(ClosedTessellation, WatertightByDefaultSplitOnRequest) { // the pictures of AG1.md §6
  const Pseudo_AG1_surface<Double> s(TS::thesis_polyhedron<Double>("icosahedron"));
  const auto& m = s.mesh();
  const TS::Patch_sampler<Pseudo_AG1_surface<Double>> sampler(s);
  const int levels = 2, n = 1 << levels;
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const TS::Closed_tessellation shared = TS::tessellate_closed_surface(m, sampler, levels);
  EXPECT_EQ(shared.mesh.number_of_vertices(),
            V + E * std::size_t(n - 1) + F * std::size_t((n - 1) * (n - 2) / 2));
  EXPECT_EQ(shared.mesh.number_of_faces(), F * std::size_t(n * n));
  EXPECT_TRUE(CGAL::is_closed(shared.mesh));

  const TS::Closed_tessellation split = TS::tessellate_closed_surface(m, sampler, levels, true);
  EXPECT_EQ(split.mesh.number_of_vertices(), F * std::size_t((n + 1) * (n + 2) / 2));
  EXPECT_EQ(split.mesh.number_of_faces(), F * std::size_t(n * n));
  EXPECT_FALSE(CGAL::is_closed(split.mesh));
  // the copies of one point: the same place (C^0), each with its own face's normal, which
  // agree at the input's vertices (G^1) and not inside its edges (the jumps)
  std::map<std::array<long long, 3>, std::vector<std::size_t>> copies;
  for (auto v : split.mesh.vertices()) {
    const auto& p = split.mesh.point(v);
    copies[{{std::llround(p.x() * 1e9), std::llround(p.y() * 1e9), std::llround(p.z() * 1e9)}}]
        .push_back(std::size_t(v));
  }
  EXPECT_EQ(copies.size(), shared.mesh.number_of_vertices()); // every shared point, once
  double at_vertices = 0, inside_edges = 0;
  for (const auto& [key, list] : copies) {
    double worst = 0;
    for (std::size_t a : list)
      for (std::size_t b : list)
        worst = std::max(worst, TS::internal::closed_angle_deg(split.normals[a], split.normals[b]));
    if (list.size() >= 3) // valence 5 at the icosahedron's vertices
      at_vertices = std::max(at_vertices, worst);
    else if (list.size() == 2)
      inside_edges = std::max(inside_edges, worst);
  }
  EXPECT_LT(at_vertices, 1e-9);
  EXPECT_GT(inside_edges, 1.0); // degrees: the thesis's icosahedron jumps by a few degrees
}

} // namespace

// Tests of the self-contained parts of the pseudo-AG^1 construction over closed meshes
// (SPEC_AG1): the re-centering of a corner point (§4.2 S5, Xu Fig. 6.5, test C22) and the
// test polyhedra (§8).

#include "test_support.h"

#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/internal/recentering.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace ts_test;

namespace {

using Point_2x = Exact_kernel::Point_2;
using Q = Exact_kernel::FT;

Q q(int num, int den = 1) {
  return Q(num) / Q(den);
}

template <class K>
std::vector<typename K::Point_2> polygon(const std::vector<std::array<int, 2>>& xy) {
  std::vector<typename K::Point_2> p;
  for (const auto& c : xy)
    p.emplace_back(c[0], c[1]);
  return p;
}

template <class K>
bool strictly_inside(const std::vector<typename K::Point_2>& P, const typename K::Point_2& x) {
  return CGAL::bounded_side_2(P.begin(), P.end(), x, K()) == CGAL::ON_BOUNDED_SIDE;
}

template <class K>
bool is_convex_ccw(const std::vector<typename K::Point_2>& P) {
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    if (CGAL::orientation(P[(i + n - 1) % n], P[i], P[(i + 1) % n]) == CGAL::RIGHT_TURN)
      return false;
  return n >= 3;
}

const std::vector<std::array<int, 2>> golden_notch{
    {{0, 1}}, {{3, -1}}, {{4, 3}}, {{-3, 4}}, {{-3, -1}}};
const std::vector<std::array<int, 2>> golden_vertex_hits{
    {{0, 1}}, {{3, -1}}, {{3, 3}}, {{-3, 3}}, {{-3, -1}}};
const std::vector<std::array<int, 2>> golden_two_reflex{{{1, 0}}, {{4, -2}}, {{5, 2}},  {{2, 1}},
                                                        {{1, 5}}, {{-3, 1}}, {{-2, -3}}};

} // namespace

// ---------------------------------------------------------------------------------------
// Re-centering (SPEC_AG1 §4.2 S5, C22). The golden polygons are tested with two centres
// that trigger it: a point of the notch at the first reflex vertex (outside P) and the
// first vertex itself (on the boundary, so not strictly inside).

TEST(Recentering, GoldenNotchOneCut) {
  const auto P = polygon<Exact_kernel>(golden_notch);
  for (const Point_2x& z0 : {Point_2x(0, 0), P[0]}) {
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_TRUE(r.simple_ccw);
    EXPECT_TRUE(r.recentred);
    EXPECT_EQ(r.cuts, 1);
    // cut at (0,1): v_1 = (54/17, 53/17) on the edge (3,-1)-(4,3), v_2 = (-3,3) on (-3,4)-(-3,-1)
    const std::vector<Point_2x> expected{Point_2x(0, 1), Point_2x(q(54, 17), q(53, 17)),
                                         Point_2x(-3, 4), Point_2x(-3, 3)};
    EXPECT_EQ(r.polygon, expected);
    EXPECT_EQ(r.center, Point_2x(q(-12, 17), q(189, 68)));
    EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
  }
}

TEST(Recentering, GoldenRaysHittingVertices) {
  const auto P = polygon<Exact_kernel>(golden_vertex_hits);
  for (const Point_2x& z0 : {Point_2x(0, 0), P[0]}) {
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_TRUE(r.simple_ccw && r.recentred);
    EXPECT_EQ(r.cuts, 1);
    // both rays end at vertices, (3,3) and (-3,3), which are not repeated
    EXPECT_EQ(r.polygon, (std::vector<Point_2x>{Point_2x(0, 1), Point_2x(3, 3), Point_2x(-3, 3)}));
    EXPECT_EQ(r.center, Point_2x(0, q(7, 3)));
    EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
  }
}

TEST(Recentering, GoldenTwoReflexVertices) {
  const auto P = polygon<Exact_kernel>(golden_two_reflex);
  for (const Point_2x& z0 : {Point_2x(1, -1), P[0]}) {
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_TRUE(r.simple_ccw && r.recentred);
    // the ray from (1,0) along (3,3) ends exactly at the other reflex vertex (2,1), which
    // the cut makes convex: one cut suffices
    EXPECT_EQ(r.cuts, 1);
    EXPECT_EQ(r.polygon, (std::vector<Point_2x>{Point_2x(1, 0), Point_2x(2, 1), Point_2x(1, 5),
                                                Point_2x(-2, 2)}));
    EXPECT_EQ(r.center, Point_2x(q(1, 2), 2));
    EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
  }
}

TEST(Recentering, TwoSuccessiveCuts) {
  // notches at the bottom and at the top: the first cut (at index 0) leaves the second
  const auto P =
      polygon<Exact_kernel>({{{0, 1}}, {{3, -1}}, {{3, 5}}, {{0, 3}}, {{-3, 5}}, {{-3, -1}}});
  const auto r = TS::internal::recenter<Exact_kernel>(P, Point_2x(0, 0));
  EXPECT_TRUE(r.simple_ccw && r.recentred);
  EXPECT_EQ(r.cuts, 2);
  // the second cut starts the polygon at its reflex vertex (0,3)
  EXPECT_EQ(r.polygon, (std::vector<Point_2x>{Point_2x(0, 3), Point_2x(q(-3, 2), 2), Point_2x(0, 1),
                                              Point_2x(q(3, 2), 2)}));
  EXPECT_EQ(r.center, Point_2x(0, 2));
  EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
}

TEST(Recentering, VertexHitKeepsStraightVertices) {
  // the ray from (1,1) ends at the reflex vertex (0,1), which the cut straightens: one cut,
  // and the vertices with straight angles stay in the centroid
  const auto P = polygon<Exact_kernel>(
      {{{0, 0}}, {{4, 0}}, {{4, 1}}, {{1, 1}}, {{1, 4}}, {{0, 4}}, {{0, 1}}, {{-3, 1}}, {{-3, 0}}});
  const auto r = TS::internal::recenter<Exact_kernel>(P, Point_2x(5, 5));
  EXPECT_TRUE(r.simple_ccw && r.recentred);
  EXPECT_EQ(r.cuts, 1);
  EXPECT_EQ(r.polygon, (std::vector<Point_2x>{Point_2x(1, 1), Point_2x(0, 1), Point_2x(-3, 1),
                                              Point_2x(-3, 0), Point_2x(0, 0), Point_2x(1, 0)}));
  EXPECT_EQ(r.center, Point_2x(q(-2, 3), q(1, 2)));
  EXPECT_TRUE(is_convex_ccw<Exact_kernel>(r.polygon));
  EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
}

TEST(Recentering, CentreStrictlyInsideIsKept) {
  const auto P = polygon<Exact_kernel>({{{0, 0}}, {{4, 0}}, {{4, 3}}, {{0, 3}}});
  const Point_2x z0(q(1, 3), q(5, 2));
  const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
  EXPECT_TRUE(r.simple_ccw);
  EXPECT_FALSE(r.recentred);
  EXPECT_EQ(r.cuts, 0);
  EXPECT_EQ(r.center, z0);
  EXPECT_EQ(r.polygon, P);
  // non-convex, but z0 strictly inside: untouched as well
  const auto notch = polygon<Exact_kernel>(golden_notch);
  const auto s = TS::internal::recenter<Exact_kernel>(notch, Point_2x(3, 1));
  EXPECT_TRUE(s.simple_ccw && !s.recentred);
  EXPECT_EQ(s.center, Point_2x(3, 1));
}

TEST(Recentering, CentreOnTheBoundaryIsMoved) {
  const auto P = polygon<Exact_kernel>({{{0, 0}}, {{4, 0}}, {{4, 3}}, {{0, 3}}});
  for (const Point_2x& z0 : {Point_2x(2, 0), Point_2x(4, 3)}) {
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_TRUE(r.simple_ccw && r.recentred);
    EXPECT_EQ(r.cuts, 0); // already convex: its vertex centroid
    EXPECT_EQ(r.center, Point_2x(2, q(3, 2)));
  }
}

TEST(Recentering, InvalidPolygonsAreLeftAlone) {
  const Point_2x z0(7, 7);
  const std::vector<std::vector<std::array<int, 2>>> invalid{
      {{{0, 0}}, {{0, 3}}, {{4, 3}}, {{4, 0}}},           // clockwise
      {{{0, 0}}, {{4, 0}}, {{0, 3}}, {{4, 3}}},           // bow tie
      {{{0, 0}}, {{4, 0}}, {{4, 0}}, {{4, 3}}, {{0, 3}}}, // repeated vertex
      {{{0, 0}}, {{4, 0}}, {{2, 0}}, {{2, 3}}},           // spike folding back onto an edge
      {{{0, 0}}, {{4, 0}}, {{8, 0}}},                     // collinear
      {{{0, 0}}, {{4, 0}}},                               // too few vertices
      {{{0, 0}}, {{4, 0}}, {{4, 4}}, {{2, 0}}, {{0, 4}}}, // a vertex touching an edge
  };
  for (const auto& xy : invalid) {
    const auto P = polygon<Exact_kernel>(xy);
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_FALSE(r.simple_ccw) << "polygon with " << xy.size() << " vertices, first edge to ("
                               << xy[1][0] << ", " << xy[1][1] << ")";
    EXPECT_FALSE(r.recentred);
    EXPECT_EQ(r.center, z0);
  }
}

TEST(Recentering, RandomStarShapedPolygonsInDouble) {
  std::mt19937 engine(20260611);
  std::uniform_real_distribution<double> unit(0, 1);
  int recentred = 0, cut = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 4 + trial % 12;
    std::vector<double> angles;
    // jittered angles: consecutive gaps below pi keep the radial polygon simple
    for (int i = 0; i < n; ++i)
      angles.push_back(2 * CGAL_PI * (i + 0.9 * unit(engine)) / n);
    std::vector<Epick::Point_2> P;
    for (double a : angles) {
      const double radius = 0.15 + unit(engine);
      P.emplace_back(radius * std::cos(a), radius * std::sin(a));
    }
    // the first vertex (on the boundary) and a far point must both trigger re-centering
    for (const Epick::Point_2& z0 : {P[0], Epick::Point_2(3, 3)}) {
      const auto r = TS::internal::recenter<Epick>(P, z0);
      ASSERT_TRUE(r.simple_ccw) << "trial " << trial;
      ASSERT_TRUE(r.recentred) << "trial " << trial;
      ASSERT_LE(r.cuts, n) << "trial " << trial; // no hang: a cut removes a reflex vertex
      ASSERT_TRUE(is_convex_ccw<Epick>(r.polygon)) << "trial " << trial;
      ASSERT_TRUE(strictly_inside<Epick>(P, r.center)) << "trial " << trial;
      ++recentred;
      cut += r.cuts > 0;
    }
  }
  EXPECT_EQ(recentred, 400);
  EXPECT_GT(cut, 100); // most of them are not convex
}

TEST(Recentering, GoldenInSimpleCartesianDouble) {
  using K = CGAL::Simple_cartesian<double>;
  const auto r = TS::internal::recenter<K>(polygon<K>(golden_notch), K::Point_2(0, 0));
  EXPECT_EQ(r.cuts, 1);
  EXPECT_NEAR(r.center.x(), -12.0 / 17, 1e-14);
  EXPECT_NEAR(r.center.y(), 189.0 / 68, 1e-14);
}

// ---------------------------------------------------------------------------------------
// Test polyhedra (SPEC_AG1 §8)

namespace {

using Exact_mesh = CGAL::Surface_mesh<Exact_kernel::Point_3>;

struct Expected_counts {
  std::size_t V, E, F;
  int chi;
};

const std::map<std::string, Expected_counts> expected_counts{
    {"tetrahedron", {4, 6, 4, 2}},     {"sato", {4, 6, 4, 2}},
    {"octahedron", {6, 12, 8, 2}},     {"cube", {8, 18, 12, 2}},
    {"cube-centres", {14, 36, 24, 2}}, {"icosahedron", {12, 30, 20, 2}},
    {"pentakis", {42, 120, 80, 2}},    {"torus", {72, 216, 144, 0}},
    {"torus9", {9, 27, 18, 0}},        {"star", {14, 36, 24, 2}},
    {"v-arm", {10, 24, 16, 2}}};

template <class K>
typename K::FT signed_volume_times_6(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  typename K::FT v(0);
  for (auto f : mesh.faces()) {
    std::vector<typename K::Vector_3> p;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
      p.push_back(mesh.point(x) - CGAL::ORIGIN);
    v += p[0] * CGAL::cross_product(p[1], p[2]);
  }
  return v;
}

} // namespace

TEST(Thesis_polyhedra, EveryShapeIsAClosedOutwardTriangleMesh) {
  ASSERT_EQ(TS::thesis_polyhedron_names().size(), expected_counts.size());
  for (const std::string& name : TS::thesis_polyhedron_names()) {
    SCOPED_TRACE(name);
    ASSERT_EQ(expected_counts.count(name), 1u);
    const Expected_counts& c = expected_counts.at(name);
    const Exact_mesh mesh = TS::thesis_polyhedron<Exact_kernel>(name);
    EXPECT_TRUE(mesh.is_valid(false));
    EXPECT_TRUE(CGAL::is_closed(mesh));
    EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
    EXPECT_EQ(mesh.number_of_vertices(), c.V);
    EXPECT_EQ(mesh.number_of_edges(), c.E);
    EXPECT_EQ(mesh.number_of_faces(), c.F);
    EXPECT_EQ(int(c.V) - int(c.E) + int(c.F), c.chi);
    EXPECT_EQ(int(mesh.number_of_vertices()) - int(mesh.number_of_edges()) +
                  int(mesh.number_of_faces()),
              c.chi);
    // exact even for the converted double coordinates: they are converted exactly
    EXPECT_GT(signed_volume_times_6<Exact_kernel>(mesh), Q(0));
    for (auto f : mesh.faces()) {
      std::vector<Exact_kernel::Point_3> p;
      for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
        p.push_back(mesh.point(x));
      EXPECT_FALSE(CGAL::collinear(p[0], p[1], p[2])) << "face " << f.idx();
    }
    // manifold at every vertex: one cycle of faces (Surface_mesh could hold two)
    for (auto v : mesh.vertices()) {
      std::size_t around = 0;
      for (auto h : halfedges_around_target(halfedge(v, mesh), mesh)) {
        (void)h;
        ++around;
      }
      EXPECT_EQ(around, degree(v, mesh)) << "vertex " << v.idx();
      EXPECT_GE(around, 3u);
    }
  }
}

TEST(Thesis_polyhedra, EmbeddedWithoutSelfIntersections) {
  for (const std::string& name : TS::thesis_polyhedron_names()) {
    const auto mesh = TS::thesis_polyhedron<Epick>(name);
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(mesh)) << name;
  }
}

TEST(Thesis_polyhedra, TetrahedronFacesInTheSpecOrder) {
  const Exact_mesh mesh = TS::thesis_polyhedron<Exact_kernel>("tetrahedron");
  const std::vector<Exact_kernel::Point_3> abcd{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (auto v : mesh.vertices()) {
    EXPECT_EQ(mesh.point(v), abcd[v.idx()]);
  }
  // abc, adb, bdc, cda, each starting at its listed first vertex
  const std::vector<std::vector<std::size_t>> faces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  for (auto f : mesh.faces()) {
    std::vector<std::size_t> around;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
      around.push_back(x.idx());
    EXPECT_EQ(around, faces[f.idx()]) << "face " << f.idx();
  }
}

TEST(Thesis_polyhedra, ExactCoordinatesAndValences) {
  const Exact_mesh varm = TS::thesis_polyhedron<Exact_kernel>("v-arm");
  EXPECT_EQ(varm.point(Exact_mesh::Vertex_index(2)), Exact_kernel::Point_3(q(1, 2), q(1, 2), 0));
  EXPECT_EQ(varm.point(Exact_mesh::Vertex_index(5)), Exact_kernel::Point_3(q(-1, 10), q(1, 10), 0));
  EXPECT_EQ(varm.point(Exact_mesh::Vertex_index(8)), Exact_kernel::Point_3(0, 0, 1));
  const Exact_mesh star = TS::thesis_polyhedron<Exact_kernel>("star");
  EXPECT_EQ(star.point(Exact_mesh::Vertex_index(12)), Exact_kernel::Point_3(0, 0, q(3, 5)));
  EXPECT_EQ(star.point(Exact_mesh::Vertex_index(3)), Exact_kernel::Point_3(0, q(2, 5), 0));
  // the triangulated cube: valence 6 at vertices 0 and 7, 4 elsewhere; vertex numbering
  const Exact_mesh cube = TS::thesis_polyhedron<Exact_kernel>("cube");
  for (auto v : cube.vertices()) {
    EXPECT_EQ(degree(v, cube), (v.idx() == 0 || v.idx() == 7) ? 6u : 4u) << v.idx();
    const int i = int(v.idx());
    EXPECT_EQ(cube.point(v), Exact_kernel::Point_3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1));
  }
  // the six diagonals, each through the smallest vertex number of its square
  for (const auto& d : std::vector<std::array<std::size_t, 2>>{
           {{0, 3}}, {{4, 7}}, {{0, 5}}, {{2, 7}}, {{0, 6}}, {{1, 7}}})
    EXPECT_TRUE(
        CGAL::halfedge(Exact_mesh::Vertex_index(d[0]), Exact_mesh::Vertex_index(d[1]), cube).second)
        << d[0] << "-" << d[1];
  // with face centres: the centres have valence 4 and lie in their faces
  const Exact_mesh centres = TS::thesis_polyhedron<Exact_kernel>("cube-centres");
  for (std::size_t i = 8; i < 14; ++i)
    EXPECT_EQ(degree(Exact_mesh::Vertex_index(i), centres), 4u);
  // the 9-vertex torus: every vertex of valence 6
  const Exact_mesh torus9 = TS::thesis_polyhedron<Exact_kernel>("torus9");
  for (auto v : torus9.vertices())
    EXPECT_EQ(degree(v, torus9), 6u);
}

TEST(Thesis_polyhedra, UnknownNameIsRejectedWithTheList) {
  try {
    TS::thesis_polyhedron<Epick>("dodecahedron");
    FAIL() << "no exception";
  } catch (const TS::Invalid_input& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("dodecahedron"), std::string::npos);
    for (const std::string& name : TS::thesis_polyhedron_names())
      EXPECT_NE(what.find(name), std::string::npos) << name;
  }
}

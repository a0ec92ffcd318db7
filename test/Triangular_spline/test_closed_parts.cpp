// Tests of the self-contained parts of the pseudo-AG^1 construction over closed
// meshes (SPEC_AG1): the re-centering of a corner point (§4.2 S5, Xu Fig. 6.5,
// test C22), the test polyhedra (§8), and the curved PN triangles used as a
// comparator.

#include "test_support.h"

#include <CGAL/Triangular_spline/Comparators/PN_triangles.h>
#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/internal/recentering.h>

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
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
// Re-centering (SPEC_AG1 §4.2 S5, C22). The golden polygons are tested with two
// centres that trigger it: a point of the notch at the first reflex vertex
// (outside P) and the first vertex itself (on the boundary, so not strictly
// inside).

TEST(Recentering, GoldenNotchOneCut) {
  const auto P = polygon<Exact_kernel>(golden_notch);
  for (const Point_2x& z0 : {Point_2x(0, 0), P[0]}) {
    const auto r = TS::internal::recenter<Exact_kernel>(P, z0);
    EXPECT_TRUE(r.simple_ccw);
    EXPECT_TRUE(r.recentred);
    EXPECT_EQ(r.cuts, 1);
    // cut at (0,1): v_1 = (54/17, 53/17) on the edge (3,-1)-(4,3), v_2 = (-3,3)
    // on (-3,4)-(-3,-1)
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
    // the ray from (1,0) along (3,3) ends exactly at the other reflex vertex
    // (2,1), which the cut makes convex: one cut suffices
    EXPECT_EQ(r.cuts, 1);
    EXPECT_EQ(r.polygon, (std::vector<Point_2x>{Point_2x(1, 0), Point_2x(2, 1), Point_2x(1, 5),
                                                Point_2x(-2, 2)}));
    EXPECT_EQ(r.center, Point_2x(q(1, 2), 2));
    EXPECT_TRUE(strictly_inside<Exact_kernel>(P, r.center));
  }
}

TEST(Recentering, TwoSuccessiveCuts) {
  // notches at the bottom and at the top: the first cut (at index 0) leaves the
  // second
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
  // the ray from (1,1) ends at the reflex vertex (0,1), which the cut
  // straightens: one cut, and the vertices with straight angles stay in the
  // centroid
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
    // the first vertex (on the boundary) and a far point must both trigger
    // re-centering
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
    // exact even for the converted double coordinates: they are converted
    // exactly
    EXPECT_GT(signed_volume_times_6<Exact_kernel>(mesh), Q(0));
    for (auto f : mesh.faces()) {
      std::vector<Exact_kernel::Point_3> p;
      for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
        p.push_back(mesh.point(x));
      EXPECT_FALSE(CGAL::collinear(p[0], p[1], p[2])) << "face " << f.idx();
    }
    // manifold at every vertex: one cycle of faces (Surface_mesh could hold
    // two)
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
  // the triangulated cube: valence 6 at vertices 0 and 7, 4 elsewhere; vertex
  // numbering
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

// ---------------------------------------------------------------------------------------
// PN triangles (Vlachos, Peters, Boyd, Mitchell 2001)

namespace {

template <class K>
using Patch = TS::Bezier_triangle<K, typename K::Vector_3>;

// The position of vertex `v` in face `f`'s vertex order.
template <class Mesh>
int position_in_face(const Mesh& mesh, typename Mesh::Face_index f, typename Mesh::Vertex_index v) {
  int i = 0;
  for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
    if (x == v)
      return i;
    ++i;
  }
  return -1;
}

// The control point of patch `f` with multiplicity `ma` at vertex a and 3 - ma
// at b.
template <class K, class Mesh>
typename K::Vector_3 edge_control_point(const Mesh& mesh, const std::vector<Patch<K>>& patches,
                                        typename Mesh::Face_index f, typename Mesh::Vertex_index a,
                                        typename Mesh::Vertex_index b, int ma) {
  TS::Multi_index index{0, 0, 0};
  index[position_in_face(mesh, f, a)] = ma;
  index[position_in_face(mesh, f, b)] = 3 - ma;
  return patches[f.idx()].control_point(index);
}

// Every edge: the four boundary control points of both faces are identical
// (operator==: exact for rationals, bitwise for double).
template <class K, class Mesh>
::testing::AssertionResult boundaries_identical(const Mesh& mesh,
                                                const std::vector<Patch<K>>& patches) {
  for (auto e : mesh.edges()) {
    const auto h = halfedge(e, mesh);
    const auto a = source(h, mesh), b = target(h, mesh);
    const auto f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    for (int ma = 0; ma <= 3; ++ma)
      if (!(edge_control_point<K>(mesh, patches, f, a, b, ma) ==
            edge_control_point<K>(mesh, patches, g, a, b, ma)))
        return ::testing::AssertionFailure()
               << "edge " << e.idx() << ": control point " << ma << " differs";
  }
  return ::testing::AssertionSuccess();
}

std::array<double, 3> to_array(const Epick::Vector_3& v) {
  return {{v.x(), v.y(), v.z()}};
}

double angle_deg(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  const std::array<double, 3> c{
      {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  const double s = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  return std::atan2(s, u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) * 180 / CGAL_PI;
}

// Area-weighted vertex normals, computed independently of the header.
template <class Mesh>
std::vector<std::array<double, 3>> area_weighted_normals(const Mesh& mesh) {
  std::vector<std::array<double, 3>> n(mesh.number_of_vertices(), {{0, 0, 0}});
  for (auto f : mesh.faces()) {
    std::vector<Epick::Point_3> p;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
      p.push_back(mesh.point(x));
    const auto c = to_array(CGAL::cross_product(p[1] - p[0], p[2] - p[0]));
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
      for (std::size_t k = 0; k < 3; ++k)
        n[x.idx()][k] += c[k];
  }
  return n;
}

// A rational, not unit, normal per vertex: the direction from the vertex
// centroid.
Exact_mesh::Property_map<Exact_mesh::Vertex_index, Exact_kernel::Vector_3>
radial_normals(Exact_mesh& mesh) {
  Exact_kernel::Vector_3 centroid(0, 0, 0);
  for (auto v : mesh.vertices())
    centroid = centroid + (mesh.point(v) - CGAL::ORIGIN);
  centroid = centroid / Q(int(mesh.number_of_vertices()));
  auto normals =
      mesh.add_property_map<Exact_mesh::Vertex_index, Exact_kernel::Vector_3>("v:pn_normal").first;
  for (auto v : mesh.vertices())
    normals[v] = (mesh.point(v) - CGAL::ORIGIN) - centroid;
  return normals;
}

} // namespace

TEST(PN_triangles, OneCubicPatchPerFaceInTheFaceOrder) {
  const auto mesh = TS::thesis_polyhedron<Epick>("cube");
  const auto patches = TS::pn_triangles<Epick>(mesh);
  ASSERT_EQ(patches.size(), mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    const Patch<Epick>& p = patches[f.idx()];
    EXPECT_EQ(p.degree(), 3);
    EXPECT_EQ(p.vertex(0), Epick::Point_2(0, 0));
    EXPECT_EQ(p.vertex(1), Epick::Point_2(1, 0));
    EXPECT_EQ(p.vertex(2), Epick::Point_2(0, 1));
    int i = 0;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
      TS::Multi_index corner{0, 0, 0};
      corner[i++] = 3;
      EXPECT_EQ(p.control_point(corner), mesh.point(x) - CGAL::ORIGIN);
    }
  }
}

TEST(PN_triangles, ContinuousExactlyWithRationalNormals) {
  for (const std::string name : {"tetrahedron", "sato", "cube", "v-arm", "star"}) {
    Exact_mesh mesh = TS::thesis_polyhedron<Exact_kernel>(name);
    const auto normals = radial_normals(mesh);
    const auto patches = TS::pn_triangles<Exact_kernel>(mesh, normals);
    EXPECT_TRUE(boundaries_identical<Exact_kernel>(mesh, patches)) << name;
  }
}

TEST(PN_triangles, ContinuousBitwiseWithDefaultNormals) {
  for (const std::string name : {"sato", "icosahedron", "pentakis", "torus", "star", "v-arm"}) {
    const auto mesh = TS::thesis_polyhedron<Epick>(name);
    const auto patches = TS::pn_triangles<Epick>(mesh);
    EXPECT_TRUE(boundaries_identical<Epick>(mesh, patches)) << name;
  }
}

TEST(PN_triangles, RegularTetrahedronGoldenNet) {
  // face abc with the normals N_v = v (computed by hand with rationals):
  // b_210 = (2a + b - ((b - a).a / a.a) a)/3, b_111 = E + (E - V)/2 with E = (13/27)(1,1,-1)
  Exact_mesh mesh = TS::thesis_polyhedron<Exact_kernel>("tetrahedron");
  auto normals =
      mesh.add_property_map<Exact_mesh::Vertex_index, Exact_kernel::Vector_3>("v:n").first;
  for (auto v : mesh.vertices())
    normals[v] = mesh.point(v) - CGAL::ORIGIN;
  const auto patches = TS::pn_triangles<Exact_kernel>(mesh, normals);
  using V3 = Exact_kernel::Vector_3;
  const Patch<Exact_kernel>& abc = patches[0];
  EXPECT_EQ(abc.control_point(3, 0, 0), V3(1, 1, 1));
  EXPECT_EQ(abc.control_point(2, 1, 0), V3(q(13, 9), q(7, 9), q(7, 9)));
  EXPECT_EQ(abc.control_point(1, 1, 1), V3(q(5, 9), q(5, 9), q(-5, 9)));
}

TEST(PN_triangles, NormalLengthDoesNotMatter) {
  Exact_mesh mesh = TS::thesis_polyhedron<Exact_kernel>("sato");
  const auto normals = radial_normals(mesh);
  auto scaled =
      mesh.add_property_map<Exact_mesh::Vertex_index, Exact_kernel::Vector_3>("v:scaled").first;
  for (auto v : mesh.vertices())
    scaled[v] = Q(int(v.idx()) + 2) / Q(3) * normals[v];
  const auto a = TS::pn_triangles<Exact_kernel>(mesh, normals);
  const auto b = TS::pn_triangles<Exact_kernel>(mesh, scaled);
  for (std::size_t f = 0; f < a.size(); ++f)
    EXPECT_EQ(a[f].control_points(), b[f].control_points()) << "face " << f;
}

TEST(PN_triangles, CornerNormalsAreTheVertexNormals) {
  // The corner tangents are the edges projected along N_v onto the plane normal
  // to N_v, so their cross product is (N_F . N_v) N_v up to a positive factor:
  // parallel to N_v, and reversed where the face turns away from N_v (skewed
  // input such as Sato's tetrahedron).
  const std::array<Epick::Point_2, 3> corners{
      {Epick::Point_2(0, 0), Epick::Point_2(1, 0), Epick::Point_2(0, 1)}};
  for (const std::string name : {"sato", "cube", "icosahedron", "torus", "star", "v-arm"}) {
    SCOPED_TRACE(name);
    const auto mesh = TS::thesis_polyhedron<Epick>(name);
    const std::vector<std::array<double, 3>> n = area_weighted_normals(mesh);
    const auto patches = TS::pn_triangles<Epick>(mesh);
    double worst = 0;
    int reversed = 0;
    for (auto f : mesh.faces()) {
      std::vector<Epick::Point_3> p;
      for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
        p.push_back(mesh.point(x));
      const auto face_normal = to_array(CGAL::cross_product(p[1] - p[0], p[2] - p[0]));
      int i = 0;
      for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
        const Patch<Epick>& patch = patches[f.idx()];
        const auto du = patch.partial_derivative(corners[i], 1, 0);
        const auto dv = patch.partial_derivative(corners[i], 0, 1);
        std::array<double, 3> expected = n[x.idx()];
        if (angle_deg(face_normal, expected) > 90) {
          ++reversed;
          for (double& c : expected)
            c = -c;
        }
        worst = (std::max)(worst, angle_deg(to_array(CGAL::cross_product(du, dv)), expected));
        ++i;
      }
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(reversed > 0,
              name == "sato"); // the only mesh with a face turned away
  }
}

TEST(PN_triangles, FlatInputReproducesTheTriangles) {
  // a closed fan of triangles in the plane x + 2y + 2z = 3, normal (1, 2, 2)
  // (not unit)
  using P3 = Exact_kernel::Point_3;
  Exact_mesh mesh;
  auto on_plane = [](const Q& x, const Q& y) { return P3(x, y, (Q(3) - x - Q(2) * y) / Q(2)); };
  const auto centre = mesh.add_vertex(on_plane(q(1, 3), q(1, 7)));
  std::vector<Exact_mesh::Vertex_index> ring;
  for (const auto& xy :
       std::vector<std::array<int, 2>>{{{5, 0}}, {{3, 4}}, {{-2, 3}}, {{-4, -1}}, {{1, -5}}})
    ring.push_back(mesh.add_vertex(on_plane(Q(xy[0]), Q(xy[1]))));
  for (std::size_t k = 0; k < ring.size(); ++k)
    mesh.add_face(centre, ring[k], ring[(k + 1) % ring.size()]);
  auto normals =
      mesh.add_property_map<Exact_mesh::Vertex_index, Exact_kernel::Vector_3>("v:n").first;
  for (auto v : mesh.vertices())
    normals[v] = Exact_kernel::Vector_3(1, 2, 2);
  const auto patches = TS::pn_triangles<Exact_kernel>(mesh, normals);
  ASSERT_EQ(patches.size(), 5u);
  for (auto f : mesh.faces()) {
    std::vector<Exact_kernel::Vector_3> P;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh))
      P.push_back(mesh.point(x) - CGAL::ORIGIN);
    for (const TS::Multi_index& m : TS::multi_indices(3))
      EXPECT_EQ(patches[f.idx()].control_point(m),
                (Q(m.i) * P[0] + Q(m.j) * P[1] + Q(m.k) * P[2]) / Q(3))
          << "face " << f.idx() << ", (" << m.i << m.j << m.k << ")";
    // hence the patch is the affine map of the triangle
    const Exact_kernel::Point_2 x(q(2, 7), q(3, 11));
    EXPECT_EQ(patches[f.idx()].evaluate(x),
              (Q(1) - x.x() - x.y()) * P[0] + x.x() * P[1] + x.y() * P[2]);
  }
}

TEST(PN_triangles, IcosahedronStaysNearTheSphere) {
  const auto mesh = TS::thesis_polyhedron<Epick>("icosahedron");
  const auto patches = TS::pn_triangles<Epick>(mesh);
  const int N = 12;
  double worst = 0;
  for (const auto& p : patches)
    for (int i = 0; i <= N; ++i)
      for (int j = 0; i + j <= N; ++j) {
        const auto x = p.evaluate(Epick::Point_2(double(i) / N, double(j) / N));
        worst = (std::max)(worst, std::fabs(std::sqrt(x.squared_length()) - 1));
      }
  EXPECT_LT(worst, 0.1);
  EXPECT_GT(worst, 0); // a curved surface, not the sphere itself
}

TEST(PN_triangles, InvalidInputIsRejected) {
  // a quadrilateral face
  CGAL::Surface_mesh<Epick::Point_3> quad;
  const auto a = quad.add_vertex({0, 0, 0}), b = quad.add_vertex({1, 0, 0}),
             c = quad.add_vertex({1, 1, 0}), d = quad.add_vertex({0, 1, 0});
  quad.add_face(a, b, c, d);
  EXPECT_THROW(TS::pn_triangles<Epick>(quad), TS::Invalid_input);
  // a zero normal given
  auto mesh = TS::thesis_polyhedron<Epick>("tetrahedron");
  auto zero =
      mesh.add_property_map<CGAL::Surface_mesh<Epick::Point_3>::Vertex_index, Epick::Vector_3>(
              "v:zero", CGAL::NULL_VECTOR)
          .first;
  EXPECT_THROW(TS::pn_triangles<Epick>(mesh, zero), TS::Invalid_input);
}

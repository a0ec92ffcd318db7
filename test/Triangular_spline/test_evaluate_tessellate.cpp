// Tests of the output layer: point location in a planar domain, evaluation at query points,
// tessellation into a Surface_mesh with normals and curvatures, and mesh files.
// The patches are one random quintic polynomial expressed over every face (with the
// vertices listed in varying orders), so every expected value is known exactly.

#include "test_support.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Triangular_spline/Patch_network.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>
#include <CGAL/Triangular_spline/tessellate.h>
#include <CGAL/Triangular_spline/Domain/domain_from_triangulation_2.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/release.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>

using namespace ts_test;
using TS::Bezier_triangle;
using TS::Domain_locator;
using TS::Planar_domain;
using TS::Polynomial_surface;

namespace {

using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Mesh_vertex = Mesh::Vertex_index;
using Index = std::uint32_t;

// ---------------------------------------------------------------------------------------
// Domains
// ---------------------------------------------------------------------------------------

// cells x cells squares of side 1/2 from (-1, -1), each split by one diagonal whose
// direction alternates like a chessboard. Dyadic coordinates: exact in both kernels.
template <class K>
Planar_domain<K> grid_domain(int cells) {
  using FT = typename K::FT;
  std::vector<typename K::Point_2> points;
  auto id = [cells](int i, int j) { return static_cast<Index>(j * (cells + 1) + i); };
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i)
      points.emplace_back(FT(i) / FT(2) - FT(1), FT(j) / FT(2) - FT(1));
  std::vector<std::array<Index, 3>> triangles;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        triangles.push_back({{a, b, c}});
        triangles.push_back({{a, c, d}});
      } else {
        triangles.push_back({{a, b, d}});
        triangles.push_back({{b, c, d}});
      }
    }
  return Planar_domain<K>(std::move(points), std::move(triangles));
}

// The square [0,3]^2 cut into 3x3 unit cells with the centre cell removed: a ring of 16
// triangles around the square hole [1,2]^2 (two boundary loops).
template <class K>
Planar_domain<K> ring_domain() {
  std::vector<typename K::Point_2> points;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i)
      points.emplace_back(i, j);
  auto id = [](int i, int j) { return static_cast<Index>(j * 4 + i); };
  std::vector<std::array<Index, 3>> triangles;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1)
        continue;
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      // clockwise on purpose for some cells: the domain reorients them
      if ((i + j) % 2 == 0) {
        triangles.push_back({{a, c, b}});
        triangles.push_back({{a, c, d}});
      } else {
        triangles.push_back({{a, b, d}});
        triangles.push_back({{d, c, b}});
      }
    }
  return Planar_domain<K>(std::move(points), std::move(triangles));
}

template <class K>
using Delaunay = CGAL::Delaunay_triangulation_2<K>;

// Delaunay triangulation of random rational points (small denominators).
template <class K>
Planar_domain<K> delaunay_domain(Delaunay<K>& dt, unsigned seed, int count) {
  Random_rationals random(seed);
  for (int i = 0; i < count; ++i)
    dt.insert(random.point<K>());
  std::vector<typename Delaunay<K>::Vertex_handle> handles;
  return TS::domain_from_triangulation_2<K>(
      dt, [](typename Delaunay<K>::Face_handle) { return true; }, handles);
}

// ---------------------------------------------------------------------------------------
// Patches: one polynomial over every face, listing the face's vertices in the six possible
// orders in turn; every seventh face gets a patch over a larger triangle (the face scaled
// by 2 about a vertex), which exercises the path where the patch's vertices do not match.
// ---------------------------------------------------------------------------------------

template <class K, class Value>
std::vector<Bezier_triangle<K, Value>> patches_of(const Planar_domain<K>& domain,
                                                  const Polynomial_surface<K, Value>& polynomial,
                                                  bool with_foreign_triangles = true) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                   {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::vector<Bezier_triangle<K, Value>> patches;
  for (std::size_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(static_cast<Index>(f));
    const int* o = orders[f % 6];
    const auto& r = domain.point(t[o[0]]);
    const auto& s = domain.point(t[o[1]]);
    const auto& u = domain.point(t[o[2]]);
    if (with_foreign_triangles && f % 7 == 3)
      patches.push_back(polynomial.to_bezier(5, r, r + (s - r) * typename K::FT(2),
                                             r + (u - r) * typename K::FT(2)));
    else
      patches.push_back(polynomial.to_bezier(5, r, s, u));
  }
  return patches;
}

// The patches over `domain` as a TriangularSplineNetwork (a copy of both).
template <class K, class Patch>
TS::Patch_network<K, typename Patch::Value_type> network(const Planar_domain<K>& domain,
                                                         const std::vector<Patch>& patches) {
  return TS::Patch_network<K, typename Patch::Value_type>(domain, patches);
}

// A model of TriangularSplineNetwork whose patch(f) returns by value (as C1_quintic_spline).
template <class Network>
struct By_value_network {
  using Geom_traits = typename Network::Geom_traits;
  using Index = typename Network::Index;
  const Network& network;
  const auto& domain() const { return network.domain(); }
  auto patch(Index f) const { return network.patch(f); }
  int degree() const { return network.degree(); }
};

template <class K>
std::vector<std::pair<std::string, Planar_domain<K>>> test_domains(Delaunay<K>& dt) {
  std::vector<std::pair<std::string, Planar_domain<K>>> domains;
  domains.emplace_back("grid", grid_domain<K>(4));
  domains.emplace_back("ring", ring_domain<K>());
  domains.emplace_back("delaunay", delaunay_domain<K>(dt, 11, 60));
  return domains;
}

// Random point of face f: rational barycentric weights (a, b, c) / (a + b + c).
template <class K>
typename K::Point_2 random_point_in(const Planar_domain<K>& domain, Index f,
                                    Random_rationals& random) {
  using FT = typename K::FT;
  const int a = random.integer(0, 9), b = random.integer(0, 9), c = random.integer(1, 9);
  const FT sum(a + b + c);
  const auto& t = domain.face(f);
  const auto& p = domain.point(t[0]);
  const auto& q = domain.point(t[1]);
  const auto& r = domain.point(t[2]);
  const FT x = (FT(a) * p.x() + FT(b) * q.x() + FT(c) * r.x()) / sum;
  const FT y = (FT(a) * p.y() + FT(b) * q.y() + FT(c) * r.y()) / sum;
  return typename K::Point_2(x, y);
}

template <class K>
bool in_closed_face(const Planar_domain<K>& domain, Index f, const typename K::Point_2& p) {
  const auto& t = domain.face(f);
  for (int i = 0; i < 3; ++i)
    if (CGAL::orientation(domain.point(t[i]), domain.point(t[(i + 1) % 3]), p) == CGAL::RIGHT_TURN)
      return false;
  return true;
}

template <class K>
class Output : public ::testing::Test {};
TYPED_TEST_SUITE(Output, Kernels, Kernel_names);

} // namespace

// ---------------------------------------------------------------------------------------
// Domain_locator
// ---------------------------------------------------------------------------------------

TYPED_TEST(Output, LocatorFindsRandomInteriorPoints) {
  using K = TypeParam;
  using FT = typename K::FT;
  constexpr bool exact = is_exact<K>;
  Delaunay<K> dt;
  Random_rationals random(3);
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    SCOPED_TRACE(name);
    const Domain_locator<K> locator(domain);
    EXPECT_GE(locator.number_of_buckets(), 1u);
    for (Index f = 0; f < domain.number_of_faces(); ++f)
      for (int trial = 0; trial < 5; ++trial) {
        const typename K::Point_2 p = random_point_in(domain, f, random);
        // (in double the rounded point may leave f, and the domain if f is on the boundary)
        if (!in_closed_face(domain, f, p))
          continue;
        const auto location = locator.locate(p);
        ASSERT_TRUE(location.has_value());
        const Index g = location->face;
        EXPECT_TRUE(in_closed_face(domain, g, p));
        const auto& w = location->barycentric;
        const auto& t = domain.face(g);
        for (const FT& c : w) {
          EXPECT_GE(c, FT(0));
          EXPECT_LE(c, FT(1));
        }
        const FT sum = w[0] + w[1] + w[2];
        const FT x = w[0] * domain.point(t[0]).x() + w[1] * domain.point(t[1]).x() +
                     w[2] * domain.point(t[2]).x();
        const FT y = w[0] * domain.point(t[0]).y() + w[1] * domain.point(t[1]).y() +
                     w[2] * domain.point(t[2]).y();
        if constexpr (exact) {
          EXPECT_EQ(sum, FT(1));
          EXPECT_EQ(typename K::Point_2(x, y), p);
        } else {
          // weights from 2x2 determinants of coordinates up to 20: a few dozen ulps
          const double scale = (std::max)({1.0, std::abs(p.x()), std::abs(p.y())});
          EXPECT_NEAR(sum, 1.0, 1e-15);
          EXPECT_NEAR(x, p.x(), 1e-13 * scale);
          EXPECT_NEAR(y, p.y(), 1e-13 * scale);
        }
      }
  }
}

TYPED_TEST(Output, LocatorFindsVerticesAndEdgePoints) {
  using K = TypeParam;
  using FT = typename K::FT;
  Delaunay<K> dt;
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    SCOPED_TRACE(name);
    const Domain_locator<K> locator(domain);
    for (Index v = 0; v < domain.number_of_vertices(); ++v) {
      const auto location = locator.locate(domain.point(v));
      ASSERT_TRUE(location.has_value());
      const auto& t = domain.face(location->face);
      int position = -1;
      for (int i = 0; i < 3; ++i)
        if (t[i] == v)
          position = i;
      ASSERT_GE(position, 0) << "vertex " << v << " located in a face not incident to it";
      for (int i = 0; i < 3; ++i) // exactly a unit vector, also in double
        EXPECT_EQ(location->barycentric[i], FT(i == position ? 1 : 0));
    }
    int on_edges = 0;
    for (Index e = 0; e < domain.number_of_edges(); ++e) {
      const auto& a = domain.point(domain.edge(e)[0]);
      const auto& b = domain.point(domain.edge(e)[1]);
      for (int k = 1; k <= 3; ++k) {
        const FT s = FT(k) / FT(4);
        const FT x = a.x() + s * (b.x() - a.x()), y = a.y() + s * (b.y() - a.y());
        const typename K::Point_2 p(x, y);
        // with double, (a + s(b - a)) may round off the edge; test only points on it
        if (!CGAL::collinear(a, b, p))
          continue;
        ++on_edges;
        const auto location = locator.locate(p);
        ASSERT_TRUE(location.has_value());
        const auto& ef = domain.edge_faces(e);
        ASSERT_TRUE(location->face == ef[0] || location->face == ef[1]);
        // the coordinate of the vertex opposite the edge is exactly zero
        const Index opposite = domain.opposite_vertex(location->face, e);
        const auto& t = domain.face(location->face);
        for (int i = 0; i < 3; ++i)
          if (t[i] == opposite) {
            EXPECT_EQ(location->barycentric[i], FT(0));
          }
      }
    }
    EXPECT_GT(on_edges, 0);
  }
}

TYPED_TEST(Output, LocatorRejectsOutsidePointsAndHoles) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  // named FT arguments: gmpxx expressions must not reach the point constructor
  const auto pt = [](const FT& x, const FT& y) { return Point_2(x, y); };
  {
    const Planar_domain<K> grid = grid_domain<K>(4); // [-1, 1]^2
    const Domain_locator<K> locator(grid);
    for (const Point_2& p : {pt(-100, 0), pt(0, 1e6), pt(FT(-9) / FT(8), 0),
                             pt(FT(1) + FT(1) / FT(1 << 20), FT(1) / FT(3)),
                             pt(FT(1) / FT(3), FT(-1) - FT(1) / FT(1 << 30))})
      EXPECT_FALSE(locator.locate(p).has_value()) << p;
    for (const Point_2& p : {pt(-1, -1), pt(1, FT(1) / FT(3)), pt(0, 1)})
      EXPECT_TRUE(locator.locate(p).has_value()) << p;
  }
  {
    const Planar_domain<K> ring = ring_domain<K>(); // [0,3]^2 minus the open (1,2)^2
    const Domain_locator<K> locator(ring);
    const FT tiny = FT(1) / FT(1 << 20);
    for (const Point_2& p :
         {pt(FT(3) / FT(2), FT(3) / FT(2)), pt(1 + tiny, 2 - tiny), pt(2 - tiny, 1 + tiny),
          pt(FT(3) / FT(2), 1 + tiny), pt(-1, 1), pt(3 + tiny, 3)})
      EXPECT_FALSE(locator.locate(p).has_value()) << p;
    // the border of the hole belongs to the domain
    for (const Point_2& p : {pt(1, FT(3) / FT(2)), pt(2, 2), pt(FT(7) / FT(4), 1),
                             pt(1 - tiny, FT(3) / FT(2)), pt(3, 3)})
      EXPECT_TRUE(locator.locate(p).has_value()) << p;
  }
  {
    // Convex hull of random points: agree with the triangulation's own point location.
    Delaunay<K> dt;
    const Planar_domain<K> domain = delaunay_domain<K>(dt, 5, 40);
    const Domain_locator<K> locator(domain);
    Random_rationals random(17);
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      const FT x = random.rational<FT>(24, 7), y = random.rational<FT>(24, 7);
      const Point_2 p(x, y);
      typename Delaunay<K>::Locate_type type;
      int li;
      dt.locate(p, type, li);
      const bool expected =
          type == Delaunay<K>::VERTEX || type == Delaunay<K>::EDGE || type == Delaunay<K>::FACE;
      const auto location = locator.locate(p);
      EXPECT_EQ(location.has_value(), expected) << p;
      (expected ? inside : outside) += 1;
      if (location) {
        EXPECT_TRUE(in_closed_face(domain, location->face, p));
      }
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 100);
  }
}

TYPED_TEST(Output, LocatorRejectsNonFiniteQueries) {
  using K = TypeParam;
  if constexpr (!is_exact<K>) {
    const Planar_domain<K> grid = grid_domain<K>(4);
    const Domain_locator<K> locator(grid);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto& p : {typename K::Point_2(nan, 0), typename K::Point_2(0, nan),
                          typename K::Point_2(inf, 0), typename K::Point_2(0, -inf)})
      EXPECT_FALSE(locator.locate(p).has_value());
  } else {
    GTEST_SKIP() << "exact rationals have no NaN or infinity";
  }
}

TYPED_TEST(Output, LocatorStaysLinearOnAFan) {
  // 400 long thin triangles around the centre of [-1, 1]^2: each one's bounding box covers
  // a large part of the domain, so the grid must be coarsened to keep memory linear.
  using K = TypeParam;
  using FT = typename K::FT;
  const int per_side = 100;
  std::vector<typename K::Point_2> points{typename K::Point_2(0, 0)};
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < per_side; ++k) {
      const FT s = FT(2 * k) / FT(per_side) - FT(1); // -1 .. 1 - 2/per_side
      switch (side) {
      case 0:
        points.emplace_back(s, -1);
        break;
      case 1:
        points.emplace_back(1, s);
        break;
      case 2:
        points.emplace_back(-s, 1);
        break;
      default:
        points.emplace_back(-1, -s);
        break;
      }
    }
  std::vector<std::array<Index, 3>> triangles;
  const Index ring = static_cast<Index>(points.size() - 1);
  for (Index i = 0; i < ring; ++i)
    triangles.push_back({{0, 1 + i, 1 + (i + 1) % ring}});
  const Planar_domain<K> fan(points, triangles);
  const Domain_locator<K> locator(fan);
  EXPECT_LE(locator.number_of_entries(), 8 * fan.number_of_faces() + 16);
  Random_rationals random(23);
  for (int trial = 0; trial < 500; ++trial) {
    const Index f = static_cast<Index>(random.integer(0, ring - 1));
    const typename K::Point_2 p = random_point_in(fan, f, random);
    const auto location = locator.locate(p);
    ASSERT_TRUE(location.has_value());
    EXPECT_TRUE(in_closed_face(fan, location->face, p));
  }
  EXPECT_TRUE(locator.locate(typename K::Point_2(0, 0)).has_value());
  EXPECT_FALSE(locator.locate(typename K::Point_2(FT(3) / FT(2), 0)).has_value());
}

// ---------------------------------------------------------------------------------------
// The double plan on all cores: frames, routes, flip choices and the weights' statistics are
// computed per vertex and per edge in parallel (this file builds without
// CGAL_TRIANGULAR_SPLINE_CHECK_IMPLICIT_RULES, which keeps test_xu's plans serial).
// ---------------------------------------------------------------------------------------

// The rules at which two plans of as many rules differ (target, sources or weights).
template <class Rule>
std::size_t differing_rules(const std::vector<Rule>& a, const std::vector<Rule>& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    differing +=
        a[i].target == b[i].target && a[i].sources == b[i].sources && a[i].weights == b[i].weights
            ? 0
            : 1;
  return differing;
}

TEST(Plan, OnAllCoresIsTheOneThreadPlan) {
  using Spline = TS::C1_quintic_spline<Epick>;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0, 1);
  // random points (thin frames re-routed) and a grid jittered by rounding (degenerate frames,
  // near-singular vertices)
  for (const bool scattered : {true, false}) {
    std::vector<Epick::Point_2> points;
    if (scattered) {
      for (int i = 0; i < 30000; ++i)
        points.emplace_back(uniform(random), uniform(random));
    } else {
      for (int i = 0; i < 175; ++i)
        for (int j = 0; j < 175; ++j)
          points.emplace_back((i + 1e-12 * uniform(random)) / 174,
                              (j + 1e-12 * uniform(random)) / 174);
    }
    Delaunay<Epick> dt(points.begin(), points.end());
    std::vector<Delaunay<Epick>::Vertex_handle> handles;
    const auto domain = TS::domain_from_triangulation_2<Epick>(
        dt, [](Delaunay<Epick>::Face_handle) { return true; }, handles);
    ASSERT_GT(domain.number_of_vertices(), 20000u); // the plan's loops run in parallel there
    TS::internal::thread_limit() = 1;
    const Spline one(domain);
    TS::internal::thread_limit() = 0;
    const Spline all(domain);
    ASSERT_EQ(one.number_of_rules(), all.number_of_rules());
    const std::vector<Spline::Rule> rules = all.rules(), one_rules = one.rules();
    EXPECT_EQ(differing_rules(rules, one_rules), 0u);
    EXPECT_TRUE(one.free_slots() == all.free_slots());
    EXPECT_EQ(one.number_of_stored_rules(), all.number_of_stored_rules());
    EXPECT_TRUE(one.near_singular_vertices() == all.near_singular_vertices());
    ASSERT_EQ(one.rerouted_frames().size(), all.rerouted_frames().size());
    for (std::size_t i = 0; i < all.rerouted_frames().size(); ++i) {
      const auto &a = all.rerouted_frames()[i], &b = one.rerouted_frames()[i];
      EXPECT_TRUE(a.edge == b.edge && a.vertex == b.vertex && a.thin == b.thin &&
                  a.numerical == b.numerical && a.regular_weight == b.regular_weight)
          << i;
    }
    if (scattered) {
      EXPECT_GT(all.rerouted_frames().size(), 1000u);
    } else {
      EXPECT_GT(all.near_singular_vertices().size(), 10u);
    }
    // the statistics, gathered by block on all cores, are those of the rules
    const auto above = expect_weight_statistics_of_rules(all, rules);
    expect_weight_statistics_of_rules(one, one_rules);
    if (scattered) { // flip rules above the bound exist (the counts are tested)
      EXPECT_GT(above[std::size_t(TS::Slot_kind::MIDDLE_INNER)], 0u);
    }
  }
}

// A plan whose thin re-routings close a dependency cycle is built again without the least
// thin one on each (plan_rounds() 2 and more). The corner regions' frames and their weights
// are chosen once for all rounds, and the ordering's first pass runs in runs of one kind on
// all cores: the plan must still be a propagation order, count every rule's weight once, and
// be the one-thread plan. (About one set of 2 10^5 random points in six needed two rounds,
// most sets of 10^6 points did; their cycles were all single faces', which the plan now
// breaks before listing, so this test leaves those to the ordering.)
// An exact plan stores every rule; from 20000 rules propagation_amplification() runs them
// depth by depth on all cores, and gives the one-thread estimate (plan order) bit for bit.
TEST(Plan, ExactAmplificationOnAllCoresIsTheOneThreadEstimate) {
  using K = Exact_kernel;
  using FT = K::FT;
  std::mt19937 random(19);
  std::uniform_int_distribution<int> coordinate(0, 1000000);
  Delaunay<K> dt;
  for (int i = 0; i < 3500; ++i) {
    const FT x = FT(coordinate(random)) / 1000000;
    dt.insert(K::Point_2(x, FT(coordinate(random)) / 1000000));
  }
  std::vector<Delaunay<K>::Vertex_handle> handles;
  const auto domain = TS::domain_from_triangulation_2<K>(
      dt, [](Delaunay<K>::Face_handle) { return true; }, handles);
  const TS::C1_quintic_spline<K> spline(domain);
  ASSERT_GT(spline.number_of_rules(), 40000u);
  const double all = spline.propagation_amplification();
  TS::internal::thread_limit() = 1;
  const double one = spline.propagation_amplification();
  TS::internal::thread_limit() = 0;
  EXPECT_EQ(all, one);
  EXPECT_GE(all, 1.0); // the free signs are +-1 and pass into the rules' targets
}

// Tests that need the plan's second round: face cycles left to order_rules(), and put back
// however the test ends.
struct Face_cycles_left_to_the_ordering {
  Face_cycles_left_to_the_ordering() { TS::internal::break_face_cycles_first() = false; }
  ~Face_cycles_left_to_the_ordering() { TS::internal::break_face_cycles_first() = true; }
};

// A face whose three edges are re-routed at three different corners, each corner's link
// solving for the face's own corner-inner point, closes a dependency cycle: every cycle of
// four sets of 10^6 random points (two or three each) was one. The plan breaks them before
// listing any rule, in one round, with the plan that order_rules() and a second round give:
// the same rules (targets, sources, weights) in the same order and the same free slots. The
// two neighbourhoods are two rings around such faces of 10^6 random points.
TEST(Plan, FaceCyclesBrokenBeforeListingGiveTheRebuiltPlan) {
  const std::vector<std::vector<std::array<double, 2>>> neighbourhoods = {
      {
          {0.30335331068553761, 0.73149742902651771}, {0.30386490106441427, 0.73211307461169539},
          {0.30513472544094145, 0.73173030233236125}, {0.30681265373837863, 0.73190859919253226},
          {0.30567522715345874, 0.73031778987348317}, {0.30576245702770599, 0.73065406768443397},
          {0.30522853864147309, 0.73146997541640812}, {0.30330026242130043, 0.73100480484937325},
          {0.30323028355912363, 0.73058379422683351}, {0.30435194398190279, 0.72975987348128746},
          {0.30494610894183932, 0.72800778290064982}, {0.30344798653299365, 0.72963038032332217},
          {0.30498498716898348, 0.72938716466108189}, {0.3030598844126064, 0.72856391821627076},
          {0.30294580409251615, 0.72924770444730791}, {0.30141243214070096, 0.72967611948944411},
          {0.30256269194273011, 0.72956788944329121}, {0.30230170506793685, 0.73026050916864016},
          {0.30175550992170697, 0.7300817843349825},  {0.30132769384492764, 0.73089697627567152},
          {0.30224280271567239, 0.73054224405871693}, {0.30296667502364899, 0.73075650948585824},
          {0.30197536274498338, 0.73186670441823343}, {0.30175761497125658, 0.7307638566293666},
          {0.30163401687327862, 0.73262912406235958}, {0.30312227092391003, 0.73269522695145306},
          {0.30096292306049977, 0.73193462404119713},
      },
      {
          {0.69456447335886506, 0.98272588153188145}, {0.69441392515349354, 0.98225885647459088},
          {0.69221000870054961, 0.98177862344498679}, {0.69193918645856112, 0.98282135077390642},
          {0.69128302866511093, 0.98210294050462943}, {0.68973558988559591, 0.98270743616173994},
          {0.68951347470852498, 0.98279848921057422}, {0.69054819936207101, 0.98582214355002074},
          {0.69088149433720702, 0.98600291116942473}, {0.6925775313015673, 0.98571248977751158},
          {0.69261319606103966, 0.98523416881696735}, {0.69103723212540036, 0.98462878770905171},
          {0.68898463784830877, 0.98423410161314706}, {0.6911679873907105, 0.98370392329517709},
          {0.69264394983929145, 0.98490413836651347}, {0.69329194558616225, 0.98495717991463938},
          {0.69434879923548953, 0.98407326642176418}, {0.69435299434936881, 0.9837580151421812},
          {0.69510642009099233, 0.98322655924773406}, {0.69526464944155641, 0.98413101049749463},
          {0.6937087287679693, 0.9850320377456081},   {0.69293442057895849, 0.98496497730145804},
          {0.69368307583437983, 0.9861630565524554},  {0.69188914163556714, 0.9875805704883639},
          {0.69108581966123794, 0.9873922421730037},  {0.69070186547543233, 0.98695242959720264},
      }};
  auto check = [](auto kernel, const std::vector<std::array<double, 2>>& points) {
    using K = decltype(kernel);
    using Spline = TS::C1_quintic_spline<K>;
    Delaunay<K> dt;
    for (const auto& p : points)
      dt.insert(typename K::Point_2(p[0], p[1]));
    std::vector<typename Delaunay<K>::Vertex_handle> handles;
    const auto domain = TS::domain_from_triangulation_2<K>(
        dt, [](typename Delaunay<K>::Face_handle) { return true; }, handles);
    const Spline first(domain);
    EXPECT_EQ(first.plan_rounds(), 1);
    std::optional<Spline> rebuilt;
    {
      Face_cycles_left_to_the_ordering left;
      rebuilt.emplace(domain);
    }
    EXPECT_EQ(rebuilt->plan_rounds(), 2);
    ASSERT_EQ(first.number_of_rules(), rebuilt->number_of_rules());
    EXPECT_EQ(differing_rules(first.rules(), rebuilt->rules()), 0u);
    EXPECT_TRUE(first.free_slots() == rebuilt->free_slots());
    EXPECT_EQ(first.rerouted_frames().size(), rebuilt->rerouted_frames().size());
    EXPECT_EQ(first.max_propagation_weight(), rebuilt->max_propagation_weight());
    EXPECT_GT(first.rerouted_frames().size(), 2u); // the faces' two other thin edges
  };
  for (const auto& points : neighbourhoods) {
    check(Epick(), points);
    check(Exact_kernel(), points);
  }
}

TEST(Plan, RebuiltAfterADependencyCycleIsAnOrderAndTheOneThreadPlan) {
  Face_cycles_left_to_the_ordering left; // else no cycle is left for a second round
  using Spline = TS::C1_quintic_spline<Epick>;
  const auto domain_of = [](unsigned seed, int n) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::vector<Epick::Point_2> points;
    for (int i = 0; i < n; ++i)
      points.emplace_back(uniform(random), uniform(random));
    Delaunay<Epick> dt(points.begin(), points.end());
    std::vector<Delaunay<Epick>::Vertex_handle> handles;
    return TS::domain_from_triangulation_2<Epick>(
        dt, [](Delaunay<Epick>::Face_handle) { return true; }, handles);
  };
  const auto domain = domain_of(3, 20000); // 3 of the first 200 seeds need two rounds
  const Spline all(domain);
  ASSERT_GE(all.plan_rounds(), 2);
  const std::vector<Spline::Rule> rules = all.rules();
  // every source free or computed by an earlier rule, every other slot computed once
  std::vector<char> known(all.values().size(), 0);
  for (const Spline::Slot s : all.free_slots())
    known[s] = 1;
  std::size_t unknown_sources = 0, computed_twice = 0;
  for (const Spline::Rule& r : rules) {
    for (int i = 0; i < r.size(); ++i)
      unknown_sources += known[r.sources[std::size_t(i)]] ? 0 : 1;
    computed_twice += known[r.target] ? 1 : 0;
    known[r.target] = 1;
  }
  EXPECT_EQ(unknown_sources, 0u);
  EXPECT_EQ(computed_twice, 0u);
  EXPECT_EQ(std::count(known.begin(), known.end(), 0), 0);
  // the statistics of the last round, the corner regions' taken from the first
  expect_weight_statistics_of_rules(all, rules);
  TS::internal::thread_limit() = 1;
  const Spline one(domain);
  TS::internal::thread_limit() = 0;
  EXPECT_EQ(one.plan_rounds(), all.plan_rounds());
  ASSERT_EQ(one.number_of_rules(), all.number_of_rules());
  const std::vector<Spline::Rule> one_rules = one.rules();
  EXPECT_EQ(differing_rules(rules, one_rules), 0u);
  EXPECT_TRUE(one.free_slots() == all.free_slots());
  EXPECT_EQ(one.max_propagation_weight(), all.max_propagation_weight());
}

// internal::release() frees a vector's storage (`v = {}` keeps it: an empty initializer
// list assigned).
TEST(Support, ReleaseFreesTheStorage) {
  std::vector<double> v(100000, 1.0);
  TS::internal::release(v);
  EXPECT_EQ(v.capacity(), 0u);
  std::vector<std::vector<int>> nested(1000, std::vector<int>(10));
  TS::internal::release(nested);
  EXPECT_EQ(nested.capacity(), 0u);
}

TEST(Locator, LazyExactKernelWithRoundedCoordinates) {
  // Epeck's to_double is not monotone, so the bucket boxes are widened; coordinates in
  // thirds round in double, and points on edges and at vertices must still be found.
  using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
  using FT = Epeck::FT;
  const int cells = 6;
  std::vector<Epeck::Point_2> points;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i)
      points.emplace_back(FT(i) / FT(3), FT(j) / FT(3));
  std::vector<std::array<Index, 3>> triangles;
  auto id = [](int i, int j) { return static_cast<Index>(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  const Planar_domain<Epeck> domain(points, triangles);
  const Domain_locator<Epeck> locator(domain);
  for (Index v = 0; v < domain.number_of_vertices(); ++v)
    EXPECT_TRUE(locator.locate(domain.point(v)).has_value());
  for (Index e = 0; e < domain.number_of_edges(); ++e) {
    const auto location = locator.locate(
        CGAL::midpoint(domain.point(domain.edge(e)[0]), domain.point(domain.edge(e)[1])));
    ASSERT_TRUE(location.has_value());
    EXPECT_TRUE(location->face == domain.edge_faces(e)[0] ||
                location->face == domain.edge_faces(e)[1]);
  }
  EXPECT_FALSE(locator.locate(Epeck::Point_2(FT(-1) / FT(3 << 20), 1)).has_value());
  EXPECT_FALSE(locator.locate(Epeck::Point_2(1, FT(2) + FT(1) / FT(3 << 20))).has_value());
}

// ---------------------------------------------------------------------------------------
// Evaluation
// ---------------------------------------------------------------------------------------

TYPED_TEST(Output, EvaluateFunctionalReproducesThePolynomial) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  constexpr bool exact = is_exact<K>;
  Delaunay<K> dt;
  Random_rationals random(7);
  const Polynomial_surface<K> polynomial = random.polynomial<K>(5);
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    SCOPED_TRACE(name);
    const Domain_locator<K> locator(domain);
    const auto patches = patches_of(domain, polynomial);
    std::vector<Point_2> queries;
    std::vector<bool> inside;
    for (Index f = 0; f < domain.number_of_faces(); ++f) {
      queries.push_back(random_point_in(domain, f, random));
      inside.push_back(true);
    }
    for (const Point_2& p : domain.points()) {
      queries.push_back(p);
      inside.push_back(true);
    }
    const FT half = FT(3) / FT(2);
    for (const Point_2& p : {Point_2(-50, 0), Point_2(0, 50), Point_2(half, half)})
      if (!locator.locate(p)) {
        queries.push_back(p);
        inside.push_back(false);
      }
    const std::vector<double> values =
        TS::evaluate_functional(network(domain, patches), locator, queries);
    const auto exact_values = TS::evaluate_at(network(domain, patches), locator, queries);
    ASSERT_EQ(values.size(), queries.size());
    ASSERT_EQ(exact_values.size(), queries.size());
    for (std::size_t q = 0; q < queries.size(); ++q) {
      if (!inside[q]) {
        EXPECT_TRUE(std::isnan(values[q]));
        EXPECT_FALSE(exact_values[q].has_value());
        continue;
      }
      const FT expected = polynomial.evaluate(queries[q]);
      const double e = CGAL::to_double(expected);
      ASSERT_TRUE(exact_values[q].has_value());
      // double: de Casteljau on values of size ~1e3 at points of size ~3 (stated tolerance)
      const double tolerance = exact ? 1e-12 : 1e-9;
      EXPECT_LE(std::abs(values[q] - e), tolerance * (std::max)(1.0, std::abs(e)))
          << "query " << q << " value " << values[q] << " expected " << e;
      EXPECT_TRUE(
          same_value(*exact_values[q], expected, exact, 1e-9, (std::max)(1.0, std::abs(e))));
    }
    // the one-point overload agrees
    EXPECT_EQ(TS::evaluate_at(network(domain, patches), locator, queries.front()).has_value(),
              true);
    EXPECT_FALSE(TS::evaluate_at(network(domain, patches), locator, Point_2(-50, -50)).has_value());
  }
}

TYPED_TEST(Output, EvaluateAtParametricPatches) {
  using K = TypeParam;
  using Vector_3 = typename K::Vector_3;
  constexpr bool exact = is_exact<K>;
  Random_rationals random(9);
  const Polynomial_surface<K, Vector_3> polynomial = random.polynomial<K, Vector_3>(5);
  const Planar_domain<K> domain = grid_domain<K>(3);
  const Domain_locator<K> locator(domain);
  const auto patches = patches_of(domain, polynomial);
  std::vector<typename K::Point_2> queries;
  for (Index f = 0; f < domain.number_of_faces(); ++f)
    queries.push_back(random_point_in(domain, f, random));
  queries.emplace_back(5, 5);
  // a network returning patches by value works as well
  const auto stored = network(domain, patches);
  const auto values = TS::evaluate_at(By_value_network<decltype(stored)>{stored}, locator, queries);
  for (std::size_t q = 0; q + 1 < queries.size(); ++q) {
    ASSERT_TRUE(values[q].has_value());
    const Vector_3 expected = polynomial.evaluate(queries[q]);
    EXPECT_TRUE(same_value(*values[q], expected, exact, 1e-9, 1e3));
  }
  EXPECT_FALSE(values.back().has_value());
}

// ---------------------------------------------------------------------------------------
// Jets (value, gradient, Hessian), snapping to hull edges, outside modes
// ---------------------------------------------------------------------------------------

namespace {

// The jet of a polynomial: its derivatives as polynomials, evaluated at p.
template <class K, class Value>
TS::Point_jet<Value> polynomial_jet(const Polynomial_surface<K, Value>& polynomial,
                                    const typename K::Point_2& p) {
  return {polynomial.evaluate(p),
          {{polynomial.derivative(1, 0).evaluate(p), polynomial.derivative(0, 1).evaluate(p)}},
          {{polynomial.derivative(2, 0).evaluate(p), polynomial.derivative(1, 1).evaluate(p),
            polynomial.derivative(0, 2).evaluate(p)}}};
}

// Exact: identical members; double: relative tolerance. `order` limits what is compared.
template <class Value>
::testing::AssertionResult same_jet(const TS::Point_jet<Value>& a, const TS::Point_jet<Value>& b,
                                    bool exact, double scale, int order = 2) {
  std::vector<std::pair<const Value*, const Value*>> members{{&a.value, &b.value}};
  if (order >= 1)
    for (std::size_t i = 0; i < 2; ++i)
      members.emplace_back(&a.gradient[i], &b.gradient[i]);
  if (order >= 2)
    for (std::size_t i = 0; i < 3; ++i)
      members.emplace_back(&a.hessian[i], &b.hessian[i]);
  for (std::size_t m = 0; m < members.size(); ++m) {
    ::testing::AssertionResult r =
        same_value(*members[m].first, *members[m].second, exact, 1e-8, scale);
    if (!r)
      return r << " in member " << m << " (value, zx, zy, zxx, zxy, zyy)";
  }
  return ::testing::AssertionSuccess();
}

// A point at distance `relative` * |ab| outside the boundary edge e (the outer normal side),
// above the point of the edge with parameter 1/3.
template <class K>
std::pair<typename K::Point_2, typename K::Point_2>
point_outside_edge(const Planar_domain<K>& domain, Index e, const typename K::FT& relative) {
  using FT = typename K::FT;
  const auto& ends = domain.edge(e);
  const auto& a = domain.point(ends[0]);
  const auto& b = domain.point(ends[1]);
  const auto& faces = domain.edge_faces(e);
  const Index f = faces[0] != Planar_domain<K>::null_index ? faces[0] : faces[1];
  const auto& c = domain.point(domain.opposite_vertex(f, e));
  const FT third = FT(1) / FT(3);
  const typename K::Point_2 on = a + (b - a) * third;
  typename K::Vector_2 normal(b.y() - a.y(), a.x() - b.x()); // |normal| = |ab|
  if ((c - on) * normal > FT(0))
    normal = -normal;
  return {on + normal * relative, on};
}

} // namespace

TYPED_TEST(Output, JetsReproduceThePolynomialDerivatives) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  constexpr bool exact = is_exact<K>;
  Delaunay<K> dt;
  Random_rationals random(31);
  const Polynomial_surface<K> polynomial = random.polynomial<K>(5);
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    SCOPED_TRACE(name);
    const Domain_locator<K> locator(domain);
    // vertex orders vary and every seventh patch is over a larger triangle
    const auto patches = patches_of(domain, polynomial);
    std::vector<Point_2> queries(domain.points());
    for (Index f = 0; f < domain.number_of_faces(); ++f)
      for (int trial = 0; trial < 3; ++trial)
        queries.push_back(random_point_in(domain, f, random));
    for (int order = 0; order <= 2; ++order) {
      const auto jets = TS::evaluate_jets(network(domain, patches), locator, queries,
                                          TS::Outside::NO_VALUE, order);
      ASSERT_EQ(jets.size(), queries.size());
      for (std::size_t q = 0; q < queries.size(); ++q) {
        ASSERT_TRUE(jets[q].has_value()) << queries[q];
        const TS::Point_jet<FT> expected = polynomial_jet(polynomial, queries[q]);
        EXPECT_TRUE(same_jet(*jets[q], expected, exact, 1e3, order)) << queries[q];
        // derivatives above `order` are zero
        if (order < 2) {
          EXPECT_EQ(jets[q]->hessian[1], FT(0));
        }
        if (order < 1) {
          EXPECT_EQ(jets[q]->gradient[0], FT(0));
        }
      }
    }
    EXPECT_TRUE(same_jet(*TS::evaluate_jet(network(domain, patches), locator, queries.back()),
                         polynomial_jet(polynomial, queries.back()), exact, 1e3));
    EXPECT_FALSE(TS::evaluate_jet(network(domain, patches), locator, Point_2(-50, 7)).has_value());
  }
}

TEST(Jets, LowDegreeAndParametricPatches) {
  using K = Exact_kernel;
  using FT = K::FT;
  using Vector_3 = K::Vector_3;
  Random_rationals random(37);
  const auto t = random.triangle<K>();
  const K::Point_2 p = CGAL::barycenter(t[0], FT(2), t[1], FT(3), t[2], FT(5));
  for (int degree = 0; degree <= 3; ++degree) {
    SCOPED_TRACE(degree);
    const Polynomial_surface<K> polynomial = random.polynomial<K>(degree);
    const auto patch = polynomial.to_bezier(degree, t[0], t[1], t[2]);
    EXPECT_TRUE(same_jet(patch.jet(p), polynomial_jet(polynomial, p), true, 1));
  }
  const Polynomial_surface<K, Vector_3> surface = random.polynomial<K, Vector_3>(4);
  const auto patch = surface.to_bezier(4, t[0], t[1], t[2]);
  EXPECT_TRUE(same_jet(patch.jet(p), polynomial_jet(surface, p), true, 1));
}

TEST(Jets, C1SplineFittedToACubicHasTheCubicsDerivativesExactly) {
  // Local polynomial fits reproduce a cubic exactly in exact arithmetic, so the spline's
  // value, gradient and Hessian are the cubic's at every rational point.
  using K = Exact_kernel;
  using FT = K::FT;
  Delaunay<K> dt;
  const Planar_domain<K> domain = delaunay_domain<K>(dt, 41, 40);
  Random_rationals random(43);
  const Polynomial_surface<K> cubic = random.polynomial<K>(3);
  std::vector<FT> values;
  for (const auto& p : domain.points())
    values.push_back(cubic.evaluate(p));
  TS::C1_quintic_spline<K> spline(domain, TS::Corner_frame::CORNER_AND_TWO_STARS);
  TS::fit_vertex_data(spline, values, TS::Fit::LOCAL_POLYNOMIAL, 3);
  const Domain_locator<K> locator(spline.domain());
  std::vector<K::Point_2> queries;
  for (Index f = 0; f < spline.domain().number_of_faces(); ++f)
    queries.push_back(random_point_in(spline.domain(), f, random));
  const auto jets = TS::evaluate_jets(spline, locator, queries);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    ASSERT_TRUE(jets[q].has_value());
    EXPECT_TRUE(same_jet(*jets[q], polynomial_jet(cubic, queries[q]), true, 1)) << queries[q];
  }
}

namespace {

// The local-polynomial spline of sin(3x) cos(2y) at 300 random points (double).
TS::C1_quintic_spline<Epick> smooth_spline(unsigned seed) {
  Delaunay<Epick> dt;
  const Planar_domain<Epick> domain = delaunay_domain<Epick>(dt, seed, 300);
  std::vector<double> values;
  for (const auto& p : domain.points())
    values.push_back(std::sin(3 * p.x()) * std::cos(2 * p.y()));
  TS::C1_quintic_spline<Epick> spline(domain, TS::Corner_frame::CORNER_AND_TWO_STARS);
  TS::fit_vertex_data(spline, values, TS::Fit::LOCAL_POLYNOMIAL, 5);
  return spline;
}

} // namespace

// Many queries run on all cores (double): every result must be bit for bit the one of a
// single query (always on the calling thread), inside, outside and extrapolated.
TEST(Jets, ManyQueriesOnAllCoresMatchOneAtATime) {
  using K = Epick;
  const TS::C1_quintic_spline<K> spline = smooth_spline(53);
  const Planar_domain<K>& domain = spline.domain();
  const Domain_locator<K> locator(spline.domain());
  // random points over a box a little larger than the hull, so some fall outside
  std::mt19937_64 engine(7);
  std::vector<double> xs, ys;
  for (const auto& p : domain.points()) {
    xs.push_back(p.x());
    ys.push_back(p.y());
  }
  const auto [xmin, xmax] = std::minmax_element(xs.begin(), xs.end());
  const auto [ymin, ymax] = std::minmax_element(ys.begin(), ys.end());
  std::uniform_real_distribution<double> x(*xmin - 0.1, *xmax + 0.1), y(*ymin - 0.1, *ymax + 0.1);
  std::vector<K::Point_2> queries;
  for (int i = 0; i < 50000; ++i)
    queries.emplace_back(x(engine), y(engine));
  const auto jets = TS::evaluate_jets(spline, locator, queries, TS::Outside::LINEAR);
  const std::vector<double> heights = TS::evaluate_functional(spline, locator, queries);
  std::size_t outside = 0;
  for (std::size_t q = 0; q < queries.size(); q += 7) {
    const auto one = TS::evaluate_jet(spline, locator, queries[q], TS::Outside::LINEAR);
    ASSERT_TRUE(jets[q].has_value() && one.has_value());
    EXPECT_TRUE(jets[q]->value == one->value && jets[q]->gradient == one->gradient &&
                jets[q]->hessian == one->hessian)
        << queries[q];
    const auto value = TS::evaluate_at(spline, locator, queries[q]);
    if (value)
      EXPECT_EQ(heights[q], *value);
    else {
      EXPECT_TRUE(std::isnan(heights[q]));
      ++outside;
    }
  }
  EXPECT_GT(outside, 100u);
  // Spatially sorted, the queries locate from the previous query's face: the same results.
  std::vector<K::Point_2> sorted = queries;
  CGAL::hilbert_sort(sorted.begin(), sorted.end());
  const auto sorted_jets = TS::evaluate_jets(spline, locator, sorted, TS::Outside::LINEAR);
  for (std::size_t q = 0; q < sorted.size(); q += 7) {
    const auto one = TS::evaluate_jet(spline, locator, sorted[q], TS::Outside::LINEAR);
    EXPECT_TRUE(sorted_jets[q]->value == one->value && sorted_jets[q]->gradient == one->gradient &&
                sorted_jets[q]->hessian == one->hessian)
        << sorted[q];
  }
  // The spline's nets, read without building patches, give its patches' own results.
  std::vector<Bezier_triangle<K>> patches;
  for (Index f = 0; f < spline.domain().number_of_faces(); ++f)
    patches.push_back(spline.patch(f));
  const TS::Patch_network<K> stored(spline.domain(), patches);
  const auto via_patches = TS::evaluate_jets(stored, locator, queries, TS::Outside::LINEAR);
  const std::vector<double> heights_via_patches = TS::evaluate_functional(stored, locator, queries);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    EXPECT_TRUE(via_patches[q]->value == jets[q]->value &&
                via_patches[q]->gradient == jets[q]->gradient &&
                via_patches[q]->hessian == jets[q]->hessian)
        << queries[q];
    EXPECT_TRUE(heights_via_patches[q] == heights[q] ||
                (std::isnan(heights_via_patches[q]) && std::isnan(heights[q])));
  }
}

TEST(Locator, EvaluationOrderGroupsRandomQueriesByBucket) {
  // Random queries are evaluated bucket by bucket (a stable counting sort); queries already
  // in spatial order (a grid's rows) and few queries keep their own order.
  using K = Epick;
  Delaunay<K> dt;
  const Planar_domain<K> domain = delaunay_domain<K>(dt, 61, 200);
  const Domain_locator<K> locator(domain);
  std::mt19937_64 engine(11);
  std::uniform_real_distribution<double> u(-25, 25); // beyond the domain too
  std::vector<K::Point_2> random, grid;
  for (int i = 0; i < 30000; ++i)
    random.emplace_back(u(engine), u(engine));
  random.emplace_back(std::nan(""), 0.0);
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i)
      grid.emplace_back(-20 + 0.2 * i, -20 + 0.2 * j);
  const std::vector<std::size_t> order = TS::internal::evaluation_order(locator, random);
  ASSERT_EQ(order.size(), random.size());
  std::vector<char> seen(random.size(), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    ASSERT_LT(order[i], random.size());
    EXPECT_FALSE(seen[order[i]]);
    seen[order[i]] = 1;
    if (i > 0) {
      const std::size_t a = locator.bucket(random[order[i - 1]]),
                        b = locator.bucket(random[order[i]]);
      EXPECT_TRUE(a < b || (a == b && order[i - 1] < order[i])) << i;
    }
  }
  EXPECT_EQ(locator.bucket(random.back()), locator.number_of_buckets());
  EXPECT_TRUE(TS::internal::evaluation_order(locator, grid).empty());
  std::vector<K::Point_2> sorted(random.begin(), random.end() - 1); // spatially ordered
  CGAL::hilbert_sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(TS::internal::evaluation_order(locator, sorted).empty());
  random.resize(19999);
  EXPECT_TRUE(TS::internal::evaluation_order(locator, random).empty());
}

TEST(Locator, TriesTheHintFirst) {
  // A vertex lies in every face of its star: with a hint from the star it is located in the
  // hint; a hint elsewhere, none, or a non-finite point give what locate_snapped() gives.
  using K = Epick;
  Delaunay<K> dt;
  const Planar_domain<K> domain = delaunay_domain<K>(dt, 59, 60);
  const Domain_locator<K> locator(domain);
  std::size_t tried = 0;
  for (Index v = 0; v < domain.number_of_vertices(); ++v) {
    const K::Point_2& p = domain.point(v);
    const auto plain = locator.locate_snapped(p);
    ASSERT_TRUE(plain.has_value());
    const auto [fb, fe] = domain.star_faces(v);
    for (auto f = fb; f != fe; ++f) {
      const auto hinted = locator.locate_snapped(p, *f);
      ASSERT_TRUE(hinted.has_value());
      EXPECT_EQ(hinted->face, *f);
      ++tried;
    }
    for (const Index hint : {Planar_domain<K>::null_index, Index((plain->face + 7) % 11)}) {
      const auto other = locator.locate_snapped(p, hint);
      ASSERT_TRUE(other.has_value());
      const auto& t = domain.face(other->face);
      EXPECT_TRUE(t[0] == v || t[1] == v || t[2] == v);
    }
    EXPECT_EQ(locator.locate_snapped(p, Planar_domain<K>::null_index)->face, plain->face);
  }
  EXPECT_GT(tried, 200u);
  EXPECT_FALSE(locator.locate_snapped(K::Point_2(std::nan(""), 0), 0).has_value());
}

TYPED_TEST(Output, HintedLocationsWalkToTheFaceOfThePoint) {
  // From any hint, near or far, inside or outside the domain, on a convex domain and on one
  // with a hole: the face found contains the point (exact orientations), and a point inside
  // one face only gets that face with the very coordinates of the unhinted location; a
  // point on an edge or a vertex gets a face around it, with the same point's coordinates.
  using K = TypeParam;
  using FT = typename K::FT;
  Delaunay<K> dt;
  std::vector<std::pair<std::string, Planar_domain<K>>> domains;
  domains.emplace_back("delaunay", delaunay_domain<K>(dt, 23, 400));
  domains.emplace_back("ring", ring_domain<K>());
  Random_rationals random(29);
  for (const auto& [name, domain] : domains) {
    const Domain_locator<K> locator(domain);
    const Index F = static_cast<Index>(domain.number_of_faces());
    std::size_t inside = 0, on_edges = 0;
    auto contains = [&](Index f, const typename K::Point_2& p) {
      const auto& t = domain.face(f);
      for (int i = 0; i < 3; ++i)
        if (CGAL::orientation(domain.point(t[std::size_t(i)]),
                              domain.point(t[std::size_t((i + 1) % 3)]), p) == CGAL::RIGHT_TURN)
          return false;
      return true;
    };
    // random points over the domain's box and beyond it, and points of edges and vertices
    const int extent = name == "ring" ? 4 : 24, denominator = name == "ring" ? 5 : 7;
    std::vector<typename K::Point_2> points;
    for (int i = 0; i < 300; ++i)
      points.emplace_back(random.rational<FT>(extent, denominator),
                          random.rational<FT>(extent, denominator));
    for (Index f = 0; f < F; f += 3) {
      const auto& t = domain.face(f);
      const FT w = FT(random.integer(1, 9)) / FT(10);
      points.push_back(CGAL::barycenter(domain.point(t[0]), w, domain.point(t[1]), FT(1) - w));
      points.push_back(domain.point(t[2]));
    }
    for (const auto& p : points) {
      const auto plain = locator.locate_snapped(p);
      for (const Index hint : {Index(0), Index(F / 2), Index(F - 1), plain ? plain->face : 0}) {
        const auto hinted = locator.locate_snapped(p, hint);
        ASSERT_EQ(hinted.has_value(), plain.has_value()) << name << " " << p;
        if (!plain)
          continue;
        if (!contains(plain->face, p)) { // snapped onto the boundary: the same either way
          EXPECT_EQ(hinted->face, plain->face);
          continue;
        }
        ASSERT_TRUE(contains(hinted->face, p)) << name << " " << p << " hint " << hint;
        const auto& b = plain->barycentric;
        if (b[0] > FT(0) && b[1] > FT(0) && b[2] > FT(0)) {
          EXPECT_EQ(hinted->face, plain->face) << name << " " << p;
          EXPECT_TRUE(hinted->barycentric == plain->barycentric);
          ++inside;
        } else {
          // the same point, in the coordinates of another face around it
          const auto& t = domain.face(hinted->face);
          const auto& c = hinted->barycentric;
          const FT x = c[0] * domain.point(t[0]).x() + c[1] * domain.point(t[1]).x() +
                       c[2] * domain.point(t[2]).x();
          if constexpr (is_exact<K>)
            EXPECT_EQ(x, p.x());
          else // coordinates up to 24, weights from rounded areas: a few ulps
            EXPECT_NEAR(CGAL::to_double(x), CGAL::to_double(p.x()), 1e-12);
          ++on_edges;
        }
      }
    }
    EXPECT_GT(inside, 50u) << name;
    EXPECT_GT(on_edges, 20u) << name;
  }
}

TEST(Locator, FilteredSidesDecideAsExactOrientations) {
  // Points a few ulps from the line of an edge, in double and the same points in rationals:
  // the faces found are the exact kernel's, and so are the zero coordinates of the points
  // exactly on an edge.
  using K = Epick;
  Delaunay<K> dt;
  const Planar_domain<K> domain = delaunay_domain<K>(dt, 31, 200);
  std::vector<Exact_kernel::Point_2> exact_points;
  for (const auto& p : domain.points())
    exact_points.emplace_back(p.x(), p.y());
  std::vector<std::array<Index, 3>> faces;
  for (Index f = 0; f < domain.number_of_faces(); ++f)
    faces.push_back(domain.face(f));
  const Planar_domain<Exact_kernel> exact_domain(std::move(exact_points), std::move(faces));
  const Domain_locator<K> locator(domain);
  const Domain_locator<Exact_kernel> exact_locator(exact_domain);
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> t(0.01, 0.99);
  std::size_t decided = 0, on_line = 0;
  for (Index e = 0; e < domain.number_of_edges(); ++e) {
    const auto& a = domain.point(domain.edge(e)[0]);
    const auto& b = domain.point(domain.edge(e)[1]);
    const double s = t(engine);
    const double x = a.x() + s * (b.x() - a.x()), y = a.y() + s * (b.y() - a.y());
    for (int dx = -3; dx <= 3; ++dx) {
      double px = x;
      for (int k = 0; k < std::abs(dx); ++k)
        px = std::nextafter(px, dx > 0 ? HUGE_VAL : -HUGE_VAL);
      const K::Point_2 p(px, y);
      const auto found = locator.locate(p);
      const auto exact = exact_locator.locate(Exact_kernel::Point_2(px, y));
      ASSERT_EQ(found.has_value(), exact.has_value()) << p;
      if (!found)
        continue;
      EXPECT_EQ(found->face, exact->face) << p;
      // exactly on an edge: a zero coordinate (off it, the rounded area may be zero too)
      for (std::size_t i = 0; i < 3; ++i) {
        if (CGAL::is_zero(exact->barycentric[i])) {
          EXPECT_EQ(found->barycentric[i], 0.0) << p;
        }
      }
      on_line +=
          CGAL::is_zero(exact->barycentric[0] * exact->barycentric[1] * exact->barycentric[2]) ? 1
                                                                                               : 0;
      ++decided;
    }
  }
  EXPECT_GT(decided, 2000u);
  EXPECT_GT(on_line, 10u); // some of the points are exactly on their edge
}

TEST(Evaluate, NetsKeptFromQueryToQueryFollowTheValues) {
  // Sorted queries reuse the net of the previous query's face within a call; a later call
  // sees the spline's new values, and another spline's on the same domain.
  using K = Epick;
  TS::C1_quintic_spline<K> spline = smooth_spline(37);
  TS::C1_quintic_spline<K> other = spline;
  for (const auto s : other.free_slots())
    other.set_free_value(s, 2 * other.value(s) + 1);
  other.propagate();
  const Domain_locator<K> locator(spline.domain());
  std::mt19937_64 engine(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Point_2> queries;
  for (int i = 0; i < 40000; ++i)
    queries.emplace_back(u(engine), u(engine));
  CGAL::hilbert_sort(queries.begin(), queries.end());
  auto via_patches = [&](const TS::C1_quintic_spline<K>& s) {
    std::vector<Bezier_triangle<K>> patches;
    for (Index f = 0; f < s.domain().number_of_faces(); ++f)
      patches.push_back(s.patch(f));
    return TS::evaluate_functional(TS::Patch_network<K>(s.domain(), patches), locator, queries);
  };
  auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i]))))
        return false;
    return a.size() == b.size();
  };
  const std::vector<double> first = via_patches(spline), second = via_patches(other);
  EXPECT_FALSE(same(first, second));
  for (int round = 0; round < 2; ++round) {
    EXPECT_TRUE(same(TS::evaluate_functional(spline, locator, queries), first));
    EXPECT_TRUE(same(TS::evaluate_functional(other, locator, queries), second));
  }
  // one query at a time, on this thread: its face's net, kept from the call before, is the
  // other spline's
  for (std::size_t q = 0; q < queries.size(); q += 97) {
    const std::vector<K::Point_2> one{queries[q]};
    const double a = TS::evaluate_functional(spline, locator, one)[0];
    const double b = TS::evaluate_functional(other, locator, one)[0];
    EXPECT_TRUE(a == first[q] || (std::isnan(a) && std::isnan(first[q])));
    EXPECT_TRUE(b == second[q] || (std::isnan(b) && std::isnan(second[q])));
    const auto jet = TS::evaluate_jets(spline, locator, one, TS::Outside::NO_VALUE, 0)[0];
    EXPECT_TRUE(jet ? jet->value == first[q] : std::isnan(first[q]));
  }
  // the jets' nets too
  const auto jets = TS::evaluate_jets(other, locator, queries, TS::Outside::NO_VALUE, 0);
  for (std::size_t q = 0; q < queries.size(); ++q)
    EXPECT_TRUE(jets[q] ? jets[q]->value == second[q] : std::isnan(second[q]));
  for (const auto s : spline.free_slots())
    spline.set_free_value(s, other.value(s));
  spline.propagate();
  EXPECT_TRUE(same(TS::evaluate_functional(spline, locator, queries), second));
}

TEST(Evaluate, FixedDegreeDeCasteljauIsTheStepsBitForBit) {
  std::mt19937_64 engine(13);
  std::uniform_real_distribution<double> u(-3, 3), w(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    TS::internal::Scratch_net<double> net;
    for (int k = 0; k < 21; ++k)
      net.push_back(u(engine));
    std::array<double, 3> b{{w(engine), w(engine), 0}};
    if (trial % 4 == 1)
      b = {{1, 0, 0}};
    if (trial % 4 == 2)
      b[1] = 1 - b[0]; // on an edge
    b[2] = 1 - b[0] - b[1];
    const double value = TS::internal::de_casteljau_value<5>(net.data(), b);
    for (int n = 5; n > 0; --n)
      TS::internal::de_casteljau_step(net, n, b);
    ASSERT_EQ(net.size(), 1u);
    EXPECT_EQ(std::memcmp(&value, &net[0], sizeof value), 0) << trial;
  }
}

TYPED_TEST(Output, QueriesOnHullEdgesUpToRoundingGetAValue) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  constexpr bool exact = is_exact<K>;
  Delaunay<K> dt;
  Random_rationals random(47);
  const Polynomial_surface<K> polynomial = random.polynomial<K>(5);
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    SCOPED_TRACE(name);
    const Domain_locator<K> locator(domain);
    const auto patches = patches_of(domain, polynomial, false);
    int strictly_outside = 0;
    for (Index e = 0; e < domain.number_of_edges(); ++e) {
      if (!domain.is_boundary_edge(e))
        continue;
      // 1e-12 of the edge length outside: snapped to the edge, valued as on the edge
      const auto [near, on] = point_outside_edge(domain, e, FT(1) / (FT(1000000) * FT(1000000)));
      if (!locator.locate(near))
        ++strictly_outside;
      const auto location = locator.locate_snapped(near);
      ASSERT_TRUE(location.has_value()) << near;
      const double values =
          TS::evaluate_functional(network(domain, patches), locator, std::vector<Point_2>{near})
              .front();
      const double expected = CGAL::to_double(polynomial.evaluate(on));
      EXPECT_NEAR(values, expected, 1e-9 * (std::max)(1.0, std::abs(expected)));
      const auto jet = TS::evaluate_jet(network(domain, patches), locator, near);
      ASSERT_TRUE(jet.has_value());
      // the projection of `near` onto the edge is `on`, exactly in exact arithmetic
      EXPECT_TRUE(same_jet(*jet, polynomial_jet(polynomial, on), exact, 1e3));
      // 1e-7 of the edge length is beyond the tolerance: still outside
      const Point_2 far = point_outside_edge(domain, e, FT(1) / FT(10000000)).first;
      EXPECT_FALSE(locator.locate_snapped(far).has_value()) << far;
      EXPECT_TRUE(std::isnan(
          TS::evaluate_functional(network(domain, patches), locator, std::vector<Point_2>{far})
              .front()));
    }
    if (exact) {
      EXPECT_GT(strictly_outside, 0); // the snapping did the work
    }
  }
  if constexpr (!exact) {
    // Points of a slanted hull edge computed in double: some round outside, none is lost.
    const Planar_domain<K> domain({Point_2(0, 0), Point_2(1, 0), Point_2(0.1, 0.7)}, {{{0, 1, 2}}});
    const Domain_locator<K> locator(domain);
    int rounded_outside = 0;
    for (int i = 0; i <= 1000; ++i) {
      const double t = i / 1000.0;
      const Point_2 p((1 - t) * 1 + t * 0.1, t * 0.7);
      rounded_outside += locator.locate(p) ? 0 : 1;
      EXPECT_TRUE(locator.locate_snapped(p).has_value()) << p;
    }
    EXPECT_GT(rounded_outside, 0);
  }
}

TYPED_TEST(Output, OutsideModesUseTheNearestBoundaryPoint) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  constexpr bool exact = is_exact<K>;
  Random_rationals random(53);
  const Polynomial_surface<K> polynomial = random.polynomial<K>(4);
  const Planar_domain<K> ring = ring_domain<K>(); // [0,3]^2 minus the open (1,2)^2
  const Domain_locator<K> locator(ring);
  const auto patches = patches_of(ring, polynomial, false);
  const FT half = FT(1) / FT(2);
  // query -> nearest boundary point: beside an edge, beyond a corner, inside the hole
  const std::vector<std::pair<Point_2, Point_2>> cases{
      {Point_2(5, half), Point_2(3, half)},
      {Point_2(-1, -2), Point_2(0, 0)},
      {Point_2(FT(3) / FT(2), FT(7) / FT(5)), Point_2(FT(3) / FT(2), 1)},
      {Point_2(FT(1000), FT(-3000)), Point_2(3, 0)}};
  for (const auto& [p, q] : cases) {
    SCOPED_TRACE(::testing::Message() << p);
    EXPECT_FALSE(TS::evaluate_jet(network(ring, patches), locator, p).has_value());
    const auto nearest = locator.nearest_boundary_point(p);
    ASSERT_TRUE(nearest.has_value());
    EXPECT_EQ(nearest->point, q);
    const TS::Point_jet<FT> at_q = polynomial_jet(polynomial, q);
    const auto n = TS::evaluate_jet(network(ring, patches), locator, p, TS::Outside::NEAREST);
    ASSERT_TRUE(n.has_value());
    EXPECT_TRUE(same_jet(*n, at_q, exact, 1e3));
    const auto l = TS::evaluate_jet(network(ring, patches), locator, p, TS::Outside::LINEAR);
    ASSERT_TRUE(l.has_value());
    TS::Point_jet<FT> linear = at_q;
    const FT extrapolated =
        at_q.value + (p.x() - q.x()) * at_q.gradient[0] + (p.y() - q.y()) * at_q.gradient[1];
    linear.value = extrapolated;
    linear.hessian = {{FT(0), FT(0), FT(0)}};
    EXPECT_TRUE(same_jet(*l, linear, exact, 1e7));
    // values only: the extrapolation still uses the gradient
    const auto l0 =
        TS::evaluate_jets(network(ring, patches), locator, {p}, TS::Outside::LINEAR, 0).front();
    ASSERT_TRUE(l0.has_value());
    EXPECT_TRUE(same_value(l0->value, extrapolated, exact, 1e-8, 1e7));
    EXPECT_EQ(l0->gradient[0], FT(0));
  }
  // the ring search agrees with a scan of every boundary edge
  for (int trial = 0; trial < 300; ++trial) {
    const Point_2 p(random.rational<FT>(40, 7), random.rational<FT>(40, 7));
    FT best = -1;
    for (Index e = 0; e < ring.number_of_edges(); ++e)
      if (ring.is_boundary_edge(e)) {
        const typename K::Segment_2 s(ring.point(ring.edge(e)[0]), ring.point(ring.edge(e)[1]));
        const FT d2 = CGAL::squared_distance(p, s);
        if (best < FT(0) || d2 < best)
          best = d2;
      }
    const auto nearest = locator.nearest_boundary_point(p);
    ASSERT_TRUE(nearest.has_value());
    EXPECT_TRUE(same_value(nearest->squared_distance, best, exact, 1e-12, 1e3)) << p;
  }
}

// ---------------------------------------------------------------------------------------
// Tessellation
// ---------------------------------------------------------------------------------------

namespace {

std::size_t border_halfedges(const Mesh& mesh) {
  std::size_t count = 0;
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h))
      ++count;
  return count;
}

std::array<double, 3> face_normal(const Mesh& mesh, Mesh::Face_index f) {
  std::array<Epick::Point_3, 3> p;
  int i = 0;
  for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    p[i++] = mesh.point(v);
  const Epick::Vector_3 n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
  return {{n.x(), n.y(), n.z()}};
}

// Checks shared by all tessellations: counts, validity, border, orientation.
template <class K>
void check_mesh_structure(const Planar_domain<K>& domain, int levels, const Mesh& mesh,
                          const TS::Tessellation_statistics& statistics) {
  const std::size_t n = std::size_t(1) << levels;
  const std::size_t V = domain.number_of_vertices(), E = domain.number_of_edges(),
                    F = domain.number_of_faces();
  EXPECT_EQ(mesh.number_of_vertices(), V + E * (n - 1) + F * (n - 1) * (n - 2) / 2);
  EXPECT_EQ(mesh.number_of_faces(), F * n * n);
  EXPECT_EQ(statistics.vertices, mesh.number_of_vertices());
  EXPECT_EQ(statistics.faces, mesh.number_of_faces());
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(border_halfedges(mesh), domain.number_of_boundary_edges() * n);
  for (auto v : mesh.vertices())
    EXPECT_FALSE(mesh.is_isolated(v));
  // the first V mesh vertices are the domain vertices
  for (Index v = 0; v < V; ++v) {
    const Epick::Point_3& p = mesh.point(Mesh_vertex(v));
    EXPECT_EQ(p.x(), CGAL::to_double(domain.point(v).x()));
    EXPECT_EQ(p.y(), CGAL::to_double(domain.point(v).y()));
  }
}

} // namespace

TYPED_TEST(Output, TessellateFunctionalMatchesThePolynomial) {
  using K = TypeParam;
  using FT = typename K::FT;
  constexpr bool exact = is_exact<K>;
  Delaunay<K> dt;
  Random_rationals random(13);
  const Polynomial_surface<K> polynomial = random.polynomial<K>(5);
  const Polynomial_surface<K> fx = polynomial.derivative(1, 0), fy = polynomial.derivative(0, 1),
                              fxx = polynomial.derivative(2, 0), fxy = polynomial.derivative(1, 1),
                              fyy = polynomial.derivative(0, 2);
  for (const auto& [name, domain] : test_domains<K>(dt)) {
    const auto patches = patches_of(domain, polynomial);
    for (int levels = 0; levels <= (exact ? 2 : 3); ++levels) {
      SCOPED_TRACE(name + " level " + std::to_string(levels));
      Mesh mesh;
      const TS::Tessellation_statistics statistics =
          TS::tessellate(network(domain, patches), levels, mesh);
      check_mesh_structure(domain, levels, mesh, statistics);
      auto [normals, has_normals] = mesh.property_map<Mesh_vertex, Epick::Vector_3>("v:normal");
      auto [gaussian, has_gaussian] =
          mesh.property_map<Mesh_vertex, double>("v:gaussian_curvature");
      auto [mean, has_mean] = mesh.property_map<Mesh_vertex, double>("v:mean_curvature");
      ASSERT_TRUE(has_normals && has_gaussian && has_mean);
      const Domain_locator<K> locator(domain);
      for (auto v : mesh.vertices()) {
        const Epick::Point_3& p = mesh.point(v);
        // the mesh coordinates are exact dyadic rationals: evaluate exactly there
        const typename K::Point_2 xy(FT(p.x()), FT(p.y()));
        // (the Delaunay domain's rational vertices are rounded, possibly off the domain)
        if (name != "delaunay") {
          ASSERT_TRUE(locator.locate(xy).has_value()) << "vertex off the domain: " << p;
        }
        const FT z = polynomial.evaluate(xy);
        const double scale = (std::max)(1.0, std::abs(CGAL::to_double(z)));
        EXPECT_NEAR(p.z(), CGAL::to_double(z), 1e-9 * scale) << p;
        // analytic graph normal (-F_x, -F_y, 1) / |.|, and curvatures of a graph
        const double gx = CGAL::to_double(fx.evaluate(xy)), gy = CGAL::to_double(fy.evaluate(xy));
        const double hxx = CGAL::to_double(fxx.evaluate(xy)),
                     hxy = CGAL::to_double(fxy.evaluate(xy)),
                     hyy = CGAL::to_double(fyy.evaluate(xy));
        const double w = 1 + gx * gx + gy * gy, root = std::sqrt(w);
        const Epick::Vector_3& normal = normals[v];
        EXPECT_NEAR(normal.squared_length(), 1.0, 1e-12);
        EXPECT_NEAR(normal.x(), -gx / root, 1e-9);
        EXPECT_NEAR(normal.y(), -gy / root, 1e-9);
        EXPECT_NEAR(normal.z(), 1 / root, 1e-9);
        const double K_expected = (hxx * hyy - hxy * hxy) / (w * w);
        const double H_expected =
            ((1 + gy * gy) * hxx - 2 * gx * gy * hxy + (1 + gx * gx) * hyy) / (2 * w * root);
        // surface_curvature() forms EG - F^2 = 1 + |grad F|^2 from terms of size
        // |grad F|^4, which costs about w ulps: the tolerance grows with the slope
        const double relative = 1e-9 + 1e-14 * w;
        EXPECT_NEAR(gaussian[v], K_expected, relative * (std::max)(1.0, std::abs(K_expected)));
        EXPECT_NEAR(mean[v], H_expected, relative * (std::max)(1.0, std::abs(H_expected)));
      }
      // counter-clockwise domain triangles give upward faces
      for (auto f : mesh.faces())
        EXPECT_GT(face_normal(mesh, f)[2], 0.0);
    }
  }
}

TYPED_TEST(Output, TessellateParametricEnneper) {
  using K = TypeParam;
  using Vector_3 = typename K::Vector_3;
  const Polynomial_surface<K, Vector_3> enneper = TS::enneper_surface<K>();
  const Polynomial_surface<K, Vector_3> du = enneper.derivative(1, 0),
                                        dv = enneper.derivative(0, 1);
  const Planar_domain<K> domain = grid_domain<K>(is_exact<K> ? 2 : 4);
  const auto patches = patches_of(domain, enneper);
  const int levels = 2;
  Mesh mesh;
  const auto statistics = TS::tessellate(network(domain, patches), levels, mesh);
  // the first V vertices are at F(domain vertex), not at the domain vertex: check counts only
  const std::size_t n = 4;
  EXPECT_EQ(statistics.vertices, domain.number_of_vertices() + domain.number_of_edges() * (n - 1) +
                                     domain.number_of_faces() * (n - 1) * (n - 2) / 2);
  EXPECT_EQ(statistics.faces, domain.number_of_faces() * n * n);
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(border_halfedges(mesh), domain.number_of_boundary_edges() * n);
  auto normals = mesh.property_map<Mesh_vertex, Epick::Vector_3>("v:normal").first;
  // Enneper's surface is minimal: mean curvature zero
  auto mean = mesh.property_map<Mesh_vertex, double>("v:mean_curvature").first;
  // Recover each vertex's parameter from the numbering: domain vertices come first.
  for (Index v = 0; v < domain.number_of_vertices(); ++v) {
    const typename K::Point_2& uv = domain.point(v);
    const Vector_3 expected = enneper.evaluate(uv);
    const Epick::Point_3& p = mesh.point(Mesh_vertex(v));
    EXPECT_NEAR(p.x(), CGAL::to_double(expected.x()), 1e-12);
    EXPECT_NEAR(p.y(), CGAL::to_double(expected.y()), 1e-12);
    EXPECT_NEAR(p.z(), CGAL::to_double(expected.z()), 1e-12);
    const Vector_3 n_exact = CGAL::cross_product(du.evaluate(uv), dv.evaluate(uv));
    const double length = std::sqrt(CGAL::to_double(n_exact.squared_length()));
    const Epick::Vector_3& normal = normals[Mesh_vertex(v)];
    EXPECT_NEAR(normal.x(), CGAL::to_double(n_exact.x()) / length, 1e-9);
    EXPECT_NEAR(normal.y(), CGAL::to_double(n_exact.y()) / length, 1e-9);
    EXPECT_NEAR(normal.z(), CGAL::to_double(n_exact.z()) / length, 1e-9);
  }
  for (auto v : mesh.vertices()) {
    EXPECT_NEAR(normals[v].squared_length(), 1.0, 1e-12);
    EXPECT_NEAR(mean[v], 0.0, 1e-9);
  }
  // faces agree with the normals (Enneper is regular and embedded on [-1, 1]^2)
  for (auto f : mesh.faces()) {
    const auto nf = face_normal(mesh, f);
    const auto v = mesh.target(mesh.halfedge(f));
    EXPECT_GT(nf[0] * normals[v].x() + nf[1] * normals[v].y() + nf[2] * normals[v].z(), 0.0);
  }
}

TYPED_TEST(Output, TessellateAgreesWithSurfaceCurvatureForAnyDegree) {
  // One triangle, patch vertices in another order; degrees 0..6 exercise every branch of
  // the shared-pyramid derivatives, which must agree with surface_curvature().
  using K = TypeParam;
  using FT = typename K::FT;
  using Vector_3 = typename K::Vector_3;
  using Point_2 = typename K::Point_2;
  const std::vector<Point_2> corners{Point_2(FT(-1) / FT(2), 0), Point_2(2, FT(1) / FT(4)),
                                     Point_2(FT(1) / FT(8), FT(3) / FT(2))};
  const Planar_domain<K> domain(corners, {{{0, 1, 2}}});
  Random_rationals random(31);
  const int levels = is_exact<K> ? 2 : 3;
  auto near = [](double a, double b, double tolerance) {
    return std::abs(a - b) <= tolerance * (std::max)(1.0, std::abs(b));
  };
  for (int degree = 0; degree <= 6; ++degree) {
    SCOPED_TRACE("degree " + std::to_string(degree));
    const std::vector<Bezier_triangle<K>> functional{
        random.polynomial<K>(degree).to_bezier(degree, corners[2], corners[0], corners[1])};
    const std::vector<Bezier_triangle<K, Vector_3>> parametric{
        random.polynomial<K, Vector_3>(degree).to_bezier(degree, corners[1], corners[0],
                                                         corners[2])};
    for (int kind = 0; kind < 2; ++kind) {
      Mesh mesh;
      if (kind == 0)
        TS::tessellate(network(domain, functional), levels, mesh);
      else
        TS::tessellate(network(domain, parametric), levels, mesh);
      const auto normals = mesh.property_map<Mesh_vertex, Epick::Vector_3>("v:normal").first;
      const auto gaussian = mesh.property_map<Mesh_vertex, double>("v:gaussian_curvature").first;
      const auto mean = mesh.property_map<Mesh_vertex, double>("v:mean_curvature").first;
      // the grid points in the tessellation's numbering: corners, edges (lo -> hi), interior
      std::vector<Point_2> grid_points(domain.points());
      const std::size_t n = std::size_t(1) << levels;
      for (Index e = 0; e < domain.number_of_edges(); ++e)
        for (std::size_t t = 1; t < n; ++t) {
          const Point_2& a = domain.point(domain.edge(e)[0]);
          const Point_2& b = domain.point(domain.edge(e)[1]);
          const FT s = FT(static_cast<int>(t)) / FT(static_cast<int>(n));
          const FT x = a.x() + s * (b.x() - a.x()), y = a.y() + s * (b.y() - a.y());
          grid_points.emplace_back(x, y);
        }
      const auto& face = domain.face(0);
      for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = 1; i + j < n; ++j) {
          const FT wi = FT(static_cast<int>(i)) / FT(static_cast<int>(n));
          const FT wj = FT(static_cast<int>(j)) / FT(static_cast<int>(n));
          const FT wk = FT(1) - wi - wj;
          const FT x = wi * domain.point(face[0]).x() + wj * domain.point(face[1]).x() +
                       wk * domain.point(face[2]).x();
          const FT y = wi * domain.point(face[0]).y() + wj * domain.point(face[1]).y() +
                       wk * domain.point(face[2]).y();
          grid_points.emplace_back(x, y);
        }
      ASSERT_EQ(grid_points.size(), mesh.number_of_vertices());
      for (std::size_t v = 0; v < grid_points.size(); ++v) {
        const Mesh_vertex mv(static_cast<Mesh::size_type>(v));
        const Point_2& p = grid_points[v];
        const TS::Surface_curvature expected = kind == 0 ? TS::surface_curvature(functional[0], p)
                                                         : TS::surface_curvature(parametric[0], p);
        const Epick::Point_3& position = mesh.point(mv);
        if (kind == 0) {
          EXPECT_EQ(position.x(), CGAL::to_double(p.x()));
          EXPECT_EQ(position.y(), CGAL::to_double(p.y()));
          EXPECT_TRUE(near(position.z(), CGAL::to_double(functional[0].evaluate(p)), 1e-12));
        } else {
          const Vector_3 value = parametric[0].evaluate(p);
          EXPECT_TRUE(near(position.x(), CGAL::to_double(value.x()), 1e-12));
          EXPECT_TRUE(near(position.y(), CGAL::to_double(value.y()), 1e-12));
          EXPECT_TRUE(near(position.z(), CGAL::to_double(value.z()), 1e-12));
        }
        if (!expected.regular) { // degree 0 parametric: a point, no normal
          EXPECT_EQ(normals[mv], Epick::Vector_3(0, 0, 0));
          EXPECT_TRUE(std::isnan(gaussian[mv]) && std::isnan(mean[mv]));
          continue;
        }
        EXPECT_NEAR(normals[mv].x(), expected.normal[0], 1e-12);
        EXPECT_NEAR(normals[mv].y(), expected.normal[1], 1e-12);
        EXPECT_NEAR(normals[mv].z(), expected.normal[2], 1e-12);
        EXPECT_TRUE(near(gaussian[mv], expected.gaussian, 1e-9))
            << gaussian[mv] << " vs " << expected.gaussian;
        EXPECT_TRUE(near(mean[mv], expected.mean, 1e-9)) << mean[mv] << " vs " << expected.mean;
        if (degree <= 1) {
          EXPECT_EQ(gaussian[mv], 0.0);
          EXPECT_EQ(mean[mv], 0.0);
        }
      }
    }
  }
}

TYPED_TEST(Output, TessellateRejectsBadLevels) {
  using K = TypeParam;
  const Planar_domain<K> domain = grid_domain<K>(1);
  Random_rationals random(1);
  const auto patches = patches_of(domain, random.polynomial<K>(5));
  Mesh mesh;
  EXPECT_THROW(TS::tessellate(network(domain, patches), -1, mesh), TS::Invalid_input);
  EXPECT_THROW(TS::tessellate(network(domain, patches), 11, mesh), TS::Invalid_input);
  // level 0 gives the domain triangles themselves
  TS::tessellate(network(domain, patches), 0, mesh);
  EXPECT_EQ(mesh.number_of_faces(), domain.number_of_faces());
  EXPECT_EQ(mesh.number_of_vertices(), domain.number_of_vertices());
}

TEST(Tessellate, ReplacesThePreviousMeshContent) {
  const Planar_domain<Epick> domain = grid_domain<Epick>(2);
  Random_rationals random(2);
  const auto patches = patches_of(domain, random.polynomial<Epick>(5));
  Mesh mesh;
  TS::tessellate(network(domain, patches), 2, mesh);
  const auto statistics = TS::tessellate(network(domain, patches), 1, mesh);
  EXPECT_EQ(mesh.number_of_faces(), domain.number_of_faces() * 4);
  EXPECT_EQ(statistics.faces, mesh.number_of_faces());
  EXPECT_TRUE(mesh.is_valid(false));
}

// ---------------------------------------------------------------------------------------
// Writing meshes
// ---------------------------------------------------------------------------------------

namespace {

class Temporary_directory {
public:
  Temporary_directory() {
    m_path = std::filesystem::temp_directory_path() /
             ("ts_test_output_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(m_path);
  }
  ~Temporary_directory() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  std::string file(const std::string& name) const { return (m_path / name).string(); }

private:
  std::filesystem::path m_path;
};

Mesh sample_mesh() {
  const Planar_domain<Epick> domain = ring_domain<Epick>();
  Random_rationals random(4);
  const auto patches = patches_of(domain, random.polynomial<Epick>(5));
  Mesh mesh;
  TS::tessellate(network(domain, patches), 2, mesh);
  return mesh;
}

} // namespace

TEST(WriteMesh, EachFormatReadsBack) {
  const Mesh mesh = sample_mesh();
  const auto normals = mesh.property_map<Mesh_vertex, Epick::Vector_3>("v:normal").first;
  Temporary_directory directory;
  for (const std::string name : {"mesh.ply", "mesh.off", "mesh.obj", "MESH.PLY", "a.b/mesh.Off"}) {
    SCOPED_TRACE(name);
    const std::string path = directory.file(name);
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    TS::write_mesh(path, mesh);
    Mesh back;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, back));
    EXPECT_EQ(back.number_of_vertices(), mesh.number_of_vertices());
    EXPECT_EQ(back.number_of_faces(), mesh.number_of_faces());
    EXPECT_TRUE(back.is_valid(false));
    // binary PLY and 17-digit ASCII keep every double
    for (auto v : mesh.vertices())
      EXPECT_EQ(back.point(v), mesh.point(v));
  }
  {
    // the PLY file carries the normals and the curvatures (Surface_mesh's own reader)
    std::ifstream in(directory.file("mesh.ply"), std::ios::binary);
    CGAL::IO::set_mode(in, CGAL::IO::BINARY);
    Mesh back;
    ASSERT_TRUE(CGAL::IO::read_PLY(in, back));
    auto [back_normals, found] = back.property_map<Mesh_vertex, Epick::Vector_3>("v:normal");
    ASSERT_TRUE(found);
    auto [back_mean, found_mean] = back.property_map<Mesh_vertex, double>("v:mean_curvature");
    EXPECT_TRUE(found_mean);
    const auto mean = mesh.property_map<Mesh_vertex, double>("v:mean_curvature").first;
    for (auto v : mesh.vertices()) {
      EXPECT_EQ(back_normals[v], normals[v]);
      if (found_mean) {
        EXPECT_EQ(back_mean[v], mean[v]);
      }
    }
  }
  {
    // OFF is written as NOFF, OBJ with one vn line per vertex
    std::ifstream off(directory.file("mesh.off"));
    std::string header;
    off >> header;
    EXPECT_EQ(header, "NOFF");
    std::ifstream obj(directory.file("mesh.obj"));
    std::size_t vn = 0;
    for (std::string line; std::getline(obj, line);)
      if (line.rfind("vn ", 0) == 0)
        ++vn;
    EXPECT_EQ(vn, mesh.number_of_vertices());
  }
}

TEST(WriteMesh, RejectsUnknownExtensionsAndUnwritablePaths) {
  const Mesh mesh = sample_mesh();
  Temporary_directory directory;
  for (const std::string name : {"mesh.stl", "mesh", "mesh.", "dir.ply/mesh", "mesh.xyz"})
    EXPECT_THROW(TS::write_mesh(directory.file(name), mesh), TS::Invalid_input) << name;
  const std::string missing = directory.file("no/such/directory/mesh.ply");
  try {
    TS::write_mesh(missing, mesh);
    FAIL() << "writing into a missing directory succeeded";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(missing), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(directory.file("mesh.stl")));
}

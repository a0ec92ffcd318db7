// Tests of the Bézier-triangle core: multi-indices and roles, blossom, de Casteljau,
// derivatives, subdivision, degree elevation, re-expression, curvature, bad input.
// Templated bodies run on a double kernel (Epick) and an exact one (Exact_rational).

#include "test_support.h"

#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/differential_geometry.h>

#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace ts_test;
using TS::Bezier_triangle;
using TS::Control_point_role;
using TS::Multi_index;
using TS::Polynomial_surface;

// ---------------------------------------------------------------------------------------
// Multi-indices
// ---------------------------------------------------------------------------------------

TEST(MultiIndex, EnumerationFollowsXuTable23) {
  const std::vector<Multi_index> all = TS::multi_indices(5);
  ASSERT_EQ(all.size(), 21u);
  // Bottom row of Table 2.3 first (005 014 ... 050), apex 500 last.
  EXPECT_EQ(all.front(), (Multi_index{0, 0, 5}));
  EXPECT_EQ(all[1], (Multi_index{0, 1, 4}));
  EXPECT_EQ(all[5], (Multi_index{0, 5, 0}));
  EXPECT_EQ(all[6], (Multi_index{1, 0, 4}));
  EXPECT_EQ(all.back(), (Multi_index{5, 0, 0}));
  for (int m = 0; m <= 12; ++m) {
    const std::vector<Multi_index> net = TS::multi_indices(m);
    ASSERT_EQ(net.size(), TS::number_of_control_points(m));
    for (std::size_t p = 0; p < net.size(); ++p) {
      EXPECT_EQ(net[p].degree(), m);
      EXPECT_EQ(TS::linear_index(net[p]), p);
      EXPECT_EQ(TS::multi_index(p, m), net[p]);
    }
  }
}

// linear_index() checks its documented precondition (a programming error: CGAL's failure);
// a degree or a position out of range is a bad argument (Invalid_input).
TEST(MultiIndex, ContractsAreChecked) {
  EXPECT_EQ(TS::linear_index(3, 0, 3), 9u);
  EXPECT_THROW(TS::linear_index(-1, 0, 3), CGAL::Failure_exception);
  EXPECT_THROW(TS::linear_index(0, -1, 3), CGAL::Failure_exception);
  EXPECT_THROW(TS::linear_index(2, 2, 3), CGAL::Failure_exception);
  EXPECT_THROW(TS::linear_index(Multi_index{1, 1, -1}), CGAL::Failure_exception);
  EXPECT_THROW(TS::number_of_control_points(-1), TS::Invalid_input);
  EXPECT_THROW(TS::multi_index(10, 3), TS::Invalid_input);
}

TEST(MultiIndex, QuinticRolesMatchSpec) {
  auto role = [](int i, int j, int k) { return TS::role(Multi_index{i, j, k}); };
  EXPECT_EQ(role(5, 0, 0), Control_point_role::CORNER);
  EXPECT_EQ(role(0, 0, 5), Control_point_role::CORNER);
  EXPECT_EQ(role(4, 1, 0), Control_point_role::STAR);
  EXPECT_EQ(role(4, 0, 1), Control_point_role::STAR);
  EXPECT_EQ(role(0, 1, 4), Control_point_role::STAR);
  EXPECT_EQ(role(3, 2, 0), Control_point_role::EDGE_MIDDLE);
  EXPECT_EQ(role(2, 3, 0), Control_point_role::EDGE_MIDDLE);
  EXPECT_EQ(role(0, 2, 3), Control_point_role::EDGE_MIDDLE);
  EXPECT_EQ(role(3, 1, 1), Control_point_role::CORNER_INNER);
  EXPECT_EQ(role(1, 3, 1), Control_point_role::CORNER_INNER);
  EXPECT_EQ(role(1, 1, 3), Control_point_role::CORNER_INNER);
  EXPECT_EQ(role(2, 2, 1), Control_point_role::MIDDLE_INNER);
  EXPECT_EQ(role(2, 1, 2), Control_point_role::MIDDLE_INNER);
  EXPECT_EQ(role(1, 2, 2), Control_point_role::MIDDLE_INNER);

  // Counts per role in a quintic: 3 corners, 6 stars, 6 edge-middle, 3 + 3 inner.
  std::map<Control_point_role, int> count;
  for (const Multi_index& index : TS::multi_indices(5))
    ++count[TS::role(index)];
  EXPECT_EQ(count[Control_point_role::CORNER], 3);
  EXPECT_EQ(count[Control_point_role::STAR], 6);
  EXPECT_EQ(count[Control_point_role::EDGE_MIDDLE], 6);
  EXPECT_EQ(count[Control_point_role::CORNER_INNER], 3);
  EXPECT_EQ(count[Control_point_role::MIDDLE_INNER], 3);
  EXPECT_EQ(count[Control_point_role::DEEP_INTERIOR], 0);

  // Owners: the star (4,1,0) belongs to vertex 0; the flip point (2,2,1) to the edge
  // opposite vertex 2.
  EXPECT_EQ(TS::owning_vertex(Multi_index{4, 1, 0}), 0);
  EXPECT_EQ(TS::owning_vertex(Multi_index{1, 3, 1}), 1);
  EXPECT_EQ(TS::owning_edge(Multi_index{2, 2, 1}), 2);
  EXPECT_EQ(TS::owning_edge(Multi_index{0, 3, 2}), 0);
  EXPECT_EQ(TS::owning_edge(Multi_index{4, 1, 0}), -1);
}

TEST(MultiIndex, RolesGeneraliseToOtherDegrees) {
  // m = 2: edge midpoints touch corners -> stars; m = 3: the centre is corner-inner.
  EXPECT_EQ(TS::role(Multi_index{1, 1, 0}), Control_point_role::STAR);
  EXPECT_EQ(TS::role(Multi_index{1, 1, 1}), Control_point_role::CORNER_INNER);
  // m = 7: (2,2,3) is farther than one row from every edge.
  EXPECT_EQ(TS::role(Multi_index{2, 2, 3}), Control_point_role::DEEP_INTERIOR);
  EXPECT_EQ(TS::role(Multi_index{5, 1, 1}), Control_point_role::CORNER_INNER);
  EXPECT_EQ(TS::role(Multi_index{3, 3, 1}), Control_point_role::MIDDLE_INNER);
  // Every index of every degree has exactly one role and names are distinct.
  EXPECT_EQ(TS::role_name(Control_point_role::MIDDLE_INNER), "middle-inner");
  EXPECT_THROW(TS::multi_index(21, 5), TS::Invalid_input);
  EXPECT_THROW(TS::number_of_control_points(-1), TS::Invalid_input);
}

// ---------------------------------------------------------------------------------------
// Paper check: Enneper's surface, Xu Table 2.2
// ---------------------------------------------------------------------------------------

TEST(Enneper, ControlPointsAreXuTable22) {
  using K = Exact_kernel;
  using FT = K::FT;
  using V = K::Vector_3;
  const FT third = FT(1) / FT(3);
  // Frame: r = (1,0), s = (0,1), t = (0,0) in the (u,v) plane.
  // F(u,v) = (u - u^3/3 + u v^2, v - v^3/3 + u^2 v, u^2 - v^2) (Xu §2.7.1).
  const auto net =
      TS::enneper_surface<K>().to_bezier(3, K::Point_2(1, 0), K::Point_2(0, 1), K::Point_2(0, 0));
  const FT t2 = 2 * third;
  struct Row {
    int i, j, k;
    V expected;
  };
  const std::vector<Row> table = {{3, 0, 0, V(t2, 0, 1)},        {2, 0, 1, V(t2, 0, third)},
                                  {2, 1, 0, V(t2, t2, third)},   {1, 0, 2, V(third, 0, 0)},
                                  {1, 1, 1, V(third, third, 0)}, {1, 2, 0, V(t2, t2, -third)},
                                  {0, 0, 3, V(0, 0, 0)},         {0, 1, 2, V(0, third, 0)},
                                  {0, 2, 1, V(0, t2, -third)},   {0, 3, 0, V(0, t2, -1)}};
  ASSERT_EQ(net.control_points().size(), 10u);
  for (const Row& row : table)
    EXPECT_EQ(net.control_point(row.i, row.j, row.k), row.expected)
        << "f(r^" << row.i << " s^" << row.j << " t^" << row.k << ")";
}

// ---------------------------------------------------------------------------------------
// Blossom, evaluation, subdivision (both kernels)
// ---------------------------------------------------------------------------------------

template <class K>
class BezierTriangleTest : public ::testing::Test {
protected:
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  using Vector_3 = typename K::Vector_3;
  static constexpr bool exact = is_exact<K>;
  Random_rationals random{20261122};

  // A random quintic (functional) over a random triangle, with its polynomial.
  std::pair<Polynomial_surface<K>, Bezier_triangle<K>> random_patch(int degree = 5) {
    const Polynomial_surface<K> p = random.template polynomial<K>(degree);
    const auto t = random.template triangle<K>();
    return {p, p.to_bezier(degree, t[0], t[1], t[2])};
  }

  std::vector<Point_2> random_points(int n) {
    std::vector<Point_2> points;
    for (int i = 0; i < n; ++i)
      points.push_back(random.template point<K>());
    return points;
  }
};

TYPED_TEST_SUITE(BezierTriangleTest, Kernels, Kernel_names);

TYPED_TEST(BezierTriangleTest, BlossomIsSymmetricMultiaffineAndDiagonal) {
  using FT = typename TypeParam::FT;
  using Point_2 = typename TypeParam::Point_2;
  for (int trial = 0; trial < 5; ++trial) {
    const auto [polynomial, patch] = this->random_patch(5);
    const double scale = 1e3 * scale_of(patch);
    std::vector<Point_2> args = this->random_points(5);
    const auto value = patch.blossom(args);
    // Symmetric: every permutation gives the same value.
    std::sort(args.begin(), args.end());
    int permutations = 0;
    do {
      EXPECT_TRUE(same_value(patch.blossom(args), value, this->exact, 1e-9, scale));
      ++permutations;
    } while (std::next_permutation(args.begin(), args.end()) && permutations < 40);
    // Multi-affine in the first argument (any affine combination, also extrapolating).
    const Point_2 x = this->random.template point<TypeParam>();
    const FT alpha = this->random.template rational<FT>();
    const Point_2 mixed = CGAL::barycenter(args[0], alpha, x, FT(1) - alpha);
    std::vector<Point_2> args_x = args, args_mixed = args;
    args_x[0] = x;
    args_mixed[0] = mixed;
    // Explicit FT: with gmpxx, `auto` would keep an expression of dangling temporaries.
    const FT expected = alpha * patch.blossom(args) + (FT(1) - alpha) * patch.blossom(args_x);
    EXPECT_TRUE(same_value(patch.blossom(args_mixed), expected, this->exact, 1e-9, scale * 20));
    // Diagonal: f(a,...,a) = F(a) = the polynomial; and the blossom agrees with the
    // monomial polar form computed independently (Xu §2.7.2).
    const Point_2 a = this->random.template point<TypeParam>();
    EXPECT_TRUE(same_value(patch.blossom(std::vector<Point_2>(5, a)), patch.evaluate(a),
                           this->exact, 1e-9, scale));
    EXPECT_TRUE(same_value(patch.evaluate(a), polynomial.evaluate(a), this->exact, 1e-9, scale));
    EXPECT_TRUE(
        same_value(patch.blossom(args), polynomial.blossom(args), this->exact, 1e-9, scale));
  }
}

TYPED_TEST(BezierTriangleTest, DeCasteljauEqualsBernsteinSum) {
  for (int degree : {0, 1, 2, 3, 5, 8}) {
    const auto [polynomial, patch] = this->random_patch(degree);
    const double scale = 1e3 * scale_of(patch);
    for (const auto& a : this->random_points(10))
      EXPECT_TRUE(
          same_value(patch.evaluate(a), patch.evaluate_bernstein(a), this->exact, 1e-9, scale))
          << "degree " << degree;
  }
}

TYPED_TEST(BezierTriangleTest, SubdivisionElevationAndReexpressionKeepThePolynomial) {
  using Point_2 = typename TypeParam::Point_2;
  for (int trial = 0; trial < 3; ++trial) {
    const auto [polynomial, patch] = this->random_patch(5);
    const double scale = 1e4 * scale_of(patch);
    const std::vector<Point_2> args = this->random_points(5);
    const auto reference = patch.blossom(args);

    // 3-split at an interior point (a random convex combination of the corners).
    const auto& v = patch.vertices();
    const Point_2 inside = CGAL::barycenter(v[0], 2, v[1], 3, v[2], 4);
    const auto pieces = patch.split(inside);
    for (const auto& piece : pieces)
      EXPECT_TRUE(same_value(piece.blossom(args), reference, this->exact, 1e-9, scale));
    EXPECT_EQ(pieces[0].vertex(0), inside);
    EXPECT_EQ(pieces[1].vertex(1), inside);
    EXPECT_EQ(pieces[2].vertex(2), inside);
    // The tetrahedron faces equal the independent re-expression (exact kernel only: the
    // two algorithms round differently).
    if (this->exact) {
      const auto direct = patch.reexpress(inside, v[1], v[2]);
      EXPECT_EQ(pieces[0].control_points(), direct.control_points());
    }

    // 4-split at the edge midpoints: four patches of the same polynomial, same orientation.
    const auto quarters = patch.subdivide();
    for (const auto& quarter : quarters) {
      EXPECT_TRUE(same_value(quarter.blossom(args), reference, this->exact, 1e-9, scale));
      EXPECT_EQ(CGAL::orientation(quarter.vertex(0), quarter.vertex(1), quarter.vertex(2)),
                CGAL::orientation(v[0], v[1], v[2]));
    }
    EXPECT_EQ(quarters[0].vertex(0), v[0]);
    EXPECT_EQ(quarters[1].vertex(1), v[1]);
    EXPECT_EQ(quarters[2].vertex(2), v[2]);

    // Degree elevation: same polynomial, now with a degree-6 blossom.
    const auto elevated = patch.elevate_degree();
    ASSERT_EQ(elevated.degree(), 6);
    std::vector<Point_2> args6 = args;
    args6.push_back(this->random.template point<TypeParam>());
    EXPECT_TRUE(same_value(elevated.blossom(args6), polynomial.blossom(args6), this->exact, 1e-9,
                           scale * 10));
    for (const auto& a : this->random_points(5))
      EXPECT_TRUE(same_value(elevated.evaluate(a), patch.evaluate(a), this->exact, 1e-9, scale));

    // Re-expression over an unrelated triangle (need not overlap the original).
    const auto other = this->random.template triangle<TypeParam>();
    const auto moved = patch.reexpress(other[0], other[1], other[2]);
    EXPECT_TRUE(same_value(moved.blossom(args), reference, this->exact, 1e-9, scale * 10));
    const auto back = moved.reexpress(v[0], v[1], v[2]);
    for (std::size_t c = 0; c < back.control_points().size(); ++c)
      EXPECT_TRUE(same_value(back.control_points()[c], patch.control_points()[c], this->exact, 1e-9,
                             scale * 100));
  }
}

TYPED_TEST(BezierTriangleTest, ParametricPatchesWorkCoordinatewise) {
  using K = TypeParam;
  using V = typename K::Vector_3;
  const auto p = this->random.template polynomial<K, V>(4);
  const auto t = this->random.template triangle<K>();
  const auto patch = p.to_bezier(5, t[0], t[1], t[2]);
  double scale = 1;
  for (const V& c : patch.control_points())
    scale = (std::max)(scale, TS::max_abs_coordinate(c));
  for (const auto& a : this->random_points(5)) {
    EXPECT_TRUE(same_value(patch.evaluate(a), p.evaluate(a), this->exact, 1e-9, 1e3 * scale));
    EXPECT_TRUE(same_value(patch.partial_derivative(a, 1, 2), p.derivative(1, 2).evaluate(a),
                           this->exact, 1e-9, 1e3 * scale));
  }
}

TYPED_TEST(BezierTriangleTest, DerivativesEqualThoseOfThePolynomial) {
  using FT = typename TypeParam::FT;
  using Vector_2 = typename TypeParam::Vector_2;
  const auto [polynomial, patch] = this->random_patch(5);
  const double scale = 1e5 * scale_of(patch);
  for (const auto& a : this->random_points(4)) {
    for (int p = 0; p <= 6; ++p)
      for (int q = 0; p + q <= 6; ++q)
        EXPECT_TRUE(same_value(patch.partial_derivative(a, p, q),
                               polynomial.derivative(p, q).evaluate(a), this->exact, 1e-9, scale))
            << "d^" << p + q << "/dx^" << p << "dy^" << q;
    // A directional derivative is the matching combination of partials.
    const Vector_2 u(FT(2), FT(-3));
    const FT expected = FT(2) * polynomial.derivative(1, 0).evaluate(a) -
                        FT(3) * polynomial.derivative(0, 1).evaluate(a);
    EXPECT_TRUE(
        same_value(patch.directional_derivative(a, {u}), expected, this->exact, 1e-9, scale));
  }
}

// ---------------------------------------------------------------------------------------
// Normals and curvature (double results from exact derivatives)
// ---------------------------------------------------------------------------------------

TYPED_TEST(BezierTriangleTest, ParaboloidCurvatureMatchesClosedForm) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  for (const auto& ab : std::vector<std::pair<int, int>>{{1, 2}, {1, -3}, {-2, -1}}) {
    // z = a x^2/2 + b y^2/2, written as a quintic over a triangle around the origin.
    const double a = ab.first, b = ab.second;
    Polynomial_surface<K> p(2);
    p.set_coefficient(2, 0, FT(ab.first) / FT(2));
    p.set_coefficient(0, 2, FT(ab.second) / FT(2));
    const auto patch = p.to_bezier(5, Point_2(-1, -1), Point_2(2, -1), Point_2(-1, 2));
    for (const auto& q : std::vector<std::pair<int, int>>{{0, 0}, {1, 2}, {-1, 3}, {3, -2}}) {
      const Point_2 at(FT(q.first) / FT(4), FT(q.second) / FT(4));
      const double x = CGAL::to_double(at.x()), y = CGAL::to_double(at.y());
      const double fx = a * x, fy = b * y, w2 = 1 + fx * fx + fy * fy;
      const double K_expected = a * b / (w2 * w2);
      const double H_expected = ((1 + fy * fy) * a + (1 + fx * fx) * b) / (2 * std::pow(w2, 1.5));
      const TS::Surface_curvature c = TS::surface_curvature(patch, at);
      // Only the final square root and a few products are rounded: 1e-12 relative.
      EXPECT_NEAR(c.gaussian, K_expected, 1e-12 * (1 + std::abs(K_expected)));
      EXPECT_NEAR(c.mean, H_expected, 1e-12 * (1 + std::abs(H_expected)));
      const double w = std::sqrt(w2);
      EXPECT_NEAR(c.normal[0], -fx / w, 1e-14);
      EXPECT_NEAR(c.normal[1], -fy / w, 1e-14);
      EXPECT_NEAR(c.normal[2], 1 / w, 1e-14);
      // The same surface as a parametric patch (x, y, z) has the same geometry.
      Polynomial_surface<K, typename K::Vector_3> graph(2);
      graph.set_coefficient(1, 0, typename K::Vector_3(1, 0, 0));
      graph.set_coefficient(0, 1, typename K::Vector_3(0, 1, 0));
      graph.set_coefficient(2, 0, typename K::Vector_3(0, 0, FT(ab.first) / FT(2)));
      graph.set_coefficient(0, 2, typename K::Vector_3(0, 0, FT(ab.second) / FT(2)));
      const auto parametric = graph.to_bezier(5, Point_2(-1, -1), Point_2(2, -1), Point_2(-1, 2));
      const TS::Surface_curvature cp = TS::surface_curvature(parametric, at);
      EXPECT_NEAR(cp.gaussian, K_expected, 1e-12 * (1 + std::abs(K_expected)));
      EXPECT_NEAR(cp.mean, H_expected, 1e-12 * (1 + std::abs(H_expected)));
      const auto n = TS::surface_normal(parametric, at);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(n[i], c.normal[i], 1e-14);
    }
  }
}

TYPED_TEST(BezierTriangleTest, SphereCapCurvatureAndFiniteDifferences) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  // Taylor polynomial of the cap z = sqrt(R^2 - x^2 - y^2), R = 2, to degree 4:
  // z = R - rho^2/(2R) - rho^4/(8R^3). Its curvature at the pole is the sphere's.
  const FT R(2);
  Polynomial_surface<K> cap(4);
  cap.set_coefficient(0, 0, R);
  cap.set_coefficient(2, 0, FT(-1) / (2 * R));
  cap.set_coefficient(0, 2, FT(-1) / (2 * R));
  const FT quartic = FT(-1) / (8 * R * R * R);
  cap.set_coefficient(4, 0, quartic);
  cap.set_coefficient(2, 2, 2 * quartic);
  cap.set_coefficient(0, 4, quartic);
  const auto patch = cap.to_bezier(5, Point_2(-1, -1), Point_2(1, -1), Point_2(0, 1));
  const TS::Surface_curvature pole = TS::surface_curvature(patch, Point_2(0, 0));
  EXPECT_NEAR(pole.gaussian, 0.25, 1e-14); // 1/R^2
  EXPECT_NEAR(pole.mean, -0.5, 1e-14);     // -1/R: the cap bends away from its upward normal
  EXPECT_GT(pole.normal[2], 0.999999);

  // Elsewhere, compare the exact derivatives with central differences of the evaluation.
  // Step 1e-3: truncation error ~ h^2/12 |f''''| ~ 1e-7 and rounding ~ eps/h^2 ~ 2e-10
  // for the second derivatives, so 1e-5 is a safe bound.
  const double h = 1e-3;
  auto F = [&](double x, double y) {
    return CGAL::to_double(patch.evaluate(Point_2(FT(x), FT(y))));
  };
  for (const auto& q : std::vector<std::pair<double, double>>{{0.1, 0.2}, {-0.3, 0.05}}) {
    const double x = q.first, y = q.second;
    const TS::Surface_derivatives d = TS::surface_derivatives(patch, Point_2(FT(x), FT(y)));
    EXPECT_NEAR(d.fx[2], (F(x + h, y) - F(x - h, y)) / (2 * h), 1e-5);
    EXPECT_NEAR(d.fy[2], (F(x, y + h) - F(x, y - h)) / (2 * h), 1e-5);
    EXPECT_NEAR(d.fxx[2], (F(x + h, y) - 2 * F(x, y) + F(x - h, y)) / (h * h), 1e-5);
    EXPECT_NEAR(d.fyy[2], (F(x, y + h) - 2 * F(x, y) + F(x, y - h)) / (h * h), 1e-5);
    EXPECT_NEAR(d.fxy[2],
                (F(x + h, y + h) - F(x + h, y - h) - F(x - h, y + h) + F(x - h, y - h)) /
                    (4 * h * h),
                1e-5);
    // Near the pole the Taylor cap is close to the sphere: K within 2% of 1/R^2.
    EXPECT_NEAR(TS::surface_curvature(patch, Point_2(FT(x), FT(y))).gaussian, 0.25, 0.005);
  }
}

TEST(Curvature, SingularPointIsReportedNotNaNSilently) {
  using K = Epick;
  // A parametric patch that collapses to a curve: F(x,y) = (x, 0, 0).
  Polynomial_surface<K, K::Vector_3> p(1);
  p.set_coefficient(1, 0, K::Vector_3(1, 0, 0));
  const auto patch = p.to_bezier(2, K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(0, 1));
  const TS::Surface_curvature c = TS::surface_curvature(patch, K::Point_2(0.2, 0.2));
  EXPECT_FALSE(c.regular);
  EXPECT_EQ(c.normal[0], 0);
  EXPECT_EQ(c.normal[2], 0);
}

// ---------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const TS::Invalid_input& e) {
    return e.what();
  }
  return "";
}

TYPED_TEST(BezierTriangleTest, BadInputIsRejectedWithAClearMessage) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  const std::vector<FT> quadratic(6, FT(1));
  // Collinear corners, decided exactly (1/3 is inexact in double, but the kernel's
  // predicate is exact on the stored values; use a triple that is collinear in both).
  EXPECT_NE(error_of([&] {
              Bezier_triangle<K>(2, Point_2(0, 0), Point_2(1, 1), Point_2(4, 4), quadratic);
            }).find("collinear"),
            std::string::npos);
  // Repeated corner.
  EXPECT_FALSE(error_of([&] {
                 Bezier_triangle<K>(2, Point_2(0, 0), Point_2(0, 0), Point_2(1, 0), quadratic);
               }).empty());
  // Wrong net size.
  EXPECT_NE(error_of([&] {
              Bezier_triangle<K>(3, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), quadratic);
            }).find("needs 10 control points, got 6"),
            std::string::npos);
  EXPECT_FALSE(error_of([&] {
                 Bezier_triangle<K>(-1, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), {});
               }).empty());
  const Bezier_triangle<K> ok(2, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), quadratic);
  EXPECT_FALSE(error_of([&] { ok.control_point(1, 1, 1); }).empty());
  EXPECT_FALSE(error_of([&] { ok.blossom({Point_2(0, 0)}); }).empty());
  EXPECT_FALSE(error_of([&] { ok.split(Point_2(FT(1) / FT(2), 0)); }).empty());
  EXPECT_FALSE(error_of([&] { ok.partial_derivative(Point_2(0, 0), -1, 0); }).empty());
  EXPECT_FALSE(
      error_of([&] { ok.reexpress(Point_2(0, 0), Point_2(1, 0), Point_2(2, 0)); }).empty());
  if constexpr (!is_exact<K>) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> with_nan = quadratic;
    with_nan[3] = nan;
    EXPECT_NE(error_of([&] {
                Bezier_triangle<K>(2, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), with_nan);
              }).find("non-finite"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                Bezier_triangle<K>(2, Point_2(0, 0), Point_2(inf, 0), Point_2(0, 1), quadratic);
              }).find("non-finite"),
              std::string::npos);
    // Huge but finite corners: the doubled area overflows, which must not pass silently.
    EXPECT_FALSE(error_of([&] {
                   Bezier_triangle<K>(2, Point_2(0, 0), Point_2(1e300, 0), Point_2(0, 1e300),
                                      quadratic);
                 }).empty());
    Bezier_triangle<K> editable = ok;
    EXPECT_FALSE(error_of([&] { editable.set_control_point(Multi_index{0, 0, 2}, nan); }).empty());
  }
}

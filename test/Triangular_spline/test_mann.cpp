// Tests of Mann's continuity adjustment (pairs and networks) and of his interpolant with
// polynomial precision: Continuity_adjustment.h and mann_interpolant.h.

#include "test_support.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Mann/Continuity_adjustment.h>
#include <CGAL/Triangular_spline/Patch_network.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>
#include <CGAL/Triangular_spline/Domain/domain_from_triangulation_2.h>

#include <cmath>
#include <string>

using namespace ts_test;
using TS::Bezier_triangle;
using TS::Join_conditions;
using TS::Multi_index;
using TS::Planar_domain;
using TS::Polynomial_surface;

namespace {

// Runs `f` and checks that it throws Invalid_input whose message contains `expected`.
template <class F>
::testing::AssertionResult throws_with(F f, const std::string& expected) {
  try {
    f();
  } catch (const TS::Invalid_input& e) {
    if (std::string(e.what()).find(expected) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "message \"" << e.what() << "\" lacks \"" << expected << "\"";
  }
  return ::testing::AssertionFailure()
         << "no Invalid_input thrown (expected \"" << expected << "\")";
}

template <class K, class Value>
bool identical(const std::vector<Bezier_triangle<K, Value>>& a,
               const std::vector<Bezier_triangle<K, Value>>& b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t f = 0; f < a.size(); ++f)
    if (a[f].control_points() != b[f].control_points())
      return false;
  return true;
}

// The C^k certificate of `patches` over `domain` (copied into a network).
template <class K, class Value>
TS::Continuity_certificate certify_patches(const Planar_domain<K>& domain,
                                           const std::vector<Bezier_triangle<K, Value>>& patches,
                                           int k, double tolerance = 0) {
  return TS::certify_continuity(TS::Patch_network<K, Value>(domain, patches), k,
                                TS::parameters::residual_tolerance(tolerance));
}

} // namespace

template <class K>
class MannTest : public ::testing::Test {
protected:
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  static constexpr bool exact = is_exact<K>;
  Random_rationals random{2024};

  struct Pair_of_triangles {
    Point_2 p, q, r, s; // A over (p, r, s), B over (q, r, s) up to the vertex order used
  };

  Pair_of_triangles adjacent_triangles() {
    for (;;) {
      Pair_of_triangles t{this->random.template point<K>(), this->random.template point<K>(),
                          this->random.template point<K>(), this->random.template point<K>()};
      if (t.r == t.s)
        continue;
      const auto op = CGAL::orientation(t.r, t.s, t.p), oq = CGAL::orientation(t.r, t.s, t.q);
      if (op != CGAL::COLLINEAR && oq != CGAL::COLLINEAR && op != oq)
        return t;
    }
  }

  // The linear function vanishing on the line rs.
  Polynomial_surface<K> edge_function(const Point_2& r, const Point_2& s) {
    Polynomial_surface<K> l(1);
    l.set_coefficient(1, 0, r.y() - s.y());
    l.set_coefficient(0, 1, s.x() - r.x());
    l.set_coefficient(0, 0, r.x() * s.y() - r.y() * s.x());
    return l;
  }

  // P + l^k Q: meets P along rs with C^(k-1) exactly, generically not C^k.
  Polynomial_surface<K> bumped(const Polynomial_surface<K>& P, const Pair_of_triangles& t, int k) {
    Polynomial_surface<K> bump = this->random.template polynomial<K>(P.degree() - k);
    for (int e = 0; e < k; ++e)
      bump = bump.multiplied_by(edge_function(t.r, t.s));
    return P + bump;
  }

  Bezier_triangle<K> random_patch(int n, const Point_2& a, const Point_2& b, const Point_2& c) {
    std::vector<FT> net;
    for (std::size_t i = 0; i < TS::number_of_control_points(n); ++i)
      net.push_back(this->random.template rational<FT>());
    return Bezier_triangle<K>(n, a, b, c, std::move(net));
  }

  Planar_domain<K> random_delaunay(int points) {
    CGAL::Delaunay_triangulation_2<K> dt;
    while (dt.number_of_vertices() < std::size_t(points))
      dt.insert(this->random.template point<K>());
    std::vector<typename CGAL::Delaunay_triangulation_2<K>::Vertex_handle> handles;
    return TS::domain_from_triangulation_2<K>(
        dt, [](auto) { return true; }, handles);
  }

  // One random patch per face, over the face's corners in a rotated order (the adjustment
  // must not rely on the patch listing the corners as the domain does).
  std::vector<Bezier_triangle<K>> random_network(const Planar_domain<K>& domain, int n) {
    std::vector<Bezier_triangle<K>> patches;
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
      const auto& t = domain.face(f);
      const int shift = int(f % 3);
      patches.push_back(random_patch(n, domain.point(t[(0 + shift) % 3]),
                                     domain.point(t[(1 + shift) % 3]),
                                     domain.point(t[(2 + shift) % 3])));
    }
    return patches;
  }

  // Absolute tolerance for double residuals of order-k conditions on these small random
  // triangles (coordinates up to 20 with denominators up to 7: aspect ratios up to ~1e3).
  double tolerance(double scale, int k) const { return 1e-11 * scale * std::pow(1e3, k); }
};

TYPED_TEST_SUITE(MannTest, Kernels, Kernel_names);

// ---------------------------------------------------------------------------------------
// Pairs

TYPED_TEST(MannTest, PairsCutFromOnePolynomialAreUnchanged) {
  using K = TypeParam;
  for (int k = 0; k <= 3; ++k)
    for (int n : {k + 1, 4 * k + 1, 4 * k + 3}) {
      const auto P = this->random.template polynomial<K>(n);
      const auto t = this->adjacent_triangles();
      const auto A = P.to_bezier(n, t.p, t.r, t.s);
      const auto B = P.to_bezier(n, t.r, t.q, t.s); // another vertex order
      auto A2 = A, B2 = B;
      const TS::Join_adjustment result = TS::adjust_join(A2, B2, k);
      EXPECT_EQ(result.order, k);
      if (this->exact) {
        // Bit for bit: no correction is computed as non-zero.
        EXPECT_FALSE(result.changed()) << "k=" << k << " n=" << n;
        EXPECT_EQ(A2.control_points(), A.control_points());
        EXPECT_EQ(B2.control_points(), B.control_points());
      } else {
        // Double: the Lai values differ by round-off only; so do the corrections.
        const double scale = scale_of(A);
        for (std::size_t c = 0; c < A.control_points().size(); ++c) {
          EXPECT_TRUE(same_value(A2.control_points()[c], A.control_points()[c], false,
                                 this->tolerance(scale, k)));
          EXPECT_TRUE(same_value(B2.control_points()[c], B.control_points()[c], false,
                                 this->tolerance(scale, k)));
        }
      }
    }
}

TYPED_TEST(MannTest, PairsMeetingCkMinus1AreRaisedToCk) {
  using K = TypeParam;
  using FT = typename K::FT;
  for (int k = 1; k <= 3; ++k)
    for (int n : {4 * k + 1, 4 * k + 2}) {
      const auto P = this->random.template polynomial<K>(n);
      const auto t = this->adjacent_triangles();
      const auto A = P.to_bezier(n, t.p, t.r, t.s);                     // apex p is local vertex 0
      const auto B = this->bumped(P, t, k).to_bezier(n, t.s, t.r, t.q); // apex q is vertex 2
      if constexpr (is_exact<K>) {
        ASSERT_TRUE(TS::check_join(A, B, k - 1).holds);
        ASSERT_FALSE(TS::check_join(A, B, k).holds);
      }
      auto A2 = A, B2 = B;
      const TS::Join_adjustment result = TS::adjust_join(A2, B2, k);
      EXPECT_TRUE(result.changed());
      EXPECT_LE(result.first_touched.size(), std::size_t(n - k + 1));
      EXPECT_LE(result.second_touched.size(), std::size_t(n - k + 1));
      for (const Multi_index& index : result.first_touched)
        EXPECT_EQ(index.i, k);
      for (const Multi_index& index : result.second_touched)
        EXPECT_EQ(index.k, k);
      // Only row k (k copies of the apex) may move; every other point is untouched.
      for (const Multi_index& index : TS::multi_indices(n)) {
        if (index.i != k) {
          EXPECT_TRUE(A2.control_point(index) == A.control_point(index));
        }
        if (index.k != k) {
          EXPECT_TRUE(B2.control_point(index) == B.control_point(index));
        }
      }
      if constexpr (is_exact<K>) {
        for (Join_conditions set :
             {Join_conditions::EXTENSION, Join_conditions::LAI, Join_conditions::COMPLETE})
          EXPECT_TRUE(TS::check_join(A2, B2, k, set).holds) << "k=" << k << " n=" << n;
        // Floater's view (Mann §2.5): the moved points are those of the average polynomial.
        for (int i = 0; i <= n - k; ++i) {
          std::vector<typename K::Point_2> args(std::size_t(k), t.p);
          args.insert(args.end(), std::size_t(i), t.r);
          args.insert(args.end(), std::size_t(n - k - i), t.s);
          const FT expected_a = (A.blossom(args) + B.blossom(args)) / FT(2);
          EXPECT_EQ(A2.control_point(k, i, n - k - i), expected_a);
          std::vector<typename K::Point_2> args_b(std::size_t(k), t.q);
          args_b.insert(args_b.end(), std::size_t(i), t.r);
          args_b.insert(args_b.end(), std::size_t(n - k - i), t.s);
          const FT expected_b = (A.blossom(args_b) + B.blossom(args_b)) / FT(2);
          EXPECT_EQ(B2.control_point(n - k - i, i, k), expected_b);
        }
      } else {
        const TS::Join_report report = TS::check_join(A2, B2, k, Join_conditions::LAI);
        for (const TS::Join_condition& c : report.conditions)
          EXPECT_LE(c.residual, this->tolerance(scale_of(A2), c.order)) << "k=" << k;
      }
    }
}

TYPED_TEST(MannTest, MatchesMannSection22ForC2) {
  // Mann §2.2, literally: average the extrapolated points F(D0 V0 V1^i V2^j) and
  // G(D0 V0 V1^i V2^j), then extrapolate back with (v0, v1, v2) and (d0, d1, d2).
  using K = TypeParam;
  using FT = typename K::FT;
  if (!this->exact)
    GTEST_SKIP() << "an identity between exact formulas";
  const int n = 6;
  const auto P = this->random.template polynomial<K>(n);
  const auto t = this->adjacent_triangles();
  const auto& V0 = t.p;
  const auto& D0 = t.q;
  const auto& V1 = t.r;
  const auto& V2 = t.s;
  const auto F = P.to_bezier(n, V0, V1, V2);
  const auto G = this->bumped(P, t, 2).to_bezier(n, D0, V1, V2);
  auto F2 = F, G2 = G;
  TS::adjust_join(F2, G2, 2);
  const auto d = F.barycentric_coordinates(D0); // D0 w.r.t. (V0, V1, V2)
  const auto v = G.barycentric_coordinates(V0); // V0 w.r.t. (D0, V1, V2)
  for (int i = 0; i <= n - 2; ++i) {
    const int j = n - 2 - i;
    auto at = [&](const typename K::Point_2& x, const typename K::Point_2& y) {
      std::vector<typename K::Point_2> args{x, y};
      args.insert(args.end(), std::size_t(i), V1);
      args.insert(args.end(), std::size_t(j), V2);
      return args;
    };
    const FT average = (F.blossom(at(D0, V0)) + G.blossom(at(D0, V0))) / FT(2);
    const FT f_bar = v[0] * average + v[1] * F.blossom(at(V1, V0)) + v[2] * F.blossom(at(V2, V0));
    const FT g_bar = d[0] * average + d[1] * G.blossom(at(V1, D0)) + d[2] * G.blossom(at(V2, D0));
    EXPECT_EQ(F2.control_point(2, i, j), f_bar);
    EXPECT_EQ(G2.control_point(2, i, j), g_bar);
  }
}

TYPED_TEST(MannTest, ArbitraryPairsAreRaisedOrderByOrder) {
  using K = TypeParam;
  const int n = 7;
  const auto t = this->adjacent_triangles();
  auto A = this->random_patch(n, t.p, t.r, t.s);
  auto B = this->random_patch(n, t.r, t.s, t.q);
  for (int l = 0; l <= 3; ++l) {
    TS::adjust_join(A, B, l);
    const TS::Join_report report = TS::check_join(A, B, l, Join_conditions::LAI);
    if (this->exact) {
      EXPECT_TRUE(report.holds) << "order " << l;
    } else {
      for (const TS::Join_condition& c : report.conditions)
        EXPECT_LE(c.residual, this->tolerance(scale_of(A), c.order));
    }
  }
  // C^0 step: the boundary points are the same value in both patches, also in double.
  auto C = this->random_patch(n, t.p, t.r, t.s);
  auto D = this->random_patch(n, t.r, t.s, t.q);
  const auto C0 = C, D0 = D;
  const TS::Join_adjustment result = TS::adjust_join(C, D, 0);
  EXPECT_EQ(result.first_touched.size(), std::size_t(n + 1));
  for (int i = 0; i <= n; ++i) {
    EXPECT_TRUE(C.control_point(0, i, n - i) == D.control_point(i, n - i, 0));
    using FT = typename K::FT;
    const FT average = (C0.control_point(0, i, n - i) + D0.control_point(i, n - i, 0)) / FT(2);
    EXPECT_TRUE(same_value(C.control_point(0, i, n - i), average, this->exact));
  }
}

TYPED_TEST(MannTest, BadPairsAreRejected) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  const auto P = this->random.template polynomial<K>(5);
  const auto A = P.to_bezier(5, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1));
  const auto B = P.to_bezier(5, Point_2(1, 1), Point_2(0, 1), Point_2(1, 0));
  auto a = A, b = B;
  EXPECT_TRUE(throws_with(
      [&] {
        auto e = b.elevate_degree();
        TS::adjust_join(a, e, 1);
      },
      "different degrees (5 and 6)"));
  const auto far = P.to_bezier(5, Point_2(1, 0), Point_2(2, 0), Point_2(2, 1));
  auto c = far;
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, c, 1); }, "share 1 vertices"));
  const auto overlapping =
      P.to_bezier(5, Point_2(1, 0), Point_2(0, 1), Point_2(FT(1) / 4, FT(1) / 4));
  auto o = overlapping;
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, o, 0); }, "overlap"));
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, b, 5); }, "continuity order 5 outside 0..4"));
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, b, -1); }, "outside"));
  // Not C^1: the C^2 adjustment is refused, and nothing is changed.
  auto bent = B;
  bent.set_control_point(Multi_index{1, 2, 2}, bent.control_point(1, 2, 2) + 1);
  auto bent_copy = bent;
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, bent, 2); },
                          "must meet C^1 before the C^2 adjustment, but they only meet C^0"));
  EXPECT_EQ(bent.control_points(), bent_copy.control_points());
  EXPECT_EQ(a.control_points(), A.control_points());
  // Not even C^0.
  auto moved = B;
  moved.set_control_point(Multi_index{0, 2, 3}, moved.control_point(0, 2, 3) + 1);
  EXPECT_TRUE(throws_with([&] { TS::adjust_join(a, moved, 1); }, "do not even meet C^0"));
}

// ---------------------------------------------------------------------------------------
// Networks

TYPED_TEST(MannTest, RandomNetworksBecomeCk) {
  for (int k : {1, 2}) {
    if (k == 2 && !this->exact)
      continue; // C^2 of random double nets: residuals are all round-off; covered exactly
    const auto domain = this->random_delaunay(k == 1 ? 14 : 8);
    const int n = 4 * k + 1;
    auto patches = this->random_network(domain, n);
    const TS::Network_adjustment report = TS::adjust_network(domain, patches, k);
    EXPECT_EQ(report.order, k);
    EXPECT_EQ(report.degree, n);
    EXPECT_EQ(report.edges.size(), domain.number_of_interior_edges());
    EXPECT_FALSE(report.vertices.empty()); // random corners: every vertex is projected
    if (this->exact) {
      const TS::Continuity_certificate certificate = certify_patches(domain, patches, k);
      EXPECT_TRUE(certificate.exact);
      EXPECT_TRUE(certificate.certified)
          << "k=" << k << ": " << certificate.failed_edges << " failed edges";
      EXPECT_EQ(certificate.lowest_order, k);
      if (k == 1) {
        EXPECT_TRUE(certify_patches(domain, patches, 1).certified);
      }
      // Idempotent: a C^k network is left alone, bit for bit.
      const auto before = patches;
      const TS::Network_adjustment again = TS::adjust_network(domain, patches, k);
      EXPECT_EQ(again.number_of_touched_points(), 0u);
      EXPECT_TRUE(identical(before, patches));
    } else {
      double scale = 1;
      for (const auto& p : patches)
        scale = (std::max)(scale, scale_of(p));
      const TS::Continuity_certificate certificate =
          certify_patches(domain, patches, k, this->tolerance(scale, k));
      EXPECT_TRUE(certificate.certified) << "largest residual " << certificate.max_residual;
    }
    // The edge sweep moves points outside both corner regions only.
    for (const TS::Edge_adjustment& e : report.edges)
      for (const TS::Touched_control_point& point : e.touched) {
        const auto& patch_f = patches[point.face];
        for (std::uint32_t end : e.vertices) {
          const int c = TS::internal::local_vertex(patch_f, domain.point(end));
          ASSERT_GE(c, 0);
          EXPECT_LT(point.index[c], n - 2 * k) << "edge " << e.edge;
        }
      }
  }
}

TYPED_TEST(MannTest, PolynomialNetworksAreUnchanged) {
  using K = TypeParam;
  const auto domain = this->random_delaunay(12);
  for (int k : {0, 1, 2}) {
    const int n = 4 * k + 1 + (k == 0 ? 2 : 0);
    const auto P = this->random.template polynomial<K>(n);
    std::vector<Bezier_triangle<K>> patches;
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
      const auto& t = domain.face(f);
      patches.push_back(P.to_bezier(n, domain.point(t[1]), domain.point(t[2]), domain.point(t[0])));
    }
    const auto before = patches;
    const TS::Network_adjustment report = TS::adjust_network(domain, patches, k);
    EXPECT_TRUE(report.vertices.empty()) << "k=" << k;
    if (this->exact) {
      EXPECT_EQ(report.number_of_touched_points(), 0u);
      EXPECT_TRUE(identical(before, patches));
    }
  }
}

TYPED_TEST(MannTest, XuC1SplinesAreUnchangedByTheC1Adjustment) {
  // A C^1 quintic spline is generally not C^2 at its vertices: the vertex step must leave
  // it alone all the same (a projection, not an averaging of second-order jets).
  using K = TypeParam;
  if (!this->exact)
    GTEST_SKIP() << "exact C^1 needs exact arithmetic";
  TS::C1_quintic_spline<K> spline(this->random_delaunay(10));
  for (auto s : spline.free_slots())
    spline.set_free_value(s, this->random.template rational<typename K::FT>());
  spline.propagate();
  std::vector<Bezier_triangle<K>> patches;
  for (std::uint32_t f = 0; f < spline.domain().number_of_faces(); ++f)
    patches.push_back(spline.patch(f));
  ASSERT_TRUE(certify_patches(spline.domain(), patches, 1).certified);
  ASSERT_FALSE(certify_patches(spline.domain(), patches, 2).certified);
  const auto before = patches;
  const TS::Network_adjustment report = TS::adjust_network(spline.domain(), patches, 1);
  EXPECT_EQ(report.number_of_touched_points(), 0u);
  EXPECT_TRUE(identical(before, patches));
}

TYPED_TEST(MannTest, ParametricNetworksAreAdjustedToo) {
  using K = TypeParam;
  using Vector_3 = typename K::Vector_3;
  if (!this->exact)
    GTEST_SKIP() << "one instantiation is enough";
  const auto domain = this->random_delaunay(9);
  std::vector<Bezier_triangle<K, Vector_3>> patches;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    std::vector<Vector_3> net;
    for (std::size_t c = 0; c < TS::number_of_control_points(5); ++c)
      net.push_back(this->random.template value<K, Vector_3>());
    patches.emplace_back(5, domain.point(t[0]), domain.point(t[1]), domain.point(t[2]), net);
  }
  TS::adjust_network(domain, patches, 1);
  EXPECT_TRUE(certify_patches(domain, patches, 1).certified);
}

TYPED_TEST(MannTest, DegreeRuleAndBadNetworksAreRefused) {
  const auto domain = this->random_delaunay(8);
  for (auto [k, n] : {std::pair<int, int>{1, 4}, {2, 8}, {3, 12}}) {
    auto patches = this->random_network(domain, n);
    const auto before = patches;
    EXPECT_TRUE(throws_with(
        [&] { TS::adjust_network(domain, patches, k); },
        "C^" + std::to_string(k) + " on a network needs degree at least 4k+1 = " +
            std::to_string(4 * k + 1) + " (Mann 3.1, Zenisek), got " + std::to_string(n)));
    EXPECT_TRUE(identical(before, patches));
  }
  auto patches = this->random_network(domain, 5);
  EXPECT_TRUE(
      throws_with([&] { TS::adjust_network(domain, patches, -1); }, "negative continuity order"));
  auto fewer = patches;
  fewer.pop_back();
  EXPECT_TRUE(throws_with([&] { TS::adjust_network(domain, fewer, 1); },
                          std::to_string(fewer.size()) + " patches for " +
                              std::to_string(domain.number_of_faces()) + " faces"));
  auto swapped = patches;
  std::swap(swapped[0], swapped[1]);
  EXPECT_TRUE(throws_with([&] { TS::adjust_network(domain, swapped, 1); },
                          "the patch of face 0 is not over that face"));
  auto mixed = patches;
  mixed[1] = mixed[1].elevate_degree();
  EXPECT_TRUE(throws_with([&] { TS::adjust_network(domain, mixed, 1); },
                          "patch 1 has degree 6, patch 0 has degree 5"));
}

// ---------------------------------------------------------------------------------------
// The simple interpolant

TYPED_TEST(MannTest, TaylorPolynomialsFromDerivatives) {
  using K = TypeParam;
  using FT = typename K::FT;
  const auto P = this->random.template polynomial<K>(5);
  const auto c = this->random.template point<K>();
  const auto T = TS::taylor_polynomial(P, c);
  const auto D = TS::taylor_polynomial_from_derivatives<K>(
      5, [&](int p, int q) { return P.derivative(p, q).evaluate(c); });
  for (int p = 0; p <= 5; ++p)
    for (int q = 0; p + q <= 5; ++q)
      EXPECT_TRUE(same_value(T.coefficient(p, q), D.coefficient(p, q), this->exact, 1e-9, 1e6));
  // T(x - c) = P(x).
  const auto x = this->random.template point<K>();
  const FT expected = P.evaluate(x);
  const FT got = T.evaluate(typename K::Point_2(x.x() - c.x(), x.y() - c.y()));
  EXPECT_TRUE(same_value(got, expected, this->exact, 1e-9, 1e8));
}

TYPED_TEST(MannTest, C0NetworkFollowsTheNearestVertexRegions) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  const auto domain = this->random_delaunay(10);
  for (int n : {5, 6}) {
    std::vector<Polynomial_surface<K>> jets;
    for (std::size_t v = 0; v < domain.number_of_vertices(); ++v)
      jets.push_back(this->random.template polynomial<K>(n));
    const auto patches = TS::mann_c0_network(domain, jets, n);
    ASSERT_EQ(patches.size(), domain.number_of_faces());
    // C^0 exactly, also in double (canonical argument order).
    for (std::uint32_t e = 0; e < domain.number_of_edges(); ++e) {
      if (domain.is_boundary_edge(e))
        continue;
      const auto& ef = domain.edge_faces(e);
      // check_C1_join compares the boundary control points themselves (no blossom).
      const TS::Join_report report = TS::check_C1_join(patches[ef[0]], patches[ef[1]]);
      EXPECT_GE(report.achieved_order, 0);
      for (const TS::Join_condition& c : report.conditions)
        if (c.order == 0) {
          EXPECT_EQ(c.residual, 0.0);
        }
    }
    // Fig. 11 in face 0: blossoms of the centred Taylor polynomial of the nearest vertex.
    const auto& t = domain.face(0);
    auto value = [&](int owner, const Multi_index& index) {
      const Point_2& c = domain.point(t[owner]);
      std::vector<Point_2> args;
      for (int corner = 0; corner < 3; ++corner)
        for (int copy = 0; copy < index[corner]; ++copy)
          args.emplace_back(domain.point(t[corner]).x() - c.x(),
                            domain.point(t[corner]).y() - c.y());
      return jets[t[owner]].blossom(args);
    };
    const Multi_index own{n - 2, 1, 1};
    EXPECT_TRUE(same_value(patches[0].control_point(own), value(0, own), this->exact, 1e-9, 1e9));
    const Multi_index tie{2, 2, n - 4};
    const FT two = (value(0, tie) + value(1, tie)) / FT(2);
    if (n == 5) {
      EXPECT_TRUE(same_value(patches[0].control_point(tie), two, this->exact, 1e-9, 1e9));
    }
    if (n == 6) {
      const Multi_index centre{2, 2, 2};
      const FT three = (value(0, centre) + value(1, centre) + value(2, centre)) / FT(3);
      EXPECT_TRUE(same_value(patches[0].control_point(centre), three, this->exact, 1e-9, 1e9));
    }
    // Corners interpolate the data.
    EXPECT_TRUE(patches[0].control_point(n, 0, 0) == jets[t[0]].coefficient(0, 0));
  }
}

TYPED_TEST(MannTest, PolynomialPrecisionOfTheInterpolant) {
  using K = TypeParam;
  for (auto [n, k, points] : {std::array<int, 3>{5, 1, 30}, {9, 2, 8}}) {
    if (n == 9 && !this->exact)
      continue;
    const auto domain = this->random_delaunay(points);
    const auto P = this->random.template polynomial<K>(n);
    std::vector<Polynomial_surface<K>> jets;
    for (const auto& p : domain.points())
      jets.push_back(TS::taylor_polynomial(P, p));
    const auto c0 = TS::mann_c0_network(domain, jets, n);
    const auto result = TS::mann_interpolant(domain, jets, n);
    EXPECT_EQ(result.degree(), n);
    EXPECT_EQ(result.continuity, k);
    ASSERT_EQ(result.patches().size(), domain.number_of_faces());
    double scale = 1;
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
      const auto& t = domain.face(f);
      const auto expected =
          P.to_bezier(n, domain.point(t[0]), domain.point(t[1]), domain.point(t[2]));
      scale = (std::max)(scale, scale_of(expected));
      for (std::size_t c = 0; c < expected.control_points().size(); ++c) {
        EXPECT_TRUE(same_value(c0[f].control_points()[c], expected.control_points()[c], this->exact,
                               1e-9, scale_of(expected)));
        EXPECT_TRUE(same_value(result.patch(f).control_points()[c], expected.control_points()[c],
                               this->exact, 1e-9, scale_of(expected)));
      }
    }
    const auto& patches = result.patches();
    if (this->exact) {
      EXPECT_EQ(result.adjustment.number_of_touched_points(), 0u);
      EXPECT_TRUE(certify_patches(domain, patches, 1).certified);
      EXPECT_TRUE(certify_patches(domain, patches, k).certified);
    } else {
      EXPECT_TRUE(certify_patches(domain, patches, 1, this->tolerance(scale, 1)).certified);
    }
  }
}

TYPED_TEST(MannTest, GeneralVertexDataGivesACkInterpolant) {
  using K = TypeParam;
  using FT = typename K::FT;
  for (auto [n, k, points] : {std::array<int, 3>{5, 1, 16}, {9, 2, 7}}) {
    if (n == 9 && !this->exact)
      continue;
    const auto domain = this->random_delaunay(points);
    std::vector<Polynomial_surface<K>> jets;
    for (std::size_t v = 0; v < domain.number_of_vertices(); ++v)
      jets.push_back(this->random.template polynomial<K>(TS::mann_derivative_order(n)));
    const auto result = TS::mann_interpolant(domain, jets, n);
    EXPECT_EQ(result.continuity, k);
    // Vertex data is consistent: no vertex step; the edge sweep moves few points.
    EXPECT_TRUE(result.adjustment.vertices.empty());
    EXPECT_GT(result.adjustment.number_of_changed_edges(), 0u);
    const auto& patches = result.patches();
    if (this->exact) {
      EXPECT_TRUE(certify_patches(domain, patches, k).certified);
      if (k == 1) {
        EXPECT_TRUE(certify_patches(domain, patches, 1).certified);
      }
    } else {
      double scale = 1;
      for (const auto& p : result.patches())
        scale = (std::max)(scale, scale_of(p));
      EXPECT_TRUE(certify_patches(domain, patches, 1, this->tolerance(scale, 1)).certified);
    }
    if (n == 5) { // one point per patch and edge, at (1, 2, 2) in the edge's frame
      for (const auto& e : result.adjustment.edges) {
        EXPECT_LE(e.touched.size(), 2u);
      }
    }
    // The data is interpolated with its derivatives up to order 2k at every vertex.
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f)
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t v = domain.face(f)[c];
        const auto& P = result.patch(f);
        for (int p = 0; p <= 2 * k; ++p)
          for (int q = 0; p + q <= 2 * k; ++q) {
            FT factorials(1);
            for (int e = 2; e <= p; ++e)
              factorials = factorials * FT(e);
            for (int e = 2; e <= q; ++e)
              factorials = factorials * FT(e);
            const FT expected = jets[v].coefficient(p, q) * factorials;
            EXPECT_TRUE(same_value(P.partial_derivative(domain.point(v), p, q), expected,
                                   this->exact, 1e-6, 1e4))
                << "vertex " << v << " derivative (" << p << "," << q << ")";
          }
      }
  }
}

TYPED_TEST(MannTest, EstimatedDerivativesAreExactForPolynomialData) {
  using K = TypeParam;
  using FT = typename K::FT;
  const auto domain = this->random_delaunay(40);
  for (int d : {0, 1, 2, 3, 5}) {
    const auto P = this->random.template polynomial<K>(d);
    std::vector<FT> values;
    for (const auto& p : domain.points())
      values.push_back(P.evaluate(p));
    const auto jets = TS::estimate_vertex_derivatives(domain, values, d);
    ASSERT_EQ(jets.size(), domain.number_of_vertices());
    for (std::size_t v = 0; v < jets.size(); ++v) {
      const auto T = TS::taylor_polynomial(P, domain.point(std::uint32_t(v)));
      EXPECT_EQ(jets[v].degree(), d);
      for (int p = 0; p <= d; ++p)
        for (int q = 0; p + q <= d; ++q)
          EXPECT_TRUE(
              same_value(jets[v].coefficient(p, q), T.coefficient(p, q), this->exact, 1e-6, 1e5))
              << "order " << d << " vertex " << v << " (" << p << "," << q << ")";
    }
  }
  // The whole pipeline from values only: cubic data, cubic estimates, quintic interpolant.
  const auto P = this->random.template polynomial<K>(3);
  std::vector<FT> values;
  for (const auto& p : domain.points())
    values.push_back(P.evaluate(p));
  const auto result =
      TS::mann_interpolant(domain, TS::estimate_vertex_derivatives(domain, values, 3));
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto x = CGAL::centroid(domain.point(domain.face(f)[0]), domain.point(domain.face(f)[1]),
                                  domain.point(domain.face(f)[2]));
    EXPECT_TRUE(same_value(result.patch(f).evaluate(x), P.evaluate(x), this->exact, 1e-6, 1e4));
  }
}

TYPED_TEST(MannTest, BadVertexDataIsRejected) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  const auto domain = this->random_delaunay(10);
  std::vector<Polynomial_surface<K>> jets;
  for (std::size_t v = 0; v < domain.number_of_vertices(); ++v)
    jets.push_back(this->random.template polynomial<K>(3));
  EXPECT_NO_THROW(TS::mann_interpolant(domain, jets, 5));
  auto missing = jets;
  missing.pop_back();
  EXPECT_TRUE(throws_with([&] { TS::mann_interpolant(domain, missing, 5); },
                          "derivative data for 9 vertices, but the domain has 10"));
  auto low = jets;
  low[4] = this->random.template polynomial<K>(2);
  EXPECT_TRUE(throws_with([&] { TS::mann_interpolant(domain, low, 5); },
                          "vertex 4 has derivatives up to order 2, degree 5 patches need them up "
                          "to order 3"));
  auto high = jets;
  high[2] = this->random.template polynomial<K>(6);
  EXPECT_TRUE(
      throws_with([&] { TS::mann_c0_network(domain, high, 5); },
                  "vertex 2 has a Taylor polynomial of degree 6, above the patch degree 5"));
  std::vector<Polynomial_surface<K>> sextic;
  for (std::size_t v = 0; v < domain.number_of_vertices(); ++v)
    sextic.push_back(this->random.template polynomial<K>(5));
  EXPECT_TRUE(throws_with([&] { TS::mann_interpolant(domain, sextic, 8, 2); },
                          "C^2 needs degree at least 4k+1 = 9, got 8"));
  EXPECT_TRUE(
      throws_with([&] { TS::mann_interpolant(domain, jets, 5, -2); }, "negative continuity order"));

  // Derivative estimates.
  std::vector<FT> values(domain.number_of_vertices(), FT(1));
  EXPECT_TRUE(throws_with(
      [&] {
        TS::estimate_vertex_derivatives(domain, std::vector<FT>(values.begin(), values.end() - 1),
                                        3);
      },
      "9 values for 10 vertices"));
  EXPECT_TRUE(
      throws_with([&] { TS::estimate_vertex_derivatives(domain, values, 11); }, "outside 0..10"));
  const Planar_domain<K> square({Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)},
                                {{{0, 1, 2}}, {{0, 2, 3}}});
  // Too few points for the degree asked: lowered, never refused (issue 10). Four points
  // determine planes only; data from a plane are reproduced exactly (in double: to rounding).
  auto plane = [](const Point_2& p) -> FT { return FT(3) + FT(2) * p.x() - FT(5) * p.y(); };
  std::vector<FT> linear;
  for (std::size_t v = 0; v < 4; ++v)
    linear.push_back(plane(square.point(std::uint32_t(v))));
  std::vector<int> degrees;
  const auto lowered = TS::estimate_vertex_derivatives(square, linear, 2, &degrees);
  EXPECT_EQ(degrees, std::vector<int>(4, 1));
  const double tolerance = this->exact ? 0.0 : 1e-12;
  for (const auto& jet : lowered) {
    EXPECT_NEAR(CGAL::to_double(jet.coefficient(1, 0)), 2.0, tolerance);
    EXPECT_NEAR(CGAL::to_double(jet.coefficient(0, 1)), -5.0, tolerance);
    EXPECT_EQ(jet.coefficient(2, 0), FT(0));
    EXPECT_EQ(jet.coefficient(1, 1), FT(0));
  }
  // Three points in all, degree 3 asked: a plane at every vertex.
  const Planar_domain<K> triangle({Point_2(0, 0), Point_2(1, 0), Point_2(0, 1)}, {{{0, 1, 2}}});
  TS::estimate_vertex_derivatives(triangle, std::vector<FT>{FT(1), FT(2), FT(4)}, 3, &degrees);
  EXPECT_EQ(degrees, std::vector<int>(3, 1));
  // Enough points: the degree asked everywhere.
  TS::estimate_vertex_derivatives(domain, values, 1, &degrees);
  EXPECT_EQ(degrees, std::vector<int>(domain.number_of_vertices(), 1));
}

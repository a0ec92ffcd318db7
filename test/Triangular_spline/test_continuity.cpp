// Tests of the C^k join test between two patches over adjacent domain triangles (Xu
// Lemma 3.1.4 and (3.4)/(3.5); Lai's construction as in Mann §1.2).

#include "test_support.h"

#include <CGAL/Triangular_spline/continuity.h>

#include <cmath>

using namespace ts_test;
using TS::Bezier_triangle;
using TS::Join_conditions;
using TS::Multi_index;
using TS::Polynomial_surface;

namespace {

const std::vector<Join_conditions> all_condition_sets = {
    Join_conditions::EXTENSION, Join_conditions::LAI, Join_conditions::COMPLETE};

} // namespace

template <class K>
class JoinTest : public ::testing::Test {
protected:
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  static constexpr bool exact = is_exact<K>;
  Random_rationals random{4242};

  struct Pair_of_triangles {
    Point_2 p, q, r, s; // A = (p, r, s), B = (q, r, s) up to the vertex order used
  };

  // Two triangles sharing rs, apexes on opposite sides. `thin` puts p within 1e-6 of the
  // line rs: a nearly degenerate (but valid) domain triangle.
  Pair_of_triangles adjacent_triangles(bool thin = false) {
    for (;;) {
      Pair_of_triangles t{this->random.template point<K>(), this->random.template point<K>(),
                          this->random.template point<K>(), this->random.template point<K>()};
      if (t.r == t.s)
        continue;
      if (thin) {
        // p = midpoint(r,s) + 1e-6 * perpendicular(s - r)
        const auto d = t.s - t.r;
        t.p = CGAL::midpoint(t.r, t.s) + FT(1) / FT(1000000) * typename K::Vector_2(-d.y(), d.x());
      }
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
};

TYPED_TEST_SUITE(JoinTest, Kernels, Kernel_names);

TYPED_TEST(JoinTest, PatchesCutFromOnePolynomialJoinWithEveryOrder) {
  using K = TypeParam;
  for (int trial = 0; trial < 6; ++trial) {
    const bool thin = trial >= 4;
    const int m = trial % 2 == 0 ? 5 : 3 + trial;
    const auto polynomial = this->random.template polynomial<K>(m);
    const auto t = this->adjacent_triangles(thin);
    const auto A = polynomial.to_bezier(m, t.p, t.r, t.s);
    // B lists its vertices in another order: the shared edge is found by comparison.
    const auto B = polynomial.to_bezier(m, t.r, t.q, t.s);
    for (Join_conditions set : all_condition_sets) {
      const TS::Join_report report = TS::check_join(A, B, m, set);
      if (this->exact) {
        EXPECT_TRUE(report.exact);
        EXPECT_TRUE(report.holds) << "trial " << trial;
        EXPECT_EQ(report.achieved_order, m);
        EXPECT_EQ(report.max_residual, 0.0);
      } else {
        // Double: an order-l condition evaluates a blossom at the other apex l times, and
        // the barycentric weights of that apex grow like the aspect ratio (1e6 for the thin
        // triangle), so round-off grows like aspect^l. Check each order against
        // 1e-12 * scale * aspect^l: beyond C^1 on thin triangles double is meaningless,
        // which is why certificates are exact.
        const double aspect = thin ? 1e6 : 1e2;
        for (const TS::Join_condition& c : report.conditions)
          EXPECT_LE(c.residual, 1e-12 * scale_of(A) * std::pow(aspect, c.order + 1))
              << "trial " << trial << " order " << c.order;
      }
      EXPECT_EQ(report.a_vertices, (std::array<int, 3>{{0, 1, 2}}));
      EXPECT_EQ(report.b_vertices, (std::array<int, 3>{{1, 0, 2}}));
    }
    // The minimal sets have sum_{l<=k} (m-l+1) conditions.
    EXPECT_EQ(TS::check_join(A, B, 1).conditions.size(), static_cast<std::size_t>(2 * m + 1));
  }
}

TYPED_TEST(JoinTest, ExactOrderIsDetectedByAllConditionSets) {
  using K = TypeParam;
  if (!this->exact)
    GTEST_SKIP() << "the order of a join is an exact notion";
  const int m = 5;
  for (int order = 0; order <= 3; ++order) {
    // B = P + l^(order+1) Q: derivatives up to `order` agree along rs, the next differs.
    const auto P = this->random.template polynomial<K>(m);
    const auto t = this->adjacent_triangles(order == 2);
    Polynomial_surface<K> bump = this->random.template polynomial<K>(m - order - 1);
    for (int e = 0; e <= order; ++e)
      bump = bump.multiplied_by(this->edge_function(t.r, t.s));
    const auto A = P.to_bezier(m, t.p, t.r, t.s);
    const auto B = (P + bump).to_bezier(m, t.q, t.s, t.r);
    for (Join_conditions set : all_condition_sets) {
      const TS::Join_report report = TS::check_join(A, B, m, set);
      EXPECT_EQ(report.achieved_order, order) << "set " << static_cast<int>(set);
      EXPECT_FALSE(report.holds);
      EXPECT_GT(report.max_residual, 0.0);
      EXPECT_TRUE(TS::check_join(A, B, order, set).holds);
    }
    if constexpr (is_exact<K>) {
      EXPECT_TRUE(TS::is_Ck_join(A, B, order));
      EXPECT_FALSE(TS::is_Ck_join(A, B, order + 1));
    }
  }
  // Unrelated patches: not even C^0.
  const auto t = this->adjacent_triangles();
  const auto A = this->random.template polynomial<K>(m).to_bezier(m, t.p, t.r, t.s);
  const auto B = this->random.template polynomial<K>(m).to_bezier(m, t.q, t.r, t.s);
  EXPECT_EQ(TS::check_join(A, B, 1).achieved_order, -1);
}

TYPED_TEST(JoinTest, PerturbedControlPointIsCaughtAndMeasured) {
  using K = TypeParam;
  using FT = typename K::FT;
  const int m = 5;
  const auto polynomial = this->random.template polynomial<K>(m);
  const auto t = this->adjacent_triangles();
  const auto A = polynomial.to_bezier(m, t.p, t.r, t.s);
  const auto B = polynomial.to_bezier(m, t.q, t.r, t.s); // q is vertex 0 of B
  // Round-off of the unperturbed conditions stays below 1e-12 * scale * 1e2^3 = 1e-6 scale
  // (see above); the perturbation is a power of two far above that, so it is exact in double
  // and must be reported as the residual of its own condition.
  const double tolerance = 1e-6 * scale_of(A);
  const double delta_d = std::exp2(std::ceil(std::log2(scale_of(A))) - 3);
  const FT delta = FT(delta_d);

  // Row h of B (h copies of q) holds the points of the order-h conditions.
  for (int h = 0; h <= 2; ++h) {
    for (int i = 0; i <= m - h; i += 2) {
      Bezier_triangle<K> broken = B;
      const Multi_index at{h, i, m - h - i};
      broken.set_control_point(at, broken.control_point(at) + delta);
      const TS::Join_report report =
          TS::check_join(A, broken, 2, Join_conditions::EXTENSION, tolerance);
      EXPECT_EQ(report.achieved_order, h - 1) << "perturbed (" << h << "," << i << ")";
      EXPECT_FALSE(report.holds);
      // The extension residual of that very condition is the perturbation.
      bool found = false;
      for (const TS::Join_condition& c : report.conditions)
        if (c.q_count == h && c.r_count == i) {
          found = true;
          EXPECT_NEAR(c.residual, delta_d, this->exact ? 0.0 : tolerance);
          EXPECT_FALSE(c.satisfied);
        } else {
          EXPECT_TRUE(c.satisfied);
        }
      EXPECT_TRUE(found);
      EXPECT_NEAR(report.max_residual, delta_d, this->exact ? 0.0 : tolerance);
      if constexpr (is_exact<K>) {
        EXPECT_EQ(TS::is_Ck_join(A, broken, 1), h >= 2);
      }
    }
  }
}

TYPED_TEST(JoinTest, XuDiamondRuleHoldsOnControlPoints) {
  // Condition (3.5) in terms of control points: with q = lambda p + mu r + nu s,
  // b^B(q r^i s^(m-1-i)) = lambda b^A(p r^i s^(m-1-i)) + mu b^A(r^(i+1) ...) + nu b^A(r^i s^(m-i)).
  using K = TypeParam;
  const int m = 5;
  const auto polynomial = this->random.template polynomial<K>(m);
  const auto t = this->adjacent_triangles();
  const auto A = polynomial.to_bezier(m, t.p, t.r, t.s);
  const auto B = polynomial.to_bezier(m, t.q, t.r, t.s);
  const auto w = A.barycentric_coordinates(t.q);
  for (int i = 0; i <= m - 1; ++i) {
    using FT = typename K::FT;
    const FT lhs = B.control_point(1, i, m - 1 - i);
    const FT rhs = w[0] * A.control_point(1, i, m - 1 - i) +
                   w[1] * A.control_point(0, i + 1, m - 1 - i) +
                   w[2] * A.control_point(0, i, m - i);
    EXPECT_TRUE(same_value(lhs, rhs, this->exact, 1e-9, 1e3 * scale_of(A)));
  }
}

TYPED_TEST(JoinTest, BadInputIsRejected) {
  using K = TypeParam;
  using Point_2 = typename K::Point_2;
  const auto P = this->random.template polynomial<K>(3);
  const auto A = P.to_bezier(3, Point_2(0, 0), Point_2(1, 0), Point_2(0, 1));
  const auto B = P.to_bezier(3, Point_2(1, 1), Point_2(0, 1), Point_2(1, 0));
  EXPECT_NO_THROW(TS::check_join(A, B, 1));
  // Degree mismatch.
  EXPECT_THROW(TS::check_join(A, B.elevate_degree(), 1), TS::Invalid_input);
  // Order out of range.
  EXPECT_THROW(TS::check_join(A, B, -1), TS::Invalid_input);
  EXPECT_THROW(TS::check_join(A, B, 4), TS::Invalid_input);
  // One shared vertex only.
  const auto C = P.to_bezier(3, Point_2(1, 0), Point_2(2, 0), Point_2(2, 1));
  EXPECT_THROW(TS::check_join(A, C, 1), TS::Invalid_input);
  // Same triangle twice.
  EXPECT_THROW(TS::check_join(A, A, 1), TS::Invalid_input);
  // Overlapping: the apexes lie on the same side of the shared edge.
  const auto D = P.to_bezier(3, Point_2(1, 0), Point_2(0, 1),
                             Point_2(typename K::FT(1) / 4, typename K::FT(1) / 4));
  try {
    TS::check_join(A, D, 1);
    ADD_FAILURE() << "overlapping triangles accepted";
  } catch (const TS::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("overlap"), std::string::npos) << e.what();
  }
}

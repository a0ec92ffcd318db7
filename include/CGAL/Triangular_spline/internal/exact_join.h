// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_EXACT_JOIN_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_EXACT_JOIN_H

// The fast C^1 checks of certify_continuity() for splines that store their control values in
// shared slots (C1_quintic_spline): Xu's conditions read on the slots of the two faces, no
// patch built; in exact number types each condition decided by an exact zero test, in
// double the residuals of the full check, bit for bit.
//
// Why no interval filter decides here: a join condition holds iff an affine combination of
// control values is exactly zero, and an interval can only show that it is not (a failure).
// For a spline that is C^1 every condition needs the exact test, so that test itself is made
// cheap: the condition is multiplied by its common denominator without ever reducing a
// fraction (GMP's gcd was about half of the exact build's time), and the scratch integers are
// kept per thread, so a condition allocates nothing once they have grown.

#include <CGAL/Triangular_spline/Multi_index.h>

#include <CGAL/number_utils.h>

#include <CGAL/Triangular_spline/internal/parallel.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#if __has_include(<gmpxx.h>)
#include <gmpxx.h>
#define CGAL_TRIANGULAR_SPLINE_HAS_GMPXX 1
#endif

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Decides sum_k c_k x_k == 0 exactly for terms added one by one. The generic version uses the
// number type's own arithmetic.
template <class FT>
class Exact_zero_sum {
public:
  void clear() { m_sum = FT(0); }
  void add(const FT& c, const FT& x) { m_sum += c * x; }
  void subtract(const FT& c, const FT& x) { m_sum -= c * x; }
  bool is_zero() const { return CGAL::is_zero(m_sum); }

private:
  FT m_sum = FT(0);
};

#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMPXX
// GMP rationals: the sum is kept as an unreduced fraction num/den (den > 0); each product
// c x = (c.num x.num) / (c.den x.den) is added by cross-multiplication, or directly when the
// denominators agree. Multiplications only, no gcd: the value is the same fraction, so the
// numerator is zero iff the sum is.
template <>
class Exact_zero_sum<mpq_class> {
public:
  void clear() { m_empty = true; }
  void add(const mpq_class& c, const mpq_class& x) { add(c, x, false); }
  void subtract(const mpq_class& c, const mpq_class& x) { add(c, x, true); }
  bool is_zero() const { return m_empty || mpz_sgn(m_num.get_mpz_t()) == 0; }

  // c x for an integer c
  void add(const mpz_class& c, const mpq_class& x) { add(c.get_mpz_t(), x, false); }
  void subtract(const mpz_class& c, const mpq_class& x) { add(c.get_mpz_t(), x, true); }

private:
  void add(mpz_srcptr c, const mpq_class& x, bool negate) {
    mpz_mul(m_t.get_mpz_t(), c, mpq_numref(x.get_mpq_t()));
    if (mpz_sgn(m_t.get_mpz_t()) == 0)
      return;
    if (negate)
      mpz_neg(m_t.get_mpz_t(), m_t.get_mpz_t());
    add_term(mpq_denref(x.get_mpq_t()));
  }
  void add(const mpq_class& c, const mpq_class& x, bool negate) {
    mpz_mul(m_t.get_mpz_t(), mpq_numref(c.get_mpq_t()), mpq_numref(x.get_mpq_t()));
    if (mpz_sgn(m_t.get_mpz_t()) == 0)
      return;
    if (negate)
      mpz_neg(m_t.get_mpz_t(), m_t.get_mpz_t());
    mpz_mul(m_d.get_mpz_t(), mpq_denref(c.get_mpq_t()), mpq_denref(x.get_mpq_t()));
    add_term(m_d.get_mpz_t());
  }
  // adds t/d, t in m_t (d may be m_d)
  void add_term(mpz_srcptr d) {
    if (m_empty) {
      mpz_swap(m_num.get_mpz_t(), m_t.get_mpz_t());
      mpz_set(m_den.get_mpz_t(), d);
      m_empty = false;
    } else if (mpz_cmp(m_den.get_mpz_t(), d) == 0) {
      mpz_add(m_num.get_mpz_t(), m_num.get_mpz_t(), m_t.get_mpz_t());
    } else {
      // num/den + t/d = (num d + t den) / (den d)
      mpz_mul(m_num.get_mpz_t(), m_num.get_mpz_t(), d);
      mpz_addmul(m_num.get_mpz_t(), m_t.get_mpz_t(), m_den.get_mpz_t());
      mpz_mul(m_den.get_mpz_t(), m_den.get_mpz_t(), d);
    }
  }
  bool m_empty = true;
  mpz_class m_num, m_den, m_t, m_d;
};
#endif

// The domain's points as integers for fast_exact_C1_join(): X = x L_x and Y = y L_y, with L_x
// and L_y the least common multiples of the x and of the y denominators, kept only while
// those stay below `max_bits` (decimal data: powers of ten; full double mantissas written
// with 17 digits: 10^17). Every determinant of the join test is then the rational one times
// L_x L_y > 0, so its zero tests and signs are the same, and no fraction is reduced per edge:
// the rational determinants took 15 reductions per edge, 40% of the certificate's time at
// 10^5 points with 17-digit coordinates. `usable` is false for other number types and where
// the multiples grow beyond max_bits (coordinates with many coprime denominators).
struct Integer_points {
  bool usable = false;
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMPXX
  std::vector<mpz_class> x, y;
#endif
};

template <class Domain>
Integer_points integer_points(const Domain& domain, std::size_t max_bits = 256) {
  Integer_points result;
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMPXX
  if constexpr (std::is_same_v<typename Domain::FT, mpq_class>) {
    const std::size_t V = domain.number_of_vertices();
    std::array<mpz_class, 2> multiple{{mpz_class(1), mpz_class(1)}};
    for (std::size_t v = 0; v < V; ++v)
      for (int c = 0; c < 2; ++c) {
        const auto& p = domain.point(typename Domain::Index(v));
        mpz_srcptr den = mpq_denref((c == 0 ? p.x() : p.y()).get_mpq_t());
        mpz_class& L = multiple[std::size_t(c)];
        if (mpz_divisible_p(L.get_mpz_t(), den))
          continue;
        mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), den);
        if (mpz_sizeinbase(L.get_mpz_t(), 2) > max_bits)
          return result;
      }
    result.x.resize(V);
    result.y.resize(V);
    parallel_for_index(V, thread_count(V, 20000), [&](std::size_t v) {
      const auto& p = domain.point(typename Domain::Index(v));
      for (int c = 0; c < 2; ++c) {
        mpq_srcptr q = (c == 0 ? p.x() : p.y()).get_mpq_t();
        mpz_class& X = (c == 0 ? result.x : result.y)[v];
        mpz_divexact(X.get_mpz_t(), multiple[std::size_t(c)].get_mpz_t(), mpq_denref(q));
        mpz_mul(X.get_mpz_t(), X.get_mpz_t(), mpq_numref(q));
      }
    });
    result.usable = true;
  }
#else
  (void)domain;
  (void)max_bits;
#endif
  return result;
}

// Whether `Network` stores its control values in slots: value(slot(f, index)), read by
// reference (C1_quintic_spline).
template <class Network, class = void>
struct has_slot_values : std::false_type {};
template <class Network>
struct has_slot_values<Network, std::void_t<decltype(std::declval<const Network&>().value(
                                    std::declval<const Network&>().slot(0u, Multi_index())))>>
    : std::true_type {};

// The sign of a determinant of the join test, rational or integer.
template <class T>
int join_sign(const T& x) {
  return int(CGAL::sign(x));
}
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMPXX
inline int join_sign(const mpz_class& x) {
  return mpz_sgn(x.get_mpz_t());
}
#endif

// The outcome of the fast check of one interior edge.
enum class Fast_join { ZERO, NOT_ZERO, UNDECIDED };

// Checks Xu's C^0 conditions (3.4) and C^1 conditions (3.5) across interior edge `e` of
// `network`, a slot network of degree 5 with values of its number type FT, exactly:
// q = (W_p p + W_r r + W_s s) / D with the 2x2 determinants W and D, and each condition is
// tested as D b_q - W_p a_p - W_r a_r - W_s a_s == 0. ZERO: every condition is exactly zero
// (a proof); otherwise the caller runs the full check for the residuals (UNDECIDED when the
// triangles do not lie on opposite sides of the edge: the full check reports that).
// With `points` (integer_points() of the network's domain, usable) the determinants are
// computed in integers, scaled by the same positive factor.
template <class Network, class Index>
Fast_join fast_exact_C1_join(const Network& network, Index e,
                             const Integer_points* points = nullptr) {
  using FT = typename Network::FT;
  const auto& domain = network.domain();
  const auto& ef = domain.edge_faces(e);
  const Index A = ef[0], B = ef[1];
  const Index p = domain.opposite_vertex(A, e), q = domain.opposite_vertex(B, e);
  const Index r = domain.edge(e)[0], s = domain.edge(e)[1];
  constexpr int m = 5;
  // The slot of the control point of face f with g copies of apex, i of r, m-g-i of s.
  auto slot = [&](Index f, Index apex, int g, int i) {
    const auto& t = domain.face(f);
    Multi_index index;
    for (int c = 0; c < 3; ++c)
      index[c] = t[std::size_t(c)] == apex ? g : (t[std::size_t(c)] == r ? i : m - g - i);
    return network.slot(f, index);
  };
  // (3.4): the edge's points are shared slots, equal by construction; compared otherwise.
  for (int i = 0; i <= m; ++i) {
    const auto a = slot(A, p, 0, i), b = slot(B, q, 0, i);
    if (a != b && !(network.value(a) == network.value(b)))
      return Fast_join::NOT_ZERO;
  }
  thread_local Exact_zero_sum<FT> sum;
  // the four conditions D b_q - W_p a_p - W_r a_r - W_s a_s == 0 (rational determinants, or
  // integer ones scaled by a common positive factor)
  auto conditions = [&](const auto& D, const auto& Wp, const auto& Wr, const auto& Ws) {
    // q strictly on the other side of rs than p: its coordinate at p is negative.
    if (join_sign(Wp) * join_sign(D) >= 0)
      return Fast_join::UNDECIDED;
    for (int i = 0; i <= m - 1; ++i) {
      sum.clear();
      sum.add(D, network.value(slot(B, q, 1, i)));
      sum.subtract(Wp, network.value(slot(A, p, 1, i)));
      sum.subtract(Wr, network.value(slot(A, p, 0, i + 1)));
      sum.subtract(Ws, network.value(slot(A, p, 0, i)));
      if (!sum.is_zero())
        return Fast_join::NOT_ZERO;
    }
    return Fast_join::ZERO;
  };
#ifdef CGAL_TRIANGULAR_SPLINE_HAS_GMPXX
  if constexpr (std::is_same_v<FT, mpq_class>) {
    if (points != nullptr && points->usable) {
      thread_local std::array<mpz_class, 10> z; // differences, then determinants
      auto difference = [&](mpz_class& out, const std::vector<mpz_class>& c, Index a) {
        mpz_sub(out.get_mpz_t(), c[std::size_t(a)].get_mpz_t(), c[std::size_t(p)].get_mpz_t());
      };
      mpz_class &rx = z[0], &ry = z[1], &sx = z[2], &sy = z[3], &qx = z[4], &qy = z[5];
      mpz_class &D = z[6], &Wr = z[7], &Ws = z[8], &Wp = z[9];
      difference(rx, points->x, r);
      difference(ry, points->y, r);
      difference(sx, points->x, s);
      difference(sy, points->y, s);
      difference(qx, points->x, q);
      difference(qy, points->y, q);
      auto determinant = [](mpz_class& out, const mpz_class& a, const mpz_class& b,
                            const mpz_class& c, const mpz_class& d) { // a d - b c
        mpz_mul(out.get_mpz_t(), a.get_mpz_t(), d.get_mpz_t());
        mpz_submul(out.get_mpz_t(), b.get_mpz_t(), c.get_mpz_t());
      };
      determinant(D, rx, ry, sx, sy);
      determinant(Wr, qx, qy, sx, sy);
      determinant(Ws, rx, ry, qx, qy);
      mpz_sub(Wp.get_mpz_t(), D.get_mpz_t(), Wr.get_mpz_t());
      mpz_sub(Wp.get_mpz_t(), Wp.get_mpz_t(), Ws.get_mpz_t());
      return conditions(D, Wp, Wr, Ws);
    }
  }
#endif
  (void)points;
  const auto& P = domain.point(p);
  const auto& Q = domain.point(q);
  const auto& R = domain.point(r);
  const auto& S = domain.point(s);
  const FT rx = R.x() - P.x(), ry = R.y() - P.y();
  const FT sx = S.x() - P.x(), sy = S.y() - P.y();
  const FT qx = Q.x() - P.x(), qy = Q.y() - P.y();
  const FT D = rx * sy - ry * sx;
  const FT Wr = qx * sy - qy * sx;
  const FT Ws = rx * qy - ry * qx;
  const FT Wp = D - Wr - Ws;
  return conditions(D, Wp, Wr, Ws);
}

// The residuals of check_C1_join_in_larger_frame() for interior edge `e` of a slot network of
// degree 5 with values of its inexact number type FT, read on the slots: the same operations
// in the same order on the same numbers (the larger triangle by compute_area_2, its
// barycentric weights of the other apex from the same determinants and reciprocal as a
// Bezier_triangle's, each extension w0 a + w1 b + w2 c), so the same bits, without building
// two patches and a report per edge (a third of the certificate's time at 10^6 points).
// Fills `c` and returns true when every condition holds within `tolerance` and every
// nonzero residual is a normal double; otherwise returns false and the caller runs the full
// check (failures, thin or overlapping triangles, residuals beyond double's range).
template <class Network, class Index, class Certificate>
bool fast_double_C1_join(const Network& network, Index e, double tolerance, Certificate& c) {
  using FT = typename Network::FT;
  using Point_2 = typename Network::Point_2;
  const auto& domain = network.domain();
  const auto& traits = domain.geom_traits();
  constexpr int m = 5;
  const auto& ef = domain.edge_faces(e);
  auto area = [&](Index f) {
    const auto& t = domain.face(f);
    return CGAL::abs(
        traits.compute_area_2_object()(domain.point(t[0]), domain.point(t[1]), domain.point(t[2])));
  };
  // check_C1_join(A, B) with A the larger triangle (ef[0] on ties)
  const bool swap = area(ef[1]) > area(ef[0]);
  const Index A = swap ? ef[1] : ef[0], B = swap ? ef[0] : ef[1];
  const auto &ta = domain.face(A), &tb = domain.face(B);
  // shared_edge(): av = (apex, first shared, second shared) in A's vertex order, bv the
  // positions in B of the same vertices
  std::array<int, 3> av{{-1, -1, -1}}, bv{{-1, -1, -1}};
  int shared = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (ta[std::size_t(a)] == tb[std::size_t(b)] && shared < 2) {
        av[std::size_t(1 + shared)] = a;
        bv[std::size_t(1 + shared)] = b;
        ++shared;
      }
  if (shared != 2)
    return false;
  av[0] = 3 - av[1] - av[2];
  bv[0] = 3 - bv[1] - bv[2];
  // Twice the signed area as a Bezier_triangle's constructor computes it; 0 where that
  // constructor throws (collinear corners, or a determinant that rounds to 0 or overflows).
  const auto orientation = traits.orientation_2_object();
  auto usable_area2 = [&](const auto& t) {
    const Point_2 &a = domain.point(t[0]), &b = domain.point(t[1]), &c = domain.point(t[2]);
    if (orientation(a, b, c) == CGAL::COLLINEAR)
      return FT(0);
    const FT area2 = determinant(b - a, c - a);
    return CGAL::is_finite(area2) ? area2 : FT(0);
  };
  const Point_2& r = domain.point(ta[std::size_t(av[1])]);
  const Point_2& s = domain.point(ta[std::size_t(av[2])]);
  const Point_2& q = domain.point(tb[std::size_t(bv[0])]);
  const FT area2 = usable_area2(ta);
  // overlapping triangles (shared_edge() throws) or a patch that could not be built
  if (orientation(r, s, domain.point(ta[std::size_t(av[0])])) == orientation(r, s, q) ||
      CGAL::is_zero(area2) || CGAL::is_zero(usable_area2(tb)))
    return false;
  const Point_2 &v0 = domain.point(ta[0]), &v1 = domain.point(ta[1]), &v2 = domain.point(ta[2]);
  const FT inverse_area2 = FT(1) / area2;
  const FT mu = determinant(q - v0, v2 - v0) * inverse_area2;
  const FT nu = determinant(v1 - v0, q - v0) * inverse_area2;
  const std::array<FT, 3> local{{FT(1) - mu - nu, mu, nu}};
  const std::array<FT, 3> w{
      {local[std::size_t(av[0])], local[std::size_t(av[1])], local[std::size_t(av[2])]}};
  auto point = [&](Index f, const std::array<int, 3>& at, int g, int i) -> const FT& {
    Multi_index index;
    index[at[0]] = g;
    index[at[1]] = i;
    index[at[2]] = m - g - i;
    return network.value(network.slot(f, index));
  };
  const FT bound(tolerance);
  double largest = 0, normal_largest = 0;
  bool zero = true;
  auto record = [&](const FT& difference) {
    const double residual = CGAL::abs(CGAL::to_double(difference));
    const bool is_zero = CGAL::is_zero(difference);
    if (!is_zero && !(tolerance > 0 && CGAL::abs(difference) <= bound))
      return false;
    if (!is_zero && !(residual >= 1e-300 && residual <= 1e300))
      return false;
    zero = zero && is_zero;
    if (!(residual <= largest))
      largest = residual;
    if (!is_zero && residual > normal_largest)
      normal_largest = residual;
    return true;
  };
  for (int i = 0; i <= m; ++i)
    if (!record(point(B, bv, 0, i) - point(A, av, 0, i)))
      return false;
  for (int i = 0; i <= m - 1; ++i) {
    const FT extension =
        w[0] * point(A, av, 1, i) + w[1] * point(A, av, 0, i + 1) + w[2] * point(A, av, 0, i);
    if (!record(point(B, bv, 1, i) - extension))
      return false;
  }
  c.edge = e;
  c.vertices = {{domain.edge(e)[0], domain.edge(e)[1]}};
  c.achieved_order = 1;
  c.holds = true;
  c.zero = zero;
  c.residual = largest;
  if (normal_largest > 0)
    c.residual_log10 = std::log10(normal_largest);
  return true;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_EXACT_JOIN_H

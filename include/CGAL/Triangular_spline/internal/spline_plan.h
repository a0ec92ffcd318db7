// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_PLAN_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_PLAN_H

// The plan of C1_quintic_spline: where each control point is stored (shared with the
// dimension count of Spline_space.h), and the barycentric weights of its propagation rules.

#include <CGAL/Triangular_spline/Multi_index.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Fraction_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The storage layout of a quintic spline's control points, shared by the spline and by the
// independent dimension count: vertices, then 4 slots per edge, then 6 per face.
template <class Domain>
std::uint32_t quintic_vertex_slot(const Domain&, typename Domain::Index v) {
  return static_cast<std::uint32_t>(v);
}
template <class Domain>
std::uint32_t quintic_edge_slot(const Domain& d, typename Domain::Index e, int t) {
  return static_cast<std::uint32_t>(d.number_of_vertices() + 4 * std::size_t(e) + std::size_t(t));
}
template <class Domain>
std::uint32_t quintic_face_slot(const Domain& d, typename Domain::Index f, int t) {
  return static_cast<std::uint32_t>(d.number_of_vertices() + 4 * d.number_of_edges() +
                                    6 * std::size_t(f) + std::size_t(t));
}
template <class Domain>
std::uint32_t quintic_slot(const Domain& d, typename Domain::Index f, const Multi_index& index) {
  const auto& t = d.face(f);
  for (int v = 0; v < 3; ++v)
    if (index[v] == 5)
      return quintic_vertex_slot(d, t[std::size_t(v)]);
  for (int v = 0; v < 3; ++v)
    if (index[v] == 0) {
      // on the edge opposite v: slot 4 - (copies of the edge's smaller vertex)
      const auto e = d.face_edge(f, v);
      const auto lo = d.edge(e)[0];
      int lo_count = 0;
      for (int w = 0; w < 3; ++w)
        if (t[std::size_t(w)] == lo)
          lo_count = index[w];
      return quintic_edge_slot(d, e, 4 - lo_count);
    }
  for (int v = 0; v < 3; ++v)
    if (index[v] == 3)
      return quintic_face_slot(d, f, v);
  for (int v = 0; v < 3; ++v)
    if (index[v] == 1)
      return quintic_face_slot(d, f, 3 + v);
  CGAL_error_msg("not a quintic multi-index");
  return 0;
}

// Barycentric coordinates (lambda, mu, nu) of x with respect to (a, b, c), points given as
// coordinate pairs of one number type, computed as written (no filtering).
template <class Coordinates>
auto barycentric_of_coordinates(const Coordinates& x, const Coordinates& a, const Coordinates& b,
                                const Coordinates& c) {
  using T = std::decay_t<decltype(x[0])>;
  const T d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const T mu = ((x[0] - a[0]) * (c[1] - a[1]) - (x[1] - a[1]) * (c[0] - a[0])) / d;
  const T nu = ((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / d;
  const T lambda = T(1) - mu - nu;
  return std::array<T, 3>{{lambda, mu, nu}};
}

// barycentric_of_coordinates() for a number type of fractions (Fraction_traits): the
// differences and determinants in integers, over unreduced denominators, and one reduction
// per coordinate, where the rational formula reduces a fraction (a gcd) at each of its
// nineteen operations. The same rationals (tested); with the formula a quarter of an exact
// plan's time went here (2 10^4 decimal points, --fit approximate: 1.05 times faster now).
template <class FT>
std::array<FT, 3> barycentric_of_fractions(const std::array<FT, 2>& x, const std::array<FT, 2>& a,
                                           const std::array<FT, 2>& b, const std::array<FT, 2>& c) {
  using Traits = CGAL::Fraction_traits<FT>;
  using Z = typename Traits::Numerator_type;
  struct Fraction {
    Z n, d;
  };
  typename Traits::Decompose decompose;
  auto split = [&](const FT& t) {
    Fraction f;
    decompose(t, f.n, f.d);
    return f;
  };
  const Fraction ax = split(a[0]), ay = split(a[1]);
  auto minus_a = [&](const FT& t, const Fraction& s) { // t - s, unreduced
    const Fraction f = split(t);
    return Fraction{f.n * s.d - s.n * f.d, f.d * s.d};
  };
  const Fraction ux = minus_a(b[0], ax), uy = minus_a(b[1], ay); // b - a
  const Fraction vx = minus_a(c[0], ax), vy = minus_a(c[1], ay); // c - a
  const Fraction wx = minus_a(x[0], ax), wy = minus_a(x[1], ay); // x - a
  // det(p, q) = p_x q_y - p_y q_x over the denominator Dpx Dqy Dpy Dqx, numerators only
  auto det = [](const Fraction& px, const Fraction& py, const Fraction& qx, const Fraction& qy) {
    return Z(px.n * qy.n * (py.d * qx.d) - py.n * qx.n * (px.d * qy.d));
  };
  const Z d = det(ux, uy, vx, vy);                 // over Dux Dvy Duy Dvx
  const Z A = det(wx, wy, vx, vy) * (ux.d * uy.d); // mu = A / (E d)
  const Z B = det(ux, uy, wx, wy) * (vx.d * vy.d); // nu = B / (E d)
  const Z Ed = wx.d * wy.d * d;                    // (the factors Dvx Dvy, Dux Duy cancelled)
  typename Traits::Compose compose;
  return {{compose(Z(Ed - A - B), Ed), compose(A, Ed), compose(B, Ed)}};
}

#if defined(__GMP_PLUSPLUS__) && defined(__SIZEOF_INT128__)
// Trailing zero bits of a non-zero 128-bit integer.
inline int trailing_zeros_128(unsigned __int128 v) {
  const std::uint64_t low = std::uint64_t(v);
  return low != 0 ? __builtin_ctzll(low) : 64 + __builtin_ctzll(std::uint64_t(v >> 64));
}

// Greatest common divisor of two 128-bit integers, not both zero (binary: shifts and
// subtractions only). Each step takes the smaller value and the shifted difference with
// conditional moves (which of the two is smaller is a coin toss: a branch on it missed
// every other step), and once both fit in 64 bits the rest runs in 64-bit words: 0.6x the
// time of the plain loop on the determinants of 17-digit data (the exact plan's hot spot).
inline unsigned __int128 gcd_128(unsigned __int128 a, unsigned __int128 b) {
  using U = unsigned __int128;
  if (a == 0)
    return b;
  if (b == 0)
    return a;
  const int shift = trailing_zeros_128(a | b);
  a >>= trailing_zeros_128(a);
  b >>= trailing_zeros_128(b);
  while (((a | b) >> 64) != 0) { // both odd
    if (a == b)
      return a << shift;
    const bool less = a < b;
    const U smaller = less ? a : b;
    const U difference = less ? b - a : a - b; // even, non-zero
    a = smaller;
    b = difference >> trailing_zeros_128(difference);
  }
  std::uint64_t x = std::uint64_t(a), y = std::uint64_t(b);
  while (x != y) { // both odd
    const bool less = x < y;
    const std::uint64_t smaller = less ? x : y;
    const std::uint64_t difference = less ? y - x : x - y;
    x = smaller;
    y = difference >> __builtin_ctzll(difference);
  }
  return U(x) << shift;
}

// The coordinates of points given as GMP rationals, brought to their least common
// denominator L, as integers: std::nullopt unless L and every such integer are below 2^61
// (decimal data of up to about 18 digits; doubles that share a binade). Differences of
// them are below 2^62 and determinants of the differences below 2^125: 128 bits hold them.
// `q`: the rationals, read in place (copies of them took three quarters of the time).
template <std::size_t n>
std::optional<std::array<__int128, n>>
small_integer_coordinates(const std::array<const mpq_class*, n>& q) {
  using I = __int128;
  using U = unsigned __int128;
  constexpr I bound = I(1) << 61;
  std::uint64_t common = 1;
  for (const mpq_class* t : q) {
    const mpz_srcptr d = mpq_denref(t->get_mpq_t());
    if (mpz_sizeinbase(d, 2) > 62)
      return std::nullopt;
    const std::uint64_t dv = std::uint64_t(mpz_get_ui(d));
    const U l = U(common / std::gcd(common, dv)) * dv;
    if (l >= U(bound))
      return std::nullopt;
    common = std::uint64_t(l);
  }
  std::array<I, n> X;
  for (std::size_t i = 0; i < n; ++i) {
    const mpz_srcptr z = mpq_numref(q[i]->get_mpq_t());
    if (mpz_sizeinbase(z, 2) > 62)
      return std::nullopt;
    const I magnitude =
        I(mpz_get_ui(z)) * I(common / std::uint64_t(mpz_get_ui(mpq_denref(q[i]->get_mpq_t()))));
    if (magnitude >= bound)
      return std::nullopt;
    X[i] = mpz_sgn(z) < 0 ? -magnitude : magnitude;
  }
  return X;
}

// The canonical rational n / d of 128-bit integers, d != 0, `g` = gcd(|n|, |d|).
inline mpq_class fraction_of_128(__int128 n, __int128 d, unsigned __int128 g) {
  using U = unsigned __int128;
  // (limbs written in place: a shift and an add grew the integer twice, each a new block)
  auto set = [](mpz_ptr z, U v) {
    const std::uint64_t high = std::uint64_t(v >> 64), low = std::uint64_t(v);
    if constexpr (sizeof(unsigned long) != 8 || GMP_NUMB_BITS != 64) {
      mpz_set_ui(z, (unsigned long)(high));
      mpz_mul_2exp(z, z, 64);
      mpz_add_ui(z, z, (unsigned long)(low));
      return;
    }
    if (high == 0) {
      mpz_set_ui(z, (unsigned long)(low));
      return;
    }
    mp_limb_t* limbs = mpz_limbs_write(z, 2);
    limbs[0] = mp_limb_t(low);
    limbs[1] = mp_limb_t(high);
    mpz_limbs_finish(z, 2);
  };
  const bool negative = (n < 0) != (d < 0);
  const U un = n < 0 ? U(-n) : U(n), ud = d < 0 ? U(-d) : U(d);
  mpq_class r;
  set(r.get_num_mpz_t(), un / g);
  set(r.get_den_mpz_t(), ud / g);
  if (negative)
    mpz_neg(r.get_num_mpz_t(), r.get_num_mpz_t());
  return r; // canonical: coprime, positive denominator (1 for zero)
}

inline unsigned __int128 abs_128(__int128 v) {
  return v < 0 ? (unsigned __int128)(-v) : (unsigned __int128)(v);
}

// barycentric_of_fractions() for GMP's rationals whose coordinates small_integer_coordinates()
// takes: L cancels, the weights are ratios of determinants of those integers, computed in 128
// bits and reduced by one binary gcd each: no GMP arithmetic and no allocation but the
// results'. std::nullopt beyond, for barycentric_of_fractions(). (The same rationals, tested.)
// `q`: the coordinates of x, a, b and c, in that order.
inline std::optional<std::array<mpq_class, 3>>
barycentric_of_small_fractions(const std::array<const mpq_class*, 8>& q) {
  using I = __int128;
  const auto X = small_integer_coordinates(q);
  if (!X)
    return std::nullopt;
  const I ux = (*X)[4] - (*X)[2], uy = (*X)[5] - (*X)[3]; // b - a
  const I vx = (*X)[6] - (*X)[2], vy = (*X)[7] - (*X)[3]; // c - a
  const I wx = (*X)[0] - (*X)[2], wy = (*X)[1] - (*X)[3]; // x - a
  const I d = ux * vy - uy * vx;
  if (d == 0)
    return std::nullopt;
  const I A = wx * vy - wy * vx; // mu = A / d
  const I B = ux * wy - uy * wx; // nu = B / d
  auto fraction = [&](I n) { return fraction_of_128(n, d, gcd_128(abs_128(n), abs_128(d))); };
  return std::array<mpq_class, 3>{{fraction(d - A - B), fraction(A), fraction(B)}};
}

// The barycentric weights of each of four points with respect to the other three, for GMP
// rationals that small_integer_coordinates() takes. An interior edge's four rules (the
// edge-middle points from either end, the flip point from either apex) are such weights of
// its two ends and two apexes, and every weight is a ratio of two of the four triangles'
// determinants: six gcds serve all twelve weights, where barycentric_of_small_fractions()
// takes one per weight. (The same rationals, tested.)
class Barycentric_quad {
public:
  // `q`: the coordinates of the four points, in order.
  static std::optional<Barycentric_quad> make(const std::array<const mpq_class*, 8>& q) {
    const auto X = small_integer_coordinates(q);
    if (!X)
      return std::nullopt;
    return Barycentric_quad(*X);
  }

  // The weights of point x with respect to (a, b, c) (distinct indices 0 to 3, in the
  // order of barycentric_weights_in_order()); std::nullopt if a, b and c are collinear.
  std::optional<std::array<mpq_class, 3>> weights(int x, int a, int b, int c) {
    const __int128 d = determinant(a, b, c);
    if (d == 0)
      return std::nullopt;
    // weight of a = det(x, b, c) / det(a, b, c): |det(x, b, c)| is the triangle without a
    return std::array<mpq_class, 3>{{fraction_of_128(determinant(x, b, c), d, gcd(x, a)),
                                     fraction_of_128(determinant(a, x, c), d, gcd(x, b)),
                                     fraction_of_128(determinant(a, b, x), d, gcd(x, c))}};
  }

  // The largest absolute weight of x with respect to (a, b, c), in double division of the
  // determinants rounded to double: within 4e-16 relative of the weights' exact value (two
  // roundings and a division); infinity if a, b and c are collinear.
  double approximate_largest(int x, int a, int b, int c) const {
    const double d = std::abs(double(determinant(a, b, c)));
    return (std::max)({std::abs(double(determinant(x, b, c))),
                       std::abs(double(determinant(a, x, c))),
                       std::abs(double(determinant(a, b, x)))}) /
           d;
  }

private:
  explicit Barycentric_quad(const std::array<__int128, 8>& X) : m_X(X) {}
  __int128 determinant(int a, int b, int c) const {
    const __int128 ux = m_X[2 * b] - m_X[2 * a], uy = m_X[2 * b + 1] - m_X[2 * a + 1];
    const __int128 vx = m_X[2 * c] - m_X[2 * a], vy = m_X[2 * c + 1] - m_X[2 * a + 1];
    return ux * vy - uy * vx;
  }
  // gcd of the determinants of the triangles without i and without j, i != j: computed once
  unsigned __int128 gcd(int i, int j) {
    const int lo = (std::min)(i, j), hi = (std::max)(i, j);
    const int k =
        lo == 0 ? hi - 1 : lo + hi; // (0,1..3) -> 0..2, (1,2) -> 3, (1,3) -> 4, (2,3) -> 5
    if (!m_known[std::size_t(k)]) {
      m_gcd[std::size_t(k)] = gcd_128(abs_128(without(lo)), abs_128(without(hi)));
      m_known[std::size_t(k)] = true;
    }
    return m_gcd[std::size_t(k)];
  }
  __int128 without(int i) const {
    return i == 0   ? determinant(1, 2, 3)
           : i == 1 ? determinant(0, 2, 3)
           : i == 2 ? determinant(0, 1, 3)
                    : determinant(0, 1, 2);
  }
  std::array<__int128, 8> m_X;
  std::array<unsigned __int128, 6> m_gcd{};
  std::array<bool, 6> m_known{};
};
#endif

// CGAL::to_double(b - a), the exact difference truncated (mpq_get_d() rounds towards zero),
// without reducing the difference: GMP's subtraction takes gcds of the denominators and of
// the result, the conversion only needs the value (the same double, tested).
template <class FT>
double to_double_of_difference(const FT& b, const FT& a) {
#if defined(__GMP_PLUSPLUS__)
  if constexpr (std::is_same_v<FT, mpq_class>) {
    static thread_local mpq_class t;
    mpz_ptr n = mpq_numref(t.get_mpq_t()), d = mpq_denref(t.get_mpq_t());
    const mpz_srcptr bn = mpq_numref(b.get_mpq_t()), bd = mpq_denref(b.get_mpq_t());
    const mpz_srcptr an = mpq_numref(a.get_mpq_t()), ad = mpq_denref(a.get_mpq_t());
    if (mpz_cmp(ad, bd) == 0) {
      mpz_sub(n, bn, an);
      mpz_set(d, ad);
    } else {
      mpz_mul(n, bn, ad);
      mpz_submul(n, an, bd);
      mpz_mul(d, ad, bd);
    }
    return mpq_get_d(t.get_mpq_t());
  } else
#endif
    return CGAL::to_double(b - a);
}

// barycentric_weights() for the corners in the order given.
template <class Point_2>
auto barycentric_weights_in_order(const Point_2& x, const Point_2& a, const Point_2& b,
                                  const Point_2& c) {
  using FT = std::decay_t<decltype(x.x())>;
  auto coords = [](const Point_2& p) { return std::array<FT, 2>{{p.x(), p.y()}}; };
  if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
    if constexpr (std::is_same_v<typename CGAL::Fraction_traits<FT>::Is_fraction, CGAL::Tag_true>) {
#if defined(__GMP_PLUSPLUS__) && defined(__SIZEOF_INT128__)
      if constexpr (std::is_same_v<FT, mpq_class>)
        if (auto small = barycentric_of_small_fractions(
                {{&x.x(), &x.y(), &a.x(), &a.y(), &b.x(), &b.y(), &c.x(), &c.y()}}))
          return *small;
#endif
      return barycentric_of_fractions(coords(x), coords(a), coords(b), coords(c));
    } else
      return barycentric_of_coordinates(coords(x), coords(a), coords(b), coords(c));
  } else {
    const double bx = CGAL::to_double(b.x() - a.x()), by = CGAL::to_double(b.y() - a.y());
    const double cx = CGAL::to_double(c.x() - a.x()), cy = CGAL::to_double(c.y() - a.y());
    const double d = bx * cy - by * cx;
    const double scale =
        (std::max)(std::abs(bx), std::abs(by)) * (std::max)(std::abs(cx), std::abs(cy));
    if (std::abs(d) > 1e-10 * scale)
      return barycentric_of_coordinates(coords(x), coords(a), coords(b), coords(c));
    using Q = CGAL::Exact_rational;
    auto exact = [](const Point_2& p) {
      return std::array<Q, 2>{{Q(CGAL::to_double(p.x())), Q(CGAL::to_double(p.y()))}};
    };
    const std::array<Q, 3> w = barycentric_of_coordinates(exact(x), exact(a), exact(b), exact(c));
    return std::array<FT, 3>{
        {FT(CGAL::to_double(w[0])), FT(CGAL::to_double(w[1])), FT(CGAL::to_double(w[2]))}};
  }
}

// Barycentric coordinates of x with respect to (a, b, c), which the exact predicates have
// found non-collinear. With an inexact number type a nearly collinear frame can round its
// determinant to zero (or to the wrong size): below the error bound the weights are
// recomputed with exact rationals and rounded once, so they are never infinite and always
// accurate to the last bit. Inexact weights are computed with the corners in the
// lexicographic order of their points: their bits then do not depend on the order the
// caller names the corners in, which follows the vertex numbering, and a tile of a larger
// point set, numbered otherwise, gets the very rules of the whole set
// (doc/design/tile_parallel.md).
template <class Point_2>
auto barycentric_weights(const Point_2& x, const Point_2& a, const Point_2& b, const Point_2& c) {
  using FT = std::decay_t<decltype(x.x())>;
  if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
    return barycentric_weights_in_order(x, a, b, c);
  } else {
    const std::array<const Point_2*, 3> p = {&a, &b, &c};
    std::array<std::size_t, 3> corner = {0, 1, 2};
    auto before = [&](std::size_t i, std::size_t j) {
      return p[i]->x() < p[j]->x() || (p[i]->x() == p[j]->x() && p[i]->y() < p[j]->y());
    };
    if (before(corner[1], corner[0]))
      std::swap(corner[0], corner[1]);
    if (before(corner[2], corner[1]))
      std::swap(corner[1], corner[2]);
    if (before(corner[1], corner[0]))
      std::swap(corner[0], corner[1]);
    const std::array<FT, 3> w =
        barycentric_weights_in_order(x, *p[corner[0]], *p[corner[1]], *p[corner[2]]);
    std::array<FT, 3> result;
    for (std::size_t i = 0; i < 3; ++i)
      result[corner[i]] = w[i];
    return result;
  }
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_SPLINE_PLAN_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BEZIER_TRIANGLE_H
#define CGAL_TRIANGULAR_SPLINE_BEZIER_TRIANGLE_H

#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/internal/de_casteljau.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief the value, gradient and Hessian of a function of the plane at a point (its 2-jet),
  as returned by `Bezier_triangle::jet()` and `evaluate_jets()`.

  \tparam Value the value type: `FT` for a functional (height) spline, a vector type for a
  parametric one (then each derivative is a vector).
*/
template <class Value>
struct Point_jet {
  /// \f$F(a)\f$
  Value value;
  /// \f$(F_x, F_y)\f$
  std::array<Value, 2> gradient;
  /// \f$(F_{xx}, F_{xy}, F_{yy})\f$ (the Hessian is symmetric)
  std::array<Value, 3> hessian;
};

namespace internal {

// The jet of a patch of degree m from its net (destroyed), at barycentric weights w, with
// dx and dy the barycentric directions of the unit vectors: m-2 de Casteljau steps leave
// the quadratic net of f(., ., a^(m-2)), whose blossom at (a, a), (e, a) and (e, e') gives
// the value, F_e / m and F_ee' / (m (m - 1)). Shared by Bezier_triangle::jet_barycentric()
// and the evaluation of networks that hand out their nets without building patches.
template <class Net, class FT>
Point_jet<typename Net::value_type> jet_of_net(Net& net, int m_degree, const std::array<FT, 3>& w,
                                               const std::array<FT, 3>& dx,
                                               const std::array<FT, 3>& dy, int order) {
  using Value = typename Net::value_type;
  using Weights = std::array<FT, 3>;
  const Value zero = Value_traits<Value>::zero();
  Point_jet<Value> jet{zero, {{zero, zero}}, {{zero, zero, zero}}};
  const int steps = m_degree < 2 ? 0 : m_degree - 2;
  for (int l = 0; l < steps; ++l)
    de_casteljau_step(net, m_degree - l, w);
  // net now has degree min(m, 2); the last steps read it in place (no copies).
  using Linear = std::array<Value, 3>;
  // a degree 1 net: (1,0,0) at 2, (0,1,0) at 1, (0,0,1) at 0
  const auto dot = [](const Linear& l, const Weights& u) -> Value {
    Value v = u[0] * l[2] + u[1] * l[1] + u[2] * l[0];
    return v;
  };
  if (m_degree == 0) {
    jet.value = net[0];
    return jet;
  }
  if (m_degree == 1) {
    const Linear l{{net[0], net[1], net[2]}};
    jet.value = dot(l, w);
    if (order >= 1) {
      jet.gradient[0] = dot(l, dx);
      jet.gradient[1] = dot(l, dy);
    }
    return jet;
  }
  // one de Casteljau step of the degree 2 net (positions as in `de_casteljau_step()`)
  const auto step = [&net](const Weights& u) -> Linear {
    Value v0 = u[0] * net[3] + u[1] * net[1] + u[2] * net[0];
    Value v1 = u[0] * net[4] + u[1] * net[2] + u[2] * net[1];
    Value v2 = u[0] * net[5] + u[1] * net[4] + u[2] * net[3];
    return Linear{{std::move(v0), std::move(v1), std::move(v2)}};
  };
  const Linear at_a = step(w);
  jet.value = dot(at_a, w);
  if (order >= 1) {
    const FT m(m_degree);
    const Value gx = dot(at_a, dx), gy = dot(at_a, dy);
    jet.gradient[0] = m * gx;
    jet.gradient[1] = m * gy;
  }
  if (order >= 2) {
    const FT mm(m_degree * (m_degree - 1));
    const Linear along_x = step(dx);
    const Value hxx = dot(along_x, dx), hxy = dot(along_x, dy);
    const Value hyy = dot(step(dy), dy);
    jet.hessian[0] = mm * hxx;
    jet.hessian[1] = mm * hxy;
    jet.hessian[2] = mm * hyy;
  }
  return jet;
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineCore
  \brief a polynomial patch of total degree `m` over a domain triangle \f$(r,s,t)\f$ of the
  plane, given by its Bézier control net \f$b_{i,j,k} = f(r^i s^j t^k)\f$ (Xu, Lemma 2.7.1).

  Every construction here (blossom, de Casteljau evaluation, derivatives, subdivision,
  degree elevation, re-expression) is a rational function of the control points and the
  domain points, so with an exact number type every result is exact. Only the
  differential-geometric quantities (`normal()`, curvatures) need square roots; they are
  computed in `double` from exact derivatives.

  \tparam GeomTraits a model of `Kernel` providing `Point_2`, `Vector_2` and `FT`, e.g.
  `CGAL::Exact_predicates_inexact_constructions_kernel` (fast) or
  `CGAL::Simple_cartesian<CGAL::Exact_rational>` (exact).
  \tparam Value the control value type (see `Value_traits`): `GeomTraits::FT` for a
  functional (height) patch, `GeomTraits::Vector_3` for a parametric patch.
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
class Bezier_triangle {
public:
  /// \name Types
  /// @{

  /// the kernel
  using Geom_traits = GeomTraits;
  /// the number type
  using FT = typename Geom_traits::FT;
  /// the point type of the domain plane
  using Point_2 = typename Geom_traits::Point_2;
  /// the vector type of the domain plane
  using Vector_2 = typename Geom_traits::Vector_2;
  /// the control value type
  using Value_type = Value;
  /// barycentric weights of a point (sum 1) or of a vector (sum 0)
  using Weights = std::array<FT, 3>;
  /// @}

  static_assert(std::is_same<typename Value_traits<Value>::FT, FT>::value,
                "the control values must be built from the kernel's number type");

  /// \name Creation
  /// @{

  /*!
    creates the patch of degree `degree` over the triangle `(r, s, t)` with the control
    points `net` given in Xu's Table 2.3 order (see `linear_index()`).
    \throws Invalid_input if the triangle is degenerate (decided with the kernel's exact
    collinearity predicate), a coordinate or control value is not finite, `degree < 0`, or
    `net` does not hold \f$(m+1)(m+2)/2\f$ values.
    \param degree the degree
    \param r the first corner of the domain triangle
    \param s the second corner of the domain triangle
    \param t the third corner of the domain triangle
    \param net the control values, \f$(m+1)(m+2)/2\f$ of them for degree \f$m\f$
    \param traits the geometric traits
  */
  Bezier_triangle(int degree, const Point_2& r, const Point_2& s, const Point_2& t,
                  std::vector<Value> net, const Geom_traits& traits = Geom_traits())
      : m_degree(degree), m_vertices{{r, s, t}}, m_net(std::move(net)), m_traits(traits) {
    if (degree < 0)
      throw Invalid_input("Bézier triangle: negative degree " + std::to_string(degree));
    if (m_net.size() != number_of_control_points(degree))
      throw Invalid_input("Bézier triangle: a degree " + std::to_string(degree) + " net needs " +
                          std::to_string(number_of_control_points(degree)) +
                          " control points, got " + std::to_string(m_net.size()));
    for (const Value& v : m_net)
      if (!is_finite_value(v))
        throw Invalid_input("Bézier triangle: non-finite control value");
    set_domain(r, s, t);
  }

  /*!
    creates the patch of degree `degree` over `(r, s, t)` whose control points are the
    values `blossom(r^i s^j t^k)` of a symmetric multi-affine function; `blossom` is called
    with a `std::vector<Point_2>` of `degree` points.
    \tparam Blossom a callable taking a `std::vector<Point_2>` and returning a `Value`
    \param degree the degree
    \param r the first corner of the domain triangle
    \param s the second corner of the domain triangle
    \param t the third corner of the domain triangle
    \param blossom the symmetric multi-affine function, called with a `std::vector<Point_2>`
    \param traits the geometric traits
    \returns the patch whose control points are the blossom values
  */
  template <class Blossom>
  static Bezier_triangle from_blossom(int degree, const Point_2& r, const Point_2& s,
                                      const Point_2& t, const Blossom& blossom,
                                      const Geom_traits& traits = Geom_traits()) {
    std::vector<Value> net;
    net.reserve(number_of_control_points(degree));
    std::vector<Point_2> arguments(static_cast<std::size_t>(degree < 0 ? 0 : degree));
    for (const Multi_index& index : multi_indices(degree)) {
      std::size_t a = 0;
      for (int c = 0; c < index.i; ++c)
        arguments[a++] = r;
      for (int c = 0; c < index.j; ++c)
        arguments[a++] = s;
      for (int c = 0; c < index.k; ++c)
        arguments[a++] = t;
      net.push_back(blossom(arguments));
    }
    return Bezier_triangle(degree, r, s, t, std::move(net), traits);
  }
  /// @}

  /// \name Access
  /// @{

  /// returns the degree `m`.
  /// \returns the degree `m`
  int degree() const { return m_degree; }
  /// returns domain vertex `v` (0: r, 1: s, 2: t).
  /// \param v the index of a vertex
  /// \returns domain vertex `v` (0: r, 1: s, 2: t)
  const Point_2& vertex(int v) const { return m_vertices[static_cast<std::size_t>(v)]; }
  /// returns the three domain vertices.
  /// \returns the three domain vertices
  const std::array<Point_2, 3>& vertices() const { return m_vertices; }
  /// returns the control net in Xu's Table 2.3 order.
  /// \returns the control net in Xu's Table 2.3 order
  const std::vector<Value>& control_points() const { return m_net; }
  /// returns \f$b_{i,j,k}\f$.
  /// \param index the multi-index of a control point
  /// \returns \f$b_{i,j,k}\f$
  const Value& control_point(const Multi_index& index) const {
    check_index(index);
    return m_net[linear_index(index)];
  }
  /// returns \f$b_{i,j,k}\f$.
  /// \param i the first index of \f$b_{i,j,k}\f$
  /// \param j the second index of \f$b_{i,j,k}\f$
  /// \param k the third index of \f$b_{i,j,k}\f$, with \f$i + j + k\f$ = `degree()`
  /// \returns \f$b_{i,j,k}\f$
  const Value& control_point(int i, int j, int k) const {
    return control_point(Multi_index{i, j, k});
  }
  /// replaces \f$b_{i,j,k}\f$ by `value`.
  /// \param index the multi-index of a control point
  /// \param value the new control value
  void set_control_point(const Multi_index& index, const Value& value) {
    check_index(index);
    if (!is_finite_value(value))
      throw Invalid_input("Bézier triangle: non-finite control value");
    m_net[linear_index(index)] = value;
  }
  /// returns the geometric traits.
  /// \returns the geometric traits
  const Geom_traits& geom_traits() const { return m_traits; }
  /// @}

  /// \name Barycentric coordinates
  /// @{

  /// returns the barycentric coordinates \f$(\lambda,\mu,\nu)\f$ of `a` with respect to
  /// \f$(r,s,t)\f$, so that \f$a = \lambda r + \mu s + \nu t\f$ (ratios of 2x2 determinants).
  /// \param a the point of the domain plane
  /// \returns the barycentric coordinates \f$(\lambda,\mu,\nu)\f$ of `a` with respect to
  /// \f$(r,s,t)\f$, so that \f$a = \lambda r + \mu s + \nu t\f$ (ratios of 2x2 determinants)
  Weights barycentric_coordinates(const Point_2& a) const {
    const FT mu = determinant(a - m_vertices[0], m_vertices[2] - m_vertices[0]) * m_inverse_area2;
    const FT nu = determinant(m_vertices[1] - m_vertices[0], a - m_vertices[0]) * m_inverse_area2;
    return Weights{{FT(1) - mu - nu, mu, nu}};
  }

  /// returns the barycentric coordinates of the vector `u` (they sum to zero).
  /// \param u the vector
  /// \returns the barycentric coordinates of the vector `u` (they sum to zero)
  Weights barycentric_direction(const Vector_2& u) const {
    const FT mu = determinant(u, m_vertices[2] - m_vertices[0]) * m_inverse_area2;
    const FT nu = determinant(m_vertices[1] - m_vertices[0], u) * m_inverse_area2;
    return Weights{{-mu - nu, mu, nu}};
  }
  /// @}

  /// \name Evaluation
  /// @{

  /*!
    returns the blossom (polar form) \f$f(a_1,\dots,a_m)\f$, each argument given by its
    barycentric weights; weights summing to 0 stand for vectors (the linear extension of
    the blossom, used for derivatives). De Casteljau's algorithm with distinct arguments.
    \throws Invalid_input if `arguments.size() != degree()`
    \param arguments the blossom arguments, one per degree
    \returns the blossom (polar form) \f$f(a_1,\dots,a_m)\f$, each argument given by its barycentric
    weights
  */
  Value blossom_barycentric(const std::vector<Weights>& arguments) const {
    if (arguments.size() != static_cast<std::size_t>(m_degree))
      throw Invalid_input("blossom: a degree " + std::to_string(m_degree) + " blossom takes " +
                          std::to_string(m_degree) + " arguments, got " +
                          std::to_string(arguments.size()));
    internal::Scratch_net<Value> net(m_net.begin(), m_net.end());
    for (int l = 0; l < m_degree; ++l)
      internal::de_casteljau_step(net, m_degree - l, arguments[static_cast<std::size_t>(l)]);
    return net[0];
  }

  /// returns the blossom \f$f(a_1,\dots,a_m)\f$ at the points `arguments`.
  /// \throws Invalid_input if `arguments.size() != degree()`
  /// \param arguments the blossom arguments, one per degree
  /// \returns the blossom \f$f(a_1,\dots,a_m)\f$ at the points `arguments`
  Value blossom(const std::vector<Point_2>& arguments) const {
    std::vector<Weights> weights;
    weights.reserve(arguments.size());
    for (const Point_2& a : arguments)
      weights.push_back(barycentric_coordinates(a));
    return blossom_barycentric(weights);
  }

  /// returns \f$F(a) = f(a,\dots,a)\f$ by de Casteljau's algorithm.
  /// \param a the point of the domain plane
  /// \returns \f$F(a) = f(a,\dots,a)\f$ by de Casteljau's algorithm
  Value evaluate(const Point_2& a) const {
    return evaluate_barycentric(barycentric_coordinates(a));
  }

  /// returns \f$F(a)\f$ for `a` given by its barycentric coordinates.
  /// \param w the barycentric coordinates of the point
  /// \returns \f$F(a)\f$ for `a` given by its barycentric coordinates
  Value evaluate_barycentric(const Weights& w) const {
    internal::Scratch_net<Value> net(m_net.begin(), m_net.end());
    for (int l = 0; l < m_degree; ++l)
      internal::de_casteljau_step(net, m_degree - l, w);
    return net[0];
  }

  /// returns \f$F(a)\f$ evaluated as the Bernstein sum
  /// \f$\sum \frac{m!}{i!j!k!}\lambda^i\mu^j\nu^k b_{i,j,k}\f$ (an independent formula,
  /// used to cross-check de Casteljau and in benchmarks).
  /// \param a the point of the domain plane
  /// \returns \f$F(a)\f$ evaluated as the Bernstein sum \f$\sum
  /// \frac{m!}{i!j!k!}\lambda^i\mu^j\nu^k b_{i,j,k}\f$ (an independent formula, used to cross-check
  /// de Casteljau and in benchmarks)
  Value evaluate_bernstein(const Point_2& a) const {
    const Weights w = barycentric_coordinates(a);
    std::array<std::vector<FT>, 3> powers;
    for (int c = 0; c < 3; ++c) {
      powers[c].assign(static_cast<std::size_t>(m_degree + 1), FT(1));
      for (int e = 1; e <= m_degree; ++e)
        powers[c][e] = powers[c][e - 1] * w[c];
    }
    const std::vector<FT> factorial = factorials(m_degree);
    Value sum = Value_traits<Value>::zero();
    for (const Multi_index& index : multi_indices(m_degree)) {
      const FT coefficient = factorial[m_degree] /
                             (factorial[index.i] * factorial[index.j] * factorial[index.k]) *
                             powers[0][index.i] * powers[1][index.j] * powers[2][index.k];
      sum = sum + coefficient * m_net[linear_index(index)];
    }
    return sum;
  }

  /*!
    returns the mixed directional derivative \f$D_{u_1}\cdots D_{u_k}F(a) =
    \frac{m!}{(m-k)!} f(u_1,\dots,u_k,a^{m-k})\f$; zero when `k > m`.
    \param a the point at which the derivative is taken
    \param directions the directions \f$u_1,\dots,u_k\f$
    \returns the mixed directional derivative \f$D_{u_1}\cdots D_{u_k}F(a) = \frac{m!}{(m-k)!}
    f(u_1,\dots,u_k,a^{m-k})\f$
  */
  Value directional_derivative(const Point_2& a, const std::vector<Vector_2>& directions) const {
    const std::size_t order = directions.size();
    if (order > static_cast<std::size_t>(m_degree))
      return Value_traits<Value>::zero();
    std::vector<Weights> arguments(static_cast<std::size_t>(m_degree), barycentric_coordinates(a));
    FT scale(1);
    for (std::size_t d = 0; d < order; ++d) {
      arguments[d] = barycentric_direction(directions[d]);
      scale = scale * FT(m_degree - static_cast<int>(d));
    }
    const Value polar = blossom_barycentric(arguments);
    return scale * polar;
  }

  /*!
    returns the value, gradient and Hessian of \f$F\f$ at the point with barycentric
    coordinates `w`, with respect to the domain coordinates \f$(x, y)\f$. Derivatives of
    order above `order` (0, 1 or 2) are set to zero and not computed.

    One pass of \f$m-2\f$ de Casteljau steps gives the quadratic net of
    \f$f(\cdot, \cdot, a^{m-2})\f$; its blossom at \f$(u, v)\f$ times \f$m(m-1)\f$ is
    \f$D_uD_vF(a)\f$, and at \f$(u, a)\f$ times \f$m\f$ is \f$D_uF(a)\f$. The cost is that of
    one evaluation plus a constant, and every result is a rational function of the control
    points, `w` and the vertices: exact for an exact `FT`.
    \param w the barycentric coordinates of the point
    \param order the highest derivative order computed (0, 1 or 2)
    \returns the value, gradient and Hessian of \f$F\f$ at the point with barycentric coordinates
    `w`, with respect to the domain coordinates \f$(x, y)\f$
  */
  Point_jet<Value> jet_barycentric(const Weights& w, int order = 2) const {
    // barycentric directions of the unit vectors e_x and e_y
    const Weights dx = barycentric_direction(Vector_2(FT(1), FT(0)));
    const Weights dy = barycentric_direction(Vector_2(FT(0), FT(1)));
    internal::Scratch_net<Value> net(m_net.begin(), m_net.end());
    return internal::jet_of_net(net, m_degree, w, dx, dy, order);
  }

  /// returns the value, gradient and Hessian of \f$F\f$ at `a` (see `jet_barycentric()`).
  /// \param a the point of the domain plane
  /// \param order the highest derivative order computed (0, 1 or 2)
  /// \returns the value, gradient and Hessian of \f$F\f$ at `a` (see `jet_barycentric()`)
  Point_jet<Value> jet(const Point_2& a, int order = 2) const {
    return jet_barycentric(barycentric_coordinates(a), order);
  }

  /// returns the partial derivative \f$\partial^{p+q}F / \partial x^p \partial y^q\f$ at `a`
  /// (domain coordinates).
  /// \param a the point of the domain plane
  /// \param p the order of differentiation in \f$x\f$
  /// \param q the order of differentiation in \f$y\f$
  /// \returns the partial derivative \f$\partial^{p+q}F / \partial x^p \partial y^q\f$ at `a`
  /// (domain coordinates)
  Value partial_derivative(const Point_2& a, int p, int q) const {
    if (p < 0 || q < 0)
      throw Invalid_input("partial derivative: negative order");
    std::vector<Vector_2> directions;
    directions.insert(directions.end(), static_cast<std::size_t>(p), Vector_2(FT(1), FT(0)));
    directions.insert(directions.end(), static_cast<std::size_t>(q), Vector_2(FT(0), FT(1)));
    return directional_derivative(a, directions);
  }
  /// @}

  /// \name Subdivision and change of representation
  /// @{

  /*!
    returns the patch re-expressed over another domain triangle `(r2, s2, t2)`: the net
    \f$f(r_2^i s_2^j t_2^k)\f$ of the same polynomial (the triangle need not overlap the
    original one).
    \throws Invalid_input if `(r2, s2, t2)` is degenerate.
    \param r2 the first corner of the new triangle
    \param s2 the second corner of the new triangle
    \param t2 the third corner of the new triangle
    \returns the re-expressed patch
  */
  Bezier_triangle reexpress(const Point_2& r2, const Point_2& s2, const Point_2& t2) const {
    const Weights wr = barycentric_coordinates(r2), ws = barycentric_coordinates(s2),
                  wt = barycentric_coordinates(t2);
    std::vector<Value> result(m_net.size(), Value_traits<Value>::zero());
    // Apply t2 k times, then s2 j times, then r2 i times: each stage reuses the last.
    internal::Scratch_net<Value> after_t(m_net.begin(), m_net.end());
    for (int k = 0; k <= m_degree; ++k) {
      if (k > 0)
        internal::de_casteljau_step(after_t, m_degree - k + 1, wt);
      internal::Scratch_net<Value> after_s = after_t;
      for (int j = 0; j <= m_degree - k; ++j) {
        if (j > 0)
          internal::de_casteljau_step(after_s, m_degree - k - j + 1, ws);
        const int i = m_degree - k - j;
        internal::Scratch_net<Value> after_r = after_s;
        for (int l = 0; l < i; ++l)
          internal::de_casteljau_step(after_r, i - l, wr);
        result[linear_index(i, j, m_degree)] = after_r[0];
      }
    }
    return Bezier_triangle(m_degree, r2, s2, t2, std::move(result), m_traits);
  }

  /*!
    returns the three patches over \f$(a,s,t)\f$, \f$(r,a,t)\f$ and \f$(r,s,a)\f$ read off
    the de Casteljau tetrahedron at `a` (Xu §2.7.4). For `a` inside the triangle they tile
    it with the orientation of the original.
    \throws Invalid_input if `a` lies on the line of an edge (a sub-triangle would be flat).
    \param a the point of the domain plane
    \returns the three patches over \f$(a,s,t)\f$, \f$(r,a,t)\f$ and \f$(r,s,a)\f$
  */
  std::array<Bezier_triangle, 3> split(const Point_2& a) const {
    const Weights w = barycentric_coordinates(a);
    if (CGAL::is_zero(w[0]) || CGAL::is_zero(w[1]) || CGAL::is_zero(w[2]))
      throw Invalid_input("split: the point " + internal::point_to_string(a) +
                          " lies on the line of an edge of the domain triangle");
    // layers[l] is the degree m-l net of f(a^l, .).
    std::vector<std::vector<Value>> layers{m_net};
    for (int l = 1; l <= m_degree; ++l) {
      layers.push_back(layers.back());
      internal::de_casteljau_step(layers.back(), m_degree - l + 1, w);
    }
    const std::size_t n = m_net.size();
    std::vector<Value> ast(n), rat(n), rsa(n);
    for (const Multi_index& index : multi_indices(m_degree)) {
      const std::size_t at = linear_index(index);
      // over (a,s,t): f(a^i s^j t^k) = layer i at (0, j)
      ast[at] = layers[index.i][linear_index(0, index.j, m_degree - index.i)];
      // over (r,a,t): f(r^i a^j t^k) = layer j at (i, 0)
      rat[at] = layers[index.j][linear_index(index.i, 0, m_degree - index.j)];
      // over (r,s,a): f(r^i s^j a^k) = layer k at (i, j)
      rsa[at] = layers[index.k][linear_index(index.i, index.j, m_degree - index.k)];
    }
    const Point_2 &r = m_vertices[0], &s = m_vertices[1], &t = m_vertices[2];
    return {{Bezier_triangle(m_degree, a, s, t, std::move(ast), m_traits),
             Bezier_triangle(m_degree, r, a, t, std::move(rat), m_traits),
             Bezier_triangle(m_degree, r, s, a, std::move(rsa), m_traits)}};
  }

  /*!
    returns the four patches of the midpoint subdivision (Xu §2.7.4, Fig. 2.5), over
    \f$(r,c,b)\f$, \f$(c,s,a)\f$, \f$(b,a,t)\f$ and \f$(a,b,c)\f$ where \f$a,b,c\f$ are
    the midpoints of \f$st, tr, rs\f$. All four keep the orientation of the original.
    \returns the four sub-patches
  */
  std::array<Bezier_triangle, 4> subdivide() const {
    const Point_2 &r = m_vertices[0], &s = m_vertices[1], &t = m_vertices[2];
    const auto midpoint = m_traits.construct_midpoint_2_object();
    const Point_2 a = midpoint(s, t), b = midpoint(t, r), c = midpoint(r, s);
    return {{reexpress(r, c, b), reexpress(c, s, a), reexpress(b, a, t), reexpress(a, b, c)}};
  }

  /*!
    returns the same polynomial as a patch of degree `m + 1`:
    \f$b'_{i,j,k} = (i\,b_{i-1,j,k} + j\,b_{i,j-1,k} + k\,b_{i,j,k-1})/(m+1)\f$.
    \returns the same polynomial as a patch of degree `m + 1`
  */
  Bezier_triangle elevate_degree() const {
    const int n = m_degree + 1;
    std::vector<Value> result;
    result.reserve(number_of_control_points(n));
    const FT inverse = FT(1) / FT(n);
    for (const Multi_index& index : multi_indices(n)) {
      Value v = Value_traits<Value>::zero();
      if (index.i > 0)
        v = v + FT(index.i) * m_net[linear_index(index.i - 1, index.j, m_degree)];
      if (index.j > 0)
        v = v + FT(index.j) * m_net[linear_index(index.i, index.j - 1, m_degree)];
      if (index.k > 0)
        v = v + FT(index.k) * m_net[linear_index(index.i, index.j, m_degree)];
      result.push_back(inverse * v);
    }
    return Bezier_triangle(n, m_vertices[0], m_vertices[1], m_vertices[2], std::move(result),
                           m_traits);
  }
  /// @}

private:
  static FT determinant(const Vector_2& u, const Vector_2& v) {
    return u.x() * v.y() - u.y() * v.x();
  }

  static std::vector<FT> factorials(int n) {
    std::vector<FT> f(static_cast<std::size_t>(n + 1), FT(1));
    for (int i = 1; i <= n; ++i)
      f[i] = f[i - 1] * FT(i);
    return f;
  }

  // The test inline, the message out of line: every control-point read of the checks calls it.
  void check_index(const Multi_index& index) const {
    if (index.i < 0 || index.j < 0 || index.k < 0 || index.degree() != m_degree)
      throw_bad_index(index);
  }
  [[noreturn]] void throw_bad_index(const Multi_index& index) const {
    throw Invalid_input("Bézier triangle: multi-index (" + std::to_string(index.i) + "," +
                        std::to_string(index.j) + "," + std::to_string(index.k) +
                        ") is not in Delta_" + std::to_string(m_degree));
  }

  void set_domain(const Point_2& r, const Point_2& s, const Point_2& t) {
    for (const Point_2& p : m_vertices)
      if (!CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y()))
        throw Invalid_input("Bézier triangle: non-finite domain vertex " +
                            internal::point_to_string(p));
    // orientation_2, not collinear_2: the same exact test, statically filtered by Epick (a
    // patch is built per face and per edge side by the checks of a c1 run)
    if (m_traits.orientation_2_object()(r, s, t) == CGAL::COLLINEAR)
      throw Invalid_input("Bézier triangle: degenerate domain triangle " +
                          internal::point_to_string(r) + ", " + internal::point_to_string(s) +
                          ", " + internal::point_to_string(t) + " (collinear corners)");
    const FT area2 = determinant(s - r, t - r);
    // Exact predicates said non-degenerate; in double the determinant may still round to
    // zero or overflow for extreme coordinates, which would poison every barycentric weight.
    if (CGAL::is_zero(area2) || !CGAL::is_finite(area2))
      throw Invalid_input("Bézier triangle: the domain triangle " + internal::point_to_string(r) +
                          ", " + internal::point_to_string(s) + ", " +
                          internal::point_to_string(t) +
                          " is too thin or too large for the number type");
    m_inverse_area2 = FT(1) / area2;
  }

  int m_degree;
  std::array<Point_2, 3> m_vertices;
  std::vector<Value> m_net;
  Geom_traits m_traits;
  FT m_inverse_area2;
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns `patch` with its domain and control values converted to the kernel `K2`
  (e.g. from `double` to `CGAL::Exact_rational`, which is exact).
  \tparam K2 the target kernel; `V2` the target value type (defaults to the value type of
  the same kind: `K2::FT` for functional patches).
  \tparam V2 the target value type
  \tparam K1 the source kernel
  \tparam V1 the source value type
  \param patch the patch to convert
  \returns `patch` with its domain and control values converted to the kernel `K2` (e.g. from
  `double` to `CGAL::Exact_rational`, which is exact)
*/
template <class K2, class V2 = void, class K1, class V1>
auto convert_patch(const Bezier_triangle<K1, V1>& patch) {
  using Target_value = std::conditional_t<
      std::is_void<V2>::value,
      std::conditional_t<std::is_same<V1, typename K1::FT>::value, typename K2::FT,
                         std::conditional_t<std::is_same<V1, typename K1::Vector_3>::value,
                                            typename K2::Vector_3, typename K2::Vector_2>>,
      V2>;
  const CGAL::Cartesian_converter<K1, K2> convert;
  std::vector<Target_value> net;
  net.reserve(patch.control_points().size());
  for (const V1& v : patch.control_points())
    net.push_back(convert(v));
  return Bezier_triangle<K2, Target_value>(patch.degree(), convert(patch.vertex(0)),
                                           convert(patch.vertex(1)), convert(patch.vertex(2)),
                                           std::move(net));
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BEZIER_TRIANGLE_H

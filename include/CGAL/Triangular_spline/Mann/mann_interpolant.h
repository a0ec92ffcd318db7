// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_MANN_MANN_INTERPOLANT_H
#define CGAL_TRIANGULAR_SPLINE_MANN_MANN_INTERPOLANT_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Mann/Continuity_adjustment.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Patch_network.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/mann_vertex_jets.h>

#include <CGAL/Algebraic_structure_traits.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineMann
  \brief returns \f$\lfloor 2n/3 \rfloor\f$, the highest order of vertex derivatives that
  Mann's degree-\f$n\f$ interpolant uses (Mann §3).

  A control point \f$b_{ijk}\f$ is set from the vertex with the largest index, which is at
  least \f$\lceil n/3\rceil\f$; the blossom of a Taylor polynomial centred at that vertex
  with that many arguments at the vertex depends on derivatives up to order
  \f$n - \lceil n/3\rceil = \lfloor 2n/3 \rfloor\f$ only.
  \param degree the degree \f$n\f$ of the interpolant
  \returns \f$\lfloor 2n/3 \rfloor\f$, the highest order of vertex derivatives that Mann's
  degree-\f$n\f$ interpolant uses (Mann §3)
*/
constexpr int mann_derivative_order(int degree) {
  return 2 * degree / 3;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief returns the Taylor polynomial of `f` at `center`, in the local variables
  \f$(u, v) = (x - c_x, y - c_y)\f$: the coefficient of \f$u^p v^q\f$ is
  \f$\partial^{p+q} f(c) / (\partial x^p \partial y^q\, p!\, q!)\f$. It is `f` itself,
  written around `center` (exact with an exact number type).

  This is the form in which `mann_interpolant()` takes vertex data: centred polynomials
  keep the blossoms well conditioned in `double` far from the origin.
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param f the index of a face
  \param center the point of expansion \f$c\f$
  \returns the Taylor polynomial of `f` at `center`, in the local variables \f$(u, v)\f$
*/
template <class GeomTraits, class Value>
Polynomial_surface<GeomTraits, Value>
taylor_polynomial(const Polynomial_surface<GeomTraits, Value>& f,
                  const typename GeomTraits::Point_2& center) {
  using FT = typename GeomTraits::FT;
  Polynomial_surface<GeomTraits, Value> result(f.degree());
  for (int p = 0; p <= f.degree(); ++p)
    for (int q = 0; p + q <= f.degree(); ++q) {
      FT factorials(1);
      for (int e = 2; e <= p; ++e)
        factorials = factorials * FT(e);
      for (int e = 2; e <= q; ++e)
        factorials = factorials * FT(e);
      const Value derivative = f.derivative(p, q).evaluate(center);
      result.set_coefficient(p, q, (FT(1) / factorials) * derivative);
    }
  return result;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief returns the Taylor polynomial of order `order` built from partial derivatives, in
  the local variables centred at the point where they were taken: the coefficient of
  \f$u^p v^q\f$ is `derivative(p, q)` \f$/ (p!\, q!)\f$.
  \tparam Derivative a callable `derivative(p, q)` returning
  \f$\partial^{p+q} f / \partial x^p \partial y^q\f$ at the point, as a `Value`
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param order the order of the Taylor polynomial
  \param derivative the callable `derivative(p, q)` returning the partial derivatives
  \returns the Taylor polynomial of order `order` built from partial derivatives, in the local
  variables centred at the point where they were taken
*/
template <class GeomTraits, class Value = typename GeomTraits::FT, class Derivative>
Polynomial_surface<GeomTraits, Value>
taylor_polynomial_from_derivatives(int order, const Derivative& derivative) {
  using FT = typename GeomTraits::FT;
  if (order < 0)
    throw Invalid_input("Taylor polynomial: negative order " + std::to_string(order));
  Polynomial_surface<GeomTraits, Value> result(order);
  for (int p = 0; p <= order; ++p)
    for (int q = 0; p + q <= order; ++q) {
      FT factorials(1);
      for (int e = 2; e <= p; ++e)
        factorials = factorials * FT(e);
      for (int e = 2; e <= q; ++e)
        factorials = factorials * FT(e);
      const Value d = derivative(p, q);
      result.set_coefficient(p, q, (FT(1) / factorials) * d);
    }
  return result;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief returns Mann's \f$C^0\f$ network of degree `degree` set from vertex data (Mann §3,
  Fig. 11): `patches[f]` is over the corners of face `f` in `domain.face(f)` order.

  Each control point \f$b_{ijk}\f$ of a face with corners \f$(V_0, V_1, V_2)\f$ is the
  blossom \f$T_a(V_0^i V_1^j V_2^k)\f$ of the Taylor polynomial of the vertex \f$a\f$ with
  the largest index among \f$i, j, k\f$ (the nearest vertex: the control points of each
  corner form the region of Fig. 11); where two or three indices tie for the largest the
  values computed from those vertices are averaged. A boundary point depends only on the
  data of the edge's two vertices and on the points of the edge, so adjacent patches share
  their boundary control points: the network is \f$C^0\f$ (bit for bit, also in `double`:
  the arguments are passed in a canonical order). If all the Taylor polynomials are those
  of one polynomial of degree at most \f$n\f$ at the vertices, every patch is that
  polynomial (polynomial precision of degree \f$n\f$).

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` or a vector type (see `Value_traits`)
  \param domain the domain triangulation
  \param jets `jets[v]` is the Taylor polynomial of the data at vertex `v` in variables
  centred at the vertex (see `taylor_polynomial()`), of degree between
  `mann_derivative_order(degree)` and `degree`
  \param degree the patch degree \f$n \ge 1\f$
  \throws Invalid_input if `jets` does not hold one polynomial per vertex or one has a
  degree outside that range (derivatives missing or too many)
  \returns Mann's \f$C^0\f$ network of degree `degree` set from vertex data (Mann §3, Fig. 11)
*/
template <class GeomTraits, class Value>
std::vector<Bezier_triangle<GeomTraits, Value>>
mann_c0_network(const Planar_domain<GeomTraits>& domain,
                const std::vector<Polynomial_surface<GeomTraits, Value>>& jets, int degree) {
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Index = std::uint32_t;
  internal::check_vertex_jets(domain, jets, degree);
  const FT half = FT(1) / FT(2), third = FT(1) / FT(3);
  std::vector<Bezier_triangle<GeomTraits, Value>> patches;
  patches.reserve(domain.number_of_faces());
  std::vector<Point_2> arguments(static_cast<std::size_t>(degree));
  std::vector<Value> net;
  for (Index f = 0; f < domain.number_of_faces(); ++f) {
    const std::array<Index, 3>& t = domain.face(f);
    // Corners sorted by global index: the argument order of every blossom, and the order in
    // which tied values are summed, are then the same in both faces of an edge.
    std::array<int, 3> order{{0, 1, 2}};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return t[a] < t[b]; });
    net.clear();
    net.reserve(number_of_control_points(degree));
    for (const Multi_index& index : multi_indices(degree)) {
      const int largest = (std::max)({index.i, index.j, index.k});
      Value sum = Value_traits<Value>::zero();
      int owners = 0;
      for (int o : order) {
        if (index[o] != largest)
          continue;
        const Point_2& center = domain.point(t[std::size_t(o)]);
        std::size_t a = 0;
        for (int c : order) {
          const Point_2& corner = domain.point(t[std::size_t(c)]);
          const Point_2 local(corner.x() - center.x(), corner.y() - center.y());
          for (int copy = 0; copy < index[c]; ++copy)
            arguments[a++] = local;
        }
        const Value value = jets[t[std::size_t(o)]].blossom(arguments);
        if (owners++ == 0)
          sum = value;
        else
          sum = sum + value;
      }
      if (owners == 1)
        net.push_back(sum);
      else
        net.push_back((owners == 2 ? half : third) * sum);
    }
    patches.emplace_back(degree, domain.point(t[0]), domain.point(t[1]), domain.point(t[2]), net);
  }
  return patches;
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief Mann's interpolant: the domain, the patches (`patch(f)` over the corners of face
  `f` in `domain().face(f)` order, all of degree `degree()`) and what the continuity
  adjustment moved.
  \cgalModels `TriangularSplineNetwork`
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
struct Mann_interpolant : Patch_network<GeomTraits, Value> {
  /// takes the adjusted network, its order and what the adjustment moved
  /// \param network the spline network
  /// \param continuity the order \f$k\f$ of continuity reached
  /// \param adjustment what the adjustment moved
  Mann_interpolant(Patch_network<GeomTraits, Value> network, int continuity,
                   Network_adjustment adjustment)
      : Patch_network<GeomTraits, Value>(std::move(network)), continuity(continuity),
        adjustment(std::move(adjustment)) {}
  int continuity = 0;            ///< the order \f$k\f$ reached across every interior edge
  Network_adjustment adjustment; ///< the control points moved from the \f$C^0\f$ network
};

/*!
  \ingroup PkgTriangularSplineMann
  \brief builds Mann's simple interpolant (Mann §3): the \f$C^0\f$ network of
  `mann_c0_network()`, raised to \f$C^k\f$ by `adjust_network()`.

  The result interpolates the data at the vertices (each corner control point is the
  vertex's value; the derivatives of order \f$\le 2k\f$ at the vertices are those of the
  data, since the corner regions are left untouched), meets \f$C^k\f$ across every interior
  edge (exactly with an exact number type), and reproduces every polynomial of degree
  \f$\le n\f$: such data gives a network cut from one polynomial, which the adjustment
  leaves unchanged. For the default quintic, \f$k = 1\f$: a \f$C^1\f$ interpolant with
  quintic precision, built from derivatives up to order 3 at the vertices.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param domain the domain triangulation
  \param jets the vertex data, as for `mann_c0_network()`
  \param degree the patch degree \f$n\f$
  \param continuity the order \f$k\f$; \f$-1\f$ (the default) means the highest the degree
  allows, \f$\lfloor (n-1)/4 \rfloor\f$
  \param tolerance passed to `adjust_network()` (inexact number types only)
  \throws Invalid_input for bad vertex data (see `mann_c0_network()`), or if \f$n < 4k+1\f$
  \returns the interpolant
*/
template <class GeomTraits, class Value>
Mann_interpolant<GeomTraits, Value>
mann_interpolant(const Planar_domain<GeomTraits>& domain,
                 const std::vector<Polynomial_surface<GeomTraits, Value>>& jets, int degree = 5,
                 int continuity = -1, double tolerance = 1e-9) {
  if (continuity < -1)
    throw Invalid_input("Mann interpolant: negative continuity order " +
                        std::to_string(continuity));
  const int k = continuity == -1 ? (std::max)(0, (degree - 1) / 4) : continuity;
  if (degree < minimum_degree_for_network_continuity(k))
    throw Invalid_input("Mann interpolant: C^" + std::to_string(k) +
                        " needs degree at least 4k+1 = " +
                        std::to_string(minimum_degree_for_network_continuity(k)) + ", got " +
                        std::to_string(degree) + " (Mann 3.1)");
  Patch_network<GeomTraits, Value> network(domain, mann_c0_network(domain, jets, degree));
  Network_adjustment adjustment = adjust_network(network.domain(), network.patches(), k, tolerance);
  return Mann_interpolant<GeomTraits, Value>(std::move(network), k, std::move(adjustment));
}

/*!
  \ingroup PkgTriangularSplineMann
  \brief <b>estimates</b> the partial derivatives up to order `order` of scattered data at
  every vertex, by local polynomial least squares; returns one Taylor polynomial per vertex
  in variables centred at the vertex (the form `mann_interpolant()` takes).

  For vertex \f$v\f$, the neighbourhood grows ring by ring (neighbours, their neighbours, ...)
  until it holds at least \f$\lceil 3u/2 \rceil\f$ other vertices, \f$u = (d+1)(d+2)/2 - 1\f$
  for \f$d\f$ = `order`, and the monomials \f$u^p v^q\f$, \f$1 \le p + q \le d\f$, are linearly
  independent on it (the neighbourhood is unisolvent); then the polynomial of degree \f$d\f$
  through \f$(v, z_v)\f$ closest in weighted least squares to the neighbours' values is the
  estimate. The weight of a neighbour at distance \f$\delta\f$ is
  \f$\big((\rho^2 - \delta^2)/(\rho^2 \delta^2)\big)^2\f$ with \f$\rho^2\f$ 1.1 times the
  largest squared distance in the neighbourhood: Renka's weights of CSHEP (TOMS 660) written
  in squared distances, so that they are rational; near points count most. The value at the
  vertex is kept exactly, so an interpolant built from the estimates interpolates the data.
  Coordinates are scaled by the neighbourhood's extent before the solve (Householder QR with
  column pivoting in `double`; exact normal equations with an exact number type, whose cost
  grows quickly with `order` and the size of the input coordinates' rationals).

  The result is only an estimate of the derivatives of the function the data was sampled
  from, except for data from a polynomial of degree at most `order`, which it reproduces
  (exactly with an exact number type).

  \tparam GeomTraits a model of `Kernel`
  \param domain the domain triangulation; neighbourhoods follow its edges
  \param values `values[v]` is the datum at vertex `v`
  \param order the highest derivative order \f$d\f$, \f$0 \le d \le 10\f$
  \param degrees if not null, receives for each vertex the degree actually fitted: lower
  than `order` where the vertex's whole connected component has too few vertices, or
  vertices too special (all on a conic for \f$d = 2\f$, ...), to determine a polynomial of
  degree `order`; the degree is then lowered until they do (a plane through three points,
  a constant for fewer), and the higher derivatives are zero
  \throws Invalid_input if `values` does not hold one value per vertex or `order` is out of
  range
  \returns one Taylor polynomial per vertex in variables centred at the vertex (the form
  `mann_interpolant()` takes)
*/
template <class GeomTraits>
std::vector<Polynomial_surface<GeomTraits>>
estimate_vertex_derivatives(const Planar_domain<GeomTraits>& domain,
                            const std::vector<typename GeomTraits::FT>& values, int order,
                            std::vector<int>* degrees = nullptr) {
  using FT = typename GeomTraits::FT;
  using Index = std::uint32_t;
  const std::string where = "derivative estimate: ";
  const std::size_t V = domain.number_of_vertices();
  if (values.size() != V)
    throw Invalid_input(where + std::to_string(values.size()) + " values for " + std::to_string(V) +
                        " vertices");
  if (order < 0 || order > 10)
    throw Invalid_input(where + "order " + std::to_string(order) + " outside 0..10");
  // The monomials u^p v^q with 1 <= p + q <= degree; u of them, and the neighbourhood size
  // aimed at (half as many points again as unknowns).
  std::vector<std::pair<int, int>> monomials;
  std::size_t u = 0, target = 0;
  auto set_degree = [&](int degree) {
    monomials.clear();
    for (int total = 1; total <= degree; ++total)
      for (int p = total; p >= 0; --p)
        monomials.emplace_back(p, total - p);
    u = monomials.size();
    target = u + (u + 1) / 2;
  };
  if (degrees != nullptr)
    degrees->assign(V, order);

  std::vector<Polynomial_surface<GeomTraits>> result;
  result.reserve(V);
  std::vector<Index> stamp(V, Index(-1));
  std::vector<Index> neighbourhood, frontier, next;
  std::vector<FT> dx, dy, dz;
  for (Index v = 0; v < V; ++v) {
    Polynomial_surface<GeomTraits> jet(order);
    jet.set_coefficient(0, 0, values[v]);
    neighbourhood.clear();
    frontier.assign(1, v);
    stamp[v] = v;
    int degree = order;
    set_degree(degree);
    bool solved = u == 0;
    while (!solved) {
      // One more ring.
      next.clear();
      for (Index w : frontier) {
        const auto [begin, end] = domain.neighbours(w);
        for (const Index* x = begin; x != end; ++x)
          if (stamp[*x] != v) {
            stamp[*x] = v;
            next.push_back(*x);
          }
      }
      frontier.swap(next);
      neighbourhood.insert(neighbourhood.end(), frontier.begin(), frontier.end());
      const bool exhausted = frontier.empty();
      if (neighbourhood.size() < target && !exhausted)
        continue;
      if (neighbourhood.size() < u) {
        // The whole component cannot determine this degree: lower it (a constant at worst).
        set_degree(--degree);
        solved = u == 0;
        continue;
      }
      // Scaled local coordinates: |u|, |v| <= 1.
      const auto& c = domain.point(v);
      FT h(0);
      dx.clear();
      dy.clear();
      dz.clear();
      for (Index w : neighbourhood) {
        dx.push_back(domain.point(w).x() - c.x());
        dy.push_back(domain.point(w).y() - c.y());
        dz.push_back(values[w] - values[v]);
        const FT ax = CGAL::abs(dx.back()), ay = CGAL::abs(dy.back());
        if (h < ax)
          h = ax;
        if (h < ay)
          h = ay;
      }
      const FT inverse_h = FT(1) / h;
      const std::size_t rows = neighbourhood.size();
      std::vector<FT> coefficients(u, FT(0));
      std::vector<FT> design(rows * u);
      // Row weights (square roots of the least-squares weights) decreasing with the squared
      // distance d2 and vanishing just beyond the neighbourhood, after Renka's weights
      // ((R - d) / (R d))^2, in squared distances so that they stay rational.
      FT far(0);
      for (std::size_t r = 0; r < rows; ++r) {
        const FT x = dx[r] * inverse_h, y = dy[r] * inverse_h;
        const FT d2 = x * x + y * y;
        if (far < d2)
          far = d2;
      }
      const FT R2 = far * FT(11) / FT(10);
      for (std::size_t r = 0; r < rows; ++r) {
        const FT x = dx[r] * inverse_h, y = dy[r] * inverse_h;
        const FT d2 = x * x + y * y;
        const FT weight = (R2 - d2) / (R2 * d2);
        dz[r] = weight * dz[r];
        for (std::size_t col = 0; col < u; ++col) {
          FT m(1);
          for (int e = 0; e < monomials[col].first; ++e)
            m = m * x;
          for (int e = 0; e < monomials[col].second; ++e)
            m = m * y;
          design[r * u + col] = weight * m;
        }
      }
      if constexpr (std::is_same<FT, double>::value) {
        Eigen::MatrixXd A(rows, u);
        Eigen::VectorXd b(rows);
        for (std::size_t r = 0; r < rows; ++r) {
          for (std::size_t col = 0; col < u; ++col)
            A(Eigen::Index(r), Eigen::Index(col)) = design[r * u + col];
          b(Eigen::Index(r)) = dz[r];
        }
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
        qr.setThreshold(1e-10);
        if (qr.rank() == Eigen::Index(u)) {
          const Eigen::VectorXd solution = qr.solve(b);
          for (std::size_t col = 0; col < u; ++col)
            coefficients[col] = solution(Eigen::Index(col));
          solved = true;
        }
      } else {
        // Normal equations, solved exactly.
        std::vector<FT> normal(u * u, FT(0));
        std::vector<FT> rhs(u, FT(0));
        for (std::size_t r = 0; r < rows; ++r)
          for (std::size_t a = 0; a < u; ++a) {
            const FT da = design[r * u + a];
            rhs[a] = rhs[a] + da * dz[r];
            for (std::size_t b = a; b < u; ++b)
              normal[a * u + b] = normal[a * u + b] + da * design[r * u + b];
          }
        for (std::size_t a = 0; a < u; ++a)
          for (std::size_t b = 0; b < a; ++b)
            normal[a * u + b] = normal[b * u + a];
        if (internal::solve_consistent(std::move(normal), rhs, u, 1e-12) == u) {
          coefficients = std::move(rhs);
          solved = true;
        }
      }
      if (solved) {
        for (std::size_t col = 0; col < u; ++col) {
          FT scale(1);
          for (int e = 0; e < monomials[col].first + monomials[col].second; ++e)
            scale = scale * inverse_h;
          jet.set_coefficient(monomials[col].first, monomials[col].second,
                              coefficients[col] * scale);
        }
      } else if (exhausted) {
        // Points on a curve of this degree: one degree lower.
        set_degree(--degree);
        solved = u == 0;
      }
    }
    if (degrees != nullptr)
      (*degrees)[v] = degree;
    result.push_back(std::move(jet));
  }
  return result;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_MANN_MANN_INTERPOLANT_H

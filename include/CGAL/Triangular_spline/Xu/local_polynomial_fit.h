// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H
#define CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Algebraic_structure_traits.h>

#include <Eigen/Dense>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief how `Local_polynomials` chooses the degree at each vertex.
*/
enum class Degree_selection {
  /// the largest degree that the neighbourhood determines
  LARGEST,
  /// leave-one-out cross-validation: the lowest degree whose leave-one-out residuals over
  /// the neighbourhood (weighted mean square) are within 10% of the best degree's; smooth
  /// data get high degrees, rough data low ones
  CROSS_VALIDATION
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief one local polynomial per domain vertex, fitted to the data around it: the
  estimate of the underlying function that the `Fit::LOCAL_POLYNOMIAL` fit of a
  `C1_quintic_spline` reads its control points from.

  Around vertex \f$v\f$ the polynomial \f$p_v\f$ of degree \f$d_v \le\f$ `max_degree`
  interpolates the value at \f$v\f$ and fits the values at the vertices of the nearest rings
  of the triangulation (as many rings, up to eight, as give twice the unknowns) in weighted least
  squares (weights \f$1/|w-v|^2\f$), in the scaled local coordinates \f$(x - v)/S_v\f$, \f$S_v\f$ a
  power of two. If the data come from a polynomial of degree at most \f$d_v\f$, \f$p_v\f$ is that
  polynomial, exactly with an exact number type: this is what gives the spline its polynomial
  precision.

  <b>Degree.</b> \f$d_v\f$ is the largest degree for which the fewest rings that hold
  at least 1.5 times as many points as the fit has unknowns (all rings if none does) give a
  well-conditioned scaled, weighted design matrix (column-pivoted QR, smallest pivot at
  least \f$10^{-6}\f$ of the largest). Sparse data, the boundary and points near a conic lower it,
  down to 1 (a plane, two neighbours suffice) and 0 (a constant). The decision is taken in `double`
  for every number type, so double and exact builds choose the same degrees; the
  coefficients are then solved in `FT` (normal equations by exact elimination for exact
  number types, the QR for inexact ones).

  <b>Cost.</b> \f$O(V)\f$ time and memory: a bounded neighbourhood and at most five small
  least-squares problems per vertex (about 90 microseconds per vertex at degree 5 on one
  core, 20 at degree 3). Inexact number types fit large inputs on all cores.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` or a vector type, see `Value_traits`
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
class Local_polynomials {
public:
  /// the number type
  using FT = typename GeomTraits::FT;
  /// the point type of the domain
  using Point_2 = typename GeomTraits::Point_2;
  /// the triangulated domain
  using Domain = Planar_domain<GeomTraits>;
  /// index of a domain vertex
  using Index = typename Domain::Index;
  /// the largest degree supported
  static constexpr int max_supported_degree = 5;

  /*!
    fits one polynomial per vertex of `domain` to `values` (one per vertex), on `threads`
    threads (0: one per core for inexact number types and more than 2000 vertices, else
    one); the result does not depend on the number of threads.
    \throws Invalid_input if `values` has the wrong size or `max_degree` is not in 0..5
    \param domain the triangulated planar domain
    \param values the data values, one per domain vertex
    \param max_degree the largest degree of a local polynomial
    \param selection the rule choosing the degree of each local polynomial
    \param threads the number of threads (0: automatic)
  */
  Local_polynomials(const Domain& domain, const std::vector<Value>& values, int max_degree = 3,
                    Degree_selection selection = Degree_selection::CROSS_VALIDATION,
                    std::size_t threads = 0)
      : m_domain(&domain), m_max_degree(max_degree), m_selection(selection) {
    if (values.size() != domain.number_of_vertices())
      throw Invalid_input("local fit: " + std::to_string(values.size()) + " data values for " +
                          std::to_string(domain.number_of_vertices()) + " vertices");
    if (max_degree < 0 || max_degree > max_supported_degree)
      throw Invalid_input("local fit: degree must be between 0 and 5, not " +
                          std::to_string(max_degree));
    const std::size_t V = domain.number_of_vertices();
    m_degree.assign(V, 0);
    m_resolution.assign(V, 1.0);
    m_scale.assign(V, FT(1));
    m_coefficients.assign(V * coefficients_per_vertex, Value_traits<Value>::zero());
    // The fits are independent: one thread per core on large inputs (each vertex's result
    // does not depend on the partition, so output is deterministic). Exact builds stay on
    // one thread: their fits are small and the rational arithmetic allocates.
    if (threads == 0) {
      const std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
      threads = exact ? 1 : (std::min)(cores, V / 2000 + 1);
    }
    auto fit_range = [&](std::size_t first) {
      Workspace work;
      for (std::size_t v = first; v < V; v += threads)
        fit_vertex(static_cast<Index>(v), values, work);
    };
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < threads; ++t)
      workers.emplace_back(fit_range, t);
    fit_range(0);
    for (std::thread& worker : workers)
      worker.join();
  }

  /// returns the degree \f$d_v\f$ chosen at vertex `v`.
  /// \param v the index of a vertex
  /// \returns the degree \f$d_v\f$ chosen at vertex `v`
  int degree(Index v) const { return m_degree[v]; }
  /*!
    returns how well the data around `v` are resolved: the root of the ratio of the
    leave-one-out mean square residual of \f$p_v\f$ to that of the best plane through
    \f$(v, z_v)\f$ (both over their own rings, weighted as the fits), in [0, 1]. 0 when
    \f$p_v\f$ predicts every left-out neighbour exactly (data from a polynomial of degree
    \f$d_v\f$, or from a plane); near 0 for smooth, densely sampled data (the ratio falls as
    \f$h^{d_v - 1}\f$); near 1 when the polynomial predicts no better than a plane:
    data too sparse for their features, noise, cliffs. 1 where no plane is determined.
    Decided in `double` for every number type.
    \param v the index of a vertex
    \returns the resolution ratio, in [0, 1]
  */
  double resolution(Index v) const { return m_resolution[v]; }
  /// returns the largest degree asked for.
  /// \returns the largest degree asked for
  int max_degree() const { return m_max_degree; }

  /// returns \f$p_v(x)\f$.
  /// \param v the index of a vertex
  /// \param x the point
  /// \returns \f$p_v(x)\f$
  Value value(Index v, const Point_2& x) const {
    const std::array<std::pair<const Point_2*, int>, 1> arguments{{{&x, m_max_degree}}};
    return polar_value(v, arguments.begin(), arguments.end(), m_max_degree);
  }

  /*!
    returns the polar form of degree `n` of \f$p_v\f$ (\f$n \ge d_v\f$, at most 5) at the
    points with multiplicities in [`begin`, `end`) (pairs of a point pointer and a
    multiplicity, summing to `n`): for a quintic spline with `n` = 5, the control value that
    \f$p_v\f$ gives the control point with that polar label.
    \tparam Iterator an input iterator over pairs of a `const Point_2*` and an `int`
    \param v the index of a vertex
    \param begin the first (point pointer, multiplicity) pair
    \param end past the last pair
    \param n the degree of the polar form
    \returns the value of the polar form
  */
  template <class Iterator>
  Value polar_value(Index v, Iterator begin, Iterator end, int n) const {
    const int d = m_degree[v];
    const Point_2& c = m_domain->point(v);
    const FT& inverse_scale = m_scale[v];
    // e[h][k]: coefficient of X^h Y^k in prod (1 + xi X + eta Y)^m, truncated at degree d.
    std::array<std::array<FT, max_supported_degree + 1>, max_supported_degree + 1> e;
    for (auto& row : e)
      row.fill(FT(0));
    e[0][0] = FT(1);
    for (auto it = begin; it != end; ++it) {
      const Point_2& q = *it->first;
      const FT xi = (q.x() - c.x()) * inverse_scale, eta = (q.y() - c.y()) * inverse_scale;
      for (int copy = 0; copy < it->second; ++copy)
        for (int total = d; total >= 1; --total)
          for (int h = 0; h <= total; ++h) {
            const int k = total - h;
            FT add(0);
            if (h > 0)
              add = add + xi * e[std::size_t(h - 1)][std::size_t(k)];
            if (k > 0)
              add = add + eta * e[std::size_t(h)][std::size_t(k - 1)];
            e[std::size_t(h)][std::size_t(k)] = e[std::size_t(h)][std::size_t(k)] + add;
          }
    }
    Value sum = m_coefficients[coefficients_per_vertex * std::size_t(v)];
    for (int h = 0; h <= d; ++h)
      for (int k = 0; h + k <= d; ++k) {
        if (h + k == 0)
          continue;
        const FT count = FT(binomial(n, h) * binomial(n - h, k));
        sum = sum + (e[std::size_t(h)][std::size_t(k)] / count) * coefficient(v, h, k);
      }
    return sum;
  }

  /// returns the gradient of \f$p_v\f$ at \f$v\f$.
  /// \param v the index of a vertex
  /// \returns the gradient of \f$p_v\f$ at \f$v\f$
  std::array<Value, 2> gradient(Index v) const {
    return {{m_scale[v] * coefficient(v, 1, 0), m_scale[v] * coefficient(v, 0, 1)}};
  }

private:
  static constexpr std::size_t coefficients_per_vertex =
      (max_supported_degree + 1) * (max_supported_degree + 2) / 2;
  static constexpr int D = Value_traits<Value>::dimension;
  static constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  // Interior vertices reach twice the unknowns of a quintic within three rings; corners of
  // the domain see a quarter of each ring and need more.
  static constexpr int max_rings = 8;

  struct Workspace {
    std::vector<Index> points;         // the rings, nearest first
    std::vector<std::size_t> ring_end; // points[0, ring_end[r]) are rings 1..r+1
    std::vector<std::uint32_t> mark;   // BFS marks, by vertex (stamp = v + 1)
  };

  static int binomial(int n, int k) {
    int r = 1;
    for (int i = 1; i <= k; ++i)
      r = r * (n - k + i) / i;
    return r;
  }
  static int unknowns(int d) { return (d + 1) * (d + 2) / 2 - 1; }
  // Position of x^h y^k in the per-vertex coefficient block (by total degree, then h).
  static std::size_t position(int h, int k) {
    const int t = h + k;
    return std::size_t(t * (t + 1) / 2 + k);
  }
  const Value& coefficient(Index v, int h, int k) const {
    return m_coefficients[coefficients_per_vertex * std::size_t(v) + position(h, k)];
  }
  Value& coefficient(Index v, int h, int k) {
    return m_coefficients[coefficients_per_vertex * std::size_t(v) + position(h, k)];
  }

  // Rings of v by breadth-first search, up to max_rings rings or enough points for
  // max_degree.
  void gather(Index v, Workspace& work) const {
    const Domain& domain = *m_domain;
    if (work.mark.size() != domain.number_of_vertices())
      work.mark.assign(domain.number_of_vertices(), 0);
    const std::uint32_t stamp = static_cast<std::uint32_t>(v) + 1;
    work.points.clear();
    work.ring_end.clear();
    work.mark[v] = stamp;
    const std::size_t wanted = std::size_t(2 * unknowns(m_max_degree));
    std::size_t begin = 0;
    for (int ring = 0; ring < max_rings; ++ring) {
      const std::size_t end = work.points.size();
      auto visit = [&](Index u) {
        const auto [nb, ne] = domain.neighbours(u);
        for (auto w = nb; w != ne; ++w)
          if (work.mark[*w] != stamp) {
            work.mark[*w] = stamp;
            work.points.push_back(*w);
          }
      };
      if (ring == 0)
        visit(v);
      else
        for (std::size_t i = begin; i < end; ++i)
          visit(work.points[i]);
      begin = end;
      work.ring_end.push_back(work.points.size());
      if (work.points.size() >= wanted || work.points.size() == end)
        break;
    }
    // Within a ring the order follows the triangulation; sort by index so that the
    // rounding of the double solve does not depend on the traversal.
    std::size_t from = 0;
    for (std::size_t end : work.ring_end) {
      std::sort(work.points.begin() + std::ptrdiff_t(from),
                work.points.begin() + std::ptrdiff_t(end),
                [&](Index a, Index b) { return point_less(a, b); });
      from = end;
    }
  }

  bool point_less(Index a, Index b) const {
    const Point_2 &p = m_domain->point(a), &q = m_domain->point(b);
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  }

  void fit_vertex(Index v, const std::vector<Value>& values, Workspace& work) {
    const Domain& domain = *m_domain;
    coefficient(v, 0, 0) = values[v];
    if (m_max_degree == 0)
      return;
    gather(v, work);
    const Point_2& c = domain.point(v);
    const double cx = CGAL::to_double(c.x()), cy = CGAL::to_double(c.y());
    struct Candidate {
      int degree = -1;
      std::size_t n = 0;
      double scale = 0, score = 0;
      Eigen::MatrixXd x;
    };
    // The weighted least-squares fit of degree d to the first n points of the rings, with
    // its leave-one-out score; false if the neighbourhood does not determine it.
    auto assess = [&](int d, std::size_t n, Candidate& candidate) {
      const int u = unknowns(d);
      // Scale: a power of two at least the largest distance, so |xi|, |eta| <= 1 and the
      // exact coordinates stay dyadic multiples of the data.
      double radius = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Point_2& p = domain.point(work.points[i]);
        radius = (std::max)(radius,
                            std::hypot(CGAL::to_double(p.x()) - cx, CGAL::to_double(p.y()) - cy));
      }
      if (!(radius > 0) || !std::isfinite(radius))
        return false; // candidate.degree stays -1: no higher degree either
      candidate.degree = d;
      const double scale = std::exp2(std::ceil(std::log2(radius)));
      Eigen::MatrixXd A(Eigen::Index(n), u);
      Eigen::MatrixXd b(Eigen::Index(n), D);
      double weight_sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Point_2& p = domain.point(work.points[i]);
        const double xi = (CGAL::to_double(p.x()) - cx) / scale;
        const double eta = (CGAL::to_double(p.y()) - cy) / scale;
        const double w = 1 / std::hypot(xi, eta); // square root of the weight 1/|.|^2
        weight_sum += w * w;
        fill_monomials(xi, eta, d, w, A.row(Eigen::Index(i)));
        for (int k = 0; k < D; ++k)
          b(Eigen::Index(i), k) =
              w * (CGAL::to_double(Value_traits<Value>::coordinate(values[work.points[i]], k)) -
                   CGAL::to_double(Value_traits<Value>::coordinate(values[v], k)));
      }
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
      // A plane is needed for linear precision however thin the neighbourhood; exact
      // builds then solve exactly (a vertex of a valid domain always has a full-rank pair).
      qr.setThreshold(d == 1 ? 1e-14 : 1e-6);
      if (qr.rank() < u && !(exact && d == 1))
        return false;
      candidate = Candidate{d, n, scale, 0, qr.solve(b)};
      // Leave-one-out residuals of weighted least squares: r_i / (1 - h_ii), h the hat
      // matrix Q Q^T; their weighted mean square is the score of this degree.
      const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(Eigen::Index(n), u);
      const Eigen::MatrixXd residual = b - A * candidate.x;
      double score = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double leverage = Q.row(Eigen::Index(i)).squaredNorm();
        if (!(1 - leverage > 1e-8)) {
          score = std::numeric_limits<double>::infinity();
          break;
        }
        score += residual.row(Eigen::Index(i)).squaredNorm() / ((1 - leverage) * (1 - leverage));
      }
      candidate.score = score / weight_sum;
      return true;
    };
    boost::container::static_vector<Candidate, max_supported_degree> candidates;
    for (int d = 1; d <= m_max_degree; ++d) {
      const int u = unknowns(d);
      const std::size_t needed = d == 1 ? 2 : std::size_t((3 * u + 1) / 2);
      // The fewest rings holding enough points (all of them if none does).
      std::size_t n = work.points.size();
      for (std::size_t end : work.ring_end)
        if (end >= needed) {
          n = end;
          break;
        }
      if (n < needed)
        break;
      Candidate candidate;
      if (!assess(d, n, candidate)) {
        if (candidate.degree < 0)
          break; // no extent: no higher degree either
        continue;
      }
      candidates.push_back(std::move(candidate));
    }
    if (candidates.empty()) {
      m_degree[v] = 0; // isolated or degenerate neighbourhood: a constant
      return;
    }
    // Largest degree, or the lowest degree that predicts left-out points nearly as well
    // as the best one (scores at rounding level count as ties).
    // Scores at rounding level of the neighbourhood's data count as zero.
    double data_scale = 0;
    for (Index w : work.points)
      for (int k = 0; k < D; ++k)
        data_scale = (std::max)(
            data_scale, std::abs(CGAL::to_double(Value_traits<Value>::coordinate(values[w], k)) -
                                 CGAL::to_double(Value_traits<Value>::coordinate(values[v], k))));
    const double floor = 1e-24 * data_scale * data_scale;
    std::size_t chosen = candidates.size() - 1;
    if (m_selection == Degree_selection::CROSS_VALIDATION) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& candidate : candidates)
        best = (std::min)(best, candidate.score);
      for (chosen = 0; chosen + 1 < candidates.size(); ++chosen)
        if (candidates[chosen].score <= (std::max)(m_tie_ratio * best, floor))
          break;
    }
    // Resolution: leave-one-out score of the chosen degree against the plane's (degree 1 is
    // the first candidate whenever a plane is determined).
    {
      // The plane on the chosen degree's own points: the same points, one model less rich.
      Candidate flat;
      const bool has_plane = candidates[chosen].degree == 1 ? (flat = candidates[chosen], true)
                                                            : assess(1, candidates[chosen].n, flat);
      const double plane = flat.score, own = candidates[chosen].score;
      if (!has_plane || !std::isfinite(plane))
        m_resolution[v] = 1;
      else if (!(own > floor))
        m_resolution[v] = 0;
      else
        m_resolution[v] = (std::min)(1.0, std::sqrt(own / (std::max)(plane, floor)));
    }
    for (std::size_t k = chosen + 1; k-- > 0;) {
      const Candidate& candidate = candidates[k];
      const int d = candidate.degree;
      m_scale[v] = FT(1) / FT(candidate.scale);
      if constexpr (exact) {
        if (!solve_exact(v, values, work, candidate.n, d, m_scale[v]))
          continue;
      } else {
        for (int t = 1, col = 0; t <= d; ++t)
          for (int j = 0; j <= t; ++j, ++col) {
            std::array<FT, std::size_t(D)> cs;
            for (int i = 0; i < D; ++i)
              cs[std::size_t(i)] = FT(candidate.x(col, i));
            coefficient(v, t - j, j) = Value_traits<Value>::from_coordinates(cs);
          }
      }
      m_degree[v] = d;
      return;
    }
    m_degree[v] = 0;
  }

  template <class Row>
  static void fill_monomials(double xi, double eta, int d, double w, Row&& row) {
    int col = 0;
    for (int t = 1; t <= d; ++t)
      for (int k = 0; k <= t; ++k, ++col)
        row(col) = w * std::pow(xi, t - k) * std::pow(eta, k);
  }

  // Normal equations sum w a a^T x = sum w a (z - z_v) with w = 1/|xi|^2, solved by exact
  // Gaussian elimination; false if singular (never expected after the double rank test).
  bool solve_exact(Index v, const std::vector<Value>& values, const Workspace& work, std::size_t n,
                   int d, const FT& inverse_scale) {
    const int u = unknowns(d);
    const Point_2& c = m_domain->point(v);
    std::vector<std::vector<FT>> M(std::size_t(u), std::vector<FT>(std::size_t(u + D), FT(0)));
    std::vector<FT> a(static_cast<std::size_t>(u), FT(0));
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& p = m_domain->point(work.points[i]);
      const FT xi = (p.x() - c.x()) * inverse_scale, eta = (p.y() - c.y()) * inverse_scale;
      const FT w = FT(1) / (xi * xi + eta * eta);
      int col = 0;
      for (int t = 1; t <= d; ++t)
        for (int k = 0; k <= t; ++k, ++col) {
          FT m(1);
          for (int e = 0; e < t - k; ++e)
            m = m * xi;
          for (int e = 0; e < k; ++e)
            m = m * eta;
          a[std::size_t(col)] = m;
        }
      for (int r = 0; r < u; ++r) {
        const FT wa = w * a[std::size_t(r)];
        for (int s = 0; s < u; ++s)
          M[std::size_t(r)][std::size_t(s)] =
              M[std::size_t(r)][std::size_t(s)] + wa * a[std::size_t(s)];
        for (int j = 0; j < D; ++j)
          M[std::size_t(r)][std::size_t(u + j)] =
              M[std::size_t(r)][std::size_t(u + j)] +
              wa * (Value_traits<Value>::coordinate(values[work.points[i]], j) -
                    Value_traits<Value>::coordinate(values[v], j));
      }
    }
    for (int col = 0; col < u; ++col) {
      int pivot = col;
      while (pivot < u && CGAL::is_zero(M[std::size_t(pivot)][std::size_t(col)]))
        ++pivot;
      if (pivot == u)
        return false;
      std::swap(M[std::size_t(pivot)], M[std::size_t(col)]);
      for (int r = 0; r < u; ++r) {
        if (r == col || CGAL::is_zero(M[std::size_t(r)][std::size_t(col)]))
          continue;
        const FT f = M[std::size_t(r)][std::size_t(col)] / M[std::size_t(col)][std::size_t(col)];
        for (int s = col; s < u + D; ++s)
          M[std::size_t(r)][std::size_t(s)] =
              M[std::size_t(r)][std::size_t(s)] - f * M[std::size_t(col)][std::size_t(s)];
      }
    }
    for (int t = 1, col = 0; t <= d; ++t)
      for (int k = 0; k <= t; ++k, ++col) {
        std::array<FT, std::size_t(D)> cs;
        for (int j = 0; j < D; ++j)
          cs[std::size_t(j)] =
              M[std::size_t(col)][std::size_t(u + j)] / M[std::size_t(col)][std::size_t(col)];
        coefficient(v, t - k, k) = Value_traits<Value>::from_coordinates(cs);
      }
    return true;
  }

  const Domain* m_domain;
  int m_max_degree;
  Degree_selection m_selection;
  double m_tie_ratio = 1.1;
  std::vector<int> m_degree;
  std::vector<double> m_resolution;
  std::vector<FT> m_scale; // 1 / S_v
  std::vector<Value> m_coefficients;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H

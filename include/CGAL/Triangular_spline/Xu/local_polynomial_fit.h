// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H
#define CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/avx2_clones.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Fraction_traits.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <atomic>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__GNUC__) && !defined(CGAL_TRIANGULAR_SPLINE_NO_LANE_BATCHES)
#define CGAL_TRIANGULAR_SPLINE_LANE_BATCHES 1
#else
#define CGAL_TRIANGULAR_SPLINE_LANE_BATCHES 0
#endif

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
  \brief how `Local_polynomials` solves its normal equations with an exact number type.
*/
enum class Exact_elimination {
  /// over the integers of the number type's fractions (`Fraction_traits`): exact divisions
  /// only (Bareiss), the coefficients kept as numerators over one denominator per vertex;
  /// rational elimination for number types without `Fraction_traits`
  FRACTION_FREE,
  /// Gauss-Jordan elimination in the number type itself (a gcd per operation with GMP)
  RATIONAL
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief which vertices' coefficients `Local_polynomials` keeps.
*/
enum class Local_polynomial_storage {
  /// every vertex is fitted by the constructor and keeps its coefficients
  ALL_VERTICES,
  /// the constructor fits no vertex; `Local_polynomials::fit()` fits chosen vertices and
  /// keeps only theirs: a pass over a large domain holds one block's coefficients at a time
  /// (all of them take 21 values per vertex, 168 MB at \f$10^6\f$ vertices in `double`)
  ON_DEMAND
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief one local polynomial per domain vertex, fitted to the data around it: the
  estimate of the underlying function that the `Fit::LOCAL_POLYNOMIAL` fit of a
  `C1_quintic_spline` reads its control points from.

  Around vertex \f$v\f$ the polynomial \f$p_v\f$ of degree \f$d_v \le\f$ `max_degree`
  interpolates the value at \f$v\f$ and fits the values at the nearest data points in
  weighted least squares (weights \f$1/|w-v|^2\f$): the first ring of the triangulation for a
  plane, 14 points (1.5 times the unknowns of a cubic) for degrees 2 and 3, 30 (a quintic's)
  for degrees 4 and 5, from the rings around \f$v\f$ (up to eight), nearest first, the
  distance of a point in ring \f$r\f$ counted \f$1.5^{r-1}\f$ times (nearest points, but
  balanced around \f$v\f$ where the data are clustered); a boundary vertex first takes its
  first-ring neighbours within twice the distance of the farthest of these points. The
  fits are taken in the scaled local coordinates \f$(x - v)/S_v\f$, \f$S_v\f$ a power of two. If the
  data come from a polynomial of degree at most \f$d_v\f$, \f$p_v\f$ is that polynomial, exactly
  with an exact number type: this is what gives the spline its polynomial precision.

  <b>Degree.</b> \f$d_v\f$ is the largest degree for which these points (as many as exist,
  at least 1.5 times its unknowns) give a well-conditioned scaled, weighted design matrix
  (Householder QR with the columns ordered by degree: every column at a distance from the span of
  the previous ones of at least \f$10^{-6}\f$ of its length; \f$10^{-14}\f$ for a plane; where
  the points do not determine the larger degree of a group, or one of them has leverage 1, twice
  as many are tried first). Sparse
  data, the boundary and points near a conic lower it, down to 1 (a plane, two neighbours suffice)
  and 0 (a constant). The decision is taken in `double` for every number type, so double and exact
  builds choose the same degrees; the coefficients are then solved in `FT` (normal equations by
  exact elimination for exact number types, the QR for inexact ones). Exact builds weight each
  point by \f$1/|w-v|^2\f$ rounded to `double` (any positive weights reproduce the
  polynomial the data come from; a double is a short fraction), so exact and double builds
  agree to rounding.

  <b>Stability.</b> Leave-one-out cannot see what a fit does between the points where they
  lie on a few nearly parallel lines (a nearly straight hull, the last columns of a jittered
  grid): the columns are then determined only to about \f$10^{-5}\f$ and the polynomial
  swings between the lines (0.4 half a cell from the hull on data of size 2.7). Where a column
  of the chosen degree is within \f$10^{-3}\f$ of the span of the previous ones, the fit's
  Lebesgue constant \f$L\f$ at the corner-inner points of \f$v\f$'s star (where the spline
  reads it) is computed; if \f$L > 300\f$, or \f$L\f$ times the leave-one-out error exceeds
  the plane's error on the same points, the next lower degree is taken.

  <b>Cost.</b> \f$O(V)\f$ time and memory: a bounded neighbourhood and one Householder QR
  per set of points (three), whose leading columns give the fit and the leave-one-out score of
  every degree sharing those points. Large inputs are fitted on all cores. With an exact
  number type that has `Fraction_traits` (GMP's rationals), the normal equations are solved
  fraction-free in its integers and each coefficient is kept as a numerator over a common
  denominator per vertex, from which `polar_value()` sums in integers: about 4 ms per
  quintic vertex for scattered `double` data, whose exact coefficients run to thousands of
  digits (rational elimination: about half a second). The coefficients take 21 values per
  vertex; with `Local_polynomial_storage::ON_DEMAND` only those of the vertices of the last
  `fit()` are kept, so that a pass over a large domain holds one block of them (the
  `LOCAL_POLYNOMIAL` and `ADAPTIVE` fits of `fit_vertex_data()` do).

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
    \param elimination how exact number types solve the normal equations: over the integers
    of their fractions where they have `Fraction_traits` (the default and the fast way), or
    by rational elimination (for tests: both give the same rationals)
    \param storage `ALL_VERTICES` fits every vertex now; `ON_DEMAND` fits none (see `fit()`),
    and `values` must then outlive the object
  */
  Local_polynomials(const Domain& domain, const std::vector<Value>& values, int max_degree = 3,
                    Degree_selection selection = Degree_selection::CROSS_VALIDATION,
                    std::size_t threads = 0,
                    Exact_elimination elimination = Exact_elimination::FRACTION_FREE,
                    Local_polynomial_storage storage = Local_polynomial_storage::ALL_VERTICES)
      : m_domain(&domain), m_data(&values), m_max_degree(max_degree), m_selection(selection),
        m_fraction_free(elimination == Exact_elimination::FRACTION_FREE), m_threads(threads),
        m_on_demand(storage == Local_polynomial_storage::ON_DEMAND) {
    if (values.size() != domain.number_of_vertices())
      throw Invalid_input("local fit: " + std::to_string(values.size()) + " data values for " +
                          std::to_string(domain.number_of_vertices()) + " vertices");
    if (max_degree < 0 || max_degree > max_supported_degree)
      throw Invalid_input("local fit: degree must be between 0 and 5, not " +
                          std::to_string(max_degree));
    const std::size_t V = domain.number_of_vertices();
    m_degree.assign(V, 0);
    m_resolution.assign(V, 1.0);
    m_radius.assign(V, 0.0f);
    m_scale.assign(V, FT(1));
    if (m_on_demand) {
      m_stored_at.assign(V, not_kept);
      return;
    }
    allocate(V);
    fit_list(V, [](std::size_t i) { return static_cast<Index>(i); });
  }

  /*!
    fits the polynomials of `vertices` (distinct), on the constructor's number of threads,
    and keeps their coefficients instead of those kept so far. The degree, resolution and
    radius of every vertex fitted stay available. A vertex's polynomial does not depend on
    the others fitted with it, nor on the number of threads.
    \throws Invalid_input if the object was not constructed with
    `Local_polynomial_storage::ON_DEMAND`, or `vertices` repeats a vertex or names none of
    the domain (then no vertex is kept)
    \param vertices the vertices to fit
  */
  void fit(const std::vector<Index>& vertices) {
    if (!m_on_demand)
      throw Invalid_input("local fit: fit() needs Local_polynomial_storage::ON_DEMAND");
    for (Index v : m_kept)
      m_stored_at[v] = not_kept;
    m_kept = vertices;
    for (std::size_t i = 0; i < m_kept.size(); ++i) {
      const Index v = m_kept[i];
      if (std::size_t(v) >= m_stored_at.size() || m_stored_at[v] != not_kept) {
        for (std::size_t j = 0; j < i; ++j)
          m_stored_at[m_kept[j]] = not_kept;
        m_kept.clear();
        throw Invalid_input(
            "local fit: vertex " + std::to_string(v) +
            (std::size_t(v) >= m_stored_at.size() ? " is not in the domain" : " is listed twice"));
      }
      m_stored_at[v] = static_cast<std::uint32_t>(i);
    }
    allocate(m_kept.size());
    fit_list(m_kept.size(), [&](std::size_t i) { return m_kept[i]; });
  }

  /// \cond SKIP_IN_MANUAL
  // fit() of vertices 0, 1, 2, ... below `count`, on the calling thread alone, until `stop`
  // is set (make_c1_quintic_spline() fits them while the plan is built, until it is);
  // returns how many were fitted and are kept.
  std::size_t fit_first(std::size_t count, const std::atomic<bool>& stop) {
    if (!m_on_demand)
      throw Invalid_input("local fit: fit() needs Local_polynomial_storage::ON_DEMAND");
    for (Index v : m_kept)
      m_stored_at[v] = not_kept;
    m_kept.clear();
    count = (std::min)(count, m_stored_at.size());
    allocate(count);
    for (std::size_t i = 0; i < count; ++i)
      m_stored_at[i] = static_cast<std::uint32_t>(i);
    auto fit = [&]() -> std::size_t {
#if CGAL_TRIANGULAR_SPLINE_AVX2_CLONES
      if (internal::use_avx2_clones())
        return fit_first_avx2(count, stop);
#endif
      return fit_first_share<false>(count, stop);
    };
    const std::size_t fitted = fit();
    for (std::size_t i = fitted; i < count; ++i)
      m_stored_at[i] = not_kept;
    m_kept.resize(fitted);
    for (std::size_t i = 0; i < fitted; ++i)
      m_kept[i] = static_cast<Index>(i);
    return fitted;
  }
  /// \endcond

  /// returns whether the coefficients of \f$p_v\f$ are kept (`value()`, `polar_value()` and
  /// `gradient()` need them): always with `ALL_VERTICES`, after `fit()` with `ON_DEMAND`.
  /// \param v the index of a vertex
  /// \returns whether the coefficients of \f$p_v\f$ are kept
  bool is_kept(Index v) const {
    return !m_on_demand || m_stored_at[v] != not_kept;
  }

  /// returns the degree \f$d_v\f$ chosen at vertex `v`.
  /// \param v the index of a vertex
  /// \returns the degree \f$d_v\f$ chosen at vertex `v`
  int degree(Index v) const {
    return m_degree[v];
  }
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
  double resolution(Index v) const {
    return m_resolution[v];
  }
  /*!
    returns the radius of \f$p_v\f$'s fit: the largest distance from \f$v\f$ of the data
    points it was fitted to (0 for a constant). Far beyond it \f$p_v\f$ extrapolates: its
    terms of degree \f$k\f$ grow as the \f$k\f$-th power of the distance in radii.
    \param v the index of a vertex
    \returns the radius of the fit at `v`
  */
  double radius(Index v) const {
    return double(m_radius[v]);
  }
  /// returns the largest degree asked for.
  /// \returns the largest degree asked for
  int max_degree() const {
    return m_max_degree;
  }

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
    // Copies of points other than v multiplied in so far: e[h][k] with h + k > passes is
    // still exactly 0, and the updates below skip it (they would add exact zeros to it). v
    // itself (xi = eta = 0) is skipped entirely: its factors add exact zeros, and e never
    // holds -0 for them to turn into +0. A slot's label repeats the vertex whose polynomial
    // it reads 3 to 5 times, so most of the work of a polar value was these no-ops.
    int passes = 0;
    for (auto it = begin; it != end; ++it) {
      const Point_2& q = *it->first;
      if (&q == &c || (q.x() == c.x() && q.y() == c.y()))
        continue;
      const FT xi = (q.x() - c.x()) * inverse_scale, eta = (q.y() - c.y()) * inverse_scale;
      for (int copy = 0; copy < it->second; ++copy) {
        ++passes;
        for (int total = (std::min)(d, passes); total >= 1; --total)
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
    }
    if constexpr (fraction_free)
      if (has_fraction(v))
        return polar_value_fraction_free(v, e, (std::min)(d, passes), n);
    Value sum = m_coefficients[coefficients_per_vertex * at(v)];
    for (int h = 0; h <= d; ++h)
      for (int k = 0; h + k <= d; ++k) {
        if (h + k == 0)
          continue;
        if (h + k > passes) { // e is 0: (0 / count) is 0, without the division
          sum = sum + FT(0) * coefficient(v, h, k);
          continue;
        }
        const FT count = FT(binomial(n, h) * binomial(n - h, k));
        sum = sum + (e[std::size_t(h)][std::size_t(k)] / count) * coefficient(v, h, k);
      }
    return sum;
  }

  /// returns the gradient of \f$p_v\f$ at \f$v\f$.
  /// \param v the index of a vertex
  /// \returns the gradient of \f$p_v\f$ at \f$v\f$
  std::array<Value, 2> gradient(Index v) const {
    if constexpr (fraction_free)
      if (has_fraction(v))
        return {{m_scale[v] * fraction(v, 1, 0), m_scale[v] * fraction(v, 0, 1)}};
    return {{m_scale[v] * coefficient(v, 1, 0), m_scale[v] * coefficient(v, 0, 1)}};
  }

private:
  static constexpr std::size_t coefficients_per_vertex =
      (max_supported_degree + 1) * (max_supported_degree + 2) / 2;
  static constexpr std::uint32_t not_kept = std::numeric_limits<std::uint32_t>::max();
  // Where v's coefficients are: their block in m_coefficients (and m_numerators).
  std::size_t at(Index v) const {
    CGAL_precondition(is_kept(v));
    return m_on_demand ? std::size_t(m_stored_at[v]) : std::size_t(v);
  }
  // Zeroed coefficient storage for n vertices (a fraction-free vertex is recognised by its
  // non-zero denominator, so none may be left from the vertices kept before).
  void allocate(std::size_t n) {
    // (a fit_first() of many vertices must not leave its storage to every later block)
    if (m_coefficients.capacity() > 2 * n * coefficients_per_vertex + 4096)
      std::vector<Value>().swap(m_coefficients);
    m_coefficients.assign(n * coefficients_per_vertex, Value_traits<Value>::zero());
    if constexpr (fraction_free) {
      if (m_fraction_free) {
        if (m_numerators.capacity() > 2 * n * coefficients_per_vertex * D + 4096)
          std::vector<Integer>().swap(m_numerators);
        m_numerators.assign(n * coefficients_per_vertex * D, Integer(0));
        m_denominators.assign(n * D, Integer(0));
      }
    }
  }
  // Fits vertex_at(i) for i in [0, n). The fits are independent: one thread per core on
  // large inputs (each vertex's result does not depend on the partition, so output is
  // deterministic). An exact fit costs milliseconds, so exact builds go parallel from a few
  // hundred vertices.
  template <class Vertex_at>
  void fit_list(std::size_t n, const Vertex_at& vertex_at) {
    std::size_t threads = m_threads;
    if (threads == 0) {
      const std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
      threads = (std::min)(cores, n / (exact ? 128 : 2000) + 1);
    }
    auto fit_range = [&](std::size_t first) {
#if CGAL_TRIANGULAR_SPLINE_AVX2_CLONES
      if (internal::use_avx2_clones()) {
        fit_every_avx2(first, threads, n, vertex_at);
        return;
      }
#endif
      fit_every(first, threads, n, vertex_at);
    };
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < threads; ++t)
      workers.emplace_back(fit_range, t);
    fit_range(0);
    for (std::thread& worker : workers)
      worker.join();
  }
  // Fits vertex_at(i) for i = first, first + step, ... below n (one thread's share). The
  // double kernels are inlined into it; fit_every() and fit_every_avx2() compile it for
  // SSE2 and for AVX2 (internal/avx2_clones.h: the same bits, the kernels in 0.8 times the
  // time). With AVX, four vertices at a time (fit_batch(): the same bits again, the fits in
  // 0.7 times the time on random points).
  template <bool Wide, class Vertex_at>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE void fit_share(std::size_t first, std::size_t step,
                                                      std::size_t n, const Vertex_at& vertex_at) {
#if CGAL_TRIANGULAR_SPLINE_LANE_BATCHES
    if constexpr (!exact && (Wide || native_wide_lanes)) {
      Lanes lanes;
      std::array<Index, batch_lanes> batch;
      std::size_t count = 0;
      for (std::size_t i = first; i < n; i += step) {
        batch[count++] = vertex_at(i);
        if (count == batch_lanes) {
          fit_batch<Wide>(batch, count, lanes);
          count = 0;
        }
      }
      if (count > 0)
        fit_batch<Wide>(batch, count, lanes);
      return;
    }
#endif
    Workspace work;
    for (std::size_t i = first; i < n; i += step)
      fit_vertex<Wide>(vertex_at(i), *m_data, work);
  }
  template <class Vertex_at>
  void fit_every(std::size_t first, std::size_t step, std::size_t n, const Vertex_at& vertex_at) {
    fit_share<false>(first, step, n, vertex_at);
  }
  // fit_first(): vertices 0, 1, ... below n until `stop` (read every 64 vertices, about half
  // a millisecond); returns how many.
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE std::size_t fit_first_share(std::size_t n,
                                                                   const std::atomic<bool>& stop) {
    std::size_t i = 0;
#if CGAL_TRIANGULAR_SPLINE_LANE_BATCHES
    if constexpr (!exact && (Wide || native_wide_lanes)) {
      Lanes lanes;
      for (; i < n; i += batch_lanes) { // 64 is a multiple of batch_lanes
        if (i % 64 == 0 && stop.load(std::memory_order_relaxed))
          break;
        std::array<Index, batch_lanes> batch;
        const std::size_t count = (std::min)(batch_lanes, n - i);
        for (std::size_t l = 0; l < count; ++l)
          batch[l] = static_cast<Index>(i + l);
        fit_batch<Wide>(batch, count, lanes);
      }
      return (std::min)(i, n);
    }
#endif
    Workspace work;
    for (; i < n; ++i) {
      if (i % 64 == 0 && stop.load(std::memory_order_relaxed))
        break;
      fit_vertex<Wide>(static_cast<Index>(i), *m_data, work);
    }
    return i;
  }
#if CGAL_TRIANGULAR_SPLINE_AVX2_CLONES
  template <class Vertex_at>
  CGAL_TRIANGULAR_SPLINE_AVX2_TARGET void
  fit_every_avx2(std::size_t first, std::size_t step, std::size_t n, const Vertex_at& vertex_at) {
    fit_share<true>(first, step, n, vertex_at);
  }
  CGAL_TRIANGULAR_SPLINE_AVX2_TARGET std::size_t fit_first_avx2(std::size_t n,
                                                                const std::atomic<bool>& stop) {
    return fit_first_share<true>(n, stop);
  }
#endif
  static constexpr int D = Value_traits<Value>::dimension;
  static constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  // Exact number types that are fractions of an integer type fit over those integers.
  static constexpr bool fraction_free =
      std::is_same_v<typename Fraction_traits<FT>::Is_fraction, Tag_true>;
  using Integer =
      std::conditional_t<fraction_free, typename Fraction_traits<FT>::Numerator_type, char>;
  // Interior vertices reach twice the points a quintic needs within four rings; corners of
  // the domain see a quarter of each ring and need more.
  static constexpr int max_rings = 8;

  struct Workspace {
    std::vector<Index> ring;         // the first ring, in point order (the plane's points)
    std::vector<Index> points;       // candidates from the rings, nearest first
    std::vector<std::uint32_t> mark; // BFS marks, by vertex (stamp = v + 1; lanes share one)
    // the double fits, column-major: design, rhs (reflected in place), their originals, the
    // rows of Q, leverages and fitted values
    std::vector<double> design, rhs, original, rhs_original, q, leverage, fitted;
    std::vector<double> monomials; // the stability check's design rows and weights
    std::vector<int> ring_of;      // the ring of each candidate (0: the first)
    // the candidates with their distances weighted by ring; the first `ordered` of them (and
    // of `points`) are the nearest, in order, the rest in no order
    std::vector<std::pair<double, Index>> near;
    std::size_t ordered = 0;
  };

  // C(n, k) for n, k <= 5, from a table: polar values sit on the hot path of every fit (one
  // per free control point), and the loop with integer divisions cost more than the rest.
  static int binomial(int n, int k) {
    static constexpr int table[6][6] = {{1, 0, 0, 0, 0, 0}, {1, 1, 0, 0, 0, 0},
                                        {1, 2, 1, 0, 0, 0}, {1, 3, 3, 1, 0, 0},
                                        {1, 4, 6, 4, 1, 0}, {1, 5, 10, 10, 5, 1}};
    return table[n][k];
  }
  static constexpr int unknowns(int d) {
    return (d + 1) * (d + 2) / 2 - 1;
  }

  // Whether v's coefficients of degree >= 1 are kept as numerators over a common
  // denominator (then only there: reducing each fraction costs a gcd of thousands of digits).
  bool has_fraction(Index v) const {
    return !m_denominators.empty() && !CGAL::is_zero(m_denominators[at(v) * D]);
  }
  // The coefficient of xi^h eta^k of such a vertex.
  Value fraction(Index v, int h, int k) const {
    typename Fraction_traits<FT>::Compose compose;
    std::array<FT, std::size_t(D)> cs;
    for (int j = 0; j < D; ++j)
      cs[std::size_t(j)] = compose(
          m_numerators[(coefficients_per_vertex * at(v) + position(h, k)) * D + std::size_t(j)],
          m_denominators[at(v) * D + std::size_t(j)]);
    return Value_traits<Value>::from_coordinates(cs);
  }

  // polar_value() from the numerators over the vertex's common denominator: the factors
  // e[h][k] / C(n; h, k) are brought to one small denominator, the sum is taken in integers,
  // and one fraction is formed per coordinate (a rational sum would reduce every partial
  // sum against the coefficients' denominators of thousands of digits).
  template <class Table>
  Value polar_value_fraction_free(Index v, const Table& e, int top, int n) const {
    using FTr = Fraction_traits<FT>;
    typename FTr::Decompose decompose;
    typename FTr::Compose compose;
    const auto gcd = typename Algebraic_structure_traits<Integer>::Gcd();
    const auto divide = typename Algebraic_structure_traits<Integer>::Integral_division();
    std::array<Integer, coefficients_per_vertex> p, q;
    Integer common(1);
    for (int t = 1; t <= top; ++t)
      for (int h = 0; h <= t; ++h) {
        const int k = t - h;
        const std::size_t i = position(h, k);
        decompose(e[std::size_t(h)][std::size_t(k)] / FT(binomial(n, h) * binomial(n - h, k)), p[i],
                  q[i]);
        if (!CGAL::is_zero(p[i]))
          common = divide(common, gcd(common, q[i])) * q[i];
      }
    std::array<FT, std::size_t(D)> cs;
    const Value& constant = m_coefficients[coefficients_per_vertex * at(v)];
    for (int j = 0; j < D; ++j) {
      Integer sum(0);
      for (int t = 1; t <= top; ++t)
        for (int h = 0; h <= t; ++h) {
          const std::size_t i = position(h, t - h);
          if (!CGAL::is_zero(p[i]))
            sum += p[i] * divide(common, q[i]) *
                   m_numerators[(coefficients_per_vertex * at(v) + i) * D + std::size_t(j)];
        }
      cs[std::size_t(j)] = Value_traits<Value>::coordinate(constant, j) +
                           compose(sum, common * m_denominators[at(v) * D + std::size_t(j)]);
    }
    return Value_traits<Value>::from_coordinates(cs);
  }
  // Position of x^h y^k in the per-vertex coefficient block (by total degree, then h).
  static std::size_t position(int h, int k) {
    const int t = h + k;
    return std::size_t(t * (t + 1) / 2 + k);
  }
  const Value& coefficient(Index v, int h, int k) const {
    return m_coefficients[coefficients_per_vertex * at(v) + position(h, k)];
  }
  Value& coefficient(Index v, int h, int k) {
    return m_coefficients[coefficients_per_vertex * at(v) + position(h, k)];
  }

  // The points a fit of degree d takes: 1.5 times its unknowns (a plane: 2).
  static constexpr std::size_t needed(int d) {
    return d == 1 ? 2 : std::size_t((3 * unknowns(d) + 1) / 2);
  }

  // The neighbourhood of v: its first ring (the plane's points), and candidates from the
  // rings by breadth-first search (up to max_rings rings, until twice the points the
  // largest degree needs), ordered by their distance from v times 1.5 per ring beyond the
  // first. The fits take the first candidates in that order rather than whole rings: along
  // the hull of scattered data the rings reach far along long boundary edges, the fits then
  // bend to those far points and choose low degrees (Franke's function from 16641 random
  // points: largest error 1.4e-3 near the hull with whole rings, 3.3e-6 now; scipy's
  // Clough-Tocher 3.2e-4). The factor keeps the rings' balance where the data are sparse
  // or clustered: with plain distances (factor 1) the nearest points of a vertex at the edge
  // of a cluster all lie on one side and its polynomial overshoots the data by 3x (60
  // clustered points). A boundary vertex also keeps the first-ring neighbours within twice
  // the distance of its farthest point: its polynomial is read along the boundary edges,
  // and without them the local fit of 500 points of a terrain overshot by 3 km along a
  // long hull edge.
  static constexpr std::array<double, max_rings + 1> ring_factor2 = {
      1,
      2.25,
      5.0625,
      11.390625,
      25.62890625,
      57.6650390625,
      129.746337890625,
      291.92926025390625,
      656.8408355712891}; // 1.5^(2 ring)
  void gather(Index v, Workspace& work, std::vector<std::uint32_t>& mark) const {
    const Domain& domain = *m_domain;
    if (mark.size() != domain.number_of_vertices())
      mark.assign(domain.number_of_vertices(), 0);
    const std::uint32_t stamp = static_cast<std::uint32_t>(v) + 1;
    work.points.clear();
    work.ring_of.clear();
    mark[v] = stamp;
    const std::size_t wanted = 2 * needed(m_max_degree);
    std::size_t begin = 0;
    for (int ring = 0; ring < max_rings; ++ring) {
      const std::size_t end = work.points.size();
      auto visit = [&](Index u) {
        const auto [nb, ne] = domain.neighbours(u);
        for (auto w = nb; w != ne; ++w)
          if (mark[*w] != stamp) {
            mark[*w] = stamp;
            work.points.push_back(*w);
            work.ring_of.push_back(ring);
          }
      };
      if (ring == 0)
        visit(v);
      else
        for (std::size_t i = begin; i < end; ++i)
          visit(work.points[i]);
      if (ring == 0)
        work.ring.assign(work.points.begin(), work.points.end());
      begin = end;
      if (work.points.size() >= wanted || work.points.size() == end)
        break;
    }
    // Orders that do not depend on the traversal, so that neither does the double solve.
    std::sort(work.ring.begin(), work.ring.end(),
              [&](Index a, Index b) { return point_less(a, b); });
    const Point_2& c = domain.point(v);
    const double cx = CGAL::to_double(c.x()), cy = CGAL::to_double(c.y());
    auto distance2 = [&](Index a) {
      const double dx = CGAL::to_double(domain.point(a).x()) - cx;
      const double dy = CGAL::to_double(domain.point(a).y()) - cy;
      return dx * dx + dy * dy;
    };
    const auto& factor2 = ring_factor2;
    work.near.resize(work.points.size());
    for (std::size_t i = 0; i < work.points.size(); ++i)
      work.near[i] = {distance2(work.points[i]) * factor2[std::size_t(work.ring_of[i])],
                      work.points[i]};
    work.ordered = 0;
    // Interior vertices order only the candidates a fit takes (order_nearest()); a boundary
    // vertex reorders them all below.
    if (domain.is_boundary_vertex(v) && !work.points.empty()) {
      order_nearest(work.points.size(), work);
      // First-ring neighbours within twice the distance of the farthest point the largest
      // degree takes come first, nearest first.
      const std::size_t k = (std::min)(needed(m_max_degree), work.points.size());
      const double reach2 = 4 * distance2(work.points[k - 1]);
      auto kept = [&](Index w) {
        return distance2(w) <= reach2 &&
               std::binary_search(work.ring.begin(), work.ring.end(), w,
                                  [&](Index a, Index b) { return point_less(a, b); });
      };
      std::stable_partition(work.points.begin(), work.points.end(), kept);
    }
  }

  // Puts the `count` nearest candidates first in `work.points`, nearest first: the order of
  // a full sort (the order is total), paid only for the candidates the fits take (a tenth
  // fewer instructions to gather than sorting all of them).
  void order_nearest(std::size_t count, Workspace& work) const {
    count = (std::min)(count, work.near.size());
    if (count <= work.ordered)
      return;
    auto less = [&](const std::pair<double, Index>& a, const std::pair<double, Index>& b) {
      return a.first < b.first || (a.first == b.first && point_less(a.second, b.second));
    };
    const auto first = work.near.begin() + std::ptrdiff_t(work.ordered);
    const auto middle = work.near.begin() + std::ptrdiff_t(count);
    if (middle != work.near.end())
      std::nth_element(first, middle, work.near.end(), less);
    std::sort(first, middle, less);
    for (std::size_t i = work.ordered; i < work.near.size(); ++i)
      work.points[i] = work.near[i].second; // the tail too: data_scale reads every candidate
    work.ordered = count;
  }

  bool point_less(Index a, Index b) const {
    const Point_2 &p = m_domain->point(a), &q = m_domain->point(b);
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  }

  // One Householder QR of the weighted design matrix of the points [0, n), columns ordered
  // by degree (x, y, x^2, xy, y^2, ...): its leading columns are the QR of every lower
  // degree on the same points, so one factorization gives the fits and leave-one-out
  // scores of all the degrees that share these points (issue 10: one QR instead of five,
  // and no explicit Q).
  static constexpr std::size_t max_columns = 20; // the unknowns of a quintic

  // sum x[i] y[i] over [begin, end), in four interleaved partial sums: without them the
  // compiler may not reorder the additions, and one chain of dependent adds is four times
  // slower (the order is fixed, so the result does not depend on the machine's load).
  // GCC and Clang: the four sums as two vectors of two lanes (SSE2), or one of four lanes
  // (Wide: the AVX2 clone), the same operations on every lane (the same bits), which the
  // compiler does not find itself (half the instructions of the fits went here).
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static double dot(const double* x, const double* y,
                                                         std::size_t begin, std::size_t end) {
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    std::size_t i = begin;
#if defined(__GNUC__)
    if constexpr (Wide) { // lane l sums the products l mod 4
      typedef double Quad __attribute__((vector_size(32)));
      Quad s = {0, 0, 0, 0};
      for (; i + 4 <= end; i += 4) {
        Quad xv, yv;
        std::memcpy(&xv, x + i, sizeof(Quad));
        std::memcpy(&yv, y + i, sizeof(Quad));
        s += xv * yv;
      }
      s0 = s[0];
      s1 = s[1];
      s2 = s[2];
      s3 = s[3];
    } else {
      typedef double Pair __attribute__((vector_size(16)));
      Pair s01 = {0, 0}, s23 = {0, 0};
      for (; i + 4 <= end; i += 4) {
        Pair x01, x23, y01, y23;
        std::memcpy(&x01, x + i, sizeof(Pair));
        std::memcpy(&x23, x + i + 2, sizeof(Pair));
        std::memcpy(&y01, y + i, sizeof(Pair));
        std::memcpy(&y23, y + i + 2, sizeof(Pair));
        s01 += x01 * y01;
        s23 += x23 * y23;
      }
      s0 = s01[0];
      s1 = s01[1];
      s2 = s23[0];
      s3 = s23[1];
    }
#else
    for (; i + 4 <= end; i += 4) {
      s0 += x[i] * y[i];
      s1 += x[i + 1] * y[i + 1];
      s2 += x[i + 2] * y[i + 2];
      s3 += x[i + 3] * y[i + 3];
    }
#endif
    for (; i < end; ++i)
      s0 += x[i] * y[i];
    return (s0 + s1) + (s2 + s3);
  }
#if defined(__GNUC__)
  // The loops below over whole vectors of `Bytes` (16: SSE2, 32: AVX2 or two SSE2
  // registers), from i on; each lane does the scalar loop's operations.
  template <std::size_t Bytes>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static void
  subtract_multiple_lanes(double* x, const double* a, double f, std::size_t& i, std::size_t end) {
    typedef double Lanes __attribute__((vector_size(Bytes)));
    constexpr std::size_t L = Bytes / sizeof(double);
    const Lanes ff = Lanes{} + f;
    for (; i + L <= end; i += L) {
      Lanes xv, av;
      std::memcpy(&xv, x + i, sizeof(Lanes));
      std::memcpy(&av, a + i, sizeof(Lanes));
      xv -= ff * av;
      std::memcpy(x + i, &xv, sizeof(Lanes));
    }
  }
  template <std::size_t Bytes>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static void
  subtract_two_multiples_lanes(double* y, const double* a0, double r0, const double* a1, double r1,
                               std::size_t& i, std::size_t n) {
    typedef double Lanes __attribute__((vector_size(Bytes)));
    constexpr std::size_t L = Bytes / sizeof(double);
    const Lanes rr0 = Lanes{} + r0, rr1 = Lanes{} + r1;
    for (; i + L <= n; i += L) {
      Lanes yv, v0, v1;
      std::memcpy(&yv, y + i, sizeof(Lanes));
      std::memcpy(&v0, a0 + i, sizeof(Lanes));
      std::memcpy(&v1, a1 + i, sizeof(Lanes));
      yv = (yv - rr0 * v0) - rr1 * v1;
      std::memcpy(y + i, &yv, sizeof(Lanes));
    }
  }
#endif
  // x[i] -= f a[i] over [begin, end), four (Wide) then two lanes at a time where the compiler
  // allows (its own vectorisation of these short loops of varying start spent more on
  // peeling than on work).
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static void
  subtract_multiple(double* x, const double* a, double f, std::size_t begin, std::size_t end) {
    std::size_t i = begin;
#if defined(__GNUC__)
    if constexpr (Wide)
      subtract_multiple_lanes<32>(x, a, f, i, end);
    subtract_multiple_lanes<16>(x, a, f, i, end);
#endif
    for (; i < end; ++i)
      x[i] -= f * a[i];
  }
  // y[i] = (y[i] - r0 a0[i]) - r1 a1[i] over [0, n): two subtractions per pass, in order.
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static void
  subtract_two_multiples(double* y, const double* a0, double r0, const double* a1, double r1,
                         std::size_t n) {
    std::size_t i = 0;
#if defined(__GNUC__)
    if constexpr (Wide)
      subtract_two_multiples_lanes<32>(y, a0, r0, a1, r1, i, n);
    subtract_two_multiples_lanes<16>(y, a0, r0, a1, r1, i, n);
#endif
    for (; i < n; ++i)
      y[i] = (y[i] - r0 * a0[i]) - r1 * a1[i];
  }
  // Scratch buffers only grow: every entry read is written first, and zero-filling them anew
  // at each of the three fits of every vertex cost 5% of the fits.
  static void grow(std::vector<double>& buffer, std::size_t size) {
    if (buffer.size() < size)
      buffer.resize(size);
  }
  struct Group {
    Group() {}            // no zero-filling: only the entries written are read
    bool on_ring = false; // the first ring's points, else the nearest candidates
    std::size_t n = 0;
    double scale = 0, weight_sum = 0;
    double radius = 0; // the largest distance of the points from v
    int columns = 0;   // columns factorized (a column nearly in the span of the previous ones
                       // stops the factorization)
    std::array<double, max_columns> ratio;           // |R_kk| / |a_k|: how independent column k is
    std::array<double, max_columns * max_columns> R; // upper triangle, R[j * 20 + i], i <= j
    std::array<double, max_columns * std::size_t(D)> c; // Q^T b, per coordinate
  };

  // Factorizes the weighted design of degree `d` on the first `n` points into `g`;
  // false if the points have no extent.
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE bool
  factorize(Index v, const std::vector<Value>& values, const std::vector<Index>& points, int d,
            std::size_t n, Workspace& work, Group& g) const {
    const Domain& domain = *m_domain;
    const Point_2& center = domain.point(v);
    const double cx = CGAL::to_double(center.x()), cy = CGAL::to_double(center.y());
    // Scale: a power of two at least the largest distance, so |xi|, |eta| <= 1 and the
    // exact coordinates stay dyadic multiples of the data.
    double radius2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& p = domain.point(points[i]);
      const double dx = CGAL::to_double(p.x()) - cx, dy = CGAL::to_double(p.y()) - cy;
      radius2 = (std::max)(radius2, dx * dx + dy * dy);
    }
    const double radius = std::sqrt(radius2);
    if (!(radius > 0) || !std::isfinite(radius))
      return false;
    const int u = unknowns(d);
    g.n = n;
    g.scale = std::exp2(std::ceil(std::log2(radius)));
    g.radius = radius;
    g.weight_sum = 0;
    grow(work.design, n * std::size_t(u));
    grow(work.rhs, n * std::size_t(D));
    double* A = work.design.data();
    double* b = work.rhs.data();
    std::array<double, 6> xp, yp;
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& p = domain.point(points[i]);
      const double xi = (CGAL::to_double(p.x()) - cx) / g.scale;
      const double eta = (CGAL::to_double(p.y()) - cy) / g.scale;
      const double w = 1 / std::sqrt(xi * xi + eta * eta); // square root of the weight
      g.weight_sum += w * w;
      xp[0] = w;
      yp[0] = 1;
      for (int e = 1; e <= d; ++e) {
        xp[std::size_t(e)] = xp[std::size_t(e - 1)] * xi;
        yp[std::size_t(e)] = yp[std::size_t(e - 1)] * eta;
      }
      int col = 0;
      for (int t = 1; t <= d; ++t)
        for (int k = 0; k <= t; ++k, ++col) // w xi^(t-k) eta^k
          A[std::size_t(col) * n + i] = xp[std::size_t(t - k)] * yp[std::size_t(k)];
      for (int k = 0; k < D; ++k)
        b[std::size_t(k) * n + i] =
            w * (CGAL::to_double(Value_traits<Value>::coordinate(values[points[i]], k)) -
                 CGAL::to_double(Value_traits<Value>::coordinate(values[v], k)));
    }
    // kept for the rows of Q = A R^-1 and the residuals
    work.original.assign(A, A + n * std::size_t(u));
    work.rhs_original.assign(b, b + n * std::size_t(D));
    g.columns = 0;
    for (int k = 0; k < u; ++k) {
      double* a = A + std::size_t(k) * n;
      const double* original = work.original.data() + std::size_t(k) * n;
      const double norm2 = dot<Wide>(original, original, 0, n);
      const double below2 = dot<Wide>(a, a, std::size_t(k), n);
      const double sigma = std::sqrt(below2);
      const double ratio = norm2 > 0 ? sigma / std::sqrt(norm2) : 0;
      if (!(ratio > 1e-14))
        break; // dependent: no division by a vanishing pivot
      g.ratio[std::size_t(k)] = ratio;
      // Householder reflector H = I - v v^T / (sigma |a_k|), v = a - alpha e_k.
      const double alpha = a[k] > 0 ? -sigma : sigma;
      a[k] -= alpha;
      const double beta = sigma * std::abs(a[k]); // v^T v / 2
      for (int j = k + 1; j < u; ++j) {
        double* x = A + std::size_t(j) * n;
        subtract_multiple<Wide>(x, a, dot<Wide>(a, x, std::size_t(k), n) / beta, std::size_t(k), n);
      }
      for (int j = 0; j < D; ++j) {
        double* x = b + std::size_t(j) * n;
        subtract_multiple<Wide>(x, a, dot<Wide>(a, x, std::size_t(k), n) / beta, std::size_t(k), n);
      }
      for (int i = 0; i < k; ++i)
        g.R[std::size_t(k) * max_columns + std::size_t(i)] = A[std::size_t(k) * n + std::size_t(i)];
      g.R[std::size_t(k) * max_columns + std::size_t(k)] = alpha;
      for (int j = 0; j < D; ++j)
        g.c[std::size_t(j) * max_columns + std::size_t(k)] = b[std::size_t(j) * n + std::size_t(k)];
      ++g.columns;
    }
    // R's entries above the diagonal of the columns not yet stored (row k of column j > k
    // is final once reflector k has been applied).
    for (int j = 0; j < g.columns; ++j)
      for (int i = 0; i < j; ++i)
        g.R[std::size_t(j) * max_columns + std::size_t(i)] = A[std::size_t(j) * n + std::size_t(i)];
    return true;
  }

  // Leave-one-out scores of the fits with the first u[0] < u[1] < ... columns of `g`
  // (weighted least squares: residual r_i / (1 - h_ii), h the hat matrix Q Q^T; the rows of
  // Q are those of A R^-1): the weighted mean square of the left-out residuals, infinite
  // where a point's leverage is 1.
  template <bool Wide, std::size_t N>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE void scores(const Group& g, const std::array<int, N>& u,
                                                   std::size_t count, Workspace& work,
                                                   std::array<double, N>& score) const {
    const std::size_t n = g.n;
    const int last = u[count - 1];
    // Y = A R^-1 column by column (each column an update of contiguous point vectors), with
    // every point's leverage and fitted values accumulated as the columns come.
    grow(work.q, n * std::size_t(last));
    work.leverage.assign(n, 0.0);
    work.fitted.assign(n * std::size_t(D), 0.0);
    double* Y = work.q.data();
    std::size_t next = 0;
    for (int j = 0; j < last; ++j) {
      double* y = Y + std::size_t(j) * n;
      const double* a = work.original.data() + std::size_t(j) * n;
      for (std::size_t i = 0; i < n; ++i)
        y[i] = a[i];
      // two previous columns per pass, subtracted in the same order (the same bits), y read
      // and written half as often
      int l = 0;
      for (; l + 2 <= j; l += 2) {
        const double r0 = g.R[std::size_t(j) * max_columns + std::size_t(l)];
        const double r1 = g.R[std::size_t(j) * max_columns + std::size_t(l + 1)];
        subtract_two_multiples<Wide>(y, Y + std::size_t(l) * n, r0, Y + std::size_t(l + 1) * n, r1,
                                     n);
      }
      if (l < j)
        subtract_multiple<Wide>(y, Y + std::size_t(l) * n,
                                g.R[std::size_t(j) * max_columns + std::size_t(l)], 0, n);
      const double inverse = 1 / g.R[std::size_t(j) * max_columns + std::size_t(j)];
      for (std::size_t i = 0; i < n; ++i) {
        y[i] *= inverse;
        work.leverage[i] += y[i] * y[i];
      }
      for (int k = 0; k < D; ++k) {
        const double c = g.c[std::size_t(k) * max_columns + std::size_t(j)];
        double* f = work.fitted.data() + std::size_t(k) * n;
        for (std::size_t i = 0; i < n; ++i)
          f[i] += y[i] * c;
      }
      if (j + 1 != u[next])
        continue;
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        double residual2 = 0;
        for (int k = 0; k < D; ++k) {
          const double r =
              work.rhs_original[std::size_t(k) * n + i] - work.fitted[std::size_t(k) * n + i];
          residual2 += r * r;
        }
        const double keep = 1 - work.leverage[i];
        if (!(keep > 1e-8)) {
          sum = std::numeric_limits<double>::infinity();
          break;
        }
        sum += residual2 / (keep * keep);
      }
      score[next++] = sum / g.weight_sum;
    }
  }

  // The groups of degrees 2-3 and 4-5 of nearly every vertex, on the nearest needed(3) and
  // needed(5) candidates: their factorizations and scores dominate the fits.
  static constexpr std::size_t batch_points = needed(max_supported_degree);
  struct Prefactored {
    Group group;
    std::array<double, 3> score; // of the plane and the group's two degrees on its points
  };
#if CGAL_TRIANGULAR_SPLINE_LANE_BATCHES
  // Four vertices' groups (of degrees 2-3, then 4-5) factorized side by side, one vertex per
  // lane of a vector of four doubles: factorize() and scores() on the same points, operation for
  // operation (the same sums in the same order, dot()'s four partial sums included), so
  // the same bits, without the horizontal sums, tails and short loops that kept the
  // one-vertex kernels at about a quarter of the vector units' rate. Generic vectors: two
  // SSE2 or one AVX2 operation each, the same bits either way.
  static constexpr std::size_t batch_lanes = 4;
  typedef double Lane_vector __attribute__((vector_size(32)));
  // Only where a vector of four doubles is one register: as two SSE2 registers the lanes
  // took 1.12 times the one-vertex kernels' time (200000 random points).
#if defined(__AVX__)
  static constexpr bool native_wide_lanes = true;
#else
  static constexpr bool native_wide_lanes = false;
#endif
  struct Lane_arrays { // column-major as in factorize(): entry i of column k at [k * n + i]
    Lane_vector design[max_columns * batch_points], original[max_columns * batch_points];
    Lane_vector q[max_columns * batch_points]; // the rows of Q = A R^-1, as in scores()
    Lane_vector rhs[D * batch_points], rhs_original[D * batch_points];
    Lane_vector fitted[D * batch_points], leverage[batch_points];
    Lane_vector R[max_columns * max_columns], c[D * max_columns];
  };
  struct Lanes {
    std::array<Workspace, batch_lanes> work;
    std::unique_ptr<Lane_arrays> arrays{new Lane_arrays};
    std::array<std::array<Prefactored, batch_lanes>, 2> pre; // degrees 2-3, 4-5
  };
  // dot() on every lane (the result through a reference: a vector of four doubles passed by
  // value has another ABI with and without AVX)
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE static void dot_lanes(const Lane_vector* x,
                                                             const Lane_vector* y,
                                                             std::size_t begin, std::size_t end,
                                                             Lane_vector& result) {
    Lane_vector s0 = {0, 0, 0, 0}, s1 = s0, s2 = s0, s3 = s0;
    std::size_t i = begin;
    for (; i + 4 <= end; i += 4) {
      s0 += x[i] * y[i];
      s1 += x[i + 1] * y[i + 1];
      s2 += x[i + 2] * y[i + 2];
      s3 += x[i + 3] * y[i + 3];
    }
    for (; i < end; ++i)
      s0 += x[i] * y[i];
    result = (s0 + s1) + (s2 + s3);
  }

  // factorize() of degree Top (3 or 5) on the first needed(Top) candidates and scores() of
  // the plane and degrees Top - 1 and Top, for the lanes `eligible` (the others compute a
  // copy of an eligible lane and are ignored), into lanes.pre[Top / 2 - 1]; returns the
  // lanes whose factorization has every column (finish_vertex() redoes the others).
  template <int Top>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE std::array<bool, batch_lanes>
  factorize_lanes(const std::array<Index, batch_lanes>& batch,
                  const std::array<bool, batch_lanes>& eligible, Lanes& lanes) const {
    static_assert(Top == 3 || Top == max_supported_degree, "the groups of fit_vertex()");
    const Domain& domain = *m_domain;
    const std::vector<Value>& values = *m_data;
    constexpr std::size_t n = needed(Top);
    constexpr int u = unknowns(Top);
    Lane_arrays& L = *lanes.arrays;
    std::array<Prefactored, batch_lanes>& pre = lanes.pre[Top / 2 - 1];
    std::array<std::size_t, batch_lanes> source;
    std::size_t first = 0;
    while (!eligible[first])
      ++first;
    std::array<bool, batch_lanes> valid;
    Lane_vector cx, cy, scale;
    for (std::size_t l = 0; l < batch_lanes; ++l) {
      source[l] = eligible[l] ? l : first;
      const Index v = batch[source[l]];
      const std::vector<Index>& points = lanes.work[source[l]].points;
      Group& g = pre[l].group;
      const Point_2& center = domain.point(v);
      cx[l] = CGAL::to_double(center.x());
      cy[l] = CGAL::to_double(center.y());
      double radius2 = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Point_2& p = domain.point(points[i]);
        const double dx = CGAL::to_double(p.x()) - cx[l], dy = CGAL::to_double(p.y()) - cy[l];
        radius2 = (std::max)(radius2, dx * dx + dy * dy);
      }
      const double radius = std::sqrt(radius2);
      valid[l] = eligible[l] && radius > 0 && std::isfinite(radius);
      g.on_ring = false;
      g.n = n;
      g.scale = valid[l] ? std::exp2(std::ceil(std::log2(radius))) : 1.0;
      g.radius = radius;
      g.columns = u;
      scale[l] = g.scale;
    }
    // the weighted design and right-hand sides, as factorize() builds them
    const Lane_vector one = {1, 1, 1, 1};
    Lane_vector weight_sum = {0, 0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      Lane_vector px = {0, 0, 0, 0}, py = px, w = px;
      std::array<Lane_vector, std::size_t(D)> difference;
      for (std::size_t l = 0; l < batch_lanes; ++l) {
        const Index v = batch[source[l]], p = lanes.work[source[l]].points[i];
        px[l] = CGAL::to_double(domain.point(p).x());
        py[l] = CGAL::to_double(domain.point(p).y());
        for (int k = 0; k < D; ++k)
          difference[std::size_t(k)][l] =
              CGAL::to_double(Value_traits<Value>::coordinate(values[p], k)) -
              CGAL::to_double(Value_traits<Value>::coordinate(values[v], k));
      }
      const Lane_vector xi = (px - cx) / scale, eta = (py - cy) / scale;
      const Lane_vector r2 = xi * xi + eta * eta;
      for (std::size_t l = 0; l < batch_lanes; ++l)
        w[l] = 1 / std::sqrt(r2[l]);
      weight_sum += w * w;
      std::array<Lane_vector, Top + 1> xp, yp;
      xp[0] = w;
      yp[0] = one;
      for (std::size_t e = 1; e <= std::size_t(Top); ++e) {
        xp[e] = xp[e - 1] * xi;
        yp[e] = yp[e - 1] * eta;
      }
      std::size_t col = 0;
      for (std::size_t t = 1; t <= std::size_t(Top); ++t)
        for (std::size_t k = 0; k <= t; ++k, ++col)
          L.design[col * n + i] = xp[t - k] * yp[k];
      for (std::size_t k = 0; k < std::size_t(D); ++k)
        L.rhs[k * n + i] = w * difference[k];
    }
    std::copy(L.design, L.design + std::size_t(u) * n, L.original);
    std::copy(L.rhs, L.rhs + std::size_t(D) * n, L.rhs_original);
    // Householder QR, as factorize()
    for (std::size_t k = 0; k < std::size_t(u); ++k) {
      Lane_vector* a = L.design + k * n;
      Lane_vector norm2, below2, sigma = {0, 0, 0, 0}, alpha = sigma, beta = sigma;
      dot_lanes(L.original + k * n, L.original + k * n, 0, n, norm2);
      dot_lanes(a, a, k, n, below2);
      for (std::size_t l = 0; l < batch_lanes; ++l) {
        sigma[l] = std::sqrt(below2[l]);
        const double ratio = norm2[l] > 0 ? sigma[l] / std::sqrt(norm2[l]) : 0;
        if (!(ratio > 1e-14))
          valid[l] = false; // factorize() stops here: fit_vertex() redoes it
        pre[l].group.ratio[k] = ratio;
        alpha[l] = a[k][l] > 0 ? -sigma[l] : sigma[l];
      }
      a[k] -= alpha;
      for (std::size_t l = 0; l < batch_lanes; ++l)
        beta[l] = sigma[l] * std::abs(a[k][l]);
      for (std::size_t j = k + 1; j < std::size_t(u) + std::size_t(D); ++j) {
        Lane_vector* x = j < std::size_t(u) ? L.design + j * n : L.rhs + (j - std::size_t(u)) * n;
        Lane_vector f;
        dot_lanes(a, x, k, n, f);
        f /= beta;
        for (std::size_t i = k; i < n; ++i)
          x[i] -= f * a[i];
      }
      L.R[k * max_columns + k] = alpha;
      for (std::size_t j = 0; j < std::size_t(D); ++j)
        L.c[j * max_columns + k] = L.rhs[j * n + k];
    }
    for (std::size_t j = 0; j < std::size_t(u); ++j)
      for (std::size_t i = 0; i < j; ++i)
        L.R[j * max_columns + i] = L.design[j * n + i];
    // scores() of the plane and degrees Top - 1 and Top
    constexpr std::array<std::size_t, 3> checkpoint{
        {std::size_t(unknowns(1)), std::size_t(unknowns(Top - 1)), std::size_t(unknowns(Top))}};
    const Lane_vector zero = {0, 0, 0, 0};
    std::fill(L.leverage, L.leverage + n, zero);
    std::fill(L.fitted, L.fitted + std::size_t(D) * n, zero);
    std::size_t next = 0;
    for (std::size_t j = 0; j < std::size_t(u); ++j) {
      Lane_vector* y = L.q + j * n;
      std::copy(L.original + j * n, L.original + (j + 1) * n, y);
      std::size_t l = 0;
      for (; l + 2 <= j; l += 2) {
        const Lane_vector r0 = L.R[j * max_columns + l], r1 = L.R[j * max_columns + l + 1];
        const Lane_vector *y0 = L.q + l * n, *y1 = L.q + (l + 1) * n;
        for (std::size_t i = 0; i < n; ++i)
          y[i] = (y[i] - r0 * y0[i]) - r1 * y1[i];
      }
      if (l < j) {
        const Lane_vector r = L.R[j * max_columns + l];
        const Lane_vector* y0 = L.q + l * n;
        for (std::size_t i = 0; i < n; ++i)
          y[i] -= r * y0[i];
      }
      const Lane_vector inverse = one / L.R[j * max_columns + j];
      for (std::size_t i = 0; i < n; ++i) {
        y[i] *= inverse;
        L.leverage[i] += y[i] * y[i];
      }
      for (std::size_t k = 0; k < std::size_t(D); ++k) {
        const Lane_vector c = L.c[k * max_columns + j];
        Lane_vector* f = L.fitted + k * n;
        for (std::size_t i = 0; i < n; ++i)
          f[i] += y[i] * c;
      }
      if (j + 1 != checkpoint[next])
        continue;
      Lane_vector sum = zero;
      std::array<bool, batch_lanes> infinite{};
      for (std::size_t i = 0; i < n; ++i) {
        Lane_vector residual2 = zero;
        for (std::size_t k = 0; k < std::size_t(D); ++k) {
          const Lane_vector r = L.rhs_original[k * n + i] - L.fitted[k * n + i];
          residual2 += r * r;
        }
        const Lane_vector keep = one - L.leverage[i];
        for (std::size_t m = 0; m < batch_lanes; ++m)
          infinite[m] = infinite[m] || !(keep[m] > 1e-8);
        sum += residual2 / (keep * keep);
      }
      for (std::size_t m = 0; m < batch_lanes; ++m)
        pre[m].score[next] =
            infinite[m] ? std::numeric_limits<double>::infinity() : sum[m] / weight_sum[m];
      ++next;
    }
    for (std::size_t l = 0; l < batch_lanes; ++l) {
      if (!valid[l])
        continue;
      Group& g = pre[l].group;
      g.weight_sum = weight_sum[l];
      for (std::size_t j = 0; j < std::size_t(u); ++j)
        for (std::size_t i = 0; i <= j; ++i)
          g.R[j * max_columns + i] = L.R[j * max_columns + i][l];
      for (std::size_t k = 0; k < std::size_t(D); ++k)
        for (std::size_t j = 0; j < std::size_t(u); ++j)
          g.c[k * max_columns + j] = L.c[k * max_columns + j][l];
    }
    return valid;
  }

  // fit_vertex() of up to batch_lanes vertices, their groups of degrees 2-3 and 4-5
  // factorized side by side
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE void fit_batch(const std::array<Index, batch_lanes>& batch,
                                                      std::size_t count, Lanes& lanes) {
    const std::vector<Value>& values = *m_data;
    std::array<bool, batch_lanes> started{}, cubic{}, quintic{};
    bool any_cubic = false, any_quintic = false;
    for (std::size_t l = 0; l < count; ++l) {
      Workspace& work = lanes.work[l];
      started[l] = start_vertex(batch[l], values, work, lanes.work[0].mark);
      if (!started[l] || m_max_degree < 3 || work.points.size() < needed(3))
        continue;
      // the nearest candidates, in the order finish_vertex() takes them (prefixes of one
      // total order: its own calls for as many or fewer of them then change nothing)
      cubic[l] = any_cubic = true;
      if (m_max_degree == max_supported_degree && work.points.size() >= batch_points) {
        order_nearest(batch_points, work);
        quintic[l] = any_quintic = true;
      } else {
        order_nearest(needed(3), work);
      }
    }
    std::array<bool, batch_lanes> cubic_valid{}, quintic_valid{};
    if (any_cubic)
      cubic_valid = factorize_lanes<3>(batch, cubic, lanes);
    if (any_quintic)
      quintic_valid = factorize_lanes<max_supported_degree>(batch, quintic, lanes);
    for (std::size_t l = 0; l < count; ++l)
      if (started[l])
        finish_vertex<Wide>(batch[l], values, lanes.work[l],
                            {{cubic_valid[l] ? &lanes.pre[0][l] : nullptr,
                              quintic_valid[l] ? &lanes.pre[1][l] : nullptr}});
  }
#endif

  // Whether the first u columns of g are independent (each at a distance from the span of
  // the previous ones of at least 1e-6 of its length).
  // The largest Lebesgue constant a local fit may have near its vertex (see fit_vertex):
  // on random points and jittered grids 99% of the fits are below 10; a bound of 1000 instead
  // left an error of 9e-4 on a 33^2 grid jittered by 1e-3 (1.3e-4 with 300), one of 100 cost
  // a third of the accuracy on a grid jittered by 1e-2.
  static constexpr double max_lebesgue = 300;

  // Whether every one of the first u columns of g is at a distance of at least 1e-3 of its
  // length from the span of the previous ones: then the fit's Lebesgue constant near v stays
  // small (measured), and the stability check in fit_vertex is skipped (it would cost half
  // the fit; 98% of the fits on random points pass this).
  static bool well_determined(const Group& g, int u) {
    for (int k = 0; k < u; ++k)
      if (!(g.ratio[std::size_t(k)] >= 1e-3))
        return false;
    return true;
  }

  static bool determined(const Group& g, int u) {
    if (g.columns < u)
      return false;
    for (int k = 0; k < u; ++k)
      if (!(g.ratio[std::size_t(k)] > 1e-6))
        return false;
    return true;
  }

  // The monomials of `degree` (column order) at (px, py) in the scaled coordinates of a fit
  // around (cx, cy); returns the weight 1/|xi|^2.
  static double monomials_at(double px, double py, double cx, double cy, double scale, int degree,
                             double* a) {
    const double xi = (px - cx) / scale, eta = (py - cy) / scale;
    std::array<double, 6> xp, yp;
    xp[0] = yp[0] = 1;
    for (int e = 1; e <= degree; ++e) {
      xp[std::size_t(e)] = xp[std::size_t(e - 1)] * xi;
      yp[std::size_t(e)] = yp[std::size_t(e - 1)] * eta;
    }
    for (int t = 1, col = 0; t <= degree; ++t)
      for (int j = 0; j <= t; ++j, ++col)
        a[col] = xp[std::size_t(t - j)] * yp[std::size_t(j)];
    return 1 / (xi * xi + eta * eta);
  }

  // The fit's largest Lebesgue constant at the corner-inner points of v's star, the points
  // nearest v at which the spline reads it: the fit's value at x is z_v + sum l_i(x) (z_i -
  // z_v), and |1 - sum l_i| + sum |l_i| bounds how much it amplifies data errors and the
  // degree's own misfit there. With g = QR of the weighted design A, l(x) = W A (R^T R)^-1 a(x).
  double lebesgue_constant(Index v, const Group& g, int degree, const std::vector<Index>& points,
                           Workspace& work) const {
    const Domain& domain = *m_domain;
    const int u = unknowns(degree);
    const std::size_t stride = max_columns + 1; // a row's monomials, then its weight
    const Point_2& center = domain.point(v);
    const double cx = CGAL::to_double(center.x()), cy = CGAL::to_double(center.y());
    if (work.monomials.size() < g.n * stride)
      work.monomials.resize(g.n * stride);
    for (std::size_t i = 0; i < g.n; ++i) {
      const Point_2& p = domain.point(points[i]);
      double* row = work.monomials.data() + i * stride;
      row[max_columns] = monomials_at(CGAL::to_double(p.x()), CGAL::to_double(p.y()), cx, cy,
                                      g.scale, degree, row);
    }
    double largest = 0;
    const auto [fb, fe] = domain.star_faces(v);
    for (auto f = fb; f != fe; ++f) {
      const auto& t = domain.face(*f);
      double px = 2 * cx, py = 2 * cy; // (3 v + a + b) / 5
      for (int i = 0; i < 3; ++i) {
        px += CGAL::to_double(domain.point(t[std::size_t(i)]).x());
        py += CGAL::to_double(domain.point(t[std::size_t(i)]).y());
      }
      std::array<double, max_columns> s{};
      monomials_at(px / 5, py / 5, cx, cy, g.scale, degree, s.data());
      for (int i = 0; i < u; ++i) { // R^T y = a
        double y = s[std::size_t(i)];
        for (int l = 0; l < i; ++l)
          y -= g.R[std::size_t(i) * max_columns + std::size_t(l)] * s[std::size_t(l)];
        s[std::size_t(i)] = y / g.R[std::size_t(i) * max_columns + std::size_t(i)];
      }
      for (int i = u; i-- > 0;) { // R s = y
        double y = s[std::size_t(i)];
        for (int l = i + 1; l < u; ++l)
          y -= g.R[std::size_t(l) * max_columns + std::size_t(i)] * s[std::size_t(l)];
        s[std::size_t(i)] = y / g.R[std::size_t(i) * max_columns + std::size_t(i)];
      }
      double sum = 0, abs_sum = 0;
      for (std::size_t i = 0; i < g.n; ++i) {
        const double* row = work.monomials.data() + i * stride;
        double l = 0;
        for (int c = 0; c < u; ++c)
          l += row[c] * s[std::size_t(c)];
        l *= row[max_columns];
        sum += l;
        abs_sum += std::abs(l);
      }
      largest = (std::max)(largest, std::abs(1 - sum) + abs_sum);
    }
    return largest;
  }

  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE void fit_vertex(Index v, const std::vector<Value>& values,
                                                       Workspace& work) {
    if (start_vertex(v, values, work, work.mark))
      finish_vertex<Wide>(v, values, work, {});
  }
  // The constant term and the neighbourhood; false if the fit is a constant.
  bool start_vertex(Index v, const std::vector<Value>& values, Workspace& work,
                    std::vector<std::uint32_t>& mark) {
    coefficient(v, 0, 0) = values[v];
    if (m_max_degree == 0)
      return false;
    gather(v, work, mark);
    return true;
  }
  // The rest of fit_vertex(), after start_vertex(); pre[0] and pre[1], where given, are the
  // groups of degrees 2-3 and 4-5, factorized and scored by factorize_lanes() (the bits
  // factorize() and scores() give).
  template <bool Wide>
  CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE void finish_vertex(Index v, const std::vector<Value>& values,
                                                          Workspace& work,
                                                          std::array<const Prefactored*, 2> pre) {
    struct Candidate {
      int degree = -1;
      std::size_t group = 0;
      double score = 0;
    };
    // A plane fits the whole first ring; degrees 2 and 3 the points the cubic needs, nearest
    // first, and degrees 4 and 5 the quintic's (fewer where fewer exist): one QR per group.
    boost::container::static_vector<Candidate, max_supported_degree> candidates;
    // the groups factorized here (at most three, and two wider refits), and every group's
    // own or prefactored one (read in place: a copy cost 3% of the fits)
    boost::container::static_vector<Group, max_supported_degree> groups;
    boost::container::static_vector<const Group*, max_supported_degree> group_at;
    boost::container::static_vector<double, max_supported_degree> plane_score;
    int d = 1;
    while (d <= m_max_degree) {
      const int high = d == 1 ? 1 : d <= 3 ? (std::min)(3, m_max_degree) : m_max_degree;
      const std::vector<Index>& points = d == 1 ? work.ring : work.points;
      const std::size_t n = d == 1 ? points.size() : (std::min)(points.size(), needed(high));
      if (n < needed(d))
        break;
      if (d > 1)
        order_nearest(n, work);
      int top = high;
      while (top > d && needed(top) > n)
        --top;
      const Prefactored* const prefactored =
          d == 2 && top == 3 && n == needed(3)                         ? pre[0]
          : d == 4 && top == max_supported_degree && n == batch_points ? pre[1]
                                                                       : nullptr;
      const Group* own = prefactored ? &prefactored->group : nullptr;
      if (!own) {
        Group& fresh = groups.emplace_back();
        fresh.on_ring = d == 1;
        if (!factorize<Wide>(v, values, points, top, n, work, fresh)) {
          groups.pop_back();
          break; // no extent: no higher degree either
        }
        own = &fresh;
      }
      const Group& g = *own;
      // The degrees of this group the points determine: a plane needs its two columns
      // independent to 1e-14 (linear precision however thin the neighbourhood), higher
      // degrees every column to 1e-6; exact builds accept a plane in any case and solve it
      // exactly (a vertex of a valid domain always has a full-rank pair).
      std::array<int, max_supported_degree + 1> u{};
      std::size_t count = 0;
      u[count++] = 2; // the plane on these points, for the resolution
      std::array<int, max_supported_degree> degree_of{};
      for (int e = (std::max)(d, 2); e <= top; ++e) {
        const int ue = unknowns(e);
        if (!determined(g, ue))
          break; // the higher degrees of this group include the dependent columns
        degree_of[count - 1] = e;
        u[count++] = ue;
      }
      const bool plane = g.columns >= 2;
      std::array<double, max_supported_degree + 1> s{};
      if (plane && prefactored)
        std::copy(prefactored->score.begin(), prefactored->score.begin() + std::ptrdiff_t(count),
                  s.begin());
      else if (plane)
        scores<Wide>(g, u, count, work, s);
      // Points on few lines do not determine the group's top degree (a quintic needs them on
      // six), and with 1.5 points per unknown one of them may fit a direction alone (its
      // leave-one-out residual is then undefined, the score infinite): then twice the points,
      // where they exist, before a lower degree.
      if (d > 1 && points.size() > n &&
          (!determined(g, unknowns(top)) || !std::isfinite(s[count - 1]))) {
        Group more;
        const std::size_t n2 = (std::min)(points.size(), 2 * n);
        order_nearest(n2, work);
        if (factorize<Wide>(v, values, points, top, n2, work, more) &&
            determined(more, unknowns(top))) {
          std::array<int, max_supported_degree + 1> u2{};
          std::size_t count2 = 0;
          u2[count2++] = 2;
          for (int e = (std::max)(d, 2); e <= top && determined(more, unknowns(e)); ++e)
            u2[count2++] = unknowns(e);
          std::array<double, max_supported_degree + 1> s2{};
          scores<Wide>(more, u2, count2, work, s2);
          if (std::isfinite(s2[count2 - 1])) {
            own = &groups.emplace_back(more);
            u = u2;
            count = count2;
            s = s2;
            for (std::size_t k = 1; k < count; ++k)
              degree_of[k - 1] = (std::max)(d, 2) + int(k) - 1;
          }
        }
      }
      group_at.push_back(own);
      plane_score.push_back(plane ? s[0] : std::numeric_limits<double>::infinity());
      if (d == 1 && (plane || exact))
        candidates.push_back(
            {1, group_at.size() - 1, plane ? s[0] : std::numeric_limits<double>::infinity()});
      for (std::size_t k = 1; k < count; ++k)
        candidates.push_back({degree_of[k - 1], group_at.size() - 1, s[k]});
      d = top + 1;
    }
    if (candidates.empty()) {
      m_degree[v] = 0; // isolated or degenerate neighbourhood: a constant
      return;
    }
    // Largest degree, or the lowest degree that predicts left-out points nearly as well
    // as the best one. Scores at rounding level of the neighbourhood's data count as zero.
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
    // Stability: a degree whose fit amplifies its data more than `max_lebesgue` times near v,
    // or its own misfit (Lebesgue constant times the leave-one-out error) beyond the plane's
    // error on the same points, gives way to the next lower one. Points on a few nearly
    // parallel lines (a hull straight to 1e-7, a jittered grid's last columns) determine the
    // columns to about 1e-5, and leave-one-out cannot see what the polynomial does between the
    // lines: exp(x) sin(2y) from a 33^2 grid jittered by 1e-5 had an error of 0.5, a cubic 0.4
    // off half a cell from the hull (constant 7e3); with the check 1.1e-4, the grid's own.
    for (; candidates[chosen].degree > 1; --chosen) {
      const Candidate& candidate = candidates[chosen];
      const Group& g = *group_at[candidate.group];
      if (well_determined(g, unknowns(candidate.degree)))
        break;
      const double L =
          lebesgue_constant(v, g, candidate.degree, g.on_ring ? work.ring : work.points, work);
      if (L <= max_lebesgue &&
          L * std::sqrt(candidate.score) <= std::sqrt(plane_score[candidate.group]))
        break;
      if (chosen == 0)
        break;
    }
    // Resolution: leave-one-out score of the chosen degree against the plane's on the
    // chosen degree's own points (the same points, one model less rich).
    {
      const double plane = plane_score[candidates[chosen].group], own = candidates[chosen].score;
      if (!std::isfinite(plane))
        m_resolution[v] = 1;
      else if (!(own > floor))
        m_resolution[v] = 0;
      else
        m_resolution[v] = (std::min)(1.0, std::sqrt(own / (std::max)(plane, floor)));
    }
    for (std::size_t k = chosen + 1; k-- > 0;) {
      const Candidate& candidate = candidates[k];
      const Group& g = *group_at[candidate.group];
      const int degree = candidate.degree;
      m_scale[v] = FT(1) / FT(g.scale);
      m_radius[v] = float(g.radius);
      if constexpr (exact) {
        if (!solve_exact(v, values, g.on_ring ? work.ring : work.points, g.n, degree, m_scale[v]))
          continue;
      } else {
        // back substitution R x = Q^T b on the degree's leading columns
        const int u = unknowns(degree);
        std::array<double, max_columns * std::size_t(D)> x{};
        for (int j = 0; j < D; ++j)
          for (int i = u; i-- > 0;) {
            double s = g.c[std::size_t(j) * max_columns + std::size_t(i)];
            for (int l = i + 1; l < u; ++l)
              s -= g.R[std::size_t(l) * max_columns + std::size_t(i)] *
                   x[std::size_t(j) * max_columns + std::size_t(l)];
            x[std::size_t(j) * max_columns + std::size_t(i)] =
                s / g.R[std::size_t(i) * max_columns + std::size_t(i)];
          }
        for (int t = 1, col = 0; t <= degree; ++t)
          for (int j = 0; j <= t; ++j, ++col) {
            std::array<FT, std::size_t(D)> cs;
            for (int i = 0; i < D; ++i)
              cs[std::size_t(i)] = FT(x[std::size_t(i) * max_columns + std::size_t(col)]);
            coefficient(v, t - j, j) = Value_traits<Value>::from_coordinates(cs);
          }
      }
      m_degree[v] = degree;
      return;
    }
    m_degree[v] = 0;
  }

  // The weight of a point at scaled offset (xi, eta): 1/|xi|^2 rounded to double, taken
  // exactly. Any positive weights reproduce the polynomial the data come from, and a dyadic
  // weight keeps the normal equations' integers short; exact 1/|xi|^2 only if the double
  // is not a normal positive number.
  static FT exact_weight(const FT& xi, const FT& eta) {
    const double x = CGAL::to_double(xi), y = CGAL::to_double(eta);
    const double w = 1 / (x * x + y * y);
    if (std::isnormal(w) && w > 0)
      return FT(w);
    return FT(1) / (xi * xi + eta * eta);
  }

  // Normal equations sum w a a^T x = sum w a (z - z_v), w = exact_weight(); false if
  // singular (never expected after the double rank test). Number types with
  // Fraction_traits are solved over their integers (solve_fraction_free()), others by
  // rational Gaussian elimination.
  bool solve_exact(Index v, const std::vector<Value>& values, const std::vector<Index>& points,
                   std::size_t n, int d, const FT& inverse_scale) {
    if constexpr (fraction_free)
      if (m_fraction_free)
        return solve_fraction_free(v, values, points, n, d, inverse_scale);
    return solve_rational(v, values, points, n, d, inverse_scale);
  }

  // Fraction-free (Bareiss) elimination: the offsets, weights and values are brought to
  // common denominators, the normal equations are built and eliminated in integers with
  // exact divisions only, and the coefficients stay numerators over one denominator (not
  // reduced: polar_value_fraction_free() reads them so). The same rationals as
  // solve_rational(), without a gcd per operation: at degree 5 on scattered doubles, about
  // 4 ms per vertex against half a second.
  bool solve_fraction_free(Index v, const std::vector<Value>& values,
                           const std::vector<Index>& points, std::size_t n, int d,
                           const FT& inverse_scale) {
    using FTr = Fraction_traits<FT>;
    static_assert(std::is_same_v<Integer, typename FTr::Denominator_type>);
    typename FTr::Decompose decompose;
    const auto gcd = typename Algebraic_structure_traits<Integer>::Gcd();
    const auto divide = typename Algebraic_structure_traits<Integer>::Integral_division();
    const auto lcm = [&](const Integer& a, const Integer& b) -> Integer {
      return divide(a, gcd(a, b)) * b;
    };
    const int u = unknowns(d);
    const Point_2& c = m_domain->point(v);
    // numerators and denominators: xi, eta, weight, then the D value differences
    const std::size_t K = 3 + std::size_t(D);
    std::vector<Integer> num(n * K), den(n * K);
    std::array<Integer, 3 + std::size_t(D)> common; // xi and eta share common[0]
    common.fill(Integer(1));
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& p = m_domain->point(points[i]);
      const FT xi = (p.x() - c.x()) * inverse_scale, eta = (p.y() - c.y()) * inverse_scale;
      std::array<FT, 3 + std::size_t(D)> q;
      q[0] = xi;
      q[1] = eta;
      q[2] = exact_weight(xi, eta);
      for (int j = 0; j < D; ++j)
        q[3 + std::size_t(j)] = Value_traits<Value>::coordinate(values[points[i]], j) -
                                Value_traits<Value>::coordinate(values[v], j);
      for (std::size_t k = 0; k < K; ++k) {
        decompose(q[k], num[i * K + k], den[i * K + k]);
        Integer& l = common[k == 0 ? 1 : k];
        l = lcm(l, den[i * K + k]);
      }
    }
    common[0] = common[1] = lcm(common[0], common[1]);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < K; ++k)
        num[i * K + k] *= divide(common[k], den[i * K + k]);
    // augmented normal equations [G | h], G = sum W A A^T, h = sum W A Z in the integer
    // offsets X = xi L (A the monomials of X, Y), weights W and values Z
    const std::size_t width = std::size_t(u + D);
    std::vector<Integer> G(std::size_t(u) * width, Integer(0));
    std::vector<Integer> A(static_cast<std::size_t>(u)), WA(static_cast<std::size_t>(u));
    std::array<Integer, max_supported_degree + 1> xp, yp;
    for (std::size_t i = 0; i < n; ++i) {
      xp[0] = yp[0] = Integer(1);
      for (int e = 1; e <= d; ++e) {
        xp[std::size_t(e)] = xp[std::size_t(e - 1)] * num[i * K];
        yp[std::size_t(e)] = yp[std::size_t(e - 1)] * num[i * K + 1];
      }
      for (int t = 1, col = 0; t <= d; ++t)
        for (int k = 0; k <= t; ++k, ++col) {
          A[std::size_t(col)] = xp[std::size_t(t - k)] * yp[std::size_t(k)];
          WA[std::size_t(col)] = num[i * K + 2] * A[std::size_t(col)];
        }
      for (int r = 0; r < u; ++r) {
        Integer* row = &G[std::size_t(r) * width];
        for (int s = r; s < u; ++s)
          row[s] += WA[std::size_t(r)] * A[std::size_t(s)];
        for (int j = 0; j < D; ++j)
          row[u + j] += WA[std::size_t(r)] * num[i * K + 3 + std::size_t(j)];
      }
    }
    // Bareiss on the upper triangle: after step k, entry (r, s) of the trailing block is the
    // (k+1)-minor of G bordered by row r and column s, so the block stays symmetric and the
    // division by the previous pivot is exact. G is positive semidefinite, so a zero pivot (a
    // singular leading block) means G is singular: no pivoting.
    Integer previous(1);
    for (int k = 0; k < u; ++k) {
      const Integer* pk = &G[std::size_t(k) * width];
      if (CGAL::is_zero(pk[k]))
        return false;
      for (int r = k + 1; r < u; ++r) {
        Integer* pr = &G[std::size_t(r) * width];
        for (std::size_t s = std::size_t(r); s < width; ++s)
          pr[s] = divide(pr[s] * pk[k] - pk[r] * pk[s], previous);
      }
      previous = pk[k];
    }
    // back substitution for y = det x, an integer vector by Cramer's rule (det the last
    // pivot, the determinant of G), so every division is exact
    const Integer& det = previous;
    std::vector<Integer> y(static_cast<std::size_t>(u));
    std::array<Integer, max_supported_degree + 1> Lp; // powers of the offsets' denominator
    Lp[0] = Integer(1);
    for (int e = 1; e <= d; ++e)
      Lp[std::size_t(e)] = Lp[std::size_t(e - 1)] * common[0];
    for (int j = 0; j < D; ++j) {
      for (int r = u; r-- > 0;) {
        const Integer* pr = &G[std::size_t(r) * width];
        Integer s = det * pr[u + j];
        for (int l = r + 1; l < u; ++l)
          s -= pr[l] * y[std::size_t(l)];
        y[std::size_t(r)] = divide(s, pr[r]);
      }
      // x = y / det solves the integer system; the coefficient of a degree-t monomial of
      // (xi, eta) is L^t x / Z's common denominator
      const Integer denominator = det * common[3 + std::size_t(j)];
      for (int t = 1, col = 0; t <= d; ++t)
        for (int k = 0; k <= t; ++k, ++col)
          m_numerators[(coefficients_per_vertex * at(v) + position(t - k, k)) * D +
                       std::size_t(j)] = y[std::size_t(col)] * Lp[std::size_t(t)];
      m_denominators[at(v) * D + std::size_t(j)] = denominator;
    }
    return true;
  }

  // The same normal equations by rational Gauss-Jordan elimination.
  bool solve_rational(Index v, const std::vector<Value>& values, const std::vector<Index>& points,
                      std::size_t n, int d, const FT& inverse_scale) {
    const int u = unknowns(d);
    const Point_2& c = m_domain->point(v);
    std::vector<std::vector<FT>> M(std::size_t(u), std::vector<FT>(std::size_t(u + D), FT(0)));
    std::vector<FT> a(static_cast<std::size_t>(u), FT(0));
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& p = m_domain->point(points[i]);
      const FT xi = (p.x() - c.x()) * inverse_scale, eta = (p.y() - c.y()) * inverse_scale;
      const FT w = exact_weight(xi, eta);
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
              wa * (Value_traits<Value>::coordinate(values[points[i]], j) -
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
  const std::vector<Value>* m_data;
  int m_max_degree;
  Degree_selection m_selection;
  bool m_fraction_free;
  std::size_t m_threads;
  bool m_on_demand;
  std::vector<std::uint32_t> m_stored_at; // ON_DEMAND: kept vertex's block, or not_kept
  std::vector<Index> m_kept;              // ON_DEMAND: the vertices kept
  double m_tie_ratio = 1.1;
  std::vector<int> m_degree;
  std::vector<double> m_resolution;
  std::vector<float> m_radius; // 4 bytes: a threshold's scale, not a coordinate
  std::vector<FT> m_scale;     // 1 / S_v
  std::vector<Value> m_coefficients;
  // exact fraction types: the coefficients' numerators (D per coefficient) over one
  // denominator per vertex and coordinate (0: not fitted fraction-free)
  std::vector<Integer> m_numerators, m_denominators;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_LOCAL_POLYNOMIAL_FIT_H

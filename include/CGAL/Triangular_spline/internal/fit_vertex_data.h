// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FIT_VERTEX_DATA_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FIT_VERTEX_DATA_H

// The body of fit_vertex_data() (Xu/fit_vertex_data.h), with the options of the global
// solver and what it did, for tests and benchmarks.

#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/Fit.h>
#include <CGAL/Triangular_spline/Xu/estimate_gradients.h>
#include <CGAL/Triangular_spline/Xu/local_polynomial_fit.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/free_value_solves.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/vertex_rings.h>
#include <CGAL/Triangular_spline/internal/schwarz_solver.h>

#include <CGAL/Algebraic_structure_traits.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Resolution (Local_polynomials::resolution()) below which a vertex's polynomial is trusted
// fully, and above which not at all, in the Adaptive fit. Measured on the TOMS 792 node sets
// and jittered grids: every vertex of smooth data sampled at h <= 1/8 has a resolution below
// 1e-4; the sparse sets' spread over [0.05, 1].
inline std::pair<double, double> adaptive_resolution_thresholds() {
  return {0.1, 0.5};
}
// Rings around the untrusted vertices over which the Adaptive fit's energy solve extends.
// Without a margin the solve bends the surface next to thin hull triangles to flatten the
// kinks of the local values there (benchmark/hull_strip.py, 2 10^4 terrain points: largest
// error 0.406 without, 0.327 with one ring or three). One ring was as accurate as three on
// TOMS 792, terrain.py and hull_strip.py from 500 to 10^5 points (the same printed digits
// but 0.484 against 0.483 once), and the solve is much smaller: 10^6 ridged terrain points,
// 0.77 times the CPU and 906 against 1000 MB.
constexpr int adaptive_energy_margin_rings = 1;
// Tension of the Adaptive fit's energy solve (minimal_energy_free_values()): thin plate +
// tau / h^2 int |grad f - grad g|^2, g the piecewise linear interpolant, tau this constant
// times a vertex's distrust (1 - trust). Measured on the TOMS 792 node sets (avg SSE/SSM,
// sets 1..5; scipy CT 8.5e-3, 0.255, 0.145, 4.8e-3, 2.1e-3): without tension 5.2e-3, 0.259,
// 0.147, 3.2e-3, 1.4e-3 (sets 2, 3 lose); with 2, 6.1e-3, 0.251, 0.136, 3.5e-3, 1.9e-3, and
// lower terrain errors (benchmark/terrain.py) at 500 and 2000 points; 1 and 3 are within 2%
// of 2 on sets 2, 3. A third-order term (h^2 int |D^3 f|^2) helps the smooth sets but raised
// the terrain's max error above scipy's at every weight tried (>= 0.003).
constexpr double adaptive_tension = 2;

// The distance of two domain points, in double (for thresholds: every number type decides
// alike).
template <class Point_2>
double distance_as_double(const Point_2& p, const Point_2& q) {
  const double dx = CGAL::to_double(q.x()) - CGAL::to_double(p.x());
  const double dy = CGAL::to_double(q.y()) - CGAL::to_double(p.y());
  return std::sqrt(dx * dx + dy * dy);
}

// Local polynomials far from their data. A slot's target reads the polynomial p_u of a vertex
// u of its label at the label's vertices; when one of them, w, lies more than
// local_polynomial_reach().first fit radii (Local_polynomials::radius()) from u, p_u
// extrapolates there, its terms of degree k growing as the k-th power of the distance in
// radii. If p_u also misses the data at w (local_polynomial_miss()), the target moves to the
// polar form of the piecewise linear interpolant (the label's data values weighted by
// multiplicity), wholly at .second radii, and the Adaptive fit distrusts u as much. Where this
// happens: under a long hull edge of random points (the hull of 10^5 points of the unit square
// has edges of 0.3 to 0.8, the fits a radius of 0.01), whose slivers read the polynomials of
// the hull vertices at the edge's far end. benchmark/hull_strip.py, terrain-like function
// (range [-0.57, 2.41]), largest error within 10^-3 of the sides at 8000 / 2 10^4 / 10^5
// points: 2.35 / 1.89 / 4.90 before, 0.44 / 0.33 / 0.80 now, scipy CT 1.20 / 0.96 / 1.05.
// Thresholds (2, 4), (4, 8), (6, 12) radii gave 0.51, 0.51, 0.97 at 2 10^4 points (before
// the miss test).
inline std::pair<double, double> local_polynomial_reach() {
  return {4, 8};
}

// How far a target reading a polynomial of degree `degree` and fit radius `radius` at
// `reach` may move to the linear average: 0 (not at all) to 1 (wholly), see
// local_polynomial_reach().
inline double local_polynomial_pull(double reach, double radius, int degree) {
  const auto [near, far] = local_polynomial_reach();
  if (degree < 1 || !(reach > near * radius))
    return 0;
  return reach >= far * radius ? 1 : (reach - near * radius) / ((far - near) * radius);
}

// The share of that pull taken, from how far the polynomial misses the data at the far
// vertex (`miss`, in units of the data range): none within 10^-2, all from 10^-1,
// logarithmic between. Smooth data are extrapolated well and keep their polynomials
// (exp(x) sin(2y): its errors next to the sides in benchmark/hull_strip.py are those of
// the polynomials read at any distance; with 10^-3 instead the corners of 1000 random
// points, reading theirs along whole sides, were distrusted and the error 0.02 from the
// hull rose from 4e-6 to 2.2e-5); rough data are not (the terrain-like function misses by
// about 1/3 of its range).
inline double local_polynomial_miss(double miss) {
  if (!(miss > 1e-2))
    return 0;
  return miss >= 1e-1 ? 1 : std::log10(miss / 1e-2);
}

// The local and Adaptive fits hold the polynomials of this many vertices at a time (21
// coefficients each: 11 MB in double), not all of them (168 MB at 10^6 vertices).
constexpr std::size_t local_polynomial_block = 65536;

// Local polynomials fitted before fit_vertex_data() runs, for it to take over:
// make_c1_quintic_spline() fits them on one thread while the plan is built
// (C1_quintic_spline's While_planning), whose serial stretches leave a core idle (about 1.4
// core-seconds of the 3 s plan of 10^6 random points), until the plan is done. Only the
// streamed fits (LOCAL_POLYNOMIAL, ADAPTIVE) take them: vertices [0, vertices), kept
// (Local_polynomial_storage::ON_DEMAND). A vertex's polynomial does not depend on which
// others are fitted with it, so the fit is the same bit for bit.
template <class GeomTraits, class Value>
struct Prefitted_polynomials {
  std::optional<Local_polynomials<GeomTraits, Value>> local;
  std::size_t vertices = 0;
};

// The most vertices fitted ahead: a quarter of them (their coefficients, 21 values per
// vertex, are kept until the fit reads them: 42 MB at 10^6 points), at least a block.
inline std::size_t prefit_vertices(std::size_t V) {
  return (std::min)(V, (std::max)(local_polynomial_block, V / 4));
}

// Fits into `prefit` the first vertices that fit_vertex_data(spline, values, fit, degree,
// selection, ...) on a spline over `domain` fits, at most `count`, until `stop` is set; or
// nothing: for the other fits, and for input that fit_vertex_data() rejects (it reports
// that itself). Never throws: on any failure nothing is kept, and the fit does the work.
template <class GeomTraits, class Value>
void prefit_local_polynomials(const Planar_domain<GeomTraits>& domain,
                              const std::vector<Value>& values, Fit fit, int degree,
                              Degree_selection selection, std::size_t count,
                              const std::atomic<bool>& stop,
                              Prefitted_polynomials<GeomTraits, Value>& prefit) noexcept {
  try {
    if ((fit != Fit::LOCAL_POLYNOMIAL && fit != Fit::ADAPTIVE) ||
        values.size() != domain.number_of_vertices() ||
        !std::all_of(values.begin(), values.end(),
                     [](const Value& v) { return is_finite_value(v); }))
      return;
    prefit.local.emplace(domain, values, degree, selection, 0, Exact_elimination::FRACTION_FREE,
                         Local_polynomial_storage::ON_DEMAND);
    prefit.vertices = prefit.local->fit_first(count, stop);
    if (prefit.vertices == 0)
      prefit.local.reset(); // (stopped at once: nothing to take over)
  } catch (...) {
    prefit.local.reset();
    prefit.vertices = 0;
  }
}

// fit_vertex_data() with the solver's options, and what the solver did (tests, benchmarks);
// `prefit`, if given, holds local polynomials prefit_local_polynomials() fitted for this
// call's arguments (taken over).
template <class GeomTraits, class Value>
Fit_statistics fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline,
                               const std::vector<Value>& values, Fit fit, int local_degree,
                               Degree_selection selection, double smoothing,
                               const std::vector<std::array<Value, 2>>& given_gradients,
                               const Schwarz_options& options, Schwarz_statistics* solver = nullptr,
                               std::optional<double> tension = std::nullopt,
                               Prefitted_polynomials<GeomTraits, Value>* prefit = nullptr) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  const auto& domain = spline.domain();
  if (values.size() != domain.number_of_vertices())
    throw Invalid_input("fit: " + std::to_string(values.size()) + " data values for " +
                        std::to_string(domain.number_of_vertices()) + " vertices");
  for (const Value& v : values)
    if (!is_finite_value(v))
      throw Invalid_input("fit: non-finite data value");
  if (fit != Fit::APPROXIMATE && spline.corner_frame() != Corner_frame::CORNER_AND_TWO_STARS)
    throw Invalid_input("fit: interpolation needs corner points to be prescribed "
                        "(build the spline with Corner_frame::CORNER_AND_TWO_STARS)");
  const bool given = !given_gradients.empty();
  if (given) {
    if (given_gradients.size() != domain.number_of_vertices())
      throw Invalid_input("fit: " + std::to_string(given_gradients.size()) + " gradients for " +
                          std::to_string(domain.number_of_vertices()) + " vertices");
    for (const auto& g : given_gradients)
      if (!is_finite_value(g[0]) || !is_finite_value(g[1]))
        throw Invalid_input("fit: non-finite gradient");
    if (fit == Fit::APPROXIMATE)
      throw Invalid_input("fit: given gradients need an interpolating fit (not approximate)");
    if (smoothing > 0)
      throw Invalid_input("fit: given gradients are interpolated; smoothing would move the "
                          "values they belong to");
  }
  std::vector<std::array<Value, 2>> gradients;
  if (fit == Fit::TANGENT_PLANES)
    gradients = given ? given_gradients : estimate_gradients(domain, values);
  // With given gradients every star point is the tangent plane's: z_v + g_v.(w - v)/5 for
  // the star f(v^4 w). Its corner region is then that plane, so the spline interpolates
  // the gradient at every vertex.
  auto given_star = [&](Slot s, Value& star) {
    if (!given || spline.kind(s) != Slot_kind::STAR)
      return false;
    const auto label = spline.polar_label(s);
    const auto [v, w] = label[0].second == 4 ? std::pair(label[0].first, label[1].first)
                                             : std::pair(label[1].first, label[0].first);
    const FT dx = (domain.point(w).x() - domain.point(v).x()) / FT(5);
    const FT dy = (domain.point(w).y() - domain.point(v).y()) / FT(5);
    star = values[v] + dx * given_gradients[v][0] + dy * given_gradients[v][1];
    return true;
  };
  if (!(smoothing >= 0) || !std::isfinite(smoothing))
    throw Invalid_input("fit: the smoothing must be a finite number >= 0");
  if (smoothing > 0 && fit != Fit::MINIMAL_ENERGY)
    throw Invalid_input("fit: smoothing needs the minimal-energy fit");
  if (tension) {
    if (!(*tension >= 0) || !std::isfinite(*tension))
      throw Invalid_input("fit: the tension must be a finite number >= 0");
    if (*tension > 0 && fit != Fit::ADAPTIVE && fit != Fit::MINIMAL_ENERGY)
      throw Invalid_input("fit: a tension needs the adaptive or the minimal-energy fit");
    if (smoothing > 0 && *tension > 0)
      throw Invalid_input("fit: a tension pulls toward the interpolant of the data; it does "
                          "not go with smoothing");
  }
  std::optional<Local_polynomials<GeomTraits, Value>> local;
  // The local and Adaptive fits stream: each block of vertices is fitted and writes its
  // shares of the free slots' targets at once (below). The least-squares fit and the
  // minimal-energy solve read any slot's target at any time. A windowed energy solve starts
  // from the local polynomials' values: the first sweep's windows see them beyond their
  // margins.
  const bool streamed = fit == Fit::LOCAL_POLYNOMIAL || fit == Fit::ADAPTIVE;
  std::size_t prefitted = 0; // vertices [0, prefitted) fitted and kept already
  if (streamed && prefit && prefit->local && prefit->vertices > 0) {
    local = std::move(prefit->local);
    prefitted = prefit->vertices;
    prefit->local.reset();
  } else if (streamed)
    local.emplace(domain, values, local_degree, selection, 0, Exact_elimination::FRACTION_FREE,
                  Local_polynomial_storage::ON_DEMAND);
  else if (fit == Fit::LEAST_SQUARES || (fit == Fit::MINIMAL_ENERGY &&
                                         spline.number_of_free_parameters() > options.direct_limit))
    local.emplace(domain, values, local_degree, selection);
  // Per-slot work runs on all cores: in double from 50000 free values, exactly (a polar value
  // of a local polynomial costs about a tenth of a millisecond there) from 500.
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  const std::size_t threads =
      internal::thread_count(spline.number_of_free_parameters(), exact ? 500 : 50000);
  const std::size_t block = exact ? 16 : internal::parallel_block;
  Fit_statistics statistics;
  // How far the targets that read u's polynomial at vertex w move to the linear average
  // (local_polynomial_pull()): by the distance in fit radii, where the polynomial misses
  // the data at w.
  const double scale = local ? internal::data_scale(values) : 1.0;
  auto edge_pull = [&](std::uint32_t u, std::uint32_t w) {
    const double reach = internal::distance_as_double(domain.point(u), domain.point(w));
    const double pull = internal::local_polynomial_pull(reach, local->radius(u), local->degree(u));
    if (!(pull > 0))
      return 0.0;
    const Value p = local->value(u, domain.point(w));
    double miss = 0;
    for (int d = 0; d < Value_traits<Value>::dimension; ++d)
      miss = (std::max)(miss,
                        std::abs(CGAL::to_double(Value_traits<Value>::coordinate(p, d)) -
                                 CGAL::to_double(Value_traits<Value>::coordinate(values[w], d))));
    return pull * internal::local_polynomial_miss(miss / scale);
  };
  // the largest pull of v's polynomial along its edges
  auto vertex_pull = [&](std::uint32_t v) {
    const auto [nb, ne] = domain.neighbours(v);
    double pull = 0;
    for (auto w = nb; w != ne; ++w)
      pull = (std::max)(pull, edge_pull(v, std::uint32_t(*w)));
    return pull;
  };
  // The polar form of the piecewise linear interpolant at a label: its vertices' data values
  // weighted by their multiplicities, summed in the lexicographic order of the points (not
  // the numbering's).
  // (Exact sums need no order; the multiplicities' fifths are made once: as fractions they
  // cost two allocations and a gcd each.)
  std::array<FT, 6> fifths;
  for (int m = 0; m <= 5; ++m)
    fifths[std::size_t(m)] = FT(m) / FT(5);
  auto linear_average = [&](const auto& label) {
    std::array<std::pair<std::uint32_t, int>, 3> terms;
    std::size_t count = 0;
    for (const auto& entry : label)
      terms[count++] = entry;
    auto before = [&](std::size_t i, std::size_t j) {
      const auto &p = domain.point(terms[i].first), &q = domain.point(terms[j].first);
      return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
    };
    if constexpr (!exact)
      for (std::size_t i = 1; i < count; ++i)
        for (std::size_t j = i; j > 0 && before(j, j - 1); --j)
          std::swap(terms[j], terms[j - 1]);
#ifdef __GMP_PLUSPLUS__
    if constexpr (std::is_same_v<Value, mpq_class>) {
      // Summed over the values' common denominator L (data of one decimal scale share it) and
      // reduced once: the result is N / (5 L) with gcd(N, L) and gcd(N, 5) divided out (5 is
      // prime), canonical. Rational products and sums reduce by gcds at each step: this
      // took a third of an exact approximate fit's CPU (10^5 17-digit points).
      static thread_local mpz_class N, L, g, t;
      auto den = [&](std::size_t i) { return mpq_denref(values[terms[i].first].get_mpq_t()); };
      auto num = [&](std::size_t i) { return mpq_numref(values[terms[i].first].get_mpq_t()); };
      std::size_t big = 0;
      for (std::size_t i = 1; i < count; ++i)
        if (mpz_cmp(den(i), den(big)) > 0)
          big = i;
      mpz_set(L.get_mpz_t(), den(big));
      for (std::size_t i = 0; i < count; ++i)
        if (i != big && !mpz_divisible_p(L.get_mpz_t(), den(i))) {
          mpz_gcd(g.get_mpz_t(), L.get_mpz_t(), den(i));
          mpz_divexact(t.get_mpz_t(), den(i), g.get_mpz_t());
          mpz_mul(L.get_mpz_t(), L.get_mpz_t(), t.get_mpz_t());
        }
      mpz_set_ui(N.get_mpz_t(), 0);
      for (std::size_t i = 0; i < count; ++i) {
        mpz_mul_ui(t.get_mpz_t(), num(i), static_cast<unsigned long>(terms[i].second));
        if (mpz_cmp(L.get_mpz_t(), den(i)) != 0) {
          mpz_divexact(g.get_mpz_t(), L.get_mpz_t(), den(i));
          mpz_mul(t.get_mpz_t(), t.get_mpz_t(), g.get_mpz_t());
        }
        mpz_add(N.get_mpz_t(), N.get_mpz_t(), t.get_mpz_t());
      }
      Value sum;
      if (mpz_sgn(N.get_mpz_t()) == 0)
        return sum;
      mpz_gcd(g.get_mpz_t(), N.get_mpz_t(), L.get_mpz_t());
      if (mpz_cmp_ui(g.get_mpz_t(), 1) != 0) {
        mpz_divexact(N.get_mpz_t(), N.get_mpz_t(), g.get_mpz_t());
        mpz_divexact(L.get_mpz_t(), L.get_mpz_t(), g.get_mpz_t());
      }
      if (mpz_divisible_ui_p(N.get_mpz_t(), 5))
        mpz_divexact_ui(N.get_mpz_t(), N.get_mpz_t(), 5);
      else
        mpz_mul_ui(L.get_mpz_t(), L.get_mpz_t(), 5);
      mpz_set(mpq_numref(sum.get_mpq_t()), N.get_mpz_t());
      mpz_set(mpq_denref(sum.get_mpq_t()), L.get_mpz_t());
      return sum;
    }
#endif
    Value sum = Value_traits<Value>::zero();
    for (std::size_t i = 0; i < count; ++i)
      sum = sum + fifths[std::size_t(terms[i].second)] * values[terms[i].first];
    return sum;
  };
  // How far the target of a slot reading u's polynomial at `label` moves to the linear
  // average: the largest pull toward the label's other vertices.
  auto extrapolation_pull = [&](std::uint32_t u, const auto& label) {
    double pull = 0;
    for (const auto& entry : label)
      if (entry.first != u)
        pull = (std::max)(pull, edge_pull(u, entry.first));
    return pull;
  };
  // The value a slot should take from the data: polar blend, or tangent plane of the
  // nearest corner(s) at the slot's domain point.
  auto target = [&](Slot s) {
    Value v = Value_traits<Value>::zero();
    if (given_star(s, v))
      return v;
    const auto label = spline.polar_label(s);
    if (fit == Fit::APPROXIMATE || fit == Fit::INTERPOLATE)
      return linear_average(label);
    int largest = 0;
    for (const auto& entry : label)
      largest = (std::max)(largest, entry.second);
    if (local) {
      std::array<std::pair<const typename GeomTraits::Point_2*, int>, 3> arguments;
      std::size_t count = 0;
      for (const auto& [vertex, multiplicity] : label)
        arguments[count++] = {&domain.point(vertex), multiplicity};
      int ties = 0;
      for (const auto& entry : label) {
        if (entry.second != largest)
          continue;
        ++ties;
        const double pull = extrapolation_pull(entry.first, label);
        if (pull >= 1) {
          v = v + linear_average(label);
          continue;
        }
        const Value polar =
            local->polar_value(entry.first, arguments.begin(), arguments.begin() + count, 5);
        v = v + (pull > 0 ? Value((FT(1) - FT(pull)) * polar + FT(pull) * linear_average(label))
                          : polar);
      }
      return ties == 1 ? v : Value((FT(1) / FT(ties)) * v);
    }
    const auto x = spline.domain_point(s);
    int ties = 0;
    for (const auto& [vertex, multiplicity] : label) {
      if (multiplicity != largest)
        continue;
      const FT dx = x.x() - domain.point(vertex).x(), dy = x.y() - domain.point(vertex).y();
      v = v + values[vertex] + dx * gradients[vertex][0] + dy * gradients[vertex][1];
      ++ties;
    }
    return Value((FT(1) / FT(ties)) * v);
  };
  // The streamed pass: vertex u's share of the target of each free slot where u has the
  // largest multiplicity (target() sums the shares of tied vertices in label order, and
  // divides by their number). Only middle-inner slots, f(u w^2 x^2), have two, and a sum of
  // two terms does not depend on their order, so each share is added as soon as it is
  // computed (under a lock: the other may be added by another thread at the same time).
  // The vertices' pulls are kept for the trust below.
  std::vector<double> pull_of;
  if (streamed) {
    const std::size_t V = domain.number_of_vertices();
    pull_of.assign(V, 0.0);
    for (Slot s : spline.free_slots())
      if (spline.kind(s) == Slot_kind::MIDDLE_INNER)
        spline.set_free_value(s, Value_traits<Value>::zero());
    std::array<std::mutex, 64> locks;
    auto share = [&](std::uint32_t u, Slot s) {
      if (!spline.is_free(s))
        return;
      Value star;
      if (given_star(s, star)) {
        spline.set_free_value(s, star);
        return;
      }
      const auto label = spline.polar_label(s);
      Value add;
      const double pull = extrapolation_pull(u, label);
      if (pull >= 1) {
        add = linear_average(label);
      } else {
        std::array<std::pair<const typename GeomTraits::Point_2*, int>, 3> arguments;
        std::size_t count = 0;
        for (const auto& [vertex, multiplicity] : label)
          arguments[count++] = {&domain.point(vertex), multiplicity};
        const Value polar = local->polar_value(u, arguments.begin(), arguments.begin() + count, 5);
        add =
            pull > 0 ? Value((FT(1) - FT(pull)) * polar + FT(pull) * linear_average(label)) : polar;
      }
      if (spline.kind(s) != Slot_kind::MIDDLE_INNER) {
        spline.set_free_value(s, Value(Value_traits<Value>::zero() + add));
        return;
      }
#if defined(__GNUC__)
      if constexpr (std::is_same_v<Value, double>) {
        // a compare-and-swap on the value instead of a lock (a lock and an unlock per
        // middle-inner share took 3% of the CPU of a default fit at 10^6 points)
        double* const target = const_cast<double*>(spline.values().data()) + s;
        double expected, sum;
        __atomic_load(target, &expected, __ATOMIC_RELAXED);
        do
          sum = expected + add;
        while (!__atomic_compare_exchange(target, &expected, &sum, true, __ATOMIC_RELAXED,
                                          __ATOMIC_RELAXED));
        return;
      }
#endif
      std::lock_guard<std::mutex> hold(locks[s % locks.size()]);
      spline.set_free_value(s, Value(spline.value(s) + add));
    };
    auto shares = [&](std::uint32_t u) {
      pull_of[u] = vertex_pull(u);
      share(u, Slot(u));
      const auto [eb, ee] = domain.star_edges(u);
      for (auto e = eb; e != ee; ++e) { // f(u^4 w), f(u^3 w^2)
        const bool first = domain.edge(*e)[0] == u;
        const Slot s = Slot(V + 4 * std::size_t(*e));
        share(u, first ? s : s + 3);
        share(u, first ? s + 1 : s + 2);
      }
      const auto [fb, fe] = domain.star_faces(u);
      for (auto f = fb; f != fe; ++f) { // f(u^3 w x), f(u^2 w^2 x), f(u^2 w x^2)
        const auto& t = domain.face(*f);
        const int at = t[0] == u ? 0 : t[1] == u ? 1 : 2;
        for (int i = 0; i < 6; ++i)
          if (i == at || (i >= 3 && i - 3 != at))
            share(u, spline.face_slot(*f, i));
      }
    };
    const std::size_t block =
        options.local_block > 0 ? options.local_block : internal::local_polynomial_block;
    std::vector<std::uint32_t> vertices;
    for (std::size_t first = 0; first < V; first += vertices.size()) {
      const bool fitted = first == 0 && prefitted > 0;
      vertices.resize(fitted ? prefitted : (std::min)(block, V - first));
      for (std::size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = std::uint32_t(first + i);
      if (!fitted)
        local->fit(vertices);
      internal::parallel_for_index(
          vertices.size(), internal::thread_count(vertices.size(), exact ? 16 : 2000),
          [&](std::size_t i) { shares(vertices[i]); }, exact ? 1 : 64);
    }
    for (Slot s : spline.free_slots())
      if (spline.kind(s) == Slot_kind::MIDDLE_INNER)
        spline.set_free_value(s, Value((FT(1) / FT(2)) * spline.value(s)));
  }
  auto pull_at = [&](std::uint32_t v) { return streamed ? pull_of[v] : vertex_pull(v); };
  if (local)
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
      ++statistics.vertices_by_degree[std::size_t(local->degree(v))];
      statistics.vertices_beyond_reach += pull_at(v) > 0 ? 1 : 0;
    }
  // The tension's weight: adaptive_tension by default in the adaptive fit (times each
  // vertex's distrust), none in the minimal-energy fit (Xu's thin plate).
  const double tension_weight = tension                ? *tension
                                : fit == Fit::ADAPTIVE ? internal::adaptive_tension
                                                       : 0.0;
  // Adaptive fit: trust in each vertex's polynomial, from how well it resolves the data.
  std::vector<double> trust;
  bool blend_energy = false;
  if (fit == Fit::ADAPTIVE) {
    const auto [low, high] = internal::adaptive_resolution_thresholds();
    trust.resize(domain.number_of_vertices());
    bool unresolved = false;
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
      const double r = local->resolution(v);
      trust[v] = r <= low ? 1.0 : r >= high ? 0.0 : (high - r) / (high - low);
      unresolved = unresolved || trust[v] < 1;
    }
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
      // A polynomial read along an edge far longer than its fit's radius extrapolates (the
      // slivers under a long hull edge): its targets there are pulled to the linear
      // interpolant, and where an energy solve runs anyway the vertex is distrusted as much,
      // so that the solve decides those slivers (bounded; pulled targets alone are amplified
      // by the slivers' rules: terrain-like data, 2 10^4 points, largest error next to the
      // sides 1.59 against 0.51). Resolved data (a few hull vertices of smooth data) keep the
      // pulled targets: the solve's set-up takes time linear in the whole spline (a
      // propagation, a pass over every rule and every face), not in the region.
      if (unresolved)
        trust[v] = (std::min)(trust[v], 1 - pull_at(v));
      ++statistics.vertices_by_trust[trust[v] >= 1 ? 0 : trust[v] > 0 ? 1 : 2];
    }
    // Fully trusted data need no solve: the fit is then Local_polynomial.
    blend_energy = statistics.vertices_by_trust[1] + statistics.vertices_by_trust[2] > 0;
  }
  internal::Schwarz_statistics solved;
  if (fit == Fit::MINIMAL_ENERGY) {
    solved = internal::minimal_energy_free_values(
        spline, values, smoothing,
        tension_weight > 0 ? std::vector<double>(domain.number_of_vertices(), tension_weight)
                           : std::vector<double>{},
        given_star, [&](Slot s) { return local ? target(s) : Value_traits<Value>::zero(); },
        options);
  } else if (blend_energy) {
    auto nearest = [&](Slot s) {
      const auto label = spline.polar_label(s);
      int largest = 0;
      for (const auto& entry : label)
        largest = (std::max)(largest, entry.second);
      boost::container::static_vector<std::uint32_t, 3> ties;
      for (const auto& entry : label)
        if (entry.second == largest)
          ties.push_back(entry.first);
      return ties;
    };
    // The energy solve covers the untrusted vertices and a margin of rings around them,
    // with the local values beyond as boundary values. The margin keeps the local values'
    // kinks in thin boundary triangles (tiny in value, huge in energy) out of the solve,
    // which would otherwise bend the surface next to them to reduce their energy.
    std::vector<int> ring(domain.number_of_vertices(), -1);
    std::vector<std::uint32_t> front;
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
      if (trust[v] < 1) {
        ring[v] = 0;
        front.push_back(v);
      }
    internal::grow_vertex_rings(domain, ring, std::move(front),
                                options.adaptive_margin_rings >= 0
                                    ? options.adaptive_margin_rings
                                    : internal::adaptive_energy_margin_rings);
    // The slots the energy solve keeps fixed have their local values from the streamed
    // pass. The solve starts the others from their targets, and the blend below reads the
    // polynomials of their tied vertices: those of the region and next to it are fitted
    // again (each fit is the same as in the pass).
    auto outside_solve = [&](Slot s) {
      for (std::uint32_t v : nearest(s))
        if (ring[v] >= 0)
          return false;
      return true;
    };
    {
      std::vector<char> near(domain.number_of_vertices(), 0);
      for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
        if (ring[v] >= 0) {
          near[v] = 1;
          const auto [nb, ne] = domain.neighbours(v);
          for (auto w = nb; w != ne; ++w)
            near[*w] = 1;
        }
      std::vector<std::uint32_t> refit;
      for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
        if (near[v])
          refit.push_back(v);
      local->fit(refit);
    }
    std::vector<double> distrust_tension;
    if (tension_weight > 0)
      for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
        distrust_tension.push_back(tension_weight * (1 - trust[v]));
    solved = internal::minimal_energy_free_values(
        spline, values, 0, distrust_tension,
        [&](Slot s, Value& fixed) {
          if (given_star(s, fixed))
            return true;
          if (!outside_solve(s))
            return false;
          fixed = spline.value(s); // target(s), from the streamed pass
          return true;
        },
        target, options);
    // Blend: each untrusted vertex's share of a slot moves from its polynomial to the
    // minimal-energy value in proportion to its distrust.
    for (Slot s : spline.free_slots()) {
      if (s < domain.number_of_vertices())
        continue;
      Value star;
      if (given_star(s, star)) {
        spline.set_free_value(s, star);
        continue;
      }
      const auto ties = nearest(s);
      bool trusted = true;
      for (std::uint32_t v : ties)
        trusted = trusted && trust[v] >= 1;
      if (trusted) {
        // solved only as part of the margin: the local value is the one to keep
        if (std::any_of(ties.begin(), ties.end(), [&](std::uint32_t v) { return ring[v] >= 0; }))
          spline.set_free_value(s, target(s));
        continue;
      }
      const auto label = spline.polar_label(s);
      std::array<std::pair<const typename GeomTraits::Point_2*, int>, 3> arguments;
      std::size_t count = 0;
      for (const auto& [vertex, multiplicity] : label)
        arguments[count++] = {&domain.point(vertex), multiplicity};
      const Value smooth = spline.value(s);
      Value v = Value_traits<Value>::zero();
      for (std::uint32_t w : ties) {
        const FT t(trust[w]);
        v = v + t * local->polar_value(w, arguments.begin(), arguments.begin() + count, 5) +
            (FT(1) - t) * smooth;
      }
      spline.set_free_value(s, ties.size() == 1 ? v : Value((FT(1) / FT(int(ties.size()))) * v));
    }
  } else if (fit == Fit::LEAST_SQUARES) {
    // (the local polynomials, 168 bytes per vertex, go once every slot's target is read)
    solved = internal::least_squares_free_values(spline, values, target, given_star, options,
                                                 [&] { local.reset(); });
  } else if (!streamed) {
    internal::parallel_for_index(
        spline.number_of_slots(), threads,
        [&](std::size_t i) {
          if (spline.is_free(Slot(i)))
            spline.set_free_value(Slot(i), target(Slot(i)));
        },
        block);
  }
  // The polynomials (21 coefficients per vertex) are not read again.
  local.reset();
  spline.propagate();
  static const char* const methods[] = {"", "direct", "windows", "conjugate_gradients"};
  statistics.solver_method = methods[solved.method];
  statistics.solver_sweeps = solved.sweeps;
  statistics.solver_windows = solved.windows;
  statistics.solver_window_solves = solved.window_solves;
  statistics.solver_iterations = solved.iterations;
  statistics.solver_last_change = solved.last_change;
  statistics.solver_converged = solved.converged;
  if (solver)
    *solver = solved;
  return statistics;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FIT_VERTEX_DATA_H

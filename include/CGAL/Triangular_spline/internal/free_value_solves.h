// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FREE_VALUE_SOLVES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FREE_VALUE_SOLVES_H

// The global fits of fit_vertex_data(): every slot as an affine function of the free values,
// and the least-squares and minimal-energy choices of those values (one direct solve, or
// overlapping windows beyond).

#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/thin_plate_energy.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/release.h>
#include <CGAL/Triangular_spline/internal/schwarz_solver.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Every slot's value as an affine function of the unknowns, by running the rules
// symbolically: value(s) = sum_i weight[i] x[unknown[i]] + constant(s) over the entries i of
// slot s's row. The unknowns are the free slots, without the corners when they interpolate
// the data (`corners_fixed`) and without the slots for which fixed(s, value) gives a value,
// which affine_slots() sets in the spline (a list of them took 16 bytes per free slot).
// The rows lie in two flat arrays (about 2.8 entries per slot on random points; a vector
// per slot cost 2.6 s and 1 GB at 10^5 points), each sorted by unknown.
//
// Inexact number types: the constants are the spline's own values, propagated with every
// unknown at zero (value(s) at x = 0 is constant(s)), valid until the spline's values
// change; exact ones keep them in an array of doubles (an exact propagation costs more than
// the solve). Where few slots have a row (the adaptive fit's local solve) the rows are found
// through a bitmap and a hash table instead of an index per slot. A constant and an index
// per slot took 12 bytes per slot, 300 MB at 10^6 points, for a solve that touches 2% of
// the slots (terrain-like data: 1265 MB, now 999).
template <class Value>
struct Affine_slots {
  static constexpr int D = Value_traits<Value>::dimension;
  static constexpr std::uint32_t no_row = std::numeric_limits<std::uint32_t>::max();
  std::size_t unknowns = 0;
  // Slot s's entries are row_begin[row_of(s)] .. + row_size[row_of(s)]. affine_slots() makes
  // rows 0 .. unknowns - 1 the unknowns' own rows (row j: the single entry 1 x_j), in order.
  std::vector<std::size_t> row_begin;
  std::vector<std::uint32_t> row_size;
  std::vector<int> unknown;
  std::vector<double> weight;

  bool has_row(std::size_t s) const { return row_of(s) != no_row; }
  // the row of slot s, or no_row
  std::uint32_t row_of(std::size_t s) const {
    if (!m_dense.empty())
      return m_dense[s];
    if (!((m_reached[s / 64] >> (s % 64)) & 1u))
      return no_row;
    for (std::size_t i = hash(s);; i = (i + 1) & (m_table.size() - 1))
      if (std::uint32_t(m_table[i] >> 32) == std::uint32_t(s))
        return std::uint32_t(m_table[i]);
  }
  std::size_t row_length(std::size_t s) const { return has_row(s) ? row_size[row_of(s)] : 0; }
  // the unknown of free slot s, or -1 if s is fixed (a free unknown's row is itself)
  int column(std::size_t s) const {
    const std::uint32_t r = row_of(s);
    return r != no_row ? unknown[row_begin[r]] : -1;
  }
  // calls f(unknown, weight) for the entries of slot s's row, in increasing unknown order
  template <class F>
  void for_each_entry(std::size_t s, const F& f) const {
    const std::uint32_t r = row_of(s);
    if (r == no_row)
      return;
    for (std::size_t i = row_begin[r], end = i + row_size[r]; i < end; ++i)
      f(unknown[i], weight[i]);
  }
  // coordinate c of slot s's constant
  double constant(std::size_t s, int c) const {
    if (m_values)
      return CGAL::to_double(Value_traits<Value>::coordinate((*m_values)[s], c));
    return m_constant[s][std::size_t(c)];
  }

  // (for affine_slots())
  void reset(std::size_t slots, bool dense_rows, const std::vector<Value>* values) {
    m_values = values;
    if (!values)
      m_constant.assign(slots, std::array<double, D>{});
    if (dense_rows)
      m_dense.assign(slots, no_row);
    else
      m_reached.assign(slots / 64 + 1, 0);
  }
  std::array<double, D>& stored_constant(std::size_t s) { return m_constant[s]; }
  bool stores_constants() const { return m_values == nullptr; }
  void set_row(std::size_t s, std::uint32_t r) {
    if (!m_dense.empty()) {
      m_dense[s] = r;
      return;
    }
    if (2 * (m_entries + 1) > m_table.size()) { // at most half full
      std::vector<std::uint64_t> old((std::max)(std::size_t(64), 2 * m_table.size()), empty);
      old.swap(m_table);
      for (std::uint64_t e : old)
        if (e != empty)
          insert(e);
    }
    m_reached[s / 64] |= std::uint64_t(1) << (s % 64);
    insert((std::uint64_t(s) << 32) | r);
    ++m_entries;
  }

private:
  static constexpr std::uint64_t empty = ~std::uint64_t(0);
  std::size_t hash(std::size_t s) const {
    return std::size_t((std::uint64_t(s) * 0x9E3779B97F4A7C15ull) >> 32) & (m_table.size() - 1);
  }
  void insert(std::uint64_t e) {
    std::size_t i = hash(std::size_t(e >> 32));
    while (m_table[i] != empty)
      i = (i + 1) & (m_table.size() - 1);
    m_table[i] = e;
  }
  const std::vector<Value>* m_values = nullptr;
  std::vector<std::array<double, D>> m_constant;
  std::vector<std::uint32_t> m_dense;   // row per slot (global fits)
  std::vector<std::uint64_t> m_reached; // bit per slot: has a row (local solves)
  std::vector<std::uint64_t> m_table;   // (slot << 32 | row), open addressing
  std::size_t m_entries = 0;
};

template <class GeomTraits, class Value, class Fixed>
Affine_slots<Value> affine_slots(C1_quintic_spline<GeomTraits, Value>& spline,
                                 const std::vector<Value>& values, bool corners_fixed,
                                 const Fixed& fixed) {
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  using FT = typename GeomTraits::FT;
  constexpr int D = Traits::dimension;
  constexpr bool exact = Algebraic_structure_traits<FT>::Is_exact::value;
  const std::size_t n = spline.values().size(); // control points and auxiliary slots
  const std::size_t V = spline.domain().number_of_vertices();
  // The unknowns first (the fixed values set in the spline, the unknowns at zero).
  std::vector<Slot> unknown_slots;
  Value given = Traits::zero();
  for (Slot s : spline.free_slots()) {
    if (corners_fixed && s < V)
      given = values[s];
    else if (!fixed(s, given)) {
      unknown_slots.push_back(s);
      spline.set_free_value(s, Traits::zero());
      continue;
    }
    spline.set_free_value(s, given);
  }
  Affine_slots<Value> a;
  // The global fits make every slot's row reach unknowns, about three entries each: reserved
  // at once (growing them copied 1.5 times their final size). A local solve (the adaptive
  // fit's) grows them as needed.
  const bool global = 4 * unknown_slots.size() > spline.number_of_free_parameters();
  a.reset(n, global, exact ? nullptr : &spline.values());
  if (global) {
    a.row_begin.reserve(n);
    a.row_size.reserve(n);
    a.unknown.reserve(3 * n);
    a.weight.reserve(3 * n);
  }
  if (a.stores_constants())
    for (Slot s : spline.free_slots())
      for (int c = 0; c < D; ++c)
        a.stored_constant(s)[std::size_t(c)] =
            CGAL::to_double(Traits::coordinate(spline.value(s), c));
  else
    spline.propagate();
  for (Slot s : unknown_slots) {
    a.set_row(s, static_cast<std::uint32_t>(a.row_begin.size()));
    a.row_begin.push_back(a.unknown.size());
    a.row_size.push_back(1);
    a.unknown.push_back(static_cast<int>(a.unknowns++));
    a.weight.push_back(1.0);
  }
  std::vector<Slot>().swap(unknown_slots);
  // A rule's row: the merge of its (at most three) sources' sorted rows, equal unknowns
  // summed in source order.
  constexpr int max_sources = 3;
  spline.for_each_rule([&](const auto& rule) {
    std::array<std::size_t, max_sources> at{}, end{};
    std::array<double, max_sources> w{};
    std::size_t total = 0;
    const int sources = rule.size();
    for (int i = 0; i < sources; ++i) {
      const Slot src = rule.sources[std::size_t(i)];
      w[std::size_t(i)] = CGAL::to_double(rule.weights[std::size_t(i)]);
      const std::uint32_t r = a.row_of(src);
      if (r != a.no_row) {
        at[std::size_t(i)] = a.row_begin[r];
        end[std::size_t(i)] = at[std::size_t(i)] + a.row_size[r];
        total += a.row_size[r];
      }
    }
    if (a.stores_constants()) {
      std::array<double, D> k;
      k.fill(0);
      for (int i = 0; i < sources; ++i)
        for (int c = 0; c < D; ++c)
          k[std::size_t(c)] +=
              w[std::size_t(i)] * a.stored_constant(rule.sources[std::size_t(i)])[std::size_t(c)];
      a.stored_constant(rule.target) = k;
    }
    if (total == 0)
      return; // no unknown reaches the target: a constant
    const std::size_t begin = a.unknown.size();
    a.unknown.resize(begin + total); // may move the arrays: indices, not pointers, above
    a.weight.resize(begin + total);
    std::size_t out = begin;
    for (;;) {
      int j = std::numeric_limits<int>::max();
      for (int i = 0; i < sources; ++i)
        if (at[std::size_t(i)] < end[std::size_t(i)])
          j = (std::min)(j, a.unknown[at[std::size_t(i)]]);
      if (j == std::numeric_limits<int>::max())
        break;
      double c = 0;
      for (int i = 0; i < sources; ++i)
        if (at[std::size_t(i)] < end[std::size_t(i)] && a.unknown[at[std::size_t(i)]] == j)
          c += w[std::size_t(i)] * a.weight[at[std::size_t(i)]++];
      a.unknown[out] = j;
      a.weight[out++] = c;
    }
    a.unknown.resize(out);
    a.weight.resize(out);
    if (out == begin)
      return; // the unknowns cancelled
    a.set_row(rule.target, static_cast<std::uint32_t>(a.row_begin.size()));
    a.row_begin.push_back(begin);
    a.row_size.push_back(std::uint32_t(out - begin));
  });
  // Grown by appends, their doubled capacity would last through the solve; but a reserve that
  // was nearly right is kept: shrinking copies (at 10^6 points 0.85 GB of fresh pages for the
  // 6% of the global fits' reserve left unused).
  auto fit_capacity = [](auto& array) {
    if (array.capacity() - array.size() > array.size() / 8)
      array.shrink_to_fit();
  };
  fit_capacity(a.row_begin);
  fit_capacity(a.row_size);
  fit_capacity(a.unknown);
  fit_capacity(a.weight);
  return a;
}

// The unit of the solver's tolerance (Schwarz_options): the largest range of a coordinate
// of the data values; their largest magnitude if they are constant, 1 if all zero.
template <class Value>
double data_scale(const std::vector<Value>& values) {
  using Traits = Value_traits<Value>;
  double range = 0, magnitude = 0;
  for (int c = 0; c < Traits::dimension; ++c) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Value& v : values) {
      const double t = CGAL::to_double(Traits::coordinate(v, c));
      lo = (std::min)(lo, t);
      hi = (std::max)(hi, t);
      magnitude = (std::max)(magnitude, std::abs(t));
    }
    range = (std::max)(range, hi - lo);
  }
  return range > 0 ? range : magnitude > 0 ? magnitude : 1.0;
}

// The weight of a triangle's energy in the minimal-energy fits: 1, except for thin
// triangles (shape quality q = 4 sqrt(3) area / sum of squared edges below 0.1, about 1:17),
// (q / 0.1)^3. A thin triangle's energy grows as the inverse cube of its thinness; at full
// weight the thin triangles along the hull of scattered data dominate the solve, which then
// bends the surface around them (and loses the rest of the triangles to rounding).
template <class Point_2>
double thin_triangle_weight(const Point_2& p, const Point_2& q, const Point_2& r) {
  const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
  const double ux = CGAL::to_double(q.x()) - px, uy = CGAL::to_double(q.y()) - py;
  const double vx = CGAL::to_double(r.x()) - px, vy = CGAL::to_double(r.y()) - py;
  const double area = std::abs(ux * vy - uy * vx) / 2;
  const double edges =
      ux * ux + uy * uy + vx * vx + vy * vy + (ux - vx) * (ux - vx) + (uy - vy) * (uy - vy);
  const double quality = 4 * std::sqrt(3.0) * area / edges;
  return quality >= 0.1 ? 1.0 : std::pow(quality / 0.1, 3);
}

// The vertex owning free slot s's unknown in the global solves (it decides the windows and
// the preconditioner's blocks): the vertex of largest multiplicity of s's label, the
// smallest index on ties.
template <class GeomTraits, class Value>
std::uint32_t owning_vertex(const C1_quintic_spline<GeomTraits, Value>& spline,
                            typename C1_quintic_spline<GeomTraits, Value>::Slot s) {
  int largest = -1;
  std::uint32_t owner = 0;
  for (const auto& [v, m] : spline.polar_label(s))
    if (m > largest || (m == largest && std::uint32_t(v) < owner)) {
      largest = m;
      owner = std::uint32_t(v);
    }
  return owner;
}

// The tension term of the Adaptive fit's energy, int_T |grad f - grad g|^2 for a quintic f
// over T and a linear g, in factored form as thin_plate_energy_factors(): f_x and f_y have
// the quartic coefficients 5 L_x b and 5 L_y b, M is the quartic Gram matrix times 25 (so
// that (L_x b)^T M (L_x b) = int f_x^2), and int_T f_x = (area / 3) 1^T L_x b.
struct Tension_factors {
  Eigen::Matrix<double, 15, 21, Eigen::RowMajor> first[2];
  Eigen::Matrix<double, 15, 15> gram;
  double area = 0;
  std::array<double, 3> ex{}, ey{}; // barycentric coordinates of the unit vectors
};
inline Tension_factors tension_factors(const std::array<std::array<double, 2>, 3>& corner) {
  Tension_factors t;
  const double ux = corner[1][0] - corner[0][0], uy = corner[1][1] - corner[0][1];
  const double vx = corner[2][0] - corner[0][0], vy = corner[2][1] - corner[0][1];
  const double det = ux * vy - uy * vx;
  t.ex = {{(uy - vy) / det, vy / det, -uy / det}};
  t.ey = {{(vx - ux) / det, -vx / det, ux / det}};
  t.area = std::abs(det) / 2;
  const auto coarse = bernstein_indices(4);
  for (int p = 0; p < 2; ++p) {
    const auto& e = p == 0 ? t.ex : t.ey;
    t.first[p].setZero();
    for (std::size_t g = 0; g < coarse.size(); ++g)
      for (int i = 0; i < 3; ++i) {
        Multi_index a = coarse[g];
        ++a[i];
        t.first[p](Eigen::Index(g), Eigen::Index(bernstein_position(5, a))) += e[std::size_t(i)];
      }
  }
  const std::vector<double>& table = bernstein_gram_table<double>(4);
  const double scale = 25 * t.area / 45; // 45: the area of the table's triangle, C(10, 2)
  for (Eigen::Index a = 0; a < 15; ++a)
    for (Eigen::Index b = 0; b < 15; ++b)
      t.gram(a, b) = scale * table[std::size_t(a * 15 + b)];
  return t;
}

// The quadratic objectives of the least-squares and minimal-energy fits, as a sum of face
// terms in the slot values s = R x + c (affine_slots()):
//   energy_weight[f] * E_f(s)  (thin-plate energy of face f's patch; skipped when 0),
//   tension_weight[f] * int_f |grad s - grad g_f|^2, g_f the linear interpolant of the
//   face's corner values (only with fixed corners; no term when tension_weight is empty),
//   misfit_weight * |s_t - target_t|^2 for the misfit slots t that face f owns (each slot
//   is owned by the first face containing it).
// It is minimised by schwarz_minimise(): one direct solve up to options.direct_limit
// unknowns, overlapping windows beyond. Unknowns start from initial(s) (the windows' first
// sweep sees them); the result is written to the free slots, converted to FT.
template <class GeomTraits, class Value, class Initial>
Schwarz_statistics minimise_slot_quadratic(
    C1_quintic_spline<GeomTraits, Value>& spline, const Affine_slots<Value>& a,
    const std::vector<double>& energy_weight, const std::vector<double>& tension_weight,
    std::vector<std::pair<std::uint32_t, Value>> misfits, double misfit_weight,
    const Initial& initial, const Schwarz_options& options, double scale, const char* what) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  using Point = CGAL::Simple_cartesian<double>::Point_2;
  constexpr int D = Traits::dimension;
  const auto& domain = spline.domain();
  if (a.unknowns == 0)
    return {};
  const auto indices = bernstein_indices(5);
  constexpr std::size_t n = 21;
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // slots' owning faces (4 bytes per slot: only when there are misfits); misfit targets by
  // face
  std::vector<std::uint32_t> owning_face;
  if (!misfits.empty()) {
    owning_face.assign(spline.number_of_slots(), none);
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f)
      for (const auto& index : indices) {
        const Slot s = spline.slot(f, index);
        if (owning_face[s] == none)
          owning_face[s] = f;
      }
  }
  // (none without misfits: 8 bytes per face)
  std::vector<std::size_t> misfit_start(misfits.empty() ? 0 : domain.number_of_faces() + 1, 0);
  std::vector<std::pair<Slot, std::array<double, D>>> face_misfits(misfits.size());
  for (const auto& m : misfits)
    ++misfit_start[owning_face[m.first] + 1];
  for (std::size_t f = 0; f + 1 < misfit_start.size(); ++f)
    misfit_start[f + 1] += misfit_start[f];
  if (!misfits.empty()) {
    std::vector<std::size_t> next(misfit_start.begin(), misfit_start.end() - 1);
    for (const auto& [s, t] : misfits) {
      std::array<double, D> target;
      for (int d = 0; d < D; ++d)
        target[std::size_t(d)] = CGAL::to_double(Traits::coordinate(t, d));
      face_misfits[next[owning_face[s]]++] = {s, target};
    }
  }
  // Regrouped by face: the caller's list (every slot's target in a least-squares fit, 16
  // bytes per slot) goes before the solve.
  std::vector<std::pair<std::uint32_t, Value>>().swap(misfits);
  release(owning_face);
  // the owners of the unknowns (owning_vertex())
  std::vector<Slot> slot_of(a.unknowns);
  std::vector<std::uint32_t> owner(a.unknowns);
  Eigen::MatrixXd x(Eigen::Index(a.unknowns), D);
  for (Slot s : spline.free_slots()) {
    if (a.column(s) < 0)
      continue;
    const auto j = std::size_t(a.column(s));
    slot_of[j] = s;
    owner[j] = owning_vertex(spline, s);
    const Value start = initial(s);
    for (int d = 0; d < D; ++d)
      x(Eigen::Index(j), d) = CGAL::to_double(Traits::coordinate(start, d));
  }
  auto unknowns_of = [&](std::uint32_t f, std::vector<std::uint32_t>& out) {
    for (const auto& index : indices)
      a.for_each_entry(spline.slot(f, index),
                       [&](int j, double) { out.push_back(std::uint32_t(j)); });
  };
  // The factors of the face terms: the Gram matrices of the Bernstein polynomials of degree 3
  // (second derivatives) and 4 (first derivatives) as U^T U. A face's terms are then sums of
  // squares |Y x + Y0|^2, Y = (scaled U) (differences L) (slot rows R): differences first,
  // as thin_plate_energy() does (forming L^T M L first loses thin triangles' energy to
  // cancellation in double), and Y R costs a few operations per entry of R's about 60.
  auto gram_factor = [](int degree) {
    const auto& table = bernstein_gram_table<double>(degree);
    const Eigen::Index c = Eigen::Index((degree + 1) * (degree + 2) / 2);
    Eigen::MatrixXd gram(c, c);
    for (Eigen::Index i = 0; i < c; ++i)
      for (Eigen::Index j = 0; j < c; ++j)
        gram(i, j) = table[std::size_t(i * c + j)];
    return Eigen::MatrixXd(gram.llt().matrixU());
  };
  const Eigen::MatrixXd U3 = gram_factor(3), U4 = gram_factor(4);
  const auto cubic = bernstein_indices(3), quartic = bernstein_indices(4);
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  struct Entry {
    int slot, column; // 0 .. 20, 0 .. k - 1
    double weight;
  };
  // one per worker of schwarz_minimise() (windows are solved on all cores)
  struct Scratch {
    Rows Y, Y0; // the squares' rows: in the unknowns, and constants
    Eigen::Matrix<double, 15, 21, Eigen::RowMajor> difference;
    Rows DR;
    Eigen::MatrixXd DC, C;
    std::vector<Entry> entries;
  };
  std::vector<Scratch> scratch(schwarz_workers(options));
  for (Scratch& own : scratch) {
    own.DC.resize(15, D);
    own.C.resize(Eigen::Index(n), D);
  }
  auto face_terms = [&](std::uint32_t f, Face_terms& terms, std::size_t worker) {
    Scratch& own = scratch[worker];
    Rows &Y = own.Y, &Y0 = own.Y0, &DR = own.DR;
    auto& difference = own.difference;
    Eigen::MatrixXd &DC = own.DC, &C = own.C;
    std::vector<Entry>& entries = own.entries;
    std::array<Slot, n> slot;
    auto& columns = terms.columns;
    columns.clear();
    for (std::size_t i = 0; i < n; ++i) {
      slot[i] = spline.slot(f, indices[i]);
      a.for_each_entry(slot[i], [&](int j, double) { columns.push_back(j); });
    }
    if (columns.empty())
      return;
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    const Eigen::Index k = Eigen::Index(columns.size());
    // R as (slot, column, weight) entries; C the slots' constants
    entries.clear();
    for (std::size_t i = 0; i < n; ++i) {
      for (int d = 0; d < D; ++d)
        C(Eigen::Index(i), d) = a.constant(slot[i], d);
      a.for_each_entry(slot[i], [&](int j, double c) {
        const auto l = std::lower_bound(columns.begin(), columns.end(), j) - columns.begin();
        entries.push_back({int(i), int(l), c});
      });
    }
    const bool energy = energy_weight[f] > 0;
    const bool tension = !tension_weight.empty() && tension_weight[f] > 0;
    const std::size_t first_misfit = face_misfits.empty() ? 0 : misfit_start[f];
    const std::size_t last_misfit = face_misfits.empty() ? 0 : misfit_start[f + 1];
    const Eigen::Index m =
        (energy ? 30 : 0) + (tension ? 30 : 0) + Eigen::Index(last_misfit - first_misfit);
    Y.setZero(m, k);
    Y0.setZero(m, D);
    terms.B.setZero(k, D);
    Eigen::Index row = 0;
    // rows += scale * U * (difference R), constants likewise (`c` differences)
    auto add_squares = [&](Eigen::Index c, const Eigen::MatrixXd& U, double scale) {
      DR.setZero(c, k);
      for (const auto& e : entries)
        DR.col(e.column) += e.weight * difference.col(e.slot).head(c);
      DC.topRows(c).noalias() = difference.topLeftCorner(c, Eigen::Index(n)) * C;
      Y.middleRows(row, c).noalias() = U.template triangularView<Eigen::Upper>() * DR;
      Y.middleRows(row, c) *= scale;
      Y0.middleRows(row, c).noalias() = U.template triangularView<Eigen::Upper>() * DC.topRows(c);
      Y0.middleRows(row, c) *= scale;
      row += c;
    };
    if (energy || tension) {
      const auto& t = domain.face(f);
      std::array<Point, 3> p;
      for (std::size_t i = 0; i < 3; ++i)
        p[i] =
            Point(CGAL::to_double(domain.point(t[i]).x()), CGAL::to_double(domain.point(t[i]).y()));
      std::array<double, 3> ex, ey;
      double scale;
      thin_plate_frame(5, p[0], p[1], p[2], ex, ey, scale);
      if (energy) {
        // f_xx, f_xy (weight 2), f_yy: second differences, Gram of degree 3 (scale: the area
        // and the factor 20^2 of the second derivatives)
        const std::array<const std::array<double, 3>*, 6> uw{{&ex, &ex, &ex, &ey, &ey, &ey}};
        for (int q = 0; q < 3; ++q) {
          difference.setZero();
          const auto &u = *uw[std::size_t(2 * q)], &w = *uw[std::size_t(2 * q + 1)];
          for (std::size_t g = 0; g < cubic.size(); ++g)
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) {
                Multi_index b = cubic[g];
                ++b[i];
                ++b[j];
                difference(Eigen::Index(g), Eigen::Index(bernstein_position(5, b))) +=
                    u[std::size_t(i)] * w[std::size_t(j)];
              }
          add_squares(10, U3, std::sqrt(energy_weight[f] * scale * (q == 1 ? 2 : 1)));
        }
      }
      if (tension) {
        // int |grad s - grad g|^2: first differences (f_x = 5 L_x b), Gram of degree 4 over
        // the face; the cross term -2 grad g . int grad s goes to B (g from the corners,
        // which are constants here)
        const double area = std::abs((p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) -
                                     (p[1].y() - p[0].y()) * (p[2].x() - p[0].x())) /
                            2;
        const double w = tension_weight[f];
        for (int q = 0; q < 2; ++q) {
          const auto& e = q == 0 ? ex : ey;
          difference.setZero();
          for (std::size_t g = 0; g < quartic.size(); ++g)
            for (int i = 0; i < 3; ++i) {
              Multi_index b = quartic[g];
              ++b[i];
              difference(Eigen::Index(g), Eigen::Index(bernstein_position(5, b))) +=
                  e[std::size_t(i)];
            }
          add_squares(15, U4, std::sqrt(w * 25 * area / 45));
          const Eigen::RowVectorXd column_sums = DR.topRows(15).colwise().sum();
          for (int d = 0; d < D; ++d) {
            double gradient = 0;
            for (std::size_t i = 0; i < 3; ++i)
              gradient += e[i] * a.constant(t[i], d);
            terms.B.col(d) += (w * gradient * area / 3) * column_sums.transpose();
          }
        }
      }
    }
    const double root = std::sqrt(misfit_weight);
    for (std::size_t mi = first_misfit; mi < last_misfit; ++mi, ++row) {
      const auto& [s, target] = face_misfits[mi];
      const auto i = Eigen::Index(std::find(slot.begin(), slot.end(), s) - slot.begin());
      for (const auto& e : entries)
        if (e.slot == i)
          Y(row, e.column) += root * e.weight;
      for (int d = 0; d < D; ++d)
        Y0(row, d) = root * (C(i, d) - target[std::size_t(d)]);
    }
    // the lower triangle only (schwarz_minimise() reads no more): half the products
    terms.H.setZero(k, k);
    terms.H.template selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose());
    terms.B.noalias() -= Y.transpose() * Y0;
  };
  auto neighbours = [&](std::uint32_t v, std::vector<std::uint32_t>& out) {
    const auto [begin, end] = domain.neighbours(v);
    for (auto w = begin; w != end; ++w)
      out.push_back(std::uint32_t(*w));
  };
  auto position = [&](std::uint32_t v) {
    const auto& p = domain.point(v);
    return std::array<double, 2>{{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
  };
  const Schwarz_statistics statistics =
      schwarz_minimise(domain.number_of_vertices(), owner, domain.number_of_faces(), unknowns_of,
                       face_terms, neighbours, position, x, options, scale, what);
  for (std::size_t j = 0; j < a.unknowns; ++j) {
    std::array<FT, std::size_t(D)> c;
    for (int d = 0; d < D; ++d)
      c[std::size_t(d)] = FT(x(Eigen::Index(j), d));
    spline.set_free_value(slot_of[j], Value_traits<Value>::from_coordinates(c));
  }
  return statistics;
}

// Replaces the symmetric positive definite k x k matrix A (packed lower triangle, A(i, j) at
// i (i + 1) / 2 + j for j <= i) by its inverse: A = L L^T (Cholesky), then A^-1 = L^-T L^-1
// in `scratch`. (Eigen's dynamic LLT and solve(I) took 0.14 CPU s for the 10^5 blocks of
// about 11 unknowns of a least-squares fit at 10^5 points: allocations and blocking for
// matrices this small.) The blocks of conjugate gradients' preconditioner are >= I.
inline void invert_packed_positive_definite(double* A, std::size_t k,
                                            std::vector<double>& scratch) {
  auto at = [](std::size_t i, std::size_t j) { return i * (i + 1) / 2 + j; };
  for (std::size_t i = 0; i < k; ++i) { // Cholesky, row by row
    double* Li = A + at(i, 0);
    for (std::size_t j = 0; j < i; ++j) {
      const double* Lj = A + at(j, 0);
      double t = Li[j];
      for (std::size_t l = 0; l < j; ++l)
        t -= Li[l] * Lj[l];
      Li[j] = t / Lj[j];
    }
    double d = Li[i];
    for (std::size_t l = 0; l < i; ++l)
      d -= Li[l] * Li[l];
    CGAL_assertion(d > 0);
    Li[i] = std::sqrt(d);
  }
  // L^-1 in place, row by row (row i reads L's row i from column j on and the rows above,
  // already inverted)
  for (std::size_t i = 0; i < k; ++i) {
    double* Li = A + at(i, 0);
    const double inverse = 1 / Li[i];
    for (std::size_t j = 0; j < i; ++j) {
      double t = 0;
      for (std::size_t l = j; l < i; ++l)
        t += Li[l] * A[at(l, j)];
      Li[j] = -t * inverse;
    }
    Li[i] = inverse;
  }
  // A^-1 (i, j) = sum over l >= i of L^-1 (l, i) L^-1 (l, j), for j <= i
  scratch.assign(k * (k + 1) / 2, 0.0);
  for (std::size_t l = 0; l < k; ++l) {
    const double* row = A + at(l, 0);
    for (std::size_t i = 0; i <= l; ++i) {
      double* out = scratch.data() + at(i, 0);
      const double c = row[i];
      for (std::size_t j = 0; j <= i; ++j)
        out[j] += c * row[j];
    }
  }
  std::copy(scratch.begin(), scratch.end(), A);
}

// The least-squares fit beyond options.direct_limit unknowns: the normal equations N x = b,
// N = R^T R and b = R^T (t - c) over the control slots' rows r_s (Affine_slots) and targets
// t_s, by conjugate gradients preconditioned with the inverses of N's diagonal blocks of
// the unknowns owned by one vertex. Every unknown's own row (1 x_j) is among the rows, so
// N >= I and |x - x*|_inf <= |x - x*|_2 <= |b - N x|_2: the iteration stops when that
// residual, recomputed from R rather than the recurrence's, is within options.tolerance *
// scale (the bound is Schwarz_statistics::last_change). Measured at 10^5 random points
// (1.1 10^6 unknowns, R with 7.1 10^6 entries), from the unknowns' targets: 10 iterations
// on exp(x) sin(2y), 36 with noise (N's diagonal alone: 63 and more). The whole run took
// 2.9 / 4.4 CPU s against 7.6 / 14.0 with the windows (one ring, 2 sweeps of 196). The
// targets, N's diagonal blocks and the iterations run on all cores (chunks below): at 10^6
// random points (22 iterations) the run took 0.88 times the wall clock of the serial solve
// (33.3 against 37.7 s) for 1.05 times its CPU (memory-bound loops on two cores).
template <class GeomTraits, class Value, class Target>
Schwarz_statistics least_squares_conjugate_gradients(C1_quintic_spline<GeomTraits, Value>& spline,
                                                     Affine_slots<Value> a, const Target& target,
                                                     const Schwarz_options& options, double scale,
                                                     const std::function<void()>& targets_read) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  constexpr int D = Traits::dimension;
  const std::size_t n = a.unknowns, V = spline.domain().number_of_vertices();
  Schwarz_statistics statistics;
  statistics.scale = scale;
  statistics.method = Schwarz_statistics::CONJUGATE_GRADIENTS;
  statistics.sweeps = 1;
  if (n == 0)
    return statistics;
  // Unknowns renumbered by owner (owning_vertex(), as the windows own them): a vertex's
  // block is a range, and rows read nearby memory.
  std::vector<Slot> slot_of(n);
  std::vector<std::uint32_t> owner(n);
  {
    const std::size_t all = spline.values().size(); // (control points and auxiliary slots)
    parallel_for_index(
        all, thread_count(all, 50000),
        [&](std::size_t i) {
          const Slot s = static_cast<Slot>(i);
          if (!spline.is_free(s))
            return;
          const int j = a.column(s);
          if (j < 0)
            return;
          CGAL_assertion(std::size_t(s) < spline.number_of_slots()); // its row is in R: N >= I
          slot_of[std::size_t(j)] = s;
          owner[std::size_t(j)] = owning_vertex(spline, s);
        },
        parallel_block);
  }
  std::vector<std::size_t> start(V + 1, 0);
  for (std::uint32_t v : owner)
    ++start[v + 1];
  for (std::size_t v = 0; v < V; ++v)
    start[v + 1] += start[v];
  std::vector<std::uint32_t> position(n);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t j = 0; j < n; ++j)
      position[j] = std::uint32_t(next[owner[j]]++);
  }
  release(owner);
  // R = [I; S] (rows permuted): the unknowns' own rows, kept as their targets t_own (a
  // sixth of R's entries, and of the rows' loop), and S, the other control slots' rows
  // (CSR, each row sorted) with y = t - c. S is compacted in a's arrays, its columns
  // renumbered (a copy, 0.7 GB at 10^6 points, raised the peak from 3.17 to 3.25 GB).
  std::vector<std::array<double, D>> own(n);
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> kept_as(a.row_size.size(), none); // S's row of a's row r
  // (affine_slots() lists the unknowns' own rows first: row j is unknown j's)
  auto is_own = [&](std::size_t s) { return a.row_of(s) < n; };
  std::size_t rows = 0;
  for (std::size_t s = 0; s < spline.number_of_slots(); ++s)
    if (a.has_row(s) && !is_own(s))
      kept_as[a.row_of(s)] = 0;
  for (std::uint32_t& k : kept_as)
    if (k == 0)
      k = std::uint32_t(rows++);
  std::vector<std::array<double, D>> y(rows);
  // the targets, on all cores (each slot writes its own entry)
  constexpr bool exact = Algebraic_structure_traits<FT>::Is_exact::value;
  const std::size_t slots = spline.number_of_slots();
  parallel_for_index(
      slots, thread_count(slots, exact ? 500 : 50000),
      [&](std::size_t s) {
        if (!a.has_row(s))
          return;
        const Value t = target(static_cast<Slot>(s));
        std::array<double, D>& r = is_own(s) ? own[position[a.row_of(s)]] : y[kept_as[a.row_of(s)]];
        for (int d = 0; d < D; ++d)
          r[std::size_t(d)] = CGAL::to_double(Traits::coordinate(t, d)) - a.constant(s, d);
      },
      exact ? 16 : parallel_block);
  if (targets_read) // what computes them (the local polynomials) can go before the solve
    targets_read();
  std::vector<std::size_t> row_start(rows + 1, 0);
  std::vector<int> column = std::move(a.unknown);
  std::vector<double> weight = std::move(a.weight);
  {
    std::size_t out = 0; // <= the row's begin: rows only move forward
    for (std::size_t r = 0; r < kept_as.size(); ++r) {
      if (kept_as[r] == none)
        continue;
      const std::size_t begin = a.row_begin[r], size = a.row_size[r];
      for (std::size_t i = 0; i < size; ++i) { // insertion into the sorted row
        const int j = int(position[std::size_t(column[begin + i])]);
        const double w = weight[begin + i];
        std::size_t at = out + i;
        for (; at > out && column[at - 1] > j; --at) {
          column[at] = column[at - 1];
          weight[at] = weight[at - 1];
        }
        column[at] = j;
        weight[at] = w;
      }
      out += size;
      row_start[kept_as[r] + 1] = out;
    }
    column.resize(out);
    weight.resize(out);
  }
  release(kept_as);
  a = {};
  // Chunks: ranges of whole vertex blocks of about n / chunks unknowns each, their number
  // fixed by n alone, so that the result does not depend on the number of threads. A chunk's
  // loops run on one thread and write only its own unknowns. chunk_rows lists, chunk by
  // chunk and in increasing order, the rows of S that reach the chunk's unknowns; chunk k
  // adds a row's products to its own unknowns only, in row order as the serial loops did, so
  // that N p, the residual and the diagonal blocks are the one-thread ones bit for bit (the
  // dot products are sums of the chunks' sums). A row reaching several chunks (near their
  // borders: the unknowns are numbered by vertex, and the vertices spatially) is multiplied
  // in each.
  const std::size_t chunks = (std::min)(std::size_t(64), (std::max)(std::size_t(1), n / 16384));
  std::vector<std::uint32_t> chunk_vertex(chunks + 1, std::uint32_t(V));
  std::vector<std::size_t> chunk_unknown(chunks + 1, n); // empty chunks at the end
  chunk_vertex[0] = 0;
  chunk_unknown[0] = 0;
  for (std::uint32_t v = 0, k = 1; v < V && k < chunks; ++v)
    if (start[v] >= k * n / chunks) {
      chunk_vertex[k] = v;
      chunk_unknown[k++] = start[v];
    }
  auto chunk_of = [&](std::size_t j) {
    return std::size_t(std::upper_bound(chunk_unknown.begin(), chunk_unknown.end(), j) -
                       chunk_unknown.begin() - 1);
  };
  std::vector<std::size_t> chunk_row_start(chunks + 1, 0);
  std::vector<std::uint32_t> chunk_rows;
  {
    // calls f(k) for each chunk that row r reaches, in increasing order
    auto chunks_of_row = [&](std::size_t r, const auto& f) {
      std::size_t k = chunk_of(std::size_t(column[row_start[r]]));
      f(k);
      for (std::size_t i = row_start[r] + 1; i < row_start[r + 1]; ++i)
        if (std::size_t(column[i]) >= chunk_unknown[k + 1]) {
          k = chunk_of(std::size_t(column[i]));
          f(k);
        }
    };
    for (std::size_t r = 0; r < rows; ++r)
      chunks_of_row(r, [&](std::size_t k) { ++chunk_row_start[k + 1]; });
    for (std::size_t k = 0; k < chunks; ++k)
      chunk_row_start[k + 1] += chunk_row_start[k];
    chunk_rows.resize(chunk_row_start[chunks]);
    std::vector<std::size_t> next(chunk_row_start.begin(), chunk_row_start.end() - 1);
    for (std::size_t r = 0; r < rows; ++r)
      chunks_of_row(r, [&](std::size_t k) { chunk_rows[next[k]++] = std::uint32_t(r); });
  }
  const std::size_t chunk_threads = (std::min)(chunks, thread_count(chunks, 1));
  auto for_each_chunk = [&](const auto& f) { parallel_for_index(chunks, chunk_threads, f, 1); };
  // sum over the chunks of f(k), in chunk order
  std::vector<double> chunk_sum(chunks);
  auto sum_of_chunks = [&](const auto& f) {
    for_each_chunk([&](std::size_t k) { chunk_sum[k] = f(k); });
    return std::accumulate(chunk_sum.begin(), chunk_sum.end(), 0.0);
  };
  // N's diagonal blocks (I plus S's products), packed lower triangles
  std::vector<std::uint32_t> vertex_of(n);
  std::vector<std::size_t> block_at(V + 1, 0);
  for (std::size_t v = 0; v < V; ++v) {
    const std::size_t k = start[v + 1] - start[v];
    block_at[v + 1] = block_at[v] + k * (k + 1) / 2;
    for (std::size_t i = start[v]; i < start[v + 1]; ++i)
      vertex_of[i] = std::uint32_t(v);
  }
  // (each chunk sets up its own blocks: their pages are touched on all cores)
  std::unique_ptr<double[]> block(new double[block_at[V]]);
  for_each_chunk([&](std::size_t k) {
    for (std::uint32_t v = chunk_vertex[k]; v < chunk_vertex[k + 1]; ++v) {
      std::fill(block.get() + block_at[v], block.get() + block_at[v + 1], 0.0);
      for (std::size_t i = 0; i < start[v + 1] - start[v]; ++i)
        block[block_at[v] + i * (i + 1) / 2 + i] = 1;
    }
    const std::size_t lo = chunk_unknown[k], hi = chunk_unknown[k + 1];
    for (std::size_t c = chunk_row_start[k]; c < chunk_row_start[k + 1]; ++c) {
      const std::size_t r = chunk_rows[c];
      for (std::size_t p = row_start[r]; p < row_start[r + 1]; ++p) {
        const std::size_t j = std::size_t(column[p]);
        if (j < lo || j >= hi)
          continue;
        const std::uint32_t v = vertex_of[j];
        double* L = block.get() + block_at[v];
        const std::size_t i = j - start[v];
        for (std::size_t q = p + 1; q-- > row_start[r] && vertex_of[column[q]] == v;)
          L[i * (i + 1) / 2 + (column[q] - start[v])] += weight[p] * weight[q];
      }
    }
  });
  release(vertex_of);
  // each block replaced by its inverse (packed lower triangle)
  for_each_chunk([&](std::size_t chunk) {
    std::vector<double> scratch;
    for (std::uint32_t v = chunk_vertex[chunk]; v < chunk_vertex[chunk + 1]; ++v)
      invert_packed_positive_definite(block.get() + block_at[v], start[v + 1] - start[v], scratch);
  });
  // z = (block diagonal of N)^-1 r on chunk k's unknowns; returns their r.z
  auto precondition = [&](std::size_t chunk, const double* r, double* z) {
    double rz = 0;
    for (std::uint32_t v = chunk_vertex[chunk]; v < chunk_vertex[chunk + 1]; ++v) {
      const double* L = block.get() + block_at[v];
      const std::size_t o = start[v], k = start[v + 1] - o;
      const double* rv = r + o;
      double* zv = z + o;
      for (std::size_t i = 0; i < k; ++i) {
        const double* Li = L + i * (i + 1) / 2;
        const double ri = rv[i];
        double e = Li[i] * ri;
        for (std::size_t l = 0; l < i; ++l) {
          e += Li[l] * rv[l];
          zv[l] += Li[l] * ri;
        }
        zv[i] = e;
      }
      for (std::size_t i = 0; i < k; ++i)
        rz += rv[i] * zv[i];
    }
    return rz;
  };
  // g = N p = p + S^T S p; returns p^T N p = |p|^2 + |S p|^2 (a row's square counted by the
  // chunk of its first unknown)
  auto normal_product = [&](const double* p, double* g) {
    return sum_of_chunks([&](std::size_t k) {
      const std::size_t lo = chunk_unknown[k], hi = chunk_unknown[k + 1];
      double squares = 0;
      for (std::size_t i = lo; i < hi; ++i) {
        g[i] = p[i];
        squares += p[i] * p[i];
      }
      for (std::size_t c = chunk_row_start[k]; c < chunk_row_start[k + 1]; ++c) {
        const std::size_t r = chunk_rows[c];
        const std::size_t begin = row_start[r], end = row_start[r + 1];
        double t = 0;
        for (std::size_t i = begin; i < end; ++i)
          t += weight[i] * p[column[i]];
        if (std::size_t(column[begin]) >= lo)
          squares += t * t;
        for (std::size_t i = begin; i < end; ++i)
          if (std::size_t(column[i]) >= lo && std::size_t(column[i]) < hi)
            g[column[i]] += weight[i] * t;
      }
      return squares;
    });
  };
  // r = b - N x = (t_own - x) + S^T (y - S x), for coordinate d; returns |r|^2
  auto residual_of = [&](const double* x, std::size_t d, double* r) {
    return sum_of_chunks([&](std::size_t k) {
      const std::size_t lo = chunk_unknown[k], hi = chunk_unknown[k + 1];
      for (std::size_t i = lo; i < hi; ++i)
        r[i] = own[i][d] - x[i];
      for (std::size_t c = chunk_row_start[k]; c < chunk_row_start[k + 1]; ++c) {
        const std::size_t row = chunk_rows[c];
        const std::size_t begin = row_start[row], end = row_start[row + 1];
        double t = y[row][d];
        for (std::size_t i = begin; i < end; ++i)
          t -= weight[i] * x[column[i]];
        for (std::size_t i = begin; i < end; ++i)
          if (std::size_t(column[i]) >= lo && std::size_t(column[i]) < hi)
            r[column[i]] += weight[i] * t;
      }
      double squares = 0;
      for (std::size_t i = lo; i < hi; ++i)
        squares += r[i] * r[i];
      return squares;
    });
  };
  const double threshold = options.tolerance * scale;
  const int limit = (std::max)(0, options.max_iterations);
  // Not zeroed: every entry is written first by its chunk, so that the pages are touched on
  // all cores (fresh pages cost up to 2 s per GB on the machines measured). z = M r and
  // g = N p share their array: g is read only by the update that follows the product, z
  // only until the direction p is formed from it, and each is written before it is read.
  std::unique_ptr<double[]> vectors(new double[4 * n]);
  double *const x = vectors.get(), *const r = x + n, *const z = r + n, *const p = z + n,
                *const g = z;
  statistics.converged = true;
  for (std::size_t d = 0; d < std::size_t(D); ++d) {
    // from the unknowns' own targets
    for_each_chunk([&](std::size_t k) {
      for (std::size_t i = chunk_unknown[k]; i < chunk_unknown[k + 1]; ++i)
        x[i] = own[i][d];
    });
    int iterations = 0;
    double residual = 0;
    for (;;) { // restarted from the recomputed residual until it is within the threshold
      residual = std::sqrt(residual_of(x, d, r));
      if (!std::isfinite(residual))
        throw Invalid_input("fit: the least-squares iteration gave a non-finite residual");
      if (residual <= threshold || iterations >= limit)
        break;
      double rz = sum_of_chunks([&](std::size_t k) { return precondition(k, r, z); });
      for_each_chunk([&](std::size_t k) {
        std::copy(z + chunk_unknown[k], z + chunk_unknown[k + 1], p + chunk_unknown[k]);
      });
      while (iterations < limit) {
        ++iterations;
        const double alpha = rz / normal_product(p, g);
        const double squares = sum_of_chunks([&](std::size_t k) {
          double sum = 0;
          for (std::size_t i = chunk_unknown[k]; i < chunk_unknown[k + 1]; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * g[i];
            sum += r[i] * r[i];
          }
          return sum;
        });
        if (std::sqrt(squares) <= threshold)
          break;
        const double next = sum_of_chunks([&](std::size_t k) { return precondition(k, r, z); });
        const double beta = next / rz;
        for_each_chunk([&](std::size_t k) {
          for (std::size_t i = chunk_unknown[k]; i < chunk_unknown[k + 1]; ++i)
            p[i] = z[i] + beta * p[i];
        });
        rz = next;
      }
    }
    statistics.iterations = (std::max)(statistics.iterations, iterations);
    statistics.last_change = (std::max)(statistics.last_change, residual);
    statistics.converged = statistics.converged && residual <= threshold;
    // coordinate d's targets are not read again: they give way to the solution
    for_each_chunk([&](std::size_t k) {
      for (std::size_t i = chunk_unknown[k]; i < chunk_unknown[k + 1]; ++i)
        own[i][d] = x[i];
    });
  }
  vectors.reset();
  parallel_for_index(
      n, thread_count(n, exact ? 500 : 50000),
      [&](std::size_t j) {
        std::array<FT, std::size_t(D)> c;
        for (int d = 0; d < D; ++d)
          c[std::size_t(d)] = FT(own[position[j]][std::size_t(d)]);
        spline.set_free_value(slot_of[j], Value_traits<Value>::from_coordinates(c));
      },
      exact ? 16 : parallel_block);
  return statistics;
}

// Least-squares choice of the free values (Fit::LEAST_SQUARES): corners fixed to the data,
// the free slots for which fixed(s, value) is true to that value, then min sum_s |value(s) -
// target(s)|^2 over all slots: one direct solve up to options.direct_limit unknowns,
// conjugate gradients beyond.
template <class GeomTraits, class Value, class Target, class Fixed>
Schwarz_statistics least_squares_free_values(C1_quintic_spline<GeomTraits, Value>& spline,
                                             const std::vector<Value>& values, const Target& target,
                                             const Fixed& fixed,
                                             const Schwarz_options& options = {},
                                             const std::function<void()>& targets_read = {}) {
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  auto a = affine_slots(spline, values, true, fixed);
  if (a.unknowns > options.direct_limit)
    return least_squares_conjugate_gradients(spline, std::move(a), target, options,
                                             data_scale(values), targets_read);
  std::vector<std::pair<std::uint32_t, Value>> misfits;
  misfits.reserve(spline.number_of_slots());
  for (std::size_t s = 0; s < spline.number_of_slots(); ++s)
    if (a.has_row(s))
      misfits.emplace_back(std::uint32_t(s), target(static_cast<Slot>(s)));
  return minimise_slot_quadratic(
      spline, a, std::vector<double>(spline.domain().number_of_faces(), 0), {}, std::move(misfits),
      1.0, target, options, data_scale(values), "least-squares");
}

// Minimal thin-plate energy (Fit::MINIMAL_ENERGY): corners fixed to the data, the free slots
// for which fixed(s, value) is true fixed to that value, and min sum_f b_f^T G_f b_f over
// the others; with smoothing > 0 the corners are unknowns too and the objective is
// sum_v |s(v) - z_v|^2 + smoothing * h^2 * energy, h^2 the domain's area per vertex (so
// that smoothing is dimensionless: invariant under scaling of x and y). With a tension per
// vertex (interpolating only; empty: none) the energy has the term (tau_f / h^2) int_f
// |grad s - grad g|^2, tau_f the mean of face f's vertices' tensions and g the piecewise
// linear interpolant of the data: it pulls badly resolved data toward g and vanishes, like
// the thin-plate energy, on linear data. Faces whose control points are all
// fixed only add a constant and are skipped. The unknowns start from initial(s) (used only
// by the windows of large problems).
template <class GeomTraits, class Value, class Fixed, class Initial>
Schwarz_statistics minimal_energy_free_values(C1_quintic_spline<GeomTraits, Value>& spline,
                                              const std::vector<Value>& values, double smoothing,
                                              const std::vector<double>& tension,
                                              const Fixed& fixed, const Initial& initial,
                                              const Schwarz_options& options = {}) {
  const auto& domain = spline.domain();
  const bool interpolating = !(smoothing > 0);
  CGAL_precondition(interpolating || tension.empty());
  const auto a = affine_slots(spline, values, interpolating, fixed);
  double area = 0;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    const auto &p = domain.point(t[0]), &q = domain.point(t[1]), &r = domain.point(t[2]);
    area += std::abs(CGAL::to_double((q.x() - p.x()) * (r.y() - p.y()) -
                                     (q.y() - p.y()) * (r.x() - p.x()))) /
            2;
  }
  const double h2 = area / double(domain.number_of_vertices());
  const double weight = interpolating ? 1 : smoothing * h2;
  std::vector<double> energy_weight(domain.number_of_faces()), tension_weight;
  if (!tension.empty())
    tension_weight.resize(domain.number_of_faces());
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    const double thin =
        thin_triangle_weight(domain.point(t[0]), domain.point(t[1]), domain.point(t[2]));
    energy_weight[f] = weight * thin;
    if (!tension.empty())
      tension_weight[f] = (tension[t[0]] + tension[t[1]] + tension[t[2]]) / (3 * h2) * thin;
  }
  // s(v) is the corner slot of v, an unknown when smoothing
  std::vector<std::pair<std::uint32_t, Value>> misfits;
  if (!interpolating)
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
      if (a.has_row(v))
        misfits.emplace_back(v, values[v]);
  return minimise_slot_quadratic(
      spline, a, energy_weight, tension_weight, std::move(misfits), 1.0, initial,
      schwarz_margin_rings(options, interpolating ? energy_margin_rings : smoothing_margin_rings),
      data_scale(values), "minimal-energy");
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FREE_VALUE_SOLVES_H

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
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Every slot's value as an affine function of the unknowns, by running the rules
// symbolically: value(s) = sum rows[s] x + constant[s]. The unknowns are the free slots,
// without the corners when they interpolate the data (`corners_fixed`) and without the
// slots for which fixed(s, value) gives a value.
template <class Value>
struct Affine_slots {
  static constexpr int D = Value_traits<Value>::dimension;
  std::vector<int> column;
  std::size_t unknowns = 0;
  std::vector<std::vector<std::pair<int, double>>> rows;
  std::vector<std::array<double, D>> constant;
  std::vector<std::pair<std::uint32_t, Value>> fixed; // the free slots that are not unknowns
};

template <class GeomTraits, class Value, class Fixed>
Affine_slots<Value> affine_slots(const C1_quintic_spline<GeomTraits, Value>& spline,
                                 const std::vector<Value>& values, bool corners_fixed,
                                 const Fixed& fixed) {
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  constexpr int D = Traits::dimension;
  const std::size_t n = spline.values().size(); // control points and auxiliary slots
  const std::size_t V = spline.domain().number_of_vertices();
  Affine_slots<Value> a;
  a.column.assign(n, -1);
  a.rows.resize(n);
  a.constant.resize(n);
  for (auto& c : a.constant)
    c.fill(0);
  Value given = Traits::zero();
  for (Slot s : spline.free_slots()) {
    if (corners_fixed && s < V)
      given = values[s];
    else if (!fixed(s, given)) {
      a.column[s] = static_cast<int>(a.unknowns++);
      a.rows[s] = {{a.column[s], 1.0}};
      continue;
    }
    for (int c = 0; c < D; ++c)
      a.constant[s][std::size_t(c)] = CGAL::to_double(Traits::coordinate(given, c));
    a.fixed.emplace_back(s, given);
  }
  std::vector<std::pair<int, double>> merged;
  for (const auto& rule : spline.rules()) {
    merged.clear();
    std::array<double, D> k;
    k.fill(0);
    for (int i = 0; i < rule.size(); ++i) {
      const double w = CGAL::to_double(rule.weights[std::size_t(i)]);
      const Slot src = rule.sources[std::size_t(i)];
      for (const auto& [j, c] : a.rows[src])
        merged.emplace_back(j, w * c);
      for (int c = 0; c < D; ++c)
        k[std::size_t(c)] += w * a.constant[src][std::size_t(c)];
    }
    std::sort(merged.begin(), merged.end());
    auto& row = a.rows[rule.target];
    row.clear();
    for (const auto& [j, c] : merged) {
      if (!row.empty() && row.back().first == j)
        row.back().second += c;
      else
        row.emplace_back(j, c);
    }
    a.constant[rule.target] = k;
  }
  return a;
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
    const std::vector<std::pair<std::uint32_t, Value>>& misfits, double misfit_weight,
    const Initial& initial, const Schwarz_options& options, int default_sweeps, const char* what) {
  using FT = typename GeomTraits::FT;
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  using Traits = Value_traits<Value>;
  using Point = CGAL::Simple_cartesian<double>::Point_2;
  constexpr int D = Traits::dimension;
  const auto& domain = spline.domain();
  for (const auto& [s, value] : a.fixed)
    spline.set_free_value(s, value);
  if (a.unknowns == 0)
    return {};
  const auto indices = bernstein_indices(5);
  constexpr std::size_t n = 21;
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // slots' owning faces; misfit targets by face
  std::vector<std::uint32_t> owning_face(spline.number_of_slots(), none);
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f)
    for (const auto& index : indices) {
      const Slot s = spline.slot(f, index);
      if (owning_face[s] == none)
        owning_face[s] = f;
    }
  std::vector<std::size_t> misfit_start(domain.number_of_faces() + 1, 0);
  std::vector<std::pair<Slot, std::array<double, D>>> face_misfits(misfits.size());
  for (const auto& m : misfits)
    ++misfit_start[owning_face[m.first] + 1];
  for (std::size_t f = 0; f < domain.number_of_faces(); ++f)
    misfit_start[f + 1] += misfit_start[f];
  {
    std::vector<std::size_t> next(misfit_start.begin(), misfit_start.end() - 1);
    for (const auto& [s, t] : misfits) {
      std::array<double, D> target;
      for (int d = 0; d < D; ++d)
        target[std::size_t(d)] = CGAL::to_double(Traits::coordinate(t, d));
      face_misfits[next[owning_face[s]]++] = {s, target};
    }
  }
  // the owner of an unknown: the vertex of largest multiplicity of its slot's label
  // (smallest index on ties)
  std::vector<Slot> slot_of(a.unknowns);
  std::vector<std::uint32_t> owner(a.unknowns);
  Eigen::MatrixXd x(Eigen::Index(a.unknowns), D);
  for (Slot s : spline.free_slots()) {
    if (a.column[s] < 0)
      continue;
    const auto j = std::size_t(a.column[s]);
    slot_of[j] = s;
    int largest = -1;
    for (const auto& [v, m] : spline.polar_label(s))
      if (m > largest || (m == largest && v < owner[j])) {
        largest = m;
        owner[j] = std::uint32_t(v);
      }
    const Value start = initial(s);
    for (int d = 0; d < D; ++d)
      x(Eigen::Index(j), d) = CGAL::to_double(Traits::coordinate(start, d));
  }
  auto unknowns_of = [&](std::uint32_t f, std::vector<std::uint32_t>& out) {
    for (const auto& index : indices)
      for (const auto& entry : a.rows[spline.slot(f, index)])
        out.push_back(std::uint32_t(entry.first));
  };
  std::vector<int> columns;
  using Dense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Dense L(10, Eigen::Index(n)), M(10, 10);
  Eigen::MatrixXd R, C, X, MX, H, B;
  auto assemble = [&](std::uint32_t f, const std::vector<int>& local, const Eigen::MatrixXd& at,
                      std::vector<Eigen::Triplet<double>>& triplets, Eigen::MatrixXd& rhs) {
    std::array<Slot, n> slot;
    columns.clear();
    for (std::size_t i = 0; i < n; ++i) {
      slot[i] = spline.slot(f, indices[i]);
      for (const auto& entry : a.rows[slot[i]])
        if (local[std::size_t(entry.first)] >= 0)
          columns.push_back(local[std::size_t(entry.first)]);
    }
    if (columns.empty())
      return;
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    const Eigen::Index k = Eigen::Index(columns.size());
    // slot values = R (window unknowns) + C (constants and the other unknowns' values)
    R.setZero(Eigen::Index(n), k);
    C.setZero(Eigen::Index(n), D);
    for (std::size_t i = 0; i < n; ++i) {
      for (int d = 0; d < D; ++d)
        C(Eigen::Index(i), d) = a.constant[slot[i]][std::size_t(d)];
      for (const auto& [j, c] : a.rows[slot[i]]) {
        const int l = local[std::size_t(j)];
        if (l >= 0)
          R(Eigen::Index(i),
            std::lower_bound(columns.begin(), columns.end(), l) - columns.begin()) += c;
        else
          C.row(Eigen::Index(i)) += c * at.row(j);
      }
    }
    H.setZero(k, k);
    B.setZero(k, D);
    if (energy_weight[f] > 0) {
      const auto& t = domain.face(f);
      auto point = [&](std::size_t i) {
        const auto& p = domain.point(t[i]);
        return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
      };
      // Differences first (L R, L C), then squares: forming the Gram matrix first loses
      // thin triangles' energy to cancellation in double.
      const auto factors = thin_plate_energy_factors(5, point(0), point(1), point(2));
      for (Eigen::Index a1 = 0; a1 < 10; ++a1)
        for (Eigen::Index a2 = 0; a2 < 10; ++a2)
          M(a1, a2) = energy_weight[f] * factors.gram[std::size_t(a1 * 10 + a2)];
      for (int p = 0; p < 3; ++p) {
        for (Eigen::Index a1 = 0; a1 < 10; ++a1)
          for (Eigen::Index i = 0; i < Eigen::Index(n); ++i)
            L(a1, i) = factors.second[std::size_t(p)][std::size_t(a1) * n + std::size_t(i)];
        const double w = factors.weight[std::size_t(p)];
        X.noalias() = L * R;
        MX.noalias() = M * X;
        H.noalias() += w * (X.transpose() * MX);
        B.noalias() -= w * (MX.transpose() * (L * C));
      }
    }
    if (!tension_weight.empty() && tension_weight[f] > 0) {
      const auto& t = domain.face(f);
      std::array<std::array<double, 2>, 3> corner;
      for (std::size_t i = 0; i < 3; ++i)
        corner[i] = {
            {CGAL::to_double(domain.point(t[i]).x()), CGAL::to_double(domain.point(t[i]).y())}};
      const Tension_factors tf = tension_factors(corner);
      const double w = tension_weight[f];
      for (int p = 0; p < 2; ++p) {
        const auto& e = p == 0 ? tf.ex : tf.ey;
        X.noalias() = tf.first[p] * R;
        MX.noalias() = tf.gram * X;
        H.noalias() += w * (X.transpose() * MX);
        B.noalias() -= w * (MX.transpose() * (tf.first[p] * C));
        // - 2 grad g . int grad s: the corners are constants, so g_f comes from them
        const Eigen::VectorXd column_sums = X.colwise().sum().transpose();
        for (int d = 0; d < D; ++d) {
          double g = 0;
          for (std::size_t i = 0; i < 3; ++i)
            g += e[i] * a.constant[t[i]][std::size_t(d)];
          B.col(d) += (w * g * tf.area / 3) * column_sums;
        }
      }
    }
    for (std::size_t m = misfit_start[f]; m < misfit_start[f + 1]; ++m) {
      const auto& [s, target] = face_misfits[m];
      const std::size_t i = std::size_t(std::find(slot.begin(), slot.end(), s) - slot.begin());
      const auto r = R.row(Eigen::Index(i));
      H.noalias() += misfit_weight * (r.transpose() * r);
      for (int d = 0; d < D; ++d)
        B.col(d) +=
            misfit_weight * (target[std::size_t(d)] - C(Eigen::Index(i), d)) * r.transpose();
    }
    for (Eigen::Index i = 0; i < k; ++i) {
      for (Eigen::Index j = 0; j < k; ++j)
        if (H(i, j) != 0)
          triplets.emplace_back(columns[std::size_t(i)], columns[std::size_t(j)], H(i, j));
      rhs.row(columns[std::size_t(i)]) += B.row(i);
    }
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
                       assemble, neighbours, position, x, options, default_sweeps, what);
  for (std::size_t j = 0; j < a.unknowns; ++j) {
    std::array<FT, std::size_t(D)> c;
    for (int d = 0; d < D; ++d)
      c[std::size_t(d)] = FT(x(Eigen::Index(j), d));
    spline.set_free_value(slot_of[j], Value_traits<Value>::from_coordinates(c));
  }
  return statistics;
}

// Least-squares choice of the free values (Fit::LEAST_SQUARES): corners fixed to the data,
// the free slots for which fixed(s, value) is true to that value, then min sum_s |value(s) -
// target(s)|^2 over all slots.
template <class GeomTraits, class Value, class Target, class Fixed>
Schwarz_statistics least_squares_free_values(C1_quintic_spline<GeomTraits, Value>& spline,
                                             const std::vector<Value>& values, const Target& target,
                                             const Fixed& fixed,
                                             const Schwarz_options& options = {}) {
  using Slot = typename C1_quintic_spline<GeomTraits, Value>::Slot;
  const auto a = affine_slots(spline, values, true, fixed);
  std::vector<std::pair<std::uint32_t, Value>> misfits;
  misfits.reserve(spline.number_of_slots());
  for (std::size_t s = 0; s < spline.number_of_slots(); ++s)
    if (!a.rows[s].empty())
      misfits.emplace_back(std::uint32_t(s), target(static_cast<Slot>(s)));
  return minimise_slot_quadratic(spline, a,
                                 std::vector<double>(spline.domain().number_of_faces(), 0), {},
                                 misfits, 1.0, target, options, 1, "least-squares");
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
      if (!a.rows[v].empty())
        misfits.emplace_back(v, values[v]);
  return minimise_slot_quadratic(spline, a, energy_weight, tension_weight, misfits, 1.0, initial,
                                 options, 2, "minimal-energy");
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FREE_VALUE_SOLVES_H

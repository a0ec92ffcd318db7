// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H
#define CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/Xu/local_polynomial_fit.h>
#include <CGAL/Triangular_spline/Xu/thin_plate_energy.h>
#include <CGAL/Triangular_spline/internal/schwarz_solver.h>

#include <CGAL/Simple_cartesian.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief how the free control points of a `C1_quintic_spline` are set from data at the
  vertices.
*/
enum class Fit {
  /// every free point is the polar-value blend of its patch's corner data,
  /// \f$f(a^i b^j c^k) \approx (i z_a + j z_b + k z_c)/5\f$ (Xu §7.3, §6.2.4); with
  /// `Corner_frame::SYMMETRIC_STARS` the corners are propagated: the spline approximates
  APPROXIMATE,
  /// as `APPROXIMATE`, and every corner point is prescribed to the data value (Xu §4.4.2);
  /// needs `Corner_frame::CORNER_AND_TWO_STARS`
  INTERPOLATE,
  /// interpolation of values and of gradients estimated at every vertex (least squares over
  /// its neighbours): each free point takes the tangent-plane value of its nearest corner
  /// (averaged on ties), at its domain point, the degree-1 case of Mann's nearest-vertex
  /// rule; this tilts the corner frames along the data (Xu §4.4.5) instead of
  /// flattening them. Needs `Corner_frame::CORNER_AND_TWO_STARS`
  TANGENT_PLANES,
  /// interpolation of the values; the other free points are chosen so that ALL control
  /// points (free and propagated) are as close as possible, in least squares, to the
  /// `TANGENT_PLANES` targets: every control value is a linear function of the free ones.
  /// This is the remedy for the amplification of Xu §4.4.5: thin frames propagate with large
  /// weights, and the least-squares choice keeps the propagated points near the data
  /// instead of letting them overshoot. The targets are those of `LOCAL_POLYNOMIAL`. The
  /// minimiser is global: one sparse Cholesky factorization (Eigen) up to 40000 unknowns
  /// (about 3600 vertices), beyond one sweep of overlapping windows (cells of about 500
  /// vertices and three rings, each minimised exactly with the others at their current
  /// values, starting from the targets): linear time, memory bounded by a window, and the
  /// global minimiser to 1.3e-12 (largest control-value difference from the direct solve,
  /// measured on 20000 noisy random points). The solve runs in `double`; the free values are
  /// then converted to `FT` and propagated in `FT`, so an exact spline is still exactly C^1
  /// (linear data is then reproduced up to the solve's rounding). Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  LEAST_SQUARES,
  /// interpolation of the values; every free point takes the polar value of the local
  /// polynomial (`Local_polynomials`, degree 3 by default) of its nearest corner, averaged
  /// on ties. All points of a corner region, and every corner-inner and edge-middle point,
  /// then come from one polynomial, so propagation through them reproduces it whatever its
  /// weights; only flip points and re-routed edge points mix the polynomials of
  /// neighbouring vertices. Data
  /// from a polynomial of degree at most the local degree are reproduced exactly (exactly
  /// with an exact number type); local in time and memory. Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  LOCAL_POLYNOMIAL,
  /// interpolation of the values with the least thin-plate energy
  /// \f$\int f_{xx}^2 + 2 f_{xy}^2 + f_{yy}^2\f$ over the whole spline space (exact Bernstein
  /// Gram matrices, `thin_plate_energy_matrix()`; the sparse normal equations are solved in
  /// `double` and the free values converted to `FT`, as for `LEAST_SQUARES`): the fairest
  /// interpolant, Xu §8.3's open problem; the spline analogue of a thin-plate spline. Thin
  /// triangles (shape quality \f$q = 4\sqrt{3}\,\mathrm{area} / \sum \mathrm{edge}^2 < 0.1\f$)
  /// count with weight \f$(q/0.1)^3\f$: their energy grows as the inverse cube of their
  /// thinness, and at full weight the thin triangles along the hull of scattered data would
  /// dominate the solve and bend the surface around them. With
  /// a positive `smoothing` \f$\lambda\f$ it no longer interpolates but minimises
  /// \f$\sum_v (s(v) - z_v)^2 + \lambda h^2 E(s)\f$, \f$h^2\f$ the domain's area per
  /// vertex, for noisy data. Reproduces linear data exactly (up to the solve's rounding in
  /// exact builds). The global minimiser: one sparse Cholesky factorization up to 40000
  /// unknowns (about 3600 vertices); beyond, two sweeps of overlapping windows (block
  /// Gauss-Seidel: cells of about 500 vertices with three rings of margin, each window's
  /// energy minimised exactly with the other unknowns at their current values, the first
  /// sweep starting from the `LOCAL_POLYNOMIAL` values). Every window solve lowers the
  /// energy and the sweeps converge to the global minimiser; after two, the largest
  /// difference of a control value from the direct solve is 1.2e-8 (20000 noisy random
  /// points; 3e-5 with smoothing 0.1). Linear time (about 0.13 ms per vertex and sweep),
  /// memory bounded by a window. Needs `Corner_frame::CORNER_AND_TWO_STARS`
  MINIMAL_ENERGY,
  /// interpolation of the values; `LOCAL_POLYNOMIAL` where the local polynomials resolve the
  /// data, `MINIMAL_ENERGY` where they do not, blended in between: the most accurate fit on
  /// dense smooth data and on sparse or rough data alike. Each vertex's resolution
  /// \f$\rho_v\f$ (`Local_polynomials::resolution()`, the leave-one-out residual of its
  /// polynomial relative to a plane's) gives a trust \f$\tau_v\f$: 1 for \f$\rho_v \le 0.1\f$,
  /// 0 for \f$\rho_v \ge 0.5\f$, linear between. Free points whose nearest vertices are all
  /// trusted take their local value (exactly as `LOCAL_POLYNOMIAL`); the others are chosen by
  /// least thin-plate energy over the untrusted vertices and three rings around them, with
  /// the local values beyond as boundary values (the margin keeps the kinks of local values
  /// in thin boundary triangles, tiny in value but huge in energy, from bending the surface
  /// next to them), then each nearest vertex's share
  /// becomes \f$\tau_v\f$ times its polynomial's value plus \f$1-\tau_v\f$ times the energy
  /// value. Data from a polynomial of degree at most the local degree leave every vertex
  /// trusted and are reproduced exactly, as by `LOCAL_POLYNOMIAL`. The energy solve is that
  /// of `MINIMAL_ENERGY` over the untrusted region (direct, or two sweeps of windows beyond
  /// 40000 unknowns), linear in its size and never skipped. Needs
  /// `Corner_frame::CORNER_AND_TWO_STARS`
  ADAPTIVE
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns the least-squares gradient at every vertex of the data `values`: the
  plane through \f$(v, z_v)\f$ closest to the neighbours' data (exact arithmetic with an
  exact number type; a vertex whose neighbours are collinear with it has no gradient and
  gets the zero vector).
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param domain the triangulated planar domain
  \param values the data values, one per domain vertex
  \returns the least-squares gradient at every vertex of the data `values`
*/
template <class GeomTraits, class Value>
std::vector<std::array<Value, 2>> estimate_gradients(const Planar_domain<GeomTraits>& domain,
                                                     const std::vector<Value>& values) {
  using FT = typename GeomTraits::FT;
  std::vector<std::array<Value, 2>> gradients(domain.number_of_vertices());
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
    // Normal equations of min sum |z_v + g.(w - v) - z_w|^2: 2x2, per coordinate of Value.
    FT a(0), b(0), c(0);
    Value rx = Value_traits<Value>::zero(), ry = Value_traits<Value>::zero();
    const auto [nb, ne] = domain.neighbours(v);
    for (auto w = nb; w != ne; ++w) {
      const FT dx = domain.point(*w).x() - domain.point(v).x();
      const FT dy = domain.point(*w).y() - domain.point(v).y();
      a = a + dx * dx;
      b = b + dx * dy;
      c = c + dy * dy;
      const Value dz = values[*w] - values[v];
      rx = rx + dx * dz;
      ry = ry + dy * dz;
    }
    const FT det = a * c - b * b;
    if (CGAL::is_zero(det)) {
      gradients[v] = {{Value_traits<Value>::zero(), Value_traits<Value>::zero()}};
      continue;
    }
    const Value gx = (c / det) * rx - (b / det) * ry;
    const Value gy = (a / det) * ry - (b / det) * rx;
    gradients[v] = {{gx, gy}};
  }
  return gradients;
}

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
  const std::size_t n = spline.number_of_slots();
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
    for (int i = 0; i < rule.size; ++i) {
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

// The quadratic objectives of the least-squares and minimal-energy fits, as a sum of face
// terms in the slot values s = R x + c (affine_slots()):
//   energy_weight[f] * E_f(s)  (thin-plate energy of face f's patch; skipped when 0), and
//   misfit_weight * |s_t - target_t|^2 for the misfit slots t that face f owns (each slot
//   is owned by the first face containing it).
// It is minimised by schwarz_minimise(): one direct solve up to options.direct_limit
// unknowns, overlapping windows beyond. Unknowns start from initial(s) (the windows' first
// sweep sees them); the result is written to the free slots, converted to FT.
template <class GeomTraits, class Value, class Initial>
Schwarz_statistics
minimise_slot_quadratic(C1_quintic_spline<GeomTraits, Value>& spline, const Affine_slots<Value>& a,
                        const std::vector<double>& energy_weight,
                        const std::vector<std::pair<std::uint32_t, Value>>& misfits,
                        double misfit_weight, const Initial& initial,
                        const Schwarz_options& options, int default_sweeps, const char* what) {
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
                                 std::vector<double>(spline.domain().number_of_faces(), 0), misfits,
                                 1.0, target, options, 1, "least-squares");
}

// Minimal thin-plate energy (Fit::MINIMAL_ENERGY): corners fixed to the data, the free slots
// for which fixed(s, value) is true fixed to that value, and min sum_f b_f^T G_f b_f over
// the others; with smoothing > 0 the corners are unknowns too and the objective is
// sum_v |s(v) - z_v|^2 + smoothing * h^2 * energy, h^2 the domain's area per vertex (so
// that smoothing is dimensionless: invariant under scaling of x and y). Faces whose
// control points are all fixed only add a constant and are skipped. The unknowns start
// from initial(s) (used only by the windows of large problems).
template <class GeomTraits, class Value, class Fixed, class Initial>
Schwarz_statistics minimal_energy_free_values(C1_quintic_spline<GeomTraits, Value>& spline,
                                              const std::vector<Value>& values, double smoothing,
                                              const Fixed& fixed, const Initial& initial,
                                              const Schwarz_options& options = {}) {
  const auto& domain = spline.domain();
  const bool interpolating = !(smoothing > 0);
  const auto a = affine_slots(spline, values, interpolating, fixed);
  double weight = 1;
  if (!interpolating) {
    double area = 0;
    for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
      const auto& t = domain.face(f);
      const auto &p = domain.point(t[0]), &q = domain.point(t[1]), &r = domain.point(t[2]);
      area += std::abs(CGAL::to_double((q.x() - p.x()) * (r.y() - p.y()) -
                                       (q.y() - p.y()) * (r.x() - p.x()))) /
              2;
    }
    weight = smoothing * area / double(domain.number_of_vertices());
  }
  std::vector<double> energy_weight(domain.number_of_faces());
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    energy_weight[f] =
        weight * thin_triangle_weight(domain.point(t[0]), domain.point(t[1]), domain.point(t[2]));
  }
  // s(v) is the corner slot of v, an unknown when smoothing
  std::vector<std::pair<std::uint32_t, Value>> misfits;
  if (!interpolating)
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
      if (!a.rows[v].empty())
        misfits.emplace_back(v, values[v]);
  return minimise_slot_quadratic(spline, a, energy_weight, misfits, 1.0, initial, options, 2,
                                 "minimal-energy");
}

// Resolution (Local_polynomials::resolution()) below which a vertex's polynomial is trusted
// fully, and above which not at all, in the Adaptive fit. Measured on the TOMS 792 node sets
// and jittered grids: every vertex of smooth data sampled at h <= 1/8 has a resolution below
// 1e-4; the sparse sets' spread over [0.05, 1].
inline std::pair<double, double> adaptive_resolution_thresholds() {
  return {0.1, 0.5};
}
// Rings around the untrusted vertices over which the Adaptive fit's energy solve extends.
constexpr int adaptive_energy_margin_rings = 3;

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief what `fit_vertex_data()` did: the degrees of the local polynomials
  (`LOCAL_POLYNOMIAL`, `LEAST_SQUARES` and `ADAPTIVE` fits, and `MINIMAL_ENERGY` beyond
  40000 unknowns, whose windows start from them; all zero otherwise).
*/
struct Fit_statistics {
  /// `vertices_by_degree[d]`: the number of vertices whose local polynomial has degree `d`
  std::array<std::size_t, 6> vertices_by_degree{};
  /// `ADAPTIVE` fit: the number of vertices whose polynomial is trusted fully (`[0]`),
  /// blended with the minimal-energy values (`[1]`), or not used at all (`[2]`)
  std::array<std::size_t, 3> vertices_by_trust{};
  /// always `false` (kept for compatibility): the `ADAPTIVE` fit's energy solve used to be
  /// skipped beyond \f$10^4\f$ untrusted vertices; it is now linear in their number and
  /// always done
  bool energy_skipped = false;
};

namespace internal {

// fit_vertex_data() with the solver's options, and what the solver did (tests, benchmarks).
template <class GeomTraits, class Value>
Fit_statistics
fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline, const std::vector<Value>& values,
                Fit fit, int local_degree, Degree_selection selection, double smoothing,
                const std::vector<std::array<Value, 2>>& given_gradients,
                const Schwarz_options& options, Schwarz_statistics* solver = nullptr) {
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
  std::optional<Local_polynomials<GeomTraits, Value>> local;
  // A windowed energy solve starts from the local polynomials' values: the first sweep's
  // windows see them beyond their margins.
  if (fit == Fit::LOCAL_POLYNOMIAL || fit == Fit::LEAST_SQUARES || fit == Fit::ADAPTIVE ||
      (fit == Fit::MINIMAL_ENERGY && spline.number_of_free_parameters() > options.direct_limit))
    local.emplace(domain, values, local_degree, selection);
  Fit_statistics statistics;
  if (local)
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
      ++statistics.vertices_by_degree[std::size_t(local->degree(v))];
  // The value a slot should take from the data: polar blend, or tangent plane of the
  // nearest corner(s) at the slot's domain point.
  auto target = [&](Slot s) {
    Value v = Value_traits<Value>::zero();
    if (given_star(s, v))
      return v;
    const auto label = spline.polar_label(s);
    if (fit == Fit::APPROXIMATE || fit == Fit::INTERPOLATE) {
      for (const auto& [vertex, multiplicity] : label)
        v = v + (FT(multiplicity) / FT(5)) * values[vertex];
      return v;
    }
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
        v = v + local->polar_value(entry.first, arguments.begin(), arguments.begin() + count, 5);
        ++ties;
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
  if (!(smoothing >= 0) || !std::isfinite(smoothing))
    throw Invalid_input("fit: the smoothing must be a finite number >= 0");
  if (smoothing > 0 && fit != Fit::MINIMAL_ENERGY)
    throw Invalid_input("fit: smoothing needs the minimal-energy fit");
  // Adaptive fit: trust in each vertex's polynomial, from how well it resolves the data.
  std::vector<double> trust;
  bool blend_energy = false;
  if (fit == Fit::ADAPTIVE) {
    const auto [low, high] = internal::adaptive_resolution_thresholds();
    trust.resize(domain.number_of_vertices());
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
      const double r = local->resolution(v);
      trust[v] = r <= low ? 1.0 : r >= high ? 0.0 : (high - r) / (high - low);
      ++statistics.vertices_by_trust[trust[v] >= 1 ? 0 : trust[v] > 0 ? 1 : 2];
    }
    // Fully trusted data need no solve: the fit is then Local_polynomial. The energy solve
    // is linear in the untrusted region's size (windows beyond options.direct_limit
    // unknowns), so it is never skipped.
    blend_energy = statistics.vertices_by_trust[1] + statistics.vertices_by_trust[2] > 0;
  }
  internal::Schwarz_statistics solved;
  if (fit == Fit::MINIMAL_ENERGY) {
    solved = internal::minimal_energy_free_values(
        spline, values, smoothing, given_star,
        [&](Slot s) { return local ? target(s) : Value_traits<Value>::zero(); }, options);
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
    for (int r = 1; r <= internal::adaptive_energy_margin_rings; ++r) {
      std::vector<std::uint32_t> next;
      for (std::uint32_t u : front) {
        const auto [nb, ne] = domain.neighbours(u);
        for (auto w = nb; w != ne; ++w)
          if (ring[*w] < 0) {
            ring[*w] = r;
            next.push_back(*w);
          }
      }
      front.swap(next);
    }
    solved = internal::minimal_energy_free_values(
        spline, values, 0,
        [&](Slot s, Value& fixed) {
          if (given_star(s, fixed))
            return true;
          for (std::uint32_t v : nearest(s))
            if (ring[v] >= 0)
              return false;
          fixed = target(s);
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
    solved = internal::least_squares_free_values(spline, values, target, given_star, options);
  } else {
    for (Slot s : spline.free_slots())
      spline.set_free_value(s, target(s));
  }
  spline.propagate();
  if (solver)
    *solver = solved;
  return statistics;
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief sets every free control point of `spline` from the data `values` (one per domain
  vertex) according to `fit`, then propagates, and returns what it did.

  Every mode reproduces data sampled from a linear function exactly (every prescribed point
  is then the linear function's polar value, and propagation preserves it; for
  `LOCAL_POLYNOMIAL` and `LEAST_SQUARES` with `local_degree` at least 1).
  `local_degree` is the largest degree of the local polynomials of `LOCAL_POLYNOMIAL`,
  `LEAST_SQUARES` and `ADAPTIVE` (0..5); `selection` how they choose it. `smoothing` (at least
  0) is the \f$\lambda\f$ of `MINIMAL_ENERGY`; 0 interpolates. `given_gradients` (one per
  vertex, or empty to estimate them) are interpolated by every fit but `APPROXIMATE`: each
  star point \f$f(v^4 w)\f$ becomes \f$z_v + \nabla z_v \cdot (w - v)/5\f$, so the spline's
  gradient at every vertex is the given one (exactly with an exact number type); the other
  free points follow the fit.
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \throws Invalid_input if `values` or `given_gradients` has the wrong size or a non-finite
  value, if `smoothing` is negative or not finite or given to another fit than
  `MINIMAL_ENERGY` or with gradients, if gradients are given to `APPROXIMATE`, or if a fit
  other than `APPROXIMATE` is asked of a spline whose corner points are not free.
  \param spline the spline whose free control points are set
  \param values the data values, one per domain vertex
  \param fit the fitting mode
  \param local_degree the largest degree of the local polynomials
  \param selection the rule choosing the degree of each local polynomial
  \param smoothing the weight of the smoothing term
  \param given_gradients the gradients at the vertices, one pair per domain vertex, if given
  \returns statistics of what the fit did
*/
template <class GeomTraits, class Value>
Fit_statistics fit_vertex_data(C1_quintic_spline<GeomTraits, Value>& spline,
                               const std::vector<Value>& values, Fit fit, int local_degree = 3,
                               Degree_selection selection = Degree_selection::CROSS_VALIDATION,
                               double smoothing = 0,
                               const std::vector<std::array<Value, 2>>& given_gradients = {}) {
  return internal::fit_vertex_data(spline, values, fit, local_degree, selection, smoothing,
                                   given_gradients, internal::Schwarz_options());
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_FIT_VERTEX_DATA_H

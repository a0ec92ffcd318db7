// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_ADJUSTMENT_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_ADJUSTMENT_H

// The steps of adjust_join() and adjust_network() (Mann/Continuity_adjustment.h): blossom
// expansions, the averaging of one order across an edge, an exact or pivoted solve, and the
// projection of the corner regions around a vertex.

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Mann/Network_adjustment.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// A residual for a message: three significant digits.
inline std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

// max(1, largest absolute control coordinate): double tolerances are relative to it.
template <class GeomTraits, class Value>
double control_scale(const Bezier_triangle<GeomTraits, Value>& patch) {
  double scale = 1;
  for (const Value& v : patch.control_points())
    scale = (std::max)(scale, max_abs_coordinate(v));
  return scale;
}

template <class FT>
FT power(const FT& x, int e) {
  FT result(1);
  for (int i = 0; i < e; ++i)
    result = result * x;
  return result;
}

// l! / (a! b! (l-a-b)!), exactly in 64-bit integers (and below 2^53) for l <= 30.
inline long long multinomial(int l, int a, int b) {
  long long result = 1;
  // C(l, a) * C(l - a, b), each built incrementally so that every division is exact.
  for (int x = 1; x <= a; ++x)
    result = result * (l - a + x) / x;
  long long second = 1;
  for (int x = 1; x <= b; ++x)
    second = second * (l - a - b + x) / x;
  return result * second;
}

// The multi-index with `apex` copies of local vertex local[0], `first` of local[1] and
// `second` of local[2].
inline Multi_index local_index(const std::array<int, 3>& local, int apex, int first, int second) {
  Multi_index index;
  index[local[0]] = apex;
  index[local[1]] = first;
  index[local[2]] = second;
  return index;
}

// The expansion of `copies` copies of a point with barycentric weights `w` (in a patch's
// local vertex order) in a blossom: the terms (a, b, coefficient) of the control points with
// a more copies of local[0], b more of local[1] and copies - a - b more of local[2], the
// coefficient being the multinomial copies!/(a! b! c!) times w[local[0]]^a w[local[1]]^b
// w[local[2]]^c. Zero coefficients are dropped.
template <class FT>
struct Expansion_term {
  int a, b;
  FT coefficient;
};

template <class FT>
std::vector<Expansion_term<FT>> expansion(const std::array<FT, 3>& w,
                                          const std::array<int, 3>& local, int copies) {
  std::array<std::vector<FT>, 3> powers;
  for (std::size_t x = 0; x < 3; ++x) {
    powers[x].assign(std::size_t(copies + 1), FT(1));
    for (int e = 1; e <= copies; ++e)
      powers[x][std::size_t(e)] = powers[x][std::size_t(e - 1)] * w[std::size_t(local[x])];
  }
  std::vector<Expansion_term<FT>> terms;
  for (int a = 0; a <= copies; ++a)
    for (int b = 0; a + b <= copies; ++b) {
      const FT coefficient = FT(double(multinomial(copies, a, b))) * // exact below 2^53
                             powers[0][std::size_t(a)] * powers[1][std::size_t(b)] *
                             powers[2][std::size_t(copies - a - b)];
      if (!CGAL::is_zero(coefficient))
        terms.push_back({a, b, coefficient});
    }
  return terms;
}

/*
  Enforces the order-l conditions with first-vertex count i in [i_lo, i_hi] between A over
  (p, r, s) and B over (q, r, s) (local vertex indices in `a_local` = {p, r, s} and
  `b_local` = {q, r, s}), assuming the pair meets C^(l-1).

  Lai's balanced value of A at (p^g q^h r^i s^j), g = floor(l/2), h = ceil(l/2),
  i + j = n - l, is obtained by expanding the h copies of q = d0 p + d1 r + d2 s in A's
  frame: a combination of the control points A(p^(g+a) r^(i+b) s^(j+c)), a + b + c = h,
  with multinomial coefficients (the same terms for every i). The only one with l copies of
  p is A(p^l r^i s^j), with coefficient d0^h; symmetrically B's value, with the g copies of
  p = v0 q + v1 r + v2 s expanded, contains B(q^l r^i s^j) with coefficient v0^g. Moving
  these two points by +(diff/2)/d0^h and -(diff/2)/v0^g, diff = B's value - A's value,
  makes both values the average (Mann eqs. (3), (4) and Fig. 9 in closed form). The
  order-l values for other i do not contain these points, and no condition of lower order
  does, so all corrections of one order are computed from the values before any move.
  l = 0 sets both boundary points to the average itself (bit-identical in double too).
*/
template <class GeomTraits, class Value>
void adjust_order(Bezier_triangle<GeomTraits, Value>& A, const std::array<int, 3>& a_local,
                  Bezier_triangle<GeomTraits, Value>& B, const std::array<int, 3>& b_local, int l,
                  int i_lo, int i_hi, std::vector<Multi_index>* a_touched,
                  std::vector<Multi_index>* b_touched, double& max_correction) {
  using FT = typename GeomTraits::FT;
  const int n = A.degree();
  if (i_lo > i_hi)
    return;
  const int g = l / 2, h = l - l / 2;
  const std::array<FT, 3> wq = A.barycentric_coordinates(B.vertex(b_local[0]));
  const std::array<FT, 3> wp = B.barycentric_coordinates(A.vertex(a_local[0]));
  const std::vector<Expansion_term<FT>> a_terms = expansion(wq, a_local, h);
  const std::vector<Expansion_term<FT>> b_terms = expansion(wp, b_local, g);
  auto value = [n](const Bezier_triangle<GeomTraits, Value>& P, const std::array<int, 3>& local,
                   const std::vector<Expansion_term<FT>>& terms, int apex, int copies, int i) {
    const int j = n - apex - copies - i;
    Value sum = Value_traits<Value>::zero();
    for (const Expansion_term<FT>& t : terms) {
      const Value& point = P.control_points()[linear_index(
          local_index(local, apex + t.a, i + t.b, j + (copies - t.a - t.b)))];
      sum = sum + t.coefficient * point;
    }
    return sum;
  };
  // The values of all conditions first: the moves below change no other value of order l.
  std::vector<Value> differences;
  differences.reserve(std::size_t(i_hi - i_lo + 1));
  std::vector<Value> sums; // order 0: the sums of the two boundary points
  for (int i = i_lo; i <= i_hi; ++i) {
    const Value a_value = value(A, a_local, a_terms, g, h, i);
    const Value b_value = value(B, b_local, b_terms, h, g, i);
    differences.push_back(b_value - a_value);
    if (l == 0)
      sums.push_back(a_value + b_value);
  }
  // Computed on first use: most conditions of a nearly smooth network need no correction.
  bool have_factors = false;
  FT a_factor(0), b_factor(0);
  const FT half = FT(1) / FT(2);
  for (int i = i_lo; i <= i_hi; ++i) {
    const Value& difference = differences[std::size_t(i - i_lo)];
    if (is_zero_value(difference))
      continue;
    const int j = n - l - i;
    const Multi_index at_a = local_index(a_local, l, i, j);
    const Multi_index at_b = local_index(b_local, l, i, j);
    if (l == 0) {
      const Value average = half * sums[std::size_t(i - i_lo)];
      max_correction = (std::max)(max_correction, max_abs_coordinate(Value(half * difference)));
      A.set_control_point(at_a, average);
      B.set_control_point(at_b, average);
    } else {
      if (!have_factors) {
        a_factor = half / power(wq[std::size_t(a_local[0])], h);
        b_factor = half / power(wp[std::size_t(b_local[0])], g);
        have_factors = true;
      }
      const Value a_correction = a_factor * difference;
      const Value b_correction = b_factor * difference;
      max_correction = (std::max)(max_correction, (std::max)(max_abs_coordinate(a_correction),
                                                             max_abs_coordinate(b_correction)));
      const Value a_new = A.control_point(at_a) + a_correction;
      const Value b_new = B.control_point(at_b) - b_correction;
      A.set_control_point(at_a, a_new);
      B.set_control_point(at_b, b_new);
    }
    if (a_touched)
      a_touched->push_back(at_a);
    if (b_touched)
      b_touched->push_back(at_b);
  }
}

// Gauss-Jordan elimination with full pivoting on the m x m matrix `matrix` (row-major),
// for a consistent system: on return `rhs` holds a solution, with the free unknowns of a
// singular matrix set to zero. Exact number types pivot on any non-zero entry; double
// ones on the largest, and entries below `relative_threshold` times the largest entry of
// the input count as zero. Returns the rank.
template <class FT, class Value>
std::size_t solve_consistent(std::vector<FT> matrix, std::vector<Value>& rhs, std::size_t m,
                             double relative_threshold) {
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  double largest = 0;
  if (!exact)
    for (const FT& x : matrix)
      largest = (std::max)(largest, std::abs(CGAL::to_double(x)));
  const double threshold = relative_threshold * largest;
  std::vector<std::size_t> column(m);
  for (std::size_t c = 0; c < m; ++c)
    column[c] = c;
  auto at = [&](std::size_t r, std::size_t c) -> FT& { return matrix[r * m + c]; };
  std::size_t rank = 0;
  for (; rank < m; ++rank) {
    std::size_t pr = m, pc = m;
    double best = threshold;
    for (std::size_t r = rank; r < m && (pr == m || !exact); ++r)
      for (std::size_t c = rank; c < m; ++c) {
        if (exact) {
          if (!CGAL::is_zero(at(r, c))) {
            pr = r;
            pc = c;
            break;
          }
        } else {
          const double x = std::abs(CGAL::to_double(at(r, c)));
          if (x > best) {
            best = x;
            pr = r;
            pc = c;
          }
        }
      }
    if (pr == m)
      break;
    if (pr != rank) {
      for (std::size_t c = 0; c < m; ++c)
        std::swap(at(pr, c), at(rank, c));
      std::swap(rhs[pr], rhs[rank]);
    }
    if (pc != rank) {
      for (std::size_t r = 0; r < m; ++r)
        std::swap(at(r, pc), at(r, rank));
      std::swap(column[pc], column[rank]);
    }
    const FT inverse = FT(1) / at(rank, rank);
    for (std::size_t c = rank; c < m; ++c)
      at(rank, c) = at(rank, c) * inverse;
    rhs[rank] = inverse * rhs[rank];
    for (std::size_t r = 0; r < m; ++r) {
      if (r == rank || CGAL::is_zero(at(r, rank)))
        continue;
      const FT factor = at(r, rank);
      for (std::size_t c = rank; c < m; ++c)
        at(r, c) = at(r, c) - factor * at(rank, c);
      rhs[r] = rhs[r] - factor * rhs[rank];
    }
  }
  std::vector<Value> solution(m, Value_traits<Value>::zero());
  for (std::size_t s = 0; s < rank; ++s)
    solution[column[s]] = rhs[s];
  rhs = std::move(solution);
  return rank;
}

// Local vertex index of the domain point `point` in `patch`, or -1.
template <class GeomTraits, class Value>
int local_vertex(const Bezier_triangle<GeomTraits, Value>& patch,
                 const typename GeomTraits::Point_2& point) {
  for (int v = 0; v < 3; ++v)
    if (patch.vertex(v) == point)
      return v;
  return -1;
}

// The patch-local index of each corner of each face: local[f][c] is the position in
// patches[f] of domain.face(f)[c].
template <class GeomTraits, class Value>
std::vector<std::array<int, 3>>
face_to_patch_vertices(const Planar_domain<GeomTraits>& domain,
                       const std::vector<Bezier_triangle<GeomTraits, Value>>& patches,
                       const std::string& where) {
  const std::size_t F = domain.number_of_faces();
  if (patches.size() != F)
    throw Invalid_input(where + std::to_string(patches.size()) + " patches for " +
                        std::to_string(F) + " faces");
  std::vector<std::array<int, 3>> local(F);
  for (std::size_t f = 0; f < F; ++f) {
    const auto& t = domain.face(static_cast<std::uint32_t>(f));
    for (std::size_t c = 0; c < 3; ++c) {
      local[f][c] = local_vertex(patches[f], domain.point(t[c]));
      if (local[f][c] < 0)
        throw Invalid_input(where + "the patch of face " + std::to_string(f) +
                            " is not over that face (domain vertex " + std::to_string(t[c]) + " " +
                            point_to_string(domain.point(t[c])) + " is not one of its corners)");
    }
    if (patches[f].degree() != patches.front().degree())
      throw Invalid_input(where + "patch " + std::to_string(f) + " has degree " +
                          std::to_string(patches[f].degree()) + ", patch 0 has degree " +
                          std::to_string(patches.front().degree()));
  }
  return local;
}

// Local index in face f's patch of domain vertex v (which is a corner of f).
template <class GeomTraits>
int corner_in_patch(const Planar_domain<GeomTraits>& domain,
                    const std::vector<std::array<int, 3>>& local, std::uint32_t f,
                    std::uint32_t v) {
  const auto& t = domain.face(f);
  for (std::size_t c = 0; c < 3; ++c)
    if (t[c] == v)
      return local[f][c];
  CGAL_error_msg("vertex is not a corner of the face");
  return -1;
}

// Buffers of project_vertex(), reused from vertex to vertex (no allocation per vertex once
// they have grown).
template <class FT, class Value>
struct Vertex_workspace {
  std::vector<std::uint32_t> faces;
  std::vector<int> corner;
  std::vector<std::pair<std::size_t, FT>> entries; // the rows of C, one after the other
  std::vector<std::size_t> row_begin;              // row r is entries[row_begin[r], [r+1])
  std::vector<std::pair<std::array<int, 2>, FT>> terms;
  std::vector<Value> residual;
};

/*
  The corner regions around vertex v (the control points with at least n - 2k copies of v,
  in each incident patch) must meet the C^k conditions of the edges around v that involve
  only them: for edge (v, w), order l <= k and i <= 2k - l copies of w. If they do not, they
  are replaced by their orthogonal projection onto the subspace where they do (least change
  in the Euclidean norm of the control values): x' = x - C^T z with (C C^T) z = C x. The
  projection is the identity on points that already meet the conditions (in particular on
  any C^k network and on data from one polynomial), and these conditions read no point
  outside the corner regions.
*/
template <class GeomTraits, class Value>
void project_vertex(const Planar_domain<GeomTraits>& domain,
                    std::vector<Bezier_triangle<GeomTraits, Value>>& patches,
                    const std::vector<std::array<int, 3>>& local, std::uint32_t v, int k,
                    double tolerance, Vertex_workspace<typename GeomTraits::FT, Value>& work,
                    Network_adjustment& report) {
  using FT = typename GeomTraits::FT;
  using Index = std::uint32_t;
  constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  const int n = patches.front().degree();
  const int R = 2 * k;
  const auto [face_begin, face_end] = domain.star_faces(v);
  std::vector<Index>& faces = work.faces;
  faces.assign(face_begin, face_end);
  const std::size_t D = std::size_t(R + 1) * std::size_t(R + 2) / 2;
  const std::size_t N = faces.size() * D;
  auto slot_of = [&](Index f) {
    return static_cast<std::size_t>(std::find(faces.begin(), faces.end(), f) - faces.begin());
  };
  // Column of the point `index` of the patch of faces[slot] (its v count >= n - R).
  std::vector<int>& corner = work.corner;
  corner.resize(faces.size());
  for (std::size_t s = 0; s < faces.size(); ++s)
    corner[s] = corner_in_patch(domain, local, faces[s], v);
  auto column = [&](std::size_t slot, const Multi_index& index) {
    const int c = corner[slot];
    const int rho = n - index[c];
    const int a = index[(c + 1) % 3];
    return slot * D + std::size_t(rho * (rho + 1) / 2 + a);
  };
  auto index_of = [&](std::size_t col) {
    const std::size_t slot = col / D;
    std::size_t pos = col % D;
    int rho = 0;
    while (std::size_t((rho + 1) * (rho + 2) / 2) <= pos)
      ++rho;
    const int a = static_cast<int>(pos) - rho * (rho + 1) / 2;
    const int c = corner[slot];
    Multi_index index;
    index[c] = n - rho;
    index[(c + 1) % 3] = a;
    index[(c + 2) % 3] = rho - a;
    return std::make_pair(slot, index);
  };

  // The conditions, in the Extension form of check_join(): B(q^l w^i v^j) equals A's
  // polynomial at the same arguments, q = wq[p] p + wq[w] w + wq[v] v in A's frame. Their
  // residuals are accumulated as the rows are built.
  work.entries.clear();
  work.row_begin.assign(1, 0);
  work.residual.clear();
  double scale = 1, largest = 0;
  bool satisfied = true;
  const auto [edge_begin, edge_end] = domain.star_edges(v);
  for (const Index* e = edge_begin; e != edge_end; ++e) {
    if (domain.is_boundary_edge(*e))
      continue;
    const auto& ef = domain.edge_faces(*e);
    const Index w = domain.edge(*e)[0] == v ? domain.edge(*e)[1] : domain.edge(*e)[0];
    const std::size_t sa = slot_of(ef[0]), sb = slot_of(ef[1]);
    const Bezier_triangle<GeomTraits, Value>& A = patches[ef[0]];
    const Bezier_triangle<GeomTraits, Value>& B = patches[ef[1]];
    const int av = corner[sa], aw = corner_in_patch(domain, local, ef[0], w), ap = 3 - av - aw;
    const int bv = corner[sb], bw = corner_in_patch(domain, local, ef[1], w), bq = 3 - bv - bw;
    const std::array<FT, 3> wq = A.barycentric_coordinates(B.vertex(bq));
    for (int l = 0; l <= k; ++l) {
      // The coefficients of A(p^a w^(i+b) v^(j+c)) in A's value at (q^l w^i v^j), the same
      // for every i.
      work.terms.clear();
      for (const Expansion_term<FT>& t : expansion(wq, {{ap, aw, av}}, l))
        work.terms.push_back({{{t.a, t.b}}, -t.coefficient});
      for (int i = 0; i <= R - l; ++i) {
        const int j = n - l - i;
        Multi_index at_b;
        at_b[bq] = l;
        at_b[bw] = i;
        at_b[bv] = j;
        const Value& b_point = B.control_points()[linear_index(at_b)];
        scale = (std::max)(scale, max_abs_coordinate(b_point));
        Value residual = b_point;
        work.entries.emplace_back(column(sb, at_b), FT(1));
        for (const auto& [ab, coefficient] : work.terms) {
          Multi_index at_a;
          at_a[ap] = ab[0];
          at_a[aw] = i + ab[1];
          at_a[av] = j + (l - ab[0] - ab[1]);
          const Value& a_point = A.control_points()[linear_index(at_a)];
          scale = (std::max)(scale, max_abs_coordinate(a_point));
          residual = residual + coefficient * a_point;
          work.entries.emplace_back(column(sa, at_a), coefficient);
        }
        work.row_begin.push_back(work.entries.size());
        largest = (std::max)(largest, max_abs_coordinate(residual));
        if (exact && !is_zero_value(residual))
          satisfied = false;
        work.residual.push_back(residual);
      }
    }
  }
  if (!exact)
    satisfied = largest <= tolerance * scale;
  const std::size_t m = work.residual.size();
  if (m == 0 || satisfied)
    return;

  // Dense C (m x N) and M = C C^T; then z = M^+ (C x), and x' = x - C^T z.
  auto row = [&](std::size_t r) {
    return std::make_pair(work.entries.begin() + std::ptrdiff_t(work.row_begin[r]),
                          work.entries.begin() + std::ptrdiff_t(work.row_begin[r + 1]));
  };
  std::vector<FT> dense(m * N, FT(0));
  for (std::size_t r = 0; r < m; ++r)
    for (auto [it, end] = row(r); it != end; ++it)
      dense[r * N + it->first] = dense[r * N + it->first] + it->second;
  std::vector<FT> normal(m * m, FT(0));
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t s = r; s < m; ++s) {
      FT sum(0);
      for (auto [it, end] = row(r); it != end; ++it)
        if (!CGAL::is_zero(dense[s * N + it->first]))
          sum = sum + it->second * dense[s * N + it->first];
      normal[r * m + s] = sum;
      normal[s * m + r] = sum;
    }
  std::vector<Value> z = work.residual;
  solve_consistent(std::move(normal), z, m, 1e-13);
  Vertex_adjustment adjustment;
  adjustment.vertex = v;
  adjustment.residual = largest;
  for (std::size_t col = 0; col < N; ++col) {
    Value correction = Value_traits<Value>::zero();
    for (std::size_t r = 0; r < m; ++r)
      if (!CGAL::is_zero(dense[r * N + col]))
        correction = correction + dense[r * N + col] * z[r];
    if (is_zero_value(correction))
      continue;
    const auto [slot, index] = index_of(col);
    const Value moved = patches[faces[slot]].control_point(index) - correction;
    patches[faces[slot]].set_control_point(index, moved);
    adjustment.touched.push_back({faces[slot], index});
  }
  if (!adjustment.touched.empty())
    report.vertices.push_back(std::move(adjustment));
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_CONTINUITY_ADJUSTMENT_H

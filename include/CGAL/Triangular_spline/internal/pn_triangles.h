// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_PN_TRIANGLES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_PN_TRIANGLES_H

// The construction behind pn_triangles() (Comparators/PN_triangles.h).

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The PN control point of the edge p -> q next to p: (2p + q)/3 projected along n onto the
// tangent plane at p. Dividing by n.n makes it depend only on the direction of n, so that
// exact (rational, not unit) normals give exact points. Both faces of an edge call this
// with the same arguments, so their boundary points are equal even in double.
template <class K>
typename K::Vector_3 pn_edge_point(const typename K::Vector_3& p, const typename K::Vector_3& q,
                                   const typename K::Vector_3& n) {
  using FT = typename K::FT;
  const typename K::Vector_3 d = q - p;
  const FT w = (d * n) / (n * n);
  return (FT(2) * p + q - w * n) / FT(3);
}

// The area-weighted vertex normals (the sum of the faces' cross products, whose lengths are
// twice the areas), normalised in double and converted, one per vertex index.
template <class K>
std::vector<typename K::Vector_3>
pn_default_normals(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  using Vector_3 = typename K::Vector_3;
  std::vector<std::array<double, 3>> sum(mesh.number_of_vertices(), {{0, 0, 0}});
  std::vector<bool> used(mesh.number_of_vertices(), false);
  for (auto f : mesh.faces()) {
    std::vector<typename K::Point_3> p;
    std::vector<std::size_t> v;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
      p.push_back(mesh.point(x));
      v.push_back(static_cast<std::size_t>(x.idx()));
    }
    const Vector_3 c = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const std::array<double, 3> cd{
        {CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z())}};
    for (std::size_t i : v) {
      used[i] = true;
      for (std::size_t k = 0; k < 3; ++k)
        sum[i][k] += cd[k];
    }
  }
  std::vector<Vector_3> normals;
  normals.reserve(sum.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    if (!used[i]) { // an isolated vertex: no patch uses its normal
      normals.emplace_back(0, 0, 1);
      continue;
    }
    const std::array<double, 3>& s = sum[i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(length > 0) || !std::isfinite(length))
      throw Invalid_input("PN triangles: the faces around vertex " + std::to_string(i) +
                          " have a zero (or non-finite) area-weighted normal");
    normals.emplace_back(s[0] / length, s[1] / length, s[2] / length);
  }
  return normals;
}

template <class K>
std::vector<Bezier_triangle<K, typename K::Vector_3>>
pn_triangles_impl(const CGAL::Surface_mesh<typename K::Point_3>& mesh,
                  const std::vector<typename K::Vector_3>& normals) {
  using FT = typename K::FT;
  using Vector_3 = typename K::Vector_3;
  using Point_2 = typename K::Point_2;
  std::vector<Bezier_triangle<K, Vector_3>> patches;
  patches.reserve(mesh.number_of_faces());
  const Point_2 r(0, 0), s(1, 0), t(0, 1);
  for (auto f : mesh.faces()) {
    std::vector<Vector_3> P, N;
    for (auto x : vertices_around_face(halfedge(f, mesh), mesh)) {
      P.push_back(mesh.point(x) - CGAL::ORIGIN);
      N.push_back(normals[static_cast<std::size_t>(x.idx())]);
    }
    if (P.size() != 3)
      throw Invalid_input("PN triangles: face " + std::to_string(f.idx()) + " has " +
                          std::to_string(P.size()) + " vertices, not 3");
    // b_ijk, i/j/k counting P[0]/P[1]/P[2] (Vlachos et al. 2001, with b_300 = P_1 ...)
    std::vector<Vector_3> net(number_of_control_points(3));
    auto b = [&net](int i, int j, int k) -> Vector_3& {
      return net[linear_index(i, j, i + j + k)];
    };
    b(3, 0, 0) = P[0];
    b(0, 3, 0) = P[1];
    b(0, 0, 3) = P[2];
    b(2, 1, 0) = pn_edge_point<K>(P[0], P[1], N[0]);
    b(1, 2, 0) = pn_edge_point<K>(P[1], P[0], N[1]);
    b(0, 2, 1) = pn_edge_point<K>(P[1], P[2], N[1]);
    b(0, 1, 2) = pn_edge_point<K>(P[2], P[1], N[2]);
    b(1, 0, 2) = pn_edge_point<K>(P[2], P[0], N[2]);
    b(2, 0, 1) = pn_edge_point<K>(P[0], P[2], N[0]);
    // b_111 = E + (E - V)/2: the average E of the six edge points pushed away from the
    // vertex centroid V, which reproduces quadratics (Vlachos et al., §3.1)
    const Vector_3 E =
        (b(2, 1, 0) + b(1, 2, 0) + b(0, 2, 1) + b(0, 1, 2) + b(1, 0, 2) + b(2, 0, 1)) / FT(6);
    const Vector_3 V = (P[0] + P[1] + P[2]) / FT(3);
    b(1, 1, 1) = E + (E - V) / FT(2);
    patches.emplace_back(3, r, s, t, std::move(net));
  }
  return patches;
}

template <class K>
void pn_check_mesh(const CGAL::Surface_mesh<typename K::Point_3>& mesh) {
  if (mesh.has_garbage())
    throw Invalid_input("PN triangles: the mesh has removed elements (collect the garbage)");
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_PN_TRIANGLES_H

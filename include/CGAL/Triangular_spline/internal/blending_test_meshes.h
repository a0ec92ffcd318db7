// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_TEST_MESHES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_TEST_MESHES_H

// The generators behind blending_test_mesh_data() (Blending/test_meshes.h); also used by
// Xu/thesis_polyhedra.h and the benchmarks.

#include <CGAL/Triangular_spline/Blending/Blending_mesh_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

inline std::array<double, 3> normalized3(const std::array<double, 3>& p, double length = 1) {
  const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {{p[0] / l * length, p[1] / l * length, p[2] / l * length}};
}

// Faces of a convex polyhedron whose edges all have squared length `edge2` (up to a
// tolerance): all vertex triples pairwise at that distance, oriented outwards.
inline std::vector<std::vector<std::size_t>>
equilateral_triangles(const std::vector<std::array<double, 3>>& p, double edge2) {
  auto d2 = [&p](std::size_t a, std::size_t b) {
    double s = 0;
    for (std::size_t c = 0; c < 3; ++c)
      s += (p[a][c] - p[b][c]) * (p[a][c] - p[b][c]);
    return s;
  };
  auto close = [edge2](double x) { return std::fabs(x - edge2) < 1e-6 * edge2; };
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = a + 1; b < p.size(); ++b)
      for (std::size_t c = b + 1; c < p.size(); ++c)
        if (close(d2(a, b)) && close(d2(b, c)) && close(d2(a, c))) {
          std::array<double, 3> u, v, centroid;
          for (std::size_t k = 0; k < 3; ++k) {
            u[k] = p[b][k] - p[a][k];
            v[k] = p[c][k] - p[a][k];
            centroid[k] = p[a][k] + p[b][k] + p[c][k];
          }
          const std::array<double, 3> n{
              {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
          if (n[0] * centroid[0] + n[1] * centroid[1] + n[2] * centroid[2] > 0)
            faces.push_back({a, b, c});
          else
            faces.push_back({a, c, b});
        }
  return faces;
}

inline Blending_mesh_data icosahedron_data(double radius) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p;
  for (double s : {-1.0, 1.0})
    for (double t : {-1.0, 1.0}) {
      p.push_back({{0, s, t * phi}});
      p.push_back({{s, t * phi, 0}});
      p.push_back({{t * phi, 0, s}});
    }
  Blending_mesh_data m;
  m.faces = equilateral_triangles(p, 4);
  for (const auto& q : p) {
    m.points.push_back(normalized3(q, radius));
    m.normals.push_back(normalized3(q));
  }
  return m;
}

// Each triangle into four, the new points pushed to the sphere of `radius`.
inline Blending_mesh_data subdivided_on_sphere(const Blending_mesh_data& in, double radius) {
  Blending_mesh_data m;
  m.points = in.points;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
  auto middle = [&](std::size_t a, std::size_t b) {
    const std::pair<std::size_t, std::size_t> key{(std::min)(a, b), (std::max)(a, b)};
    auto it = midpoint.find(key);
    if (it != midpoint.end())
      return it->second;
    std::array<double, 3> q;
    for (std::size_t c = 0; c < 3; ++c)
      q[c] = (m.points[a][c] + m.points[b][c]) / 2;
    m.points.push_back(normalized3(q, radius));
    midpoint[key] = m.points.size() - 1;
    return m.points.size() - 1;
  };
  for (const auto& f : in.faces) {
    const std::size_t a = f[0], b = f[1], c = f[2];
    const std::size_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    m.faces.push_back({a, ab, ca});
    m.faces.push_back({b, bc, ab});
    m.faces.push_back({c, ca, bc});
    m.faces.push_back({ab, bc, ca});
  }
  for (auto& q : m.points) {
    q = normalized3(q, radius);
    m.normals.push_back(normalized3(q));
  }
  return m;
}

inline std::array<double, 3> torus_point(double R, double r, double u, double v) {
  return {
      {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)}};
}

inline Blending_mesh_data torus_data(double R, double r, std::size_t nu, std::size_t nv,
                                     bool triangles) {
  Blending_mesh_data m;
  const double pi = 3.14159265358979323846;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * double(i) / double(nu), v = 2 * pi * double(j) / double(nv);
      m.points.push_back(torus_point(R, r, u, v));
      m.normals.push_back({{std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)}});
    }
  auto id = [nu, nv](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, c, d});
      }
    }
  return m;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_BLENDING_TEST_MESHES_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_TESSELLATION_GRID_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_TESSELLATION_GRID_H

// The grid of tessellate(): its numbering, its triangles, and the value and derivatives of a
// patch at each grid point from one de Casteljau pyramid.

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/internal/de_casteljau.h>
#include <CGAL/Triangular_spline/internal/values_as_3d.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class Point>
struct Surface_mesh_point {
  static_assert(sizeof(Point) == 0, "tessellate() writes into a CGAL::Surface_mesh");
};
template <class Point>
struct Surface_mesh_point<CGAL::Surface_mesh<Point>> {
  using type = Point;
};

// Index of grid point (i, j, n-i-j) of a triangle cut into n^2: rows of n+1-i points.
inline std::size_t grid_index(std::size_t i, std::size_t j, std::size_t n) {
  return i * (n + 1) - i * (i - 1) / 2 + j;
}

// The value and the first and second partial derivatives of a patch at one point, from a
// single de Casteljau pyramid: the m-2 steps towards the point are shared, and the last two
// levels are taken towards the point or the directions x, y (D_u F = m f(u, a^{m-1}),
// D_u D_v F = m(m-1) f(u, v, a^{m-2})). Rational, so exact with an exact FT; about five
// times cheaper than one evaluation plus five partial_derivative() calls.
template <class GeomTraits, class Value>
struct Patch_jet {
  using FT = typename GeomTraits::FT;
  using Weights = std::array<FT, 3>;

  explicit Patch_jet(const Bezier_triangle<GeomTraits, Value>& patch)
      : m_patch(patch), m_degree(patch.degree()),
        m_x(patch.barycentric_direction(typename GeomTraits::Vector_2(FT(1), FT(0)))),
        m_y(patch.barycentric_direction(typename GeomTraits::Vector_2(FT(0), FT(1)))) {}

  // `w`: barycentric coordinates w.r.t. the patch's vertices
  void compute(const Weights& w, Value& value, Surface_derivatives& d) const {
    constexpr bool graph = Value_traits<Value>::dimension == 1;
    const Value zero = Value_traits<Value>::zero();
    Scratch_net<Value> net(m_patch.control_points().begin(), m_patch.control_points().end());
    const int m = m_degree;
    for (int l = m; l > 2; --l)
      de_casteljau_step(net, l, w);
    Value fx = zero, fy = zero, fxx = zero, fxy = zero, fyy = zero;
    if (m == 0) {
      value = net[0];
    } else {
      const int top = (std::min)(m, 2);
      Scratch_net<Value> at_w = net;
      if (top == 2)
        de_casteljau_step(at_w, 2, w);
      const FT first(m);
      value = linear(at_w, w);
      fx = first * linear(at_w, m_x);
      fy = first * linear(at_w, m_y);
      if (top == 2) {
        const FT second(m * (m - 1));
        Scratch_net<Value> at_x = net, at_y = net;
        de_casteljau_step(at_x, 2, m_x);
        de_casteljau_step(at_y, 2, m_y);
        fxx = second * linear(at_x, m_x);
        fxy = second * linear(at_x, m_y);
        fyy = second * linear(at_y, m_y);
      }
    }
    d.fx = as_3d(fx, graph, 1, 0);
    d.fy = as_3d(fy, graph, 0, 1);
    d.fxx = as_3d(fxx, graph, 0, 0);
    d.fxy = as_3d(fxy, graph, 0, 0);
    d.fyy = as_3d(fyy, graph, 0, 0);
  }

private:
  // the value of a linear net (b_100, b_010, b_001 in Table 2.3 order) at `v`
  static Value linear(const Scratch_net<Value>& net, const Weights& v) {
    Value result = v[0] * net[linear_index(1, 0, 1)] + v[1] * net[linear_index(0, 1, 1)] +
                   v[2] * net[linear_index(0, 0, 1)];
    return result;
  }

  const Bezier_triangle<GeomTraits, Value>& m_patch;
  int m_degree;
  Weights m_x, m_y;
};

template <class Mesh, class Vertex_index>
void add_grid_face(Mesh& mesh, Vertex_index a, Vertex_index b, Vertex_index c) {
  // Cannot fail on a validated domain: a null face would be a bug in the numbering.
  if (mesh.add_face(a, b, c) == Mesh::null_face())
    CGAL_error_msg("tessellate: Surface_mesh rejected a grid triangle");
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_TESSELLATION_GRID_H

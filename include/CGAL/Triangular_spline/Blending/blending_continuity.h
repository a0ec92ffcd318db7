// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_CONTINUITY_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_CONTINUITY_H

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/blending_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief measured continuity and interpolation of a `Mesh_blending_surface`.

  Derivatives are those of the surface (in space, mesh units) with respect to the
  coordinates of the stated frame, computed exactly up to round-off with jets. A jump of
  order \f$k\f$ is the largest Euclidean norm of the difference of two partial derivatives
  \f$\partial_x^a \partial_y^b\f$, \f$a + b = k\f$.
*/
struct Blending_continuity {
  int order = 0;          ///< the blending order \f$d\f$
  int measured_order = 0; ///< derivatives measured up to this order: \f$\min(d, 6)\f$
  /// [k]: across interior edges, in the edge frame \f$\mathcal{F}^E\f$: the two faces'
  /// surfaces reparameterized by \f$r^{E,F} = (r^{F,E})^{-1}\f$ (Thm.\ 5.1)
  std::vector<double> max_edge_jump;
  /// [k]: at the vertices, in the vertex frame \f$\mathcal{F}^V\f$: each incident face's
  /// surface composed with \f$A_{F,V}^{-1}\f$ (`face_to_vertex_frame()`) against the vertex
  /// surface \f$S^V\f$ — the face's corner jet (two-zero limit) and its one-sided limits
  /// along both sides (the sub-surfaces there) all count (Thms.\ 6.1, 6.2)
  std::vector<double> max_vertex_jump;
  /// [k]: each face's surface on an edge against the edge surface \f$S^E\f$ (inheritance)
  std::vector<double> max_edge_inheritance_error;
  double max_normal_angle_jump_deg = 0; ///< angle between the two faces' normals on edges
  double max_position_error = 0;        ///< \f$\max |S^F(V) - V|\f$ at the corners
  double max_normal_error_deg = 0;      ///< angle between \f$S^F\f$'s normal at V and V's normal
  std::size_t interior_edges = 0;       ///< edges measured (two incident faces)
  std::size_t edge_samples = 0;         ///< points per edge
  std::size_t corners = 0;              ///< face corners measured
  double size = 0;                      ///< bounding-box diagonal of the input mesh
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the Gaussian curvature of a `Mesh_blending_surface` on a parameter grid, and its
  behaviour towards the vertices.
*/
struct Blending_curvature {
  double min_gaussian = 0;  ///< smallest Gaussian curvature on the grid
  double max_gaussian = 0;  ///< largest
  std::size_t samples = 0;  ///< grid points
  std::size_t singular = 0; ///< grid points without a normal
  /// the largest \f$|K(p_\delta) - K(V)|\f$ over the face corners, \f$p_\delta\f$ the
  /// point at parameter distance \f$\delta\f$ from corner V towards the face centre and
  /// \f$K(V)\f$ the curvature of the vertex surface: the curvature "gap" towards the
  /// vertices of Fang §8.1, for \f$\delta\f$ = 1e-2 and 1e-3
  std::array<double, 2> vertex_gap{{0, 0}};
  /// the same divided by \f$\max(|K(V)|, 1/\mathrm{size}^2)\f$
  std::array<double, 2> relative_vertex_gap{{0, 0}};
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief measures the continuity of `surface` across its edges and at its vertices, and its
  interpolation of the vertices and normals (Fang §5.3, Thms. 5.1, 6.1–6.3).

  - Edges: at `samples_per_edge` points \f$(0, t)\f$ of each interior edge's frame, the
    jets of order \f$\le\f$ `measured_order` of both faces' surfaces
    \f$S^F \circ (r^{F,E})^{-1}\f$ (the inverse map's jet is computed by
    `inverse_map_jet()`) are compared with each other (`max_edge_jump`) and with
    \f$S^E\f$ (`max_edge_inheritance_error`), and their normals (angle).
  - Vertices: at each face corner, the jets at the vertex of \f$S^F \circ A_{F,V}^{-1}\f$
    and of the two sub-surfaces there \f$S^{E}_F \circ A_{F,V}^{-1}\f$ are compared with the
    vertex surface \f$S^V\f$ (`max_vertex_jump`), the value with the vertex and the normal
    with the vertex normal. For the improved variants the face maps
    \f$r^{F,E,V} = r^{E,V} \circ r^{F,E}\f$ reproduce \f$A_{F,V}\f$ to order \f$d\f$, so all
    agree; for the basic variant only the values (order 0) and the normals do.

  Jumps at round-off level mean \f$C^d\f$ continuity in those frames.
  \tparam Point_3 a CGAL 3D point type (e.g. `Kernel::Point_3`)
  \throws Invalid_input if `samples_per_edge` < 1
  \param surface the blended surface
  \param samples_per_edge the number of sample points on each interior edge
  \returns the measured gaps and interpolation errors
*/
template <class Point_3>
Blending_continuity measure_blending_continuity(const Mesh_blending_surface<Point_3>& surface,
                                                int samples_per_edge = 5) {
  using Surface = Mesh_blending_surface<Point_3>;
  using Jet = typename Surface::Jet;
  if (samples_per_edge < 1)
    throw Invalid_input("measure_blending_continuity: need at least one sample per edge");
  Blending_continuity r;
  r.order = surface.order();
  r.measured_order = (std::min)(surface.order(), Jet::max_order);
  const int K = r.measured_order;
  const int jet_order = (std::max)(K, 1); // normals need first derivatives
  r.max_edge_jump.assign(static_cast<std::size_t>(K + 1), 0.0);
  r.max_vertex_jump.assign(static_cast<std::size_t>(K + 1), 0.0);
  r.max_edge_inheritance_error.assign(static_cast<std::size_t>(K + 1), 0.0);
  r.edge_samples = static_cast<std::size_t>(samples_per_edge);
  r.size = internal::mesh_size(surface);

  // --- edges ---
  for (std::size_t e = 0; e < surface.number_of_edges(); ++e) {
    const std::vector<std::pair<std::size_t, std::size_t>> sides = surface.edge_sides(e);
    if (sides.size() == 2)
      ++r.interior_edges;
    for (int k = 1; k <= samples_per_edge; ++k) {
      const double t = double(k) / double(samples_per_edge + 1);
      const std::array<Jet, 3> inherited =
          surface.edge_surface(e, Jet::variable(0, 0, jet_order), Jet::variable(t, 1, jet_order));
      std::vector<std::array<Jet, 3>> jets;
      for (const auto& [f, s] : sides) {
        const std::array<double, 2> p = surface.side_point(f, s, t);
        const std::array<Jet, 2> map = surface.face_to_edge(f, s, Jet::variable(p[0], 0, jet_order),
                                                            Jet::variable(p[1], 1, jet_order));
        const std::array<Jet, 2> inverse = inverse_map_jet(map[0], map[1]);
        const Jet a = inverse[0] + p[0], b = inverse[1] + p[1];
        jets.push_back(surface.face_surface(f, a, b));
        for (int o = 0; o <= K; ++o)
          r.max_edge_inheritance_error[static_cast<std::size_t>(o)] =
              (std::max)(r.max_edge_inheritance_error[static_cast<std::size_t>(o)],
                         internal::jet_jump(jets.back(), inherited, o));
      }
      if (jets.size() == 2) {
        for (int o = 0; o <= K; ++o)
          r.max_edge_jump[static_cast<std::size_t>(o)] =
              (std::max)(r.max_edge_jump[static_cast<std::size_t>(o)],
                         internal::jet_jump(jets[0], jets[1], o));
        r.max_normal_angle_jump_deg = (std::max)(
            r.max_normal_angle_jump_deg,
            internal::angle_deg(internal::jet_normal(jets[0]), internal::jet_normal(jets[1])));
      }
    }
  }

  // --- vertices (face corners) ---
  for (std::size_t f = 0; f < surface.number_of_faces(); ++f)
    for (std::size_t c = 0; c < surface.face_size(f); ++c) {
      ++r.corners;
      const std::size_t v = surface.face_vertex(f, c);
      internal::Affine_2 A;
      A.m = surface.face_to_vertex_frame(f, c);
      const internal::Affine_2 to_face = A.inverse();
      const Jet X = Jet::variable(0, 0, jet_order), Y = Jet::variable(0, 1, jet_order);
      std::array<Jet, 2> ab = to_face(X, Y);
      // the corner exactly (the inverse map is exact there only up to round-off)
      ab[0].set_coefficient(0, 0, surface.corner_parameter(f, c)[0]);
      ab[1].set_coefficient(0, 0, surface.corner_parameter(f, c)[1]);
      const std::array<Jet, 3> target = surface.vertex_surface(v, X, Y);
      std::vector<std::array<Jet, 3>> jets{surface.face_surface(f, ab[0], ab[1])};
      for (std::size_t s : internal::sides_at_corner(surface, f, c))
        jets.push_back(surface.side_surface(f, s, ab[0], ab[1]));
      for (const std::array<Jet, 3>& j : jets)
        for (int o = 0; o <= K; ++o)
          r.max_vertex_jump[static_cast<std::size_t>(o)] = (std::max)(
              r.max_vertex_jump[static_cast<std::size_t>(o)], internal::jet_jump(j, target, o));
      const std::array<double, 3>& P = surface.vertex_position(v);
      const std::array<Jet, 3>& full = jets.front();
      r.max_position_error = (std::max)(
          r.max_position_error, std::sqrt((full[0].value() - P[0]) * (full[0].value() - P[0]) +
                                          (full[1].value() - P[1]) * (full[1].value() - P[1]) +
                                          (full[2].value() - P[2]) * (full[2].value() - P[2])));
      r.max_normal_error_deg =
          (std::max)(r.max_normal_error_deg,
                     internal::angle_deg(internal::jet_normal(full), surface.vertex_normal(v)));
    }
  return r;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief samples the Gaussian curvature of `surface` on the parameter grid of
  `Mesh_blending_surface::tessellate()` with `resolution` segments per edge (without
  building the mesh), and measures the curvature gap towards the vertices (see
  `Blending_curvature`).
  \tparam Point_3 a CGAL 3D point type (e.g. `Kernel::Point_3`)
  \throws Invalid_input if `resolution` < 1
  \param surface the blended surface
  \param resolution the number of segments per edge
  \returns the curvature samples and the gap towards the vertices
*/
template <class Point_3>
Blending_curvature measure_blending_curvature(const Mesh_blending_surface<Point_3>& surface,
                                              int resolution = 8) {
  using Surface = Mesh_blending_surface<Point_3>;
  if (resolution < 1)
    throw Invalid_input("measure_blending_curvature: the resolution must be positive");
  Blending_curvature r;
  r.min_gaussian = std::numeric_limits<double>::infinity();
  r.max_gaussian = -std::numeric_limits<double>::infinity();
  auto record = [&r](double K, bool regular) {
    ++r.samples;
    if (!regular || !std::isfinite(K)) {
      ++r.singular;
      return;
    }
    r.min_gaussian = (std::min)(r.min_gaussian, K);
    r.max_gaussian = (std::max)(r.max_gaussian, K);
  };
  const int N = resolution;
  for (std::size_t f = 0; f < surface.number_of_faces(); ++f) {
    const std::size_t n = surface.face_size(f);
    const std::size_t pieces = n == 3 ? 1 : n;
    for (std::size_t piece = 0; piece < pieces; ++piece)
      for (int i = 0; i <= N; ++i)
        for (int j = 0; i + j <= N; ++j) {
          const int k = N - i - j;
          std::array<double, 2> p;
          if (n == 3) {
            if ((i == N) || (j == N) || (k == N))
              continue; // corners: the vertex surfaces, below
            p = {{double(i) / N, double(j) / N}};
          } else {
            if (j == N || k == N)
              continue;
            const std::array<double, 2>& q0 = surface.corner_parameter(f, piece);
            const std::array<double, 2>& q1 = surface.corner_parameter(f, (piece + 1) % n);
            p = {{(q0[0] * j + q1[0] * k) / N, (q0[1] * j + q1[1] * k) / N}};
          }
          const Surface_curvature c = surface_curvature(surface.derivatives(f, p[0], p[1]));
          record(c.gaussian, c.regular);
        }
  }
  std::vector<double> vertex_K(surface.number_of_vertices());
  for (std::size_t v = 0; v < surface.number_of_vertices(); ++v) {
    using Small = typename Surface::Curvature_jet;
    const Surface_curvature c = surface_curvature(Surface::to_derivatives(
        surface.vertex_surface(v, Small::variable(0, 0, 2), Small::variable(0, 1, 2))));
    vertex_K[v] = c.gaussian;
    record(c.gaussian, c.regular);
  }
  const double size = internal::mesh_size(surface);
  const std::array<double, 2> deltas{{1e-2, 1e-3}};
  for (std::size_t f = 0; f < surface.number_of_faces(); ++f) {
    const std::size_t n = surface.face_size(f);
    for (std::size_t c = 0; c < n; ++c) {
      const double KV = vertex_K[surface.face_vertex(f, c)];
      if (!std::isfinite(KV))
        continue;
      for (std::size_t m = 0; m < 2; ++m) {
        const double delta = deltas[m];
        std::array<double, 2> p;
        const std::array<double, 2>& q = surface.corner_parameter(f, c);
        if (n == 3) {
          // towards the centre: lambda_c = 1 - delta, the others delta / 2
          std::array<double, 3> l{{delta / 2, delta / 2, delta / 2}};
          l[c] = 1 - delta;
          p = {{l[0], l[1]}};
        } else {
          p = {{q[0] * (1 - delta), q[1] * (1 - delta)}}; // the centre is the origin
        }
        const Surface_curvature k = surface_curvature(surface.derivatives(f, p[0], p[1]));
        if (!k.regular || !std::isfinite(k.gaussian))
          continue;
        const double gap = std::fabs(k.gaussian - KV);
        r.vertex_gap[m] = (std::max)(r.vertex_gap[m], gap);
        r.relative_vertex_gap[m] = (std::max)(r.relative_vertex_gap[m],
                                              gap / (std::max)(std::fabs(KV), 1 / (size * size)));
      }
    }
  }
  return r;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_CONTINUITY_H

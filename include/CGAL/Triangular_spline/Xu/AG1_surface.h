// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_AG1_SURFACE_H
#define CGAL_TRIANGULAR_SPLINE_XU_AG1_SURFACE_H

#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Xu/AG1_system.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief builds the \f$AG^1\f$ surface that a solution of the global system of Xu §6.1 defines
  (the `ag1_global` construction of AG1.md §5.2): every edge's five diamonds on the walk's
  relation, so tangent planes agree along whole edges wherever the surface is regular.

  Per vertex, the corner point \f$z\f$ and a linear map \f$A\f$ are fitted in the least-squares
  sense so that \f$z + A u_i\f$ approaches the first-approximation stars \f$(4v + w_i)/5\f$
  (\f$u_i\f$ the walk's umbrella); the stars become \f$z + A u_i\f$ (at a vertex of valence 3
  the fit interpolates: the thesis's "once the \f$z_i\f$ are fixed"). Corner-inner and flip points
  start at their first approximations \f$(3a + b + c)/5\f$ and \f$(a + 2b + 2c)/5\f$; edge-middle
  points and flips follow from the middle diamonds with the walk's relations (the flips by the
  least change of both). Every step is rational: with an exact number type the surface is exact.

  The thesis shows that on the tetrahedron such surfaces exist but fold (AG1.md C13, C14):
  edges with \f$\lambda \ge 0\f$ admit no reparameterization with the apexes on opposite sides,
  and the normals reverse across them.
  \tparam Kernel the kernel (its `FT` is the walk's)
  \param mesh the closed, outward mesh the walk was solved on
  \param walk a complete walk of `walk_AG1_system()` with a relation on every edge
  \returns the surface: the mesh and one quintic net per face (`vertices_around_face` order)
  \throws Invalid_input if the walk is incomplete, a relation has \f$\mu = 0\f$ or \f$\nu = 0\f$,
  or the umbrella of a vertex is degenerate (the fit has no unique solution)
*/
template <class Kernel>
Surface_file<Kernel> ag1_surface_from_walk(const CGAL::Surface_mesh<typename Kernel::Point_3>& mesh,
                                           const AG1_walk<typename Kernel::FT>& walk) {
  using FT = typename Kernel::FT;
  using Vector_3 = typename Kernel::Vector_3;
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  if (walk.umbrellas.size() != mesh.number_of_vertices() ||
      walk.relations.size() != mesh.number_of_edges())
    throw Invalid_input("AG1 surface: the walk does not belong to this mesh");
  for (auto e : mesh.edges())
    if (!walk.has_relation[e])
      throw Invalid_input("AG1 surface: edge " + std::to_string(std::size_t(e)) +
                          " has no relation (the walk is incomplete)");
  auto position = [&](typename Mesh::Vertex_index v) { return mesh.point(v) - CGAL::ORIGIN; };
  std::vector<Vector_3> star(mesh.number_of_halfedges(), CGAL::NULL_VECTOR),
      corner(mesh.number_of_vertices(), CGAL::NULL_VECTOR);
  for (auto v : mesh.vertices()) {
    const auto ring = outgoing_ring(v, mesh);
    const auto& u = walk.umbrellas[v];
    if (u.size() != ring.size())
      throw Invalid_input("AG1 surface: vertex " + std::to_string(std::size_t(v)) +
                          " has no umbrella (the walk is incomplete)");
    // normal equations of min sum |z + A u_i - S_i|^2: rows (1, u_x, u_y), exactly in FT
    std::array<std::array<FT, 3>, 3> M{};
    std::array<Vector_3, 3> rhs{{CGAL::NULL_VECTOR, CGAL::NULL_VECTOR, CGAL::NULL_VECTOR}};
    for (auto& row : M)
      row = {{FT(0), FT(0), FT(0)}};
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::array<FT, 3> r{{FT(1), u[i][0], u[i][1]}};
      const Vector_3 S = (FT(4) * position(v) + position(mesh.target(ring[i]))) / FT(5);
      for (std::size_t a = 0; a < 3; ++a) {
        for (std::size_t b = 0; b < 3; ++b)
          M[a][b] += r[a] * r[b];
        rhs[a] = rhs[a] + r[a] * S;
      }
    }
    // Cramer's rule: the 3x3 system is small and exact
    auto det3 = [](const std::array<std::array<FT, 3>, 3>& m) -> FT {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const FT D = det3(M);
    if (D == FT(0))
      throw Invalid_input("AG1 surface: the umbrella of vertex " + std::to_string(std::size_t(v)) +
                          " is degenerate (its spokes are collinear)");
    std::array<Vector_3, 3> x; // z, A e_1, A e_2
    for (std::size_t k = 0; k < 3; ++k) {
      std::array<FT, 3> coordinate;
      for (int c = 0; c < 3; ++c) {
        auto Mk = M;
        for (std::size_t a = 0; a < 3; ++a)
          Mk[a][k] = rhs[a][c];
        coordinate[std::size_t(c)] = det3(Mk) / D;
      }
      x[k] = Vector_3(coordinate[0], coordinate[1], coordinate[2]);
    }
    corner[v] = x[0];
    for (std::size_t i = 0; i < ring.size(); ++i)
      star[ring[i]] = x[0] + u[i][0] * x[1] + u[i][1] * x[2];
  }
  std::vector<Vector_3> inner(mesh.number_of_halfedges(), CGAL::NULL_VECTOR),
      flip(mesh.number_of_halfedges(), CGAL::NULL_VECTOR),
      middle(mesh.number_of_halfedges(), CGAL::NULL_VECTOR);
  for (auto h : mesh.halfedges()) {
    const Vector_3 a = position(mesh.source(h)), b = position(mesh.target(h)),
                   c = position(mesh.target(mesh.next(h)));
    inner[h] = (FT(3) * a + b + c) / FT(5);
    flip[h] = (c + FT(2) * a + FT(2) * b) / FT(5);
  }
  for (auto e : mesh.edges()) {
    const auto& R = walk.relations[e];
    if (R.mu == FT(0) || R.nu == FT(0))
      throw Invalid_input("AG1 surface: edge " + std::to_string(std::size_t(e)) +
                          " has a degenerate relation (mu or nu is 0)");
    const auto h = canonical_halfedge(e, mesh), o = mesh.opposite(h);
    // D_3, D_1, D_2 of AG1.md §1.3, as in Pseudo_AG1_surface
    middle[h] = (inner[mesh.next(o)] - R.lambda * inner[h] - R.mu * star[h]) / R.nu;
    middle[o] = (inner[o] - R.lambda * inner[mesh.next(h)] - R.nu * star[o]) / R.mu;
    const Vector_3 c = R.mu * middle[h] + R.nu * middle[o];
    const Vector_3 d = c - (flip[o] - R.lambda * flip[h]);
    const FT w = FT(1) + R.lambda * R.lambda;
    flip[h] = flip[h] - (R.lambda / w) * d;
    flip[o] = flip[o] + d / w;
  }
  std::vector<std::vector<Vector_3>> nets(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    const auto h0 = mesh.halfedge(f);
    const std::array<typename Mesh::Halfedge_index, 3> from{
        {mesh.next(h0), mesh.next(mesh.next(h0)), h0}}; // from corner a to a + 1
    auto& net = nets[f];
    net.resize(number_of_control_points(5));
    for (const Multi_index& index : multi_indices(5)) {
      int nonzero = 0, big = 0;
      for (int a = 0; a < 3; ++a) {
        nonzero += index[a] > 0;
        if (index[a] > index[big])
          big = a;
      }
      Vector_3 value;
      if (nonzero == 1) {
        value = corner[mesh.source(from[std::size_t(big)])];
      } else if (nonzero == 2) {
        int x = 0;
        for (int a = 0; a < 3; ++a)
          if (index[a] > 0 && index[(a + 1) % 3] > 0)
            x = a;
        const auto xy = from[std::size_t(x)], yx = mesh.opposite(xy);
        value = index[x] == 4   ? star[xy]
                : index[x] == 3 ? middle[xy]
                : index[x] == 2 ? middle[yx]
                                : star[yx];
      } else if (index[big] == 3) {
        value = inner[from[std::size_t(big)]];
      } else {
        int one = 0;
        for (int a = 0; a < 3; ++a)
          if (index[a] == 1)
            one = a;
        value = flip[from[std::size_t((one + 1) % 3)]];
      }
      net[linear_index(index)] = value;
    }
  }
  return Surface_file<Kernel>(mesh, 5, std::move(nets),
                              CGAL::Algebraic_structure_traits<FT>::Is_exact::value);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_AG1_SURFACE_H

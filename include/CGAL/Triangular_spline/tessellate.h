// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_TESSELLATE_H
#define CGAL_TRIANGULAR_SPLINE_TESSELLATE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/tessellation_grid.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the size of a tessellation.
*/
struct Tessellation_statistics {
  std::size_t vertices = 0; ///< number of mesh vertices
  std::size_t faces = 0;    ///< number of mesh triangles
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief tessellates the surface of a spline (one Bézier patch per domain triangle) into a
  triangle mesh with per-vertex normals and curvatures.

  Each domain triangle is cut uniformly into \f$4^L\f$ triangles, \f$L\f$ = `levels`: the
  vertex grid of \f$L\f$ rounds of midpoint 4-split, i.e. the points with barycentric
  coordinates \f$(i/n, j/n, k/n)\f$, \f$i+j+k = n = 2^L\f$. These coordinates are exact
  (dyadic), and every grid point is evaluated directly by de Casteljau's algorithm in the
  patch, exactly when `FT` is exact; the result is rounded to `double` once.

  Grid points shared by several domain triangles become one mesh vertex: one per domain
  vertex, \f$n-1\f$ per domain edge, \f$(n-1)(n-2)/2\f$ per triangle interior, so the
  mesh has \f$V + E(n-1) + F(n-1)(n-2)/2\f$ vertices and \f$F n^2\f$ faces, is manifold,
  and its border is exactly the boundary of the domain (outer boundary and holes), with
  \f$n\f$ mesh edges per boundary edge. The vertices are numbered in this order: domain
  vertex `v` is mesh vertex `v`; the interior points of domain edge `e` follow, from
  `edge(e)[0]` to `edge(e)[1]`; then the triangle interiors, by face.

  The mesh point of a functional value \f$z\f$ at domain point \f$(x,y)\f$ is
  \f$(x, y, z)\f$; a parametric `Vector_3` value is the point itself. The faces are
  oriented like the domain triangles (counter-clockwise seen from above), so for a
  functional spline every face normal points up.

  Three vertex property maps are filled (and created if needed), with the formulas of
  `surface_curvature()`:
  - `"v:normal"` (`Kernel_traits<Point>::Kernel::Vector_3`): the unit normal
    \f$F_x \times F_y / \|F_x \times F_y\|\f$ from the exact first derivatives; zero
    where the surface is singular;
  - `"v:gaussian_curvature"` and `"v:mean_curvature"` (`double`), from the exact second
    derivatives; NaN where the surface is singular.

  The value and all five derivatives at a grid point come from one de Casteljau pyramid
  (the first \f$m-2\f$ steps are shared), exact in `FT` and converted to `double` at the
  end, like `surface_derivatives()`.

  A vertex on a domain edge or at a domain vertex takes these quantities from one of the
  incident patches. For a \f$C^1\f$ spline the normal is the same in every incident patch;
  the curvatures, which involve second derivatives, may differ across an edge. Only the
  normalisation (a square root) and the curvature formulas use `double`.

  `CGAL::Surface_mesh::clear()` is called first, so the mesh's previous content and user
  property maps are removed.

  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork` whose values are
  either `Geom_traits::FT` (functional) or `Geom_traits::Vector_3` (parametric)
  \tparam Mesh `CGAL::Surface_mesh<Point>` whose `Point` is a 3D point of a CGAL kernel,
  typically `CGAL::Exact_predicates_inexact_constructions_kernel::Point_3`

  \param network the spline
  \param levels the number \f$L\f$ of uniform 4-splits, from 0 (the domain triangles) to 10
  \param mesh the output mesh
  \return the numbers of vertices and faces created
  \throws Invalid_input if `levels` is outside [0, 10] or the mesh would exceed the index
  range of `Surface_mesh` (\f$2^{32}\f$ halfedges)
*/
template <class TriangularSplineNetwork, class Mesh>
Tessellation_statistics tessellate(const TriangularSplineNetwork& network, int levels, Mesh& mesh) {
  using GeomTraits = typename TriangularSplineNetwork::Geom_traits;
  using Domain = Planar_domain<GeomTraits>;
  using Index = typename Domain::Index;
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Patch = internal::Network_patch_t<TriangularSplineNetwork>;
  const Domain& domain = network.domain();
  auto patch = internal::patch_source(network);
  using Value = typename Patch::Value_type;
  using Point_3 = typename internal::Surface_mesh_point<Mesh>::type;
  using Vector_3 = typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3;
  using Vertex_index = typename Mesh::Vertex_index;
  constexpr int dimension = Value_traits<Value>::dimension;
  static_assert(dimension == 1 || dimension == 3,
                "tessellate() needs functional (scalar) or 3D parametric patches");

  if (levels < 0 || levels > 10)
    throw Invalid_input("tessellate: the number of levels must be between 0 and 10, got " +
                        std::to_string(levels));
  const std::size_t n = std::size_t(1) << levels;
  const std::size_t V = domain.number_of_vertices(), E = domain.number_of_edges(),
                    F = domain.number_of_faces();
  const std::size_t inner = (n - 1) * (n - 2) / 2; // interior grid points of one triangle
  const std::size_t vertices = V + E * (n - 1) + F * inner;
  const std::size_t faces = F * n * n;
  const std::size_t edges = E * n + F * 3 * n * (n - 1) / 2;
  // Surface_mesh indices are 32-bit; the last value marks a null index.
  if (2 * edges >= (std::numeric_limits<std::uint32_t>::max)())
    throw Invalid_input("tessellate: " + std::to_string(faces) + " triangles at level " +
                        std::to_string(levels) + " exceed the capacity of Surface_mesh");

  mesh.clear();
  mesh.reserve(static_cast<typename Mesh::size_type>(vertices),
               static_cast<typename Mesh::size_type>(edges),
               static_cast<typename Mesh::size_type>(faces));
  auto normals =
      mesh.template add_property_map<Vertex_index, Vector_3>("v:normal", Vector_3(0, 0, 0)).first;
  auto gaussian =
      mesh.template add_property_map<Vertex_index, double>("v:gaussian_curvature", 0.).first;
  auto mean = mesh.template add_property_map<Vertex_index, double>("v:mean_curvature", 0.).first;
  for (std::size_t v = 0; v < vertices; ++v)
    mesh.add_vertex();

  // Each shared grid point is evaluated once, in the first incident face.
  std::vector<Index> vertex_owner(V), edge_owner(E);
  for (std::size_t v = 0; v < V; ++v)
    vertex_owner[v] = *domain.star_faces(static_cast<Index>(v)).first;
  for (std::size_t e = 0; e < E; ++e) {
    const auto& ef = domain.edge_faces(static_cast<Index>(e));
    edge_owner[e] = ef[0] != Domain::null_index ? ef[0] : ef[1];
  }

  const FT step = FT(1) / FT(static_cast<int>(n)); // a power of two: exact in double
  std::vector<Vertex_index> grid(internal::grid_index(n, 0, n) + 1);
  for (std::size_t fi = 0; fi < F; ++fi) {
    const Index f = static_cast<Index>(fi);
    const auto& t = domain.face(f);
    const Patch& bezier = patch(f);
    const internal::Face_to_patch<GeomTraits, Value> frame(domain, f, bezier);
    const internal::Patch_jet<GeomTraits, Value> jet(bezier);
    for (std::size_t i = 0; i <= n; ++i)
      for (std::size_t j = 0; i + j <= n; ++j) {
        const std::array<std::size_t, 3> a{{i, j, n - i - j}};
        const int zeros = (a[0] == 0) + (a[1] == 0) + (a[2] == 0);
        std::size_t id;
        bool owned;
        if (zeros == 2) { // a domain vertex
          const std::size_t c = a[0] != 0 ? 0 : (a[1] != 0 ? 1 : 2);
          id = t[c];
          owned = vertex_owner[t[c]] == f;
        } else if (zeros == 1) { // on the edge opposite the zero coordinate
          const std::size_t z = a[0] == 0 ? 0 : (a[1] == 0 ? 1 : 2);
          const Index e = domain.face_edge(f, static_cast<int>(z));
          const std::size_t after = (z + 1) % 3;
          // position along lo -> hi = weight of hi
          const std::size_t along = t[after] == domain.edge(e)[1] ? a[after] : a[(z + 2) % 3];
          id = V + e * (n - 1) + (along - 1);
          owned = edge_owner[e] == f;
        } else {
          id = V + E * (n - 1) + fi * inner + internal::grid_index(i - 1, j - 1, n - 3);
          owned = true;
        }
        const Vertex_index vertex(static_cast<typename Mesh::size_type>(id));
        grid[internal::grid_index(i, j, n)] = vertex;
        if (!owned)
          continue;
        const std::array<FT, 3> weights{{FT(static_cast<int>(a[0])) * step,
                                         FT(static_cast<int>(a[1])) * step,
                                         FT(static_cast<int>(a[2])) * step}};
        Value value = Value_traits<Value>::zero();
        Surface_derivatives derivatives;
        jet.compute(frame.patch_weights(weights), value, derivatives);
        if constexpr (dimension == 1) {
          const Point_2 p =
              zeros == 2 ? domain.point(static_cast<Index>(id)) : frame.point(weights);
          mesh.point(vertex) =
              Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(value));
        } else {
          mesh.point(vertex) = Point_3(CGAL::to_double(value.x()), CGAL::to_double(value.y()),
                                       CGAL::to_double(value.z()));
        }
        const Surface_curvature curvature = surface_curvature(derivatives);
        normals[vertex] = Vector_3(curvature.normal[0], curvature.normal[1], curvature.normal[2]);
        gaussian[vertex] = curvature.gaussian;
        mean[vertex] = curvature.mean;
      }
    // The affine map from barycentric to domain coordinates keeps orientation, so both
    // kinds of grid triangles are counter-clockwise like the domain triangle.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; i + j < n; ++j) {
        // upward: (i+1, j, k), (i, j+1, k), (i, j, k+1) with i+j+k = n-1
        internal::add_grid_face(mesh, grid[internal::grid_index(i + 1, j, n)],
                                grid[internal::grid_index(i, j + 1, n)],
                                grid[internal::grid_index(i, j, n)]);
        // downward: (i, j+1, k+1), (i+1, j, k+1), (i+1, j+1, k) with i+j+k = n-2
        if (i + j + 2 <= n)
          internal::add_grid_face(mesh, grid[internal::grid_index(i, j + 1, n)],
                                  grid[internal::grid_index(i + 1, j, n)],
                                  grid[internal::grid_index(i + 1, j + 1, n)]);
      }
  }

  Tessellation_statistics statistics;
  statistics.vertices = mesh.number_of_vertices();
  statistics.faces = mesh.number_of_faces();
  return statistics;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_TESSELLATE_H

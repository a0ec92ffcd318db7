// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_TEST_MESHES_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_TEST_MESHES_H

#include <CGAL/Triangular_spline/Blending/Blending_mesh_data.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/blending_test_meshes.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the test mesh `name` of Fang's ch. 8 (and §8.1) as arrays.

  | name | mesh | normals |
  |---|---|---|
  | `franke4`, `franke8` | Franke's \f$f_4(x,y) = \frac13 e^{-\frac{81}{16}((x-\frac12)^2 +
  (y-\frac12)^2)}\f$ (eq. 8.1) sampled on a 4×4 / 8×8 grid of \f$[0,1]^2\f$, each square cut by its
  diagonal (bordered) | of the graph of \f$f_4\f$ | | `icosahedron` | vertices at distance 1 |
  radial | | `pentakis` | pentakis icosidodecahedron: the icosahedron 4-split, new vertices on the
  unit sphere (42 vertices, 80 faces) | radial | | `ellipsoid` | `pentakis` scaled by 2 along
  \f$z\f$ | of the ellipsoid \f$x^2 + y^2 + z^2/4 = 1\f$ | | `perturbed` | `pentakis` of radius 1.5,
  each vertex moved uniformly in \f$[-0.1, 0.1]^3\f$ (seeded) | none: estimated from the faces, as
  in the thesis | | `torus` | torus R 1.3, r 0.7, 12×6 vertices, quads cut into triangles | of the
  torus | | `octahedron` | the triangular sharp mesh of §8.1 (our choice: a regular octahedron,
  radius 1) | radial | | `dodecahedron` | vertices at distance 1.66 (pentagons) | radial | | `cube`
  | the quadrangular sharp mesh of §8.1 (our choice: the cube \f$[-1,1]^3\f$) | radial | |
  `quad_torus` | torus R 1.25, r 0.75, 16×8 quads | of the torus | | `mixed` | the cube's faces
  split 2×2, on the unit sphere (26 vertices), some quads (seeded) cut into triangles, radii moved
  in [0.9, 1.1] (seeded) | radial |

  The thesis does not give the sharp meshes of §8.1, the grid layout of the Franke meshes,
  nor the random generators: those here are documented choices.

  \throws Invalid_input for an unknown name
  \param name the name of the test mesh
  \param seed the seed of the random generator
  \returns the test mesh `name` of Fang's ch. 8 (and §8.1) as arrays
*/
inline Blending_mesh_data blending_test_mesh_data(const std::string& name, unsigned seed = 1) {
  using internal::normalized3;
  Blending_mesh_data m;
  if (name == "franke4" || name == "franke8") {
    const std::size_t n = name == "franke4" ? 4 : 8;
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const double x = double(i) / double(n - 1), y = double(j) / double(n - 1);
        const double e = std::exp(-81.0 / 16.0 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)));
        const double z = e / 3;
        const double zx = -81.0 / 8.0 * (x - 0.5) * z, zy = -81.0 / 8.0 * (y - 0.5) * z;
        m.points.push_back({{x, y, z}});
        m.normals.push_back(normalized3({{-zx, -zy, 1}}));
      }
    for (std::size_t j = 0; j + 1 < n; ++j)
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      }
    return m;
  }
  if (name == "icosahedron")
    return internal::icosahedron_data(1);
  if (name == "pentakis")
    return internal::subdivided_on_sphere(internal::icosahedron_data(1), 1);
  if (name == "ellipsoid") {
    m = internal::subdivided_on_sphere(internal::icosahedron_data(1), 1);
    for (std::size_t v = 0; v < m.points.size(); ++v) {
      std::array<double, 3>& p = m.points[v];
      p[2] *= 2;
      m.normals[v] = normalized3({{p[0], p[1], p[2] / 4}});
    }
    return m;
  }
  if (name == "perturbed") {
    m = internal::subdivided_on_sphere(internal::icosahedron_data(1.5), 1.5);
    std::mt19937 engine(seed);
    std::uniform_real_distribution<double> shift(-0.1, 0.1);
    for (std::array<double, 3>& p : m.points)
      for (double& x : p)
        x += shift(engine);
    m.normals.clear();
    return m;
  }
  if (name == "torus")
    return internal::torus_data(1.3, 0.7, 12, 6, true);
  if (name == "quad_torus")
    return internal::torus_data(1.25, 0.75, 16, 8, false);
  if (name == "octahedron") {
    std::vector<std::array<double, 3>> p{{{1, 0, 0}},  {{-1, 0, 0}}, {{0, 1, 0}},
                                         {{0, -1, 0}}, {{0, 0, 1}},  {{0, 0, -1}}};
    m.points = p;
    m.normals = p;
    m.faces = internal::equilateral_triangles(p, 2);
    return m;
  }
  if (name == "cube" || name == "mixed") {
    // the six faces of [-1, 1]^3, each as a k x k grid of quads (k = 1: cube, 2: mixed)
    const int k = name == "cube" ? 1 : 2;
    std::map<std::array<long, 3>, std::size_t> index;
    auto vertex = [&](const std::array<long, 3>& key) {
      auto it = index.find(key);
      if (it != index.end())
        return it->second;
      const std::array<double, 3> q{{double(key[0]) / k, double(key[1]) / k, double(key[2]) / k}};
      m.points.push_back(name == "cube" ? q : normalized3(q));
      m.normals.push_back(normalized3(q));
      index[key] = m.points.size() - 1;
      return m.points.size() - 1;
    };
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {-1, 1}) {
        const int u = (axis + 1) % 3, w = (axis + 2) % 3; // (u, w, axis) right-handed
        for (int i = 0; i < k; ++i)
          for (int j = 0; j < k; ++j) {
            std::vector<std::size_t> face;
            const std::array<std::array<int, 2>, 4> corners{
                {{{i, j}}, {{i + 1, j}}, {{i + 1, j + 1}}, {{i, j + 1}}}};
            for (const auto& c : corners) {
              std::array<long, 3> key;
              key[static_cast<std::size_t>(axis)] = sign * k;
              key[static_cast<std::size_t>(u)] = 2 * c[0] - k;
              key[static_cast<std::size_t>(w)] = 2 * c[1] - k;
              face.push_back(vertex(key));
            }
            if (sign < 0)
              face = {face[0], face[3], face[2], face[1]};
            m.faces.push_back(face);
          }
      }
    if (name == "mixed") {
      std::mt19937 engine(seed);
      std::uniform_real_distribution<double> radius(0.9, 1.1);
      for (std::array<double, 3>& p : m.points)
        p = normalized3(p, radius(engine));
      std::vector<std::vector<std::size_t>> faces;
      for (const auto& f : m.faces) {
        const unsigned choice = engine() % 3; // keep, or cut along one of the diagonals
        if (choice == 0) {
          faces.push_back(f);
        } else if (choice == 1) {
          faces.push_back({f[0], f[1], f[2]});
          faces.push_back({f[0], f[2], f[3]});
        } else {
          faces.push_back({f[0], f[1], f[3]});
          faces.push_back({f[1], f[2], f[3]});
        }
      }
      m.faces = faces;
    }
    return m;
  }
  if (name == "dodecahedron") {
    // the dual of the icosahedron: one vertex per icosahedron face (its centroid direction),
    // one pentagon per icosahedron vertex
    const Blending_mesh_data ico = internal::icosahedron_data(1);
    for (const auto& f : ico.faces) {
      std::array<double, 3> c{{0, 0, 0}};
      for (std::size_t v : f)
        for (std::size_t k = 0; k < 3; ++k)
          c[k] += ico.points[v][k];
      m.points.push_back(normalized3(c, 1.66));
      m.normals.push_back(normalized3(c));
    }
    for (std::size_t v = 0; v < ico.points.size(); ++v) {
      // the faces around v, ordered counter-clockwise around the outward direction v
      std::vector<std::size_t> around;
      for (std::size_t f = 0; f < ico.faces.size(); ++f)
        for (std::size_t x : ico.faces[f])
          if (x == v)
            around.push_back(f);
      const std::array<double, 3>& n = ico.points[v];
      std::array<double, 3> e1{{0, 0, 0}}, e2;
      const std::array<double, 3>& first = m.points[around[0]];
      const double dn = first[0] * n[0] + first[1] * n[1] + first[2] * n[2];
      for (std::size_t k = 0; k < 3; ++k)
        e1[k] = first[k] - dn * n[k];
      e2 = {
          {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]}};
      std::vector<std::pair<double, std::size_t>> angles;
      for (std::size_t f : around) {
        const std::array<double, 3>& q = m.points[f];
        angles.push_back({std::atan2(q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2],
                                     q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2]),
                          f});
      }
      std::sort(angles.begin(), angles.end());
      std::vector<std::size_t> face;
      for (const auto& a : angles)
        face.push_back(a.second);
      m.faces.push_back(face);
    }
    return m;
  }
  throw Invalid_input("unknown test mesh '" + name +
                      "' (franke4, franke8, icosahedron, pentakis, ellipsoid, perturbed, torus, "
                      "octahedron, dodecahedron, cube, quad_torus, mixed)");
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the names accepted by `blending_test_mesh()`.
  \returns the names accepted by `blending_test_mesh()`
*/
inline std::vector<std::string> blending_test_mesh_names() {
  return {"franke4", "franke8",    "icosahedron",  "pentakis", "ellipsoid",  "perturbed",
          "torus",   "octahedron", "dodecahedron", "cube",     "quad_torus", "mixed"};
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief converts mesh arrays to a `CGAL::Surface_mesh` with the normals (if any) in the
  vertex property map `"v:normal"`.
  \tparam Point_3 a CGAL 3D point type (e.g. `Kernel::Point_3`)
  \throws Invalid_input if a face refers to a missing vertex or `Surface_mesh` rejects a
  face (non-manifold or inconsistently oriented input)
  \param data the vertices, faces and optional normals of the mesh
  \returns the surface mesh
*/
template <class Point_3>
CGAL::Surface_mesh<Point_3> to_surface_mesh(const Blending_mesh_data& data) {
  using Mesh = CGAL::Surface_mesh<Point_3>;
  using Vector_3 = typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3;
  Mesh mesh;
  std::vector<typename Mesh::Vertex_index> v;
  for (const auto& p : data.points)
    v.push_back(mesh.add_vertex(Point_3(p[0], p[1], p[2])));
  if (!data.normals.empty()) {
    auto normals = mesh.template add_property_map<typename Mesh::Vertex_index, Vector_3>(
                           "v:normal", Vector_3(0, 0, 0))
                       .first;
    for (std::size_t i = 0; i < data.normals.size() && i < v.size(); ++i)
      normals[v[i]] = Vector_3(data.normals[i][0], data.normals[i][1], data.normals[i][2]);
  }
  for (std::size_t f = 0; f < data.faces.size(); ++f) {
    std::vector<typename Mesh::Vertex_index> face;
    for (std::size_t i : data.faces[f]) {
      if (i >= v.size())
        throw Invalid_input("face " + std::to_string(f) + " refers to missing vertex " +
                            std::to_string(i));
      face.push_back(v[i]);
    }
    if (mesh.add_face(face) == Mesh::null_face())
      throw Invalid_input("face " + std::to_string(f) +
                          " cannot be added (non-manifold or inconsistently oriented mesh)");
  }
  return mesh;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the test mesh `name` (see `blending_test_mesh_data()`) as a
  `CGAL::Surface_mesh` with its normals in `"v:normal"` (none for `perturbed`).
  \tparam Point_3 a CGAL 3D point type (e.g. `Kernel::Point_3`)
  \param name the name of the test mesh
  \param seed the seed of the random generator
  \returns the test mesh `name` (see `blending_test_mesh_data()`) as a `CGAL::Surface_mesh` with its
  normals in `"v:normal"` (none for `perturbed`)
*/
template <class Point_3>
CGAL::Surface_mesh<Point_3> blending_test_mesh(const std::string& name, unsigned seed = 1) {
  return to_surface_mesh<Point_3>(blending_test_mesh_data(name, seed));
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_TEST_MESHES_H

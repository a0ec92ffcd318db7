// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_TEST_MESHES_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_TEST_MESHES_H

#include <CGAL/Triangular_spline/exceptions.h>

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
  \brief a polygon mesh given as arrays: positions, optional unit normals, and faces as
  counter-clockwise vertex lists (seen from outside / from above).
*/
struct Blending_mesh_data {
  std::vector<std::array<double, 3>> points;   ///< vertex positions
  std::vector<std::array<double, 3>> normals;  ///< per-vertex normals, or empty (estimate them)
  std::vector<std::vector<std::size_t>> faces; ///< faces, counter-clockwise
};

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

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_THESIS_POLYHEDRA_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_THESIS_POLYHEDRA_H

// The meshes of thesis_polyhedron() (Xu/thesis_polyhedra.h) as arrays in the kernel's number
// type.

#include <CGAL/Triangular_spline/Blending/Blending_mesh_data.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/blending_test_meshes.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

// Declared here, defined (and documented) in Xu/thesis_polyhedra.h, which includes this
// header: the names are listed in the message for an unknown one.
inline std::vector<std::string> thesis_polyhedron_names();

namespace internal {

// A closed triangle mesh as arrays in the kernel's number type: rational coordinates are
// built as FT(num) / FT(den), so that they are exact with an exact number type.
template <class K>
struct Thesis_polyhedron_data {
  std::vector<typename K::Point_3> points;
  std::vector<std::array<std::size_t, 3>> faces; // counter-clockwise seen from outside
};

template <class K>
typename K::FT thesis_rational(int num, int den = 1) {
  return typename K::FT(num) / typename K::FT(den);
}

// Fang's generators compute in double; their coordinates are converted as they are.
template <class K>
Thesis_polyhedron_data<K> thesis_from_blending(const Blending_mesh_data& data) {
  Thesis_polyhedron_data<K> m;
  for (const std::array<double, 3>& p : data.points)
    m.points.emplace_back(p[0], p[1], p[2]);
  for (const std::vector<std::size_t>& f : data.faces)
    m.faces.push_back({{f[0], f[1], f[2]}});
  return m;
}

// The vertices of the cube [-1, 1]^3 numbered 4[x > 0] + 2[y > 0] + [z > 0], and its
// squares as counter-clockwise (seen from outside) cycles of vertex numbers.
template <class K>
std::vector<typename K::Point_3> thesis_cube_corners() {
  std::vector<typename K::Point_3> p;
  for (int v = 0; v < 8; ++v)
    p.emplace_back((v & 4) ? 1 : -1, (v & 2) ? 1 : -1, (v & 1) ? 1 : -1);
  return p;
}

inline std::vector<std::array<std::size_t, 4>> thesis_cube_squares() {
  std::vector<std::array<std::size_t, 4>> squares;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      // (u, w, axis) right-handed: (-,-), (+,-), (+,+), (-,+) in (u, w) is counter-clockwise
      // about +axis; reversed for the face on the negative side
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      const std::array<std::array<int, 2>, 4> corners{{{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}};
      std::array<std::size_t, 4> square{};
      for (std::size_t c = 0; c < 4; ++c) {
        std::array<int, 3> bit{};
        bit[static_cast<std::size_t>(axis)] = sign > 0 ? 1 : 0;
        bit[static_cast<std::size_t>(u)] = corners[c][0];
        bit[static_cast<std::size_t>(w)] = corners[c][1];
        square[c] = static_cast<std::size_t>(4 * bit[0] + 2 * bit[1] + bit[2]);
      }
      if (sign < 0)
        square = {{square[0], square[3], square[2], square[1]}};
      squares.push_back(square);
    }
  return squares;
}

// The apex-coned ring: the ring lies in z = 0, counter-clockwise seen from +z, star-shaped
// with respect to the origin; the apexes are (0, 0, +-h).
template <class K>
Thesis_polyhedron_data<K> thesis_bipyramid(const std::vector<typename K::Point_3>& ring,
                                           const typename K::FT& h) {
  Thesis_polyhedron_data<K> m;
  m.points = ring;
  const std::size_t n = ring.size(), top = n, bottom = n + 1;
  m.points.emplace_back(0, 0, h);
  m.points.emplace_back(0, 0, -h);
  for (std::size_t k = 0; k < n; ++k)
    m.faces.push_back({{k, (k + 1) % n, top}});
  for (std::size_t k = 0; k < n; ++k)
    m.faces.push_back({{(k + 1) % n, k, bottom}});
  return m;
}

template <class K>
Thesis_polyhedron_data<K> thesis_polyhedron_data(const std::string& name) {
  using FT = typename K::FT;
  using Point_3 = typename K::Point_3;
  Thesis_polyhedron_data<K> m;
  if (name == "tetrahedron") {
    // SPEC_AG1 §5.1/§5.3: a, b, c, d and the faces abc, adb, bdc, cda in this order
    m.points = {Point_3(1, 1, 1), Point_3(1, -1, -1), Point_3(-1, 1, -1), Point_3(-1, -1, 1)};
    m.faces = {{{0, 1, 2}}, {{0, 3, 1}}, {{1, 3, 2}}, {{2, 3, 0}}};
    return m;
  }
  if (name == "sato") {
    // Xu Fig. 5.3; p3 lies above the base p0 p1 p2 (z = 0), which is seen from below
    m.points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 2, 0), Point_3(2, 3, 4)};
    m.faces = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{2, 0, 3}}};
    return m;
  }
  if (name == "octahedron") {
    // +x, -x, +y, -y, +z, -z; one face per octant
    m.points = {Point_3(1, 0, 0),  Point_3(-1, 0, 0), Point_3(0, 1, 0),
                Point_3(0, -1, 0), Point_3(0, 0, 1),  Point_3(0, 0, -1)};
    for (std::size_t sx = 0; sx < 2; ++sx)
      for (std::size_t sy = 0; sy < 2; ++sy)
        for (std::size_t sz = 0; sz < 2; ++sz) {
          const std::size_t a = sx, b = 2 + sy, c = 4 + sz;
          // (+x, +y, +z) is counter-clockwise seen from outside; each sign flip mirrors
          if ((sx + sy + sz) % 2 == 0)
            m.faces.push_back({{a, b, c}});
          else
            m.faces.push_back({{a, c, b}});
        }
    return m;
  }
  if (name == "cube") {
    m.points = thesis_cube_corners<K>();
    for (std::array<std::size_t, 4> s : thesis_cube_squares()) {
      // cut by the diagonal through the smallest vertex number: rotate it to the front
      std::size_t first = 0;
      for (std::size_t c = 1; c < 4; ++c)
        if (s[c] < s[first])
          first = c;
      const std::size_t a = s[first], b = s[(first + 1) % 4], c = s[(first + 2) % 4],
                        d = s[(first + 3) % 4];
      m.faces.push_back({{a, b, c}});
      m.faces.push_back({{a, c, d}});
    }
    return m;
  }
  if (name == "cube-centres") {
    // the corners 0..7 as for "cube", then the face centres +x, -x, +y, -y, +z, -z
    m.points = thesis_cube_corners<K>();
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {1, -1}) {
        std::array<int, 3> c{{0, 0, 0}};
        c[static_cast<std::size_t>(axis)] = sign;
        m.points.emplace_back(c[0], c[1], c[2]);
      }
    const std::vector<std::array<std::size_t, 4>> squares = thesis_cube_squares();
    for (std::size_t q = 0; q < squares.size(); ++q) {
      // squares are listed -x, +x, -y, +y, -z, +z; centres +x, -x, ...
      const std::size_t centre = 8 + 2 * (q / 2) + (q % 2 == 0 ? 1 : 0);
      for (std::size_t c = 0; c < 4; ++c)
        m.faces.push_back({{centre, squares[q][c], squares[q][(c + 1) % 4]}});
    }
    return m;
  }
  if (name == "icosahedron")
    return thesis_from_blending<K>(internal::icosahedron_data(1));
  if (name == "pentakis")
    return thesis_from_blending<K>(blending_test_mesh_data("pentakis"));
  if (name == "torus")
    return thesis_from_blending<K>(blending_test_mesh_data("torus"));
  if (name == "torus9") {
    // Xu Fig. 5.5: the 3x3 grid with opposite sides identified, each square cut by the
    // same diagonal; vertex (i, j) at angles 2 pi i / 3 around the axis and 2 pi j / 3
    // around the tube (R = 2, r = 1). Each tube segment lies in its own 120° wedge, so the
    // segments meet only in their common cross-section.
    return thesis_from_blending<K>(internal::torus_data(2, 1, 3, 3, true));
  }
  if (name == "star") {
    // 12 points, radii 1 and 2/5 alternating, at angles 2 pi k / 12; apexes (0, 0, +-3/5)
    const double pi = 3.14159265358979323846;
    std::vector<Point_3> ring;
    for (int k = 0; k < 12; ++k) {
      const FT radius = k % 2 == 0 ? FT(1) : thesis_rational<K>(2, 5);
      const double angle = 2 * pi * k / 12;
      // multiples of 90° are exact; the others are the rounded cosines and sines
      const FT c = k % 3 == 0 ? FT(k == 3 || k == 9 ? 0 : (k == 0 ? 1 : -1)) : FT(std::cos(angle));
      const FT s = k % 3 == 0 ? FT(k == 3 ? 1 : (k == 9 ? -1 : 0)) : FT(std::sin(angle));
      ring.emplace_back(radius * c, radius * s, FT(0));
    }
    return thesis_bipyramid<K>(ring, thesis_rational<K>(3, 5));
  }
  if (name == "v-arm") {
    // SPEC_AG1 §8: two long arms along the axes; the apexes see the ring from (0, 0)
    auto q = [](int x, int dx, int y, int dy) {
      return Point_3(thesis_rational<K>(x, dx), thesis_rational<K>(y, dy), FT(0));
    };
    const std::vector<Point_3> ring{q(10, 1, 0, 1),    q(10, 1, 1, 1),  q(1, 2, 1, 2),
                                    q(1, 1, 10, 1),    q(0, 1, 10, 1),  q(-1, 10, 1, 10),
                                    q(-1, 10, -1, 10), q(1, 10, -1, 10)};
    return thesis_bipyramid<K>(ring, FT(1));
  }
  std::string names;
  for (const std::string& n : thesis_polyhedron_names())
    names += (names.empty() ? "" : ", ") + n;
  throw Invalid_input("unknown polyhedron '" + name + "' (" + names + ")");
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_THESIS_POLYHEDRA_H

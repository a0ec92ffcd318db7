// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_COMPARATORS_NIELSON_SIDE_VERTEX_H
#define CGAL_TRIANGULAR_SPLINE_COMPARATORS_NIELSON_SIDE_VERTEX_H

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/Blending/blending_functions.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/array_vector_3.h>
#include <CGAL/Triangular_spline/internal/blending_mesh.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief Nielson's side-vertex interpolant of a triangle mesh with vertex normals (G. M.
  Nielson, <em>A transfinite, visually continuous, triangular interpolant</em>, 1987): the
  "Nielson's algorithm" against which Fang compares his mesh blending (Fang §2.6.1,
  Def. 2.3 and eq. 2.8; §5.4, Figs. 5.8–5.13). Fang does not spell the algorithm out; this
  is the classic \f$G^1\f$ scheme built from the data `Mesh_blending_surface` uses (vertex
  positions and unit normals):

  1. **Boundary curves.** Edge \f$(P_a, P_b)\f$, \f$a < b\f$ (vertex indices), carries the
     cubic Bézier curve \f$c(t)\f$ with control points \f$P_a\f$, \f$(2P_a + P_b - w_{ab}
     N_a)/3\f$, \f$(2P_b + P_a - w_{ba} N_b)/3\f$, \f$P_b\f$, \f$w_{ab} = (P_b - P_a)\cdot
     N_a\f$: the PN-triangle edge (`pn_triangles()`), whose end tangents are the chord
     projected onto the vertices' tangent planes. Both faces of the edge evaluate the same
     curve at the same \f$t = b_b/(b_a + b_b)\f$, so they agree exactly in `double`.
  2. **Tangent planes along edges.** \f$n_e(t) = m - (m \cdot c')\,c'/|c'|^2\f$ with
     \f$m = (1-t)N_a + tN_b\f$: the interpolated end normals made orthogonal to the curve.
     It depends on the edge only, and equals \f$N_a\f$, \f$N_b\f$ at the ends.
  3. **Side-vertex surfaces.** For corner \f$i\f$ of a face with barycentric coordinates
     \f$(b_i, b_j, b_k)\f$, the point \f$Q = c(t)\f$ of the opposite edge at
     \f$t = b_k/(b_j + b_k)\f$ (in the edge's own orientation) and \f$d = Q - V_i\f$,
     \f$S_i(b)\f$ is the cubic Hermite curve from \f$V_i\f$ to \f$Q\f$ at \f$s = 1 - b_i\f$,
     with end tangents \f$d\f$ projected onto the tangent plane at \f$V_i\f$ and onto the
     plane normal to \f$n_e(t)\f$. On the edges through \f$V_i\f$ that curve is the boundary
     curve itself (same end points and tangents), so every \f$S_i\f$ interpolates all three
     boundary curves (Fang's Condition 2.1), and on its opposite edge its tangent plane is
     the one of \f$n_e\f$.
  4. **Blend.** \f$S = \sum_i f_i S_i\f$ with Nielson's functions \f$f_i = b_j b_k /
     (b_0 b_1 + b_1 b_2 + b_2 b_0)\f$ (`nielson_functions()`). On the edge opposite
     \f$V_i\f$, \f$f_i = 1\f$ and the other \f$S_j\f$ equal \f$S_i\f$, so the derivatives of
     \f$S\f$ are those of \f$S_i\f$: the tangent plane is that of \f$n_e\f$ from both sides,
     \f$G^1\f$ across every edge (jump 0 up to round-off).
  5. **Corners.** The functions are undefined where two coordinates vanish; the limit there
     is the vertex. Near \f$V_i\f$, \f$S - S_j = O(r)\f$ with its first derivatives
     (\f$S_j, S_k\f$ share the two edge curves through \f$V_i\f$ and are smooth there), so
     \f$S\f$ is \f$C^1\f$ at the corner with the first derivatives of \f$S_j\f$, \f$j = i+1\f$,
     and the normal is \f$N_i\f$: \f$G^1\f$ at the vertices. The second derivatives stay
     bounded but depend on the direction of approach (Nielson's scheme is not \f$C^2\f$
     there); at a corner `derivatives()` gives the limit of the second derivatives along the
     median, taken at distance \f$\delta\f$ = `corner_offset` in barycentric coordinates.

  Derivatives (normals, Gaussian curvature) come from `Taylor_jet`s: the formulas are
  rational and square-root free, so they are exact up to round-off. Everything is computed
  in `double`. The mesh may be closed or have borders.

  Face parameters: `w` are barycentric weights of the face's corners in the order of
  `vertices_around_face(halfedge(f), mesh)`; derivatives are taken with respect to
  \f$(w_1, w_2)\f$, \f$w_0 = 1 - w_1 - w_2\f$ (the convention of `Patch_sampler`, so the
  normal \f$S_{w_1} \times S_{w_2}\f$ follows the face orientation).

  \tparam Point_3 the point type of the input `Surface_mesh`
*/
template <class Point_3>
class Nielson_side_vertex_surface {
public:
  /// the input mesh type
  using Mesh = CGAL::Surface_mesh<Point_3>;
  /// the face index type of the mesh
  using face_descriptor = typename Mesh::Face_index;
  /// a point or vector of space
  using Vec3 = std::array<double, 3>;
  /// barycentric weights of a face's corners
  using Weights = std::array<double, 3>;
  /// the jets used for normals and curvatures
  using Jet = Taylor_jet<double, 2>;
  /// the distance (barycentric) from a corner at which its second derivatives are taken
  static constexpr double corner_offset = 1e-3;

  /*!
    builds the boundary curves of the edges.

    The normals are those of the vertex property map `"v:normal"` if the mesh has one,
    otherwise the normalised mean of the unit normals of the incident faces: the normals of
    `Mesh_blending_surface`, from the same code.
    \throws Invalid_input naming the element if the mesh has no face or has removed elements,
    a face is not a triangle or has zero area, a coordinate is not finite, a given normal is
    zero, not finite or against the orientation of the faces, an estimated normal vanishes,
    or an edge is parallel to the normal of one of its vertices (no tangent there)
    \param mesh a triangle mesh, closed or with borders, consistently oriented
  */
  explicit Nielson_side_vertex_surface(const Mesh& mesh) : m_mesh(mesh) {
    if (m_mesh.number_of_faces() == 0)
      throw Invalid_input("Nielson: the mesh has no face");
    if (m_mesh.has_garbage())
      throw Invalid_input("Nielson: the mesh has removed elements (collect the garbage)");
    for (auto f : m_mesh.faces())
      if (CGAL::degree(f, m_mesh) != 3)
        throw Invalid_input("Nielson: face " + std::to_string(std::size_t(f)) + " has " +
                            std::to_string(CGAL::degree(f, m_mesh)) + " vertices, not 3");
    m_position.resize(m_mesh.number_of_vertices());
    std::vector<std::size_t> degree(m_mesh.number_of_vertices());
    for (auto v : m_mesh.vertices()) {
      m_position[std::size_t(v)] = internal::to_array_3(m_mesh.point(v));
      degree[std::size_t(v)] = CGAL::degree(v, m_mesh);
      for (double x : m_position[std::size_t(v)])
        if (!std::isfinite(x))
          throw Invalid_input("Nielson: vertex " + std::to_string(std::size_t(v)) +
                              " has a coordinate that is not finite");
    }
    m_corners.resize(m_mesh.number_of_faces());
    for (auto f : m_mesh.faces()) {
      std::size_t c = 0;
      for (auto v : CGAL::vertices_around_face(m_mesh.halfedge(f), m_mesh))
        m_corners[std::size_t(f)][c++] = std::size_t(v);
    }
    // the normals of Mesh_blending_surface, from the same code
    const std::vector<Vec3> given =
        internal::surface_mesh_normals(m_mesh, get(CGAL::vertex_index, m_mesh));
    m_estimated_normals = given.empty();
    m_normal = internal::blending_vertex_normals(m_position, m_corners, degree, given, "Nielson");
    m_curves.resize(m_mesh.number_of_edges());
    for (auto e : m_mesh.edges()) {
      const std::array<std::size_t, 2> ab = edge_vertices(std::size_t(e));
      const Vec3 &P = m_position[ab[0]], &Q = m_position[ab[1]];
      std::array<Vec3, 4>& c = m_curves[std::size_t(e)];
      c[0] = P;
      c[1] = tangent_point(P, Q, m_normal[ab[0]], ab[0]);
      c[2] = tangent_point(Q, P, m_normal[ab[1]], ab[1]);
      c[3] = Q;
    }
  }

  /// \name Access
  /// @{

  /// \returns the copy of the input mesh that the indices refer to
  const Mesh& mesh() const { return m_mesh; }
  /// \returns `true` if the vertex normals were estimated from the faces
  bool has_estimated_normals() const { return m_estimated_normals; }
  /// \param v a vertex index
  /// \returns the unit normal of vertex `v` used by the construction
  const Vec3& vertex_normal(std::size_t v) const { return m_normal.at(v); }
  /// \param f a face index
  /// \returns the vertex indices of the corners of face `f`, in `vertices_around_face` order
  const std::array<std::size_t, 3>& face_vertices(std::size_t f) const { return m_corners.at(f); }
  /// \param e an edge index
  /// \returns the end vertices \f$(a, b)\f$, \f$a < b\f$, of edge `e`: the curve's orientation
  std::array<std::size_t, 2> edge_vertices(std::size_t e) const {
    const auto h =
        m_mesh.halfedge(typename Mesh::Edge_index(static_cast<typename Mesh::size_type>(e)));
    const std::size_t a = std::size_t(m_mesh.source(h)), b = std::size_t(m_mesh.target(h));
    return a < b ? std::array<std::size_t, 2>{{a, b}} : std::array<std::size_t, 2>{{b, a}};
  }
  /// \param e an edge index
  /// \returns the Bézier control points of the boundary curve of edge `e`, from
  /// `edge_vertices(e)[0]` to `edge_vertices(e)[1]`
  const std::array<Vec3, 4>& edge_curve(std::size_t e) const { return m_curves.at(e); }
  /// @}

  /// \name Evaluation
  /// @{

  /*!
    evaluates the blend \f$\sum_i f_i S_i\f$ of face `f` with numbers or jets (not at a
    corner, where Nielson's functions are undefined).
    \tparam T `double` or a `Taylor_jet`
    \pre no two of `b` vanish
    \param f a face index
    \param b the barycentric coordinates of the face's corners
    \returns the point (or its jet)
  */
  template <class T>
  std::array<T, 3> blend(std::size_t f, const std::array<T, 3>& b) const {
    const std::array<T, 3> w = nielson_functions(b[0], b[1], b[2]);
    std::array<T, 3> s{{T(0.), T(0.), T(0.)}};
    for (int i = 0; i < 3; ++i) {
      const std::array<T, 3> p = side_vertex(f, i, b);
      for (std::size_t c = 0; c < 3; ++c)
        s[c] += w[std::size_t(i)] * p[c];
    }
    return s;
  }

  /*!
    evaluates the side-vertex surface \f$S_i\f$ of corner `i` of face `f`.
    \tparam T `double` or a `Taylor_jet`
    \pre `b[j] + b[k]` \f$\ne 0\f$ for the other two corners (not at corner `i`)
    \param f a face index
    \param i the corner, 0, 1 or 2
    \param b the barycentric coordinates of the face's corners
    \returns the point of \f$S_i\f$ (or its jet)
  */
  template <class T>
  std::array<T, 3> side_vertex(std::size_t f, int i, const std::array<T, 3>& b) const {
    const std::size_t j = std::size_t((i + 1) % 3), k = std::size_t((i + 2) % 3);
    const std::array<std::size_t, 3>& corner = m_corners[f];
    const std::size_t e = opposite_edge(f, std::size_t(i));
    const std::array<std::size_t, 2> ab = edge_vertices(e);
    // the edge's own parameter, from the same numbers in both faces of the edge
    const T& b_first = corner[j] == ab[0] ? b[j] : b[k];
    const T& b_second = corner[j] == ab[0] ? b[k] : b[j];
    const T t = b_second / (b_first + b_second);
    std::array<T, 3> q, dq;
    curve(e, t, q, dq);
    // the edge's tangent plane: interpolated end normals, orthogonal to the curve
    const Vec3 &na = m_normal[ab[0]], &nb = m_normal[ab[1]];
    std::array<T, 3> n;
    for (std::size_t c = 0; c < 3; ++c)
      n[c] = (1.0 - t) * na[c] + t * nb[c];
    n = reject(n, dq);
    const Vec3& V = m_position[corner[std::size_t(i)]];
    std::array<T, 3> d;
    for (std::size_t c = 0; c < 3; ++c)
      d[c] = q[c] - V[c];
    std::array<T, 3> nv;
    for (std::size_t c = 0; c < 3; ++c)
      nv[c] = T(m_normal[corner[std::size_t(i)]][c]);
    const std::array<T, 3> t0 = reject(d, nv), t1 = reject(d, n);
    // cubic Hermite basis at s = 1 - b_i: exactly (0, 1, 0, 0) on the opposite edge
    const T s = 1.0 - b[std::size_t(i)];
    const T s2 = s * s, s3 = s2 * s;
    const T h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h01 = 3.0 * s2 - 2.0 * s3, h10 = s3 - 2.0 * s2 + s,
            h11 = s3 - s2;
    std::array<T, 3> r;
    for (std::size_t c = 0; c < 3; ++c)
      r[c] = h00 * V[c] + h01 * q[c] + h10 * t0[c] + h11 * t1[c];
    return r;
  }

  /*!
    \param f a face
    \param w barycentric weights of the face's corners
    \returns the point of the surface of `f` at `w` (the vertex at a corner)
  */
  Point_3 evaluate(face_descriptor f, const Weights& w) const {
    const Vec3 p = point(std::size_t(f), w);
    return Point_3(p[0], p[1], p[2]);
  }

  /*!
    \param f a face index
    \param w barycentric weights of the face's corners
    \pre `f` is below the mesh's number of faces
    \returns the point of the surface of face `f` at `w` (the vertex at a corner)
  */
  Vec3 point(std::size_t f, const Weights& w) const {
    CGAL_precondition(f < m_corners.size());
    const int c = corner_of(w);
    if (c >= 0)
      return m_position[m_corners[f][std::size_t(c)]];
    return blend(f, w);
  }

  /*!
    returns the first and second derivatives of the surface of face `f` with respect to
    \f$(w_1, w_2)\f$ at `w`, from jets. At a corner \f$i\f$: the first derivatives are the
    limit (those of \f$S_{i+1}\f$), the second ones those at distance `corner_offset` along
    the median (see the class description).
    \param f a face index
    \param w barycentric weights of the face's corners
    \pre `f` is below the mesh's number of faces
    \returns the derivatives
  */
  Surface_derivatives derivatives(std::size_t f, const Weights& w) const {
    CGAL_precondition(f < m_corners.size());
    const int c = corner_of(w);
    if (c < 0)
      return to_derivatives(blend(f, jets(w)));
    Weights inside;
    for (std::size_t a = 0; a < 3; ++a)
      inside[a] = (1 - corner_offset) * w[a] + corner_offset / 3;
    Surface_derivatives d = to_derivatives(blend(f, jets(inside)));
    const Surface_derivatives first = to_derivatives(side_vertex(f, (c + 1) % 3, jets(w)));
    d.fx = first.fx;
    d.fy = first.fy;
    return d;
  }

  /*!
    the sample of `measure_closed_surface()` and `tessellate_closed_surface()`: point, unit
    normal and Gaussian curvature from `derivatives()`; at a corner the point is the vertex
    and the normal the vertex normal.
    \param f a face
    \param w barycentric weights of the face's corners
    \returns the sample
  */
  Surface_sample operator()(face_descriptor f, const Weights& w) const {
    return sample(std::size_t(f), w);
  }

  /*!
    \param f a face index
    \param w barycentric weights of the face's corners
    \returns the sample of face `f` at `w` (see `operator()`)
  */
  Surface_sample sample(std::size_t f, const Weights& w) const {
    Surface_sample s;
    s.point = point(f, w);
    const Surface_curvature k = surface_curvature(derivatives(f, w));
    s.normal = k.normal;
    s.gaussian = k.gaussian;
    s.regular = k.regular;
    const int c = corner_of(w);
    if (c >= 0) {
      s.normal = m_normal[m_corners[f][std::size_t(c)]];
      s.regular = true;
    }
    return s;
  }
  /// @}

private:
  // The PN edge point next to p, exactly as `pn_triangles()` computes it, with a tangent
  // that must exist.
  Vec3 tangent_point(const Vec3& p, const Vec3& q, const Vec3& n, std::size_t v) const {
    const Vec3 d = internal::difference(q, p);
    const double w = internal::dot(d, n); // n is unit
    const Vec3 t = internal::difference(d, internal::scaled(n, w));
    if (!(internal::norm(t) > 1e-12 * internal::norm(d)))
      throw Invalid_input("Nielson: an edge of vertex " + std::to_string(v) +
                          " is parallel to its normal (no tangent)");
    Vec3 r;
    for (std::size_t c = 0; c < 3; ++c)
      r[c] = (2 * p[c] + q[c] - w * n[c]) / 3;
    return r;
  }

  // The edge opposite corner i of face f.
  std::size_t opposite_edge(std::size_t f, std::size_t i) const {
    // corner 0 = target(h0), 1 = target(next(h0)), 2 = source(h0): next(h0) joins 0 and 1
    auto h =
        m_mesh.next(m_mesh.halfedge(face_descriptor(static_cast<typename Mesh::size_type>(f))));
    for (std::size_t a = 0; a < (i + 1) % 3; ++a)
      h = m_mesh.next(h);
    return std::size_t(m_mesh.edge(h));
  }

  // Bernstein form of the edge curve and its derivative.
  template <class T>
  void curve(std::size_t e, const T& t, std::array<T, 3>& q, std::array<T, 3>& dq) const {
    const std::array<Vec3, 4>& c = m_curves[e];
    const T u = 1.0 - t;
    const T b0 = u * u * u, b1 = 3.0 * u * u * t, b2 = 3.0 * u * t * t, b3 = t * t * t;
    const T d0 = 3.0 * u * u, d1 = 6.0 * u * t, d2 = 3.0 * t * t;
    for (std::size_t a = 0; a < 3; ++a) {
      q[a] = b0 * c[0][a] + b1 * c[1][a] + b2 * c[2][a] + b3 * c[3][a];
      dq[a] = d0 * (c[1][a] - c[0][a]) + d1 * (c[2][a] - c[1][a]) + d2 * (c[3][a] - c[2][a]);
    }
  }

  // x minus its component along n (n nonzero, not necessarily unit).
  template <class T>
  static std::array<T, 3> reject(const std::array<T, 3>& x, const std::array<T, 3>& n) {
    const T k =
        (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]) / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return {{x[0] - k * n[0], x[1] - k * n[1], x[2] - k * n[2]}};
  }

  // The corner whose weight is the only nonzero one, or -1.
  static int corner_of(const Weights& w) {
    int zeros = 0, other = -1;
    for (int a = 0; a < 3; ++a)
      if (w[std::size_t(a)] == 0)
        ++zeros;
      else
        other = a;
    return zeros >= 2 ? other : -1;
  }

  // Jets of the barycentric coordinates in the variables (w1, w2); w0 keeps its value.
  static std::array<Jet, 3> jets(const Weights& w) {
    return {{Jet::affine(w[0], -1, -1, 2), Jet::variable(w[1], 0, 2), Jet::variable(w[2], 1, 2)}};
  }

  static Surface_derivatives to_derivatives(const std::array<Jet, 3>& p) {
    return Mesh_blending_surface<Point_3>::to_derivatives(p);
  }

  Mesh m_mesh;
  bool m_estimated_normals = true;
  std::vector<Vec3> m_position, m_normal;
  std::vector<std::array<std::size_t, 3>> m_corners;
  std::vector<std::array<Vec3, 4>> m_curves;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_COMPARATORS_NIELSON_SIDE_VERTEX_H

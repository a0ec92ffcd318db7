// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_MESH_BLENDING_SURFACE_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_MESH_BLENDING_SURFACE_H

#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/Blending/blending_functions.h>
#include <CGAL/Triangular_spline/Blending/vertex_surfaces.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/array_vector_3.h>
#include <CGAL/Triangular_spline/internal/blending_arithmetic.h>
#include <CGAL/Triangular_spline/internal/blending_geometry.h>
#include <CGAL/Triangular_spline/internal/blending_mesh.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the edge-to-face reparameterization of Fang's mesh interpolation algorithm.
*/
enum class Blending_variant {
  /// the basic algorithm (ch.\ 5, eq.\ 5.8; multi-sided eq.\ 7.2): one affine (similarity)
  /// map per face side; \f$C^d\f$ across edges, only normals (\f$d \ge 1\f$) continuous at
  /// the vertices
  BASIC,
  /// improved with vertex continuity (§6.1, eqs.\ 6.8–6.11; multi-sided §7.3, eqs.\ 7.6–7.8):
  /// two affine maps blended so that each face is \f$C^d\f$ at its corners in the
  /// vertex frames
  VERTEX_CONTINUITY,
  /// improved with open-set continuity (§6.2, eqs.\ 6.18–6.21): the affine maps are used
  /// unblended near the corners, so the surface is \f$C^d\f$ in the vertex frame on a
  /// neighbourhood of every vertex. For multi-sided faces (not in the thesis) the
  /// neighbourhoods are the discs of radius 1/3 of the side around its ends, and the blend
  /// indicators are the distances to these discs.
  ///
  /// Eqs. 6.20/6.21 are implemented relabelled. With the labels of eq. 6.18 (\f$u\f$,
  /// \f$v\f$, \f$1-u-v\f$ the weights of \f$V_0\f$, \f$V_1\f$, \f$V_2\f$; the side
  /// runs from \f$V_0\f$ to \f$V_2\f$) the printed equations use \f$r_{V_0}\f$ where
  /// \f$u + v < 1/3\f$, i.e. near \f$V_2\f$, and \f$r_{V_2}\f$ where \f$v > 2/3\f$, near
  /// the opposite corner \f$V_1\f$; at \f$V_0\f$ they blend both maps evenly, and the
  /// surface is then not even \f$C^1\f$ at the vertices. We read them with \f$(u, v)\f$
  /// replaced by \f$(v, 1-u-v)\f$: \f$r_{V_0}\f$ where \f$u > 2/3\f$, \f$r_{V_2}\f$
  /// where \f$u + v < 1/3\f$, otherwise \f$f_0 r_{V_0} + f_1 r_{V_2}\f$ with
  /// \f$b^r = (2/3 - u,\; u + v - 1/3)\f$, which is what the text describes (the uniformly mapped
  /// portions
  /// at \f$V_0\f$ and \f$V_2\f$, Fig. 6.6) and what Thm. 6.2 needs. The test
  /// `OpenSetLabels.PrintedLabelsBreakVertexContinuityOursHold`
  /// builds both readings from the public frame maps: ours meets the vertex surfaces to
  /// order \f$d\f$ at every corner, the printed one differs at order 1.
  OPEN_SET
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns "basic", "vertex" or "open" (the names of the command-line tool).
  \param v the variant
  \returns "basic", "vertex" or "open" (the names of the command-line tool)
*/
inline const char* to_string(Blending_variant v) {
  switch (v) {
  case Blending_variant::BASIC:
    return "basic";
  case Blending_variant::VERTEX_CONTINUITY:
    return "vertex";
  case Blending_variant::OPEN_SET:
    return "open";
  }
  return "?";
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief how the vertex surfaces \f$S^V\f$ are built (Fang §5.2.1).
*/
enum class Vertex_surface_method {
  /// de Boor and Ron's least interpolant of the vertex (value and zero gradient in its
  /// frame) and its neighbours (`least_interpolant()`), as in the thesis
  LEAST,
  /// the polynomial of degree `Mesh_blending_options::least_squares_degree` through the
  /// vertex with its normal, fitting the neighbours in the least-squares sense
  /// (`least_squares_polynomial()`)
  LEAST_SQUARES,
  /// the polynomial of degree `Mesh_blending_options::normals_degree` through the vertex
  /// with its normal and through its neighbours, fitting the neighbours' normals in the
  /// least-squares sense (minimum-norm when they do not determine all coefficients); the
  /// degree is raised while the positions cannot be interpolated (high valence, or
  /// neighbours on a curve of the degree). Not in the thesis, whose §9 suggests
  /// interpolating more data: on coarse meshes these vertex surfaces are far more accurate,
  /// and the blend amplifies their disagreement less (user manual, "Where the Curvature
  /// Comes From").
  LEAST_SQUARES_NORMALS
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the options of `Mesh_blending_surface`.
*/
struct Mesh_blending_options {
  int order = 2;                                         ///< the blending order \f$d \ge 0\f$
  Blending_variant variant = Blending_variant::OPEN_SET; ///< the reparameterization
  Vertex_surface_method vertex_surface = Vertex_surface_method::LEAST; ///< the vertex surfaces
  int least_squares_degree = 2;   ///< degree of the `LEAST_SQUARES` vertex surfaces (>= 1)
  int normals_degree = 4;         ///< degree of the `LEAST_SQUARES_NORMALS` vertex surfaces (>= 2)
  double least_tolerance = 1e-10; ///< rank threshold of `least_interpolant()`
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the size of a tessellation of a `Mesh_blending_surface`, the Gaussian curvature
  range at its vertices, and the time it took.
*/
struct Blending_tessellation_statistics {
  std::size_t vertices = 0;          ///< number of mesh vertices
  std::size_t faces = 0;             ///< number of mesh triangles
  std::size_t singular_points = 0;   ///< vertices where the surface is singular (no normal)
  double min_gaussian_curvature = 0; ///< smallest Gaussian curvature at a vertex
  double max_gaussian_curvature = 0; ///< largest Gaussian curvature at a vertex
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief Fang's mesh interpolation surface (ch. 5–7): a surface through the vertices of a
  polygon mesh with their normals, made of one blended patch per face, \f$C^d\f$ across the
  edges in the edge frames and (improved variants) at the vertices in the vertex frames.

  The five steps of §5.2, computed at construction (1–2) and at evaluation (3–5):
  1. **Vertex frames and surfaces.** For vertex \f$V\f$ with unit normal \f$n\f$: origin
     \f$V\f$, \f$z\f$ along \f$n\f$, \f$x\f$ towards the projection of the first neighbour
     (of the halfedge circulator) to the tangent plane, whose distance is the unit length
     \f$L\f$. The vertex surface is the graph \f$z = P(x, y)\f$ of a polynomial with
     \f$P(0) = 0\f$, \f$\nabla P(0) = 0\f$ (so it interpolates \f$V\f$ and \f$n\f$) through
     the neighbours (de Boor–Ron least interpolant) or fitting them (least squares); in
     space \f$S^V(x,y) = V + L(x e_x + y e_y + P(x,y) n)\f$.
  2. **Vertex → edge reparameterization** (eq. 5.4). Edge \f$E\f$ has head \f$H\f$ (the
     source of its halfedge 0) at \f$(0,0)\f$ and tail \f$T\f$ at \f$(0,1)\f$; the map into
     a vertex frame is the similarity sending them to the projections of \f$H, T\f$.
  3. **Edge surfaces** (eq. 5.6): binary blend \f$S^E = f_0 S^H_E + f_1 S^T_E\f$ with
     indicators \f$(y, 1-y)\f$.
  4. **Edge → face reparameterization.** Triangles use barycentric coordinates
     \f$(\lambda_0, \lambda_1, \lambda_2)\f$ of their corners (the order of
     `vertices_around_face(halfedge(f))`); the face parameter is \f$(a, b) = (\lambda_0,
     \lambda_1)\f$. Faces with more sides use the face frame of §7.2.1 (origin the vertex
     centroid, \f$z\f$ the mean vertex normal, \f$x\f$ towards corner 0, whose distance is
     the unit) and their projected polygon, which must be strictly convex. The map of a
     side into its edge frame is the variant's (`Blending_variant`).
  5. **Face surfaces**: triangular blend (eq. 5.10) with indicators \f$\lambda_i\f$,
     sub-surface \f$i\f$ = the edge opposite corner \f$i\f$; multi-sided blend (eq. 7.5)
     with the distances to the sides, sub-surface \f$i\f$ = the side from corner \f$i\f$ to
     \f$i+1\f$.

  Everything is evaluated by formulas that are generic in the scalar type: with `double`
  they give points, with `Taylor_jet<double>` all derivatives (exactly, up to round-off) —
  this is how normals, curvatures and the continuity measurements
  (`blending_continuity.h`) are computed.

  Square roots (normalised normals, frame axes, distances) are unavoidable in Fang's
  construction, so it is computed in `double` whatever the kernel of the input mesh (the
  kernel's points are converted with `CGAL::to_double()`).

  The input is any `PolygonMesh` (a model of `FaceListGraph` and `HalfedgeListGraph`, such
  as `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`), read once through its property maps; the
  surface keeps no copy of it. Vertices, edges and faces are numbered by the mesh's index
  maps (`CGAL::get_initialized_vertex_index_map()` and its edge and face versions, or those
  given as named parameters): for a `Surface_mesh` without removed elements the number of
  `v` is `std::size_t(v)`. Every accessor and evaluation takes these numbers.

  Where the package shares code and where not (user manual, "Software Design"): the vertex
  heights are the package's one polynomial class (`Polynomial_surface`, via
  `Bivariate_polynomial`), vectors and normals use the package's `std::array` helpers and
  `surface_curvature()`. Fang's surface itself is not a network of polynomial patches (its
  blending weights are rational with square roots, its face domains are not triangles of a
  planar domain), so it is not a `TriangularSplineNetwork` and `tessellate()` of
  `tessellate.h` does not apply; `tessellate_closed_surface()` applies to triangle meshes
  through `Mesh_blending_sampler`, and this class's own `tessellate()` covers what it
  cannot: any number of segments, faces with more than three sides, mean curvature, and
  the vertex order of `tspline blend`'s output.

  \tparam Point_3 the point type returned by `evaluate()`, of any CGAL kernel: for a mesh,
  the value type of its vertex point map
*/
template <class Point_3>
class Mesh_blending_surface {
public:
  /// the input type of the convenience constructor
  using Mesh = CGAL::Surface_mesh<Point_3>;
  /// the kernel of the points
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;
  /// its vector type
  using Vector_3 = typename Kernel::Vector_3;
  /// the jets used for derivatives: measured orders are at most `Jet::max_order`
  using Jet = Taylor_jet<double, 6>;
  /// the smaller jets used for normals and curvatures (orders up to 2: faster)
  using Curvature_jet = Taylor_jet<double, 2>;
  /// a point or vector of the plane
  using Vec2 = std::array<double, 2>;
  /// a point or vector of space
  using Vec3 = std::array<double, 3>;
  /// the face index type of a `Mesh`
  using face_descriptor = typename Mesh::Face_index;
  /// the vertex index type of a `Mesh`
  using vertex_descriptor = typename Mesh::Vertex_index;

  /*!
    builds the vertex frames and surfaces and the edge and face reparameterizations of
    `mesh`.

    The normals are those of `vertex_normal_map` if given; otherwise, for a
    `CGAL::Surface_mesh`, those of its vertex property `"v:normal"` (the kernel's
    `Vector_3`) if it has one; otherwise the normalised mean of the unit normals of the
    incident faces (as Fang does for the perturbed mesh, §8.2). Given normals need not be
    unit vectors.

    \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph`
    \tparam NamedParameters a sequence of named parameters

    \param mesh the input mesh, closed or with borders, consistently oriented
    \param options the blending options (order, variant, ...)
    \param np an optional sequence of named parameters among the ones listed below

    \cgalNamedParamsBegin
      \cgalParamNBegin{vertex_point_map}
        \cgalParamDescription{a property map associating a position to each vertex of `mesh`}
        \cgalParamType{a model of `ReadablePropertyMap` with key type
                       `boost::graph_traits<PolygonMesh>::%vertex_descriptor` and a value type
                       with `x()`, `y()`, `z()` convertible by `CGAL::to_double()`}
        \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
      \cgalParamNEnd
      \cgalParamNBegin{vertex_normal_map}
        \cgalParamDescription{a property map associating a normal to each vertex of `mesh`}
        \cgalParamType{a model of `ReadablePropertyMap` with key type
                       `boost::graph_traits<PolygonMesh>::%vertex_descriptor` and a vector value
                       type with `x()`, `y()`, `z()`}
        \cgalParamDefault{`"v:normal"` of a `Surface_mesh`, otherwise estimated normals}
      \cgalParamNEnd
      \cgalParamNBegin{vertex_index_map}
        \cgalParamDescription{a property map associating to each vertex of `mesh` a unique
                              index between `0` and `num_vertices(mesh) - 1`}
        \cgalParamType{a model of `ReadablePropertyMap` with key type
                       `boost::graph_traits<PolygonMesh>::%vertex_descriptor` and value type
                       `std::size_t`}
        \cgalParamDefault{an automatically indexed internal map}
      \cgalParamNEnd
      \cgalParamNBegin{edge_index_map}
        \cgalParamDescription{a property map associating to each edge of `mesh` a unique index
                              between `0` and `num_edges(mesh) - 1`}
        \cgalParamType{a model of `ReadablePropertyMap` with key type
                       `boost::graph_traits<PolygonMesh>::%edge_descriptor` and value type
                       `std::size_t`}
        \cgalParamDefault{an automatically indexed internal map}
      \cgalParamNEnd
      \cgalParamNBegin{face_index_map}
        \cgalParamDescription{a property map associating to each face of `mesh` a unique index
                              between `0` and `num_faces(mesh) - 1`}
        \cgalParamType{a model of `ReadablePropertyMap` with key type
                       `boost::graph_traits<PolygonMesh>::%face_descriptor` and value type
                       `std::size_t`}
        \cgalParamDefault{an automatically indexed internal map}
      \cgalParamNEnd
    \cgalNamedParamsEnd

    \throws Invalid_input naming the element if: `order` < 0 or a degree of the vertex
    surfaces is too small; the mesh has no face, is not a valid polygon mesh, is a
    `Surface_mesh` with removed elements, has an isolated or non-manifold vertex, a
    coordinate that is not finite, or index maps that are not \f$0, \dots, n - 1\f$; a
    face has zero area; a normal is zero, not finite, or points against the orientation of
    the incident faces; an estimated normal vanishes; all neighbours of a vertex project
    onto its normal line; an edge is parallel to the normal of one of its vertices; the
    vertex surface conditions are dependent; a face with more than three sides has a zero
    mean normal or a projection that is not strictly convex (§7.1).
  */
  template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Mesh_blending_surface(const PolygonMesh& mesh, const Mesh_blending_options& options,
                        const NamedParameters& np = CGAL::parameters::default_values())
      : m_options(options) {
    check_options();
    build(internal::read_blending_mesh(mesh, np, "blending"));
  }

  /*!
    builds the surface of a `CGAL::Surface_mesh` with its `"v:normal"` property if it has
    one (see the generic constructor). A mesh with removed elements is accepted: the surface
    is built from a copy with its garbage collected, and its indices are that copy's (those
    `collect_garbage()` gives).
    \throws Invalid_input as the generic constructor
    \param mesh the input mesh
    \param options the blending options (order, variant, ...)
  */
  explicit Mesh_blending_surface(const Mesh& mesh, const Mesh_blending_options& options = {})
      : m_options(options) {
    check_options();
    if (mesh.has_garbage()) {
      Mesh collected(mesh);
      collected.collect_garbage();
      build(
          internal::read_blending_mesh(collected, CGAL::parameters::default_values(), "blending"));
    } else {
      build(internal::read_blending_mesh(mesh, CGAL::parameters::default_values(), "blending"));
    }
  }

  /// \name Access
  /// @{

  /// returns the options.
  /// \returns the options
  const Mesh_blending_options& options() const { return m_options; }
  /// returns the blending order \f$d\f$.
  /// \returns the blending order \f$d\f$
  int order() const { return m_options.order; }
  /// returns the variant.
  /// \returns the variant
  Blending_variant variant() const { return m_options.variant; }
  /// returns `true` if the vertex normals were estimated from the faces.
  /// \returns `true` if the vertex normals were estimated from the faces
  bool has_estimated_normals() const { return m_estimated_normals; }
  /// returns the number of affine edge-to-face maps that reverse orientation (a face whose
  /// opposite corner projects across the edge in a vertex frame): a sign of a mesh too
  /// sharp for its normals; the surface is still defined but may fold there.
  /// \returns the number of orientation-reversing edge-to-face maps
  std::size_t number_of_folded_maps() const { return m_folded; }
  /// returns the number of vertices.
  /// \returns the number of vertices
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  /// returns the number of edges.
  /// \returns the number of edges
  std::size_t number_of_edges() const { return m_edges.size(); }
  /// returns the number of faces.
  /// \returns the number of faces
  std::size_t number_of_faces() const { return m_faces.size(); }
  /// returns the number of corners (= sides) of face `f`.
  /// \param f the index of a face
  /// \returns the number of corners (= sides) of face `f`
  std::size_t face_size(std::size_t f) const { return m_faces.at(f).vertex.size(); }
  /// returns the vertex at corner `c` of face `f`.
  /// \param f the index of a face
  /// \param c the index of a corner of face `f`
  /// \returns the vertex at corner `c` of face `f`
  std::size_t face_vertex(std::size_t f, std::size_t c) const { return m_faces.at(f).vertex.at(c); }
  /// returns the unit normal of vertex `v` used by the construction.
  /// \param v the index of a vertex
  /// \returns the unit normal of vertex `v` used by the construction
  const Vec3& vertex_normal(std::size_t v) const { return m_vertices.at(v).normal; }
  /// returns the position of vertex `v`.
  /// \param v the index of a vertex
  /// \returns the position of vertex `v`
  const Vec3& vertex_position(std::size_t v) const { return m_vertices.at(v).position; }
  /// returns the height polynomial \f$P\f$ of the vertex surface of `v` in its frame.
  /// \param v the index of a vertex
  /// \returns the height polynomial \f$P\f$ of the vertex surface of `v` in its frame
  const Bivariate_polynomial& vertex_height(std::size_t v) const { return m_vertices.at(v).height; }
  /*!
    replaces the height polynomial of the vertex surface of `v` (in its frame, see
    `to_vertex_frame()`): user guidance, or a surface known better than from the 1-ring (Fang
    §9 lists both as future work). The surface still interpolates the vertex with its normal,
    so \f$P(0,0)\f$ and the gradient at the origin must be zero; the neighbours need not be
    interpolated. Only evaluation uses the vertex surfaces: no other state is rebuilt.

    \throws Invalid_input if `v` is out of range or \f$P(0,0)\f$, \f$P_x(0,0)\f$,
    \f$P_y(0,0)\f$ is not zero or a coefficient is not finite
    \param v the index of a vertex
    \param height the new height polynomial, in the frame of `v`
  */
  void set_vertex_height(std::size_t v, const Bivariate_polynomial& height) {
    if (v >= m_vertices.size())
      throw Invalid_input("blending: no vertex " + std::to_string(v));
    for (int h = 0; h <= height.degree(); ++h)
      for (int k = 0; h + k <= height.degree(); ++k)
        if (!std::isfinite(height.coefficient(h, k)))
          throw Invalid_input("blending: the height of vertex " + std::to_string(v) +
                              " has a coefficient that is not finite");
    const bool linear = height.degree() >= 1; // coefficients exist up to the degree only
    if (height.coefficient(0, 0) != 0 ||
        (linear && (height.coefficient(1, 0) != 0 || height.coefficient(0, 1) != 0)))
      throw Invalid_input("blending: the height of vertex " + std::to_string(v) +
                          " must vanish with its gradient at the origin (interpolating the "
                          "vertex and its normal)");
    m_vertices[v].height = height;
  }
  /// returns the unit length \f$L\f$ of the frame of vertex `v`.
  /// \param v the index of a vertex
  /// \returns the unit length \f$L\f$ of the frame of vertex `v`
  double vertex_scale(std::size_t v) const { return m_vertices.at(v).scale; }
  /// returns the head and tail vertices of edge `e`.
  /// \param e the index of an edge
  /// \returns the head and tail vertices of edge `e`
  std::array<std::size_t, 2> edge_vertices(std::size_t e) const {
    return {{m_edges.at(e).head, m_edges.at(e).tail}};
  }
  /// returns the faces incident to edge `e` and, for each, the side of that face lying on
  /// `e` (one pair for a border edge).
  /// \param e the index of an edge
  /// \returns the pairs (face, side) of the faces incident to `e`
  std::vector<std::pair<std::size_t, std::size_t>> edge_sides(std::size_t e) const {
    return m_edges.at(e).sides;
  }
  /// returns the parameter of corner `c` of face `f`: \f$(1,0)\f$, \f$(0,1)\f$, \f$(0,0)\f$
  /// for a triangle, the projected corner in the face frame otherwise.
  /// \param f the index of a face
  /// \param c the index of a corner of face `f`
  /// \returns the parameter of corner `c` of face `f`
  const Vec2& corner_parameter(std::size_t f, std::size_t c) const {
    return m_faces.at(f).corner.at(c);
  }
  /// returns the edge of side `s` of face `f`, and the face corners at its head and tail.
  /// \param f the index of a face
  /// \param s the index of a side of face `f`
  /// \returns the edge of side `s` of face `f`, and the face corners at its head and tail
  std::array<std::size_t, 3> side_edge(std::size_t f, std::size_t s) const {
    const Side& side = m_faces.at(f).sides.at(s);
    return {{side.edge, static_cast<std::size_t>(side.end_corner[0]),
             static_cast<std::size_t>(side.end_corner[1])}};
  }
  /// returns the face parameter of the point of side `s` of face `f` at fraction `t` from the
  /// head of its edge to the tail.
  /// \param f the index of a face
  /// \param s the index of a side of face `f`
  /// \param t the fraction of the way from the head of the edge to its tail
  /// \returns the face parameter of the point
  Vec2 side_point(std::size_t f, std::size_t s, double t) const {
    const Face_data& F = m_faces.at(f);
    const Side& side = F.sides.at(s);
    const Vec2& h = F.corner[static_cast<std::size_t>(side.end_corner[0])];
    const Vec2& e = F.corner[static_cast<std::size_t>(side.end_corner[1])];
    return {{h[0] + t * (e[0] - h[0]), h[1] + t * (e[1] - h[1])}};
  }
  /// returns the projection \f$\pi_V(q)\f$ of a point to the frame of vertex `v`.
  /// \param v the index of a vertex
  /// \param q the point to project
  /// \returns the projection \f$\pi_V(q)\f$ of a point to the frame of vertex `v`
  Vec2 to_vertex_frame(std::size_t v, const Vec3& q) const {
    const Vertex_data& V = m_vertices.at(v);
    const Vec3 d = internal::difference(q, V.position);
    return {{internal::dot(d, V.ex) / V.scale, internal::dot(d, V.ey) / V.scale}};
  }
  /*!
    returns the affine map \f$A_{F,V}\f$ from the parameters of face `f` to the frame of the
    vertex at its corner `c` that sends corner `c` to the origin and the two adjacent
    corners to their projections \f$\pi_V\f$ — the map the improved reparameterizations
    reproduce at the corner (Fang, Fig. 6.2, the "blue" triangle), as coefficients
    \f$(m_0, \dots, m_5)\f$ of \f$(x, y) = (m_0 a + m_1 b + m_2, m_3 a + m_4 b + m_5)\f$.
    \param f the index of a face
    \param c the index of a corner of face `f`
    \returns the coefficients of the affine map \f$A_{F,V}\f$
  */
  std::array<double, 6> face_to_vertex_frame(std::size_t f, std::size_t c) const {
    return vertex_map(f, c).m;
  }
  /// @}

  /// \name Evaluation
  /// All are generic in the scalar `T`: `double` or `Jet` (derivatives).
  /// @{

  /// returns \f$S^V(x, y)\f$, the vertex surface of `v` at frame coordinates \f$(x, y)\f$.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param v the index of a vertex
  /// \param x the first frame coordinate
  /// \param y the second frame coordinate
  /// \returns \f$S^V(x, y)\f$, the vertex surface of `v` at frame coordinates \f$(x, y)\f$
  template <class T>
  std::array<T, 3> vertex_surface(std::size_t v, const T& x, const T& y) const {
    const Vertex_data& V = m_vertices[v];
    const T z = V.height(x, y);
    std::array<T, 3> p;
    for (std::size_t c = 0; c < 3; ++c) {
      const T coordinate = (x * V.ex[c] + y * V.ey[c] + z * V.normal[c]) * V.scale + V.position[c];
      p[c] = coordinate;
    }
    return p;
  }

  /// returns the map \f$r^{E,V}\f$ (eq.\ 5.4) from the frame of edge `e` to the frame of its
  /// end `end` (0: head, 1: tail).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param e the index of an edge
  /// \param end the end of the edge: 0 for its head, 1 for its tail
  /// \param x the first frame coordinate
  /// \param y the second frame coordinate
  /// \returns the map \f$r^{E,V}\f$ applied to the point
  template <class T>
  std::array<T, 2> edge_to_vertex(std::size_t e, int end, const T& x, const T& y) const {
    const Edge_data& E = m_edges[e];
    const Vec2& h = E.head_in[end];
    const Vec2& t = E.tail_in[end];
    const T X = x * (t[1] - h[1]) + y * (t[0] - h[0]) + h[0];
    const T Y = x * (h[0] - t[0]) + y * (t[1] - h[1]) + h[1];
    return {{X, Y}};
  }

  /// returns \f$S^E(x, y)\f$, the edge surface of `e` (eq.\ 5.6).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param e the index of an edge
  /// \param x the first frame coordinate
  /// \param y the second frame coordinate
  /// \returns \f$S^E(x, y)\f$, the edge surface of `e` (eq. 5.6)
  template <class T>
  std::array<T, 3> edge_surface(std::size_t e, const T& x, const T& y) const {
    const T other = 1.0 - y;
    const std::vector<T> f = blending_functions(std::vector<T>{y, other}, order());
    std::array<T, 3> p;
    bool first = true;
    for (int end = 0; end < 2; ++end) {
      if constexpr (std::is_same<T, double>::value)
        if (f[static_cast<std::size_t>(end)] == 0)
          continue;
      const std::array<T, 2> q = edge_to_vertex(e, end, x, y);
      const std::size_t v = end == 0 ? m_edges[e].head : m_edges[e].tail;
      const std::array<T, 3> s = vertex_surface(v, q[0], q[1]);
      for (std::size_t c = 0; c < 3; ++c) {
        const T term = f[static_cast<std::size_t>(end)] * s[c];
        p[c] = first ? term : p[c] + term;
      }
      first = false;
    }
    return p;
  }

  /// returns the map \f$r^{F,E}\f$ from the parameters of face `f` to the frame of the
  /// edge of its side `s`, as the variant defines it.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param f the index of a face
  /// \param s the index of a side of face `f`
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the map \f$r^{F,E}\f$ applied to the point
  template <class T>
  std::array<T, 2> face_to_edge(std::size_t f, std::size_t s, const T& a, const T& b) const {
    const Face_data& F = m_faces[f];
    const Side& side = F.sides[s];
    const int d = order();
    switch (variant()) {
    case Blending_variant::BASIC:
      return side.basic(a, b);
    case Blending_variant::VERTEX_CONTINUITY: {
      std::vector<T> w;
      if (F.triangle) {
        const T opposite_half = barycentric(F, side.opposite, a, b) * 0.5;
        const T bh = 1.0 - barycentric(F, side.end_corner[0], a, b) - opposite_half;
        const T bt = 1.0 - barycentric(F, side.end_corner[1], a, b) - opposite_half;
        w = blending_functions(std::vector<T>{bh, bt}, d);
      } else {
        w = blending_functions_of_powers(std::vector<T>{
            internal::power_of_distance(squared_distance(F, side.end_corner[0], a, b), d),
            internal::power_of_distance(squared_distance(F, side.end_corner[1], a, b), d)});
      }
      return mix(w, side.at_end[0], side.at_end[1], a, b);
    }
    case Blending_variant::OPEN_SET: {
      std::vector<T> indicators;
      if (F.triangle) {
        // eqs. 6.20/6.21 relabelled (see Blending_variant::OPEN_SET): eq. 6.18's u is lh
        // (V0, the head), 1 - u - v is lt (V2, the tail); (u, v) -> (v, 1 - u - v) turns the
        // printed "u + v < 1/3" into lh > 2/3, "v > 2/3" into lt > 2/3 and b^r into
        // (2/3 - lh, 2/3 - lt)
        const T lh = barycentric(F, side.end_corner[0], a, b);
        const T lt = barycentric(F, side.end_corner[1], a, b);
        const double third2 = 2.0 / 3.0;
        if (internal::value_of(lh) > third2)
          return side.at_end[0](a, b);
        if (internal::value_of(lt) > third2)
          return side.at_end[1](a, b);
        indicators = {third2 - lh, third2 - lt};
      } else {
        const T qh = squared_distance(F, side.end_corner[0], a, b);
        const T qt = squared_distance(F, side.end_corner[1], a, b);
        if (internal::value_of(qh) < side.radius * side.radius)
          return side.at_end[0](a, b);
        if (internal::value_of(qt) < side.radius * side.radius)
          return side.at_end[1](a, b);
        using std::sqrt;
        indicators = {T(sqrt(qh)) - side.radius, T(sqrt(qt)) - side.radius};
      }
      return mix(blending_functions(indicators, d), side.at_end[0], side.at_end[1], a, b);
    }
    }
    return side.basic(a, b);
  }

  /// returns the inheritance indicators of face `f` at parameter \f$(a, b)\f$: the
  /// barycentric coordinates of a triangle (Def.\ 4.2), the distances to the side lines of a
  /// polygon (Def.\ 7.2; exactly zero at the corners).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param f the index of a face
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the inheritance indicators, one per side of `f`
  template <class T>
  std::vector<T> face_indicators(std::size_t f, const T& a, const T& b) const {
    const Face_data& F = m_faces[f];
    if (F.triangle) {
      const T w = 1.0 - a - b;
      return {a, b, w};
    }
    std::vector<T> m;
    const std::size_t n = F.corner.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& p = F.corner[i];
      const Vec2& q = F.corner[(i + 1) % n];
      const double ex = q[0] - p[0], ey = q[1] - p[1];
      const double length = std::sqrt(ex * ex + ey * ey);
      const T value = ((b - p[1]) * ex - (a - p[0]) * ey) / length;
      m.push_back(value);
    }
    return m;
  }

  /// returns \f$S^F(a, b)\f$, the surface of face `f` at parameter \f$(a, b)\f$ (eqs.\ 5.10,
  /// 7.5).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param f the index of a face
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the point \f$S^F(a, b)\f$
  template <class T>
  std::array<T, 3> face_surface(std::size_t f, const T& a, const T& b) const {
    const Face_data& F = m_faces[f];
    const std::vector<T> w = blending_functions(face_indicators(f, a, b), order());
    std::array<T, 3> p;
    bool first = true;
    for (std::size_t s = 0; s < F.sides.size(); ++s) {
      if constexpr (std::is_same<T, double>::value)
        if (w[s] == 0)
          continue;
      const std::array<T, 3> q = side_surface(f, s, a, b);
      for (std::size_t c = 0; c < 3; ++c) {
        const T term = w[s] * q[c];
        p[c] = first ? term : p[c] + term;
      }
      first = false;
    }
    return p;
  }

  /// returns the sub-surface \f$S^{E}_F = S^E \circ r^{F,E}\f$ of side `s` of face `f`.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param f the index of a face
  /// \param s the index of a side of face `f`
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the sub-surface \f$S^{E}_F = S^E \circ r^{F,E}\f$ of side `s` of face `f`
  template <class T>
  std::array<T, 3> side_surface(std::size_t f, std::size_t s, const T& a, const T& b) const {
    const std::array<T, 2> xy = face_to_edge(f, s, a, b);
    return edge_surface(m_faces[f].sides[s].edge, xy[0], xy[1]);
  }

  /// returns the point of the surface of face `f` at parameter \f$(a, b)\f$.
  /// \param f the index of a face
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the point of the surface of face `f` at parameter \f$(a, b)\f$
  Point_3 evaluate(std::size_t f, double a, double b) const {
    const std::array<double, 3> p = face_surface(f, a, b);
    return Point_3(p[0], p[1], p[2]);
  }

  /// returns the point of the surface of face `fd` of a `Surface_mesh` at parameter
  /// \f$(a, b)\f$: `evaluate(std::size_t(fd), a, b)`.
  /// \param fd a face of the input `Surface_mesh` (without removed elements)
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the point of the surface of face `fd` at parameter \f$(a, b)\f$
  Point_3 evaluate(face_descriptor fd, double a, double b) const {
    return evaluate(static_cast<std::size_t>(fd), a, b);
  }

  /// returns the first and second derivatives of the surface of face `f` with respect to
  /// its parameters at \f$(a, b)\f$ (exact differentiation with jets).
  /// \param f the index of a face
  /// \param a the first face parameter
  /// \param b the second face parameter
  /// \returns the first and second derivatives
  Surface_derivatives derivatives(std::size_t f, double a, double b) const {
    const std::array<Curvature_jet, 3> p =
        face_surface(f, Curvature_jet::variable(a, 0, 2), Curvature_jet::variable(b, 1, 2));
    return to_derivatives(p);
  }

  /// returns the first and second derivatives of a jet-valued point (order \f$\ge 2\f$).
  /// \tparam J a `Taylor_jet` type
  /// \param p the point whose coordinates are jets
  /// \returns the first and second derivatives of a jet-valued point (order \f$\ge 2\f$)
  template <class J>
  static Surface_derivatives to_derivatives(const std::array<J, 3>& p) {
    Surface_derivatives d;
    for (std::size_t c = 0; c < 3; ++c) {
      d.fx[c] = p[c].derivative(1, 0);
      d.fy[c] = p[c].derivative(0, 1);
      d.fxx[c] = p[c].derivative(2, 0);
      d.fxy[c] = p[c].derivative(1, 1);
      d.fyy[c] = p[c].derivative(0, 2);
    }
    return d;
  }
  /// @}

  /*!
    tessellates the surface into the triangle mesh `out` with `resolution` segments per
    edge of the input mesh.

    A triangle face is cut into \f$N^2\f$ triangles at the parameters
    \f$(i/N, j/N)\f$ (\f$N\f$ = `resolution`); a face with \f$n > 3\f$ sides is cut
    into the fan of the \f$n\f$ triangles from the origin of its frame to its sides, each
    cut into \f$N^2\f$. Points shared by faces (input vertices, \f$N - 1\f$ per input
    edge) are one output vertex, so `out` has the topology of the input (closed or not,
    same genus) and faces oriented like it.

    Vertex properties (created if needed): `"v:normal"` (unit normal, `Vector_3` of the
    output kernel; zero where singular), `"v:gaussian_curvature"`, `"v:mean_curvature"`
    (`double`, NaN where singular), from the exact first and second derivatives (jets) of
    the face surface; at an input vertex they are those of its vertex surface, which the
    face surfaces inherit there (exactly for the improved variants and \f$d \ge 2\f$). A
    face property `"f:input_face"` (`std::size_t`) gives the input face of each triangle.
    `out` is cleared first.

    This is not `tessellate()` of `tessellate.h` (whose input is a spline network of
    Bézier patches over a planar domain) nor `tessellate_closed_surface()` (triangles, powers
    of two, vertices numbered face by face), which `Mesh_blending_sampler` feeds for triangle
    meshes: it takes any `resolution`, faces with more than three sides, writes the mean
    curvature and the input face, and numbers the vertices as above, which `tspline blend`'s
    output files keep.

    \tparam OutPoint the point type of the output mesh
    \throws Invalid_input if `resolution` is outside [1, 1024]
    \param out the output mesh (cleared first)
    \param resolution the number of segments per edge
    \returns the statistics of the tessellation
  */
  template <class OutPoint>
  Blending_tessellation_statistics tessellate(CGAL::Surface_mesh<OutPoint>& out,
                                              int resolution) const {
    using Out = CGAL::Surface_mesh<OutPoint>;
    using Out_vector = typename CGAL::Kernel_traits<OutPoint>::Kernel::Vector_3;
    using Out_vertex = typename Out::Vertex_index;
    if (resolution < 1 || resolution > 1024)
      throw Invalid_input("blending: the tessellation resolution must be in [1, 1024], got " +
                          std::to_string(resolution));
    const std::size_t N = static_cast<std::size_t>(resolution);
    out.clear();
    auto normals =
        out.template add_property_map<Out_vertex, Out_vector>("v:normal", Out_vector(0, 0, 0))
            .first;
    auto gaussian =
        out.template add_property_map<Out_vertex, double>("v:gaussian_curvature", 0.).first;
    auto mean = out.template add_property_map<Out_vertex, double>("v:mean_curvature", 0.).first;
    auto source = out.template add_property_map<typename Out::Face_index, std::size_t>(
                         "f:input_face", std::size_t(0))
                      .first;
    Blending_tessellation_statistics stats;
    stats.min_gaussian_curvature = std::numeric_limits<double>::infinity();
    stats.max_gaussian_curvature = -std::numeric_limits<double>::infinity();

    auto store = [&](Out_vertex v, const Vec3& p, const Surface_derivatives& d) {
      out.point(v) = OutPoint(p[0], p[1], p[2]);
      const Surface_curvature k = surface_curvature(d);
      normals[v] = Out_vector(k.normal[0], k.normal[1], k.normal[2]);
      gaussian[v] = k.gaussian;
      mean[v] = k.mean;
      if (!k.regular || !std::isfinite(k.gaussian)) {
        ++stats.singular_points;
      } else {
        stats.min_gaussian_curvature = (std::min)(stats.min_gaussian_curvature, k.gaussian);
        stats.max_gaussian_curvature = (std::max)(stats.max_gaussian_curvature, k.gaussian);
      }
    };
    // shared vertices: input vertices, then N - 1 per input edge (head to tail)
    const std::size_t V = m_vertices.size(), E = m_edges.size();
    for (std::size_t v = 0; v < V + E * (N - 1); ++v)
      out.add_vertex();
    for (std::size_t v = 0; v < V; ++v) {
      const std::array<Curvature_jet, 3> p =
          vertex_surface(v, Curvature_jet::variable(0, 0, 2), Curvature_jet::variable(0, 1, 2));
      store(Out_vertex(static_cast<typename Out::size_type>(v)),
            Vec3{{p[0].value(), p[1].value(), p[2].value()}}, to_derivatives(p));
    }
    std::vector<char> edge_done(E * (N - 1), 0);
    auto edge_vertex = [&](std::size_t e, std::size_t from_head) {
      return Out_vertex(static_cast<typename Out::size_type>(V + e * (N - 1) + from_head - 1));
    };
    auto evaluate_at = [&](std::size_t f, const Vec2& p, Out_vertex v) {
      const std::array<Curvature_jet, 3> q =
          face_surface(f, Curvature_jet::variable(p[0], 0, 2), Curvature_jet::variable(p[1], 1, 2));
      store(v, Vec3{{q[0].value(), q[1].value(), q[2].value()}}, to_derivatives(q));
    };
    // the output vertex of a point of a face side with weights (w_head, w_tail), sum N
    auto side_vertex = [&](std::size_t f, std::size_t s, std::size_t w_head, const Vec2& p) {
      const std::size_t e = m_faces[f].sides[s].edge;
      if (w_head == N)
        return Out_vertex(static_cast<typename Out::size_type>(m_edges[e].head));
      if (w_head == 0)
        return Out_vertex(static_cast<typename Out::size_type>(m_edges[e].tail));
      const std::size_t index = N - w_head;
      const Out_vertex v = edge_vertex(e, index);
      char& done = edge_done[e * (N - 1) + index - 1];
      if (!done) {
        evaluate_at(f, p, v);
        done = 1;
      }
      return v;
    };
    auto add_triangle = [&](Out_vertex a, Out_vertex b, Out_vertex c, std::size_t f) {
      const typename Out::Face_index fi = out.add_face(a, b, c);
      if (fi == Out::null_face())
        CGAL_error_msg("blending: Surface_mesh rejected a tessellation triangle");
      source[fi] = f;
      ++stats.faces;
    };
    auto new_vertex = [&](std::size_t f, const Vec2& p) {
      const Out_vertex v = out.add_vertex();
      evaluate_at(f, p, v);
      return v;
    };
    const double step = 1.0 / double(N);
    for (std::size_t f = 0; f < m_faces.size(); ++f) {
      const Face_data& F = m_faces[f];
      const std::size_t n = F.vertex.size();
      // sub-triangles (P0, P1, P2) with grid weights (i, j, k): a triangle face is one,
      // with P = its corners; a polygon is the fan (origin, corner c, corner c + 1)
      Out_vertex center{};
      std::vector<std::vector<Out_vertex>> spokes(n);
      if (!F.triangle) {
        center = new_vertex(f, Vec2{{0, 0}});
        for (std::size_t c = 0; c < n; ++c)
          for (std::size_t j = 1; j < N; ++j)
            spokes[c].push_back(new_vertex(
                f, Vec2{{F.corner[c][0] * double(j) * step, F.corner[c][1] * double(j) * step}}));
      }
      const std::size_t pieces = F.triangle ? 1 : n;
      for (std::size_t piece = 0; piece < pieces; ++piece) {
        // grid[i][j]: weights i (P0), j (P1), k = N - i - j (P2)
        std::vector<std::vector<Out_vertex>> grid(N + 1);
        for (std::size_t i = 0; i <= N; ++i)
          for (std::size_t j = 0; i + j <= N; ++j) {
            const std::size_t k = N - i - j;
            Vec2 p;
            Out_vertex v{};
            if (F.triangle) {
              p = Vec2{{double(i) * step, double(j) * step}};
              const std::array<std::size_t, 3> w{{i, j, k}};
              const int zeros = (i == 0) + (j == 0) + (k == 0);
              if (zeros == 2) {
                const std::size_t c = i == N ? 0 : j == N ? 1 : 2;
                v = Out_vertex(static_cast<typename Out::size_type>(F.vertex[c]));
              } else if (zeros == 1) {
                const std::size_t s = i == 0 ? 0 : j == 0 ? 1 : 2; // side opposite the zero
                v = side_vertex(f, s, w[static_cast<std::size_t>(F.sides[s].end_corner[0])], p);
              } else {
                v = new_vertex(f, p);
              }
            } else {
              const std::size_t c = piece, c1 = (piece + 1) % n;
              p = Vec2{{(F.corner[c][0] * double(j) + F.corner[c1][0] * double(k)) * step,
                        (F.corner[c][1] * double(j) + F.corner[c1][1] * double(k)) * step}};
              if (i == N) {
                v = center;
              } else if (j == N) {
                v = Out_vertex(static_cast<typename Out::size_type>(F.vertex[c]));
              } else if (k == N) {
                v = Out_vertex(static_cast<typename Out::size_type>(F.vertex[c1]));
              } else if (i == 0) {
                const std::size_t w_head =
                    static_cast<std::size_t>(F.sides[c].end_corner[0]) == c ? j : k;
                v = side_vertex(f, c, w_head, p);
              } else if (k == 0) {
                v = spokes[c][N - i - 1]; // on the spoke to corner c, j = N - i from the centre
              } else if (j == 0) {
                v = spokes[c1][N - i - 1];
              } else {
                v = new_vertex(f, p);
              }
            }
            grid[i].push_back(v);
          }
        for (std::size_t i = 0; i < N; ++i)
          for (std::size_t j = 0; i + j < N; ++j) {
            // weights (i, j) are the coordinates of a counter-clockwise frame of the piece
            add_triangle(grid[i][j], grid[i + 1][j], grid[i][j + 1], f);
            if (i + j + 2 <= N)
              add_triangle(grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1], f);
          }
      }
    }
    stats.vertices = out.number_of_vertices();
    if (stats.singular_points == out.number_of_vertices())
      stats.min_gaussian_curvature = stats.max_gaussian_curvature =
          std::numeric_limits<double>::quiet_NaN();
    return stats;
  }

private:
  struct Vertex_data {
    Vec3 position{{0, 0, 0}}, normal{{0, 0, 1}}, ex{{1, 0, 0}}, ey{{0, 1, 0}};
    double scale = 1;
    Bivariate_polynomial height{0};
    std::vector<std::size_t> neighbours;
  };
  struct Edge_data {
    std::size_t head = 0, tail = 0;
    // positions of head and tail in the frame of the head ([0]) and of the tail ([1])
    std::array<Vec2, 2> head_in, tail_in;
    std::vector<std::pair<std::size_t, std::size_t>> sides; // (face, side)
  };
  struct Side {
    std::size_t edge = 0;
    std::array<int, 2> end_corner{{0, 0}};    // face corners at the edge's head and tail
    int opposite = -1;                        // triangle: the corner opposite the side
    internal::Affine_2 basic;                 // eq. 5.8 / 7.2
    std::array<internal::Affine_2, 2> at_end; // inherited at the head end and the tail end
    double radius = 0;                        // polygon open-set radius
  };
  struct Face_data {
    bool triangle = true;
    std::vector<std::size_t> vertex;
    std::vector<Vec2> corner;
    std::vector<Side> sides;
    Vec3 origin{{0, 0, 0}}, ex{{1, 0, 0}}, ey{{0, 1, 0}}, ez{{0, 0, 1}};
    double scale = 1;
  };

  template <class T>
  static T barycentric(const Face_data& F, int corner, const T& a, const T& b) {
    (void)F;
    if (corner == 0)
      return a;
    if (corner == 1)
      return b;
    const T w = 1.0 - a - b;
    return w;
  }

  template <class T>
  static T squared_distance(const Face_data& F, int corner, const T& a, const T& b) {
    const Vec2& q = F.corner[static_cast<std::size_t>(corner)];
    const T dx = a - q[0], dy = b - q[1];
    const T s = dx * dx + dy * dy;
    return s;
  }

  template <class T>
  static std::array<T, 2> mix(const std::vector<T>& w, const internal::Affine_2& A0,
                              const internal::Affine_2& A1, const T& a, const T& b) {
    if constexpr (std::is_same<T, double>::value) {
      if (w[1] == 0)
        return A0(a, b);
      if (w[0] == 0)
        return A1(a, b);
    }
    const std::array<T, 2> p = A0(a, b), q = A1(a, b);
    const T x = w[0] * p[0] + w[1] * q[0];
    const T y = w[0] * p[1] + w[1] * q[1];
    return {{x, y}};
  }

  internal::Affine_2 vertex_map(std::size_t f, std::size_t c) const {
    const Face_data& F = m_faces.at(f);
    const std::size_t n = F.vertex.size();
    const std::size_t prev = (c + n - 1) % n, next = (c + 1) % n;
    const std::size_t v = F.vertex[c];
    return internal::Affine_2::from_points(
        {{F.corner[c], F.corner[prev], F.corner[next]}},
        {{Vec2{{0, 0}}, to_vertex_frame(v, m_vertices[F.vertex[prev]].position),
          to_vertex_frame(v, m_vertices[F.vertex[next]].position)}});
  }

  // --- construction ---

  static std::string vertex_name(std::size_t v) { return "vertex " + std::to_string(v); }

  void check_options() const {
    if (m_options.order < 0)
      throw Invalid_input("blending: the blending order d must be non-negative, got " +
                          std::to_string(m_options.order));
    if (m_options.vertex_surface == Vertex_surface_method::LEAST_SQUARES &&
        m_options.least_squares_degree < 1)
      throw Invalid_input("blending: the least-squares degree must be at least 1");
    if (m_options.vertex_surface == Vertex_surface_method::LEAST_SQUARES_NORMALS &&
        m_options.normals_degree < 2)
      throw Invalid_input("blending: the degree of the vertex surfaces with normals must be at "
                          "least 2");
  }

  // Everything from the mesh as read once (internal::read_blending_mesh()).
  void build(const internal::Blending_mesh& mesh) {
    compute_normals(mesh);
    build_vertices(mesh);
    build_edges(mesh);
    build_faces(mesh);
  }

  void compute_normals(const internal::Blending_mesh& mesh) {
    const std::size_t V = mesh.position.size();
    m_vertices.assign(V, Vertex_data());
    std::vector<std::size_t> degree(V);
    for (std::size_t v = 0; v < V; ++v) {
      m_vertices[v].position = mesh.position[v];
      degree[v] = mesh.around[v].size();
    }
    m_estimated_normals = mesh.given_normal.empty();
    const std::vector<Vec3> normals = internal::blending_vertex_normals(
        mesh.position, mesh.corners, degree, mesh.given_normal, "blending");
    for (std::size_t v = 0; v < V; ++v)
      m_vertices[v].normal = normals[v];
  }

  void build_vertices(const internal::Blending_mesh& mesh) {
    for (std::size_t v = 0; v < m_vertices.size(); ++v) {
      Vertex_data& V = m_vertices[v];
      V.neighbours = mesh.around[v];
      // x axis: the projection of the first neighbour not on the normal line
      double longest = 0;
      for (std::size_t w : V.neighbours)
        longest = (std::max)(
            longest, internal::norm(internal::difference(m_vertices[w].position, V.position)));
      bool found = false;
      for (std::size_t w : V.neighbours) {
        const Vec3 d = internal::difference(m_vertices[w].position, V.position);
        const Vec3 t =
            internal::difference(d, internal::scaled(V.normal, internal::dot(d, V.normal)));
        const double length = internal::norm(t);
        if (length > 1e-9 * longest) {
          V.ex = internal::scaled(t, 1 / length);
          V.ey = internal::cross(V.normal, V.ex);
          V.scale = length;
          found = true;
          break;
        }
      }
      if (!found)
        throw Invalid_input("blending: all neighbours of " + vertex_name(v) +
                            " project onto its normal line");
      // conditions in the frame: P(0) = 0, grad P(0) = 0, P(x_i, y_i) = z_i, and for
      // LEAST_SQUARES_NORMALS grad P(x_i, y_i) = -(n_x, n_y) / n_z from the neighbour's normal
      std::vector<Interpolation_condition> at_vertex, neighbours, slopes;
      at_vertex.push_back({Interpolation_condition::VALUE, {{0, 0}}, 0});
      at_vertex.push_back({Interpolation_condition::DX, {{0, 0}}, 0});
      at_vertex.push_back({Interpolation_condition::DY, {{0, 0}}, 0});
      for (std::size_t w : V.neighbours) {
        const Vec3 d = internal::difference(m_vertices[w].position, V.position);
        const std::array<double, 2> at{
            {internal::dot(d, V.ex) / V.scale, internal::dot(d, V.ey) / V.scale}};
        neighbours.push_back(
            {Interpolation_condition::VALUE, at, internal::dot(d, V.normal) / V.scale});
        const Vec3& n = m_vertices[w].normal;
        const double nz = internal::dot(n, V.normal);
        // beyond about 75 degrees from V's normal the slope (> 3.9, infinite at 90) would
        // dominate the fit: such a normal is left out
        if (nz > 0.25) {
          slopes.push_back({Interpolation_condition::DX, at, -internal::dot(n, V.ex) / nz});
          slopes.push_back({Interpolation_condition::DY, at, -internal::dot(n, V.ey) / nz});
        }
      }
      try {
        if (m_options.vertex_surface == Vertex_surface_method::LEAST) {
          std::vector<Interpolation_condition> all = at_vertex;
          all.insert(all.end(), neighbours.begin(), neighbours.end());
          V.height = least_interpolant(all, m_options.least_tolerance);
        } else if (m_options.vertex_surface == Vertex_surface_method::LEAST_SQUARES) {
          V.height =
              least_squares_polynomial(at_vertex, neighbours, m_options.least_squares_degree);
        } else {
          std::vector<Interpolation_condition> exact = at_vertex;
          exact.insert(exact.end(), neighbours.begin(), neighbours.end());
          // as many coefficients as positions at least (high valence); when the slopes leave
          // some free (valence 3), the minimum-norm fit: on the cube and the dodecahedron it
          // bends less than lowering the degree to a determined fit
          int degree = m_options.normals_degree;
          while ((degree + 1) * (degree + 2) / 2 < static_cast<int>(exact.size()))
            ++degree;
          // neighbours on a curve of the degree: raise it
          for (int tries = 0;; ++tries, ++degree) {
            try {
              V.height = least_squares_polynomial(exact, slopes, degree);
              break;
            } catch (const Invalid_input&) {
              if (tries == 4)
                throw;
            }
          }
        }
      } catch (const Invalid_input& e) {
        throw Invalid_input("blending: vertex surface of " + vertex_name(v) + ": " + e.what());
      }
      // exactly through the vertex with its normal (these are zero up to round-off)
      V.height.set_coefficient(0, 0, 0);
      if (V.height.degree() >= 1) {
        V.height.set_coefficient(1, 0, 0);
        V.height.set_coefficient(0, 1, 0);
      }
    }
  }

  void build_edges(const internal::Blending_mesh& mesh) {
    m_edges.assign(mesh.ends.size(), Edge_data());
    for (std::size_t e = 0; e < mesh.ends.size(); ++e) {
      Edge_data& E = m_edges[e];
      E.head = mesh.ends[e][0];
      E.tail = mesh.ends[e][1];
      const std::array<std::size_t, 2> ends{{E.head, E.tail}};
      for (int end = 0; end < 2; ++end) {
        const std::size_t v = ends[static_cast<std::size_t>(end)];
        E.head_in[static_cast<std::size_t>(end)] = to_vertex_frame(v, m_vertices[E.head].position);
        E.tail_in[static_cast<std::size_t>(end)] = to_vertex_frame(v, m_vertices[E.tail].position);
        const Vec2& a = E.head_in[static_cast<std::size_t>(end)];
        const Vec2& b = E.tail_in[static_cast<std::size_t>(end)];
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        if (!(length > 1e-9))
          throw Invalid_input("blending: edge (" + std::to_string(E.head) + ", " +
                              std::to_string(E.tail) + ") is parallel to the normal of " +
                              vertex_name(v));
      }
    }
  }

  // r^{V,E}: vertex-frame point q of end `end` to the frame of edge e (inverse of eq. 5.4)
  Vec2 vertex_to_edge(std::size_t e, int end, const Vec2& q) const {
    const Edge_data& E = m_edges[e];
    const Vec2& h = E.head_in[static_cast<std::size_t>(end)];
    const Vec2& t = E.tail_in[static_cast<std::size_t>(end)];
    const double dx = t[0] - h[0], dy = t[1] - h[1], l2 = dx * dx + dy * dy;
    const double ux = q[0] - h[0], uy = q[1] - h[1];
    return {{(ux * dy - uy * dx) / l2, (ux * dx + uy * dy) / l2}};
  }

  void build_faces(const internal::Blending_mesh& mesh) {
    m_faces.assign(mesh.corners.size(), Face_data());
    for (std::size_t f = 0; f < mesh.corners.size(); ++f) {
      Face_data& F = m_faces[f];
      F.vertex = mesh.corners[f];
      const std::size_t n = F.vertex.size();
      F.triangle = (n == 3);
      if (F.triangle) {
        F.corner = {Vec2{{1, 0}}, Vec2{{0, 1}}, Vec2{{0, 0}}};
      } else {
        build_face_frame(f, F);
      }
      // sides: triangle side i opposite corner i (ends i+1, i+2); polygon side i = (i, i+1)
      F.sides.resize(n);
      for (std::size_t s = 0; s < n; ++s) {
        Side& side = F.sides[s];
        const std::size_t c0 = F.triangle ? (s + 1) % 3 : s;
        const std::size_t c1 = F.triangle ? (s + 2) % 3 : (s + 1) % n;
        side.edge = mesh.sides[f][c0]; // the face's halfedge from corner c0 to c1 = c0 + 1
        const Edge_data& E = m_edges[side.edge];
        const bool forward = (F.vertex[c0] == E.head);
        side.end_corner = {
            {static_cast<int>(forward ? c0 : c1), static_cast<int>(forward ? c1 : c0)}};
        side.opposite = F.triangle ? static_cast<int>(s) : -1;
        m_edges[side.edge].sides.push_back({f, s});
        build_side_maps(F, side, forward);
      }
    }
  }

  void build_face_frame(std::size_t f, Face_data& F) {
    const std::size_t n = F.vertex.size();
    Vec3 origin{{0, 0, 0}}, z{{0, 0, 0}};
    for (std::size_t v : F.vertex)
      for (std::size_t c = 0; c < 3; ++c) {
        origin[c] += m_vertices[v].position[c] / double(n);
        z[c] += m_vertices[v].normal[c];
      }
    const double lz = internal::norm(z);
    if (!(lz > 1e-12))
      throw Invalid_input("blending: face " + std::to_string(f) +
                          " has a zero mean vertex normal (§7.2.1)");
    z = internal::scaled(z, 1 / lz);
    const Vec3 d = internal::difference(m_vertices[F.vertex[0]].position, origin);
    const Vec3 t = internal::difference(d, internal::scaled(z, internal::dot(d, z)));
    const double lt = internal::norm(t);
    if (!(lt > 1e-12))
      throw Invalid_input("blending: face " + std::to_string(f) +
                          ": corner 0 projects onto the centre of the face frame");
    F.origin = origin;
    F.ez = z;
    F.ex = internal::scaled(t, 1 / lt);
    F.ey = internal::cross(z, F.ex);
    F.scale = lt;
    F.corner.clear();
    for (std::size_t v : F.vertex) {
      const Vec3 q = internal::difference(m_vertices[v].position, origin);
      F.corner.push_back({{internal::dot(q, F.ex) / lt, internal::dot(q, F.ey) / lt}});
    }
    // strict convexity (counter-clockwise) of the projected polygon, with a relative margin
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = F.corner[(i + n - 1) % n];
      const Vec2& b = F.corner[i];
      const Vec2& c = F.corner[(i + 1) % n];
      const double cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
      const double scale =
          std::hypot(b[0] - a[0], b[1] - a[1]) * std::hypot(c[0] - b[0], c[1] - b[1]);
      if (!(cross > 1e-10 * scale))
        throw Invalid_input("blending: face " + std::to_string(f) + " (" + std::to_string(n) +
                            " sides) projects to a polygon that is not strictly convex at "
                            "corner " +
                            std::to_string(i) +
                            "; multi-sided blending needs convex faces (Fang §7.1, §9.1.4)");
      const double winding = (b[0] - F.corner[0][0]) * (c[1] - F.corner[0][1]) -
                             (b[1] - F.corner[0][1]) * (c[0] - F.corner[0][0]);
      if (i != 0 && (i + 1) % n != 0 && !(winding > 0))
        throw Invalid_input("blending: face " + std::to_string(f) +
                            " projects to a self-intersecting polygon");
    }
  }

  // the edge-frame position of a face corner lying on the side's edge
  static Vec2 end_position(int end) { return end == 0 ? Vec2{{0, 0}} : Vec2{{0, 1}}; }

  void build_side_maps(const Face_data& F, Side& side, bool forward) {
    const std::size_t n = F.vertex.size();
    const Edge_data& E = m_edges[side.edge];
    const std::size_t ch = static_cast<std::size_t>(side.end_corner[0]);
    const std::size_t ct = static_cast<std::size_t>(side.end_corner[1]);
    if (F.triangle) {
      const std::size_t co = static_cast<std::size_t>(side.opposite);
      // eq. 5.8: the opposite corner at V' with V_h V_t V' similar to the 3D triangle
      const Vec3& H = m_vertices[E.head].position;
      const Vec3& T = m_vertices[E.tail].position;
      const Vec3& O = m_vertices[F.vertex[co]].position;
      const Vec3 e = internal::difference(T, H), o = internal::difference(O, H);
      const double l2 = internal::dot(e, e);
      const double t = internal::dot(o, e) / l2;
      const double h =
          internal::norm(internal::difference(o, internal::scaled(e, t))) / std::sqrt(l2);
      // the face lies to the left of its traversal direction: x < 0 if it runs head -> tail
      const Vec2 similar{{forward ? -h : h, t}};
      side.basic = triangle_map(F, ch, ct, co, similar);
      // eqs. 6.8, 6.9: the opposite corner as seen from each end's vertex frame
      for (int end = 0; end < 2; ++end) {
        const std::size_t v = end == 0 ? E.head : E.tail;
        const Vec2 image = vertex_to_edge(side.edge, end, to_vertex_frame(v, O));
        side.at_end[static_cast<std::size_t>(end)] = triangle_map(F, ch, ct, co, image);
      }
    } else {
      // eq. 7.2: the similarity sending Q_head -> (0, 0), Q_tail -> (0, 1)
      const Vec2& qh = F.corner[ch];
      const Vec2& qt = F.corner[ct];
      const Vec2 vy{{qt[0] - qh[0], qt[1] - qh[1]}};
      const Vec2 vx{{vy[1], -vy[0]}};
      const double l2 = vy[0] * vy[0] + vy[1] * vy[1];
      internal::Affine_2 S;
      S.m = {{vx[0] / l2, vx[1] / l2, -(vx[0] * qh[0] + vx[1] * qh[1]) / l2, vy[0] / l2, vy[1] / l2,
              -(vy[0] * qh[0] + vy[1] * qh[1]) / l2}};
      side.basic = S;
      side.radius = std::sqrt(l2) / 3;
      // eqs. 7.6, 7.7: triangle (Q_h, Q_h', Q_t) -> (P_h, C'_h, P_t), Q_h' the other face
      // neighbour of the end's corner
      for (int end = 0; end < 2; ++end) {
        const std::size_t c = end == 0 ? ch : ct;
        const std::size_t c_other = end == 0 ? ct : ch;
        const std::size_t next = (c + 1) % n, prev = (c + n - 1) % n;
        const std::size_t c_neighbour = next == c_other ? prev : next;
        const std::size_t v = end == 0 ? E.head : E.tail;
        const Vec2 image = vertex_to_edge(
            side.edge, end, to_vertex_frame(v, m_vertices[F.vertex[c_neighbour]].position));
        side.at_end[static_cast<std::size_t>(end)] = internal::Affine_2::from_points(
            {{F.corner[c], F.corner[c_neighbour], F.corner[c_other]}},
            {{end_position(end), image, end_position(1 - end)}});
      }
    }
    // the maps preserve orientation (the face lies left of its traversal, on the same side
    // in the edge frame) unless the mesh is too sharp for its normals
    const bool improved = variant() != Blending_variant::BASIC;
    if (!(side.basic.determinant() > 0) && !improved)
      ++m_folded;
    if (improved)
      for (const internal::Affine_2& A : side.at_end)
        if (!(A.determinant() > 0))
          ++m_folded;
  }

  // the affine map from the parameters (a, b) of a triangle to an edge frame sending the
  // head corner to (0,0), the tail corner to (0,1) and the opposite corner to `image`
  static internal::Affine_2 triangle_map(const Face_data& F, std::size_t ch, std::size_t ct,
                                         std::size_t co, const Vec2& image) {
    return internal::Affine_2::from_points({{F.corner[ch], F.corner[ct], F.corner[co]}},
                                           {{Vec2{{0, 0}}, Vec2{{0, 1}}, image}});
  }

  Mesh_blending_options m_options;
  bool m_estimated_normals = true;
  std::size_t m_folded = 0;
  std::vector<Vertex_data> m_vertices;
  std::vector<Edge_data> m_edges;
  std::vector<Face_data> m_faces;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_MESH_BLENDING_SURFACE_H

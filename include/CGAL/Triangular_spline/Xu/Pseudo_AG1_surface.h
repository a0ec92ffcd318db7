// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_SURFACE_H
#define CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_SURFACE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/recentering.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief how the normal of a corner plane is chosen (Xu §6.2.1, approaches 1–3).
enum class Corner_plane_normal {
  CENTROID,     ///< approach 1: the line from the vertex to the centroid of its first stars
  AVERAGE,      ///< approach 2: the plain average of the unit normals of the incident faces
  AREA_WEIGHTED ///< approach 3: the area-weighted average, \f$\sum (w_i - v)\times(w_{i+1} - v)\f$
};
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief how the star points are placed in the corner plane (Xu §6.2.1).
enum class Star_placement {
  UMBRELLA,  ///< lengths kept, angles scaled to sum to \f$2\pi\f$ (Fig. 6.6, "an umbrella opening")
  PROJECTION ///< orthogonal projection of the first approximations (rational)
};
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief the angles of the umbrella (AG1.md [U3]).
enum class Umbrella_angles { PROPORTIONAL, EQUAL };
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief the lengths of the umbrella's spokes (AG1.md R-11).
enum class Umbrella_lengths { RIGID, PROPORTIONAL, EQUAL };
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief the in-plane rotation of the umbrella (AG1.md R-12).
enum class Umbrella_rotation { LEAST_SQUARES, FIRST_STAR };
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief where the corner-inner points go (Xu §6.2.3 last paragraph, §6.2.4).
enum class Inner_placement {
  NORMAL_OFFSET,    ///< the first approximation (offset along the neighbours' normals)
  CROSS_EDGE_PLANES ///< closest point on the two planes through the stars normal to the
                    ///< cross-edge normals (AG1.md R-20)
};
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief the affine relation used for the middle diamonds of an edge (Xu §6.2.2).
enum class Edge_map {
  PARALLELOGRAM,   ///< \f$(\lambda, \mu, \nu) = (-1, 1, 1)\f$, the thesis's choice
  AVERAGED_DIAMOND ///< the mean of the two end diamonds' relations when both are convex
};
/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief which flip (middle-inner) point of an edge is prescribed (Xu §4.1.3; AG1.md R-15).
enum class Flip_rule {
  SYMMETRIC,       ///< both prescribed, then the least change of both meeting the diamond
  LARGER_FACE,     ///< the flip of the larger face (ties: the lower face index)
  LOWER_INDEX_FACE ///< the flip of the face with the lower index
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the parameters of the pseudo-AG\f$^1\f$ construction (AG1.md §4.1); the defaults are
  the preset `thesis()`.
*/
struct Pseudo_AG1_options {
  Corner_plane_normal normal = Corner_plane_normal::AREA_WEIGHTED; ///< corner-plane normal
  double plane_position = 0.5;  ///< \f$\tau\f$: 0 through the vertex, 1 through the centroid
  double undulation_gain = 1.0; ///< \f$\kappa\f$: 0 disables the raise/lower of §6.2.3
  double undulation_threshold = 4 * 3.14159265358979323846 / 5;  ///< \f$\theta^*\f$ (radians)
  Star_placement placement = Star_placement::UMBRELLA;           ///< star placement
  Umbrella_angles angles = Umbrella_angles::PROPORTIONAL;        ///< umbrella angles
  Umbrella_lengths lengths = Umbrella_lengths::RIGID;            ///< umbrella lengths
  Umbrella_rotation rotation = Umbrella_rotation::LEAST_SQUARES; ///< umbrella rotation
  bool recentering = true;          ///< re-centre corners outside their star polygon (Fig. 6.5)
  double star_scale = 1.0;          ///< \f$\sigma\f$ in (0, 1]
  bool automatic_shrinking = false; ///< shrink the stars of dipping edges (AG1.md R-19)
  /// offsets \f$(o_s, o_i, o_f)\f$ of the first approximation (stars, inner, flips)
  std::array<double, 3> offsets{{0.05, 0.10, 0.10}};
  Inner_placement inner = Inner_placement::NORMAL_OFFSET; ///< corner-inner placement
  Edge_map edge_map = Edge_map::PARALLELOGRAM;            ///< middle-diamond relation
  /// `AVERAGED_DIAMOND` keeps the parallelogram where the average has \f$-\lambda\f$, \f$\mu\f$
  /// or \f$\nu\f$ below this (propagation divides by \f$\mu\f$ and \f$\nu\f$)
  double min_averaged_weight = 0.4;
  Flip_rule flips = Flip_rule::SYMMETRIC; ///< flip rule

  /// \returns the method of §6.2 as written (the defaults)
  static Pseudo_AG1_options thesis() { return Pseudo_AG1_options(); }
  /// \returns the preliminary implementation of §5.4: planes through the centroids, projected
  /// stars, no offsets; every control point a convex combination of the input vertices
  static Pseudo_AG1_options chapter5() {
    Pseudo_AG1_options o;
    o.plane_position = 1;
    o.undulation_gain = 0;
    o.placement = Star_placement::PROJECTION;
    o.offsets = {{0, 0, 0}};
    return o;
  }
  /// \returns the thesis' method with the averaged diamond map, which §6.2.2 suggests when both
  /// end diamonds are convex (guarded by `min_averaged_weight`): on CGAL's sample meshes it
  /// divides the mean normal jump by 1.1 to 2.2
  static Pseudo_AG1_options smooth() {
    Pseudo_AG1_options o;
    o.edge_map = Edge_map::AVERAGED_DIAMOND;
    return o;
  }
  /// \returns every step rational: with an exact number type the surface is exact and
  /// certifiable
  static Pseudo_AG1_options exact() {
    Pseudo_AG1_options o = chapter5();
    o.plane_position = 0.5;
    return o;
  }
  /// \returns `true` iff every step of these options is a rational function of the input
  bool is_rational() const {
    return normal != Corner_plane_normal::AVERAGE &&
           (undulation_gain == 0 || undulation_threshold == 0) &&
           placement == Star_placement::PROJECTION && offsets[0] == 0 && offsets[1] == 0 &&
           offsets[2] == 0 && inner == Inner_placement::NORMAL_OFFSET && !automatic_shrinking;
  }
};

/// \ingroup PkgTriangularSplinePseudoAG1
/// \brief returns the options of the preset `name` ("thesis", "smooth", "chapter5", "exact").
/// \throws Invalid_input for another name
/// \param name the preset name
/// \returns the options
inline Pseudo_AG1_options pseudo_AG1_preset(const std::string& name) {
  if (name == "thesis")
    return Pseudo_AG1_options::thesis();
  if (name == "chapter5")
    return Pseudo_AG1_options::chapter5();
  if (name == "exact")
    return Pseudo_AG1_options::exact();
  if (name == "smooth")
    return Pseudo_AG1_options::smooth();
  throw Invalid_input("pseudo-AG1: unknown preset '" + name +
                      "' (expected thesis, smooth, chapter5 or exact)");
}

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the corner plane of a vertex and how it was obtained (Xu §6.2.1; AG1.md S3–S6).

  The plane is \f$\{x : \langle x - v, N\rangle = H\}\f$; \f$N\f$ is not normalized in the
  rational steps, so that the plane stays exact.
*/
template <class Kernel>
struct Corner_plane {
  typename Kernel::Vector_3 normal{CGAL::NULL_VECTOR}; ///< \f$N_v\f$ (any positive length)
  typename Kernel::FT offset;                          ///< \f$H_v\f$
  typename Kernel::Vector_3 centroid{
      CGAL::NULL_VECTOR}; ///< \f$C_v\f$, the mean of the first-approximation stars
  typename Kernel::Vector_3 corner{CGAL::NULL_VECTOR}; ///< \f$z_v\f$
  /// the umbrella: chart coordinates of \f$S_{v\to w_i} - z_v\f$ in ring order
  std::vector<typename Kernel::Point_2> umbrella;
  Corner_plane_normal normal_used = Corner_plane_normal::AREA_WEIGHTED; ///< after fallbacks
  double mean_dihedral = 0;       ///< \f$\bar\theta_v\f$ (radians)
  double star_scale = 1;          ///< \f$\sigma_v\f$
  bool normal_fallback = false;   ///< the chosen normal vanished (AG1.md R-32)
  bool recentred = false;         ///< the corner was moved into the star polygon (Fig. 6.5)
  bool folded_projection = false; ///< the projected stars are not a simple CCW polygon
  bool equalised = false; ///< an umbrella angle came within 1e-6 of \f$\pi\f$ or 0 (AG1.md R-13)
  bool inverted_corner = false; ///< a corner triangle is not CCW about \f$N_v\f$
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief the relations of an edge \f$e = (r, s)\f$, oriented as `canonical_halfedge(e)` (\f$r\f$ its
  source): \f$q = \lambda p + \mu r + \nu s\f$, with \f$p\f$ the apex of the face of \f$r\to s\f$
  and \f$q\f$ that of \f$s \to r\f$ (AG1.md §1.3).
*/
template <class FT>
struct Pseudo_AG1_edge {
  std::array<FT, 3> relation;     ///< \f$R_e\f$, used by the three middle diamonds
  std::array<FT, 3> end_r;        ///< \f$R^r_e\f$, read off the corner region of \f$r\f$
  std::array<FT, 3> end_s;        ///< \f$R^s_e\f$, read off the corner region of \f$s\f$
  bool end_r_valid = true;        ///< false if the star triangle at \f$r\f$ is degenerate
  bool end_s_valid = true;        ///< false if the star triangle at \f$s\f$ is degenerate
  bool averaged_fallback = false; ///< `AVERAGED_DIAMOND` fell back to the parallelogram
  double dihedral = 0;            ///< interior dihedral angle \f$\theta_e\f$ of the input (radians)
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief how often the construction of a `Pseudo_AG1_surface` left its default path (AG1.md §6
  M7): counts of the per-vertex and per-edge flags, for reports.
*/
struct Pseudo_AG1_flags {
  std::size_t recentred_vertices = 0;     ///< corners moved into their star polygon
  std::size_t folded_projections = 0;     ///< projected stars not a simple CCW polygon
  std::size_t equalised_umbrellas = 0;    ///< umbrella angles equalised (R-13)
  std::size_t normal_fallbacks = 0;       ///< corner-plane normals that fell back (R-32)
  std::size_t inverted_corners = 0;       ///< corner triangles not CCW about the normal
  std::size_t averaged_map_fallbacks = 0; ///< averaged edge maps that kept the parallelogram
  std::size_t dipping_edges = 0;          ///< edges with a positive dip (M6)
  std::size_t shrinking_rounds = 0;       ///< rounds of automatic star shrinking
  std::size_t reoriented_components = 0;  ///< components turned outward
  /// calls `f(name, count)` for every field, in declaration order (for reports)
  /// \tparam F a callable as `f(const char*, std::size_t)`
  /// \param f the function called for every field
  template <class F>
  void for_each(F&& f) const {
    f("recentred_vertices", recentred_vertices);
    f("folded_projections", folded_projections);
    f("equalised_umbrellas", equalised_umbrellas);
    f("normal_fallbacks", normal_fallbacks);
    f("inverted_corners", inverted_corners);
    f("averaged_map_fallbacks", averaged_map_fallbacks);
    f("dipping_edges", dipping_edges);
    f("shrinking_rounds", shrinking_rounds);
    f("reoriented_components", reoriented_components);
  }
  /// \returns the number of vertex and edge flags raised (dips and rounds not counted)
  std::size_t raised() const {
    return recentred_vertices + folded_projections + equalised_umbrellas + normal_fallbacks +
           inverted_corners + averaged_map_fallbacks;
  }
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief Xu's pseudo-AG\f$^1\f$ surface over a closed triangle mesh (thesis ch.\ 5–6, §6.2):
  one quintic Bézier patch per face, \f$C^0\f$ everywhere, \f$G^1\f$ at every vertex (each
  corner region lies in its corner plane), the three middle diamonds of every edge sharing one
  affine relation; tangent planes jump inside edges whose two end relations differ from it.

  The construction follows AG1.md §4 step by step (S0–S11). Every step is a rational function
  of the input for options with `is_rational()`; with an exact number type the surface is then
  exact and its certificates are proofs. Other options compute lengths, angles and unit
  normals in `double` (`is_exact()` is then false).

  \tparam Kernel a CGAL kernel; `Kernel::FT` may be exact (e.g. `CGAL::Exact_rational`)
*/
template <class Kernel>
class Pseudo_AG1_surface {
public:
  /// the kernel
  using Geom_traits = Kernel;
  /// the number type
  using FT = typename Kernel::FT;
  /// 3D points
  using Point_3 = typename Kernel::Point_3;
  /// 3D vectors: the control points, as vectors from the origin
  using Vector_3 = typename Kernel::Vector_3;
  /// the closed input mesh, outward
  using Mesh = CGAL::Surface_mesh<Point_3>;
  /// vertex index
  using Vertex_index = typename Mesh::Vertex_index;
  /// halfedge index
  using Halfedge_index = typename Mesh::Halfedge_index;
  /// edge index
  using Edge_index = typename Mesh::Edge_index;
  /// face index
  using Face_index = typename Mesh::Face_index;
  /// a patch: a parametric quintic over the unit triangle, in the face's vertex order
  using Patch = Bezier_triangle<Kernel, Vector_3>;

  /*!
    builds the surface of `mesh`.
    \param mesh a closed, manifold triangle mesh (copied; components are oriented outward)
    \param options the parameters
    \throws Invalid_input if the mesh is not a closed manifold triangle mesh with finite
    coordinates and no zero-area face, an option is out of range, or every corner-plane
    normal of a vertex vanishes
  */
  explicit Pseudo_AG1_surface(const Mesh& mesh,
                              const Pseudo_AG1_options& options = Pseudo_AG1_options())
      : m_mesh(mesh), m_options(options) {
    check_options();
    m_summary = prepare_closed_triangle_mesh(m_mesh, "pseudo-AG1");
    m_exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value && options.is_rational();
    build();
  }

  /// \name Access
  /// @{

  /// \returns the (oriented) input mesh
  const Mesh& mesh() const { return m_mesh; }
  /// \returns the options
  const Pseudo_AG1_options& options() const { return m_options; }
  /// \returns what validation found (components, genus, reoriented components)
  const Closed_mesh_summary& mesh_summary() const { return m_summary; }
  /// \returns the polynomial degree, 5
  int degree() const { return 5; }
  /// \returns `true` iff every control point is the exact value of the construction (exact
  /// number type and rational options)
  bool is_exact() const { return m_exact; }
  /// \param v a vertex
  /// \returns the corner plane of `v`
  const Corner_plane<Kernel>& corner_plane(Vertex_index v) const { return m_planes[v]; }
  /// \param e an edge
  /// \returns the relations of `e`
  const Pseudo_AG1_edge<FT>& edge_relation(Edge_index e) const { return m_edges[e]; }
  /// \returns the number of rounds of automatic star shrinking (0 without it)
  std::size_t shrinking_rounds() const { return m_shrinking_rounds; }
  /// \returns the counts of the construction's flags
  Pseudo_AG1_flags flags() const {
    Pseudo_AG1_flags f;
    for (auto v : m_mesh.vertices()) {
      const auto& p = m_planes[v];
      f.recentred_vertices += p.recentred;
      f.folded_projections += p.folded_projection;
      f.equalised_umbrellas += p.equalised;
      f.normal_fallbacks += p.normal_fallback;
      f.inverted_corners += p.inverted_corner;
    }
    for (auto e : m_mesh.edges()) {
      f.averaged_map_fallbacks += m_edges[e].averaged_fallback;
      f.dipping_edges += dip(e) > 0;
    }
    f.shrinking_rounds = m_shrinking_rounds;
    f.reoriented_components = m_summary.reoriented;
    return f;
  }

  /// \param h the halfedge \f$v \to w\f$
  /// \returns the star point \f$S_{v\to w}\f$
  const Vector_3& star(Halfedge_index h) const { return m_star[h]; }
  /// \param h the halfedge \f$v \to w\f$
  /// \returns the edge-middle point \f$M_{v\to w}\f$
  const Vector_3& edge_middle(Halfedge_index h) const { return m_middle[h]; }
  /// \param h a halfedge
  /// \returns the corner-inner point of `face(h)` at `source(h)`
  const Vector_3& corner_inner(Halfedge_index h) const { return m_inner[h]; }
  /// \param h a halfedge
  /// \returns the flip point of `face(h)` next to `edge(h)`
  const Vector_3& flip(Halfedge_index h) const { return m_flip[h]; }

  /*!
    returns the patch of `f` over the unit triangle \f$(0,0), (1,0), (0,1)\f$, whose corners
    correspond to `vertices_around_face(halfedge(f))` in that order (AG1.md R-2).
    \param f the face
    \returns the patch of `f`
  */
  Patch patch(Face_index f) const {
    return Patch(5, typename Kernel::Point_2(0, 0), typename Kernel::Point_2(1, 0),
                 typename Kernel::Point_2(0, 1), control_net(f));
  }

  /*!
    returns the 21 control points of `f` in Xu's Table 2.3 order, over the face's vertices in
    the order of `vertices_around_face(halfedge(f))`.
    \param f the face
    \returns the control net of `f`
  */
  std::vector<Vector_3> control_net(Face_index f) const {
    const Halfedge_index h0 = m_mesh.halfedge(f);
    // vertices_around_face starts at target(h0): v0 = target(h0), v1, v2 = source(h0).
    const std::array<Halfedge_index, 3> from{{m_mesh.next(h0), m_mesh.next(m_mesh.next(h0)), h0}};
    // from[a] runs from v_a to v_{a+1}
    std::vector<Vector_3> net(number_of_control_points(5));
    for (const Multi_index& index : multi_indices(5)) {
      int nonzero = 0, big = -1;
      for (int a = 0; a < 3; ++a) {
        nonzero += index[a] > 0;
        if (big < 0 || index[a] > index[big])
          big = a;
      }
      Vector_3 value;
      if (nonzero == 1) {
        value = m_planes[m_mesh.source(from[std::size_t(big)])].corner;
      } else if (nonzero == 2) {
        // on the side from corner x to x + 1
        int x = 0;
        for (int a = 0; a < 3; ++a)
          if (index[a] > 0 && index[(a + 1) % 3] > 0)
            x = a;
        const Halfedge_index xy = from[std::size_t(x)], yx = m_mesh.opposite(xy);
        switch (index[x]) {
        case 4:
          value = m_star[xy];
          break;
        case 3:
          value = m_middle[xy];
          break;
        case 2:
          value = m_middle[yx];
          break;
        default:
          value = m_star[yx];
          break;
        }
      } else if (index[big] == 3) {
        value = m_inner[from[std::size_t(big)]];
      } else {
        // (2,2,1): the flip next to the side of the two 2s, i.e. opposite the 1
        int one = 0;
        for (int a = 0; a < 3; ++a)
          if (index[a] == 1)
            one = a;
        value = m_flip[from[std::size_t((one + 1) % 3)]];
      }
      net[linear_index(index)] = value;
    }
    return net;
  }
  /// @}

  /// \name Local control (Xu §4.3 carried over; AG1.md §4.4)
  /// An edit sets one free control point and re-propagates only what depends on it; the
  /// surface stays pseudo-AG\f$^1\f$. Each returns the faces whose patches changed.
  /// @{

  /*!
    sets the corner-inner point of `face(h)` at `source(h)`; recomputes the edge-middle and
    flip points of the two edges of that face at `source(h)`.
    \param h a halfedge
    \param value the new control point
    \returns the faces whose patches changed, sorted
  */
  std::vector<Face_index> edit_corner_inner(Halfedge_index h, const Vector_3& value) {
    m_inner0[h] = m_inner[h] = value;
    const Halfedge_index other = m_mesh.prev(h); // the face's other edge at source(h)
    freeze_flips(h);
    freeze_flips(other);
    propagate_edge(m_mesh.edge(h));
    propagate_edge(m_mesh.edge(other));
    return sorted_faces(
        {m_mesh.face(h), m_mesh.face(m_mesh.opposite(h)), m_mesh.face(m_mesh.opposite(other))});
  }

  /*!
    sets the flip point of `face(h)` next to `edge(h)`; the other flip of that edge follows
    from the middle diamond \f$D_2\f$. Both become the prescribed values of later
    re-propagations, whatever the flip rule.
    \param h a halfedge
    \param value the new control point
    \returns the two faces of `edge(h)`, sorted
  */
  std::vector<Face_index> edit_flip(Halfedge_index h, const Vector_3& value) {
    const Edge_index e = m_mesh.edge(h);
    const Halfedge_index c = canonical_halfedge(e, m_mesh), o = m_mesh.opposite(c);
    const auto& R = m_edges[e].relation;
    const Vector_3 rest = R[1] * m_middle[c] + R[2] * m_middle[o];
    // D_2: L_B = lambda L_A + mu M_rs + nu M_sr, with A the face of the canonical halfedge
    if (h == c) {
      m_flip[c] = value;
      m_flip[o] = R[0] * value + rest;
    } else {
      m_flip[o] = value;
      m_flip[c] = (value - rest) / R[0];
    }
    m_flip0[c] = m_flip[c];
    m_flip0[o] = m_flip[o];
    return sorted_faces({m_mesh.face(c), m_mesh.face(o)});
  }
  /// @}

private:
  // Makes the current flips of edge(h) the prescribed ones, so that re-propagating the edge
  // after an edit elsewhere keeps them where the diamond allows (the symmetric rule then
  // changes both by the least amount).
  void freeze_flips(Halfedge_index h) {
    m_flip0[h] = m_flip[h];
    m_flip0[m_mesh.opposite(h)] = m_flip[m_mesh.opposite(h)];
  }
  std::vector<Face_index> sorted_faces(std::vector<Face_index> faces) const {
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
  }

  void check_options() const {
    const Pseudo_AG1_options& o = m_options;
    auto bad = [](const std::string& what) { throw Invalid_input("pseudo-AG1: " + what); };
    if (!(o.plane_position >= 0) || !std::isfinite(o.plane_position))
      bad("the plane position tau must be finite and >= 0");
    if (!(o.undulation_gain >= 0) || !std::isfinite(o.undulation_gain))
      bad("the undulation gain must be finite and >= 0");
    if (!(o.undulation_threshold > 0 && o.undulation_threshold < 2 * 3.14159265358979323846))
      bad("the undulation threshold must be in (0, 2 pi)");
    if (!(o.star_scale > 0 && o.star_scale <= 1))
      bad("the star scale must be in (0, 1]");
    if (!(o.min_averaged_weight >= 0 && o.min_averaged_weight <= 1))
      bad("the least averaged weight must be in [0, 1]");
    for (double x : o.offsets)
      if (!(x >= 0) || !std::isfinite(x))
        bad("the offsets must be finite and >= 0");
  }

  static Vector_3 unit(const Vector_3& v) {
    const double n = std::sqrt(CGAL::to_double(v.squared_length()));
    if (n == 0)
      return v;
    return Vector_3(FT(CGAL::to_double(v.x()) / n), FT(CGAL::to_double(v.y()) / n),
                    FT(CGAL::to_double(v.z()) / n));
  }
  static double length(const Vector_3& v) { return std::sqrt(CGAL::to_double(v.squared_length())); }
  Vector_3 position(Vertex_index v) const { return m_mesh.point(v) - CGAL::ORIGIN; }

  // The chart of the plane of v: drop the coordinate of largest |N|, keep CCW about N.
  typename Kernel::Point_2 chart(Vertex_index v, const Vector_3& x) const {
    const int i = m_chart_axis[v];
    const FT a = x[(i + 1) % 3], b = x[(i + 2) % 3];
    return m_chart_flip[v] ? typename Kernel::Point_2(b, a) : typename Kernel::Point_2(a, b);
  }
  Vector_3 lift(Vertex_index v, const typename Kernel::Point_2& p) const {
    const int i = m_chart_axis[v];
    const Vector_3& N = m_planes[v].normal;
    std::array<FT, 3> x;
    x[std::size_t((i + 1) % 3)] = m_chart_flip[v] ? p.y() : p.x();
    x[std::size_t((i + 2) % 3)] = m_chart_flip[v] ? p.x() : p.y();
    const FT rhs = m_planes[v].offset + N * position(v) - N[(i + 1) % 3] * x[(i + 1) % 3] -
                   N[(i + 2) % 3] * x[(i + 2) % 3];
    x[std::size_t(i)] = rhs / N[i];
    return Vector_3(x[0], x[1], x[2]);
  }
  Vector_3 project(Vertex_index v, const Vector_3& x) const {
    const Corner_plane<Kernel>& c = m_planes[v];
    const FT t = (c.normal * (x - position(v)) - c.offset) / c.normal.squared_length();
    return x - t * c.normal;
  }

  // Barycentric coordinates of x with respect to (a, b, c); false if the triangle is degenerate.
  static bool barycentric(const typename Kernel::Point_2& x, const typename Kernel::Point_2& a,
                          const typename Kernel::Point_2& b, const typename Kernel::Point_2& c,
                          std::array<FT, 3>& w) {
    auto det = [](const typename Kernel::Vector_2& u, const typename Kernel::Vector_2& v) -> FT {
      return u.x() * v.y() - u.y() * v.x();
    };
    const FT d = det(b - a, c - a);
    if (d == FT(0))
      return false;
    w[0] = det(b - x, c - x) / d;
    w[1] = det(c - x, a - x) / d;
    w[2] = FT(1) - w[0] - w[1];
    return true;
  }

  void build() {
    const std::size_t H = m_mesh.number_of_halfedges();
    m_face_normal.assign(m_mesh.number_of_faces(), Vector_3(CGAL::NULL_VECTOR));
    m_face_unit.assign(m_mesh.number_of_faces(), Vector_3(CGAL::NULL_VECTOR));
    m_face_area.assign(m_mesh.number_of_faces(), 0);
    m_edges.assign(m_mesh.number_of_edges(), Pseudo_AG1_edge<FT>());
    m_planes.assign(m_mesh.number_of_vertices(), Corner_plane<Kernel>());
    m_chart_axis.assign(m_mesh.number_of_vertices(), 2);
    m_chart_flip.assign(m_mesh.number_of_vertices(), false);
    m_star0.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_star.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_middle.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_inner0.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_inner.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_flip0.assign(H, Vector_3(CGAL::NULL_VECTOR));
    m_flip.assign(H, Vector_3(CGAL::NULL_VECTOR));
    for (auto v : m_mesh.vertices())
      m_planes[v].star_scale = m_options.star_scale;
    geometry();
    first_approximation();
    for (auto v : m_mesh.vertices())
      corner_region(v);
    inner_points();
    edge_maps();
    propagate();
    if (m_options.automatic_shrinking)
      shrink();
  }

  // S1: face normals and areas, edge lengths, cross-edge normals, dihedral angles.
  void geometry() {
    for (auto f : m_mesh.faces()) {
      const auto h = m_mesh.halfedge(f);
      const Vector_3 a = position(m_mesh.source(h)), b = position(m_mesh.target(h)),
                     c = position(m_mesh.target(m_mesh.next(h)));
      m_face_normal[f] = CGAL::cross_product(b - a, c - a);
      m_face_unit[f] = unit(m_face_normal[f]);
      m_face_area[f] = length(m_face_normal[f]) / 2;
    }
    m_edge_length.assign(m_mesh.number_of_edges(), 0);
    m_cross_normal.assign(m_mesh.number_of_edges(), Vector_3(CGAL::NULL_VECTOR));
    for (auto e : m_mesh.edges()) {
      const auto h = canonical_halfedge(e, m_mesh);
      const Face_index A = m_mesh.face(h), B = m_mesh.face(m_mesh.opposite(h));
      const Vector_3 r = position(m_mesh.source(h)), s = position(m_mesh.target(h));
      const Vector_3 q = position(m_mesh.target(m_mesh.next(m_mesh.opposite(h))));
      m_edge_length[e] = length(s - r);
      m_cross_normal[e] = unit(m_face_unit[A] + m_face_unit[B]);
      const Vector_3 nA = m_face_unit[A], nB = m_face_unit[B];
      const double angle =
          std::atan2(length(CGAL::cross_product(nA, nB)), CGAL::to_double(nA * nB));
      const bool convex = (q - r) * m_face_normal[A] <= FT(0);
      m_edges[e].dihedral = convex ? CGAL_PI - angle : CGAL_PI + angle;
    }
  }

  // S2: first approximations of the stars, corner-inner and flip points (§6.2.4).
  void first_approximation() {
    const auto& o = m_options.offsets;
    for (auto h : m_mesh.halfedges()) {
      const Face_index F = m_mesh.face(h);
      const Vector_3 a = position(m_mesh.source(h)), b = position(m_mesh.target(h)),
                     c = position(m_mesh.target(m_mesh.next(h)));
      const auto e = m_mesh.edge(h);
      m_star0[h] = (FT(4) * a + b) / FT(5);
      if (o[0] != 0)
        m_star0[h] = m_star0[h] - FT(o[0] * m_edge_length[e]) * m_cross_normal[e];
      m_inner0[h] = (FT(3) * a + b + c) / FT(5);
      const FT root_area(std::sqrt(m_face_area[F]));
      if (o[1] != 0) {
        // the faces across the two edges of F at a
        const Face_index across_ab = m_mesh.face(m_mesh.opposite(h));
        const Face_index across_ac = m_mesh.face(m_mesh.opposite(m_mesh.prev(h)));
        m_inner0[h] = m_inner0[h] +
                      FT(o[1]) * root_area * unit(m_face_unit[across_ab] + m_face_unit[across_ac]);
      }
      // the flip next to edge ab, whose apex is c
      m_flip0[h] = (c + FT(2) * a + FT(2) * b) / FT(5);
      if (o[2] != 0)
        m_flip0[h] = m_flip0[h] + FT(o[2]) * root_area * m_face_unit[F];
    }
  }

  Vector_3 normal_by(Corner_plane_normal method, Vertex_index v,
                     const std::vector<Halfedge_index>& ring, const Vector_3& C) const {
    Vector_3 area(0, 0, 0);
    for (auto h : ring)
      area = area + m_face_normal[m_mesh.face(h)];
    switch (method) {
    case Corner_plane_normal::CENTROID: {
      Vector_3 N = position(v) - C;
      return N * area < FT(0) ? -N : N;
    }
    case Corner_plane_normal::AVERAGE: {
      Vector_3 N(0, 0, 0);
      for (auto h : ring)
        N = N + m_face_unit[m_mesh.face(h)];
      return N;
    }
    default:
      return area;
    }
  }

  bool vanishes(const Vector_3& N, Vertex_index v) const {
    if (N == CGAL::NULL_VECTOR)
      return true;
    if (CGAL::Algebraic_structure_traits<FT>::Is_exact::value)
      return false;
    double scale = 0;
    for (auto h : CGAL::halfedges_around_source(v, m_mesh))
      scale = std::max(scale, m_edge_length[m_mesh.edge(h)]);
    return length(N) <= 1e-12 * std::max(scale, scale * scale);
  }

  // S3–S6 for one vertex.
  void corner_region(Vertex_index v) {
    Corner_plane<Kernel>& plane = m_planes[v];
    const std::vector<Halfedge_index> ring = outgoing_ring(v, m_mesh);
    const std::size_t n = ring.size();
    const Vector_3 pv = position(v);
    // S3: centroid of the first stars [U1] and the normal with the fallback chain
    Vector_3 C(0, 0, 0);
    for (auto h : ring)
      C = C + m_star0[h];
    C = C / FT(int(n));
    plane.centroid = C;
    const std::array<Corner_plane_normal, 3> chain{{Corner_plane_normal::CENTROID,
                                                    Corner_plane_normal::AREA_WEIGHTED,
                                                    Corner_plane_normal::AVERAGE}};
    std::vector<Corner_plane_normal> order{m_options.normal};
    for (auto m : chain)
      if (m != m_options.normal)
        order.push_back(m);
    bool found = false;
    for (auto method : order) {
      Vector_3 N = normal_by(method, v, ring, C);
      if (!vanishes(N, v)) {
        plane.normal = N;
        plane.normal_used = method;
        plane.normal_fallback = method != m_options.normal;
        found = true;
        break;
      }
    }
    if (!found)
      throw Invalid_input("pseudo-AG1: every corner-plane normal vanishes at vertex " +
                          std::to_string(std::size_t(v)));
    const Vector_3& N = plane.normal;
    // chart: drop the largest |N| component; keep CCW about N
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (CGAL::abs(N[i]) > CGAL::abs(N[axis]))
        axis = i;
    m_chart_axis[v] = axis;
    m_chart_flip[v] = N[axis] < FT(0);
    // S4: position, raised or lowered by the mean dihedral angle
    double mean = 0;
    for (auto h : ring)
      mean += m_edges[m_mesh.edge(h)].dihedral;
    plane.mean_dihedral = mean / double(n);
    const FT D = (C - pv) * N;
    FT H = FT(m_options.plane_position) * D;
    if (m_options.undulation_gain != 0 && D != FT(0))
      H = H + FT(m_options.undulation_gain *
                 (plane.mean_dihedral - m_options.undulation_threshold) / CGAL_PI) *
                  CGAL::abs(D);
    plane.offset = H;
    // S5: corner point on the line v -> C (R-5b when the line is parallel to the plane)
    const Vector_3 z0 = D != FT(0) ? pv + (H / D) * (C - pv) : pv;
    std::vector<typename Kernel::Point_2> P;
    std::vector<Vector_3> projected;
    for (auto h : ring) {
      projected.push_back(project(v, m_star0[h]));
      P.push_back(chart(v, projected.back()));
    }
    plane.corner = z0;
    bool use_umbrella = m_options.placement == Star_placement::UMBRELLA;
    if (m_options.recentering) {
      const auto result = internal::recenter<Kernel>(P, chart(v, z0));
      if (!result.simple_ccw) {
        plane.folded_projection = true;
        // the umbrella needs angles and lengths: the surface is no longer exact
        use_umbrella = true;
        m_exact = false;
      } else if (result.recentred) {
        plane.recentred = true;
        plane.corner = lift(v, result.center);
      }
    }
    place_stars(v, ring, projected, use_umbrella);
  }

  // S6: the stars in the corner plane.
  void place_stars(Vertex_index v, const std::vector<Halfedge_index>& ring,
                   const std::vector<Vector_3>& projected, bool use_umbrella) {
    Corner_plane<Kernel>& plane = m_planes[v];
    const std::size_t n = ring.size();
    const Vector_3 pv = position(v), z = plane.corner;
    const FT sigma(plane.star_scale);
    if (!use_umbrella) {
      for (std::size_t i = 0; i < n; ++i)
        m_star[ring[i]] = z + sigma * (projected[i] - z);
    } else {
      const double pi = CGAL_PI;
      const Vector_3 Nu = unit(plane.normal);
      // an orthonormal basis (e1, e2) of the plane with e1 x e2 = N
      const std::array<double, 3> nd{
          {CGAL::to_double(Nu.x()), CGAL::to_double(Nu.y()), CGAL::to_double(Nu.z())}};
      const std::array<double, 3> t = std::abs(nd[0]) < 0.9 ? std::array<double, 3>{{1, 0, 0}}
                                                            : std::array<double, 3>{{0, 1, 0}};
      auto dcross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{
            {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
      };
      auto dnorm = [](std::array<double, 3> a) {
        const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (double& x : a)
          x /= l;
        return a;
      };
      const auto e1 = dnorm(dcross(t, nd));
      const auto e2 = dcross(nd, e1);
      auto to3 = [](const Vector_3& a) {
        return std::array<double, 3>{
            {CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())}};
      };
      auto ddot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      };
      std::vector<double> alpha(n), spoke(n), phi(n), radius(n);
      double total = 0, spokes = 0, projected_spokes = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto a = to3(m_star0[ring[i]] - pv), b = to3(m_star0[ring[(i + 1) % n]] - pv);
        const auto c = dcross(a, b);
        alpha[i] = std::atan2(std::sqrt(ddot(c, c)), ddot(a, b));
        total += alpha[i];
        spoke[i] = std::sqrt(ddot(a, a));
        spokes += spoke[i];
        const auto p = to3(projected[i] - z);
        phi[i] = std::atan2(ddot(p, e2), ddot(p, e1));
        radius[i] = std::sqrt(ddot(p, p));
        projected_spokes += radius[i];
      }
      std::vector<double> angle(n);
      for (std::size_t i = 0; i < n; ++i)
        angle[i] = m_options.angles == Umbrella_angles::EQUAL ? 2 * pi / double(n)
                                                              : 2 * pi * alpha[i] / total;
      // an angle of pi or more makes a corner triangle degenerate or inverted. Ours: so
      // does an angle near 0 (a sliver face at v), and in double the relations of its edges
      // then carry 1/sin(angle) and round-off breaks the diamonds: same cure.
      const double degenerate = 1e-6;
      auto ill = [&] {
        const auto [lo, hi] = std::minmax_element(angle.begin(), angle.end());
        return *hi >= pi - degenerate || *lo <= degenerate;
      };
      if (ill()) {
        plane.equalised = true;
        const std::vector<double> original = angle;
        for (int step = 1; step <= 20; ++step) {
          const double w = 0.05 * step;
          for (std::size_t i = 0; i < n; ++i)
            angle[i] = (1 - w) * original[i] + w * 2 * pi / double(n);
          if (!ill())
            break;
        }
      }
      std::vector<double> rho(n), theta(n);
      for (std::size_t i = 0; i < n; ++i) {
        switch (m_options.lengths) {
        case Umbrella_lengths::RIGID:
          rho[i] = plane.star_scale * spoke[i];
          break;
        case Umbrella_lengths::PROPORTIONAL:
          rho[i] = plane.star_scale * spoke[i] * projected_spokes / spokes;
          break;
        default:
          rho[i] = plane.star_scale * spokes / double(n);
          break;
        }
        theta[i] = i == 0 ? 0 : theta[i - 1] + angle[i - 1];
      }
      double theta0 = phi[0];
      if (m_options.rotation == Umbrella_rotation::LEAST_SQUARES) {
        double sy = 0, sx = 0;
        for (std::size_t i = 0; i < n; ++i) {
          sy += rho[i] * radius[i] * std::sin(phi[i] - theta[i]);
          sx += rho[i] * radius[i] * std::cos(phi[i] - theta[i]);
        }
        theta0 = std::atan2(sy, sx);
      }
      for (std::size_t i = 0; i < n; ++i) {
        const double c = rho[i] * std::cos(theta0 + theta[i]),
                     s = rho[i] * std::sin(theta0 + theta[i]);
        const Vector_3 offset(FT(c * e1[0] + s * e2[0]), FT(c * e1[1] + s * e2[1]),
                              FT(c * e1[2] + s * e2[2]));
        // keep the star exactly on the plane in the arithmetic at hand
        m_star[ring[i]] = project(v, z + offset);
      }
    }
    plane.umbrella.clear();
    const auto zc = chart(v, z);
    for (std::size_t i = 0; i < n; ++i)
      plane.umbrella.push_back(CGAL::ORIGIN + (chart(v, m_star[ring[i]]) - zc));
    plane.inverted_corner = false;
    for (std::size_t i = 0; i < n; ++i)
      if (CGAL::orientation(typename Kernel::Point_2(CGAL::ORIGIN), plane.umbrella[i],
                            plane.umbrella[(i + 1) % n]) != CGAL::LEFT_TURN)
        plane.inverted_corner = true;
  }

  // S8: corner-inner points.
  void inner_points() {
    for (auto h : m_mesh.halfedges()) {
      m_inner[h] = m_inner0[h];
      if (m_options.inner != Inner_placement::CROSS_EDGE_PLANES)
        continue;
      const Halfedge_index ac = m_mesh.opposite(m_mesh.prev(h));
      const Vector_3 n1 = m_cross_normal[m_mesh.edge(h)], n2 = m_cross_normal[m_mesh.edge(ac)];
      const Vector_3 x = m_inner0[h];
      const double a11 = CGAL::to_double(n1 * n1), a12 = CGAL::to_double(n1 * n2),
                   a22 = CGAL::to_double(n2 * n2);
      const double b1 = CGAL::to_double((m_star[h] - x) * n1),
                   b2 = CGAL::to_double((m_star[ac] - x) * n2);
      const double det = a11 * a22 - a12 * a12;
      if (std::abs(det) <= 1e-12 * a11 * a22) {
        if (a11 > 0)
          m_inner[h] = x + FT(b1 / a11) * n1;
        continue;
      }
      const double s = (b1 * a22 - b2 * a12) / det, t = (a11 * b2 - a12 * b1) / det;
      m_inner[h] = x + FT(s) * n1 + FT(t) * n2;
    }
  }

  // S9: end relations and the edge maps.
  void edge_maps() {
    for (auto e : m_mesh.edges()) {
      Pseudo_AG1_edge<FT>& E = m_edges[e];
      const Halfedge_index h = canonical_halfedge(e, m_mesh), o = m_mesh.opposite(h);
      const Vertex_index r = m_mesh.source(h), s = m_mesh.target(h);
      const Halfedge_index rp = m_mesh.opposite(m_mesh.prev(h)), rq = m_mesh.next(o);
      const Halfedge_index sp = m_mesh.next(h), sq = m_mesh.opposite(m_mesh.prev(o));
      E.end_r_valid = barycentric(chart(r, m_star[rq]), chart(r, m_star[rp]),
                                  chart(r, m_planes[r].corner), chart(r, m_star[h]), E.end_r);
      E.end_s_valid = barycentric(chart(s, m_star[sq]), chart(s, m_star[sp]), chart(s, m_star[o]),
                                  chart(s, m_planes[s].corner), E.end_s);
      E.relation = {{FT(-1), FT(1), FT(1)}};
      E.averaged_fallback = false;
      if (m_options.edge_map == Edge_map::AVERAGED_DIAMOND) {
        auto convex = [](const std::array<FT, 3>& R) {
          return R[0] < FT(0) && R[1] > FT(0) && R[2] > FT(0);
        };
        std::array<FT, 3> mean;
        for (std::size_t i = 0; i < 3; ++i)
          mean[i] = (E.end_r[i] + E.end_s[i]) / FT(2);
        // Propagation divides by mu and nu (D_3, D_1): a thin diamond would throw the
        // edge-middle points far away (spikes), so such edges keep the parallelogram.
        const FT least(m_options.min_averaged_weight);
        auto bounded = [&](const FT& x) { return x >= least && x * least <= FT(1); };
        if (E.end_r_valid && E.end_s_valid && convex(E.end_r) && convex(E.end_s) &&
            bounded(-mean[0]) && bounded(mean[1]) && bounded(mean[2])) {
          E.relation = mean;
        } else {
          E.averaged_fallback = true;
        }
      }
    }
  }

  // S10: edge-middle points from D_3 and D_1, flips from D_2 (AG1.md §1.3).
  void propagate() {
    for (auto e : m_mesh.edges())
      propagate_edge(e);
  }
  void propagate_edge(Edge_index e) {
    const auto& R = m_edges[e].relation;
    const FT &lambda = R[0], &mu = R[1], &nu = R[2];
    const Halfedge_index h = canonical_halfedge(e, m_mesh), o = m_mesh.opposite(h);
    // I_A(r) = inner[h], I_B(r) = inner[next(o)], I_A(s) = inner[next(h)], I_B(s) = inner[o]
    m_middle[h] = (m_inner[m_mesh.next(o)] - lambda * m_inner[h] - mu * m_star[h]) / nu;
    m_middle[o] = (m_inner[o] - lambda * m_inner[m_mesh.next(h)] - nu * m_star[o]) / mu;
    const Vector_3 c = mu * m_middle[h] + nu * m_middle[o];
    const Vector_3 &a0 = m_flip0[h], &b0 = m_flip0[o];
    const Face_index A = m_mesh.face(h), B = m_mesh.face(o);
    bool prescribe_A = true;
    switch (m_options.flips) {
    case Flip_rule::SYMMETRIC: {
      const Vector_3 d = c - (b0 - lambda * a0);
      const FT w = FT(1) + lambda * lambda;
      m_flip[h] = a0 - (lambda / w) * d;
      m_flip[o] = b0 + d / w;
      return;
    }
    case Flip_rule::LARGER_FACE: {
      // compared in FT (exact for an exact kernel): on symmetric meshes the areas tie, and a
      // tie decided by round-off would depend on the labelling
      const FT a = m_face_normal[A].squared_length(), b = m_face_normal[B].squared_length();
      prescribe_A = a > b || (a == b && std::size_t(A) < std::size_t(B));
      break;
    }
    default:
      prescribe_A = std::size_t(A) < std::size_t(B);
      break;
    }
    if (prescribe_A) {
      m_flip[h] = a0;
      m_flip[o] = lambda * a0 + c;
    } else {
      m_flip[o] = b0;
      m_flip[h] = (b0 - c) / lambda;
    }
  }

public:
  /*!
    returns the dip of the edge control polygon of `e` (AG1.md §6 M6, Fig. 6.7): the largest
    second difference of \f$z_r, S_{r\to s}, M_{r\to s}, M_{s\to r}, S_{s\to r}, z_s\f$ along the
    cross-edge normal, signed so that positive means the edge curve bends against the input's
    convexity, relative to the edge length.
    \param e the edge
    \returns the dip (positive: the edge dips)
  */
  double dip(Edge_index e) const {
    const Halfedge_index h = canonical_halfedge(e, m_mesh), o = m_mesh.opposite(h);
    const std::array<Vector_3, 6> b{{m_planes[m_mesh.source(h)].corner, m_star[h], m_middle[h],
                                     m_middle[o], m_star[o], m_planes[m_mesh.target(h)].corner}};
    const double sign = m_edges[e].dihedral <= CGAL_PI ? 1 : -1;
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < 5; ++k)
      worst = std::max(
          worst, sign * CGAL::to_double((b[k - 1] - FT(2) * b[k] + b[k + 1]) * m_cross_normal[e]) /
                     m_edge_length[e]);
    return worst;
  }

private:
  // S7: shrink the stars at both ends of dipping edges, at most 5 rounds.
  void shrink() {
    for (m_shrinking_rounds = 0; m_shrinking_rounds < 5; ++m_shrinking_rounds) {
      std::vector<bool> changed(m_mesh.number_of_vertices(), false);
      bool any = false;
      for (auto e : m_mesh.edges())
        if (dip(e) > 0.01)
          for (auto v : {m_mesh.vertex(e, 0), m_mesh.vertex(e, 1)})
            if (m_planes[v].star_scale > 0.5 && !changed[v]) {
              m_planes[v].star_scale = std::max(0.5, 0.9 * m_planes[v].star_scale);
              changed[v] = any = true;
            }
      if (!any)
        break;
      for (auto v : m_mesh.vertices())
        if (changed[v])
          corner_region(v);
      inner_points();
      edge_maps();
      propagate();
    }
  }

  Mesh m_mesh;
  Pseudo_AG1_options m_options;
  Closed_mesh_summary m_summary;
  bool m_exact = false;
  std::size_t m_shrinking_rounds = 0;
  std::vector<Vector_3> m_face_normal, m_face_unit;
  std::vector<double> m_face_area, m_edge_length;
  std::vector<Vector_3> m_cross_normal;
  std::vector<Pseudo_AG1_edge<FT>> m_edges;
  std::vector<Corner_plane<Kernel>> m_planes;
  std::vector<int> m_chart_axis;
  std::vector<bool> m_chart_flip;
  // per halfedge h = (source -> target): stars and edge-middles of source towards target,
  // corner-inner of face(h) at source(h), flip of face(h) next to edge(h)
  std::vector<Vector_3> m_star0, m_star, m_middle, m_inner0, m_inner, m_flip0, m_flip;
};

/*!
  \ingroup PkgTriangularSplinePseudoAG1
  \brief builds the pseudo-AG\f$^1\f$ surface of any closed triangle face graph.
  \tparam Kernel the kernel of the surface
  \tparam FaceGraph a model of `FaceListGraph`
  \tparam VertexPointMap a readable property map from vertices to points convertible to
  `Kernel::Point_3`
  \param graph the closed triangle mesh
  \param points its vertex positions
  \param options the parameters
  \returns the surface
*/
template <class Kernel, class FaceGraph, class VertexPointMap>
Pseudo_AG1_surface<Kernel> make_pseudo_AG1_surface(const FaceGraph& graph, VertexPointMap points,
                                                   const Pseudo_AG1_options& options) {
  CGAL::Surface_mesh<typename Kernel::Point_3> mesh;
  CGAL::copy_face_graph(graph, mesh, CGAL::parameters::vertex_point_map(points));
  return Pseudo_AG1_surface<Kernel>(mesh, options);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_PSEUDO_AG1_SURFACE_H

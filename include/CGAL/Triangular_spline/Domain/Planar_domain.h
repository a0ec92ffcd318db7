// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DOMAIN_PLANAR_DOMAIN_H
#define CGAL_TRIANGULAR_SPLINE_DOMAIN_PLANAR_DOMAIN_H

#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/filtered_orientation.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/release.h>
#include <CGAL/Triangular_spline/internal/text.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Bbox_2.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {
// Selects the Planar_domain constructor for the faces of a CGAL triangulation of the points.
struct Triangulation_faces_tag {};
} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief a validated triangulation of a planar domain: the parameter domain of a spline.

  Vertices are points of the plane, faces are triangles given by vertex indices and stored
  counter-clockwise; edges are numbered once each. The domain may be any manifold
  triangulation of a region of the plane: non-convex, with holes, with sharp corners.
  Construction checks, with the kernel's exact predicates, everything the spline
  algorithms rely on, and throws `Invalid_input` with a message naming the culprit:

  - at least one triangle, indices in range, finite coordinates;
  - no two vertices at the same point, no unused vertex;
  - no zero-area triangle (exact collinearity test);
  - every edge in at most two triangles, which lie on opposite sides of it (no fold);
  - every vertex is manifold: its triangles form one fan, which turns once around an
    interior vertex and less than once around a boundary vertex.

  - no two triangles overlap, and no vertex lies inside an edge it does not end (a
    T-junction): triangles sharing no vertex are compared pairwise where their bounding
    boxes meet (`CGAL::box_self_intersection_d()`, exact orientation tests), which catches
    separate parts that cross and triangulations that spiral over themselves. Callers
    holding a triangulation known to be embedded (a CGAL triangulation's faces) may skip
    this test, the only one that is not linear in the size.

  The adjacency is stored in flat arrays (no per-element allocation), so domains of
  \f$10^6\f$ triangles are cheap. Every CGAL triangulation or face graph can be turned into
  a `Planar_domain` with `domain_from_triangulation_2()` or `domain_from_face_graph()`.

  \tparam GeomTraits a model of `Kernel`
*/
template <class GeomTraits>
class Planar_domain {
public:
  /// the kernel
  using Geom_traits = GeomTraits;
  /// the number type
  using FT = typename Geom_traits::FT;
  /// the point type
  using Point_2 = typename Geom_traits::Point_2;
  /// index of a vertex, edge or face
  using Index = std::uint32_t;
  /// marks a missing neighbour (the outside of a boundary edge)
  static constexpr Index null_index = (std::numeric_limits<Index>::max)();

  /// creates the domain from points and triangles (vertex indices, any orientation: each
  /// triangle is reoriented counter-clockwise).
  /// \param check_overlaps `false` skips the global overlap test (for triangulations known to
  /// be embedded, such as the faces of a CGAL triangulation)
  /// \throws Invalid_input if the triangulation violates one of the rules above
  /// \param points the vertex positions
  /// \param triangles the triangles, as triples of indices into `points`
  /// \param traits the geometric traits
  Planar_domain(std::vector<Point_2> points, std::vector<std::array<Index, 3>> triangles,
                const Geom_traits& traits = Geom_traits(), bool check_overlaps = true)
      : m_points(std::move(points)), m_faces(std::move(triangles)), m_traits(traits) {
    enclose_points();
    validate_and_orient();
    Incidence incidence = face_incidence();
    build_edges(incidence);
    build_stars(incidence, true);
    if (check_overlaps)
      check_no_overlap();
  }
  /// \cond SKIP_IN_MANUAL
  // (internal) The faces of a CGAL triangulation of `points` (delaunay_domain()), each
  // counter-clockwise by the kernel's own exact predicates, of distinct points, every point
  // a vertex, embedded: the checks only such faces pass are skipped (the sort for repeated
  // points, an orientation test per triangle, the turn of each fan; 0.2 s of wall time at
  // 10^6 random points, and with exact predicates the costliest part of the conversion).
  // Building the adjacency still checks what it reads.
  Planar_domain(internal::Triangulation_faces_tag, std::vector<Point_2> points,
                std::vector<std::array<Index, 3>> triangles,
                const Geom_traits& traits = Geom_traits())
      : m_points(std::move(points)), m_faces(std::move(triangles)), m_traits(traits) {
    enclose_points();
    check_vertices();
    Incidence incidence = face_incidence();
    build_edges(incidence);
    build_stars(incidence, false);
  }
  /// \endcond

  /// \name Sizes
  /// @{

  /// returns the number of vertices.
  /// \returns the number of vertices
  std::size_t number_of_vertices() const { return m_points.size(); }
  /// returns the number of faces.
  /// \returns the number of faces
  std::size_t number_of_faces() const { return m_faces.size(); }
  /// returns the number of edges.
  /// \returns the number of edges
  std::size_t number_of_edges() const { return m_edges.size(); }
  /// returns the number of edges with two incident faces
  /// \returns the number of edges with two incident faces
  std::size_t number_of_interior_edges() const { return m_edges.size() - m_boundary_edges; }
  /// returns the number of edges with one incident face
  /// \returns the number of edges with one incident face
  std::size_t number_of_boundary_edges() const { return m_boundary_edges; }
  /// returns the number of vertices on the boundary
  /// \returns the number of vertices on the boundary
  std::size_t number_of_boundary_vertices() const { return m_boundary_vertices; }
  /// returns the number of vertices not on the boundary
  /// \returns the number of vertices not on the boundary
  std::size_t number_of_interior_vertices() const { return m_points.size() - m_boundary_vertices; }
  /// returns the number of connected components (through shared edges)
  /// \returns the number of connected components (through shared edges)
  std::size_t number_of_components() const { return m_components; }
  /// returns the number of closed boundary curves (outer boundaries and holes)
  /// \returns the number of closed boundary curves (outer boundaries and holes)
  std::size_t number_of_boundary_loops() const { return m_boundary_loops; }
  /// returns `true` iff the domain is a topological disk: connected, one boundary curve,
  /// Euler characteristic 1 (then Morgan and Scott's dimension formula applies).
  /// \returns `true` iff the domain is a topological disk
  bool is_simply_connected() const {
    const long long chi = static_cast<long long>(number_of_vertices()) -
                          static_cast<long long>(number_of_edges()) +
                          static_cast<long long>(number_of_faces());
    return m_components == 1 && m_boundary_loops == 1 && chi == 1;
  }
  /// @}

  /// \name Elements
  /// @{

  /// returns the point of vertex `v`
  /// \param v the index of a vertex
  /// \returns the point of vertex `v`
  const Point_2& point(Index v) const { return m_points[v]; }
  /// returns the points of all vertices, indexed by vertex
  /// \returns the points of all vertices, indexed by vertex
  const std::vector<Point_2>& points() const { return m_points; }
  /// returns the orientation of the points of vertices `u`, `v` and `w` (`CGAL::LEFT_TURN`
  /// if they turn counter-clockwise), decided exactly. With GMP's rationals it first tries
  /// intervals around each coordinate, converted to `double` once when the domain was built.
  /// \param u the index of a vertex
  /// \param v the index of a vertex
  /// \param w the index of a vertex
  /// \returns the orientation of the three points
  CGAL::Orientation orientation(Index u, Index v, Index w) const {
    if (m_enclosures.empty())
      return internal::filtered_orientation(m_traits, m_points[u], m_points[v], m_points[w]);
    return internal::filtered_orientation(m_traits, m_points[u], m_points[v], m_points[w],
                                          m_enclosures[u], m_enclosures[v], m_enclosures[w]);
  }
  /// returns the vertices of face `f`, counter-clockwise
  /// \param f the index of a face
  /// \returns the vertices of face `f`, counter-clockwise
  const std::array<Index, 3>& face(Index f) const { return m_faces[f]; }
  /// returns the vertices of all faces (each counter-clockwise), indexed by face
  /// \returns the vertices of all faces (each counter-clockwise), indexed by face
  const std::vector<std::array<Index, 3>>& faces() const { return m_faces; }
  /// returns the two vertices of edge `e`, the smaller index first (the canonical
  /// orientation of the edge's control-point slots)
  /// \param e the index of an edge
  /// \returns the two vertices of `e`, the smaller index first
  const std::array<Index, 2>& edge(Index e) const { return m_edges[e]; }
  /// returns the faces on the left and on the right of edge `e` oriented from
  /// `edge(e)[0]` to `edge(e)[1]`; `null_index` where there is none
  /// \param e the index of an edge
  /// \returns the left and right faces of `e`, `null_index` where there is none
  const std::array<Index, 2>& edge_faces(Index e) const { return m_edge_faces[e]; }
  /// returns `true` iff edge `e` has only one incident face
  /// \param e the index of an edge
  /// \returns `true` iff edge `e` has only one incident face
  bool is_boundary_edge(Index e) const {
    return m_edge_faces[e][0] == null_index || m_edge_faces[e][1] == null_index;
  }
  /// returns edge `i` of face `f`: the edge opposite `face(f)[i]`
  /// \param f the index of a face
  /// \param i the position, 0..2, of the vertex of `f` opposite the edge
  /// \returns edge `i` of face `f`
  Index face_edge(Index f, int i) const { return m_face_edges[f][static_cast<std::size_t>(i)]; }
  /// returns the vertex of face `f` opposite its edge `e`
  /// \param f the index of a face
  /// \param e the index of an edge
  /// \returns the vertex of face `f` opposite its edge `e`
  Index opposite_vertex(Index f, Index e) const {
    for (int i = 0; i < 3; ++i)
      if (m_face_edges[f][static_cast<std::size_t>(i)] == e)
        return m_faces[f][static_cast<std::size_t>(i)];
    return null_index;
  }
  /// returns `true` iff vertex `v` is on the boundary
  /// \param v the index of a vertex
  /// \returns `true` iff vertex `v` is on the boundary
  bool is_boundary_vertex(Index v) const { return m_vertex_boundary[v] != 0; }
  /// returns the neighbours of `v` in counter-clockwise order; for a boundary vertex the
  /// first and the last are on the boundary, and there is one more neighbour than faces
  /// \param v the index of a vertex
  /// \returns the range `[begin, end)` of the neighbours of `v`
  std::pair<const Index*, const Index*> neighbours(Index v) const {
    return {m_star_neighbours.data() + m_neighbour_offsets[v],
            m_star_neighbours.data() + m_neighbour_offsets[v + 1]};
  }
  /// returns the number of neighbours of `v`
  /// \param v the index of a vertex
  /// \returns the number of neighbours of `v`
  std::size_t degree(Index v) const { return m_neighbour_offsets[v + 1] - m_neighbour_offsets[v]; }
  /// returns the faces around `v` counter-clockwise: face `i` is
  /// (`v`, neighbour `i`, neighbour `i+1` mod degree)
  /// \param v the index of a vertex
  /// \returns the range `[begin, end)` of the faces around `v`
  std::pair<const Index*, const Index*> star_faces(Index v) const {
    return {m_star_faces.data() + m_face_offsets[v], m_star_faces.data() + m_face_offsets[v + 1]};
  }
  /// returns the edges around `v` in the order of `neighbours(v)`
  /// \param v the index of a vertex
  /// \returns the edges around `v` in the order of `neighbours(v)`
  std::pair<const Index*, const Index*> star_edges(Index v) const {
    return {m_star_edges.data() + m_neighbour_offsets[v],
            m_star_edges.data() + m_neighbour_offsets[v + 1]};
  }
  /// returns the kernel instance
  /// \returns the kernel instance
  const Geom_traits& geom_traits() const { return m_traits; }
  /// @}

private:
  // Threads for n items of exact predicates: an exact orientation test costs about a
  // thousand times a filtered one (the face and fan checks of 10^5 exact points took 0.5 s).
  static std::size_t checking_threads(std::size_t n) {
    constexpr bool exact = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
    return internal::thread_count(n, exact ? 1000 : 20000);
  }

  std::string vertex_name(Index v) const {
    return "vertex " + std::to_string(v) + " " + internal::point_to_string(m_points[v]);
  }

  // Intervals around the coordinates, for orientation(), where the number type converts
  // with a division (GMP's rationals): each point's once, on all cores, instead of six
  // divisions per test (a tenth of the CPU of an exact build of 10^5 17-digit points went to
  // the conversions).
  void enclose_points() {
    if constexpr (internal::has_orientation_filter<FT>()) {
      const std::size_t n = m_points.size();
      m_enclosures.resize(n);
      internal::parallel_for_index(n, internal::thread_count(n, 20000), [this](std::size_t v) {
        m_enclosures[v] = internal::enclose_point(m_points[v]);
      });
    }
  }

  // At least one triangle, finite coordinates, indices that fit.
  void check_vertices() const {
    if (m_faces.empty())
      throw Invalid_input("domain: no triangle");
    const std::size_t n = m_points.size();
    for (std::size_t v = 0; v < n; ++v)
      if (!CGAL::is_finite(m_points[v].x()) || !CGAL::is_finite(m_points[v].y()))
        throw Invalid_input("domain: " + vertex_name(static_cast<Index>(v)) +
                            " has a non-finite coordinate");
    if (n >= null_index)
      throw Invalid_input("domain: too many vertices");
  }

  void validate_and_orient() {
    check_vertices();
    const std::size_t n = m_points.size();
    // Duplicate points, decided by exact comparison after sorting.
    std::vector<Index> order(n);
    std::iota(order.begin(), order.end(), Index(0));
    auto less = m_traits.less_xy_2_object();
    std::sort(order.begin(), order.end(),
              [&](Index a, Index b) { return less(m_points[a], m_points[b]); });
    for (std::size_t i = 1; i < n; ++i)
      if (m_points[order[i - 1]] == m_points[order[i]])
        throw Invalid_input("domain: vertices " + std::to_string(order[i - 1]) + " and " +
                            std::to_string(order[i]) + " are the same point " +
                            internal::point_to_string(m_points[order[i]]));
    // Each face on its own, on all cores; the error of the first bad face, as in face order.
    internal::parallel_for_index(
        m_faces.size(), checking_threads(m_faces.size()), [&](std::size_t f) {
          auto& t = m_faces[f];
          for (Index v : t)
            if (v >= n)
              throw Invalid_input("domain: triangle " + std::to_string(f) + " uses vertex " +
                                  std::to_string(v) + " but there are only " + std::to_string(n));
          if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            throw Invalid_input("domain: triangle " + std::to_string(f) + " repeats a vertex");
          const CGAL::Orientation o = orientation(t[0], t[1], t[2]);
          if (o == CGAL::COLLINEAR)
            throw Invalid_input("domain: triangle " + std::to_string(f) + " (" +
                                std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                                std::to_string(t[2]) + ") has zero area (collinear corners)");
          if (o == CGAL::CLOCKWISE)
            std::swap(t[1], t[2]);
        });
    std::vector<char> used(n, 0);
    for (const auto& t : m_faces)
      for (Index v : t)
        used[v] = 1;
    for (std::size_t v = 0; v < n; ++v)
      if (!used[v])
        throw Invalid_input("domain: " + vertex_name(static_cast<Index>(v)) +
                            " is not used by any triangle");
  }

  // The faces around each vertex (CSR: vertex v's are faces[offset[v] .. offset[v + 1]), in
  // increasing order), read by build_edges() and build_stars().
  struct Incidence {
    std::vector<std::size_t> offset;
    std::vector<Index> faces;
  };
  Incidence face_incidence() const {
    const std::size_t n = m_points.size();
    Incidence incidence;
    incidence.offset.assign(n + 1, 0);
    for (const auto& t : m_faces)
      for (Index v : t)
        ++incidence.offset[v + 1];
    for (std::size_t v = 0; v < n; ++v)
      incidence.offset[v + 1] += incidence.offset[v];
    incidence.faces.resize(incidence.offset[n]);
    std::vector<std::size_t> fill(incidence.offset.begin(), incidence.offset.end() - 1);
    for (std::size_t f = 0; f < m_faces.size(); ++f)
      for (Index v : m_faces[f])
        incidence.faces[fill[v]++] = static_cast<Index>(f);
    return incidence;
  }

  // The edges, numbered in the order of their (smaller, larger) vertex pairs, with their
  // faces and each face's edges: vertex by vertex, from the half-edges of its faces to its
  // larger neighbours (linear time, on all cores). A sort of all 3F half-edges took half of
  // the conversion of a 10^6-point Delaunay triangulation, most of it faulting in the
  // sort's 96 MB and the edge arrays' growth.
  void build_edges(const Incidence& incidence) {
    const std::size_t n = m_points.size();
    struct Half_edge {
      Index other; // the larger end (the smaller is the vertex)
      Index face;
      int side;     // index of the edge in its face (opposite vertex)
      bool forward; // traversed smaller -> larger by the counter-clockwise face
    };
    using Half_edges = boost::container::small_vector<Half_edge, 24>;
    // v's half-edges to larger neighbours, sorted by neighbour, faces in increasing order
    auto upward = [&](Index v, Half_edges& out) {
      out.clear();
      for (std::size_t k = incidence.offset[v]; k < incidence.offset[v + 1]; ++k) {
        const Index f = incidence.faces[k];
        const auto& t = m_faces[f];
        const int p = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        const Index next = t[static_cast<std::size_t>((p + 1) % 3)];
        const Index prev = t[static_cast<std::size_t>((p + 2) % 3)];
        if (next > v)
          out.push_back({next, f, (p + 2) % 3, true}); // v -> next, opposite prev
        if (prev > v)
          out.push_back({prev, f, (p + 1) % 3, false}); // prev -> v, opposite next
      }
      for (std::size_t i = 1; i < out.size(); ++i)
        for (std::size_t j = i; j > 0 && out[j].other < out[j - 1].other; --j)
          std::swap(out[j], out[j - 1]);
    };
    // calls edge(begin, end) for each of v's edges to a larger neighbour, in order, with its
    // half-edges [begin, end), after checking that they form an edge
    auto for_each_edge = [&](Index v, const Half_edges& h, const auto& edge) {
      for (std::size_t i = 0; i < h.size();) {
        std::size_t j = i;
        while (j < h.size() && h[j].other == h[i].other)
          ++j;
        if (j - i > 2)
          throw Invalid_input("domain: edge (" + std::to_string(v) + ", " +
                              std::to_string(h[i].other) + ") is shared by " +
                              std::to_string(j - i) + " triangles (non-manifold)");
        if (j - i == 2 && h[i].forward == h[i + 1].forward)
          throw Invalid_input("domain: triangles " + std::to_string(h[i].face) + " and " +
                              std::to_string(h[i + 1].face) + " overlap along edge (" +
                              std::to_string(v) + ", " + std::to_string(h[i].other) + ")");
        edge(h.begin() + std::ptrdiff_t(i), h.begin() + std::ptrdiff_t(j));
        i = j;
      }
    };
    const std::size_t threads = internal::thread_count(n, 20000);
    // each vertex's first edge (its count, then the sums); the half-edges are gathered again
    // below (kept, they would take the memory this avoids)
    std::vector<std::size_t> first_edge(n + 1, 0);
    internal::parallel_for_index(n, threads, [&](std::size_t v) {
      Half_edges h;
      upward(static_cast<Index>(v), h);
      for_each_edge(static_cast<Index>(v), h, [&](auto, auto) { ++first_edge[v + 1]; });
    });
    for (std::size_t v = 0; v < n; ++v)
      first_edge[v + 1] += first_edge[v];
    if (first_edge[n] >= null_index)
      throw Invalid_input("domain: too many edges");
    m_edges.resize(first_edge[n]);
    m_edge_faces.resize(first_edge[n]);
    m_face_edges.assign(m_faces.size(), {{null_index, null_index, null_index}});
    internal::parallel_for_index(n, threads, [&](std::size_t v) {
      Half_edges h;
      upward(static_cast<Index>(v), h);
      Index e = static_cast<Index>(first_edge[v]);
      for_each_edge(static_cast<Index>(v), h, [&](auto begin, auto end) {
        m_edges[e] = {{static_cast<Index>(v), begin->other}};
        // a face traversing smaller -> larger counter-clockwise lies on the left of the edge
        std::array<Index, 2> faces{{null_index, null_index}};
        for (auto it = begin; it != end; ++it) {
          faces[it->forward ? 0 : 1] = it->face;
          m_face_edges[it->face][static_cast<std::size_t>(it->side)] = e;
        }
        m_edge_faces[e++] = faces;
      });
    });
    m_boundary_edges = 0;
    for (const auto& faces : m_edge_faces)
      if (faces[0] == null_index || faces[1] == null_index)
        ++m_boundary_edges;
    count_components_and_loops();
  }

  void count_components_and_loops() {
    // Components through shared edges.
    std::vector<Index> parent(m_faces.size());
    std::iota(parent.begin(), parent.end(), Index(0));
    auto find = [&](Index x) {
      while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const auto& ef : m_edge_faces)
      if (ef[0] != null_index && ef[1] != null_index)
        parent[find(ef[0])] = find(ef[1]);
    m_components = 0;
    for (std::size_t f = 0; f < parent.size(); ++f)
      if (find(static_cast<Index>(f)) == f)
        ++m_components;
    // Boundary loops: at a manifold boundary vertex exactly one boundary edge leaves and
    // one arrives, so the boundary edges form disjoint cycles; count them by union-find.
    std::vector<Index> vparent(m_points.size());
    std::iota(vparent.begin(), vparent.end(), Index(0));
    auto vfind = [&](Index x) {
      while (vparent[x] != x)
        x = vparent[x] = vparent[vparent[x]];
      return x;
    };
    std::vector<char> on_boundary(m_points.size(), 0);
    for (std::size_t e = 0; e < m_edges.size(); ++e)
      if (is_boundary_edge(static_cast<Index>(e))) {
        on_boundary[m_edges[e][0]] = on_boundary[m_edges[e][1]] = 1;
        vparent[vfind(m_edges[e][0])] = vfind(m_edges[e][1]);
      }
    m_boundary_loops = 0;
    for (std::size_t v = 0; v < m_points.size(); ++v)
      if (on_boundary[v] && vfind(static_cast<Index>(v)) == v)
        ++m_boundary_loops;
  }

  // The faces around each vertex ordered into one fan; `check_turns`: and each fan turns
  // at most once (not needed for a CGAL triangulation's faces).
  void build_stars(Incidence& incidence, bool check_turns) {
    const std::size_t n = m_points.size();
    const std::vector<std::size_t>& offset = incidence.offset;
    const std::vector<Index>& incident = incidence.faces;

    m_vertex_boundary.assign(n, 0);
    m_face_offsets.assign(n + 1, 0);
    m_neighbour_offsets.assign(n + 1, 0);
    m_star_faces.reserve(offset[n]);
    m_star_neighbours.reserve(offset[n] + n);
    m_star_edges.reserve(offset[n] + n);
    for (std::size_t vi = 0; vi < n; ++vi) {
      const Index v = static_cast<Index>(vi);
      const std::size_t begin = offset[v], end = offset[v + 1];
      // Position of v in face f, and the next / previous vertex counter-clockwise.
      auto next_of = [&](Index f) {
        const auto& t = m_faces[f];
        const int i = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        return t[static_cast<std::size_t>((i + 1) % 3)];
      };
      auto prev_of = [&](Index f) {
        const auto& t = m_faces[f];
        const int i = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        return t[static_cast<std::size_t>((i + 2) % 3)];
      };
      auto edge_between = [&](Index f, Index w) {
        // the edge of f joining v and w is opposite the third vertex
        const auto& t = m_faces[f];
        for (int i = 0; i < 3; ++i)
          if (t[static_cast<std::size_t>(i)] != v && t[static_cast<std::size_t>(i)] != w)
            return m_face_edges[f][static_cast<std::size_t>(i)];
        return null_index;
      };
      auto face_across = [&](Index e, Index f) {
        const auto& ef = m_edge_faces[e];
        return ef[0] == f ? ef[1] : ef[0];
      };
      // Walk clockwise from any face to the start of the fan (a boundary edge, or back).
      Index start = incident[begin];
      bool boundary = false;
      for (std::size_t steps = 0; steps < end - begin; ++steps) {
        const Index e = edge_between(start, next_of(start));
        const Index before = face_across(e, start);
        if (before == null_index) {
          boundary = true;
          break;
        }
        start = before;
      }
      // Walk counter-clockwise: face (v, w_i, w_{i+1}).
      Index f = start;
      const Index first = next_of(f);
      m_star_neighbours.push_back(first);
      m_star_edges.push_back(edge_between(f, first));
      std::size_t faces_in_fan = 0;
      for (;;) {
        m_star_faces.push_back(f);
        ++faces_in_fan;
        const Index w = prev_of(f);
        const Index e = edge_between(f, w);
        const Index after = face_across(e, f);
        if (after == null_index || after == start) {
          if (after == null_index) {
            m_star_neighbours.push_back(w);
            m_star_edges.push_back(e);
          }
          break;
        }
        if (faces_in_fan > end - begin)
          break;
        m_star_neighbours.push_back(w);
        m_star_edges.push_back(e);
        f = after;
      }
      if (faces_in_fan != end - begin)
        throw Invalid_input("domain: " + vertex_name(v) +
                            " is non-manifold (its triangles form more than one fan)");
      m_vertex_boundary[v] = boundary ? 1 : 0;
      if (boundary)
        ++m_boundary_vertices;
      m_face_offsets[v + 1] = m_star_faces.size();
      m_neighbour_offsets[v + 1] = m_star_neighbours.size();
    }
    internal::release(incidence.faces); // (`incident` and `offset` are not read again)
    internal::release(incidence.offset);
    if (!check_turns)
      return;
    // The fan must turn once (interior) or less than once (boundary): no later cone may
    // contain the direction of the first neighbour (exact orientation tests). Vertex by
    // vertex on all cores, once every fan is built: the error of the first bad vertex.
    internal::parallel_for_index(n, checking_threads(n), [&](std::size_t vi) {
      const Index v = static_cast<Index>(vi);
      const auto [nb, ne] = neighbours(v);
      const std::size_t degree = static_cast<std::size_t>(ne - nb);
      const Point_2& c = m_points[v];
      const Point_2& w0 = m_points[nb[0]];
      auto ordered = m_traits.collinear_are_ordered_along_line_2_object();
      for (std::size_t i = 1; i + 1 < degree; ++i) {
        // Half-open cone [a, b) of the counter-clockwise turn from a to b (< pi).
        const Index a = nb[i], b = nb[(i + 1) % degree];
        const CGAL::Orientation from_a = orientation(v, a, nb[0]);
        const bool after_a = from_a == CGAL::LEFT_TURN ||
                             (from_a == CGAL::COLLINEAR && !ordered(m_points[a], c, w0));
        if (after_a && orientation(v, nb[0], b) == CGAL::LEFT_TURN)
          throw Invalid_input("domain: the triangles around " + vertex_name(v) +
                              " overlap (they turn more than once around it)");
      }
      if (m_vertex_boundary[v]) {
        const Point_2& last = m_points[nb[degree - 1]];
        if (orientation(v, nb[degree - 1], nb[0]) == CGAL::COLLINEAR && !ordered(w0, c, last))
          throw Invalid_input("domain: the triangles around " + vertex_name(v) +
                              " close up without closing (a slit)");
      }
    });
  }

  // Triangles sharing a vertex are disjoint once every fan turns at most once (checked in
  // build_stars()), so the domain is immersed and the number of triangles over a point only
  // changes across boundary edges: where two triangles overlap (or a vertex touches an
  // edge), a triangle with a boundary edge overlaps (or touches) another one. Only those
  // are compared with all triangles, where their bounding boxes meet.
  void check_no_overlap() const {
    if (m_boundary_edges == 0)
      return;
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, Index>;
    auto box = [this](std::size_t f) {
      const auto& t = m_faces[f];
      return Box(m_points[t[0]].bbox() + m_points[t[1]].bbox() + m_points[t[2]].bbox(),
                 static_cast<Index>(f));
    };
    std::vector<Box> all, boundary;
    all.reserve(m_faces.size());
    for (std::size_t f = 0; f < m_faces.size(); ++f) {
      all.push_back(box(f));
      for (Index e : m_face_edges[f])
        if (is_boundary_edge(e)) {
          boundary.push_back(all.back());
          break;
        }
    }
    CGAL::box_intersection_d(boundary.begin(), boundary.end(), all.begin(), all.end(),
                             [this](const Box& a, const Box& b) {
                               if (a.info() != b.info())
                                 check_pair(a.info(), b.info());
                             });
  }

  void check_pair(Index f, Index g) const {
    const auto& F = m_faces[f];
    const auto& G = m_faces[g];
    for (Index a : F)
      for (Index b : G)
        if (a == b)
          return;
    // side[i][k]: where vertex k of `B` lies relative to edge (i, i+1) of `A` (counter-
    // clockwise, so the interior of A is on the left).
    auto sides = [&](const std::array<Index, 3>& A, const std::array<Index, 3>& B) {
      std::array<std::array<CGAL::Orientation, 3>, 3> side;
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          side[i][k] = orientation(A[i], A[(i + 1) % 3], B[k]);
      return side;
    };
    // Interiors are disjoint iff some edge line of either triangle leaves the other one in
    // its closed outer half-plane (separating axes of two convex polygons).
    auto separated = [](const std::array<std::array<CGAL::Orientation, 3>, 3>& side) {
      for (std::size_t i = 0; i < 3; ++i)
        if (side[i][0] != CGAL::LEFT_TURN && side[i][1] != CGAL::LEFT_TURN &&
            side[i][2] != CGAL::LEFT_TURN)
          return true;
      return false;
    };
    const auto fg = sides(F, G), gf = sides(G, F);
    if (!separated(fg) && !separated(gf))
      throw Invalid_input("domain: triangles " + face_name(f) + " and " + face_name(g) +
                          " overlap (they share no vertex: the triangulation covers part of the "
                          "plane twice)");
    auto ordered = m_traits.collinear_are_strictly_ordered_along_line_2_object();
    auto t_junction = [&](const std::array<Index, 3>& A, const std::array<Index, 3>& B,
                          const std::array<std::array<CGAL::Orientation, 3>, 3>& side, Index a) {
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          if (side[i][k] == CGAL::COLLINEAR &&
              ordered(m_points[A[i]], m_points[B[k]], m_points[A[(i + 1) % 3]]))
            throw Invalid_input("domain: " + vertex_name(B[k]) + " lies inside edge (" +
                                std::to_string(A[i]) + ", " + std::to_string(A[(i + 1) % 3]) +
                                ") of triangle " + face_name(a) +
                                " without ending it (a T-junction: the triangles do not meet "
                                "edge to edge)");
    };
    t_junction(F, G, fg, f);
    t_junction(G, F, gf, g);
  }

  std::string face_name(Index f) const {
    const auto& t = m_faces[f];
    return std::to_string(f) + " (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
           std::to_string(t[2]) + ")";
  }

  std::vector<Point_2> m_points;
  std::vector<internal::Point_enclosure> m_enclosures; // (empty: the number type needs none)
  std::vector<std::array<Index, 3>> m_faces;
  Geom_traits m_traits;
  std::vector<std::array<Index, 2>> m_edges;
  std::vector<std::array<Index, 2>> m_edge_faces;
  std::vector<std::array<Index, 3>> m_face_edges;
  std::size_t m_boundary_edges = 0;
  std::size_t m_boundary_vertices = 0;
  std::size_t m_components = 0;
  std::size_t m_boundary_loops = 0;
  std::vector<char> m_vertex_boundary;
  std::vector<std::size_t> m_face_offsets, m_neighbour_offsets;
  std::vector<Index> m_star_faces, m_star_neighbours, m_star_edges;
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief returns `domain` with its points converted to the kernel `K2` (exact when `K2` is
  exact: the double coordinates are represented exactly).
  \tparam K2 the target kernel
  \tparam K1 the source kernel
  \param domain the domain to convert
  \returns `domain` with its points converted to the kernel `K2` (exact when `K2` is exact: the
  double coordinates are represented exactly)
*/
template <class K2, class K1>
Planar_domain<K2> convert_domain(const Planar_domain<K1>& domain) {
  const CGAL::Cartesian_converter<K1, K2> convert;
  std::vector<typename K2::Point_2> points;
  points.reserve(domain.number_of_vertices());
  for (const auto& p : domain.points())
    points.push_back(convert(p));
  return Planar_domain<K2>(std::move(points), domain.faces());
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DOMAIN_PLANAR_DOMAIN_H

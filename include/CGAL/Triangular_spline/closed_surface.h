// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_CLOSED_SURFACE_H
#define CGAL_TRIANGULAR_SPLINE_CLOSED_SURFACE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/closed_triangle_mesh.h>
#include <CGAL/Triangular_spline/differential_geometry.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/closed_surface_geometry.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief a point of a surface made of one piece per face of a closed mesh, with its unit
  normal and Gaussian curvature (`double`).
*/
struct Surface_sample {
  std::array<double, 3> point{{0, 0, 0}};  ///< the point
  std::array<double, 3> normal{{0, 0, 0}}; ///< the unit normal, zero where singular
  double gaussian = 0;                     ///< Gaussian curvature (NaN where singular)
  bool regular = true;                     ///< the normal exists
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief samples any surface with a parametric Bézier patch per face over the unit triangle
  (corner \f$i\f$ at the \f$i\f$-th vertex of `vertices_around_face(halfedge(f))`), such as
  `Pseudo_AG1_surface` or the PN triangles: called with a face and barycentric weights of
  those three vertices.
  \tparam Surface a class with `patch(f)` returning a `Bezier_triangle` with 3D vector values
*/
template <class Surface>
class Patch_sampler {
public:
  /// the sampler of `surface` (kept by reference)
  /// \param surface the surface
  explicit Patch_sampler(const Surface& surface) : m_surface(surface) {}
  /// \param f a face
  /// \param w barycentric weights of the face's corners
  /// \returns the sample of face `f` at `w`
  template <class Face>
  Surface_sample operator()(Face f, const std::array<double, 3>& w) const {
    // two cached patches: the measures alternate between the two faces of an edge
    std::size_t slot = m_face[0] == std::size_t(f) ? 0 : m_face[1] == std::size_t(f) ? 1 : 2;
    if (slot == 2) {
      slot = m_next;
      m_next = 1 - m_next;
      m_patch[slot] = convert_patch<CGAL::Simple_cartesian<double>>(m_surface.patch(f));
      m_face[slot] = std::size_t(f);
    }
    const Double_patch& patch = *m_patch[slot];
    const typename CGAL::Simple_cartesian<double>::Point_2 a(w[1], w[2]);
    Surface_sample s;
    const auto value = patch.evaluate(a);
    s.point = {{value.x(), value.y(), value.z()}};
    const Surface_curvature c = surface_curvature(patch, a);
    s.normal = c.normal;
    s.gaussian = c.gaussian;
    s.regular = c.regular;
    return s;
  }

private:
  using Double_patch =
      Bezier_triangle<CGAL::Simple_cartesian<double>, CGAL::Simple_cartesian<double>::Vector_3>;
  const Surface& m_surface;
  mutable std::array<std::size_t, 2> m_face{{std::size_t(-1), std::size_t(-1)}};
  mutable std::array<std::optional<Double_patch>, 2> m_patch;
  mutable std::size_t m_next = 0;
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief a watertight triangulation of a closed piecewise surface: corner and edge points are
  computed once and shared by the faces, so the mesh is closed whenever the surface is
  \f$C^0\f$.
*/
struct Closed_tessellation {
  /// the mesh (`Epick` points)
  CGAL::Surface_mesh<CGAL::Epick::Point_3> mesh;
  /// per mesh vertex: the normal of the face that produced it (`split_normals`: its own face)
  std::vector<std::array<double, 3>> normals;
  /// per mesh vertex: the Gaussian curvature there
  std::vector<double> gaussian;
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief tessellates each face of a closed piecewise surface with \f$4^{\text{levels}}\f$
  triangles (\f$n = 2^{\text{levels}}\f$ segments per edge), sharing corner and edge points.
  \tparam Mesh a `CGAL::Surface_mesh`
  \tparam Sampler callable as `Surface_sample(face, std::array<double, 3>)`
  \param mesh the closed triangle mesh the surface is built on
  \param sampler the surface
  \param levels the subdivision level, 0 to 8
  \param split_normals give every face its own copies of its corner and edge points, each
  with that face's normal: the mesh is then not closed, but shading shows where the tangent
  planes of neighbouring faces disagree (AG1.md §6, pictures)
  \throws Invalid_input if `levels` is outside [0, 8]
  \returns the tessellation
*/
template <class Mesh, class Sampler>
Closed_tessellation tessellate_closed_surface(const Mesh& mesh, const Sampler& sampler, int levels,
                                              bool split_normals = false) {
  if (levels < 0 || levels > 8)
    throw Invalid_input("tessellate: the level must be in [0, 8], got " + std::to_string(levels));
  using Out = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
  const int n = 1 << levels;
  Closed_tessellation t;
  std::vector<typename Out::Vertex_index> corner(mesh.number_of_vertices(), Out::null_vertex());
  // edge points keyed by (edge, steps from the source of its canonical halfedge)
  std::vector<std::vector<typename Out::Vertex_index>> edge_points(mesh.number_of_edges());
  auto add = [&](const Surface_sample& s) {
    t.normals.push_back(s.normal);
    t.gaussian.push_back(s.gaussian);
    return t.mesh.add_vertex(CGAL::Epick::Point_3(s.point[0], s.point[1], s.point[2]));
  };
  for (auto f : mesh.faces()) {
    const auto h0 = mesh.halfedge(f);
    // corner a of the face is vertices_around_face order: target(h0), target(next), source(h0)
    const std::array<typename Mesh::Halfedge_index, 3> side{
        {mesh.next(h0), mesh.next(mesh.next(h0)), h0}}; // side[a] from corner a to a+1
    std::vector<typename Out::Vertex_index> grid(std::size_t((n + 1) * (n + 2) / 2));
    auto at = [n](int i, int j) { // i steps towards corner 1, j towards corner 2
      return std::size_t(j * (n + 1) - j * (j - 1) / 2 + i);
    };
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const int k = n - i - j; // weight of corner 0
        const std::array<int, 3> c{{k, i, j}};
        const std::array<double, 3> w{{double(k) / n, double(i) / n, double(j) / n}};
        int zeros = 0, only = -1;
        for (int a = 0; a < 3; ++a)
          if (c[a] == 0)
            ++zeros;
          else
            only = a;
        typename Out::Vertex_index v;
        if (split_normals) {
          v = add(sampler(f, w));
        } else if (zeros == 2) {
          const auto mv = mesh.source(side[std::size_t(only)]);
          if (corner[mv] == Out::null_vertex())
            corner[mv] = add(sampler(f, w));
          v = corner[mv];
        } else if (zeros == 1) {
          int a = 0; // the side from corner a to a+1 carries the point
          for (int b = 0; b < 3; ++b)
            if (c[b] > 0 && c[(b + 1) % 3] > 0)
              a = b;
          const auto h = side[std::size_t(a)];
          const auto e = mesh.edge(h);
          // steps from the source of the canonical halfedge
          const int from_a = c[(a + 1) % 3];
          const int along = canonical_halfedge(e, mesh) == h ? from_a : n - from_a;
          auto& points = edge_points[e];
          if (points.empty())
            points.assign(std::size_t(n + 1), Out::null_vertex());
          if (points[std::size_t(along)] == Out::null_vertex())
            points[std::size_t(along)] = add(sampler(f, w));
          v = points[std::size_t(along)];
        } else {
          v = add(sampler(f, w));
        }
        grid[at(i, j)] = v;
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        t.mesh.add_face(grid[at(i, j)], grid[at(i + 1, j)], grid[at(i, j + 1)]);
        if (i + j + 1 < n)
          t.mesh.add_face(grid[at(i + 1, j)], grid[at(i + 1, j + 1)], grid[at(i, j + 1)]);
      }
  }
  return t;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief moves the mesh out of a tessellation with its normals and Gaussian curvatures as the
  vertex properties `"v:normal"` and `"v:gaussian_curvature"`, the ones `write_mesh()` writes
  to PLY and `tspline render` reads.
  \param t the tessellation (its mesh is moved out)
  \param finite_curvature write 0 instead of NaN where the surface is singular (for files)
  \returns the mesh with the two properties; a singular point's normal is zero
*/
inline CGAL::Surface_mesh<CGAL::Epick::Point_3> tessellation_mesh(Closed_tessellation&& t,
                                                                  bool finite_curvature = false) {
  using Mesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
  Mesh mesh = std::move(t.mesh);
  auto normal = mesh.add_property_map<Mesh::Vertex_index, CGAL::Epick::Vector_3>("v:normal",
                                                                                 CGAL::NULL_VECTOR)
                    .first;
  auto gaussian =
      mesh.add_property_map<Mesh::Vertex_index, double>("v:gaussian_curvature", 0.).first;
  for (auto v : mesh.vertices()) {
    const auto& n = t.normals[std::size_t(v)];
    normal[v] = CGAL::Epick::Vector_3(n[0], n[1], n[2]);
    const double k = t.gaussian[std::size_t(v)];
    gaussian[v] = finite_curvature && !std::isfinite(k) ? 0.0 : k;
  }
  return mesh;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief how far a piecewise surface over a closed mesh is from tangent-plane continuity, and
  how far from its input (AG1.md §6, M1, M2, M5).
*/
struct Closed_surface_measures {
  std::size_t edges = 0;            ///< edges measured
  std::size_t samples_per_edge = 0; ///< interior samples per edge
  /// oriented normal jump across edges (degrees): the largest
  double max_jump_deg = 0;
  double mean_edge_max_jump_deg = 0; ///< the mean over edges of each edge's largest jump
  double mean_jump_deg = 0;          ///< the mean over all samples
  double rms_jump_deg = 0;           ///< the root mean square over all samples
  double p50_jump_deg = 0;           ///< the median over all samples
  double p90_jump_deg = 0;           ///< the 90th percentile over all samples
  double p95_jump_deg = 0;           ///< the 95th percentile over all samples
  double p99_jump_deg = 0;           ///< the 99th percentile over all samples
  /// samples per jump range: `jump_histogram[i]` counts the jumps in
  /// [`jump_histogram_edges()[i]`, `jump_histogram_edges()[i + 1]`) (the last range closed)
  std::vector<std::size_t> jump_histogram;
  double max_unoriented_jump_deg = 0; ///< \f$\max \min(\theta, 180° - \theta)\f$
  /// the largest angle between the corner normals of two faces at a common vertex: 0 for a
  /// surface that is \f$G^1\f$ at its vertices
  double vertex_max_jump_deg = 0;
  std::vector<double> edge_max_jump_deg;  ///< per edge index
  std::vector<double> edge_mean_jump_deg; ///< per edge index
  double mean_input_bend_deg = 0;         ///< the input's mean bend \f$\pi - \theta_e\f$ (unsigned)
  double volume = 0;                      ///< volume of the tessellation
  double input_volume = 0;                ///< volume of the input mesh
  double volume_ratio = 0;                ///< `volume / input_volume`
  double hausdorff_rel = 0;         ///< max distance surface \f$\leftrightarrow\f$ input / diagonal
  double rms_distance_rel = 0;      ///< RMS distance of the surface samples to the input / diagonal
  double inside_fraction = 0;       ///< fraction of surface samples inside the input
  std::size_t folded_samples = 0;   ///< samples whose normal points against their face's normal
  std::size_t singular_samples = 0; ///< samples without a normal
  bool self_intersecting = false;   ///< the tessellation self-intersects
  double gaussian_min = 0;          ///< smallest Gaussian curvature on the tessellation
  double gaussian_max = 0;          ///< largest
  std::size_t tessellation_faces = 0; ///< triangles of the tessellation measured
};

/*!
  \ingroup PkgTriangularSplineCore
  \returns the edges (degrees) of the ranges of `Closed_surface_measures::jump_histogram`:
  0, 0.1, 0.5, 1, 2, 5, 10, 20, 45, 90, 180 (roughly logarithmic: smooth surfaces put nearly
  all samples below 1°, creases show up to the right)
*/
inline const std::vector<double>& jump_histogram_edges() {
  static const std::vector<double> edges{0, 0.1, 0.5, 1, 2, 5, 10, 20, 45, 90, 180};
  return edges;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief measures a piecewise surface over a closed mesh: normal jumps along every edge at
  `samples_per_edge` interior points (from the exact first derivatives of each piece), normal
  agreement at the vertices, and the shape against the input (volume ratio, distances,
  containment, folds, self-intersections, Gaussian curvature) on a tessellation of
  \f$4^{\text{levels}}\f$ triangles per face.
  \tparam Mesh a `CGAL::Surface_mesh` (outward)
  \tparam Sampler callable as `Surface_sample(face, std::array<double, 3>)`
  \param mesh the input mesh
  \param sampler the surface
  \param samples_per_edge interior samples per edge, at least 1
  \param levels tessellation level of the shape measures
  \param check_self_intersections run `does_self_intersect()` on the tessellation
  \throws Invalid_input if `samples_per_edge` < 1
  \returns the measures
*/
template <class Mesh, class Sampler>
Closed_surface_measures measure_closed_surface(const Mesh& mesh, const Sampler& sampler,
                                               int samples_per_edge = 15, int levels = 3,
                                               bool check_self_intersections = true) {
  if (samples_per_edge < 1)
    throw Invalid_input("measure: need at least one sample per edge");
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Epick = CGAL::Epick;
  Closed_surface_measures m;
  m.samples_per_edge = std::size_t(samples_per_edge);
  m.edges = mesh.number_of_edges();
  m.edge_max_jump_deg.assign(mesh.number_of_edges(), 0);
  m.edge_mean_jump_deg.assign(mesh.number_of_edges(), 0);
  std::vector<double> all;
  double bend = 0;
  auto to_d = [](const auto& p) {
    return std::array<double, 3>{
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto face_normal = [&](typename Mesh::Face_index f) {
    const auto h = mesh.halfedge(f);
    const auto a = to_d(mesh.point(mesh.source(h))), b = to_d(mesh.point(mesh.target(h))),
               c = to_d(mesh.point(mesh.target(mesh.next(h))));
    const std::array<double, 3> u{{b[0] - a[0], b[1] - a[1], b[2] - a[2]}},
        v{{c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
    return std::array<double, 3>{
        {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  };
  for (auto e : mesh.edges()) {
    const auto h = canonical_halfedge(e, mesh), o = mesh.opposite(h);
    double sum = 0;
    for (int k = 1; k <= samples_per_edge; ++k) {
      const double t = double(k) / double(samples_per_edge + 1);
      const Surface_sample a = sampler(mesh.face(h), internal::weights_on_halfedge(mesh, h, t));
      const Surface_sample b = sampler(mesh.face(o), internal::weights_on_halfedge(mesh, o, 1 - t));
      double jump = 180;
      if (a.regular && b.regular)
        jump = internal::closed_angle_deg(a.normal, b.normal);
      else
        ++m.singular_samples;
      m.edge_max_jump_deg[e] = std::max(m.edge_max_jump_deg[e], jump);
      m.max_unoriented_jump_deg = std::max(m.max_unoriented_jump_deg, std::min(jump, 180 - jump));
      sum += jump;
      all.push_back(jump);
    }
    m.edge_mean_jump_deg[e] = sum / samples_per_edge;
    m.max_jump_deg = std::max(m.max_jump_deg, m.edge_max_jump_deg[e]);
    m.mean_edge_max_jump_deg += m.edge_max_jump_deg[e];
    bend += internal::closed_angle_deg(face_normal(mesh.face(h)), face_normal(mesh.face(o)));
  }
  if (m.edges > 0) {
    m.mean_edge_max_jump_deg /= double(m.edges);
    m.mean_input_bend_deg = bend / double(m.edges);
  }
  if (!all.empty()) {
    double s = 0, s2 = 0;
    for (double x : all)
      s += x, s2 += x * x;
    m.mean_jump_deg = s / double(all.size());
    m.rms_jump_deg = std::sqrt(s2 / double(all.size()));
    std::vector<double> sorted = all;
    std::sort(sorted.begin(), sorted.end());
    auto percentile = [&](double q) {
      return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())))];
    };
    m.p50_jump_deg = percentile(0.5);
    m.p90_jump_deg = percentile(0.9);
    m.p95_jump_deg = percentile(0.95);
    m.p99_jump_deg = percentile(0.99);
  }
  {
    const auto& edges = jump_histogram_edges();
    m.jump_histogram.assign(edges.size() - 1, 0);
    for (double x : all) {
      // the first edge above x, clamped so that 180° lands in the last range
      const auto above = std::upper_bound(edges.begin() + 1, edges.end() - 1, x);
      ++m.jump_histogram[std::size_t(above - edges.begin()) - 1];
    }
  }
  // vertices: every face's corner normal against the first face's at the same vertex
  std::vector<std::array<double, 3>> first(mesh.number_of_vertices(), {{0, 0, 0}});
  std::vector<bool> seen(mesh.number_of_vertices(), false);
  for (auto f : mesh.faces()) {
    const auto h0 = mesh.halfedge(f);
    const std::array<typename Mesh::Vertex_index, 3> c{
        {mesh.target(h0), mesh.target(mesh.next(h0)), mesh.source(h0)}};
    for (std::size_t a = 0; a < 3; ++a) {
      std::array<double, 3> w{{0, 0, 0}};
      w[a] = 1;
      const Surface_sample s = sampler(f, w);
      if (!s.regular) {
        m.vertex_max_jump_deg = 180;
        continue;
      }
      if (!seen[c[a]]) {
        seen[c[a]] = true;
        first[c[a]] = s.normal;
      } else {
        m.vertex_max_jump_deg =
            std::max(m.vertex_max_jump_deg, internal::closed_angle_deg(first[c[a]], s.normal));
      }
    }
  }

  // shape, on a watertight tessellation
  const Closed_tessellation t = tessellate_closed_surface(mesh, sampler, levels);
  m.tessellation_faces = t.mesh.number_of_faces();
  CGAL::Surface_mesh<Epick::Point_3> input;
  {
    std::vector<typename CGAL::Surface_mesh<Epick::Point_3>::Vertex_index> map(
        mesh.number_of_vertices());
    for (auto v : mesh.vertices()) {
      const auto p = to_d(mesh.point(v));
      map[v] = input.add_vertex(Epick::Point_3(p[0], p[1], p[2]));
    }
    for (auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      input.add_face(map[mesh.source(h)], map[mesh.target(h)], map[mesh.target(mesh.next(h))]);
    }
  }
  m.volume = PMP::volume(t.mesh);
  m.input_volume = PMP::volume(input);
  m.volume_ratio = m.input_volume != 0 ? m.volume / m.input_volume : 0;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<CGAL::Surface_mesh<Epick::Point_3>>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, Primitive>>;
  Tree input_tree(faces(input).first, faces(input).second, input);
  input_tree.accelerate_distance_queries();
  const auto box = PMP::bbox(input);
  const double diagonal = std::sqrt((box.xmax() - box.xmin()) * (box.xmax() - box.xmin()) +
                                    (box.ymax() - box.ymin()) * (box.ymax() - box.ymin()) +
                                    (box.zmax() - box.zmin()) * (box.zmax() - box.zmin()));
  CGAL::Side_of_triangle_mesh<CGAL::Surface_mesh<Epick::Point_3>, Epick> inside(input_tree);
  double max_d2 = 0, sum_d2 = 0;
  std::size_t inside_count = 0;
  m.gaussian_min = std::numeric_limits<double>::infinity();
  m.gaussian_max = -std::numeric_limits<double>::infinity();
  for (auto v : t.mesh.vertices()) {
    const auto& p = t.mesh.point(v);
    const double d2 = input_tree.squared_distance(p);
    max_d2 = std::max(max_d2, d2);
    sum_d2 += d2;
    if (inside(p) == CGAL::ON_BOUNDED_SIDE)
      ++inside_count;
    const double g = t.gaussian[std::size_t(v)];
    if (std::isfinite(g)) {
      m.gaussian_min = std::min(m.gaussian_min, g);
      m.gaussian_max = std::max(m.gaussian_max, g);
    }
  }
  Tree surface_tree(faces(t.mesh).first, faces(t.mesh).second, t.mesh);
  surface_tree.accelerate_distance_queries();
  for (auto v : input.vertices())
    max_d2 = std::max(max_d2, surface_tree.squared_distance(input.point(v)));
  const double count = double(t.mesh.number_of_vertices());
  m.hausdorff_rel = diagonal > 0 ? std::sqrt(max_d2) / diagonal : 0;
  m.rms_distance_rel = diagonal > 0 && count > 0 ? std::sqrt(sum_d2 / count) / diagonal : 0;
  m.inside_fraction = count > 0 ? double(inside_count) / count : 0;
  // folds: samples at face interiors whose normal points against the face's normal
  for (auto f : mesh.faces()) {
    const auto n = face_normal(f);
    for (const auto& w : {std::array<double, 3>{{1.0 / 3, 1.0 / 3, 1.0 / 3}},
                          std::array<double, 3>{{2.0 / 3, 1.0 / 6, 1.0 / 6}},
                          std::array<double, 3>{{1.0 / 6, 2.0 / 3, 1.0 / 6}},
                          std::array<double, 3>{{1.0 / 6, 1.0 / 6, 2.0 / 3}}}) {
      const Surface_sample s = sampler(f, w);
      if (s.regular && s.normal[0] * n[0] + s.normal[1] * n[1] + s.normal[2] * n[2] < 0)
        ++m.folded_samples;
    }
  }
  if (check_self_intersections)
    m.self_intersecting = PMP::does_self_intersect(t.mesh);
  if (!std::isfinite(m.gaussian_min))
    m.gaussian_min = m.gaussian_max = 0;
  return m;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_CLOSED_SURFACE_H

// Bridge from CGAL::Surface_mesh to the renderer's plain arrays, and the coloured PLY export.
// Header-only and the one place (with control_net.h) where rendering meets CGAL: include it
// only in translation units that already read meshes or splines.

#ifndef TSPLINE_RENDER_SURFACE_MESH_ADAPTER_H
#define TSPLINE_RENDER_SURFACE_MESH_ADAPTER_H

#include "render/render.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <vector>

namespace tspline::render {

// Copies positions, "v:normal" (estimated with CGAL::Polygon_mesh_processing::
// compute_vertex_normals when absent) and "v:gaussian_curvature" (when present, e.g. from
// CGAL::Triangular_spline::tessellate() or a PLY it wrote). Polygons are cut into fans.
template <class Point>
Mesh to_render_mesh(const CGAL::Surface_mesh<Point>& mesh) {
  using Surface_mesh = CGAL::Surface_mesh<Point>;
  using Vertex = typename Surface_mesh::Vertex_index;
  using Vector_3 = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  Mesh result;
  std::vector<std::uint32_t> index(mesh.num_vertices(), 0); // removed vertices are skipped
  result.positions.reserve(mesh.number_of_vertices());
  for (Vertex v : mesh.vertices()) {
    index[v.idx()] = static_cast<std::uint32_t>(result.positions.size());
    const Point& p = mesh.point(v);
    result.positions.push_back(
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  result.triangles.reserve(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    std::vector<std::uint32_t> polygon;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(index[v.idx()]);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      result.triangles.push_back({{polygon[0], polygon[k], polygon[k + 1]}});
  }

  auto copy_normals = [&](const auto& normals) {
    result.normals.reserve(result.positions.size());
    for (Vertex v : mesh.vertices()) {
      const Vector_3& n = normals[v];
      result.normals.push_back(
          {CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())});
    }
  };
  const auto [normals, has_normals] = mesh.template property_map<Vertex, Vector_3>("v:normal");
  if (has_normals) {
    copy_normals(normals);
  } else if (!CGAL::is_empty(mesh)) {
    // Scratch storage indexed like the mesh: the caller's mesh stays untouched.
    std::vector<Vector_3> estimated(mesh.num_vertices(), Vector_3(0, 0, 0));
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, CGAL::make_property_map(estimated));
    copy_normals(estimated);
  }

  const auto [curvature, has_curvature] =
      mesh.template property_map<Vertex, double>("v:gaussian_curvature");
  if (has_curvature)
    for (Vertex v : mesh.vertices())
      result.gaussian_curvature.push_back(curvature[v]);
  return result;
}

// Adds (or overwrites) "v:color" with the curvature colours of "v:gaussian_curvature" scaled
// by `range`, so that a PLY written with CGAL's writer carries red/green/blue next to the
// curvature scalars. Returns false when the mesh has no curvature.
template <class Point>
bool add_curvature_colours(CGAL::Surface_mesh<Point>& mesh, double range) {
  using Vertex = typename CGAL::Surface_mesh<Point>::Vertex_index;
  const auto [curvature, has_curvature] =
      mesh.template property_map<Vertex, double>("v:gaussian_curvature");
  if (!has_curvature)
    return false;
  auto colours = mesh.template add_property_map<Vertex, CGAL::IO::Color>("v:color").first;
  for (Vertex v : mesh.vertices()) {
    const Rgb c = curvature_colour(curvature[v], range);
    colours[v] = CGAL::IO::Color(c.r, c.g, c.b);
  }
  return true;
}

} // namespace tspline::render

#endif // TSPLINE_RENDER_SURFACE_MESH_ADAPTER_H

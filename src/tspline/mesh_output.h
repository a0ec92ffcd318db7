// Tessellate a spline network and write the mesh: shared by the jobs that offer --mesh (c1,
// mann). Header-only because it is templated on the network.

#ifndef TSPLINE_MESH_OUTPUT_H
#define TSPLINE_MESH_OUTPUT_H

#include "cli.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/tessellate.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>

#include <string>

namespace tspline {

// Tessellates with `levels` 4-splits per patch, writes `path` (.ply/.off/.obj), returns the
// report entry {path, levels, vertices, faces}.
template <class Network>
Json write_tessellated_mesh(const Network& network, int levels, const std::string& path) {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  const auto stats = CGAL::Triangular_spline::tessellate(network, levels, mesh);
  CGAL::Triangular_spline::write_mesh(path, mesh);
  Json m = Json::object();
  m["path"] = path;
  m["levels"] = levels;
  m["vertices"] = stats.vertices;
  m["faces"] = stats.faces;
  return m;
}

} // namespace tspline

#endif // TSPLINE_MESH_OUTPUT_H

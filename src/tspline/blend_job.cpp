// Fang's blending pipeline: read or generate a mesh -> vertex/edge/face surfaces -> measured
// continuity and curvature -> tessellation -> outputs. Computed in double (Epick).

#include "blend_job.h"
#include "files.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/blending_continuity.h>
#include <CGAL/Triangular_spline/Blending/blending_sampler.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/Comparators/Nielson_side_vertex.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>

namespace tspline {

namespace {

namespace TS = CGAL::Triangular_spline;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

// Runs `read` with std::cerr silenced: CGAL's readers print their own diagnostics; ours is
// the one-line error.
template <class Read>
bool quietly(Read read) {
  std::ostringstream swallowed;
  std::streambuf* saved = std::cerr.rdbuf(swallowed.rdbuf());
  try {
    const bool ok = read();
    std::cerr.rdbuf(saved);
    return ok;
  } catch (...) {
    std::cerr.rdbuf(saved);
    throw;
  }
}

// Reads a polygon mesh: as a polygon soup first (to diagnose non-manifold input instead of
// repairing it silently), then converted; normals from NOFF and PLY files.
Mesh read_mesh(const std::string& path, bool& normals_in_file) {
  const std::string ext = lowercase_extension(path);
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<Vector_3> normals;
  // The checked reader of every command (counts, indices, finite coordinates).
  TS::read_mesh_soup(path, points, polygons, &normals);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw TS::Invalid_input(path + ": not a manifold, consistently oriented polygon mesh (an "
                                   "edge has more than two faces, a vertex several umbrellas, "
                                   "or neighbouring faces disagree on the orientation)");
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  // The soup's vertex i is the mesh's vertex i (every point of a valid soup is used).
  normals_in_file = false;
  if (ext == "ply") {
    Mesh with_properties;
    std::ifstream in(path, std::ios::binary);
    if (quietly([&] { return CGAL::IO::read_PLY(in, with_properties); }) &&
        with_properties.number_of_vertices() == points.size()) {
      const auto [map, found] =
          with_properties.property_map<Mesh::Vertex_index, Vector_3>("v:normal");
      if (found)
        for (Mesh::Vertex_index v : with_properties.vertices())
          normals.push_back(map[v]);
    }
  }
  if (!normals.empty() && normals.size() == points.size() &&
      mesh.number_of_vertices() == points.size()) {
    auto map =
        mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:normal", Vector_3(0, 0, 0)).first;
    for (Mesh::Vertex_index v : mesh.vertices())
      map[v] = normals[static_cast<std::size_t>(v)];
    normals_in_file = true;
  }
  return mesh;
}

Json numbers(const std::vector<double>& v) {
  Json a = Json::array();
  for (double x : v)
    a.push_back(x);
  return a;
}

std::string join(const std::vector<double>& v) {
  std::ostringstream s;
  s << std::setprecision(2) << std::scientific;
  for (std::size_t k = 0; k < v.size(); ++k)
    s << (k ? "  " : "") << "[" << k << "] " << v[k];
  return s.str();
}

// Jumps across the interior edges of a piecewise surface (closed or not): of the normal
// (degrees) and of the Gaussian curvature, which a G^1 (or C^1) surface does not control.
struct Edge_jumps {
  std::size_t edges = 0;
  double max_normal_deg = 0, mean_normal_deg = 0, max_gaussian = 0, mean_gaussian = 0;
};

template <class Sampler>
Edge_jumps measure_edge_jumps(const Mesh& mesh, const Sampler& sampler, int samples) {
  Edge_jumps j;
  std::size_t count = 0;
  for (Mesh::Edge_index e : mesh.edges()) {
    if (mesh.is_border(e))
      continue;
    ++j.edges;
    const Mesh::Halfedge_index h = mesh.halfedge(e), o = mesh.opposite(h);
    for (int k = 1; k <= samples; ++k) {
      const double t = double(k) / double(samples + 1);
      const TS::Surface_sample a =
          sampler(mesh.face(h), TS::internal::weights_on_halfedge(mesh, h, t));
      const TS::Surface_sample b =
          sampler(mesh.face(o), TS::internal::weights_on_halfedge(mesh, o, 1 - t));
      const double normal =
          a.regular && b.regular ? TS::internal::closed_angle_deg(a.normal, b.normal) : 180;
      const double gaussian = std::abs(a.gaussian - b.gaussian);
      j.max_normal_deg = std::max(j.max_normal_deg, normal);
      j.mean_normal_deg += normal;
      if (std::isfinite(gaussian)) {
        j.max_gaussian = std::max(j.max_gaussian, gaussian);
        j.mean_gaussian += gaussian;
      }
      ++count;
    }
  }
  if (count > 0) {
    j.mean_normal_deg /= double(count);
    j.mean_gaussian /= double(count);
  }
  return j;
}

Json edge_jumps_json(const Edge_jumps& j, int samples) {
  Json r = Json::object();
  r["interior_edges"] = j.edges;
  r["samples_per_edge"] = samples;
  r["max_normal_deg"] = j.max_normal_deg;
  r["mean_normal_deg"] = j.mean_normal_deg;
  r["max_gaussian"] = j.max_gaussian;
  r["mean_gaussian"] = j.mean_gaussian;
  return r;
}

bool is_triangle_mesh(const Mesh& mesh) {
  for (Mesh::Face_index f : mesh.faces())
    if (CGAL::degree(f, mesh) != 3)
      return false;
  return true;
}

// The measures of closed_surface.h (on a tessellation of 4^levels triangles per face).
Json closed_measures_json(const TS::Closed_surface_measures& m, int levels) {
  Json r = Json::object();
  r["levels"] = levels;
  r["max_normal_jump_deg"] = m.max_jump_deg;
  r["mean_normal_jump_deg"] = m.mean_jump_deg;
  r["vertex_max_normal_jump_deg"] = m.vertex_max_jump_deg;
  r["min_gaussian_curvature"] = m.gaussian_min;
  r["max_gaussian_curvature"] = m.gaussian_max;
  r["volume_ratio"] = m.volume_ratio;
  r["hausdorff_rel"] = m.hausdorff_rel;
  r["folded_samples"] = m.folded_samples;
  r["singular_samples"] = m.singular_samples;
  return r;
}

// --resolution N as a level of tessellate_closed_surface(): 2^levels >= N segments per edge.
int levels_for(int resolution) {
  int levels = 0;
  while ((1 << levels) < resolution && levels < 8)
    ++levels;
  return levels;
}

std::string edge_jumps_text(const Edge_jumps& j) {
  std::ostringstream s;
  s << std::setprecision(3) << "  across interior edges: normal jump max " << j.max_normal_deg
    << " deg, mean " << j.mean_normal_deg << " deg; Gaussian curvature jump max " << j.max_gaussian
    << ", mean " << j.mean_gaussian << "\n";
  return s.str();
}

// Nielson's side-vertex interpolant of the same mesh and normals (--scheme nielson).
Json run_nielson(const Blend_job& job, const Mesh& mesh, const std::string& source,
                 std::ostream& out, Json report, Json timings, Stopwatch& clock, Stopwatch& total) {
  std::unique_ptr<TS::Nielson_side_vertex_surface<Point_3>> built;
  try {
    built = std::make_unique<TS::Nielson_side_vertex_surface<Point_3>>(mesh);
  } catch (const TS::Invalid_input& e) {
    throw TS::Invalid_input(source + ": " + e.what());
  }
  const TS::Nielson_side_vertex_surface<Point_3>& surface = *built;
  const Mesh& m = surface.mesh();
  timings["build"] = clock.lap();
  const int levels = levels_for(job.resolution);
  report["input"] = job.shape.empty() ? Json(job.input) : Json();
  report["shape"] = job.shape.empty() ? Json() : Json(job.shape);
  report["scheme"] = "nielson";
  report["vertices"] = m.number_of_vertices();
  report["edges"] = m.number_of_edges();
  report["faces"] = m.number_of_faces();
  report["normals"] = surface.has_estimated_normals() ? "estimated" : "given";
  const Edge_jumps jumps = measure_edge_jumps(m, surface, job.samples);
  report["edge_jumps"] = edge_jumps_json(jumps, job.samples);
  report["max_normal_angle_jump_deg"] = jumps.max_normal_deg;
  timings["measure_continuity"] = clock.lap();
  std::string shape_text;
  if (CGAL::is_closed(m)) {
    const TS::Closed_surface_measures closed =
        TS::measure_closed_surface(m, surface, job.samples, levels, false);
    report["closed_measures"] = closed_measures_json(closed, levels);
    report["min_gaussian_curvature"] = closed.gaussian_min;
    report["max_gaussian_curvature"] = closed.gaussian_max;
    std::ostringstream s;
    s << std::setprecision(3) << "  Gaussian curvature in [" << closed.gaussian_min << ", "
      << closed.gaussian_max << "] (" << (1 << levels)
      << " segments per edge); normal jump at the vertices " << closed.vertex_max_jump_deg
      << " deg; volume ratio " << closed.volume_ratio << "\n";
    shape_text = s.str();
    timings["measure_shape"] = clock.lap();
  }
  if (!job.mesh.empty()) {
    const CGAL::Surface_mesh<Point_3> tm =
        TS::tessellation_mesh(TS::tessellate_closed_surface(m, surface, levels));
    TS::write_mesh(job.mesh, tm);
    Json o = Json::object();
    o["path"] = job.mesh;
    o["levels"] = levels;
    o["vertices"] = tm.number_of_vertices();
    o["faces"] = tm.number_of_faces();
    report["mesh"] = o;
    timings["tessellate_and_write"] = clock.lap();
  }
  timings["total"] = total.lap();
  report["timings"] = timings;
  out << "Nielson's side-vertex interpolant over " << source << "\n"
      << "  mesh: " << m.number_of_vertices() << " vertices, " << m.number_of_edges() << " edges, "
      << m.number_of_faces() << " triangles; normals "
      << (surface.has_estimated_normals() ? "estimated from the faces" : "given") << "\n"
      << "  PN boundary curves, cubic Hermite radial curves, Nielson's functions (Fang Def. 2.3)\n"
      << edge_jumps_text(jumps) << shape_text;
  if (!job.mesh.empty())
    out << "  mesh: " << job.mesh << " (" << report["mesh"]["vertices"] << " vertices, "
        << report["mesh"]["faces"] << " triangles)\n";
  if (!job.report.empty())
    write_json_report(job.report, report);
  return report;
}

const char* variant_description(TS::Blending_variant v) {
  switch (v) {
  case TS::Blending_variant::BASIC:
    return "basic (ch. 5: C^d across edges, normals continuous at vertices)";
  case TS::Blending_variant::VERTEX_CONTINUITY:
    return "vertex (6.1/7.3: C^d at the vertices in their frames)";
  case TS::Blending_variant::OPEN_SET:
    return "open (6.2: C^d on a neighbourhood of each vertex)";
  }
  return "";
}

} // namespace

std::string blend_shape_names() {
  std::string s;
  for (const std::string& name : TS::blending_test_mesh_names())
    s += (s.empty() ? "" : ", ") + name;
  return s;
}

Json run_blend_job(const Blend_job& job, std::ostream& out) {
  Stopwatch clock, total;
  Json timings = Json::object();
  Json report = Json::object();

  Mesh mesh;
  bool normals_in_file = false;
  std::string source;
  if (!job.shape.empty()) {
    const std::vector<std::string> names = TS::blending_test_mesh_names();
    if (std::find(names.begin(), names.end(), job.shape) == names.end())
      throw Usage_error("unknown --shape '" + job.shape + "' (one of " + blend_shape_names() + ")");
    mesh = TS::blending_test_mesh<Point_3>(job.shape, job.seed);
    normals_in_file = mesh.property_map<Mesh::Vertex_index, Vector_3>("v:normal").second;
    source = "test mesh '" + job.shape + "'";
  } else {
    mesh = read_mesh(job.input, normals_in_file);
    source = job.input;
  }
  timings["read"] = clock.lap();
  if (job.scheme == "nielson")
    return run_nielson(job, mesh, source, out, report, timings, clock, total);

  TS::Mesh_blending_options options;
  options.order = job.order;
  options.variant = job.variant == "basic"    ? TS::Blending_variant::BASIC
                    : job.variant == "vertex" ? TS::Blending_variant::VERTEX_CONTINUITY
                                              : TS::Blending_variant::OPEN_SET;
  options.vertex_surface = job.vertex_surface == "lsq" ? TS::Vertex_surface_method::LEAST_SQUARES
                           : job.vertex_surface == "normals"
                               ? TS::Vertex_surface_method::LEAST_SQUARES_NORMALS
                               : TS::Vertex_surface_method::LEAST;
  options.least_squares_degree = job.least_squares_degree;
  options.normals_degree = job.normals_degree;
  std::unique_ptr<TS::Mesh_blending_surface<Point_3>> built;
  try {
    built = std::make_unique<TS::Mesh_blending_surface<Point_3>>(mesh, options);
  } catch (const TS::Invalid_input& e) {
    throw TS::Invalid_input(source + ": " + e.what());
  }
  const TS::Mesh_blending_surface<Point_3>& surface = *built;
  timings["build"] = clock.lap();

  const TS::Blending_continuity continuity = TS::measure_blending_continuity(surface, job.samples);
  timings["measure_continuity"] = clock.lap();
  const TS::Blending_curvature curvature = TS::measure_blending_curvature(surface, job.resolution);
  timings["measure_curvature"] = clock.lap();
  // the comparison with --scheme nielson: the same measures (triangle meshes)
  // (`mesh` is read or generated without removed elements: its indices are the surface's)
  Edge_jumps jumps;
  const bool triangles = is_triangle_mesh(mesh);
  if (triangles) {
    const TS::Mesh_blending_sampler<Point_3> sampler(surface);
    jumps = measure_edge_jumps(mesh, sampler, job.samples);
    report["edge_jumps"] = edge_jumps_json(jumps, job.samples);
    if (CGAL::is_closed(mesh)) {
      const int levels = levels_for(job.resolution);
      report["closed_measures"] = closed_measures_json(
          TS::measure_closed_surface(mesh, sampler, job.samples, levels, false), levels);
    }
  }
  timings["measure_jumps"] = clock.lap();

  std::map<std::size_t, std::size_t> sides;
  for (std::size_t f = 0; f < surface.number_of_faces(); ++f)
    ++sides[surface.face_size(f)];
  std::size_t border_edges = 0;
  for (std::size_t e = 0; e < surface.number_of_edges(); ++e)
    border_edges += surface.edge_sides(e).size() == 1 ? 1 : 0;

  report["input"] = job.shape.empty() ? Json(job.input) : Json();
  report["shape"] = job.shape.empty() ? Json() : Json(job.shape);
  report["scheme"] = "fang";
  report["order"] = job.order;
  report["variant"] = job.variant;
  report["vertex_surface"] = job.vertex_surface == "lsq"       ? "least_squares"
                             : job.vertex_surface == "normals" ? "least_squares_normals"
                                                               : "least";
  if (job.vertex_surface == "lsq")
    report["least_squares_degree"] = job.least_squares_degree;
  if (job.vertex_surface == "normals")
    report["normals_degree"] = job.normals_degree;
  report["vertices"] = surface.number_of_vertices();
  report["edges"] = surface.number_of_edges();
  report["border_edges"] = border_edges;
  report["faces"] = surface.number_of_faces();
  Json by_size = Json::object();
  for (const auto& [n, count] : sides)
    by_size[std::to_string(n)] = count;
  report["faces_by_sides"] = by_size;
  report["normals"] = surface.has_estimated_normals() ? "estimated" : "given";
  report["folded_maps"] = surface.number_of_folded_maps();
  report["measured_order"] = continuity.measured_order;
  report["samples_per_edge"] = job.samples;
  report["max_edge_jump"] = numbers(continuity.max_edge_jump);
  report["max_vertex_jump"] = numbers(continuity.max_vertex_jump);
  report["max_edge_inheritance_error"] = numbers(continuity.max_edge_inheritance_error);
  report["max_normal_angle_jump_deg"] = continuity.max_normal_angle_jump_deg;
  Json interpolation = Json::object();
  interpolation["position"] = continuity.max_position_error;
  interpolation["normal_angle_deg"] = continuity.max_normal_error_deg;
  report["max_interpolation_error"] = interpolation;
  report["min_gaussian_curvature"] = curvature.min_gaussian;
  report["max_gaussian_curvature"] = curvature.max_gaussian;
  report["curvature_resolution"] = job.resolution;
  report["singular_points"] = curvature.singular;
  Json gap = Json::object();
  gap["delta"] = numbers({1e-2, 1e-3});
  gap["absolute"] = numbers({curvature.vertex_gap[0], curvature.vertex_gap[1]});
  gap["relative"] = numbers({curvature.relative_vertex_gap[0], curvature.relative_vertex_gap[1]});
  report["vertex_curvature_gap"] = gap;
  report["mesh_size"] = continuity.size;

  TS::Blending_tessellation_statistics tessellation;
  if (!job.mesh.empty()) {
    Mesh tessellated;
    tessellation = surface.tessellate(tessellated, job.resolution);
    timings["tessellate"] = clock.lap();
    TS::write_mesh(job.mesh, tessellated);
    timings["write_mesh"] = clock.lap();
    Json m = Json::object();
    m["path"] = job.mesh;
    m["resolution"] = job.resolution;
    m["vertices"] = tessellation.vertices;
    m["faces"] = tessellation.faces;
    report["mesh"] = m;
  }
  timings["total"] = total.lap();
  report["timings"] = timings;

  std::string faces_text;
  for (const auto& [n, count] : sides)
    faces_text += (faces_text.empty() ? "" : ", ") + std::to_string(count) +
                  (n == 3   ? " triangles"
                   : n == 4 ? " quads"
                            : " " + std::to_string(n) + "-gons");
  out << "Fang's blending over " << source << "\n"
      << "  mesh: " << surface.number_of_vertices() << " vertices, " << surface.number_of_edges()
      << " edges (" << border_edges << " on the border), " << surface.number_of_faces()
      << " faces (" << faces_text << "); normals "
      << (surface.has_estimated_normals() ? "estimated from the faces" : "given") << "\n"
      << "  order d = " << job.order << ", variant " << variant_description(options.variant)
      << "\n  vertex surfaces: "
      << (job.vertex_surface == "lsq"
              ? "least squares, degree " + std::to_string(job.least_squares_degree)
          : job.vertex_surface == "normals" ? "through the neighbours, normals fitted, degree >= " +
                                                  std::to_string(job.normals_degree)
                                            : std::string("de Boor-Ron least interpolant"))
      << "\n";
  if (surface.number_of_folded_maps() > 0)
    out << "  warning: " << surface.number_of_folded_maps()
        << " edge-to-face maps reverse orientation (the mesh is too sharp for its normals)\n";
  out << std::setprecision(3) << "  max derivative jump across edges (edge frames), by order:  "
      << join(continuity.max_edge_jump) << "\n"
      << "  max derivative jump at vertices (vertex frames), by order: "
      << join(continuity.max_vertex_jump) << "\n"
      << "  normal angle jump across edges: " << continuity.max_normal_angle_jump_deg
      << " deg; interpolation error at the vertices: position " << continuity.max_position_error
      << ", normal " << continuity.max_normal_error_deg << " deg\n"
      << "  Gaussian curvature in [" << curvature.min_gaussian << ", " << curvature.max_gaussian
      << "] (grid of " << job.resolution << " segments per edge); gap towards the vertices "
      << curvature.relative_vertex_gap[1] << " (relative, at 1e-3)\n";
  if (triangles)
    out << edge_jumps_text(jumps);
  if (!job.mesh.empty())
    out << "  mesh: " << job.mesh << " (" << tessellation.vertices << " vertices, "
        << tessellation.faces << " triangles)\n";
  if (!job.report.empty())
    write_json_report(job.report, report);
  return report;
}

} // namespace tspline

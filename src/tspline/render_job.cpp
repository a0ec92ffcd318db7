// tspline render: spline, closed surface or mesh -> scene (render/scene.h: Surface_mesh with
// normals and curvatures, net or curves) -> tspline_render -> PNG, coloured PLY, JSON report.
// Also the pictures at the end of `tspline demo`.

#include "render_job.h"
#include "files.h"

#include "render/control_net.h"
#include "render/scene.h"
#include "render/surface_mesh_adapter.h"

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <chrono>
#include <cstdio>

namespace tspline {
namespace {

namespace TS = CGAL::Triangular_spline;
using K = render::Scene_kernel;
using Surface_mesh = render::Scene_mesh;
using render::Scene;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Json vector_json(const render::Vector& v) {
  Json a = Json::array();
  for (double x : v)
    a.push_back(x);
  return a;
}

} // namespace

Json run_render_job(const Render_job& job, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const render::Mode mode = job.options.mode;
  const std::string ext = lowercase_extension(job.input);
  render::Progress progress(!job.quiet);
  const bool mesh_input = ext == "ply" || ext == "off" || ext == "obj" || ext == "stl";
  if (mode == render::Mode::Jump && ext != "surface")
    throw Usage_error("--mode jump needs a .surface input (the normal jumps across the edges "
                      "of a closed surface, e.g. from 'tspline pseudo-ag1 --save')");
  if (mesh_input && job.levels)
    throw Usage_error("--levels applies to .spline and .surface inputs only");
  Scene scene =
      render::load_scene(job.input, mode, job.levels, progress, job.split_normals, job.umbrellas);
  if (mesh_input && !job.ply.empty() &&
      !scene.mesh.property_map<Surface_mesh::Vertex_index, double>("v:gaussian_curvature").second)
    throw TS::Invalid_input("'" + job.input +
                            "' is a plain mesh: --ply needs a .spline input (Gaussian curvature "
                            "from the exact patch derivatives) or a PLY with per-vertex "
                            "gaussian_curvature written by tspline");

  progress.begin("rendering " + std::to_string(scene.mesh.number_of_faces()) + " triangles",
                 scene.mesh.number_of_faces());
  render::Report rendered;
  render::write_png(job.output, render::render_scene(scene, job.options, &rendered));
  progress.end();

  if (!job.ply.empty()) {
    if (!render::add_curvature_colours(scene.mesh, rendered.curvature_range))
      throw TS::Invalid_input("--ply needs curvatures, which '" + job.input + "' does not have");
    TS::write_mesh(job.ply, scene.mesh);
  }
  const double total = seconds_since(start);

  Json report = Json::object();
  report["input"] = job.input;
  report["input_kind"] = scene.kind;
  report["output"] = job.output;
  report["mode"] = render::mode_name(mode);
  Json size = Json::array();
  size.push_back(job.options.width);
  size.push_back(job.options.height);
  report["size"] = size;
  Json view = Json::array();
  view.push_back(job.options.azimuth);
  view.push_back(job.options.elevation);
  report["view"] = view;
  report["projection"] = job.options.perspective ? "perspective" : "orthographic";
  if (job.options.light)
    report["light"] = vector_json(*job.options.light);
  if (mode == render::Mode::Isophotes)
    report["bands"] = job.options.bands;
  report["supersampling"] = job.options.supersampling;
  if (scene.levels >= 0) {
    report["patches"] = scene.patches;
    report["degree"] = scene.degree;
    report["levels"] = scene.levels;
  }
  report["vertices"] = scene.mesh.number_of_vertices();
  report["triangles"] = rendered.triangles;
  report["covered_pixels"] = rendered.covered_pixels;
  if (mode == render::Mode::Net) {
    report["net_points"] = scene.net.points.size();
    report["net_segments"] = scene.net.segments.size();
  }
  if (mode == render::Mode::Jump) {
    Json jump = Json::object();
    jump["max"] = scene.jump_max;
    jump["mean_edge_max"] = scene.jump_mean_edge_max;
    jump["samples_per_edge"] = scene.jump_samples;
    jump["edges"] = scene.net.curves.size();
    jump["colour_range"] = rendered.jump_range;
    jump["colour_range_from"] = job.options.jump_range ? "--range" : "largest jump (at least 1)";
    report["normal_jump_deg"] = jump;
  }
  if (rendered.has_curvature) {
    Json curvature = Json::object();
    curvature["min"] = rendered.curvature_min;
    curvature["max"] = rendered.curvature_max;
    curvature["colour_range"] = rendered.curvature_range;
    curvature["colour_range_from"] =
        rendered.curvature_range_from_user ? "--range" : "98th percentile of |K|";
    report["gaussian_curvature"] = curvature;
  } else {
    report["gaussian_curvature"] = Json();
  }
  if (!job.ply.empty())
    report["ply"] = job.ply;
  Json seconds = Json::object();
  seconds["tessellate"] = scene.tessellation_seconds;
  seconds["render"] = rendered.seconds;
  seconds["total"] = total;
  report["seconds"] = seconds;
  if (!job.report.empty())
    write_json_report(job.report, report);

  if (!job.quiet) {
    char line[512];
    std::snprintf(line, sizeof line, "wrote %s (%dx%d, %s, %zu triangles", job.output.c_str(),
                  job.options.width, job.options.height, render::mode_name(mode).c_str(),
                  rendered.triangles);
    out << line;
    if (mode == render::Mode::Curvature) {
      std::snprintf(line, sizeof line, "; K in [%.3g, %.3g], colours saturate at |K| = %.3g",
                    rendered.curvature_min, rendered.curvature_max, rendered.curvature_range);
      out << line;
    }
    if (mode == render::Mode::Net) {
      out << "; " << scene.net.points.size() << " control points";
    }
    if (mode == render::Mode::Jump) {
      std::snprintf(line, sizeof line,
                    "; %zu edges, normal jumps up to %.3g deg, colours saturate at %.3g deg",
                    scene.net.curves.size(), scene.jump_max, rendered.jump_range);
      out << line;
    }
    std::snprintf(line, sizeof line, ") in %.2f s\n", total);
    out << line;
    if (!job.ply.empty())
      out << "wrote " << job.ply << " (per-vertex curvature colours and scalars)\n";
  }
  return report;
}

// ---------------------------------------------------------------------------------------
// tspline demo pictures

namespace {

// A small C^1 quintic spline to show prescription and propagation: the 3x3 grid on [0,2]^2
// cut into 8 triangles around the centre ("union jack"). Each boundary mid-vertex then has
// one interior edge whose apexes are collinear with it: a degenerate frame (Xu §4.4.4).
// The free control points sample a smooth bump at their domain points; propagation sets
// the rest.
TS::C1_quintic_spline<K> small_example() {
  std::vector<K::Point_2> points;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      points.emplace_back(i, j);
  auto id = [](int i, int j) { return static_cast<std::uint32_t>(3 * j + i); };
  const std::uint32_t centre = id(1, 1);
  const std::uint32_t ring[8] = {id(0, 0), id(1, 0), id(2, 0), id(2, 1),
                                 id(2, 2), id(1, 2), id(0, 2), id(0, 1)};
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int k = 0; k < 8; ++k)
    triangles.push_back({{ring[k], ring[(k + 1) % 8], centre}});
  TS::C1_quintic_spline<K> spline(TS::Planar_domain<K>(std::move(points), std::move(triangles)));
  for (auto s : spline.free_slots()) {
    const K::Point_2 p = spline.domain_point(s);
    const double dx = p.x() - 1.1, dy = p.y() - 0.9;
    spline.set_free_value(s, 0.9 / (1 + 1.5 * (dx * dx + dy * dy)) + 0.15 * p.x());
  }
  spline.propagate();
  return spline;
}

} // namespace

void render_demo_pictures(const std::filesystem::path& dir, const std::string& spline_path,
                          std::ostream& out) {
  Render_job job;
  job.input = spline_path;
  job.quiet = true;
  job.options.width = 640;
  job.options.height = 480;
  // From the front left and fairly high: the L-shape, its hole and the rising arm all show.
  job.options.azimuth = -20;
  job.options.elevation = 60;
  out << "\npictures (tspline render):\n";
  for (const auto& [mode, name] :
       {std::pair<render::Mode, const char*>{render::Mode::Shaded, "demo_shaded.png"},
        {render::Mode::Curvature, "demo_curvature.png"},
        {render::Mode::Isophotes, "demo_isophotes.png"}}) {
    job.options.mode = mode;
    job.output = (dir / name).string();
    run_render_job(job, out);
    out << "  " << job.output << ": " << render::mode_name(mode) << "\n";
  }

  const TS::C1_quintic_spline<K> spline = small_example();
  auto status = [&spline](std::size_t f, const TS::Multi_index& index) {
    return spline.is_free(spline.slot(static_cast<std::uint32_t>(f), index))
               ? render::Point_status::Prescribed
               : render::Point_status::Propagated;
  };
  const render::Net net = render::control_net(spline, status);
  Scene scene;
  TS::tessellate(spline, 4, scene.mesh);
  scene.net = net;
  render::Options options = job.options;
  options.mode = render::Mode::Net;
  options.azimuth = -25;
  options.elevation = 38;
  const std::string path = (dir / "demo_net.png").string();
  render::write_png(path, render::render_scene(scene, options));
  std::size_t prescribed = 0;
  for (const auto& p : net.points)
    prescribed += p.status == render::Point_status::Prescribed ? 1 : 0;
  out << "  " << path << ": control net of a " << spline.domain().number_of_faces()
      << "-triangle C^1 quintic spline with " << spline.degenerate_frames().size()
      << " degenerate frames, " << prescribed << " prescribed and "
      << net.points.size() - prescribed << " propagated control points\n";
}

} // namespace tspline

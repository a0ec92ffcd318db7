// tspline render: spline, closed surface or mesh -> Surface_mesh with normals and curvatures ->
// tspline_render
// -> PNG, coloured PLY, JSON report. Also the pictures at the end of `tspline demo`.

#include "render_job.h"
#include "files.h"

#include "render/control_net.h"
#include "render/surface_mesh_adapter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace tspline {
namespace {

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<K::Point_3>;

// Default tessellation budget: smooth at any picture size up to ~1920x1080, well under a second.
constexpr std::size_t default_triangle_budget = std::size_t(1) << 18;
// Tessellating or drawing 2^21 triangles takes about a second (0.3 s and 0.25 s per 10^6
// measured at 1920x1080): larger stages are announced on a terminal.
constexpr std::size_t progress_threshold = std::size_t(1) << 21;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Progress lines on stderr, only for long stages and only when stderr is a terminal.
class Progress {
public:
  explicit Progress(bool enabled) : m_enabled(enabled && isatty(STDERR_FILENO) == 1) {}
  void begin(const std::string& what, std::size_t triangles) {
    m_active = m_enabled && triangles >= progress_threshold;
    m_start = std::chrono::steady_clock::now();
    if (m_active)
      std::cerr << "tspline render: " << what << " ..." << std::flush;
  }
  void end() {
    if (m_active)
      std::cerr << " " << seconds_since(m_start) << " s\n";
    m_active = false;
  }

private:
  bool m_enabled, m_active = false;
  std::chrono::steady_clock::time_point m_start;
};

int automatic_levels(std::size_t faces) {
  int levels = 0;
  while (levels < 6 && faces * (std::size_t(1) << (2 * (levels + 1))) <= default_triangle_budget)
    ++levels;
  return levels;
}

// What the renderer needs from an input, and what the report says about it.
struct Scene {
  Surface_mesh mesh;
  render::Net net;
  std::string kind;
  int levels = -1; // tessellation levels, -1 for a mesh input
  std::size_t patches = 0;
  int degree = 0;
  double tessellation_seconds = 0;
  // Mode::Jump on a .surface: the per-edge largest normal jumps (degrees) of the curves
  double jump_max = 0, jump_mean_edge_max = 0;
  std::size_t jump_samples = 0;
};

template <class Value>
void tessellate_spline_file(std::istream& in, const std::string& path, const Render_job& job,
                            Progress& progress, Scene& scene) {
  const TS::Spline_file<K, Value> file = TS::read_spline_file<K, Value>(in, path);
  const std::size_t faces = file.domain().number_of_faces();
  scene.patches = faces;
  scene.degree = file.degree();
  scene.levels = job.levels ? *job.levels : automatic_levels(faces);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t triangles = faces << (2 * scene.levels);
  progress.begin("tessellating " + std::to_string(triangles) + " triangles", triangles);
  TS::tessellate(file, scene.levels, scene.mesh);
  progress.end();
  scene.tessellation_seconds = seconds_since(start);
  if (job.options.mode == render::Mode::Net)
    scene.net = render::control_net(file);
  scene.kind = std::string("spline (") +
               (TS::Value_traits<Value>::dimension == 3 ? "parametric" : "functional") +
               ", degree " + std::to_string(scene.degree) + ")";
}

Scene load_spline(const Render_job& job, Progress& progress) {
  std::ifstream in(job.input);
  if (!in)
    throw std::runtime_error("cannot open '" + job.input + "'");
  // The header says whether the values are heights or points: peek, then read the file.
  const int dimension = TS::spline_file_dimension(in);
  Scene scene;
  if (dimension == 3)
    tessellate_spline_file<K::Vector_3>(in, job.input, job, progress, scene);
  else
    tessellate_spline_file<K::FT>(in, job.input, job, progress, scene);
  return scene;
}

// The interior samples per edge of the jump measure: as in 'tspline pseudo-ag1' (--samples),
// so that the colours match its report.
constexpr int jump_samples_per_edge = 15;

// A .surface (e.g. from 'tspline pseudo-ag1 --save'): the watertight closed tessellation with
// the patches' normals and Gaussian curvatures; the Fig. 6.9 net or the jump curves on demand.
Scene load_surface(const Render_job& job, Progress& progress) {
  std::ifstream in(job.input);
  if (!in)
    throw std::runtime_error("cannot open '" + job.input + "'");
  const TS::Surface_file<K> file = TS::read_surface_file<K>(in, job.input);
  const auto& input = file.mesh();
  Scene scene;
  scene.patches = input.number_of_faces();
  scene.degree = file.degree();
  scene.levels = job.levels ? *job.levels : automatic_levels(scene.patches);
  scene.kind = "closed surface (degree " + std::to_string(scene.degree) + ", " +
               std::to_string(scene.patches) + " patches)";
  const TS::Patch_sampler<TS::Surface_file<K>> sampler(file);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t triangles = scene.patches << (2 * scene.levels);
  progress.begin("tessellating " + std::to_string(triangles) + " triangles", triangles);
  TS::Closed_tessellation t =
      TS::tessellate_closed_surface(input, sampler, scene.levels, job.split_normals);
  progress.end();
  scene.tessellation_seconds = seconds_since(start);
  scene.mesh = std::move(t.mesh);
  // The properties that to_render_mesh() and --ply read, as for a .spline.
  auto normal =
      scene.mesh.add_property_map<Surface_mesh::Vertex_index, K::Vector_3>("v:normal").first;
  auto gaussian =
      scene.mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:gaussian_curvature").first;
  for (auto v : scene.mesh.vertices()) {
    const auto& n = t.normals[std::size_t(v)];
    normal[v] = K::Vector_3(n[0], n[1], n[2]); // zero where singular: the renderer falls back
    gaussian[v] = t.gaussian[std::size_t(v)];  // NaN where singular: drawn grey
  }

  if (job.options.mode == render::Mode::Net) {
    // Xu's roles apply to the quintic nets of pseudo-AG^1; other degrees get role colours.
    scene.net = job.umbrellas ? render::closed_surface_umbrellas(file)
                : scene.degree == 5
                    ? render::closed_surface_control_net(file, render::Pseudo_AG1_status())
                    : render::closed_surface_control_net(file);
    scene.net.status_fills = true;
  }
  if (job.options.mode == render::Mode::Jump) {
    // Only the edge jumps are needed: no self-intersection test, and the shape measures on
    // the coarsest tessellation.
    const TS::Closed_surface_measures m =
        TS::measure_closed_surface(input, sampler, jump_samples_per_edge, 0, false);
    scene.jump_max = m.max_jump_deg;
    scene.jump_mean_edge_max = m.mean_edge_max_jump_deg;
    scene.jump_samples = m.samples_per_edge;
    // Each edge sampled from one patch at the tessellation's own points, so that the curve
    // lies on the drawn surface and passes its depth test.
    const int n = 1 << scene.levels;
    for (auto e : input.edges()) {
      const auto h = TS::canonical_halfedge(e, input);
      render::Net::Curve curve;
      curve.value = m.edge_max_jump_deg[std::size_t(e)];
      for (int k = 0; k <= n; ++k) {
        const TS::Surface_sample s =
            sampler(input.face(h), TS::internal::weights_on_halfedge(input, h, double(k) / n));
        curve.points.push_back({s.point[0], s.point[1], s.point[2]});
      }
      scene.net.curves.push_back(std::move(curve));
    }
  }
  return scene;
}

Scene load_mesh(const Render_job& job) {
  Scene scene;
  scene.kind = "mesh";
  // The reader that c1, mann and blend use: CGAL's readers trust the file's counts and
  // indices, and NaN coordinates would draw a blank picture.
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  TS::read_mesh_soup(job.input, points, polygons);
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw TS::Invalid_input(job.input + ": not a manifold, consistently oriented polygon mesh");
  if (lowercase_extension(job.input) == "ply") {
    // Surface_mesh's own PLY reader keeps every vertex property, e.g. the normals and
    // curvatures that `tspline c1 --mesh` writes; the file has passed the checks above.
    struct Silence { // CGAL's diagnostics on std::cerr
      std::ostringstream sink;
      std::streambuf* saved = std::cerr.rdbuf(sink.rdbuf());
      ~Silence() { std::cerr.rdbuf(saved); }
    } silence;
    std::ifstream in(job.input, std::ios::binary);
    const bool ok = CGAL::IO::read_PLY(in, scene.mesh);
    if (ok && scene.mesh.number_of_vertices() == points.size() &&
        scene.mesh.number_of_faces() == polygons.size())
      return scene;
    scene.mesh.clear();
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, scene.mesh);
  return scene;
}

Json vector_json(const render::Vector& v) {
  Json a = Json::array();
  for (double x : v)
    a.push_back(x);
  return a;
}

// Renders `mesh` (+ `net`) and writes the PNG; returns the renderer's report.
render::Report render_to_png(const Surface_mesh& mesh, const render::Net* net,
                             const render::Options& options, const std::string& path) {
  render::Report report;
  const render::Mesh plain = render::to_render_mesh(mesh);
  const render::Image image = render::render(plain, net, options, &report);
  render::write_png(path, image);
  return report;
}

} // namespace

Json run_render_job(const Render_job& job, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const render::Mode mode = job.options.mode;
  const std::string ext = lowercase_extension(job.input);
  Progress progress(!job.quiet);
  Scene scene;
  if (mode == render::Mode::Jump && ext != "surface")
    throw Usage_error("--mode jump needs a .surface input (the normal jumps across the edges "
                      "of a closed surface, e.g. from 'tspline pseudo-ag1 --save')");
  if (ext == "spline") {
    scene = load_spline(job, progress);
  } else if (ext == "surface") {
    scene = load_surface(job, progress);
  } else if (ext == "ply" || ext == "off" || ext == "obj" || ext == "stl") {
    if (job.levels)
      throw Usage_error("--levels applies to .spline and .surface inputs only");
    scene = load_mesh(job);
    const bool has_curvature =
        scene.mesh.property_map<Surface_mesh::Vertex_index, double>("v:gaussian_curvature").second;
    if ((mode == render::Mode::Curvature || !job.ply.empty()) && !has_curvature)
      throw TS::Invalid_input(
          "'" + job.input + "' is a plain mesh: " +
          (mode == render::Mode::Curvature ? std::string("curvature mode") : std::string("--ply")) +
          " needs a .spline input (Gaussian curvature from the exact patch derivatives) or a PLY "
          "with per-vertex gaussian_curvature written by tspline");
    if (mode == render::Mode::Net)
      throw TS::Invalid_input("'" + job.input +
                              "' is a mesh: net mode needs a .spline or .surface input (control "
                              "points)");
  } else {
    throw TS::Invalid_input("'" + job.input + "': unknown input format '." + ext +
                            "' (expected .spline, .surface, or a mesh .ply/.off/.obj/.stl)");
  }
  if (scene.mesh.number_of_faces() == 0)
    throw TS::Invalid_input("'" + job.input + "' has no triangles to draw");

  progress.begin("rendering " + std::to_string(scene.mesh.number_of_faces()) + " triangles",
                 scene.mesh.number_of_faces());
  const bool overlay = mode == render::Mode::Net || mode == render::Mode::Jump;
  const render::Report rendered =
      render_to_png(scene.mesh, overlay ? &scene.net : nullptr, job.options, job.output);
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
  Surface_mesh mesh;
  TS::tessellate(spline, 4, mesh);
  render::Options options = job.options;
  options.mode = render::Mode::Net;
  options.azimuth = -25;
  options.elevation = 38;
  const std::string path = (dir / "demo_net.png").string();
  render_to_png(mesh, &net, options, path);
  std::size_t prescribed = 0;
  for (const auto& p : net.points)
    prescribed += p.status == render::Point_status::Prescribed ? 1 : 0;
  out << "  " << path << ": control net of a " << spline.domain().number_of_faces()
      << "-triangle C^1 quintic spline with " << spline.degenerate_frames().size()
      << " degenerate frames, " << prescribed << " prescribed and "
      << net.points.size() - prescribed << " propagated control points\n";
}

} // namespace tspline

// Scenes of spline, closed-surface and mesh files for the rasteriser (see scene.h).

#include "render/scene.h"
#include "render/surface_mesh_adapter.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace tspline::render {
namespace {

namespace TS = CGAL::Triangular_spline;
using K = Scene_kernel;
using Surface_mesh = Scene_mesh;

// Default tessellation budget (automatic_levels()).
constexpr std::size_t default_triangle_budget = std::size_t(1) << 18;
// Tessellating or drawing 2^21 triangles takes about a second (0.3 s and 0.25 s per 10^6
// measured at 1920x1080): larger stages are announced on a terminal.
constexpr std::size_t progress_threshold = std::size_t(1) << 21;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::ifstream open(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot open '" + path + "'");
  return in;
}

template <class Value>
void tessellate_spline_file(std::istream& in, const std::string& path, Mode mode,
                            std::optional<int> levels, Progress& progress, Scene& scene) {
  const TS::Spline_file<K, Value> file = TS::read_spline_file<K, Value>(in, path);
  const std::size_t faces = file.domain().number_of_faces();
  scene.patches = faces;
  scene.degree = file.degree();
  scene.levels = levels ? *levels : automatic_levels(faces);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t triangles = faces << (2 * scene.levels);
  progress.begin("tessellating " + std::to_string(triangles) + " triangles", triangles);
  TS::tessellate(file, scene.levels, scene.mesh);
  progress.end();
  scene.tessellation_seconds = seconds_since(start);
  if (mode == Mode::Net)
    scene.net = control_net(file);
  scene.kind = std::string("spline (") +
               (TS::Value_traits<Value>::dimension == 3 ? "parametric" : "functional") +
               ", degree " + std::to_string(scene.degree) + ")";
}

Scene load_spline(const std::string& path, Mode mode, std::optional<int> levels,
                  Progress& progress) {
  std::ifstream in = open(path);
  // The header says whether the values are heights or points: peek, then read the file.
  const int dimension = TS::spline_file_dimension(in);
  Scene scene;
  if (dimension == 3)
    tessellate_spline_file<K::Vector_3>(in, path, mode, levels, progress, scene);
  else
    tessellate_spline_file<K::FT>(in, path, mode, levels, progress, scene);
  return scene;
}

// The interior samples per edge of the jump measure: as in 'tspline pseudo-ag1' (--samples),
// so that the colours match its report.
constexpr int jump_samples_per_edge = 15;

// A .surface (e.g. from 'tspline pseudo-ag1 --save'): the watertight closed tessellation with
// the patches' normals and Gaussian curvatures; the Fig. 6.9 net or the jump curves on demand.
Scene load_surface(const std::string& path, Mode mode, std::optional<int> levels,
                   Progress& progress, bool split_normals, bool umbrellas) {
  std::ifstream in = open(path);
  const TS::Surface_file<K> file = TS::read_surface_file<K>(in, path);
  const auto& input = file.mesh();
  Scene scene;
  scene.patches = input.number_of_faces();
  scene.degree = file.degree();
  scene.levels = levels ? *levels : automatic_levels(scene.patches);
  scene.kind = "closed surface (degree " + std::to_string(scene.degree) + ", " +
               std::to_string(scene.patches) + " patches)";
  const TS::Patch_sampler<TS::Surface_file<K>> sampler(file);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t triangles = scene.patches << (2 * scene.levels);
  progress.begin("tessellating " + std::to_string(triangles) + " triangles", triangles);
  TS::Closed_tessellation t =
      TS::tessellate_closed_surface(input, sampler, scene.levels, split_normals);
  progress.end();
  scene.tessellation_seconds = seconds_since(start);
  // the properties that to_render_mesh() and --ply read, as for a .spline: a zero normal
  // where singular (the renderer falls back), NaN curvature (drawn grey)
  scene.mesh = TS::tessellation_mesh(std::move(t));

  if (mode == Mode::Net) {
    // Xu's roles apply to the quintic nets of pseudo-AG^1; other degrees get role colours.
    scene.net = umbrellas           ? closed_surface_umbrellas(file)
                : scene.degree == 5 ? closed_surface_control_net(file, Pseudo_AG1_status())
                                    : closed_surface_control_net(file);
    scene.net.status_fills = true;
  }
  if (mode == Mode::Jump) {
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
      Net::Curve curve;
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

Scene load_mesh(const std::string& path) {
  Scene scene;
  scene.kind = "mesh";
  // The reader that c1, mann and blend use: CGAL's readers trust the file's counts and
  // indices, and NaN coordinates would draw a blank picture.
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  TS::read_mesh_soup(path, points, polygons);
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw TS::Invalid_input(path + ": not a manifold, consistently oriented polygon mesh");
  if (TS::internal::mesh_extension(path) == ".ply") {
    // Surface_mesh's own PLY reader keeps every vertex property, e.g. the normals and
    // curvatures that `tspline c1 --mesh` writes; the file has passed the checks above.
    struct Silence { // CGAL's diagnostics on std::cerr
      std::ostringstream sink;
      std::streambuf* saved = std::cerr.rdbuf(sink.rdbuf());
      ~Silence() { std::cerr.rdbuf(saved); }
    } silence;
    std::ifstream in(path, std::ios::binary);
    const bool ok = CGAL::IO::read_PLY(in, scene.mesh);
    if (ok && scene.mesh.number_of_vertices() == points.size() &&
        scene.mesh.number_of_faces() == polygons.size())
      return scene;
    scene.mesh.clear();
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, scene.mesh);
  return scene;
}

} // namespace

Progress::Progress(bool enabled) : m_enabled(enabled && isatty(STDERR_FILENO) == 1) {}

void Progress::begin(const std::string& what, std::size_t triangles) {
  m_active = m_enabled && triangles >= progress_threshold;
  m_start = std::chrono::steady_clock::now();
  if (m_active)
    std::cerr << "tspline render: " << what << " ..." << std::flush;
}

void Progress::end() {
  if (m_active)
    std::cerr << " " << seconds_since(m_start) << " s\n";
  m_active = false;
}

int automatic_levels(std::size_t faces) {
  int levels = 0;
  while (levels < 6 && faces * (std::size_t(1) << (2 * (levels + 1))) <= default_triangle_budget)
    ++levels;
  return levels;
}

Scene load_scene(const std::string& path, Mode mode, std::optional<int> levels, Progress& progress,
                 bool split_normals, bool umbrellas) {
  const std::string ext = TS::internal::mesh_extension(path); // lowercase, with the dot
  if (mode == Mode::Jump && ext != ".surface")
    throw TS::Invalid_input("'" + path +
                            "': jump mode needs a .surface input (the normal jumps across the "
                            "edges of a closed surface, e.g. from 'tspline pseudo-ag1 --save')");
  Scene scene;
  if (ext == ".spline") {
    scene = load_spline(path, mode, levels, progress);
  } else if (ext == ".surface") {
    scene = load_surface(path, mode, levels, progress, split_normals, umbrellas);
  } else if (ext == ".ply" || ext == ".off" || ext == ".obj" || ext == ".stl") {
    scene = load_mesh(path);
    const bool has_curvature =
        scene.mesh.property_map<Surface_mesh::Vertex_index, double>("v:gaussian_curvature").second;
    if (mode == Mode::Curvature && !has_curvature)
      throw TS::Invalid_input(
          "'" + path +
          "' is a plain mesh: curvature mode needs a .spline input (Gaussian curvature from the "
          "exact patch derivatives) or a PLY with per-vertex gaussian_curvature written by "
          "tspline");
    if (mode == Mode::Net)
      throw TS::Invalid_input("'" + path +
                              "' is a mesh: net mode needs a .spline or .surface input (control "
                              "points)");
  } else {
    throw TS::Invalid_input("'" + path + "': unknown input format '" + ext +
                            "' (expected .spline, .surface, or a mesh .ply/.off/.obj/.stl)");
  }
  if (scene.mesh.number_of_faces() == 0)
    throw TS::Invalid_input("'" + path + "' has no triangles to draw");
  return scene;
}

Image render_scene(const Scene& scene, const Options& options, Report* report) {
  if (scene.mesh.number_of_faces() == 0)
    throw TS::Invalid_input("no triangles to draw");
  const bool overlay = options.mode == Mode::Net || options.mode == Mode::Jump;
  return render(to_render_mesh(scene.mesh), overlay ? &scene.net : nullptr, options, report);
}

} // namespace tspline::render

// What `tspline render` draws, made reusable: a spline, closed surface or mesh file (or a spline
// network in memory, e.g. the Python module's interpolators) turned into a Surface_mesh with
// normals and Gaussian curvatures plus the overlay of the mode, then drawn by the rasteriser.
// The CLI (render_job.cpp) and the Python module (tspline.render) both go through here, so the
// same input and options give the same pixels. Library tspline_scene (CGAL; scene.cpp).

#ifndef TSPLINE_RENDER_SCENE_H
#define TSPLINE_RENDER_SCENE_H

#include "render/control_net.h"
#include "render/render.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace tspline::render {

using Scene_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Scene_mesh = CGAL::Surface_mesh<Scene_kernel::Point_3>;

// What the renderer needs from an input, and what a report says about it.
struct Scene {
  Scene_mesh mesh;
  Net net;
  std::string kind;
  int levels = -1; // tessellation levels, -1 for a mesh input
  std::size_t patches = 0;
  int degree = 0;
  double tessellation_seconds = 0;
  // Mode::Jump on a .surface: the per-edge largest normal jumps (degrees) of the curves
  double jump_max = 0, jump_mean_edge_max = 0;
  std::size_t jump_samples = 0;
};

// Progress lines on stderr for long stages (about a second and more), only when enabled and
// stderr is a terminal.
class Progress {
public:
  explicit Progress(bool enabled);
  void begin(const std::string& what, std::size_t triangles);
  void end();

private:
  bool m_enabled, m_active = false;
  std::chrono::steady_clock::time_point m_start;
};

// 4-split levels that keep a tessellation of `faces` patches under about 2.6e5 triangles:
// smooth at any picture size up to ~1920x1080, well under a second.
int automatic_levels(std::size_t faces);

// The scene of a file: a .spline (tessellated with the exact patch derivatives), a .surface
// (the watertight closed tessellation; the Fig. 6.9 net or the jump curves on demand) or a
// mesh (.ply/.off/.obj/.stl, drawn as it is). `levels`: none for automatic_levels(). Throws
// Invalid_input (or std::runtime_error for a file that cannot be opened) with one-line
// messages, also for a mode the input cannot show (curvature of a plain mesh, net of a mesh,
// jump of anything but a .surface). For a .surface, `split_normals` gives every patch its own
// points and normals (the tangent-plane jumps show as creases) and `umbrellas` makes the net of
// Mode::Net only the umbrellas: corner points, stars, spokes and rims (Xu's Fig. 6.10).
Scene load_scene(const std::string& path, Mode mode, std::optional<int> levels, Progress& progress,
                 bool split_normals = false, bool umbrellas = false);

// The scene of a spline network in memory (any TriangularSplineNetwork): as load_scene() does
// for the .spline file that write_spline_file() would write of it.
template <class Network>
Scene network_scene(const Network& network, Mode mode, std::optional<int> levels) {
  Scene scene;
  const std::size_t faces = network.domain().number_of_faces();
  scene.patches = faces;
  scene.degree = faces == 0 ? 0 : network.patch(0).degree();
  scene.levels = levels ? *levels : automatic_levels(faces);
  const auto start = std::chrono::steady_clock::now();
  CGAL::Triangular_spline::tessellate(network, scene.levels, scene.mesh);
  scene.tessellation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (mode == Mode::Net)
    scene.net = control_net(network);
  scene.kind = "spline (degree " + std::to_string(scene.degree) + ")";
  return scene;
}

// Draws the scene (with its net or curves in Mode::Net and Mode::Jump). Throws
// std::invalid_argument for bad options, Invalid_input for an empty scene.
Image render_scene(const Scene& scene, const Options& options, Report* report = nullptr);

} // namespace tspline::render

#endif // TSPLINE_RENDER_SCENE_H

// Headless pictures of triangle meshes: a small z-buffered software rasteriser with deferred
// per-sample shading (shaded, Gaussian-curvature colours, isophotes, control-net overlay),
// supersampled and box-filtered, and PNG files through libpng. C++17 standard library only,
// so that only the translation units that read meshes or splines include CGAL (see
// surface_mesh_adapter.h and control_net.h for the bridges).
//
// Everything is deterministic: the same input gives the same pixels and the same PNG bytes.

#ifndef TSPLINE_RENDER_RENDER_H
#define TSPLINE_RENDER_RENDER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tspline::render {

using Vector = std::array<double, 3>;

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb& a, const Rgb& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  }
  friend bool operator!=(const Rgb& a, const Rgb& b) { return !(a == b); }
};

// An 8-bit RGB image, rows from top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels; // 3 * width * height bytes

  Image() = default;
  Image(int w, int h, Rgb fill = {255, 255, 255});
  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
};

// A triangle mesh as plain arrays. `normals` and `gaussian_curvature`, when not empty, hold
// one entry per position; without normals the faces are shaded flat. NaN curvatures (singular
// points) are drawn grey.
struct Mesh {
  std::vector<Vector> positions;
  std::vector<Vector> normals;
  std::vector<double> gaussian_curvature;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Roles of control points, the vocabulary of Xu's scheme (corner-inner, middle-inner and
// deeper points are all "inner"), and whether a point was prescribed (a free parameter) or
// propagated by the continuity conditions, when the caller knows it.
enum class Point_role { Corner, Star, Edge_middle, Inner };
enum class Point_status { Unknown, Prescribed, Propagated };

// A control net (or any set of points and segments) drawn over the surface in `Mode::Net`,
// and the curves drawn in `Mode::Jump`.
struct Net {
  struct Point {
    Vector position;
    Point_role role = Point_role::Inner;
    Point_status status = Point_status::Unknown;
  };
  // A polyline on the surface with a value for its colour (Mode::Jump: an input edge and its
  // largest normal jump in degrees).
  struct Curve {
    std::vector<Vector> points;
    double value = 0;
  };
  std::vector<Point> points;
  std::vector<std::array<Vector, 2>> segments;
  std::vector<Curve> curves;
  // Xu's Fig. 6.9 colours: corners and stars keep their role colours, and a known status fills
  // the other markers (prescribed green, propagated yellow) instead of ringing them.
  bool status_fills = false;
};

// Jump: shaded, with Net::curves coloured by value and a colour bar from 0 to the range.
enum class Mode { Shaded, Curvature, Isophotes, Net, Jump };

// "shaded", "curvature", "isophotes", "net", "jump"; parse_mode throws std::invalid_argument.
std::string mode_name(Mode mode);
Mode parse_mode(const std::string& name);

struct Options {
  Mode mode = Mode::Shaded;
  int width = 800, height = 600; // pixels, 1..16384 each
  // The eye looks at the centre of the bounding box from azimuth/elevation (degrees), MATLAB's
  // convention: (0, 0) looks from -y towards +y with x to the right and z up; positive
  // azimuth turns the eye counter-clockwise about z; (0, 90) is the top view, x right, y up.
  double azimuth = -35, elevation = 35;
  bool perspective = false; // orthographic by default
  // Direction from the surface towards the light in world coordinates; by default a light
  // above and to the left of the eye. Isophotes use it as the direction e (by default the
  // direction towards the eye, as in Fang §2.3).
  std::optional<Vector> light;
  int bands = 12; // isophotes: |n.e| in [0, 1] is cut into this many black/white bands
  // Curvature colours saturate at |K| = range; by default the 98th percentile of |K|.
  std::optional<double> curvature_range;
  // Jump colours saturate at this value; by default the largest curve value, at least 1.
  std::optional<double> jump_range;
  int supersampling = 2; // samples per pixel along each axis, 1..4
  bool legend = true;    // colour bar (curvature, jump) or marker key (net)
};

struct Report {
  std::size_t triangles = 0;       // in the mesh
  std::size_t drawn_triangles = 0; // finite and not degenerate on screen
  std::size_t covered_pixels = 0;  // pixels with some surface in them
  bool has_curvature = false;
  double curvature_min = 0, curvature_max = 0; // over finite vertex values
  double curvature_range = 0;                  // the colour scale used (Mode::Curvature)
  bool curvature_range_from_user = false;
  double jump_max = 0;   // the largest finite curve value (Mode::Jump)
  double jump_range = 0; // the colour scale used (Mode::Jump)
  double seconds = 0;
};

// Renders `mesh` (and `net` in Mode::Net and Mode::Jump; it may be null) on a white background,
// auto-fitted with a margin of 5% of min(width, height) pixels on every side (plus room for the
// legend). Throws std::invalid_argument for bad options, out-of-range triangle indices, a
// normal/curvature array of the wrong size, or Mode::Curvature without curvatures.
// An empty mesh gives a white image.
Image render(const Mesh& mesh, const Net* net, const Options& options, Report* report = nullptr);

// Fang's colour convention: green at K = 0, through yellow to red as K/range goes to +1, and
// through cyan to blue as it goes to -1: hue = 120 (1 - t) degrees, t = K/range clamped to
// [-1, 1], full saturation and value. NaN gives grey.
Rgb curvature_colour(double K, double range);
// The colour scale chosen when the user gives none: the 98th percentile of the finite |K|,
// at least `floor` (so that round-off on a plane stays green), and 1 if there is nothing.
double robust_curvature_range(const std::vector<double>& K, double floor);

// Colours of the control-net markers (exposed for tests and legends).
Rgb role_colour(Point_role role);
Rgb status_colour(Point_status status);

// Hue in degrees [0, 360) and saturation in [0, 1] of a colour (HSV), for tests and tools.
double hue(Rgb c);
double saturation(Rgb c);

// PNG through libpng (8-bit RGB, no time stamp: identical images give identical bytes).
// Errors throw std::runtime_error naming the path.
std::vector<std::uint8_t> encode_png(const Image& image);
void write_png(const std::string& path, const Image& image);
Image read_png(const std::string& path);

} // namespace tspline::render

#endif // TSPLINE_RENDER_RENDER_H

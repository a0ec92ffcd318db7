// The rasteriser. Two passes over a supersampled buffer: (1) every triangle is scan-converted
// with edge functions into a z-buffer that keeps, per sample, the nearest triangle's id;
// (2) every covered sample is shaded once from its triangle's vertex data (deferred shading),
// so the cost of lighting does not grow with overdraw. The control net is then drawn over the
// samples, depth-tested against the surface, and the buffer is box-filtered to the image.
// Legends are drawn last, at the final resolution, so that text stays crisp.

#include "render.h"

#include "font.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace tspline::render {

Image::Image(int w, int h, Rgb fill)
    : width(w), height(h), pixels(3 * std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0))) {
  for (std::size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = fill.r;
    pixels[i + 1] = fill.g;
    pixels[i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  pixels[i] = c.r;
  pixels[i + 1] = c.g;
  pixels[i + 2] = c.b;
}

std::string mode_name(Mode mode) {
  switch (mode) {
  case Mode::Shaded:
    return "shaded";
  case Mode::Curvature:
    return "curvature";
  case Mode::Isophotes:
    return "isophotes";
  case Mode::Net:
    return "net";
  case Mode::Jump:
    return "jump";
  }
  return "shaded";
}

Mode parse_mode(const std::string& name) {
  for (Mode m : {Mode::Shaded, Mode::Curvature, Mode::Isophotes, Mode::Net, Mode::Jump})
    if (mode_name(m) == name)
      return m;
  throw std::invalid_argument("unknown render mode '" + name +
                              "' (expected shaded, curvature, isophotes, net or jump)");
}

Rgb curvature_colour(double K, double range) {
  if (std::isnan(K) || !(range > 0))
    return {150, 150, 150};
  const double t = std::clamp(K / range, -1.0, 1.0);
  const double h = 120 * (1 - t) / 60; // hue in sextants, 0 (red) .. 4 (blue)
  double r = 0, g = 0, b = 0;
  if (h < 1) {
    r = 1, g = h;
  } else if (h < 2) {
    r = 2 - h, g = 1;
  } else if (h < 3) {
    g = 1, b = h - 2;
  } else {
    g = 4 - h, b = 1;
  }
  auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(255 * v)); };
  return {byte(r), byte(g), byte(b)};
}

double robust_curvature_range(const std::vector<double>& K, double floor) {
  std::vector<double> magnitudes;
  magnitudes.reserve(K.size());
  for (double k : K)
    if (std::isfinite(k))
      magnitudes.push_back(std::abs(k));
  if (magnitudes.empty())
    return floor > 0 ? floor : 1;
  const std::size_t n = static_cast<std::size_t>(0.98 * double(magnitudes.size() - 1));
  std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(n), magnitudes.end());
  const double range = std::max(magnitudes[n], floor);
  return range > 0 ? range : 1;
}

Rgb role_colour(Point_role role) {
  switch (role) {
  case Point_role::Corner:
    return {220, 30, 30}; // Xu Fig. 6.9: corners red, stars magenta
  case Point_role::Star:
    return {215, 40, 215};
  case Point_role::Edge_middle:
    return {30, 90, 230};
  case Point_role::Inner:
    return {110, 110, 120};
  }
  return {0, 0, 0};
}

Rgb status_colour(Point_status status) {
  switch (status) {
  case Point_status::Prescribed:
    return {0, 170, 70}; // Xu §4: prescribed green
  case Point_status::Propagated:
    return {255, 190, 0}; // Xu Fig. 6.9: propagated yellow (amber, to read on white)
  case Point_status::Unknown:
    break;
  }
  return {255, 255, 255};
}

double hue(Rgb c) {
  const double r = c.r, g = c.g, b = c.b;
  const double max = std::max({r, g, b}), min = std::min({r, g, b}), delta = max - min;
  if (delta == 0)
    return 0;
  double h;
  if (max == r)
    h = std::fmod((g - b) / delta + 6, 6.0);
  else if (max == g)
    h = (b - r) / delta + 2;
  else
    h = (r - g) / delta + 4;
  return 60 * h;
}

double saturation(Rgb c) {
  const double max = std::max({c.r, c.g, c.b}), min = std::min({c.r, c.g, c.b});
  return max == 0 ? 0 : (max - min) / max;
}

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr std::uint32_t no_triangle = std::numeric_limits<std::uint32_t>::max();
constexpr float far_away = -std::numeric_limits<float>::infinity();
constexpr std::size_t max_samples = std::size_t(64) << 20; // ~11 bytes each: 700 MB at most

Vector operator+(const Vector& a, const Vector& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vector operator-(const Vector& a, const Vector& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vector operator*(double s, const Vector& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vector cross(const Vector& a, const Vector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_finite(const Vector& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
// The unit vector along `a`, or zero if `a` is zero or not finite.
Vector normalized(const Vector& a) {
  const double length = std::sqrt(dot(a, a));
  return length > 0 && std::isfinite(length) ? (1 / length) * a : Vector{0, 0, 0};
}

// A projected point: screen position in samples (y down) and "closeness" q, larger = nearer.
// q is the eye-space depth (orthographic) or its reciprocal (perspective): both vary linearly
// across a projected triangle, so the z-buffer interpolates them in screen space.
struct Projected {
  double x, y, q;
};

struct Camera {
  Vector right, up, toward_eye, centre;
  bool perspective = false;
  double eye_distance = 1;
  double scale = 1, offset_x = 0, offset_y = 0; // the 2D fit, in samples

  Vector eye() const { return centre + eye_distance * toward_eye; }

  // Camera-plane coordinates before the fit.
  Projected project_raw(const Vector& p) const {
    const Vector d = p - centre;
    const double x = dot(d, right), y = dot(d, up), z = dot(d, toward_eye);
    if (!perspective)
      return {x, y, z};
    const double s = eye_distance - z; // > 0: the eye is outside the bounding sphere
    return {x / s, y / s, 1 / s};
  }
  Projected project(const Vector& p) const {
    const Projected r = project_raw(p);
    return {offset_x + scale * r.x, offset_y - scale * r.y, r.q};
  }
};

// Room taken by the legends, and the font scale.
struct Layout {
  int font_scale = 1;
  int right = 0, bottom = 0; // pixels reserved on the right (colour bar) / bottom (marker key)
};

int font_scale_for(int width, int height) {
  return std::max(1, static_cast<int>(std::lround(std::min(width, height) / 260.0)));
}

std::string format_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

struct Legend_items {
  bool roles = false, status = false;
  // only the roles and statuses that occur get a key (e.g. umbrellas: corners and stars)
  std::array<bool, 4> role{{false, false, false, false}};
  std::array<bool, 3> state{{false, false, false}};
};

Legend_items net_legend_items(const Net* net) {
  Legend_items items;
  if (net == nullptr)
    return items;
  items.roles = !net->points.empty();
  for (const Net::Point& p : net->points) {
    items.role[std::size_t(p.role)] = true;
    items.state[std::size_t(p.status)] = true;
    if (p.status != Point_status::Unknown)
      items.status = true;
  }
  return items;
}

// The colour bar's title and labels: +-range around 0 for curvature, 0 to range for jumps.
struct Bar_labels {
  std::string title, top, middle, bottom;
};

Bar_labels bar_labels(Mode mode, double range) {
  if (mode == Mode::Jump)
    return {"DEG", format_number(range), format_number(range / 2), "0"};
  return {"K", "+" + format_number(range), "0", "-" + format_number(range)};
}

Layout layout_for(const Options& o, const Net* net, double range) {
  Layout layout;
  layout.font_scale = font_scale_for(o.width, o.height);
  if (!o.legend)
    return layout;
  const int s = layout.font_scale;
  if (o.mode == Mode::Curvature || o.mode == Mode::Jump) {
    const Bar_labels b = bar_labels(o.mode, range);
    const int labels = std::max({internal::text_width(b.top, s), internal::text_width(b.middle, s),
                                 internal::text_width(b.bottom, s)});
    layout.right = 5 * s + 4 + 4 * s + labels + 2 * s;
  } else if (o.mode == Mode::Net) {
    const Legend_items items = net_legend_items(net);
    // Xu's colours fit one row: corner, star, prescribed, propagated.
    const int rows =
        items.roles && net->status_fills ? 1 : (items.roles ? 1 : 0) + (items.status ? 1 : 0);
    layout.bottom = rows * (internal::text_height(s) + 5 * s);
  }
  // Never let a legend take more than a third of the picture.
  layout.right = std::min(layout.right, o.width / 3);
  layout.bottom = std::min(layout.bottom, o.height / 3);
  return layout;
}

void check_options(const Options& o) {
  if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
    throw std::invalid_argument("image size must be between 1x1 and 16384x16384, got " +
                                std::to_string(o.width) + "x" + std::to_string(o.height));
  if (std::size_t(o.width) * std::size_t(o.height) > max_samples)
    throw std::invalid_argument("image of " + std::to_string(o.width) + "x" +
                                std::to_string(o.height) + " pixels is too large");
  if (o.supersampling < 1 || o.supersampling > 4)
    throw std::invalid_argument("supersampling must be between 1 and 4");
  if (o.bands < 1 || o.bands > 1000)
    throw std::invalid_argument("the number of isophote bands must be between 1 and 1000");
  if (!std::isfinite(o.azimuth) || !std::isfinite(o.elevation))
    throw std::invalid_argument("view angles must be finite");
  if (o.curvature_range && !(std::isfinite(*o.curvature_range) && *o.curvature_range > 0))
    throw std::invalid_argument("the curvature range must be a positive finite number");
  if (o.jump_range && !(std::isfinite(*o.jump_range) && *o.jump_range > 0))
    throw std::invalid_argument("the jump range must be a positive finite number");
  if (o.light && normalized(*o.light) == Vector{0, 0, 0})
    throw std::invalid_argument("the light direction must be a non-zero finite vector");
}

void check_mesh(const Mesh& mesh, Mode mode) {
  const std::size_t n = mesh.positions.size();
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    throw std::invalid_argument("the mesh has " + std::to_string(mesh.normals.size()) +
                                " normals for " + std::to_string(n) + " vertices");
  if (!mesh.gaussian_curvature.empty() && mesh.gaussian_curvature.size() != n)
    throw std::invalid_argument("the mesh has " + std::to_string(mesh.gaussian_curvature.size()) +
                                " curvatures for " + std::to_string(n) + " vertices");
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= n)
        throw std::invalid_argument("triangle vertex index " + std::to_string(v) +
                                    " out of range (" + std::to_string(n) + " vertices)");
  if (mode == Mode::Curvature && mesh.gaussian_curvature.empty() && !mesh.triangles.empty())
    throw std::invalid_argument("curvature mode needs per-vertex Gaussian curvatures");
}

// The bounding box of the finite points; false (and a zero box) if there is none.
bool bounding_box(const std::vector<Vector>& points, Vector& lo, Vector& hi) {
  lo = hi = Vector{0, 0, 0};
  bool any = false;
  for (const Vector& p : points) {
    if (!is_finite(p))
      continue;
    for (int c = 0; c < 3; ++c) {
      lo[c] = any ? std::min(lo[c], p[c]) : p[c];
      hi[c] = any ? std::max(hi[c], p[c]) : p[c];
    }
    any = true;
  }
  return any;
}

// Orients the camera, then fits the projected bounding box of all finite points into the
// drawing area (image minus margin and legends), centred, keeping the aspect ratio.
Camera make_camera(const Options& o, const Layout& layout, const std::vector<Vector>& points) {
  Camera camera;
  const double az = o.azimuth * pi / 180, el = o.elevation * pi / 180;
  camera.toward_eye = {std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), std::sin(el)};
  // Horizontal and independent of the elevation, so the top view (el = 90) is well defined.
  camera.right = {std::cos(az), std::sin(az), 0};
  camera.up = cross(camera.toward_eye, camera.right);
  camera.perspective = o.perspective;

  Vector lo, hi;
  bounding_box(points, lo, hi);
  camera.centre = 0.5 * (lo + hi);
  const double radius = 0.5 * std::sqrt(dot(hi - lo, hi - lo));
  // The eye sits outside the bounding sphere, so no point is behind it: no clipping needed.
  camera.eye_distance = radius > 0 ? 3 * radius : 1;

  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool any = false;
  for (const Vector& p : points) {
    if (!is_finite(p))
      continue;
    const Projected r = camera.project_raw(p);
    x0 = any ? std::min(x0, r.x) : r.x, x1 = any ? std::max(x1, r.x) : r.x;
    y0 = any ? std::min(y0, r.y) : r.y, y1 = any ? std::max(y1, r.y) : r.y;
    any = true;
  }
  const double margin = 0.05 * std::min(o.width, o.height);
  const double area_w = std::max(1.0, o.width - 2 * margin - layout.right);
  const double area_h = std::max(1.0, o.height - 2 * margin - layout.bottom);
  const double ex = x1 - x0, ey = y1 - y0;
  double scale = 1; // a single point: any scale
  if (ex > 0 && ey > 0)
    scale = std::min(area_w / ex, area_h / ey);
  else if (ex > 0)
    scale = area_w / ex;
  else if (ey > 0)
    scale = area_h / ey;
  const double ss = o.supersampling;
  camera.scale = ss * scale;
  camera.offset_x = ss * (margin + 0.5 * area_w) - camera.scale * 0.5 * (x0 + x1);
  camera.offset_y = ss * (margin + 0.5 * area_h) + camera.scale * 0.5 * (y0 + y1);
  return camera;
}

// The supersampled frame: z-buffer, triangle ids and colours.
struct Frame {
  int width, height; // in samples
  std::vector<float> depth;
  std::vector<std::uint32_t> id;
  std::vector<std::uint8_t> colour;

  Frame(int w, int h)
      : width(w), height(h), depth(std::size_t(w) * std::size_t(h), far_away),
        id(depth.size(), no_triangle), colour(3 * depth.size(), 255) {}

  void blend(std::size_t i, Rgb c, double alpha) {
    std::uint8_t* p = &colour[3 * i];
    const std::uint8_t rgb[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k)
      p[k] = static_cast<std::uint8_t>(std::lround(p[k] + alpha * (rgb[k] - p[k])));
  }
};

double edge(const Projected& a, const Projected& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// Pass 1: scan conversion. Vertices are snapped to 1/256 of a sample, so the edge functions
// are exact 64-bit integers: two triangles sharing an edge see exactly opposite values, and
// with the inclusive test a sample on the edge belongs to both, so there are never cracks.
// The strict depth test lets the first triangle win ties: the result is deterministic.
// Sample (i, j) has its centre at (i + 1/2, j + 1/2).
constexpr std::int64_t fixed_one = 256, fixed_half = 128;
// Auto-fit keeps every finite vertex inside the frame (at most 65536 samples wide); farther
// points would only come from a bug, and are rejected before they could overflow.
constexpr double fixed_limit = double(std::int64_t(1) << 20) * fixed_one;

struct Fixed {
  std::int64_t x = 0, y = 0;
  bool valid = false;
};

std::vector<Fixed> snap(const std::vector<Projected>& projected) {
  std::vector<Fixed> result(projected.size());
  for (std::size_t v = 0; v < projected.size(); ++v) {
    const double x = projected[v].x * fixed_one, y = projected[v].y * fixed_one;
    if (std::isfinite(projected[v].q) && std::abs(x) < fixed_limit && std::abs(y) < fixed_limit)
      result[v] = {std::llround(x), std::llround(y), true};
  }
  return result;
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

std::int64_t edge(const Fixed& a, const Fixed& b, std::int64_t px, std::int64_t py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

std::size_t rasterize(const Mesh& mesh, const std::vector<Projected>& projected, Frame& frame) {
  const std::vector<Fixed> fixed = snap(projected);
  std::size_t drawn = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    Fixed a = fixed[tri[0]], b = fixed[tri[1]], c = fixed[tri[2]];
    double qa = projected[tri[0]].q, qb = projected[tri[1]].q, qc = projected[tri[2]].q;
    if (!a.valid || !b.valid || !c.valid)
      continue;
    std::int64_t area = edge(a, b, c.x, c.y);
    if (area == 0)
      continue;
    ++drawn;
    if (area < 0) {
      std::swap(b, c);
      std::swap(qb, qc);
      area = -area;
    }
    // Samples whose centres i * one + half lie in the bounding box.
    const std::int64_t x0 =
        std::max<std::int64_t>(0, -floor_div(-(std::min({a.x, b.x, c.x}) - fixed_half), fixed_one));
    const std::int64_t x1 = std::min<std::int64_t>(
        frame.width - 1, floor_div(std::max({a.x, b.x, c.x}) - fixed_half, fixed_one));
    const std::int64_t y0 =
        std::max<std::int64_t>(0, -floor_div(-(std::min({a.y, b.y, c.y}) - fixed_half), fixed_one));
    const std::int64_t y1 = std::min<std::int64_t>(
        frame.height - 1, floor_div(std::max({a.y, b.y, c.y}) - fixed_half, fixed_one));
    if (x0 > x1 || y0 > y1)
      continue;
    // Edge functions are affine: step them along each row.
    const std::int64_t d0 = -(c.y - b.y) * fixed_one, d1 = -(a.y - c.y) * fixed_one,
                       d2 = -(b.y - a.y) * fixed_one;
    const double inv_area = 1 / double(area);
    for (std::int64_t y = y0; y <= y1; ++y) {
      const std::int64_t py = y * fixed_one + fixed_half, px = x0 * fixed_one + fixed_half;
      std::int64_t w0 = edge(b, c, px, py), w1 = edge(c, a, px, py), w2 = edge(a, b, px, py);
      std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x0);
      for (std::int64_t x = x0; x <= x1; ++x, ++i, w0 += d0, w1 += d1, w2 += d2) {
        if ((w0 | w1 | w2) < 0) // some edge function is negative
          continue;
        const float q =
            static_cast<float>((double(w0) * qa + double(w1) * qb + double(w2) * qc) * inv_area);
        if (q > frame.depth[i]) {
          frame.depth[i] = q;
          frame.id[i] = static_cast<std::uint32_t>(t);
        }
      }
    }
  }
  return drawn;
}

struct Lighting {
  Vector light, fill, isophote; // unit vectors, world space
  bool isophote_is_view;        // e = towards the eye at each point
  double range;                 // curvature colour scale
};

struct Colour {
  double r, g, b;
};

Colour scaled(Rgb c, double s) {
  return {s * c.r / 255, s * c.g / 255, s * c.b / 255};
}

// x^40, the Blinn-Phong exponent, by squaring: std::pow costs more than the rest of shading.
double power_40(double x) {
  const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4, x16 = x8 * x8;
  return x8 * x16 * x16;
}

std::uint8_t to_byte(double v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5);
}

// Pass 2: one colour per covered sample.
void shade(const Mesh& mesh, const std::vector<Projected>& projected, const Camera& camera,
           const Options& o, const Lighting& lighting, Frame& frame) {
  const bool has_normals = !mesh.normals.empty();
  const bool has_curvature = !mesh.gaussian_curvature.empty();
  const Vector eye = camera.eye();
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
      const std::uint32_t t = frame.id[i];
      if (t == no_triangle)
        continue;
      const auto& tri = mesh.triangles[t];
      const Projected& a = projected[tri[0]];
      const Projected& b = projected[tri[1]];
      const Projected& c = projected[tri[2]];
      const double px = x + 0.5, py = y + 0.5;
      // Screen-space barycentrics (the sign of the area cancels), made perspective-correct
      // by weighting with q = 1/depth.
      const double area = edge(a, b, c.x, c.y);
      double l[3] = {std::max(0.0, edge(b, c, px, py) / area),
                     std::max(0.0, edge(c, a, px, py) / area),
                     std::max(0.0, edge(a, b, px, py) / area)};
      if (camera.perspective) {
        l[0] *= a.q, l[1] *= b.q, l[2] *= c.q;
      }
      const double sum = l[0] + l[1] + l[2];
      if (sum > 0)
        l[0] /= sum, l[1] /= sum, l[2] /= sum;

      const Vector& p0 = mesh.positions[tri[0]];
      const Vector& p1 = mesh.positions[tri[1]];
      const Vector& p2 = mesh.positions[tri[2]];
      Vector n{0, 0, 0};
      if (has_normals)
        n = normalized(l[0] * mesh.normals[tri[0]] + l[1] * mesh.normals[tri[1]] +
                       l[2] * mesh.normals[tri[2]]);
      if (n == Vector{0, 0, 0}) // no normals, or a singular point: the face's own normal
        n = normalized(cross(p1 - p0, p2 - p0));
      Vector view = camera.toward_eye;
      if (camera.perspective) {
        const Vector view_point = normalized(eye - (l[0] * p0 + l[1] * p1 + l[2] * p2));
        if (view_point != Vector{0, 0, 0})
          view = view_point;
      }
      const bool back = dot(n, view) < 0;
      if (back) // two-sided lighting: light the side that is seen
        n = -1 * n;
      const double diffuse = std::max(0.0, dot(n, lighting.light));
      const double fill = std::max(0.0, dot(n, lighting.fill));

      Colour colour{1, 1, 1};
      switch (o.mode) {
      case Mode::Shaded:
      case Mode::Jump: {
        const Vector half = normalized(lighting.light + view);
        const double specular = power_40(std::max(0.0, dot(n, half)));
        const double s = 0.20 + 0.70 * diffuse + 0.14 * fill;
        // The back side (against the mesh orientation; below a height field) is warm.
        const Colour base = back ? Colour{0.88, 0.72, 0.50} : Colour{0.60, 0.70, 0.86};
        colour = {base.r * s + 0.22 * specular, base.g * s + 0.22 * specular,
                  base.b * s + 0.22 * specular};
        break;
      }
      case Mode::Curvature: {
        double K = std::numeric_limits<double>::quiet_NaN();
        if (has_curvature)
          K = l[0] * mesh.gaussian_curvature[tri[0]] + l[1] * mesh.gaussian_curvature[tri[1]] +
              l[2] * mesh.gaussian_curvature[tri[2]];
        // A pure scaling keeps the hue: the colour still reads as the curvature.
        colour = scaled(curvature_colour(K, lighting.range), 0.58 + 0.34 * diffuse + 0.08 * fill);
        break;
      }
      case Mode::Isophotes: {
        const Vector e = lighting.isophote_is_view ? view : lighting.isophote;
        const double brightness = std::min(1.0, std::abs(dot(n, e)));
        const int band = std::min(o.bands - 1, static_cast<int>(brightness * o.bands));
        // The band facing e is white; the others alternate.
        const double v = (o.bands - 1 - band) % 2 == 0 ? 1.0 : 0.0;
        colour = {v, v, v};
        break;
      }
      case Mode::Net: {
        const double s = 0.62 + 0.30 * diffuse + 0.08 * fill;
        colour = {0.95 * s, 0.95 * s, 0.97 * s};
        break;
      }
      }
      std::uint8_t* out = &frame.colour[3 * i];
      out[0] = to_byte(colour.r);
      out[1] = to_byte(colour.g);
      out[2] = to_byte(colour.b);
    }
}

// Isophote stripes are white where the surface faces e; a thin outline keeps the white ones
// apart from the white background.
void draw_outline(Frame& frame, int width) {
  std::vector<std::uint8_t> edge_sample(frame.id.size(), 0);
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
      if (frame.id[i] == no_triangle)
        continue;
      bool border = false;
      for (int dy = -width; dy <= width && !border; ++dy)
        for (int dx = -width; dx <= width && !border; ++dx) {
          const int nx = x + dx, ny = y + dy;
          border =
              nx < 0 || ny < 0 || nx >= frame.width || ny >= frame.height ||
              frame.id[std::size_t(ny) * std::size_t(frame.width) + std::size_t(nx)] == no_triangle;
        }
      edge_sample[i] = border ? 1 : 0;
    }
  for (std::size_t i = 0; i < edge_sample.size(); ++i)
    if (edge_sample[i] != 0)
      frame.blend(i, {90, 90, 90}, 1.0);
}

// The control net over the surface. An element in front of the surface (within `tolerance`
// in q) is drawn opaque; one behind it is drawn faint, so the whole net stays readable.
class Net_painter {
public:
  Net_painter(const Camera& camera, Frame& frame, double tolerance, int supersampling)
      : m_camera(camera), m_frame(frame), m_tolerance(tolerance), m_ss(supersampling) {}

  // Hidden parts of the segment are blended with `hidden_alpha`.
  void segment(const Vector& p, const Vector& q, Rgb colour, double half_width,
               double hidden_alpha = 0.22) {
    const Projected a = m_camera.project(p), b = m_camera.project(q);
    if (!std::isfinite(a.x + a.y + b.x + b.y))
      return;
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    int x0, x1, y0, y1;
    if (!box(std::min(a.x, b.x) - half_width, std::max(a.x, b.x) + half_width,
             std::min(a.y, b.y) - half_width, std::max(a.y, b.y) + half_width, x0, x1, y0, y1))
      return;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5 - a.x, py = y + 0.5 - a.y;
        const double s = length2 > 0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0;
        const double ex = px - s * dx, ey = py - s * dy;
        if (ex * ex + ey * ey > half_width * half_width)
          continue;
        const std::size_t i = index(x, y);
        const double depth = a.q + s * (b.q - a.q); // q is linear along the projected segment
        const double alpha = depth >= m_frame.depth[i] - m_tolerance ? 1.0 : hidden_alpha;
        if (alpha > 0)
          m_frame.blend(i, colour, alpha);
      }
  }

  // A marker: a square for corners, a disc otherwise; with a known status, an outer ring in
  // the status colour around the role colour (or, with `fills`, the status colour filling
  // every marker but corners and stars); a dark rim.
  void marker(const Net::Point& point, double radius, bool visible_pass, bool fills) {
    const Projected c = m_camera.project(point.position);
    if (!std::isfinite(c.x + c.y))
      return;
    const bool visible = is_visible(c);
    if (visible != visible_pass)
      return;
    const double alpha = visible ? 1.0 : 0.3;
    int x0, x1, y0, y1;
    if (!box(c.x - radius, c.x + radius, c.y - radius, c.y + radius, x0, x1, y0, y1))
      return;
    const bool square = point.role == Point_role::Corner;
    const bool known = point.status != Point_status::Unknown;
    const bool filled =
        fills && known && point.role != Point_role::Corner && point.role != Point_role::Star;
    const bool ringed = known && !fills;
    const Rgb fill = filled ? status_colour(point.status) : role_colour(point.role);
    const double rim = std::max(0.6 * m_ss, 0.14 * radius);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double dx = std::abs(x + 0.5 - c.x), dy = std::abs(y + 0.5 - c.y);
        // Distance to the centre in the marker's own norm; a square's half side is 0.88 of the
        // radius so that it does not look larger than a disc.
        const double d = square ? std::max(dx, dy) / 0.88 : std::sqrt(dx * dx + dy * dy);
        if (d > radius)
          continue;
        Rgb colour = fill;
        if (d > radius - rim)
          colour = {40, 40, 40};
        else if (ringed && d > 0.6 * radius)
          colour = status_colour(point.status);
        m_frame.blend(index(x, y), colour, alpha);
      }
  }

private:
  bool box(double lx, double hx, double ly, double hy, int& x0, int& x1, int& y0, int& y1) const {
    const double bx0 = std::max(0.0, std::ceil(lx - 0.5));
    const double bx1 = std::min(m_frame.width - 1.0, std::floor(hx - 0.5));
    const double by0 = std::max(0.0, std::ceil(ly - 0.5));
    const double by1 = std::min(m_frame.height - 1.0, std::floor(hy - 0.5));
    if (!(bx0 <= bx1 && by0 <= by1))
      return false;
    x0 = static_cast<int>(bx0), x1 = static_cast<int>(bx1);
    y0 = static_cast<int>(by0), y1 = static_cast<int>(by1);
    return true;
  }
  std::size_t index(int x, int y) const {
    return std::size_t(y) * std::size_t(m_frame.width) + std::size_t(x);
  }
  bool is_visible(const Projected& c) const {
    const double x = std::floor(c.x), y = std::floor(c.y);
    if (x < 0 || y < 0 || x >= m_frame.width || y >= m_frame.height)
      return true;
    return c.q >= m_frame.depth[index(static_cast<int>(x), static_cast<int>(y))] - m_tolerance;
  }

  const Camera& m_camera;
  Frame& m_frame;
  double m_tolerance;
  int m_ss;
};

// Marker size from the net's own scale: about a third of the median projected segment.
double marker_radius(const Net& net, const Camera& camera, const Options& o) {
  std::vector<double> lengths;
  lengths.reserve(net.segments.size());
  for (const auto& s : net.segments) {
    const Projected a = camera.project(s[0]), b = camera.project(s[1]);
    const double l = std::hypot(b.x - a.x, b.y - a.y) / o.supersampling;
    if (std::isfinite(l) && l > 0)
      lengths.push_back(l);
  }
  double median = 12;
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2),
                     lengths.end());
    median = lengths[lengths.size() / 2];
  }
  const double largest = std::max(2.0, std::min(o.width, o.height) / 70.0);
  return o.supersampling * std::clamp(0.3 * median, 2.0, largest);
}

void draw_net(const Net& net, const Camera& camera, const Options& o, double tolerance,
              Frame& frame) {
  Net_painter painter(camera, frame, tolerance, o.supersampling);
  const double half_width =
      0.6 * o.supersampling * std::max(1.0, std::min(o.width, o.height) / 600.0);
  for (const auto& s : net.segments)
    painter.segment(s[0], s[1], {60, 60, 75}, half_width);
  const double radius = marker_radius(net, camera, o);
  for (bool visible : {false, true}) // hidden ones first: visible markers stay on top
    for (const Net::Point& p : net.points)
      painter.marker(p, radius, visible, net.status_fills);
}

// Each curve's projected length, for the line width of Mode::Jump.
double median_curve_length(const Net& net, const Camera& camera, int ss) {
  std::vector<double> lengths;
  for (const Net::Curve& c : net.curves) {
    double length = 0;
    for (std::size_t k = 1; k < c.points.size(); ++k) {
      const Projected a = camera.project(c.points[k - 1]), b = camera.project(c.points[k]);
      length += std::hypot(b.x - a.x, b.y - a.y) / ss;
    }
    if (std::isfinite(length) && length > 0)
      lengths.push_back(length);
  }
  if (lengths.empty())
    return 0;
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

// The curves of Mode::Jump, coloured by value on the 0..range half of the curvature scale
// (green 0, yellow, red at the range). Hidden parts are not drawn: on a closed surface they
// would only clutter the visible ones. The width follows the curves' projected length, so a
// dense mesh still shows its surface between the lines.
void draw_curves(const Net& net, const Camera& camera, const Options& o, double tolerance,
                 double range, Frame& frame) {
  Net_painter painter(camera, frame, tolerance, o.supersampling);
  const double largest = std::max(1.5, std::min(o.width, o.height) / 300.0);
  const double half_width =
      o.supersampling *
      std::clamp(0.05 * median_curve_length(net, camera, o.supersampling), 0.5, largest);
  for (const Net::Curve& c : net.curves) {
    const Rgb colour = curvature_colour(std::max(0.0, c.value), range);
    for (std::size_t k = 1; k < c.points.size(); ++k)
      painter.segment(c.points[k - 1], c.points[k], colour, half_width, 0.0);
  }
}

Image downsample(const Frame& frame, int ss, std::size_t& covered) {
  const int width = frame.width / ss, height = frame.height / ss;
  Image image(width, height);
  const int n = ss * ss;
  covered = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int sum[3] = {0, 0, 0};
      bool any = false;
      for (int sy = 0; sy < ss; ++sy)
        for (int sx = 0; sx < ss; ++sx) {
          const std::size_t i =
              std::size_t(y * ss + sy) * std::size_t(frame.width) + std::size_t(x * ss + sx);
          any = any || frame.id[i] != no_triangle;
          for (int k = 0; k < 3; ++k)
            sum[k] += frame.colour[3 * i + std::size_t(k)];
        }
      covered += any ? 1 : 0;
      image.set(x, y,
                {static_cast<std::uint8_t>((sum[0] + n / 2) / n),
                 static_cast<std::uint8_t>((sum[1] + n / 2) / n),
                 static_cast<std::uint8_t>((sum[2] + n / 2) / n)});
    }
  return image;
}

void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x)
      image.set(x, y, c);
}

// A vertical colour bar on the right: +range at the top, 0 in the middle, -range at the bottom
// (curvature), or range at the top and 0 at the bottom (jump).
void draw_colour_bar(Image& image, const Layout& layout, Mode mode, double range) {
  const int s = layout.font_scale;
  const Rgb ink{30, 30, 30};
  const int bar_w = 5 * s + 4;
  const int x0 = image.width - layout.right, x1 = x0 + bar_w;
  const int bar_h = std::max(8, image.height * 11 / 20);
  const int y0 = (image.height - bar_h) / 2, y1 = y0 + bar_h;
  fill_rect(image, x0 - 1, y0 - 1, x1 + 1, y1 + 1, ink);
  for (int y = y0; y < y1; ++y) {
    const double u = (y - y0 + 0.5) / bar_h; // 0 at the top, 1 at the bottom
    const double t = mode == Mode::Jump ? 1 - u : 1 - 2 * u;
    fill_rect(image, x0, y, x1, y + 1, curvature_colour(t * range, range));
  }
  const int text_x = x1 + 4 * s, half = internal::text_height(s) / 2;
  const Bar_labels labels = bar_labels(mode, range);
  internal::draw_text(image, text_x, y0 - half, labels.top, s, ink);
  internal::draw_text(image, text_x, (y0 + y1) / 2 - half, labels.middle, s, ink);
  internal::draw_text(image, text_x, y1 - half, labels.bottom, s, ink);
  internal::draw_text(image, x0, y0 - 3 * half - 4 * s, labels.title, s, ink);
  for (int y : {y0, (y0 + y1) / 2, y1 - 1}) // ticks
    fill_rect(image, x1, y, x1 + s + 1, y + 1, ink);
}

// The marker key below the picture: roles on one row, prescribed/propagated on the next.
void draw_net_key(Image& image, const Layout& layout, const Net* net) {
  const Legend_items items = net_legend_items(net);
  const int s = layout.font_scale;
  const int h = internal::text_height(s);
  const Rgb ink{30, 30, 30};
  const int margin = static_cast<int>(0.05 * std::min(image.width, image.height));
  int y = image.height - layout.bottom - margin / 2 + 2 * s;
  auto item = [&](int& x, const std::string& label, Rgb fill, bool square) {
    const int r = h / 2 + s;
    const int cx = x + r, cy = y + h / 2;
    for (int py = cy - r; py <= cy + r; ++py)
      for (int px = cx - r; px <= cx + r; ++px) {
        const double dx = px - cx, dy = py - cy;
        const double d = square ? std::max(std::abs(dx), std::abs(dy)) : std::hypot(dx, dy);
        if (d <= r && px >= 0 && py >= 0 && px < image.width && py < image.height)
          image.set(px, py, d > r - std::max(1, s) ? Rgb{40, 40, 40} : fill);
      }
    x += 2 * r + 2 * s;
    internal::draw_text(image, x, y, label, s, ink);
    x += internal::text_width(label, s) + 5 * s;
  };
  auto role_item = [&](int& x, Point_role r, const std::string& label, bool square) {
    if (items.role[std::size_t(r)])
      item(x, label, role_colour(r), square);
  };
  auto status_item = [&](int& x, Point_status t, const std::string& label) {
    if (items.state[std::size_t(t)])
      item(x, label, status_colour(t), false);
  };
  if (items.roles && net->status_fills) {
    int x = margin;
    role_item(x, Point_role::Corner, "CORNER", true);
    role_item(x, Point_role::Star, "STAR", false);
    status_item(x, Point_status::Prescribed, "PRESCRIBED");
    status_item(x, Point_status::Propagated, "PROPAGATED");
    return;
  }
  if (items.roles) {
    int x = margin;
    role_item(x, Point_role::Corner, "CORNER", true);
    role_item(x, Point_role::Star, "STAR", false);
    role_item(x, Point_role::Edge_middle, "EDGE-MIDDLE", false);
    role_item(x, Point_role::Inner, "INNER", false);
    y += h + 5 * s;
  }
  if (items.status) {
    int x = margin;
    item(x, "PRESCRIBED (FREE)", status_colour(Point_status::Prescribed), false);
    item(x, "PROPAGATED", status_colour(Point_status::Propagated), false);
  }
}

} // namespace

Image render(const Mesh& mesh, const Net* net, const Options& options, Report* report) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  check_mesh(mesh, options.mode);
  const Net* overlay = options.mode == Mode::Net || options.mode == Mode::Jump ? net : nullptr;

  Report r;
  r.triangles = mesh.triangles.size();
  r.has_curvature = !mesh.gaussian_curvature.empty();
  bool first = true;
  for (double k : mesh.gaussian_curvature)
    if (std::isfinite(k)) {
      r.curvature_min = first ? k : std::min(r.curvature_min, k);
      r.curvature_max = first ? k : std::max(r.curvature_max, k);
      first = false;
    }

  // Points that must fit in the picture: the mesh, and the net when it is drawn.
  std::vector<Vector> points = mesh.positions;
  if (overlay != nullptr)
    for (const Net::Point& p : overlay->points)
      points.push_back(p.position);

  if (r.has_curvature) {
    Vector lo, hi;
    bounding_box(mesh.positions, lo, hi);
    // Curvatures below 1e-6/diagonal^2 (radius of curvature 1000 diagonals) are round-off.
    const double diagonal2 = dot(hi - lo, hi - lo);
    const double floor = diagonal2 > 0 ? 1e-6 / diagonal2 : 0;
    r.curvature_range_from_user = options.curvature_range.has_value();
    r.curvature_range = options.curvature_range
                            ? *options.curvature_range
                            : robust_curvature_range(mesh.gaussian_curvature, floor);
  }

  if (options.mode == Mode::Jump) {
    first = true;
    if (overlay != nullptr)
      for (const Net::Curve& c : overlay->curves)
        if (std::isfinite(c.value)) {
          r.jump_max = first ? c.value : std::max(r.jump_max, c.value);
          first = false;
        }
    // At least one degree, so that round-off on a G^1 surface stays green.
    r.jump_range = options.jump_range ? *options.jump_range : std::max(1.0, r.jump_max);
  }

  const Layout layout =
      layout_for(options, overlay, options.mode == Mode::Jump ? r.jump_range : r.curvature_range);
  const int ss = options.supersampling;
  // Very large pictures fall back to fewer samples per pixel rather than exhausting memory.
  int samples_per_axis = ss;
  while (samples_per_axis > 1 && std::size_t(options.width) * std::size_t(options.height) *
                                         std::size_t(samples_per_axis * samples_per_axis) >
                                     max_samples)
    --samples_per_axis;
  Options o = options;
  o.supersampling = samples_per_axis;

  const Camera camera = make_camera(o, layout, points);
  std::vector<Projected> projected(mesh.positions.size());
  double q_lo = std::numeric_limits<double>::infinity(), q_hi = -q_lo;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    projected[v] = is_finite(mesh.positions[v])
                       ? camera.project(mesh.positions[v])
                       : Projected{std::numeric_limits<double>::quiet_NaN(), 0, 0};
    if (std::isfinite(projected[v].q))
      q_lo = std::min(q_lo, projected[v].q), q_hi = std::max(q_hi, projected[v].q);
  }

  Frame frame(o.width * samples_per_axis, o.height * samples_per_axis);
  r.drawn_triangles = rasterize(mesh, projected, frame);

  Lighting lighting;
  lighting.light =
      options.light
          ? normalized(*options.light)
          : normalized(-0.55 * camera.right + 0.60 * camera.up + 0.58 * camera.toward_eye);
  lighting.fill = normalized(0.6 * camera.right - 0.3 * camera.up + 0.6 * camera.toward_eye);
  lighting.isophote_is_view = !options.light.has_value();
  lighting.isophote = lighting.light;
  lighting.range = r.curvature_range;
  shade(mesh, projected, camera, o, lighting, frame);
  if (o.mode == Mode::Isophotes)
    draw_outline(frame, std::max(1, samples_per_axis / 2));
  if (overlay != nullptr) {
    const double tolerance = q_hi > q_lo ? 0.01 * (q_hi - q_lo) : 0;
    if (o.mode == Mode::Jump)
      draw_curves(*overlay, camera, o, tolerance, r.jump_range, frame);
    else
      draw_net(*overlay, camera, o, tolerance, frame);
  }

  Image image = downsample(frame, samples_per_axis, r.covered_pixels);
  if (options.legend && options.mode == Mode::Curvature && r.has_curvature)
    draw_colour_bar(image, layout, Mode::Curvature, r.curvature_range);
  if (options.legend && options.mode == Mode::Jump)
    draw_colour_bar(image, layout, Mode::Jump, r.jump_range);
  if (options.legend && options.mode == Mode::Net && overlay != nullptr)
    draw_net_key(image, layout, overlay);

  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report != nullptr)
    *report = r;
  return image;
}

} // namespace tspline::render

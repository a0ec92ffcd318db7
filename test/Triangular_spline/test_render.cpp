// Tests of the pictures (src/render): image properties that fail when the rasteriser, the
// camera, the colour conventions or the PNG encoding are wrong. Scenes are small: a flat
// square, a hemisphere, and polynomial patches tessellated with their exact curvature.

#include "render/control_net.h"

#include <CGAL/Triangular_spline/Patch_network.h>
#include "render/render.h"
#include "render/surface_mesh_adapter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace TS = CGAL::Triangular_spline;
namespace R = tspline::render;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<K::Point_3>;

const R::Rgb white{255, 255, 255};

R::Options options(R::Mode mode, int width, int height, double azimuth, double elevation) {
  R::Options o;
  o.mode = mode;
  o.width = width;
  o.height = height;
  o.azimuth = azimuth;
  o.elevation = elevation;
  o.legend = false;
  return o;
}

// The unit square [0,1]^2 at z = 0, normals up.
R::Mesh flat_square() {
  R::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals.assign(4, {0, 0, 1});
  mesh.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  return mesh;
}

// The upper unit hemisphere with exact normals, `rings` x `segments` latitude-longitude grid.
R::Mesh hemisphere(int rings, int segments) {
  const double pi = std::acos(-1.0);
  R::Mesh mesh;
  mesh.positions.push_back({0, 0, 1});
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = 0.5 * pi * i / rings, phi = 2 * pi * j / segments;
      mesh.positions.push_back(
          {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  mesh.normals = mesh.positions;
  auto id = [segments](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * segments + (j % segments));
  };
  for (int j = 0; j < segments; ++j)
    mesh.triangles.push_back({{0, id(1, j), id(1, j + 1)}});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      mesh.triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      mesh.triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return mesh;
}

// The square [-1/4, 1/4]^2 cut into 8 triangles around its centre.
TS::Planar_domain<K> small_domain() {
  std::vector<K::Point_2> points;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      points.emplace_back(0.25 * i - 0.25, 0.25 * j - 0.25);
  const std::uint32_t ring[8] = {0, 1, 2, 5, 8, 7, 6, 3};
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int k = 0; k < 8; ++k)
    triangles.push_back({{ring[k], ring[(k + 1) % 8], 4}});
  return TS::Planar_domain<K>(std::move(points), std::move(triangles));
}

// z = a x^2 + b xy + c y^2 over small_domain(), tessellated with exact curvature.
Surface_mesh quadratic_patch_mesh(double a, double b, double c) {
  TS::Polynomial_surface<K> p(2);
  p.set_coefficient(2, 0, a);
  p.set_coefficient(1, 1, b);
  p.set_coefficient(0, 2, c);
  const TS::Planar_domain<K> domain = small_domain();
  std::vector<TS::Bezier_triangle<K>> patches;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    patches.push_back(p.to_bezier(2, domain.point(t[0]), domain.point(t[1]), domain.point(t[2])));
  }
  Surface_mesh mesh;
  TS::tessellate(TS::Patch_network<K>(domain, patches), 4, mesh);
  return mesh;
}

bool is_white(R::Rgb c) {
  return c == white;
}

// With TSPLINE_RENDER_TEST_OUTPUT=DIR the test scenes are written there, to look at them.
void keep(const R::Image& image, const std::string& name) {
  if (const char* dir = std::getenv("TSPLINE_RENDER_TEST_OUTPUT"))
    R::write_png((std::filesystem::path(dir) / (name + ".png")).string(), image);
}

// Pixels that are clearly coloured (not the white background or an anti-aliased rim).
std::vector<R::Rgb> saturated_pixels(const R::Image& image, double min_saturation) {
  std::vector<R::Rgb> result;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (R::saturation(image.at(x, y)) >= min_saturation)
        result.push_back(image.at(x, y));
  return result;
}

bool contains_colour(const R::Image& image, R::Rgb colour) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y) == colour)
        return true;
  return false;
}

// Changes between black and white along row `y` from x0 to x1, ignoring grey pixels
// (anti-aliased stripe borders).
int stripe_transitions(const R::Image& image, int y, int x0, int x1) {
  int transitions = 0, last = -1;
  for (int x = x0; x <= x1; ++x) {
    const R::Rgb c = image.at(x, y);
    const int v = c.r < 60 ? 0 : (c.r > 200 ? 1 : -1);
    if (v < 0)
      continue;
    if (last >= 0 && v != last)
      ++transitions;
    last = v;
  }
  return transitions;
}

} // namespace

// ---------------------------------------------------------------------------------------
// Camera and coverage

TEST(Render, FlatSquareFromAboveFillsThePredictedRectangle) {
  // 200x100, margin 5% of 100 = 5 px: the drawing area is 190x90, the unit square is scaled
  // by 90 and centred: x in [55, 145], y in [5, 95].
  for (int samples : {1, 2, 3}) {
    R::Options o = options(R::Mode::Shaded, 200, 100, 0, 90);
    o.supersampling = samples;
    R::Report report;
    const R::Image image = R::render(flat_square(), nullptr, o, &report);
    keep(image, "square_top_" + std::to_string(samples));
    ASSERT_EQ(image.width, 200);
    ASSERT_EQ(image.height, 100);
    EXPECT_EQ(report.drawn_triangles, 2u);
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 200; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const bool inside = cx > 56 && cx < 144 && cy > 6 && cy < 94;
        const bool outside = cx < 54 || cx > 146 || cy < 4 || cy > 96;
        if (inside) {
          ASSERT_FALSE(is_white(image.at(x, y))) << "hole at " << x << "," << y;
        }
        if (outside) {
          ASSERT_TRUE(is_white(image.at(x, y))) << "ink at " << x << "," << y;
        }
      }
    EXPECT_NEAR(double(report.covered_pixels), 90.0 * 90.0, 2 * 4 * 91.0);
  }
}

TEST(Render, TopViewHasXRightAndYUp) {
  // The lower-left half of the unit square, x + y <= 1, fills the same 90x90 box as the
  // square (100x100, margin 5). Any mirror or rotation would put ink in the top-right corner.
  R::Mesh mesh = flat_square();
  mesh.triangles = {{{0, 1, 3}}};
  const R::Image image = R::render(mesh, nullptr, options(R::Mode::Shaded, 100, 100, 0, 90));
  EXPECT_FALSE(is_white(image.at(10, 89))); // (0.06, 0.06): bottom left
  EXPECT_FALSE(is_white(image.at(80, 89))); // (0.83, 0.06): bottom right
  EXPECT_FALSE(is_white(image.at(10, 20))); // (0.06, 0.83): top left
  EXPECT_TRUE(is_white(image.at(89, 10)));  // (0.94, 0.94): top right, outside
  // From the front (0, 0) the square is edge-on: nothing to draw, and no crash.
  R::Report report;
  const R::Image edge_on =
      R::render(flat_square(), nullptr, options(R::Mode::Shaded, 50, 50, 0, 0), &report);
  EXPECT_EQ(report.drawn_triangles, 0u);
  EXPECT_EQ(report.covered_pixels, 0u);
}

TEST(Render, SharedEdgesLeaveNoCracks) {
  // 128 thin triangles fanned around the centre of the unit square, which lands exactly on a
  // pixel centre (101x101: margin 5.05, scale 90.9, centre at 50.5); many edges pass exactly
  // through pixel centres. Without supersampling any crack would show as a white pixel.
  R::Mesh fan;
  fan.positions.push_back({0.5, 0.5, 0});
  const int rim = 128;
  for (int k = 0; k < rim; ++k) { // around the square's boundary, 32 points per side
    const double u = (k % 32) / 32.0;
    const int side = k / 32;
    const double x = side == 0 ? u : side == 1 ? 1 : side == 2 ? 1 - u : 0;
    const double y = side == 0 ? 0 : side == 1 ? u : side == 2 ? 1 : 1 - u;
    fan.positions.push_back({x, y, 0});
  }
  for (std::uint32_t k = 0; k < rim; ++k)
    fan.triangles.push_back({{0, 1 + k, 1 + (k + 1) % rim}});
  R::Options o = options(R::Mode::Shaded, 101, 101, 0, 90);
  o.supersampling = 1;
  const R::Image image = R::render(fan, nullptr, o);
  keep(image, "fan");
  for (int y = 7; y < 94; ++y)
    for (int x = 7; x < 94; ++x)
      ASSERT_FALSE(is_white(image.at(x, y))) << "crack at " << x << "," << y;
}

TEST(Render, PerspectiveStaysInsideTheMargin) {
  R::Options o = options(R::Mode::Shaded, 160, 120, -30, 40);
  o.perspective = true;
  R::Report report;
  const R::Image image = R::render(hemisphere(12, 24), nullptr, o, &report);
  EXPECT_GT(report.covered_pixels, 3000u);
  const int margin = 6; // 5% of 120
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x)
      if (x < margin - 1 || x > 160 - margin || y < margin - 1 || y > 120 - margin) {
        ASSERT_TRUE(is_white(image.at(x, y))) << x << "," << y;
      }
}

TEST(Render, EmptyAndDegenerateScenesGiveWhiteImages) {
  for (R::Mode mode : {R::Mode::Shaded, R::Mode::Isophotes, R::Mode::Net, R::Mode::Curvature}) {
    const R::Image image = R::render(R::Mesh(), nullptr, options(mode, 40, 30, 10, 20));
    ASSERT_EQ(image.pixels.size(), 3u * 40 * 30);
    EXPECT_FALSE(contains_colour(image, {0, 0, 0}));
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x)
        ASSERT_TRUE(is_white(image.at(x, y)));
  }
  R::Mesh point; // every vertex at one place
  point.positions.assign(3, {1, 2, 3});
  point.triangles = {{{0, 1, 2}}};
  R::Report report;
  R::render(point, nullptr, options(R::Mode::Shaded, 20, 20, 0, 90), &report);
  EXPECT_EQ(report.drawn_triangles, 0u);
  R::Mesh broken = flat_square(); // a NaN vertex removes its triangles only
  broken.positions[3] = {std::numeric_limits<double>::quiet_NaN(), 0, 0};
  R::render(broken, nullptr, options(R::Mode::Shaded, 20, 20, 0, 90), &report);
  EXPECT_EQ(report.drawn_triangles, 1u);
  EXPECT_GT(report.covered_pixels, 50u);
}

// ---------------------------------------------------------------------------------------
// Curvature colours

TEST(Render, CurvatureColourMapFollowsFang) {
  EXPECT_EQ(R::curvature_colour(0, 1), (R::Rgb{0, 255, 0}));
  EXPECT_EQ(R::curvature_colour(0.5, 1), (R::Rgb{255, 255, 0}));
  EXPECT_EQ(R::curvature_colour(1, 1), (R::Rgb{255, 0, 0}));
  EXPECT_EQ(R::curvature_colour(7, 1), (R::Rgb{255, 0, 0})); // saturates
  EXPECT_EQ(R::curvature_colour(-0.5, 1), (R::Rgb{0, 255, 255}));
  EXPECT_EQ(R::curvature_colour(-1, 1), (R::Rgb{0, 0, 255}));
  EXPECT_EQ(R::curvature_colour(std::nan(""), 1), (R::Rgb{150, 150, 150}));
  for (double t = -1; t <= 1; t += 0.125) { // hue = 120 (1 - t)
    const R::Rgb c = R::curvature_colour(3 * t, 3);
    EXPECT_NEAR(R::hue(c), 120 * (1 - t), 1.0) << t;
  }
}

TEST(Render, RobustRangeIsThe98thPercentile) {
  std::vector<double> K;
  for (int i = 1; i <= 100; ++i)
    K.push_back(i % 2 == 0 ? i : -i);
  K.push_back(std::nan(""));
  EXPECT_DOUBLE_EQ(R::robust_curvature_range(K, 0), 98.0);
  EXPECT_DOUBLE_EQ(R::robust_curvature_range({1e-17, -1e-17}, 1e-6), 1e-6); // round-off
  EXPECT_DOUBLE_EQ(R::robust_curvature_range({}, 0), 1.0);
}

TEST(Render, SphereLikeCapIsYellowToRed) {
  // z = -(x^2 + y^2)/2: K = 1/(1 + x^2 + y^2)^2 in [0.79, 1] on [-1/4, 1/4]^2, so with the
  // 98th-percentile scale every colour has t >= 0.79: hue <= 26 degrees (60 is yellow).
  const Surface_mesh mesh = quadratic_patch_mesh(-0.5, 0, -0.5);
  R::Report report;
  const R::Image image = R::render(R::to_render_mesh(mesh), nullptr,
                                   options(R::Mode::Curvature, 160, 120, -30, 50), &report);
  keep(image, "cap_curvature");
  EXPECT_GT(report.curvature_min, 0.79);
  EXPECT_LE(report.curvature_max, 1.0 + 1e-9);
  const auto pixels = saturated_pixels(image, 0.3);
  ASSERT_GT(pixels.size(), 4000u);
  for (const R::Rgb c : pixels) {
    const double h = R::hue(c);
    ASSERT_TRUE(h <= 60) << "hue " << h << " (" << int(c.r) << "," << int(c.g) << "," << int(c.b)
                         << ")";
  }
}

TEST(Render, SaddleIsCyanToBlue) {
  // z = xy: K = -1/(1 + x^2 + y^2)^2 in [-1, -0.79]: hue >= 214 degrees (180 is cyan).
  const Surface_mesh mesh = quadratic_patch_mesh(0, 1, 0);
  R::Report report;
  const R::Image image = R::render(R::to_render_mesh(mesh), nullptr,
                                   options(R::Mode::Curvature, 160, 120, -30, 50), &report);
  keep(image, "saddle_curvature");
  EXPECT_LT(report.curvature_max, -0.79);
  const auto pixels = saturated_pixels(image, 0.3);
  ASSERT_GT(pixels.size(), 4000u);
  for (const R::Rgb c : pixels) {
    const double h = R::hue(c);
    ASSERT_TRUE(h >= 180 && h <= 240) << "hue " << h;
  }
  // A parabolic cylinder z = x^2 has K = 0: all green.
  const R::Image flat = R::render(R::to_render_mesh(quadratic_patch_mesh(1, 0, 0)), nullptr,
                                  options(R::Mode::Curvature, 160, 120, -30, 50));
  for (const R::Rgb c : saturated_pixels(flat, 0.3))
    ASSERT_NEAR(R::hue(c), 120, 2);
}

TEST(Render, CurvatureLegendShowsTheColourBar) {
  const Surface_mesh mesh = quadratic_patch_mesh(0, 1, 0);
  R::Options o = options(R::Mode::Curvature, 320, 240, -30, 50);
  o.legend = true;
  o.curvature_range = 2.0; // the saddle's |K| <= 1: blue-cyan only, never red on the surface
  const R::Image image = R::render(R::to_render_mesh(mesh), nullptr, o);
  keep(image, "saddle_legend");
  bool red = false, dark_text = false;
  for (int y = 0; y < image.height; ++y)
    for (int x = image.width * 3 / 4; x < image.width; ++x) {
      const R::Rgb c = image.at(x, y);
      red = red || (c.r > 240 && c.g < 20 && c.b < 20);
      dark_text = dark_text || (c.r < 50 && c.g < 50 && c.b < 50);
    }
  EXPECT_TRUE(red);
  EXPECT_TRUE(dark_text);
}

// ---------------------------------------------------------------------------------------
// Isophotes

TEST(Render, IsophotesOfAHemisphereHaveTheExpectedStripes) {
  // Seen from above, |n.e| = cos(theta) = sqrt(1 - r^2). The row through the centre of a
  // 240x240 picture (radius 108 px) is scanned up to 3 px from the rim, where |n.e| =
  // s_min = sqrt(1 - (105/108)^2): every band above s_min is crossed twice, the top band
  // (white, facing the eye) once. Bands thinner than a pixel may merge: allow 2 fewer.
  const R::Mesh sphere = hemisphere(64, 128);
  const double s_min = std::sqrt(1 - (105.0 / 108) * (105.0 / 108));
  int previous = 0;
  for (int bands : {3, 6, 10}) {
    R::Options o = options(R::Mode::Isophotes, 240, 240, 0, 90);
    o.bands = bands;
    const R::Image image = R::render(sphere, nullptr, o);
    keep(image, "hemisphere_isophotes_" + std::to_string(bands));
    EXPECT_TRUE(contains_colour(image, {0, 0, 0}));
    const int crossed = bands - static_cast<int>(std::floor(s_min * bands));
    const int transitions = stripe_transitions(image, 120, 120 - 105, 120 + 105);
    EXPECT_LE(transitions, 2 * crossed - 2) << bands;
    EXPECT_GE(transitions, 2 * crossed - 4) << bands;
    EXPECT_GT(transitions, previous);
    previous = transitions;
    EXPECT_TRUE(is_white(image.at(120, 120)));
  }
}

// ---------------------------------------------------------------------------------------
// Control nets

TEST(Render, ControlNetOfOnePatchAndTwoPatches) {
  TS::Polynomial_surface<K> p(5);
  p.set_coefficient(1, 1, 2.0);
  const K::Point_2 r(0, 0), s(1, 0), t(0, 1), u(1, 1);
  const std::vector<TS::Bezier_triangle<K>> patches{p.to_bezier(5, r, s, t),
                                                    p.to_bezier(5, s, u, t)};
  const TS::Patch_network<K> single(TS::Planar_domain<K>({r, s, t}, {{{0, 1, 2}}}), {patches[0]});
  const TS::Patch_network<K> both(TS::Planar_domain<K>({r, s, t, u}, {{{0, 1, 2}}, {{1, 3, 2}}}),
                                  patches);
  const R::Net one = R::control_net(single);
  ASSERT_EQ(one.points.size(), 21u);
  EXPECT_EQ(one.segments.size(), 45u);
  int roles[4] = {0, 0, 0, 0};
  for (const auto& point : one.points) {
    ++roles[static_cast<int>(point.role)];
    EXPECT_EQ(point.status, R::Point_status::Unknown);
  }
  EXPECT_EQ(roles[0], 3); // corners
  EXPECT_EQ(roles[1], 6); // stars
  EXPECT_EQ(roles[2], 6); // edge-middle
  EXPECT_EQ(roles[3], 6); // inner
  // b_{2,2,1} over (r, s, t) sits at (2r + 2s + t)/5 = (0.4, 0.2), at height b_221.
  const TS::Multi_index index{2, 2, 1};
  const R::Vector expected{0.4, 0.2, patches[0].control_point(index)};
  bool found = false;
  for (const auto& point : one.points)
    found = found ||
            (std::abs(point.position[0] - expected[0]) < 1e-15 &&
             std::abs(point.position[1] - expected[1]) < 1e-15 && point.position[2] == expected[2]);
  EXPECT_TRUE(found);
  // The shared edge's 6 points and 5 segments appear once.
  const R::Net two = R::control_net(both);
  EXPECT_EQ(two.points.size(), 36u);
  EXPECT_EQ(two.segments.size(), 85u);
  // A status callback is used as given.
  const R::Net known = R::control_net(single, [](std::size_t, const TS::Multi_index& i) {
    return i.i == 5 ? R::Point_status::Prescribed : R::Point_status::Propagated;
  });
  int prescribed = 0;
  for (const auto& point : known.points)
    prescribed += point.status == R::Point_status::Prescribed ? 1 : 0;
  EXPECT_EQ(prescribed, 1);
}

TEST(Render, NetModeDrawsPrescribedAndPropagatedColours) {
  R::Net net;
  net.points.push_back({{0.25, 0.5, 0.1}, R::Point_role::Star, R::Point_status::Prescribed});
  net.points.push_back({{0.75, 0.5, 0.1}, R::Point_role::Inner, R::Point_status::Propagated});
  net.segments.push_back({{{0.25, 0.5, 0.1}, {0.75, 0.5, 0.1}}});
  R::Options o = options(R::Mode::Net, 450, 450, 0, 90);
  const R::Image image = R::render(flat_square(), &net, o);
  keep(image, "net_two_points");
  EXPECT_TRUE(contains_colour(image, R::status_colour(R::Point_status::Prescribed)));
  EXPECT_TRUE(contains_colour(image, R::status_colour(R::Point_status::Propagated)));
  EXPECT_TRUE(contains_colour(image, R::role_colour(R::Point_role::Star)));
  EXPECT_TRUE(contains_colour(image, R::role_colour(R::Point_role::Inner)));
  // Below the surface the same points are drawn faint: their exact colours disappear.
  for (auto& point : net.points)
    point.position[2] = -0.1;
  net.segments.clear();
  const R::Image hidden = R::render(flat_square(), &net, o);
  EXPECT_FALSE(contains_colour(hidden, R::status_colour(R::Point_status::Prescribed)));
  EXPECT_FALSE(contains_colour(hidden, R::status_colour(R::Point_status::Propagated)));
  // Other modes ignore the net.
  const R::Image shaded = R::render(flat_square(), &net, options(R::Mode::Shaded, 450, 450, 0, 90));
  EXPECT_FALSE(contains_colour(shaded, R::role_colour(R::Point_role::Star)));
}

TEST(Render, StatusFillsUseXusColours) {
  // Fig. 6.9: corners and stars keep their role colours, the other points are filled with
  // their status colour (no ring, so the role colour of an inner point does not appear).
  R::Net net;
  net.points.push_back({{0.2, 0.5, 0.1}, R::Point_role::Corner, R::Point_status::Unknown});
  net.points.push_back({{0.4, 0.5, 0.1}, R::Point_role::Star, R::Point_status::Prescribed});
  net.points.push_back({{0.6, 0.5, 0.1}, R::Point_role::Inner, R::Point_status::Prescribed});
  net.points.push_back({{0.8, 0.5, 0.1}, R::Point_role::Edge_middle, R::Point_status::Propagated});
  net.status_fills = true;
  R::Options o = options(R::Mode::Net, 450, 450, 0, 90);
  const R::Image image = R::render(flat_square(), &net, o);
  keep(image, "net_status_fills");
  EXPECT_TRUE(contains_colour(image, R::role_colour(R::Point_role::Corner)));
  EXPECT_TRUE(contains_colour(image, R::role_colour(R::Point_role::Star)));
  EXPECT_TRUE(contains_colour(image, R::status_colour(R::Point_status::Prescribed)));
  EXPECT_TRUE(contains_colour(image, R::status_colour(R::Point_status::Propagated)));
  EXPECT_FALSE(contains_colour(image, R::role_colour(R::Point_role::Inner)));
  EXPECT_FALSE(contains_colour(image, R::role_colour(R::Point_role::Edge_middle)));
}

TEST(Render, JumpModeColoursCurvesByValue) {
  // Two curves across the square, 0 and 2 degrees: green and (at the default range, the
  // largest value but at least 1) red; a hidden curve is not drawn at all.
  R::Net net;
  net.curves.push_back({{{0.1, 0.3, 0}, {0.5, 0.3, 0}, {0.9, 0.3, 0}}, 0.0});
  net.curves.push_back({{{0.1, 0.7, 0}, {0.9, 0.7, 0}}, 2.0});
  R::Options o = options(R::Mode::Jump, 400, 400, 0, 90);
  R::Report report;
  const R::Image image = R::render(flat_square(), &net, o, &report);
  keep(image, "jump_two_curves");
  // 400x400, margin 20: the square spans pixels 20..380, y = 0.3 on row 20 + 0.7 * 360 = 272.
  EXPECT_DOUBLE_EQ(report.jump_max, 2.0);
  EXPECT_DOUBLE_EQ(report.jump_range, 2.0);
  EXPECT_TRUE(contains_colour(image, R::curvature_colour(0, 1))); // green
  EXPECT_TRUE(contains_colour(image, R::curvature_colour(1, 1))); // red
  EXPECT_EQ(image.at(200, 272), R::curvature_colour(0, 1));       // x = 0.5, y = 0.3
  EXPECT_EQ(image.at(200, 128), R::curvature_colour(1, 1));       // y = 0.7
  o.jump_range = 4.0;                                             // 2 of 4 degrees: yellow
  EXPECT_EQ(R::render(flat_square(), &net, o).at(200, 128), R::curvature_colour(2, 4));
  // The surface is shaded as in Mode::Shaded away from the curves.
  const R::Image shaded =
      R::render(flat_square(), nullptr, options(R::Mode::Shaded, 400, 400, 0, 90));
  EXPECT_EQ(image.at(200, 200), shaded.at(200, 200));
  for (auto& curve : net.curves)
    for (auto& p : curve.points)
      p[2] = -0.1;
  const R::Image hidden = R::render(flat_square(), &net, options(R::Mode::Jump, 400, 400, 0, 90));
  EXPECT_EQ(hidden.pixels, shaded.pixels);
  // The legend is a colour bar from 0 (green, bottom) to the range (red, top).
  o.legend = true;
  o.jump_range.reset();
  const R::Image legend = R::render(flat_square(), &net, o);
  keep(legend, "jump_legend");
  bool red = false, green = false;
  for (int y = 0; y < legend.height; ++y)
    for (int x = legend.width * 3 / 4; x < legend.width; ++x) {
      const R::Rgb c = legend.at(x, y);
      red = red || (c.r > 240 && c.g < 20 && c.b < 20);
      green = green || (c.g > 240 && c.r < 20 && c.b < 20);
    }
  EXPECT_TRUE(red);
  EXPECT_TRUE(green);
}

// ---------------------------------------------------------------------------------------
// Determinism, PNG, adapters, errors

TEST(Render, ImagesAndPngBytesAreDeterministic) {
  const R::Mesh cap = R::to_render_mesh(quadratic_patch_mesh(-0.5, 0.2, -0.3));
  for (R::Mode mode : {R::Mode::Shaded, R::Mode::Curvature, R::Mode::Isophotes}) {
    R::Options o = options(mode, 120, 90, -30, 40);
    o.legend = true;
    o.perspective = mode == R::Mode::Isophotes;
    const R::Image a = R::render(cap, nullptr, o), b = R::render(cap, nullptr, o);
    ASSERT_EQ(a.pixels, b.pixels) << R::mode_name(mode);
    EXPECT_EQ(R::encode_png(a), R::encode_png(b));
  }
}

TEST(Render, PngRoundTrip) {
  R::Image image(7, 5);
  image.set(0, 0, {1, 2, 3});
  image.set(6, 4, {250, 0, 128});
  image.set(3, 2, {0, 0, 0});
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "tspline_test_render_round_trip.png";
  R::write_png(path.string(), image);
  const R::Image back = R::read_png(path.string());
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.at(0, 0), (R::Rgb{1, 2, 3}));
  EXPECT_EQ(back.at(6, 4), (R::Rgb{250, 0, 128}));
  EXPECT_EQ(back.at(1, 1), white);
  EXPECT_EQ(back.pixels, image.pixels);
  std::filesystem::remove(path);

  const std::filesystem::path text =
      std::filesystem::temp_directory_path() / "tspline_test_render_not_a.png";
  std::ofstream(text) << "not a PNG\n";
  EXPECT_THROW(R::read_png(text.string()), std::runtime_error);
  std::filesystem::remove(text);
  EXPECT_THROW(R::read_png("/nonexistent/x.png"), std::runtime_error);
  EXPECT_THROW(R::write_png("/nonexistent/dir/x.png", image), std::runtime_error);
  EXPECT_THROW(R::encode_png(R::Image()), std::invalid_argument);
}

TEST(Render, SurfaceMeshAdapterAndColouredPly) {
  Surface_mesh mesh = quadratic_patch_mesh(-0.5, 0, -0.5);
  const R::Mesh plain = R::to_render_mesh(mesh);
  EXPECT_EQ(plain.positions.size(), mesh.number_of_vertices());
  EXPECT_EQ(plain.triangles.size(), mesh.number_of_faces());
  EXPECT_EQ(plain.normals.size(), plain.positions.size());
  EXPECT_EQ(plain.gaussian_curvature.size(), plain.positions.size());

  // A quad without normals: two triangles, normals estimated by PMP (unit, pointing up).
  Surface_mesh quad;
  const auto a = quad.add_vertex({0, 0, 0}), b = quad.add_vertex({1, 0, 0}),
             c = quad.add_vertex({1, 1, 0}), d = quad.add_vertex({0, 1, 0});
  quad.add_face(a, b, c, d);
  const R::Mesh fan = R::to_render_mesh(quad);
  EXPECT_EQ(fan.triangles.size(), 2u);
  ASSERT_EQ(fan.normals.size(), 4u);
  for (const auto& n : fan.normals)
    EXPECT_NEAR(n[2], 1.0, 1e-12);
  EXPECT_TRUE(fan.gaussian_curvature.empty());
  EXPECT_FALSE(R::add_curvature_colours(quad, 1.0));

  ASSERT_TRUE(R::add_curvature_colours(mesh, 2.0));
  const auto colours =
      mesh.property_map<Surface_mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  const auto curvature =
      mesh.property_map<Surface_mesh::Vertex_index, double>("v:gaussian_curvature").first;
  for (auto v : mesh.vertices()) {
    const R::Rgb expected = R::curvature_colour(curvature[v], 2.0);
    ASSERT_EQ(colours[v].red(), expected.r);
    ASSERT_EQ(colours[v].green(), expected.g);
    ASSERT_EQ(colours[v].blue(), expected.b);
  }
}

TEST(Render, BadArgumentsAreRejected) {
  const R::Mesh square = flat_square();
  auto bad = [&square](auto change) {
    R::Options o = options(R::Mode::Shaded, 10, 10, 0, 90);
    change(o);
    EXPECT_THROW(R::render(square, nullptr, o), std::invalid_argument);
  };
  bad([](R::Options& o) { o.width = 0; });
  bad([](R::Options& o) { o.height = 20000; });
  bad([](R::Options& o) { o.width = 16384, o.height = 16384; }); // too many pixels
  bad([](R::Options& o) { o.supersampling = 5; });
  bad([](R::Options& o) { o.bands = 0; });
  bad([](R::Options& o) { o.azimuth = std::nan(""); });
  bad([](R::Options& o) { o.elevation = std::numeric_limits<double>::infinity(); });
  bad([](R::Options& o) { o.curvature_range = -1.0; });
  bad([](R::Options& o) { o.light = R::Vector{0, 0, 0}; });
  bad([](R::Options& o) { o.mode = R::Mode::Curvature; }); // the square has no curvature
  R::Mesh wrong = square;
  wrong.triangles.push_back({{0, 1, 4}});
  EXPECT_THROW(R::render(wrong, nullptr, R::Options()), std::invalid_argument);
  wrong = square;
  wrong.normals.pop_back();
  EXPECT_THROW(R::render(wrong, nullptr, R::Options()), std::invalid_argument);
  wrong = square;
  wrong.gaussian_curvature = {0.0};
  EXPECT_THROW(R::render(wrong, nullptr, R::Options()), std::invalid_argument);
  EXPECT_THROW(R::parse_mode("wireframe"), std::invalid_argument);
  EXPECT_EQ(R::parse_mode("isophotes"), R::Mode::Isophotes);
  EXPECT_EQ(R::parse_mode("jump"), R::Mode::Jump);
  bad([](R::Options& o) { o.jump_range = 0.0; });
}

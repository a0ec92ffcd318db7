// Rendering cost (src/render): the demo surface (Xu's C^1 spline over the embedded L-shaped
// domain, 256 patches, double kernel) tessellated at level 6 = 1,048,576 triangles, drawn at
// 1920x1080. Reported: triangles per second of render() (rasterisation, shading, box filter)
// for 2x2 and 1x1 samples per pixel, the curvature and isophote modes, the conversion from
// Surface_mesh, and PNG encoding.
#include "render/render.h"
#include "render/surface_mesh_adapter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/demo_data.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <benchmark/benchmark.h>

namespace TS = CGAL::Triangular_spline;
namespace R = tspline::render;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

const Mesh& surface() {
  static const Mesh mesh = [] {
    auto [domain, heights] = TS::demo_data<K>();
    TS::C1_quintic_spline<K> spline(std::move(domain));
    TS::fit_vertex_data(spline, heights, TS::Fit::APPROXIMATE);
    Mesh result;
    TS::tessellate(spline, 6, result);
    return result;
  }();
  return mesh;
}

const R::Mesh& plain() {
  static const R::Mesh mesh = R::to_render_mesh(surface());
  return mesh;
}

void render(benchmark::State& state, R::Mode mode, int samples) {
  R::Options options;
  options.mode = mode;
  options.width = 1920;
  options.height = 1080;
  options.azimuth = -20;
  options.elevation = 60;
  options.supersampling = samples;
  const R::Mesh& mesh = plain();
  R::Report report;
  for (auto _ : state) {
    R::Image image = R::render(mesh, nullptr, options, &report);
    benchmark::DoNotOptimize(image.pixels.data());
  }
  state.counters["triangles"] = double(mesh.triangles.size());
  state.counters["covered_pixels"] = double(report.covered_pixels);
  state.counters["triangles_per_second"] = benchmark::Counter(
      double(mesh.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_render_shaded_1920x1080_2x2(benchmark::State& state) {
  render(state, R::Mode::Shaded, 2);
}
void BM_render_shaded_1920x1080_1x1(benchmark::State& state) {
  render(state, R::Mode::Shaded, 1);
}
void BM_render_curvature_1920x1080_2x2(benchmark::State& state) {
  render(state, R::Mode::Curvature, 2);
}
void BM_render_isophotes_1920x1080_2x2(benchmark::State& state) {
  render(state, R::Mode::Isophotes, 2);
}

void BM_surface_mesh_to_render_mesh(benchmark::State& state) {
  const Mesh& mesh = surface();
  for (auto _ : state) {
    R::Mesh converted = R::to_render_mesh(mesh);
    benchmark::DoNotOptimize(converted.positions.data());
  }
  state.counters["triangles_per_second"] = benchmark::Counter(
      double(mesh.number_of_faces()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_encode_png_1920x1080(benchmark::State& state) {
  R::Options options;
  options.width = 1920;
  options.height = 1080;
  const R::Image image = R::render(plain(), nullptr, options);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::vector<std::uint8_t> png = R::encode_png(image);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  state.counters["png_bytes"] = double(bytes);
}

} // namespace

BENCHMARK(BM_render_shaded_1920x1080_2x2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_render_shaded_1920x1080_1x1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_render_curvature_1920x1080_2x2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_render_isophotes_1920x1080_2x2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_surface_mesh_to_render_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_encode_png_1920x1080)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

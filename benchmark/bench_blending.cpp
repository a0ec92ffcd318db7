// Costs of Fang's generalized blending (issue 5): evaluation cost per surface point (values,
// and values with first and second derivatives by jets) for d = 0, 1, 2 and the three
// variants on the pentakis icosidodecahedron (80 triangles) and the quadrangular torus
// (multi-sided faces); build and build + tessellate times for the 8x8 Franke grid and the
// triangular torus at resolution 8.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Surface = TS::Mesh_blending_surface<Point_3>;

namespace {

const Mesh& test_mesh(const std::string& name) {
  static std::vector<std::pair<std::string, Mesh>> cache;
  for (const auto& [n, m] : cache)
    if (n == name)
      return m;
  cache.emplace_back(name, TS::blending_test_mesh<Point_3>(name));
  return cache.back().second;
}

TS::Blending_variant variant_of(int v) {
  return v == 0   ? TS::Blending_variant::BASIC
         : v == 1 ? TS::Blending_variant::VERTEX_CONTINUITY
                  : TS::Blending_variant::OPEN_SET;
}

// Interior sample points of every face (a fixed set, cycled through).
std::vector<std::pair<std::size_t, std::array<double, 2>>> sample_points(const Surface& s) {
  std::vector<std::pair<std::size_t, std::array<double, 2>>> points;
  for (std::size_t f = 0; f < s.number_of_faces(); ++f) {
    const std::size_t n = s.face_size(f);
    for (const std::array<double, 2>& w :
         {std::array<double, 2>{0.2, 0.3}, {0.6, 0.1}, {0.25, 0.5}}) {
      if (n == 3) {
        points.push_back({f, w});
      } else {
        const auto& a = s.corner_parameter(f, 0);
        const auto& b = s.corner_parameter(f, 1);
        points.push_back({f, {{w[0] * a[0] + w[1] * b[0], w[0] * a[1] + w[1] * b[1]}}});
      }
    }
  }
  return points;
}

// args: mesh (0 pentakis, 1 quad_torus), order d, variant, derivatives (0: value, 1: jets
// of order 2)
void BM_evaluate(benchmark::State& state) {
  const Mesh& mesh = test_mesh(state.range(0) == 0 ? "pentakis" : "quad_torus");
  TS::Mesh_blending_options options;
  options.order = static_cast<int>(state.range(1));
  options.variant = variant_of(static_cast<int>(state.range(2)));
  const Surface surface(mesh, options);
  const auto points = sample_points(surface);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [f, p] = points[i++ % points.size()];
    if (state.range(3) == 0) {
      benchmark::DoNotOptimize(surface.face_surface(f, p[0], p[1]));
    } else {
      benchmark::DoNotOptimize(surface.derivatives(f, p[0], p[1]));
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel(std::string(state.range(0) == 0 ? "pentakis" : "quad_torus") +
                 " d=" + std::to_string(options.order) + " " + TS::to_string(options.variant) +
                 (state.range(3) == 0 ? " value" : " value+2nd derivatives"));
}
BENCHMARK(BM_evaluate)
    ->ArgsProduct({{0, 1}, {0, 1, 2}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// args: mesh (0 franke8, 1 torus), tessellate (0/1), vertex surfaces (0 least, 2 normals);
// open variant, d = 2, resolution 8
void BM_build_and_tessellate(benchmark::State& state) {
  const std::string name = state.range(0) == 0 ? "franke8" : "torus";
  const Mesh& mesh = test_mesh(name);
  TS::Mesh_blending_options options;
  options.vertex_surface = static_cast<TS::Vertex_surface_method>(state.range(2));
  std::size_t triangles = 0;
  for (auto _ : state) {
    const Surface surface(mesh, options);
    if (state.range(1) == 1) {
      Mesh out;
      triangles = surface.tessellate(out, 8).faces;
      benchmark::DoNotOptimize(out.number_of_vertices());
    } else {
      benchmark::DoNotOptimize(surface.number_of_faces());
    }
  }
  state.SetLabel(name +
                 (state.range(1) == 1 ? " build+tessellate (resolution 8, " +
                                            std::to_string(triangles) + " triangles)"
                                      : " build") +
                 (state.range(2) == 0 ? ", least vertex surfaces" : ", normals vertex surfaces"));
}
BENCHMARK(BM_build_and_tessellate)
    ->ArgsProduct({{0, 1}, {0, 1}, {0, 2}})
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

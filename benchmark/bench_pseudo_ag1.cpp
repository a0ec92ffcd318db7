// Costs of Xu's pseudo-AG^1 surfaces (issue 11, AG1.md C29 "linear time"): construction in
// double (thesis preset) and exactly (exact preset), the certificate, the normal-jump
// measures and the watertight tessellation, on the icosahedron subdivided k times on the
// unit sphere (20 * 4^k faces: 1280 ... 327680). The counter faces/s should stay constant
// within 2x across sizes if the construction is linear.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <benchmark/benchmark.h>

#include <map>

namespace TS = CGAL::Triangular_spline;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

namespace {

template <class K>
const CGAL::Surface_mesh<typename K::Point_3>& sphere(int k) {
  static std::map<int, CGAL::Surface_mesh<typename K::Point_3>> cache;
  auto it = cache.find(k);
  if (it == cache.end()) {
    TS::Blending_mesh_data data = TS::internal::icosahedron_data(1);
    for (int i = 0; i < k; ++i)
      data = TS::internal::subdivided_on_sphere(data, 1);
    data.normals.clear();
    it = cache.emplace(k, TS::to_surface_mesh<typename K::Point_3>(data)).first;
  }
  return it->second;
}

void set_faces_per_second(benchmark::State& state, std::size_t faces) {
  state.counters["faces"] = double(faces);
  state.counters["faces/s"] =
      benchmark::Counter(double(faces) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_build_thesis(benchmark::State& state) {
  const auto& mesh = sphere<Epick>(int(state.range(0)));
  for (auto _ : state) {
    TS::Pseudo_AG1_surface<Epick> s(mesh);
    benchmark::DoNotOptimize(s.corner_plane(*s.mesh().vertices().begin()).corner);
  }
  set_faces_per_second(state, mesh.number_of_faces());
}
BENCHMARK(BM_build_thesis)->DenseRange(3, 7)->Unit(benchmark::kMillisecond);

void BM_build_exact(benchmark::State& state) {
  const auto& mesh = sphere<Exact>(int(state.range(0)));
  for (auto _ : state) {
    TS::Pseudo_AG1_surface<Exact> s(mesh, TS::Pseudo_AG1_options::exact());
    benchmark::DoNotOptimize(s.is_exact());
  }
  set_faces_per_second(state, mesh.number_of_faces());
}
BENCHMARK(BM_build_exact)->DenseRange(2, 4)->Unit(benchmark::kMillisecond);

void BM_certify_exact(benchmark::State& state) {
  const TS::Pseudo_AG1_surface<Exact> s(sphere<Exact>(int(state.range(0))),
                                        TS::Pseudo_AG1_options::exact());
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::certify_pseudo_AG1(s).middle_edges);
  set_faces_per_second(state, s.mesh().number_of_faces());
}
BENCHMARK(BM_certify_exact)->DenseRange(2, 4)->Unit(benchmark::kMillisecond);

void BM_certify_double(benchmark::State& state) {
  const TS::Pseudo_AG1_surface<Epick> s(sphere<Epick>(int(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::certify_pseudo_AG1(s).middle_edges);
  set_faces_per_second(state, s.mesh().number_of_faces());
}
BENCHMARK(BM_certify_double)->DenseRange(3, 6)->Unit(benchmark::kMillisecond);

// 15 samples per edge, shape on a level-1 tessellation, no self-intersection test
void BM_measure(benchmark::State& state) {
  const TS::Pseudo_AG1_surface<Epick> s(sphere<Epick>(int(state.range(0))));
  const TS::Patch_sampler<TS::Pseudo_AG1_surface<Epick>> sampler(s);
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::measure_closed_surface(s.mesh(), sampler, 15, 1, false));
  set_faces_per_second(state, s.mesh().number_of_faces());
}
BENCHMARK(BM_measure)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);

void BM_tessellate_level2(benchmark::State& state) {
  const TS::Pseudo_AG1_surface<Epick> s(sphere<Epick>(int(state.range(0))));
  const TS::Patch_sampler<TS::Pseudo_AG1_surface<Epick>> sampler(s);
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::tessellate_closed_surface(s.mesh(), sampler, 2));
  set_faces_per_second(state, s.mesh().number_of_faces());
}
BENCHMARK(BM_tessellate_level2)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

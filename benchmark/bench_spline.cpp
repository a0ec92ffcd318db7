// Xu's C^1 quintic spline at scale: domain construction, plan, propagation (double, 10^6
// triangles), exact build + certification (10^5 triangles), local edit latency, memory.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

namespace {

// A jittered n x n grid, cells split by one diagonal: 2 n^2 triangles, generic geometry.
// Jitter is a multiple of 1/64 so the exact kernel sees the same small rationals.
template <class K>
TS::Planar_domain<K> jittered_grid(int n) {
  using FT = typename K::FT;
  std::mt19937 engine(1);
  std::uniform_int_distribution<int> jitter(-12, 12);
  std::vector<typename K::Point_2> points;
  points.reserve(std::size_t(n + 1) * std::size_t(n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border_x = i == 0 || i == n, border_y = j == 0 || j == n;
      points.emplace_back(FT(i) + (border_x ? FT(0) : FT(jitter(engine)) / FT(64)),
                          FT(j) + (border_y ? FT(0) : FT(jitter(engine)) / FT(64)));
    }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(2 * std::size_t(n) * std::size_t(n));
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return TS::Planar_domain<K>(std::move(points), std::move(triangles));
}

template <class K>
std::vector<typename K::FT> heights(const TS::Planar_domain<K>& domain) {
  std::vector<typename K::FT> z;
  for (const auto& p : domain.points())
    z.push_back(typename K::FT(std::sin(CGAL::to_double(p.x()) * 0.1) *
                               std::cos(CGAL::to_double(p.y()) * 0.07)));
  return z;
}

void BM_double_domain(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(jittered_grid<Fast>(n));
  state.counters["faces"] = 2.0 * n * n;
}

void BM_double_plan(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto domain = jittered_grid<Fast>(n);
  for (auto _ : state) {
    state.PauseTiming();
    auto copy = domain; // the spline takes its domain by value: move it in, as users do
    state.ResumeTiming();
    benchmark::DoNotOptimize(TS::C1_quintic_spline<Fast>(std::move(copy)));
  }
  state.counters["faces"] = 2.0 * n * n;
}

void BM_double_fit_and_propagate(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  TS::C1_quintic_spline<Fast> spline(jittered_grid<Fast>(n));
  const auto z = heights(spline.domain());
  for (auto _ : state)
    TS::fit_vertex_data(spline, z, TS::Fit::APPROXIMATE);
  const double faces = 2.0 * n * n;
  state.counters["faces"] = faces;
  state.counters["slots_per_face"] = double(spline.number_of_slots()) / faces;
  state.counters["rules_per_face"] = double(spline.number_of_rules()) / faces;
  state.counters["MB_values"] = double(spline.number_of_slots() * sizeof(double)) / 1e6;
  // one 32-bit reference per rule; the few stored rules of re-routed frames are left out
  state.counters["MB_rules"] = double(spline.number_of_rules() * sizeof(std::uint32_t)) / 1e6;
}

void BM_double_certify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  TS::C1_quintic_spline<Fast> spline(jittered_grid<Fast>(n));
  TS::fit_vertex_data(spline, heights(spline.domain()), TS::Fit::APPROXIMATE);
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::certify_continuity(spline, 1));
  state.counters["faces"] = 2.0 * n * n;
}

void BM_exact_build_and_certify(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto domain = jittered_grid<Exact>(n);
  const auto z = heights(domain);
  bool certified = false;
  for (auto _ : state) {
    TS::C1_quintic_spline<Exact> spline(domain);
    TS::fit_vertex_data(spline, z, TS::Fit::APPROXIMATE);
    certified = TS::certify_continuity(spline, 1).certified;
  }
  state.counters["faces"] = 2.0 * n * n;
  state.counters["certified"] = certified ? 1 : 0;
}

void BM_local_edit(benchmark::State& state) {
  TS::C1_quintic_spline<Fast> spline(jittered_grid<Fast>(300));
  TS::fit_vertex_data(spline, heights(spline.domain()), TS::Fit::APPROXIMATE);
  const auto range = spline.free_slots();
  const std::vector<TS::C1_quintic_spline<Fast>::Slot> free(range.begin(), range.end());
  std::size_t i = 0;
  std::size_t changed = 0;
  for (auto _ : state) {
    const auto s = free[(i * 7919) % free.size()];
    changed += spline.edit(s, spline.value(s) + 0.01).size();
    ++i;
  }
  state.counters["slots_changed_per_edit"] = double(changed) / double(i);
}

} // namespace

BENCHMARK(BM_double_domain)->Arg(707)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_double_plan)->Arg(707)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_double_fit_and_propagate)->Arg(707)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_double_certify)->Arg(707)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_exact_build_and_certify)->Arg(224)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_local_edit)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();

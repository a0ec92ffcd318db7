// Scattered data at scale: Delaunay triangulation (CGAL) and C^1 spline build from N points,
// timed separately, on points from a 64-bit LCG that benchmark/compare_scipy.py reproduces
// exactly, so scipy's CloughTocher2DInterpolator is timed on the same points.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

// x_{k+1} = a x_k + c mod 2^64; the top 53 bits give a double in [0, 1).
class Lcg {
public:
  double next() {
    m_state = m_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(m_state >> 11) * (1.0 / 9007199254740992.0);
  }

private:
  std::uint64_t m_state = 20261122;
};

TS::Scattered_data<K> scattered(std::size_t n) {
  Lcg lcg;
  TS::Scattered_data<K> data;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = lcg.next(), y = lcg.next();
    data.points.emplace_back(x, y);
    data.values.push_back(std::sin(6 * x) * std::cos(5 * y));
  }
  return data;
}

void BM_delaunay(benchmark::State& state) {
  const auto data = scattered(std::size_t(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::delaunay_domain(data));
}

void BM_spline_from_triangulation(benchmark::State& state) {
  const auto data = scattered(std::size_t(state.range(0)));
  const auto [domain, values] = TS::delaunay_domain(data);
  for (auto _ : state) {
    state.PauseTiming();
    auto copy = domain;
    state.ResumeTiming();
    TS::C1_quintic_spline<K> spline(std::move(copy));
    TS::fit_vertex_data(spline, values, TS::Fit::APPROXIMATE);
    benchmark::DoNotOptimize(spline.values().data());
  }
  state.counters["faces"] = double(domain.number_of_faces());
}

} // namespace

BENCHMARK(BM_delaunay)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_spline_from_triangulation)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

BENCHMARK_MAIN();

// Costs of the output layer on a 100x100 grid domain (20000 triangles, one quintic patch per
// triangle, double kernel): tessellation throughput in output triangles per second at
// levels 2 and 3 (normals and curvatures included), building the point locator, and the
// rates of point location and of evaluation at query points; and evaluation of a spline fitted
// to 10^5 scattered points.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Patch_network.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Index = std::uint32_t;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

constexpr int cells = 100;

// cells x cells unit squares, each split by one diagonal: 2 cells^2 triangles on [0, cells]^2.
const TS::Planar_domain<K>& grid() {
  static const TS::Planar_domain<K> domain = [] {
    std::vector<K::Point_2> points;
    for (int j = 0; j <= cells; ++j)
      for (int i = 0; i <= cells; ++i)
        points.emplace_back(i, j);
    std::vector<std::array<Index, 3>> triangles;
    auto id = [](int i, int j) { return static_cast<Index>(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
        triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
      }
    return TS::Planar_domain<K>(std::move(points), std::move(triangles));
  }();
  return domain;
}

const std::vector<TS::Bezier_triangle<K>>& patches() {
  static const std::vector<TS::Bezier_triangle<K>> result = [] {
    TS::Polynomial_surface<K> p(5);
    int c = 1;
    for (int h = 0; h <= 5; ++h)
      for (int k = 0; h + k <= 5; ++k, ++c)
        p.set_coefficient(h, k, (c % 11 - 5) / double(c % 3 + 1) * std::pow(0.05, h + k));
    std::vector<TS::Bezier_triangle<K>> list;
    const auto& domain = grid();
    for (Index f = 0; f < domain.number_of_faces(); ++f) {
      const auto& t = domain.face(f);
      list.push_back(p.to_bezier(5, domain.point(t[0]), domain.point(t[1]), domain.point(t[2])));
    }
    return list;
  }();
  return result;
}

const TS::Patch_network<K>& network() {
  static const TS::Patch_network<K> result(grid(), patches());
  return result;
}

std::vector<K::Point_2> queries(std::size_t n) {
  std::mt19937 engine(5);
  // a few percent of the points fall outside [0, cells]^2
  std::uniform_real_distribution<double> d(-2, cells + 2);
  std::vector<K::Point_2> points;
  for (std::size_t i = 0; i < n; ++i)
    points.emplace_back(d(engine), d(engine));
  return points;
}

void BM_tessellate(benchmark::State& state) {
  const int levels = static_cast<int>(state.range(0));
  patches();
  std::size_t triangles = 0;
  for (auto _ : state) {
    Mesh mesh;
    const TS::Tessellation_statistics statistics = TS::tessellate(network(), levels, mesh);
    triangles += statistics.faces;
    benchmark::DoNotOptimize(mesh.number_of_faces());
  }
  state.counters["triangles/s"] =
      benchmark::Counter(double(triangles), benchmark::Counter::kIsRate);
  state.counters["triangles"] = double(triangles) / double(state.iterations());
}
BENCHMARK(BM_tessellate)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_locator_build(benchmark::State& state) {
  for (auto _ : state) {
    const TS::Domain_locator<K> locator(grid());
    benchmark::DoNotOptimize(locator.number_of_entries());
  }
  state.counters["faces/s"] = benchmark::Counter(
      double(grid().number_of_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_locator_build)->Unit(benchmark::kMillisecond);

void BM_locator_query(benchmark::State& state) {
  const TS::Domain_locator<K> locator(grid());
  const std::vector<K::Point_2> points = queries(1 << 16);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(locator.locate(points[i++ & (points.size() - 1)]));
  state.counters["queries/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_locator_query);

// Queries for the evaluation benchmarks. Arg 0: random order; 1: the same queries
// Hilbert-sorted (spatially ordered, as grids and sorted lidar points are). Real time: the
// queries run on all cores.
template <class Evaluate>
void evaluate_queries(benchmark::State& state, const Evaluate& evaluate) {
  const TS::Domain_locator<K> locator(network().domain());
  std::vector<K::Point_2> points = queries(1 << 18);
  if (state.range(0) == 1)
    CGAL::hilbert_sort(points.begin(), points.end());
  for (auto _ : state)
    benchmark::DoNotOptimize(evaluate(locator, points));
  state.counters["queries/s"] = benchmark::Counter(
      double(points.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_evaluate_functional(benchmark::State& state) {
  evaluate_queries(state, [](const auto& locator, const auto& points) {
    return TS::evaluate_functional(network(), locator, points);
  });
}
BENCHMARK(BM_evaluate_functional)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same with value, gradient and Hessian (evaluate_jets, order 2).
void BM_evaluate_jets(benchmark::State& state) {
  evaluate_queries(state, [](const auto& locator, const auto& points) {
    return TS::evaluate_jets(network(), locator, points);
  });
}
BENCHMARK(BM_evaluate_jets)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// What a user evaluates (issue 12: at least 10 M values/s on 2 cores for spatially ordered
// queries): the default fit of 10^5 random points of [0, 1]^2 (exp(x) sin(2y)), a
// C1_quintic_spline read through its nets, at 2^20 queries uniform on [-0.02, 1.02]^2. Arg 0:
// random order; 1: Hilbert-sorted.
const TS::C1_quintic_spline<K>& fitted_spline() {
  static const TS::C1_quintic_spline<K> spline = [] {
    std::mt19937_64 engine(7);
    std::uniform_real_distribution<double> u(0, 1);
    TS::Scattered_data<K> data;
    for (int i = 0; i < 100000; ++i) {
      const K::Point_2 p(u(engine), u(engine));
      data.points.push_back(p);
      data.values.push_back(std::exp(p.x()) * std::sin(2 * p.y()));
    }
    auto [domain, heights] = TS::delaunay_domain(data);
    TS::C1_quintic_spline<K> s(std::move(domain), TS::Corner_frame::CORNER_AND_TWO_STARS);
    TS::fit_vertex_data(s, heights, TS::Fit::ADAPTIVE, 5);
    return s;
  }();
  return spline;
}
void BM_evaluate_fitted_spline(benchmark::State& state) {
  const TS::C1_quintic_spline<K>& spline = fitted_spline();
  const TS::Domain_locator<K> locator(spline.domain());
  std::mt19937 engine(5);
  std::uniform_real_distribution<double> d(-0.02, 1.02);
  std::vector<K::Point_2> points;
  for (int i = 0; i < (1 << 20); ++i)
    points.emplace_back(d(engine), d(engine));
  if (state.range(0) == 1)
    CGAL::hilbert_sort(points.begin(), points.end());
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::evaluate_functional(spline, locator, points));
  state.counters["queries/s"] = benchmark::Counter(
      double(points.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_evaluate_fitted_spline)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();

// Costs of the Bézier core: quintic evaluation by de Casteljau vs. the Bernstein sum, blossom
// evaluation, 4-split subdivision, degree elevation, the C^1 join test; double and exact.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

namespace {

template <class K>
TS::Bezier_triangle<K> quintic(int shift = 0) {
  TS::Polynomial_surface<K> p(5);
  int c = 1 + shift;
  for (int h = 0; h <= 5; ++h)
    for (int k = 0; h + k <= 5; ++k, ++c)
      p.set_coefficient(h, k, typename K::FT(c % 11 - 5) / typename K::FT(c % 3 + 1));
  return p.to_bezier(5, typename K::Point_2(0, 0), typename K::Point_2(1, 0),
                     typename K::Point_2(0, 1));
}

// Query points inside the unit triangle with small-denominator rational coordinates, so the
// exact runs measure realistic (not exploding) rational sizes.
template <class K>
std::vector<typename K::Point_2> query_points(int n) {
  std::mt19937 engine(7);
  std::uniform_int_distribution<int> d(0, 64);
  std::vector<typename K::Point_2> points;
  while (static_cast<int>(points.size()) < n) {
    const int a = d(engine), b = d(engine);
    if (a + b <= 64)
      points.emplace_back(typename K::FT(a) / 64, typename K::FT(b) / 64);
  }
  return points;
}

template <class K>
void BM_evaluate_de_casteljau(benchmark::State& state) {
  const auto patch = quintic<K>();
  const auto points = query_points<K>(1024);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(patch.evaluate(points[i++ % points.size()]));
  state.SetItemsProcessed(state.iterations());
}

template <class K>
void BM_evaluate_bernstein(benchmark::State& state) {
  const auto patch = quintic<K>();
  const auto points = query_points<K>(1024);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(patch.evaluate_bernstein(points[i++ % points.size()]));
  state.SetItemsProcessed(state.iterations());
}

template <class K>
void BM_blossom(benchmark::State& state) {
  const auto patch = quintic<K>();
  const auto points = query_points<K>(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    std::vector<typename K::Point_2> args;
    for (int l = 0; l < 5; ++l)
      args.push_back(points[(i + static_cast<std::size_t>(l) * 7) % points.size()]);
    ++i;
    benchmark::DoNotOptimize(patch.blossom(args));
  }
  state.SetItemsProcessed(state.iterations());
}

template <class K>
void BM_subdivide4(benchmark::State& state) {
  const auto patch = quintic<K>();
  for (auto _ : state)
    benchmark::DoNotOptimize(patch.subdivide());
  state.SetItemsProcessed(state.iterations());
}

template <class K>
void BM_elevate_degree(benchmark::State& state) {
  const auto patch = quintic<K>();
  for (auto _ : state)
    benchmark::DoNotOptimize(patch.elevate_degree());
  state.SetItemsProcessed(state.iterations());
}

template <class K>
void BM_join_test_C1(benchmark::State& state) {
  const auto A = quintic<K>();
  const auto B =
      A.reexpress(typename K::Point_2(1, 1), typename K::Point_2(0, 1), typename K::Point_2(1, 0));
  for (auto _ : state)
    benchmark::DoNotOptimize(TS::check_join(A, B, 1));
  state.SetItemsProcessed(state.iterations());
}

} // namespace

BENCHMARK_TEMPLATE(BM_evaluate_de_casteljau, Fast);
BENCHMARK_TEMPLATE(BM_evaluate_bernstein, Fast);
BENCHMARK_TEMPLATE(BM_blossom, Fast);
BENCHMARK_TEMPLATE(BM_subdivide4, Fast);
BENCHMARK_TEMPLATE(BM_elevate_degree, Fast);
BENCHMARK_TEMPLATE(BM_join_test_C1, Fast);
BENCHMARK_TEMPLATE(BM_evaluate_de_casteljau, Exact);
BENCHMARK_TEMPLATE(BM_evaluate_bernstein, Exact);
BENCHMARK_TEMPLATE(BM_blossom, Exact);
BENCHMARK_TEMPLATE(BM_subdivide4, Exact);
BENCHMARK_TEMPLATE(BM_join_test_C1, Exact);

BENCHMARK_MAIN();

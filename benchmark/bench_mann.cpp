// Mann's continuity adjustment and interpolant: adjustment throughput (interior edges per
// second) on quintic networks of 10^5 faces in double and exact arithmetic, and accuracy of
// the interpolant on Franke's function F1 (100 scattered samples, data/franke_100.xyz, and a
// 33 x 33 grid), next to Xu's C^1 quintic spline on the same data.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Mann/Continuity_adjustment.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

namespace {

// A jittered n x n grid, cells split by one diagonal: 2 n^2 triangles. Jitter is a multiple
// of 1/64, so the exact kernel sees the same small rationals.
template <class K>
TS::Planar_domain<K> jittered_grid(int n) {
  using FT = typename K::FT;
  std::mt19937 engine(1);
  std::uniform_int_distribution<int> jitter(-12, 12);
  std::vector<typename K::Point_2> points;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border_x = i == 0 || i == n, border_y = j == 0 || j == n;
      points.emplace_back(FT(i) + (border_x ? FT(0) : FT(jitter(engine)) / FT(64)),
                          FT(j) + (border_y ? FT(0) : FT(jitter(engine)) / FT(64)));
    }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return TS::Planar_domain<K>(std::move(points), std::move(triangles));
}

// Franke's F1 (Franke 1979; Renka and Brown, TOMS 792), the usual test function on [0,1]^2.
double franke(double x, double y) {
  return 0.75 * std::exp(-((9 * x - 2) * (9 * x - 2) + (9 * y - 2) * (9 * y - 2)) / 4) +
         0.75 * std::exp(-(9 * x + 1) * (9 * x + 1) / 49 - (9 * y + 1) / 10) +
         0.5 * std::exp(-((9 * x - 7) * (9 * x - 7) + (9 * y - 3) * (9 * y - 3)) / 4) -
         0.2 * std::exp(-(9 * x - 4) * (9 * x - 4) - (9 * y - 7) * (9 * y - 7));
}

// Vertex jets of a smooth function on the grid: derivative estimates in double (order 3),
// converted exactly for the exact kernel.
std::vector<TS::Polynomial_surface<Fast>> grid_jets(const TS::Planar_domain<Fast>& domain, int n) {
  std::vector<double> z;
  for (const auto& p : domain.points())
    z.push_back(franke(p.x() / n, p.y() / n));
  return TS::estimate_vertex_derivatives(domain, z, 3);
}

std::vector<TS::Polynomial_surface<Exact>>
to_exact(const std::vector<TS::Polynomial_surface<Fast>>& jets) {
  std::vector<TS::Polynomial_surface<Exact>> result;
  for (const auto& jet : jets) {
    TS::Polynomial_surface<Exact> e(jet.degree());
    for (int p = 0; p <= jet.degree(); ++p)
      for (int q = 0; p + q <= jet.degree(); ++q)
        e.set_coefficient(p, q, Exact::FT(jet.coefficient(p, q)));
    result.push_back(e);
  }
  return result;
}

// Adjustment of Mann's C^0 quintic network (consistent vertex data: the vertex step only
// checks, the edge sweep moves one point per patch and edge) to C^1.
template <class K>
void adjust_interpolant_network(benchmark::State& state, const TS::Planar_domain<K>& domain,
                                const std::vector<TS::Polynomial_surface<K>>& jets) {
  const auto network = TS::mann_c0_network(domain, jets, 5);
  std::size_t touched = 0;
  bool certified = false;
  for (auto _ : state) {
    state.PauseTiming();
    auto patches = network;
    state.ResumeTiming();
    touched = TS::adjust_network(domain, patches, 1).number_of_touched_points();
    state.PauseTiming();
    certified = TS::certify_continuity(
                    TS::Patch_network<K>(domain, patches), 1,
                    TS::parameters::residual_tolerance(std::is_same<K, Exact>::value ? 0 : 1e-9))
                    .certified;
    state.ResumeTiming();
  }
  state.counters["faces"] = double(domain.number_of_faces());
  state.counters["interior_edges"] = double(domain.number_of_interior_edges());
  state.counters["edges_per_s"] = benchmark::Counter(double(domain.number_of_interior_edges()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["touched_points"] = double(touched);
  state.counters["certified_c1"] = certified ? 1 : 0;
}

void BM_adjust_quintic_network_double(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto domain = jittered_grid<Fast>(n);
  adjust_interpolant_network(state, domain, grid_jets(domain, n));
}

void BM_adjust_quintic_network_exact(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto domain = jittered_grid<Exact>(n);
  adjust_interpolant_network(state, domain, to_exact(grid_jets(jittered_grid<Fast>(n), n)));
}

// A network of random quintic patches (not even C^0): every vertex is projected.
template <class K>
void adjust_random_network(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto domain = jittered_grid<K>(n);
  std::mt19937 engine(7);
  std::uniform_int_distribution<int> value(-9, 9);
  std::vector<TS::Bezier_triangle<K>> network;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    std::vector<typename K::FT> net;
    for (int c = 0; c < 21; ++c)
      net.push_back(typename K::FT(value(engine)));
    const auto& t = domain.face(f);
    network.emplace_back(5, domain.point(t[0]), domain.point(t[1]), domain.point(t[2]), net);
  }
  std::size_t touched = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto patches = network;
    state.ResumeTiming();
    touched = TS::adjust_network(domain, patches, 1).number_of_touched_points();
  }
  state.counters["faces"] = double(domain.number_of_faces());
  state.counters["edges_per_s"] = benchmark::Counter(double(domain.number_of_interior_edges()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["touched_per_face"] = double(touched) / double(domain.number_of_faces());
}

void BM_adjust_random_network_double(benchmark::State& state) {
  adjust_random_network<Fast>(state);
}
void BM_adjust_random_network_exact(benchmark::State& state) {
  adjust_random_network<Exact>(state);
}

// ---------------------------------------------------------------------------------------
// Accuracy on Franke's F1

TS::Scattered_data<Fast> franke_data(int which) {
  TS::Scattered_data<Fast> data;
  if (which == 0) {
    // data/franke_100.xyz, found from this source file's location.
    std::string path = __FILE__;
    path = path.substr(0, path.find_last_of("/\\") + 1) + "../data/franke_100.xyz";
    std::ifstream in(path);
    if (!in)
      throw std::runtime_error("cannot open " + path);
    return TS::read_xyz<Fast>(in, path);
  }
  for (int j = 0; j <= 32; ++j)
    for (int i = 0; i <= 32; ++i) {
      data.points.emplace_back(i / 32.0, j / 32.0);
      data.values.push_back(franke(i / 32.0, j / 32.0));
    }
  return data;
}

// Errors on a 101 x 101 grid of [0,1]^2, at the points inside the triangulation.
template <class Network>
void accuracy_counters(benchmark::State& state, const Network& network) {
  const TS::Domain_locator<Fast> locator(network.domain());
  std::vector<Fast::Point_2> queries;
  for (int j = 0; j <= 100; ++j)
    for (int i = 0; i <= 100; ++i)
      queries.emplace_back(i / 100.0, j / 100.0);
  const std::vector<double> values = TS::evaluate_functional(network, locator, queries);
  double max_error = 0, sum_error = 0, sse = 0, mean = 0;
  std::size_t count = 0;
  for (std::size_t q = 0; q < queries.size(); ++q)
    if (!std::isnan(values[q])) {
      mean += franke(queries[q].x(), queries[q].y());
      ++count;
    }
  mean /= double(count);
  double ssm = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (std::isnan(values[q]))
      continue;
    const double f = franke(queries[q].x(), queries[q].y());
    const double e = std::abs(values[q] - f);
    max_error = (std::max)(max_error, e);
    sum_error += e;
    sse += e * e;
    ssm += (f - mean) * (f - mean);
  }
  state.counters["eval_points"] = double(count);
  state.counters["max_error"] = max_error;
  state.counters["mean_error"] = sum_error / double(count);
  state.counters["SSE_over_SSM"] = sse / ssm;
}

// Mann's interpolant of degree range(1) (derivatives estimated) on data set range(0):
// 0 = franke_100.xyz, 1 = 33 x 33 grid.
void BM_franke_mann(benchmark::State& state) {
  const auto data = franke_data(int(state.range(0)));
  const int degree = int(state.range(1));
  const auto [domain, values] = TS::delaunay_domain(data);
  std::optional<TS::Mann_interpolant<Fast>> interpolant;
  for (auto _ : state) {
    const auto jets =
        TS::estimate_vertex_derivatives(domain, values, TS::mann_derivative_order(degree));
    interpolant.emplace(TS::mann_interpolant(domain, jets, degree));
  }
  accuracy_counters(state, *interpolant);
  state.counters["data_points"] = double(data.points.size());
}

// Xu's C^1 quintic spline on the same data (the main job's `--fit tangent`).
void BM_franke_xu_c1(benchmark::State& state) {
  const auto data = franke_data(int(state.range(0)));
  const auto [domain, values] = TS::delaunay_domain(data);
  TS::C1_quintic_spline<Fast> spline(domain, TS::Corner_frame::CORNER_AND_TWO_STARS);
  for (auto _ : state)
    TS::fit_vertex_data(spline, values, TS::Fit::TANGENT_PLANES);
  accuracy_counters(state, spline);
  state.counters["data_points"] = double(data.points.size());
}

} // namespace

// 224 x 224 cells: 100352 faces.
BENCHMARK(BM_adjust_quintic_network_double)->Arg(224)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_adjust_quintic_network_exact)->Arg(224)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_adjust_random_network_double)->Arg(224)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_adjust_random_network_exact)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_franke_mann)
    ->Args({0, 5})
    ->Args({1, 5})
    ->Args({0, 9})
    ->Args({1, 9})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_franke_xu_c1)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

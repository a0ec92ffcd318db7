// The C^1 quintic spline pipeline: read -> triangulate -> degenerate frames -> plan -> fit ->
// propagate -> certify -> outputs. Instantiated for double and for exact rationals.

#include "c1_job.h"
#include "csv_input.h"
#include "files.h"
#include "mesh_output.h"
#include "point_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/demo_data.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/Xu/Spline_space.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>
#include <CGAL/Triangular_spline/Xu/make_c1_quintic_spline.h>
#include <CGAL/Triangular_spline/tessellate.h>
#include <CGAL/Triangular_spline/internal/face_measures.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include "report.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace tspline {

namespace {

std::string format_number(double x) {
  std::ostringstream out;
  out << std::setprecision(3) << x;
  return out.str();
}

// log10 of a residual for JSON: null for an exact zero (-infinity).
Json log10_json(double x) {
  return std::isfinite(x) ? Json(x) : Json();
}

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

template <class K>
struct Input {
  TS::Planar_domain<K> domain;
  std::vector<typename K::FT> values;
  std::string kind;
  std::size_t merged_duplicates = 0;
  int y_exponent = 0; // --rescale: the domain's y is the data's times 2^y_exponent
  std::vector<std::array<typename K::FT, 2>> gradients; // --gradients, by domain vertex
  std::size_t flat_hull_faces = 0; // flat triangles closing the hull, removed (Delaunay)
};

// --rescale: the power of two that brings the extent in y closest to the extent in x
// (scipy's rescale=True normalises both to 1; a power of two is exact in double and in
// rationals, so the fitted spline is moved back onto the data's own points exactly).
template <class Point_2>
int rescale_exponent(const std::vector<Point_2>& points) {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (const auto& p : points) {
    x0 = (std::min)(x0, CGAL::to_double(p.x()));
    x1 = (std::max)(x1, CGAL::to_double(p.x()));
    y0 = (std::min)(y0, CGAL::to_double(p.y()));
    y1 = (std::max)(y1, CGAL::to_double(p.y()));
  }
  if (!(x1 > x0) || !(y1 > y0))
    return 0; // degenerate data: the domain builder says why
  return static_cast<int>(std::lround(std::log2((x1 - x0) / (y1 - y0))));
}

template <class Point_2>
void scale_y(std::vector<Point_2>& points, int exponent) {
  using FT = std::decay_t<decltype(points.front().x())>;
  const FT factor =
      exponent >= 0 ? FT(std::ldexp(1.0, exponent)) : FT(1) / FT(std::ldexp(1.0, -exponent));
  for (auto& p : points)
    p = Point_2(p.x(), p.y() * factor);
}

template <class K>
TS::Planar_domain<K> scaled_y(const TS::Planar_domain<K>& domain, int exponent) {
  std::vector<typename K::Point_2> points = domain.points();
  scale_y(points, exponent);
  std::vector<std::array<std::uint32_t, 3>> faces;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f)
    faces.push_back(domain.face(f));
  return TS::Planar_domain<K>(std::move(points), std::move(faces));
}

template <class K>
Input<K> read_input(const std::string& path, bool rescale, bool gradients,
                    const std::string& columns) {
  if (path.empty()) {
    auto [domain, values] = TS::demo_data<K>();
    Input<K> input{
        std::move(domain), std::move(values), "embedded demo data (L-shape with a hole)", 0, 0, {}};
    if (rescale) {
      input.y_exponent = rescale_exponent(input.domain.points());
      input.domain = scaled_y(input.domain, input.y_exponent);
    }
    return input;
  }
  const std::string ext = lowercase_extension(path);
  if (gradients && ext != "xyz" && ext != "txt" && ext != "csv" && ext != "npy")
    throw TS::Invalid_input("'" + path +
                            "': --gradients needs scattered points 'x y z zx zy' "
                            "(.xyz, .csv or .npy)");
  if (ext == "xyz" || ext == "txt" || ext == "csv" || ext == "npy") {
    TS::Scattered_data<K> data;
    if (ext == "npy") {
      data = read_npy_scattered<K>(path, columns, gradients);
    } else {
      std::ifstream file = open_input(path);
      // CSV: the chosen columns as .xyz lines, checked by the same reader
      std::istringstream csv(ext == "csv" ? csv_as_xyz(file, path, columns, gradients)
                                          : std::string());
      std::istream& in = ext == "csv" ? static_cast<std::istream&>(csv) : file;
      data = TS::read_xyz<K>(in, path, gradients);
    }
    // Rescaled before triangulating: the Delaunay triangulation of the rescaled points
    // (and dz/dy' = dz/dy / 2^exponent).
    const int exponent = rescale ? rescale_exponent(data.points) : 0;
    scale_y(data.points, exponent);
    std::vector<std::size_t> order;
    std::size_t flat = 0;
    auto [domain, values] = TS::delaunay_domain(data, &order, &flat);
    Input<K> input{std::move(domain),
                   std::move(values),
                   "scattered points, Delaunay triangulation",
                   data.merged_duplicates,
                   exponent,
                   {},
                   flat};
    using FT = typename K::FT;
    const FT y_factor =
        exponent >= 0 ? FT(std::ldexp(1.0, exponent)) : FT(1) / FT(std::ldexp(1.0, -exponent));
    if (gradients)
      for (std::size_t i : order)
        input.gradients.push_back({{data.gradients[i][0], FT(data.gradients[i][1] / y_factor)}});
    return input;
  }
  if (ext == "off" || ext == "obj" || ext == "ply" || ext == "stl") {
    auto [domain, values] = TS::read_mesh_domain<K>(path);
    const int exponent = rescale ? rescale_exponent(domain.points()) : 0;
    if (exponent != 0)
      domain = scaled_y(domain, exponent);
    return {std::move(domain),
            std::move(values),
            "triangle mesh, (x, y) as the domain",
            0,
            exponent,
            {}};
  }
  throw TS::Invalid_input("'" + path + "': unknown input format '." + ext +
                          "' (expected .xyz, .csv or .npy for scattered points, or "
                          ".off/.obj/.ply/.stl)");
}

// The tension the fit uses: the one asked for, else the library's default (0 where the fit
// has no energy).
double tension_of(const C1_job& job, TS::Fit fit) {
  if (job.tension)
    return *job.tension;
  return fit == TS::Fit::ADAPTIVE ? TS::internal::adaptive_tension : 0.0;
}

template <class Point_2>
Json point_json(const Point_2& p) {
  Json a = Json::array();
  a.push_back(CGAL::to_double(p.x()));
  a.push_back(CGAL::to_double(p.y()));
  return a;
}

template <class K>
Json run(const C1_job& job, std::ostream& out) {
  using Spline = TS::C1_quintic_spline<K>;
  Stopwatch clock, total;
  Cpu_stopwatch cpu_clock, cpu_total;
  Json timings = Json::object();
  Json cpu = Json::object();    // process CPU seconds of each stage (all threads)
  Json memory = Json::object(); // peak resident memory after each stage
  Json report = Json::object();

  // Reading and triangulating take about a second from some 10^5 points (a few MB of text).
  std::error_code size_error;
  const bool large_file = !job.input.empty() &&
                          std::filesystem::file_size(job.input, size_error) > 4000000 &&
                          !size_error;
  progress("c1", "reading and triangulating " + job.input, large_file);
  Input<K> input = read_input<K>(job.input, job.rescale, job.gradients, job.columns);
  timings["read_and_triangulate"] = clock.lap();
  memory["read_and_triangulate"] = peak_memory_mb();
  cpu["read_and_triangulate"] = cpu_clock.lap();
  // Exact arithmetic (issue 12): about 19500 triangles per second end to end with the fits
  // that read values and gradients (measured on 4*10^4 triangles of full double mantissas;
  // 30000 on 6-decimal data); with the local polynomials' exact coefficients, about 300 on
  // full double mantissas (coefficients of thousands of digits), 3800 on 6-decimal data.
  // Say what to expect, at worst, before a long silence.
  const double exact_rate =
      job.fit == "adaptive" || job.fit == "local" || job.fit == "lsq" ? 250.0 : 15000.0;
  // A few seconds of work from here on: 4 * exact_rate triangles exact, 10^6 in double.
  const bool large =
      double(input.domain.number_of_faces()) > (job.exact ? 4 * exact_rate : 300000.0);
  if (job.exact && input.domain.number_of_faces() > 10 * exact_rate)
    std::cerr << "tspline c1: note: --exact --fit " << job.fit << " on "
              << input.domain.number_of_faces() << " triangles may take "
              << format_number(input.domain.number_of_faces() / exact_rate / 60.0)
              << " minutes (about " << exact_rate
              << " triangles per second on data with full double mantissas, faster on short "
                 "decimals); the double build takes seconds and reports its round-off\n";
  const std::size_t input_vertices = input.domain.number_of_vertices();

  // Degenerate frames are re-routed by the plan; the perturbation fix moves vertices first.
  std::vector<TS::Vertex_move<typename K::Point_2, std::uint32_t>> moves;
  TS::Planar_domain<K> domain = job.fix == "perturb"
                                    ? TS::perturb_degenerate_vertices(input.domain, moves)
                                    : std::move(input.domain);
  const auto original_frames = job.fix == "perturb"
                                   ? TS::find_degenerate_frames(input.domain)
                                   : TS::Degenerate_frame_analysis<std::uint32_t>();
  timings["degenerate_frame_fix"] = clock.lap();
  memory["degenerate_frame_fix"] = peak_memory_mb();
  cpu["degenerate_frame_fix"] = cpu_clock.lap();

  const TS::Fit fit = job.fit == "interpolate" ? TS::Fit::INTERPOLATE
                      : job.fit == "tangent"   ? TS::Fit::TANGENT_PLANES
                      : job.fit == "lsq"       ? TS::Fit::LEAST_SQUARES
                      : job.fit == "local"     ? TS::Fit::LOCAL_POLYNOMIAL
                      : job.fit == "energy"    ? TS::Fit::MINIMAL_ENERGY
                      : job.fit == "adaptive"  ? TS::Fit::ADAPTIVE
                                               : TS::Fit::APPROXIMATE;
  progress("c1",
           "building the plan of " + std::to_string(domain.number_of_faces()) +
               " patches, fitting and propagating",
           large);
  namespace TSP = TS::parameters;
  TS::Fit_statistics fit_statistics;
  const TS::Degree_selection selection = job.degree_selection == "largest"
                                             ? TS::Degree_selection::LARGEST
                                             : TS::Degree_selection::CROSS_VALIDATION;
  const auto outputs = TSP::smoothing(
      job.smoothing,
      TSP::tension(tension_of(job, fit),
                   TSP::vertex_gradients(input.gradients, TSP::fit_statistics(fit_statistics))));
  // The library chooses the corner frame the fit needs.
  Spline spline = TS::make_c1_quintic_spline(
      std::move(domain), input.values,
      TSP::data_fit(fit, TSP::local_degree(job.degree, TSP::degree_selection(selection, outputs))));
  // Fitted in rescaled coordinates: back onto the data's own (exact, see map_domain()).
  if (input.y_exponent != 0)
    spline.map_domain(scaled_y(spline.domain(), -input.y_exponent));
  timings["fit_and_propagate"] = clock.lap();
  memory["fit_and_propagate"] = peak_memory_mb();
  cpu["fit_and_propagate"] = cpu_clock.lap();

  const auto& d = spline.domain();
  // Double builds: residuals are round-off, accepted up to 1e-10 of the largest control
  // value; exact builds: the verdict is a proof.
  // (Not converted in exact builds: 2.5 million fractions at 10^5 points, 0.2 s on one core.)
  double scale = 1;
  if (!job.exact)
    for (const auto& v : spline.values())
      scale = (std::max)(scale, TS::max_abs_coordinate(v));
  progress("c1",
           std::string(job.exact ? "certifying exactly " : "checking ") +
               std::to_string(d.number_of_interior_edges()) + " interior edges",
           large);
  // The report gives the totals only: the per-edge verdicts would take 40 bytes per interior
  // edge (the run's peak at 10^6 random points: 735 MiB with them, 631 without).
  TS::Continuity_certificate certificate = TS::certify_continuity(
      spline, 1,
      TS::parameters::residual_tolerance(job.exact ? 0 : 1e-10 * scale,
                                         TS::parameters::edge_verdicts(false)));
  timings["certify"] = clock.lap();
  memory["certify"] = peak_memory_mb();
  cpu["certify"] = cpu_clock.lap();

  std::optional<long long> morgan_scott =
      TS::morgan_scott_dimension(spline); // (its singular vertices)
  // The dimension, proven by two bounds: the exact plan's rules imply every C^1 condition
  // (checked exactly: dim >= its free count), and the rank of the C^1 conditions modulo a
  // prime (dim <= slots - rank). Only when several primes disagree is the rational rank
  // computed, which takes minutes from 50 scattered points on: said before it starts.
  std::optional<TS::Dimension_certificate> dimension;
  if (job.dimension) {
    // About 3 CPU seconds per 10^4 points.
    progress("c1", "proving the dimension (exact plan check, rank modulo a prime)",
             d.number_of_vertices() > 5000);
    dimension = TS::spline_dimension(d, false);
    if (!dimension->dimension) {
      std::cerr << "tspline c1: note: the rank modulo " << dimension->primes_tried
                << " primes does not meet the free count; computing the exact rational rank "
                   "(minutes from 50 scattered points on)\n";
      dimension = TS::spline_dimension(d, true);
    }
    timings["dimension"] = clock.lap();
    memory["dimension"] = peak_memory_mb();
    cpu["dimension"] = cpu_clock.lap();
  }
  const bool dimension_proven = dimension && dimension->dimension;

  // Honesty about the surface: does it go through the data, and does it stay in the data's
  // range? The sampled range (vertices and face centroids) is a lower bound of the surface's
  // range, the control values' range an upper bound (convex hull property).
  double interpolation_error = 0, data_min = HUGE_VAL, data_max = -HUGE_VAL;
  for (std::uint32_t v = 0; v < d.number_of_vertices(); ++v) {
    const double z = CGAL::to_double(input.values[v]);
    data_min = (std::min)(data_min, z);
    data_max = (std::max)(data_max, z);
    interpolation_error = (std::max)(
        interpolation_error, std::abs(CGAL::to_double(spline.value(spline.vertex_slot(v))) - z));
  }
  // The fairness measure the energy fit minimises, reported for every fit to compare them,
  // and the sampled range: measurements, not proofs, so taken in double also for exact
  // builds (the exact energies of propagated rationals cost 27 s for 200 points). A patch
  // too thin for double falls back to its exact form. The energy only goes into the report
  // (without one it would be 2.6% of a run at 10^6 points).
  const bool with_energy = !job.report.empty();
  double thin_plate = 0;
  double sampled_min = data_min, sampled_max = data_max;
  // Per face on all cores, summed in face order: the same sum as one thread.
  std::vector<double> face_energy(d.number_of_faces()), face_value(d.number_of_faces());
  const bool exact_build = CGAL::Algebraic_structure_traits<typename K::FT>::Is_exact::value;
  TS::internal::parallel_for_index(
      d.number_of_faces(),
      TS::internal::thread_count(d.number_of_faces(), exact_build ? 2000 : 20000),
      [&](std::size_t face) {
        const auto f = static_cast<std::uint32_t>(face);
        double energy = 0, z = 0;
        if constexpr (std::is_same_v<K, Fast>) { // the patch's bits, without the patch
          try {
            if (const auto measures =
                    TS::internal::face_energy_and_centroid_value(spline, f, with_energy)) {
              face_energy[face] = measures->first;
              face_value[face] = measures->second;
              return;
            }
          } catch (const TS::Invalid_input&) { // the patch's path below decides, as before
          }
        } else { // the converted patch's bits, without the exact patch and its copy
          try {
            if (const auto measures = TS::internal::converted_face_energy_and_centroid_value<Fast>(
                    spline, f, with_energy)) {
              face_energy[face] = measures->first;
              face_value[face] = measures->second;
              return;
            }
          } catch (const TS::Invalid_input&) {
          }
        }
        const auto own = spline.patch(f);
        try {
          if constexpr (std::is_same_v<K, Fast>) { // already in double: no copy
            energy = with_energy ? TS::thin_plate_energy(own) : 0.0;
            z = own.evaluate(CGAL::centroid(own.vertex(0), own.vertex(1), own.vertex(2)));
          } else {
            const auto patch = TS::convert_patch<Fast>(own);
            energy = with_energy ? TS::thin_plate_energy(patch) : 0.0;
            z = patch.evaluate(CGAL::centroid(patch.vertex(0), patch.vertex(1), patch.vertex(2)));
          }
        } catch (const TS::Invalid_input&) {
          const auto exact = TS::convert_patch<Exact>(own);
          energy = with_energy ? CGAL::to_double(TS::thin_plate_energy(exact)) : 0.0;
          z = CGAL::to_double(
              exact.evaluate(CGAL::centroid(exact.vertex(0), exact.vertex(1), exact.vertex(2))));
        }
        face_energy[face] = energy;
        face_value[face] = z;
      });
  for (std::size_t f = 0; f < face_energy.size(); ++f) {
    thin_plate += face_energy[f];
    sampled_min = (std::min)(sampled_min, face_value[f]);
    sampled_max = (std::max)(sampled_max, face_value[f]);
  }
  // (by blocks on all cores: an exact value's conversion to double is not cheap)
  double control_min = HUGE_VAL, control_max = -HUGE_VAL;
  {
    constexpr std::size_t block = std::size_t(1) << 14;
    const std::size_t slots = spline.number_of_slots();
    std::vector<std::pair<double, double>> ranges((slots + block - 1) / block,
                                                  {HUGE_VAL, -HUGE_VAL});
    TS::internal::parallel_for_index(
        ranges.size(), TS::internal::thread_count(slots, exact_build ? 20000 : 1000000),
        [&](std::size_t b) {
          auto& [low, high] = ranges[b];
          for (std::size_t s = b * block; s < (std::min)(slots, (b + 1) * block); ++s) {
            const double value = CGAL::to_double(spline.values()[s]);
            low = (std::min)(low, value);
            high = (std::max)(high, value);
          }
        },
        1);
    for (const auto& [low, high] : ranges) {
      control_min = (std::min)(control_min, low);
      control_max = (std::max)(control_max, high);
    }
  }
  const double data_span = data_max - data_min;
  const double overshoot = (std::max)(sampled_max - data_max, data_min - sampled_min);
  const bool overshoots = overshoot > 0.1 * data_span;

  // Extreme scales (issue 13): double arithmetic says little when the domain's extents differ
  // by many orders of magnitude, or when control values dwarf the data; say so and what helps.
  double x_min = HUGE_VAL, x_max = -HUGE_VAL, y_min = HUGE_VAL, y_max = -HUGE_VAL;
  for (std::uint32_t v = 0; v < d.number_of_vertices(); ++v) {
    x_min = (std::min)(x_min, CGAL::to_double(d.point(v).x()));
    x_max = (std::max)(x_max, CGAL::to_double(d.point(v).x()));
    y_min = (std::min)(y_min, CGAL::to_double(d.point(v).y()));
    y_max = (std::max)(y_max, CGAL::to_double(d.point(v).y()));
  }
  const double extent_ratio =
      (std::max)(x_max - x_min, y_max - y_min) / (std::min)(x_max - x_min, y_max - y_min);
  const std::string scale_hint = extent_ratio > 1e6 && input.y_exponent == 0
                                     ? "; the x and y extents differ by a factor " +
                                           format_number(extent_ratio) +
                                           ": --rescale fits in coordinates of equal extent"
                                     : "";
  const double data_magnitude = (std::max)(std::abs(data_min), std::abs(data_max));
  const double control_magnitude = (std::max)(std::abs(control_min), std::abs(control_max));
  std::vector<std::string> warnings;
  if (overshoots)
    warnings.push_back("the surface leaves the data range [" + format_number(data_min) + ", " +
                       format_number(data_max) + "] by " + format_number(overshoot) +
                       " (more than 10% of its span) at sampled points; for noisy data use --fit "
                       "energy --smoothing 1, a lower --degree overshoots less");
  if (!(control_magnitude <= 1e6 * data_magnitude) && data_magnitude > 0)
    warnings.push_back(
        "control values reach " + format_number(control_magnitude) +
        ", more than 10^6 times the data's largest |z| (" + format_number(data_magnitude) +
        "): the surface is meaningless near the triangles that carry them" + scale_hint);
  const double amplification = spline.propagation_amplification();
  if (amplification > 1e3)
    warnings.push_back(
        "the propagation amplifies inconsistent prescribed points " + format_number(amplification) +
        " times: control points multiply the data's errors by that much" + scale_hint);
  timings["range_checks"] = clock.lap();
  memory["range_checks"] = peak_memory_mb();
  cpu["range_checks"] = cpu_clock.lap();

  std::size_t numerical_frames = 0;
  for (const auto& f : spline.degenerate_frames())
    numerical_frames += f.numerical ? 1 : 0;

  report["input"] = job.input.empty() ? std::string("demo") : job.input;
  report["input_kind"] = input.kind;
  report["number_type"] = job.exact ? "exact" : "double";
  report["fit"] = job.fit;
  report["fix"] = job.fix;
  if (job.rescale)
    report["rescale_y_factor"] = std::ldexp(1.0, input.y_exponent);
  report["gradients"] = job.gradients ? "given" : "estimated";
  if (fit == TS::Fit::MINIMAL_ENERGY)
    report["smoothing"] = job.smoothing;
  if (fit == TS::Fit::MINIMAL_ENERGY || fit == TS::Fit::ADAPTIVE)
    report["tension"] = tension_of(job, fit);
  if (fit == TS::Fit::LOCAL_POLYNOMIAL || fit == TS::Fit::LEAST_SQUARES ||
      fit == TS::Fit::ADAPTIVE) {
    Json local = Json::object();
    local["max_degree"] = job.degree;
    local["degree_selection"] = job.degree_selection;
    Json by_degree = Json::array();
    for (std::size_t count : fit_statistics.vertices_by_degree)
      by_degree.push_back(count);
    local["vertices_by_degree"] = by_degree;
    // Polynomials read far beyond their data (long hull edges): their targets move to the
    // linear interpolant there.
    local["vertices_beyond_reach"] = fit_statistics.vertices_beyond_reach;
    if (fit == TS::Fit::ADAPTIVE) {
      // How much of the surface follows the local polynomials and how much the energy.
      const auto& trust = fit_statistics.vertices_by_trust;
      local["vertices_trusted"] = trust[0];
      local["vertices_blended"] = trust[1];
      local["vertices_minimal_energy"] = trust[2];
      local["energy_skipped"] = fit_statistics.energy_skipped;
    }
    report["local_polynomials"] = local;
  }
  if (fit_statistics.solver_sweeps > 0) {
    Json solver = Json::object();
    solver["method"] = fit_statistics.solver_method;
    solver["sweeps"] = fit_statistics.solver_sweeps;
    solver["windows_per_sweep"] = fit_statistics.solver_windows;
    solver["window_solves"] = fit_statistics.solver_window_solves;
    solver["iterations"] = fit_statistics.solver_iterations;
    solver["last_change"] = fit_statistics.solver_last_change;
    solver["converged"] = fit_statistics.solver_converged;
    report["solver"] = solver;
  }
  report["vertices"] = d.number_of_vertices();
  report["faces"] = d.number_of_faces();
  report["interior_edges"] = d.number_of_interior_edges();
  report["boundary_edges"] = d.number_of_boundary_edges();
  report["boundary_loops"] = d.number_of_boundary_loops();
  report["merged_duplicate_points"] = input.merged_duplicates;
  report["flat_hull_faces_removed"] = input.flat_hull_faces;
  report["free_parameters"] = spline.number_of_free_parameters();
  report["free_parameters_formula"] = "3V + 3F + E_I + 3E_B + sigma";
  report["dimension_morgan_scott"] = morgan_scott ? Json(*morgan_scott) : Json();
  report["dimension"] = dimension_proven ? Json(*dimension->dimension) : Json();
  report["dimension_upper_bound"] = dimension ? Json(dimension->upper_bound) : Json();
  report["dimension_rank_prime"] =
      dimension && !dimension->rational_rank ? Json(dimension->prime) : Json();
  report["dimension_primes_tried"] = dimension ? Json(dimension->primes_tried) : Json();
  report["dimension_lower_bound_proven"] = dimension ? Json(dimension->lower_bound_proven) : Json();
  // Which argument proved it: the two bounds meeting, or the exact rational rank.
  report["dimension_argument"] =
      !dimension_proven          ? Json()
      : dimension->rational_rank ? Json("exact rational rank")
                                 : Json("plan rules imply the C^1 conditions (exact) + rank mod p");
  report["singular_vertices"] = spline.singular_vertices().size();
  report["degenerate_frames"] =
      job.fix == "perturb" ? original_frames.frames.size() : spline.degenerate_frames().size();
  report["degenerate_frames_numerical"] = numerical_frames;
  report["max_interpolation_error"] = interpolation_error;
  report["thin_plate_energy"] = thin_plate;
  auto range = [](double lo, double hi) {
    Json a = Json::array();
    a.push_back(lo);
    a.push_back(hi);
    return a;
  };
  report["data_range"] = range(data_min, data_max);
  report["surface_range_sampled"] = range(sampled_min, sampled_max);
  report["control_value_range"] = range(control_min, control_max);
  report["overshoot_warning"] = overshoots;
  std::size_t thin_frames = 0;
  for (const auto& f : spline.rerouted_frames())
    thin_frames += f.thin ? 1 : 0;
  report["thin_frames_rerouted"] = thin_frames;
  report["propagation_weight_bound"] = Spline::propagation_weight_bound;
  report["max_propagation_weight"] = spline.max_propagation_weight();
  report["propagation_amplification"] = amplification;
  {
    // Where the largest weights are: by the role of the computed point (auxiliary: the
    // partial sums of the closing rules at near-singular vertices).
    Json kinds = Json::object(), counts = Json::object();
    const char* names[] = {"corner", "star", "edge_middle", "corner_inner", "flip", "auxiliary"};
    for (std::size_t k = 0; k < 6; ++k) {
      kinds[names[k]] = spline.max_propagation_weight(TS::Slot_kind(k));
      counts[names[k]] = spline.number_of_rules_above_weight_bound(TS::Slot_kind(k));
    }
    report["max_propagation_weight_by_role"] = kinds;
    report["rules_above_weight_bound_by_role"] = counts;
    report["near_singular_vertices"] = spline.near_singular_vertices().size();
    // 1, or 2 and more where thin re-routings closed a dependency cycle and the plan was
    // built again without the least thin one on each
    report["plan_rounds"] = spline.plan_rounds();
  }
  Json moved = Json::array();
  for (const auto& m : moves) {
    Json entry = Json::object();
    entry["vertex"] = m.vertex;
    entry["from"] = point_json(m.from);
    entry["to"] = point_json(m.to);
    entry["distance"] = m.distance;
    moved.push_back(entry);
  }
  report["perturbed_vertices"] = moved;
  report["degenerate_frames_rerouted"] = spline.degenerate_frames().size();
  // the tolerance is the one `tspline certify --tolerance` needs for the saved file
  set_c1_certificate(report, certificate);

  if (!job.mesh.empty()) {
    progress("c1", "tessellating and writing " + job.mesh, large || job.levels >= 5);
    report["mesh"] = write_tessellated_mesh(spline, job.levels, job.mesh);
    timings["tessellate_and_write"] = clock.lap();
    memory["tessellate_and_write"] = peak_memory_mb();
    cpu["tessellate_and_write"] = cpu_clock.lap();
  }
  if (!job.save.empty()) {
    std::ofstream file = open_output(job.save);
    TS::write_spline_file(file, spline);
    report["saved"] = job.save;
    timings["save"] = clock.lap();
    memory["save"] = peak_memory_mb();
    cpu["save"] = cpu_clock.lap();
  }
  if (!job.query.empty()) {
    if (job.values.empty())
      throw TS::Invalid_input("--query needs --values OUT.txt for the results");
    const auto queries = read_query_file<K>(job.query);
    const TS::Domain_locator<K> locator(d);
    const std::vector<double> values = TS::evaluate_functional(spline, locator, queries);
    std::ofstream values_file;
    if (job.values != "-")
      values_file = open_output(job.values);
    std::ostream& file = job.values == "-" ? std::cout : values_file;
    std::size_t outside = 0;
    for (double v : values) {
      if (std::isnan(v)) {
        file << "nan\n";
        ++outside;
      } else {
        std::string text;
        TS::internal::append_double(text, v);
        file << text << '\n';
      }
    }
    Json q = Json::object();
    q["points"] = queries.size();
    q["outside_domain"] = outside;
    q["values"] = job.values;
    report["query"] = q;
    timings["query"] = clock.lap();
    memory["query"] = peak_memory_mb();
    cpu["query"] = cpu_clock.lap();
  }
  timings["total"] = total.lap();
  memory["total"] = peak_memory_mb();
  cpu["total"] = cpu_total.lap();
  report["timings_seconds"] = timings;
  if (memory["total"].get<double>() >= 0)
    report["peak_memory_mb_after"] = memory;
  report["cpu_seconds"] = cpu;

  if (!job.quiet) {
    out << "C^1 quintic spline (Xu) over " << input.kind << "\n"
        << "  domain: " << d.number_of_vertices() << " vertices (" << input_vertices
        << " in the input), " << d.number_of_faces() << " triangles, "
        << d.number_of_interior_edges() << " interior and " << d.number_of_boundary_edges()
        << " boundary edges, " << d.number_of_boundary_loops() << " boundary loop(s)\n";
    if (input.flat_hull_faces > 0)
      out << "  flat hull triangles removed: " << input.flat_hull_faces
          << " (hull points on a line up to rounding)\n";
    out << "  degenerate frames: "
        << (job.fix == "perturb" ? original_frames.frames.size()
                                 : spline.degenerate_frames().size())
        << (job.fix == "perturb"
                ? " (fixed by moving " + std::to_string(moves.size()) + " vertices" +
                      (spline.degenerate_frames().empty()
                           ? std::string(")")
                           : "; " + std::to_string(spline.degenerate_frames().size()) +
                                 " at boundary vertices that cannot move without changing the "
                                 "domain re-routed)")
                : std::string(" (re-routed)"))
        << ", singular vertices: " << spline.singular_vertices().size()
        << ", thin frames re-routed: " << thin_frames << "\n"
        << "  largest propagation weight: " << spline.max_propagation_weight()
        << " (amplification of inconsistent prescribed points: " << amplification << ")\n"
        << "  free parameters: " << spline.number_of_free_parameters();
    if (morgan_scott)
      out << " (Morgan-Scott dimension " << *morgan_scott << ")";
    if (dimension_proven && dimension->rational_rank)
      out << " (dimension " << *dimension->dimension
          << " proven: the exact rank of the C^1 conditions over the rationals)";
    else if (dimension_proven)
      out << " (dimension " << *dimension->dimension
          << " proven: the rank of the C^1 conditions mod " << dimension->prime
          << " bounds it from above, the plan's rules imply every C^1 condition exactly)";
    else if (dimension)
      out << " (dimension at most " << dimension->upper_bound << ": rank of the C^1 conditions mod "
          << dimension->prime << "; lower bound "
          << (dimension->lower_bound_proven ? "proven" : "NOT proven: the plan check failed")
          << ")";
    out << "\n  fit: " << job.fit << ", arithmetic: " << (job.exact ? "exact rationals" : "double")
        << ", largest interpolation error: " << interpolation_error << "\n";
    if (fit_statistics.solver_method == "windows")
      out << "  solved by windows: " << fit_statistics.solver_sweeps << " sweeps of "
          << fit_statistics.solver_windows << " windows (" << fit_statistics.solver_window_solves
          << " window solves), "
          << (fit_statistics.solver_converged ? "converged"
                                              : "NOT converged: stopped at the sweep limit")
          << "\n";
    if (job.gradients)
      out << "  gradients: given at every vertex, interpolated\n";
    if (input.y_exponent != 0)
      out << "  rescaled: triangulated and fitted with y times 2^" << input.y_exponent << "\n";
    if (fit == TS::Fit::ADAPTIVE) {
      const auto& trust = fit_statistics.vertices_by_trust;
      out << "  vertices following their local polynomial: " << trust[0]
          << ", blended with the minimal-energy surface: " << trust[1]
          << ", minimal energy only: " << trust[2] << "\n";
      if (fit_statistics.energy_skipped)
        out << "  (more than 10^4 vertices poorly resolved: the energy solve was skipped and "
               "every vertex follows its local polynomial; --fit energy solves it globally)\n";
    }
    out << "  data range [" << data_min << ", " << data_max << "], surface range (sampled) ["
        << sampled_min << ", " << sampled_max << "]\n"
        << "  " << certificate_summary(certificate);
    if (!certificate.exact)
      out << "  (double build: use --exact for an exact proof of C^1; 'tspline certify' checks "
             "a saved file's values exactly and accepts their round-off with --tolerance "
          << format_number(certificate.tolerance) << ")\n";
  }
  for (const std::string& warning : warnings)
    std::cerr << "tspline c1: warning: " << warning << "\n";
  Json warning_list = Json::array();
  for (const std::string& warning : warnings)
    warning_list.push_back(warning);
  report["warnings"] = warning_list;
  if (!job.report.empty())
    write_json_report(job.report, report);
  // The outputs are written (to look at), but a spline that fails its own check is an error.
  if (!certificate.certified && certificate.exact)
    throw std::runtime_error("the exact spline fails its C^1 certificate: this is a bug, please "
                             "report it with the input");
  if (!certificate.certified)
    throw std::runtime_error("the spline is not C^1 within round-off (largest residual " +
                             format_number(certificate.max_residual) + ", tolerance " +
                             format_number(certificate.tolerance) +
                             "): double arithmetic fails on this input" + scale_hint +
                             "; --exact computes it exactly");
  return report;
}

template <class K, class Value>
Certify_result certify_file(std::istream& in, const std::string& path, double tolerance,
                            std::ostream& out) {
  const TS::Spline_file<K, Value> file = TS::read_spline_file<K, Value>(in, path);
  const TS::Continuity_certificate c = TS::certify_continuity(
      file, 1, TS::parameters::residual_tolerance(tolerance >= 0 ? tolerance : 0));
  out << "spline file " << path << ": " << file.domain().number_of_vertices() << " vertices, "
      << file.domain().number_of_faces() << " patches of degree "
      << (file.patches().empty() ? 0 : file.patches().front().degree()) << "\n"
      << certificate_summary(c);
  // A spline saved by a double build carries round-off: say so rather than only "failed".
  double scale = 0;
  for (const auto& p : file.patches())
    for (const Value& v : p.control_points())
      scale = (std::max)(scale, TS::max_abs_coordinate(v));
  std::string hint;
  // Round-off of a double build: residuals between 1e-20 and 1e-10 of the largest value.
  const double relative_log10 = c.max_residual_log10 - std::log10((std::max)(scale, 1.0));
  if (!c.certified && relative_log10 >= -20 && relative_log10 <= -10)
    hint = "the residuals (largest " + format_number(c.max_residual) +
           ") are round-off of a double build: --tolerance " +
           format_number(1e-10 * (std::max)(scale, 1.0)) +
           " accepts them (not a proof); build with --exact for a proof";
  Json report = Json::object();
  report["file"] = path;
  report["vertices"] = file.domain().number_of_vertices();
  report["faces"] = file.domain().number_of_faces();
  report["verdict"] = TS::verdict_name(c.verdict);
  report["certified_c1"] = c.verdict == TS::Certificate_verdict::PROOF;
  report["within_tolerance"] = c.certified;
  report["exact"] = true;
  report["tolerance"] = tolerance >= 0 ? Json(tolerance) : Json();
  report["max_c1_residual"] = c.max_residual;
  report["max_c1_residual_log10"] = log10_json(c.max_residual_log10);
  report["interior_edges"] = c.interior_edges;
  report["failed_edges"] = c.failed_edges;
  report["nonzero_edges"] = c.nonzero_edges;
  Json edges = Json::array();
  for (const auto& e : c.edges) {
    Json entry = Json::object();
    entry["edge"] = e.edge;
    Json v = Json::array();
    v.push_back(e.vertices[0]);
    v.push_back(e.vertices[1]);
    entry["vertices"] = v;
    entry["c0"] = e.achieved_order >= 0;
    entry["c1"] = e.holds;
    entry["zero"] = e.zero;
    entry["residual"] = e.residual;
    entry["residual_log10"] = log10_json(e.residual_log10);
    edges.push_back(entry);
  }
  report["edges"] = edges;
  return {report, c.certified, hint};
}

} // namespace

Json run_c1_job(const C1_job& job, std::ostream& out) {
  if (job.fit != "approximate" && job.fit != "interpolate" && job.fit != "tangent" &&
      job.fit != "lsq" && job.fit != "local" && job.fit != "energy" && job.fit != "adaptive")
    throw Usage_error("--fit must be adaptive, local, energy, lsq, tangent, interpolate or "
                      "approximate, not '" +
                      job.fit + "'");
  if (!(job.smoothing >= 0) || !std::isfinite(job.smoothing))
    throw Usage_error("--smoothing must be a finite number >= 0");
  if (job.smoothing > 0 && job.fit != "energy")
    throw Usage_error("--smoothing needs --fit energy");
  if (job.tension && (!(*job.tension >= 0) || !std::isfinite(*job.tension)))
    throw Usage_error("--tension must be a finite number >= 0");
  if (job.tension && job.fit != "adaptive" && job.fit != "energy")
    throw Usage_error("--tension needs --fit adaptive or --fit energy");
  if (job.tension && *job.tension > 0 && job.smoothing > 0)
    throw Usage_error("--tension pulls toward the data's interpolant: it does not go with "
                      "--smoothing");
  if (job.gradients && job.fit == "approximate")
    throw Usage_error("--gradients needs an interpolating fit (not approximate)");
  if (job.gradients && job.smoothing > 0)
    throw Usage_error("--gradients interpolates: it does not go with --smoothing");
  if (job.degree_selection != "cv" && job.degree_selection != "largest")
    throw Usage_error("--degree-selection must be cv or largest, not '" + job.degree_selection +
                      "'");
  if (job.degree < 0 || job.degree > 5)
    throw Usage_error("--degree must be between 0 and 5, not " + std::to_string(job.degree));
  if (job.fix != "reroute" && job.fix != "perturb")
    throw Usage_error("--fix must be reroute or perturb, not '" + job.fix + "'");
  if (job.levels < 0 || job.levels > 8)
    throw Usage_error("--levels must be between 0 and 8");
  if (!job.columns.empty() && lowercase_extension(job.input) != "csv" &&
      lowercase_extension(job.input) != "npy")
    throw Usage_error("--columns chooses the columns of a .csv or .npy input");
  return job.exact ? run<Exact>(job, out) : run<Fast>(job, out);
}

Certify_result run_certify_job(const std::string& path, double tolerance, std::ostream& out) {
  // The header says the dimension, which picks the value type; then read exactly.
  std::ifstream in = open_input(path);
  const int dimension = TS::spline_file_dimension(in);
  return dimension == 3 ? certify_file<Exact, Exact::Vector_3>(in, path, tolerance, out)
                        : certify_file<Exact, Exact::FT>(in, path, tolerance, out);
}

} // namespace tspline

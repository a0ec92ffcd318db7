// Mann's continuity adjustment of a saved network (exact), and Mann's interpolant from
// scattered data or a height-field mesh (double or exact).

#include "mann_job.h"
#include "report.h"
#include "files.h"
#include "mesh_output.h"
#include "point_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Mann/Continuity_adjustment.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>
#include <CGAL/Triangular_spline/tessellate.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace tspline {

namespace {

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

Json index_json(std::uint32_t face, const TS::Multi_index& index) {
  Json entry = Json::array();
  entry.push_back(face);
  entry.push_back(index.i);
  entry.push_back(index.j);
  entry.push_back(index.k);
  return entry;
}

// What the adjustment did; with `details`, the moved control points as [face, i, j, k]
// quadruples per changed edge and vertex.
Json adjustment_json(const TS::Network_adjustment& a, bool details) {
  Json result = Json::object();
  result["order"] = a.order;
  result["touched_points"] = a.number_of_touched_points();
  result["changed_edges"] = a.number_of_changed_edges();
  result["projected_vertices"] = a.vertices.size();
  if (!details)
    return result;
  Json edges = Json::array();
  for (const TS::Edge_adjustment& e : a.edges) {
    if (e.touched.empty())
      continue;
    Json entry = Json::object();
    entry["edge"] = e.edge;
    Json vertices = Json::array();
    vertices.push_back(e.vertices[0]);
    vertices.push_back(e.vertices[1]);
    entry["vertices"] = vertices;
    Json touched = Json::array();
    for (const TS::Touched_control_point& p : e.touched)
      touched.push_back(index_json(p.face, p.index));
    entry["touched"] = touched;
    edges.push_back(entry);
  }
  result["edges"] = edges;
  Json vertices = Json::array();
  for (const TS::Vertex_adjustment& v : a.vertices) {
    Json entry = Json::object();
    entry["vertex"] = v.vertex;
    entry["residual_before"] = v.residual;
    Json touched = Json::array();
    for (const TS::Touched_control_point& p : v.touched)
      touched.push_back(index_json(p.face, p.index));
    entry["touched"] = touched;
    vertices.push_back(entry);
  }
  result["vertices"] = vertices;
  return result;
}

Json continuity_json(const TS::Continuity_certificate& c) {
  Json result = Json::object();
  result["order"] = c.order;
  result["exact"] = c.exact;
  result["verdict"] = TS::verdict_name(c.verdict);
  result["certified"] = c.certified;
  result["lowest_order"] = c.lowest_order;
  result["failed_edges"] = c.failed_edges;
  result["max_residual"] = c.max_residual;
  return result;
}

std::string order_summary(const TS::Continuity_certificate& c) {
  return "C^" + std::to_string(c.order) + " on " +
         std::to_string(c.interior_edges - c.failed_edges) + " of " +
         std::to_string(c.interior_edges) + " interior edges (lowest order " +
         (c.lowest_order < 0 ? std::string("none: not C^0") : std::to_string(c.lowest_order)) + ")";
}

template <class Value>
Job_result adjust_file(std::istream& in, const Adjust_job& job, std::ostream& out) {
  Stopwatch clock, total;
  Json timings = Json::object();
  TS::Spline_file<Exact, Value> file = TS::read_spline_file<Exact, Value>(in, job.input);
  timings["read"] = clock.lap();
  const auto& domain = file.domain();
  auto& patches = file.patches();
  const int n = file.degree();
  const TS::Continuity_certificate before = TS::certify_continuity(file, job.order);
  timings["check_before"] = clock.lap();
  // A double build's file is C^k up to round-off: adjusting "repairs" the round-off by moving
  // most control points and writes rationals far longer than the input (issue 13).
  double scale = 1;
  for (const auto& p : patches)
    for (const Value& v : p.control_points())
      scale = (std::max)(scale, TS::max_abs_coordinate(v));
  if (!file.exact_values && before.failed_edges > 0 &&
      before.max_residual_log10 <= std::log10(1e-10 * scale))
    std::cerr << "tspline adjust: warning: " << job.input
              << " holds the values of a double build, C^" << job.order
              << " up to round-off (largest residual " << before.max_residual
              << "); adjusting moves control points on " << before.failed_edges
              << " edges and writes exact rationals far longer than the input; 'tspline certify "
                 "--tolerance "
              << 1e-10 * scale << "' accepts the round-off as it is\n";
  out << "patch network " << job.input << ": " << domain.number_of_vertices() << " vertices, "
      << domain.number_of_faces() << " patches of degree " << n << " ("
      << (TS::Value_traits<Value>::dimension == 1 ? "functional" : "parametric") << "), "
      << domain.number_of_interior_edges() << " interior edges\n"
      << "  before: " << order_summary(before) << "\n";

  const TS::Network_adjustment adjustment = TS::adjust_network(domain, patches, job.order);
  timings["adjust"] = clock.lap();
  const TS::Continuity_certificate after = TS::certify_continuity(file, job.order);
  const TS::Continuity_certificate c1 = TS::certify_continuity(file, 1);
  timings["certify"] = clock.lap();
  out << "  adjustment to C^" << job.order << " (exact): moved "
      << adjustment.number_of_touched_points() << " control points across "
      << adjustment.number_of_changed_edges() << " edges and around " << adjustment.vertices.size()
      << " vertices\n"
      << "  after: " << order_summary(after) << "\n";
  if (job.order == 1)
    out << "  " << certificate_summary(c1);
  else
    out << "  C^" << job.order
        << " certificate (exact rational arithmetic): " << (after.certified ? "PASSED" : "FAILED")
        << "\n";

  if (!job.output.empty()) {
    std::ofstream output = open_output(job.output);
    TS::write_spline_file(output, file);
    out << "  wrote " << job.output << "\n";
    timings["write"] = clock.lap();
  }
  timings["total"] = total.lap();

  Json report = Json::object();
  report["input"] = job.input;
  report["number_type"] = "exact";
  report["dimension"] = TS::Value_traits<Value>::dimension;
  report["degree"] = n;
  report["order"] = job.order;
  report["minimum_degree"] = TS::minimum_degree_for_network_continuity(job.order);
  report["vertices"] = domain.number_of_vertices();
  report["faces"] = domain.number_of_faces();
  report["interior_edges"] = domain.number_of_interior_edges();
  report["before"] = continuity_json(before);
  report["adjustment"] = adjustment_json(adjustment, true);
  report["after"] = continuity_json(after);
  // Exact arithmetic and no tolerance: a certified verdict here is a proof.
  report["certified_ck"] = after.verdict == TS::Certificate_verdict::PROOF;
  report["certified_c1"] = c1.verdict == TS::Certificate_verdict::PROOF;
  report["max_c1_residual"] = c1.max_residual;
  report["output"] = job.output.empty() ? Json() : Json(job.output);
  report["timings_seconds"] = timings;
  if (!job.report.empty())
    write_json_report(job.report, report);
  return {report, after.certified};
}

template <class K>
struct Input {
  TS::Planar_domain<K> domain;
  std::vector<typename K::FT> values;
  std::string kind;
};

template <class K>
Input<K> read_input(const std::string& path, const std::string& columns) {
  const std::string ext = lowercase_extension(path);
  if (ext == "xyz" || ext == "txt" || ext == "npy") {
    TS::Scattered_data<K> data;
    if (ext == "npy") {
      data = read_npy_scattered<K>(path, columns, false);
    } else {
      std::ifstream in = open_input(path);
      data = TS::read_xyz<K>(in, path);
    }
    auto [domain, values] = TS::delaunay_domain(data);
    return {std::move(domain), std::move(values), "scattered points, Delaunay triangulation"};
  }
  if (ext == "off" || ext == "obj" || ext == "ply" || ext == "stl") {
    auto [domain, values] = TS::read_mesh_domain<K>(path);
    return {std::move(domain), std::move(values), "triangle mesh, (x, y) as the domain"};
  }
  throw TS::Invalid_input("'" + path + "': unknown input format '." + ext +
                          "' (expected .xyz or .npy for scattered points, or "
                          ".off/.obj/.ply/.stl)");
}

template <class K>
Job_result mann(const Mann_job& job, std::ostream& out) {
  using FT = typename K::FT;
  Stopwatch clock, total;
  Json timings = Json::object();
  Input<K> input = read_input<K>(job.input, job.columns);
  timings["read_and_triangulate"] = clock.lap();
  const TS::Planar_domain<K>& domain = input.domain;

  const int order = TS::mann_derivative_order(job.degree);
  std::vector<int> degrees;
  const auto jets = TS::estimate_vertex_derivatives(domain, input.values, order, &degrees);
  // Small sets: the local polynomials' degree is lowered where the data cannot determine it.
  const std::size_t lowered = static_cast<std::size_t>(
      std::count_if(degrees.begin(), degrees.end(), [order](int d) { return d < order; }));
  const int lowest = degrees.empty() ? order : *std::min_element(degrees.begin(), degrees.end());
  timings["estimate_derivatives"] = clock.lap();
  const TS::Mann_interpolant<K> interpolant = TS::mann_interpolant(domain, jets, job.degree);
  timings["interpolant"] = clock.lap();
  const auto& patches = interpolant.patches();

  // Double builds: residuals are round-off, accepted up to a small multiple of the largest
  // control value (C^1: 1e-10, as `tspline c1`; C^k: 1e-8); exact builds: proofs.
  double scale = 1;
  for (const auto& p : patches)
    for (const FT& v : p.control_points())
      scale = (std::max)(scale, TS::max_abs_coordinate(v));
  const TS::Continuity_certificate c1 = TS::certify_continuity(
      interpolant, 1, TS::parameters::residual_tolerance(job.exact ? 0 : 1e-10 * scale));
  const TS::Continuity_certificate ck =
      TS::certify_continuity(interpolant, interpolant.continuity,
                             TS::parameters::residual_tolerance(job.exact ? 0 : 1e-8 * scale));
  timings["certify"] = clock.lap();

  // Interpolation error at the data points: the corner values of the incident patches.
  double max_vertex_error = 0;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = domain.face(f)[c];
      const FT difference = patches[f].evaluate(domain.point(v)) - input.values[v];
      max_vertex_error = (std::max)(max_vertex_error, std::abs(CGAL::to_double(difference)));
    }
  timings["vertex_error"] = clock.lap();

  Json report = Json::object();
  report["input"] = job.input;
  report["input_kind"] = input.kind;
  report["number_type"] = job.exact ? "exact" : "double";
  report["degree"] = job.degree;
  report["continuity"] = interpolant.continuity;
  report["derivative_order"] = order;
  report["derivatives"] = "estimated by local polynomial least squares";
  report["derivative_degree_lowered_vertices"] = lowered;
  report["lowest_derivative_degree"] = lowest;
  report["vertices"] = domain.number_of_vertices();
  report["faces"] = domain.number_of_faces();
  report["interior_edges"] = domain.number_of_interior_edges();
  report["boundary_edges"] = domain.number_of_boundary_edges();
  set_c1_certificate(report, c1);
  report["ck"] = continuity_json(ck);
  report["max_vertex_error"] = max_vertex_error;
  // Summary only: every interior edge moves points, the list would be as long as the mesh.
  report["adjustment"] = adjustment_json(interpolant.adjustment, false);

  if (!job.mesh.empty()) {
    report["mesh"] = write_tessellated_mesh(interpolant, job.levels, job.mesh);
    timings["tessellate_and_write"] = clock.lap();
  }
  if (!job.save.empty()) {
    std::ofstream file = open_output(job.save);
    TS::write_spline_file(file, interpolant);
    report["saved"] = job.save;
    timings["save"] = clock.lap();
  }
  timings["total"] = total.lap();
  report["timings_seconds"] = timings;

  out << "Mann interpolant over " << input.kind << "\n"
      << "  domain: " << domain.number_of_vertices() << " vertices, " << domain.number_of_faces()
      << " triangles, " << domain.number_of_interior_edges() << " interior edges\n"
      << "  derivatives up to order " << order
      << (lowered == 0
              ? std::string()
              : " (the local polynomial's degree lowered to " + std::to_string(lowest) + " at " +
                    std::to_string(lowered) + " vertices: too few points determine it)")
      << " estimated at every vertex (local least squares)\n"
      << "  degree " << job.degree << ", C^" << interpolant.continuity << " adjustment: moved "
      << interpolant.adjustment.number_of_touched_points() << " control points across "
      << interpolant.adjustment.number_of_changed_edges()
      << " edges, arithmetic: " << (job.exact ? "exact rationals" : "double") << "\n"
      << "  largest interpolation error at the data points: " << max_vertex_error << "\n"
      << "  " << certificate_summary(c1);
  if (interpolant.continuity > 1)
    out << "  C^" << interpolant.continuity << ": "
        << (ck.certified ? (ck.exact ? "PASSED (exact)" : "passed (tolerance)") : "FAILED") << "\n";
  if (!c1.exact)
    out << "  (double build: use --exact for an exact proof of C^1)\n";
  if (!job.report.empty())
    write_json_report(job.report, report);
  return {report, c1.certified && ck.certified};
}

} // namespace

Job_result run_adjust_job(const Adjust_job& job, std::ostream& out) {
  // The header says the dimension, which picks the value type; then read exactly.
  std::ifstream in = open_input(job.input);
  const int dimension = TS::spline_file_dimension(in);
  return dimension == 3 ? adjust_file<Exact::Vector_3>(in, job, out)
                        : adjust_file<Exact::FT>(in, job, out);
}

Job_result run_mann_job(const Mann_job& job, std::ostream& out) {
  return job.exact ? mann<Exact>(job, out) : mann<Fast>(job, out);
}

} // namespace tspline

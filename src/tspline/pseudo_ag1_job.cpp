// Xu's pseudo-AG^1 pipeline: read or generate a closed triangle mesh -> surface (double, or
// exact rationals for the rational presets) -> exact or residual certificate -> normal jumps
// and shape measures -> the same measures for PN triangles and Fang's order-1 blend on the
// same mesh -> outputs.

#include "pseudo_ag1_job.h"
#include "files.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/blending_sampler.h>
#include <CGAL/Triangular_spline/Comparators/PN_triangles.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Xu/AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/AG1_system.h>
#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>
#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace tspline {

namespace {

namespace TS = CGAL::Triangular_spline;
namespace PMP = CGAL::Polygon_mesh_processing;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Input_mesh = CGAL::Surface_mesh<Epick::Point_3>;

Input_mesh read_closed_mesh(const std::string& path) {
  std::vector<Epick::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  TS::read_mesh_soup(path, points, polygons); // counts, indices, finite coordinates
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (polygons[f].size() != 3)
      throw TS::Invalid_input(path + ": face " + std::to_string(f) + " has " +
                              std::to_string(polygons[f].size()) +
                              " vertices (pseudo-AG1 needs a triangle mesh)");
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw TS::Invalid_input(path + ": not a manifold, consistently oriented triangle mesh (an "
                                   "edge has more than two faces, a vertex several umbrellas, "
                                   "or neighbouring faces disagree on the orientation)");
  Input_mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

// PN triangles as a surface of patches (the sampler's interface).
struct PN_surface {
  using Patch = TS::Bezier_triangle<Epick, Epick::Vector_3>;
  std::vector<Patch> patches;
  const Patch& patch(Input_mesh::Face_index f) const { return patches[f]; }
};

Json measures_json(const TS::Closed_surface_measures& m, bool self_intersections_checked) {
  Json j = Json::object();
  Json jump = Json::object();
  jump["max"] = m.max_jump_deg;
  jump["mean_edge_max"] = m.mean_edge_max_jump_deg;
  jump["mean"] = m.mean_jump_deg;
  jump["rms"] = m.rms_jump_deg;
  jump["p50"] = m.p50_jump_deg;
  jump["p90"] = m.p90_jump_deg;
  jump["p95"] = m.p95_jump_deg;
  jump["p99"] = m.p99_jump_deg;
  Json histogram = Json::object();
  histogram["edges_deg"] = TS::jump_histogram_edges();
  histogram["samples"] = m.jump_histogram;
  jump["histogram"] = histogram;
  jump["max_unoriented"] = m.max_unoriented_jump_deg;
  jump["vertex_max"] = m.vertex_max_jump_deg;
  jump["input_mean_bend"] = m.mean_input_bend_deg;
  j["normal_jump_deg"] = jump;
  Json shape = Json::object();
  shape["volume_ratio"] = m.volume_ratio;
  shape["hausdorff_rel"] = m.hausdorff_rel;
  shape["rms_rel"] = m.rms_distance_rel;
  shape["inside_fraction"] = m.inside_fraction;
  shape["folded_samples"] = m.folded_samples;
  shape["singular_samples"] = m.singular_samples;
  if (self_intersections_checked)
    shape["self_intersecting"] = m.self_intersecting;
  else
    shape["self_intersecting"] = nullptr;
  shape["K_min"] = m.gaussian_min;
  shape["K_max"] = m.gaussian_max;
  j["shape"] = shape;
  return j;
}

std::string fixed(double x, int digits = 2) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

// Xu 6.1: the global AG^1 system on the (oriented) mesh, walked from one start umbrella, in
// K's number type; writes the walk's report and, on request, the AG^1 surface it defines.
template <class K>
Json solve_ag1_system(const Pseudo_ag1_job& job,
                      const CGAL::Surface_mesh<typename K::Point_3>& mesh, std::ostream& out) {
  using FT = typename K::FT;
  using Vertex_index = typename CGAL::Surface_mesh<typename K::Point_3>::Vertex_index;
  const Vertex_index start(static_cast<typename Vertex_index::size_type>(job.ag1_start));
  const TS::Umbrella<FT> umbrella = job.ag1_umbrella == "centroid"
                                        ? TS::centroid_umbrella<FT>(mesh.degree(start))
                                        : TS::projected_umbrella(mesh, start);
  const TS::AG1_walk<FT> walk = TS::walk_AG1_system(mesh, start, umbrella);
  Json r = Json::object();
  r["start"] = job.ag1_start;
  r["start_umbrella"] = job.ag1_umbrella;
  // a copy: the JSON binds by reference, and Boolean_tag::value has no definition to bind to
  r["exact"] = bool(CGAL::Algebraic_structure_traits<FT>::Is_exact::value);
  r["consistent"] = walk.consistent;
  r["complete"] = walk.complete;
  r["solved_vertices"] = walk.order.size();
  double worst = 0;
  for (double x : walk.residuals)
    if (std::isfinite(x))
      worst = std::max(worst, x);
  r["max_residual"] = worst;
  r["degenerate_vertices"] = walk.degenerate_vertices;
  r["under_determined_vertices"] = walk.under_determined_vertices;
  r["inconsistent_vertices"] = walk.inconsistent_vertices;
  r["folded_vertices"] = walk.folded_vertices;
  r["inadmissible_edges"] = walk.inadmissible_edges;
  r["non_convex_edges"] = walk.non_convex_edges;
  r["degenerate_frame_edges"] = walk.degenerate_frame_edges;
  auto number = [](const FT& x) -> Json {
    if constexpr (!CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
      return CGAL::to_double(x); // every digit, as a JSON number
    } else {
      std::ostringstream s;
      s << x; // exact rationals as "p/q", without rounding
      return s.str();
    }
  };
  Json relations = Json::array();
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e, 0);
    Json j = Json::object();
    j["edge"] = std::size_t(e);
    j["vertices"] = {std::size_t(mesh.source(h)), std::size_t(mesh.target(h))};
    if (walk.has_relation[e]) {
      const auto& R = walk.relations[e];
      j["lambda"] = number(R.lambda);
      j["mu"] = number(R.mu);
      j["nu"] = number(R.nu);
    }
    relations.push_back(j);
  }
  Json file = r;
  file["relations"] = relations; // orientation of halfedge(e, 0): q = lambda p + mu r + nu s
  write_json_report(job.ag1_system, file);
  r["path"] = job.ag1_system;
  out << "global AG^1 system (walk from vertex " << job.ag1_start << ", " << job.ag1_umbrella
      << " umbrella, " << (r["exact"].get<bool>() ? "exact" : "double")
      << "): " << walk.order.size() << "/" << mesh.number_of_vertices() << " vertices solved, "
      << (walk.consistent ? "consistent" : "INCONSISTENT") << ", "
      << walk.under_determined_vertices.size() << " under-determined, "
      << walk.inadmissible_edges.size() << " inadmissible edges (lambda >= 0), "
      << walk.folded_vertices.size() << " folded umbrellas\n";
  if (!job.ag1_save.empty()) {
    const TS::Surface_file<K> surface = TS::ag1_surface_from_walk<K>(mesh, walk);
    std::ofstream f = open_output(job.ag1_save);
    TS::write_surface_file(f, surface);
    f.close();
    if (!f)
      throw std::runtime_error("writing '" + job.ag1_save + "' failed");
    r["saved"] = job.ag1_save;
  }
  return r;
}

template <class K>
Json build(const Pseudo_ag1_job& job, const Input_mesh& input, std::ostream& out, Json& report) {
  using Mesh = CGAL::Surface_mesh<typename K::Point_3>;
  Stopwatch clock;
  Json seconds = Json::object();
  Mesh mesh;
  {
    std::vector<typename Mesh::Vertex_index> map;
    for (auto v : input.vertices()) {
      const auto& p = input.point(v);
      map.push_back(mesh.add_vertex(typename K::Point_3(p.x(), p.y(), p.z())));
    }
    for (auto f : input.faces()) {
      std::vector<typename Mesh::Vertex_index> t;
      for (auto v : CGAL::vertices_around_face(input.halfedge(f), input))
        t.push_back(map[std::size_t(v)]);
      mesh.add_face(t);
    }
  }
  progress("pseudo-ag1", "building the surface", input.number_of_faces() > 20000);
  const TS::Pseudo_AG1_surface<K> surface(mesh, job.options);
  seconds["build"] = clock.lap();
  const auto& summary = surface.mesh_summary();
  Json m = Json::object();
  m["vertices"] = summary.vertices;
  m["edges"] = summary.edges;
  m["faces"] = summary.faces;
  m["components"] = summary.components.size();
  long euler = 0;
  for (const auto& c : summary.components)
    euler += c.euler;
  m["euler"] = euler;
  m["genus"] = summary.components.size() == 1 ? Json(summary.components[0].genus) : Json(nullptr);
  m["reoriented"] = summary.reoriented;
  report["mesh"] = m;
  report["faces"] = summary.faces;
  report["exact"] = surface.is_exact();

  progress("pseudo-ag1", "certifying", input.number_of_faces() > 20000);
  const TS::Pseudo_AG1_certificate c = TS::certify_pseudo_AG1(surface);
  seconds["certify"] = clock.lap();
  Json cert = Json::object();
  cert["exact"] = c.exact;
  cert["tolerance"] = c.tolerance;
  cert["edges"] = c.edges;
  cert["c0_edges"] = c.c0_edges;
  cert["middle_edges"] = c.middle_edges;
  cert["ag1_edges"] = c.ag1_edges;
  cert["inadmissible_edges"] = c.inadmissible_edges;
  cert["coplanar_vertices"] = c.coplanar_vertices;
  cert["g1_vertices"] = c.g1_vertices;
  cert["max_edge_residual"] = c.max_edge_residual;
  cert["max_coplanarity"] = c.max_coplanarity;
  cert["pseudo_ag1"] = c.pseudo_AG1();
  report["certificate"] = cert;
  report["certified_c0"] = c.c0_edges == c.edges;
  report["vertex_g1"] = c.g1_vertices == c.vertices;
  report["ag1_edges"] = c.ag1_edges;

  if (!job.ag1_system.empty()) {
    progress("pseudo-ag1", "solving the global AG^1 system", input.number_of_faces() > 20000);
    report["ag1_system"] = solve_ag1_system<K>(job, surface.mesh(), out);
    seconds["ag1_system"] = clock.lap();
  }

  progress("pseudo-ag1", "measuring", input.number_of_faces() > 20000);
  const std::size_t tessellated = summary.faces << (2 * job.levels);
  const bool check_self = tessellated <= 400000;
  const TS::Patch_sampler<TS::Pseudo_AG1_surface<K>> sampler(surface);
  const TS::Closed_surface_measures measures =
      TS::measure_closed_surface(surface.mesh(), sampler, job.samples, job.levels, check_self);
  seconds["measure"] = clock.lap();
  const Json mj = measures_json(measures, check_self);
  report["normal_jump_deg"] = mj["normal_jump_deg"];
  report["max_normal_jump_deg"] = measures.max_jump_deg;
  report["mean_normal_jump_deg"] = measures.mean_jump_deg;
  report["shape"] = mj["shape"];
  report["volume_ratio"] = measures.volume_ratio;

  // AG^1 defect and undulation (M4, M6)
  double defect_max = 0, defect_sum = 0, worst_dip = -1e300;
  for (auto e : surface.mesh().edges()) {
    const auto& E = surface.edge_relation(e);
    for (std::size_t i = 0; i < 3; ++i) {
      const double d = std::max(std::abs(CGAL::to_double(E.end_r[i] - E.relation[i])),
                                std::abs(CGAL::to_double(E.end_s[i] - E.relation[i])));
      defect_max = std::max(defect_max, d);
      defect_sum += d / 3;
    }
    worst_dip = std::max(worst_dip, surface.dip(e));
  }
  const TS::Pseudo_AG1_flags f = surface.flags();
  Json defect = Json::object();
  defect["max"] = defect_max;
  defect["mean"] = summary.edges ? defect_sum / double(summary.edges) : 0.0;
  report["ag1_defect"] = defect;
  Json undulation = Json::object();
  undulation["dipping_edges"] = f.dipping_edges;
  undulation["worst_dip"] = worst_dip;
  report["undulation"] = undulation;

  Json flags = Json::object();
  f.for_each([&](const char* name, std::size_t count) {
    if (std::string(name) != "dipping_edges") // reported under undulation
      flags[name] = count;
  });
  report["flags"] = flags;

  if (job.per_edge) {
    Json edges = Json::array();
    for (auto e : surface.mesh().edges()) {
      const auto h = TS::canonical_halfedge(e, surface.mesh());
      const auto& E = c.per_edge[e];
      Json j = Json::object();
      j["vertices"] = {std::size_t(surface.mesh().source(h)),
                       std::size_t(surface.mesh().target(h))};
      j["max_jump_deg"] = measures.edge_max_jump_deg[e];
      j["mean_jump_deg"] = measures.edge_mean_jump_deg[e];
      j["c0"] = E.c0;
      j["middle"] = E.middle;
      j["ag1"] = E.ag1;
      j["dip"] = surface.dip(e);
      edges.push_back(j);
    }
    report["per_edge"] = edges;
  }

  if (!job.save.empty()) {
    std::ofstream file = open_output(job.save);
    TS::write_surface_file(file, surface);
    file.close();
    if (!file)
      throw std::runtime_error("writing '" + job.save + "' failed");
    report["saved"] = job.save;
  }
  if (!job.mesh.empty()) {
    const CGAL::Surface_mesh<Epick::Point_3> tm = TS::tessellation_mesh(
        TS::tessellate_closed_surface(surface.mesh(), sampler, job.mesh_levels, job.split_normals),
        true);
    TS::write_mesh(job.mesh, tm);
    Json o = Json::object();
    o["path"] = job.mesh;
    o["levels"] = job.mesh_levels;
    o["vertices"] = tm.number_of_vertices();
    o["faces"] = tm.number_of_faces();
    o["split_normals"] = job.split_normals;
    report["output"] = o;
  }
  seconds["outputs"] = clock.lap();

  out << "pseudo-AG1 surface (preset " << job.preset
      << (surface.is_exact() ? ", exact rational arithmetic" : ", double")
      << "): " << summary.vertices << " vertices, " << summary.edges << " edges, " << summary.faces
      << " faces";
  if (summary.components.size() == 1)
    out << ", genus " << summary.components[0].genus;
  else
    out << ", " << summary.components.size() << " components";
  if (summary.reoriented)
    out << " (" << summary.reoriented << " reoriented outward)";
  out << "\n";
  out << "certificate (" << (c.exact ? "exact rational arithmetic" : "residuals") << "): C^0 "
      << c.c0_edges << "/" << c.edges << " edges, middle diamonds " << c.middle_edges << "/"
      << c.edges << ", G^1 at " << c.g1_vertices << "/" << c.vertices << " vertices, AG^1 "
      << c.ag1_edges << "/" << c.edges << " edges: "
      << (c.pseudo_AG1() ? (c.exact ? "pseudo-AG^1 PROVED" : "pseudo-AG^1 (within tolerance)")
                         : "NOT pseudo-AG^1")
      << "\n";
  out << "normal jump across edges: max " << fixed(measures.max_jump_deg) << " deg, mean "
      << fixed(measures.mean_jump_deg) << " deg (input bend " << fixed(measures.mean_input_bend_deg)
      << " deg); at vertices " << std::setprecision(2) << std::scientific
      << measures.vertex_max_jump_deg << std::defaultfloat << " deg\n";
  out << "jump histogram (share of samples):";
  {
    const auto& edges = TS::jump_histogram_edges();
    const double total = double(summary.edges) * double(job.samples);
    for (std::size_t i = 0; i < measures.jump_histogram.size(); ++i)
      if (measures.jump_histogram[i] > 0)
        out << " " << edges[i] << "-" << edges[i + 1] << " deg " << std::setprecision(3)
            << 100 * double(measures.jump_histogram[i]) / total << "%";
    out << std::defaultfloat << "\n";
  }
  out << "shape: volume ratio " << fixed(measures.volume_ratio, 3) << ", distance to input "
      << fixed(100 * measures.hausdorff_rel) << "% of the diagonal, dipping edges "
      << f.dipping_edges << "/" << summary.edges << ", self-intersecting "
      << (!check_self ? std::string("not checked (tessellation of ") + std::to_string(tessellated) +
                            " triangles; lower --levels)"
          : measures.self_intersecting ? "YES"
                                       : "no");
  if (f.raised())
    out << "; flags: " << f.recentred_vertices << " re-centred, " << f.folded_projections
        << " folded projections, " << f.equalised_umbrellas << " equalised, " << f.normal_fallbacks
        << " normal fallbacks, " << f.inverted_corners << " inverted corners, "
        << f.averaged_map_fallbacks << " averaged-map fallbacks";
  out << "\n";
  return seconds;
}

} // namespace

Surface_certify_result run_certify_surface_job(const std::string& path, double tolerance,
                                               std::ostream& out) {
  std::ifstream in = open_input(path);
  const TS::Surface_file<Exact> file = TS::read_surface_file<Exact>(in, path);
  const TS::Pseudo_AG1_view<TS::Surface_file<Exact>> view(file);
  const TS::Pseudo_AG1_certificate c = TS::certify_pseudo_AG1(view, tolerance);
  Surface_certify_result result;
  result.certified = c.pseudo_AG1();
  const std::string verdict = !result.certified ? "failed" : c.exact ? "proof" : "within_tolerance";
  Json& r = result.report;
  r["input"] = path;
  r["kind"] = "pseudo-AG1 surface";
  r["number_type"] = file.exact_numbers() ? "exact" : "double";
  r["verdict"] = verdict;
  r["exact"] = c.exact;
  r["tolerance"] = c.tolerance;
  r["edges"] = c.edges;
  r["c0_edges"] = c.c0_edges;
  r["middle_edges"] = c.middle_edges;
  r["ag1_edges"] = c.ag1_edges;
  r["vertices"] = c.vertices;
  r["g1_vertices"] = c.g1_vertices;
  r["coplanar_vertices"] = c.coplanar_vertices;
  r["max_edge_residual"] = c.max_edge_residual;
  Json failing = Json::array();
  for (auto e : file.mesh().edges()) {
    const auto& E = c.per_edge[e];
    if (E.middle)
      continue;
    const auto h = TS::canonical_halfedge(e, file.mesh());
    Json j = Json::object();
    j["vertices"] = {std::size_t(file.mesh().source(h)), std::size_t(file.mesh().target(h))};
    j["c0"] = E.c0;
    j["relation_determined"] = view.relation_determined(e);
    j["residual"] = E.middle_residual;
    failing.push_back(j);
  }
  r["failing_edges"] = failing;
  std::ostringstream tol;
  tol << "tolerance " << c.tolerance;
  out << "pseudo-AG^1 certificate of " << path << " ("
      << (c.exact ? std::string("exact rational arithmetic") : tol.str()) << "): C^0 " << c.c0_edges
      << "/" << c.edges << " edges, middle diamonds " << c.middle_edges << "/" << c.edges
      << ", G^1 at " << c.g1_vertices << "/" << c.vertices << " vertices, AG^1 " << c.ag1_edges
      << "/" << c.edges << " edges: "
      << (verdict == "proof"    ? "PROVED"
          : verdict == "failed" ? "FAILED"
                                : "within tolerance")
      << "\n";
  std::size_t shown = 0;
  for (const auto& j : failing)
    if (shown++ < 10)
      out << "  edge " << j["vertices"][0] << "-" << j["vertices"][1]
          << (j["c0"].get<bool>() ? ": middle diamonds disagree" : ": not C^0") << ", residual "
          << j["residual"].get<double>() << "\n";
  if (!result.certified && c.exact && !file.exact_numbers())
    out << "  the file holds doubles (a double build): its residuals are round-off; certify it "
           "with --tolerance T (absolute), or build it exactly (--preset exact)\n";
  return result;
}

std::string pseudo_ag1_shape_names() {
  std::string s;
  for (const std::string& name : TS::thesis_polyhedron_names())
    s += (s.empty() ? "" : ", ") + name;
  return s;
}

Json run_pseudo_ag1_job(const Pseudo_ag1_job& given, std::ostream& out) {
  Stopwatch clock, total;
  Pseudo_ag1_job job = given;
  Json report = Json::object();
  Input_mesh input;
  if (!job.shape.empty()) {
    input = TS::thesis_polyhedron<Epick>(job.shape);
    report["input"] = "shape:" + job.shape;
  } else {
    input = read_closed_mesh(job.input);
    report["input"] = job.input;
  }
  if (!job.ag1_system.empty()) { // before the build: fail fast
    if (job.ag1_start < 0 || std::size_t(job.ag1_start) >= input.number_of_vertices())
      throw TS::Invalid_input("--ag1-start " + std::to_string(job.ag1_start) +
                              " is not a vertex (the mesh has " +
                              std::to_string(input.number_of_vertices()) + ")");
    // measured: 14 vertices 0.03 s, pentakis (32) over 30 s, the 12x6 torus (72) 8.5 minutes
    constexpr std::size_t exact_limit = 16;
    if (job.exact && input.number_of_vertices() > exact_limit)
      throw TS::Invalid_input("--ag1-system in exact arithmetic is limited to " +
                              std::to_string(exact_limit) + " vertices (the mesh has " +
                              std::to_string(input.number_of_vertices()) +
                              "): the walk's rationals grow exponentially along it; drop --exact "
                              "to solve the system in double");
  }
  if (job.levels < 0) {
    job.levels = 3;
    while (job.levels > 0 && (input.number_of_faces() << (2 * job.levels)) > 1000000)
      --job.levels;
  }
  Json options = Json::object();
  const auto& o = job.options;
  options["preset"] = job.preset;
  options["normal"] = o.normal == TS::Corner_plane_normal::CENTROID  ? "centroid"
                      : o.normal == TS::Corner_plane_normal::AVERAGE ? "average"
                                                                     : "area";
  options["tau"] = o.plane_position;
  options["undulation_gain"] = o.undulation_gain;
  options["threshold_deg"] = o.undulation_threshold * 180 / CGAL_PI;
  options["placement"] = o.placement == TS::Star_placement::UMBRELLA ? "umbrella" : "projection";
  options["recentering"] = o.recentering;
  options["star_scale"] = o.star_scale;
  options["shrink"] = o.automatic_shrinking ? "auto" : "none";
  options["offsets"] = {o.offsets[0], o.offsets[1], o.offsets[2]};
  options["inner"] = o.inner == TS::Inner_placement::NORMAL_OFFSET ? "offset" : "cross-edge";
  options["edge_map"] = o.edge_map == TS::Edge_map::PARALLELOGRAM ? "parallelogram" : "averaged";
  options["min_weight"] = o.min_averaged_weight;
  options["flip"] = o.flips == TS::Flip_rule::SYMMETRIC     ? "symmetric"
                    : o.flips == TS::Flip_rule::LARGER_FACE ? "larger-face"
                                                            : "lower-index";
  options["samples"] = job.samples;
  options["levels"] = job.levels;
  report["options"] = options;

  Json seconds =
      job.exact ? build<Exact>(job, input, out, report) : build<Epick>(job, input, out, report);

  if (job.compare) {
    progress("pseudo-ag1", "comparing", input.number_of_faces() > 20000);
    Json comparison = Json::object();
    const bool check_self = (input.number_of_faces() << (2 * job.levels)) <= 400000;
    PN_surface pn{TS::pn_triangles<Epick>(input)};
    const TS::Patch_sampler<PN_surface> pn_sampler(pn);
    const auto pn_m =
        TS::measure_closed_surface(input, pn_sampler, job.samples, job.levels, check_self);
    comparison["pn_triangles"] = measures_json(pn_m, check_self);
    double fang_jump = -1;
    try {
      TS::Mesh_blending_options bo;
      bo.order = 1;
      const TS::Mesh_blending_surface<Epick::Point_3> blend(input, bo);
      const TS::Mesh_blending_sampler<Epick::Point_3> blend_sampler(blend);
      const auto fang_m =
          TS::measure_closed_surface(input, blend_sampler, job.samples, job.levels, check_self);
      comparison["fang_order1"] = measures_json(fang_m, check_self);
      fang_jump = fang_m.mean_jump_deg;
    } catch (const TS::Invalid_input& e) {
      comparison["fang_order1"] = {{"error", e.what()}};
    }
    report["comparison"] = comparison;
    seconds["compare"] = clock.lap();
    out << "comparison, mean normal jump: PN triangles " << fixed(pn_m.mean_jump_deg)
        << " deg (max " << fixed(pn_m.max_jump_deg) << "), Fang order 1 "
        << (fang_jump >= 0 ? fixed(fang_jump) + " deg" : std::string("failed")) << "\n";
  }
  seconds["total"] = total.lap();
  report["timings"] = seconds;
  if (!job.report.empty())
    write_json_report(job.report, report);
  return report;
}

} // namespace tspline

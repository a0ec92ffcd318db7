// tspline c1 and tspline certify: argument handling; the work is in c1_job.cpp.

#include "c1_job.h"
#include "cli.h"
#include "commands.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_c1(const std::vector<std::string>& args) {
  Argument_parser parser("c1", std::string(command_summary("c1")));
  parser.describe(
      "Builds Xu's C^1 quintic spline over a planar triangulation: prescribes a minimal "
      "determining set of control points from the data and propagates the others, "
      "handles degenerate frames, and certifies C^1 continuity on every interior edge "
      "(exactly with --exact).");
  parser.describe("Input: '.xyz' (one 'x y z' per line, Delaunay triangulation of (x, y)) or a "
                  "triangle mesh (.off/.obj/.ply/.stl) whose vertex (x, y) is the domain and z "
                  "the height; holes and non-convex boundaries of a mesh are kept.");
  parser.add_option("input", "FILE", "scattered points (.xyz) or triangle mesh");
  parser.add_option(
      "fit", "MODE",
      "adaptive (interpolate; local polynomials where they resolve the data, "
      "least thin-plate energy where they do not: accurate on dense and sparse "
      "data), local (interpolate; every prescribed point from the local polynomial of its "
      "nearest vertex, a weighted least-squares fit of degree up to --degree: "
      "reproduces polynomials of that degree where the data determine them), energy "
      "(interpolate with the least thin-plate energy: the fairest surface, best on "
      "sparse data), lsq "
      "(interpolate; all control points closest to the local "
      "polynomials, global solve), tangent (interpolate values and estimated "
      "gradients), interpolate (corners through the data, polar blend elsewhere), "
      "approximate (Xu's polar blend of the vertex data)",
      "adaptive");
  parser.add_option("degree", "D",
                    "largest degree of the local polynomial fits of --fit adaptive, local and "
                    "lsq (0..5; "
                    "lowered where the neighbourhood does not determine it)",
                    "5");
  parser.add_option("degree-selection", "RULE",
                    "how each vertex's degree is chosen: cv (leave-one-out cross-validation, "
                    "the lowest degree predicting nearly as well as the best) or largest",
                    "cv");
  parser.add_option("smoothing", "LAMBDA",
                    "with --fit energy: stop interpolating and minimise sum of squared residuals "
                    "+ LAMBDA h^2 thin-plate energy (h^2 the area per data point; 0 interpolates)",
                    "0");
  parser.add_switch("gradients",
                    "the input has known gradients, 'x y z zx zy' per line: the spline "
                    "interpolates them at every vertex");
  parser.add_switch("rescale",
                    "triangulate and fit with y scaled by the power of two that makes its extent "
                    "closest to x's (for coordinates in different units, like scipy's "
                    "rescale=True); the spline is returned over the data's own coordinates");
  parser.add_option("fix", "FIX",
                    "degenerate frames: reroute (local re-routing) or perturb "
                    "(move vertices slightly)",
                    "reroute");
  parser.add_switch("exact", "exact rational arithmetic: the certificate is a proof");
  parser.add_switch("dimension",
                    "also compute dim S^1_5 from the rank of the C^1 conditions (modulo a prime: "
                    "an upper bound, a proof when it equals the free parameters)");
  parser.add_option("report", "FILE.json", "write the JSON report");
  parser.add_option("mesh", "FILE", "write the tessellated surface (.ply/.off/.obj)");
  parser.add_option("levels", "L", "4-split levels of the tessellation (0..8)", "3");
  parser.add_option("save", "FILE.spline", "save the spline (domain and control points)");
  parser.add_option("query", "FILE.xy", "evaluate at these points ('x y' per line)");
  parser.add_option("values", "OUT.txt", "one value per query point, 'nan' outside the domain");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  if (!parsed.has("input"))
    throw Usage_error("missing --input FILE (see 'tspline c1 --help'; 'tspline demo' needs none)");
  C1_job job;
  job.input = parsed.value("input");
  job.fit = parsed.value("fit");
  job.fix = parsed.value("fix");
  job.exact = parsed.is_set("exact");
  job.dimension = parsed.is_set("dimension");
  job.rescale = parsed.is_set("rescale");
  job.gradients = parsed.is_set("gradients");
  job.levels = static_cast<int>(parsed.integer("levels"));
  job.degree = static_cast<int>(parsed.integer_in("degree", 0, 5));
  job.degree_selection = parsed.value("degree-selection");
  job.smoothing = parsed.number("smoothing");
  for (const auto& [name, field] : {std::pair<const char*, std::string*>{"report", &job.report},
                                    {"mesh", &job.mesh},
                                    {"save", &job.save},
                                    {"query", &job.query},
                                    {"values", &job.values}})
    if (parsed.has(name))
      *field = parsed.value(name);
  if (job.query.empty() != job.values.empty())
    throw Usage_error("--query and --values go together");
  run_c1_job(job, std::cout);
  return 0;
}

int run_certify(const std::vector<std::string>& args) {
  Argument_parser parser("certify", std::string(command_summary("certify")));
  parser.describe("Reads a saved spline (format 'tspline-spline 1', see the manual) and checks "
                  "Xu's C^1 conditions (3.4) and (3.5) on every interior edge with exact rational "
                  "arithmetic. The verdict is 'proof' when every condition holds exactly, "
                  "'within_tolerance' when --tolerance accepts nonzero residuals (not a proof), "
                  "'failed' otherwise. Exit status 0 for proof and within_tolerance, 1 for failed "
                  "(the failing edges are named); a spline saved by a double build fails without "
                  "--tolerance (its residuals are round-off; 'tspline c1' prints the tolerance it "
                  "used).");
  parser.add_positional("FILE.spline", "the spline to check");
  parser.add_option("report", "FILE.json", "write the per-edge results as JSON");
  parser.add_option("tolerance", "T",
                    "accept edges whose exact residual is at most T (for splines built in double)");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  const double tolerance = parsed.has("tolerance") ? parsed.number("tolerance") : -1.0;
  if (parsed.has("tolerance") && !(tolerance >= 0 && std::isfinite(tolerance)))
    throw Usage_error("--tolerance must be a finite number >= 0");
  const Certify_result result = run_certify_job(parsed.positionals().at(0), tolerance, std::cout);
  if (parsed.has("report")) {
    std::ofstream file(parsed.value("report"));
    if (!file)
      throw std::runtime_error("cannot write '" + parsed.value("report") + "'");
    result.report.write(file);
    file << '\n';
  }
  if (!result.certified)
    std::cerr << "tspline certify: NOT C^1: the failing edges are listed above"
              << (result.round_off_hint.empty() ? "" : "; " + result.round_off_hint) << "\n";
  return result.certified ? 0 : 1;
}

} // namespace tspline

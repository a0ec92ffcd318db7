// tspline c1 and tspline certify: argument handling; the work is in c1_job.cpp.

#include "c1_job.h"
#include "command_line.h"
#include "commands.h"
#include "files.h"
#include "pseudo_ag1_job.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_c1(const std::vector<std::string>& args) {
  C1_job job;
  Command_line cl("c1");
  cl.describe("Builds Xu's C^1 quintic spline over a planar triangulation: prescribes a minimal "
              "determining set of control points from the data and propagates the others, "
              "handles degenerate frames, and certifies C^1 continuity on every interior edge "
              "(exactly with --exact).");
  cl.describe("Input: '.xyz' (one 'x y z' per line, Delaunay triangulation of (x, y)), '.csv' "
              "(a header line naming the columns; --columns chooses them), '.npy' (a NumPy "
              "(n, 3) array, or (n, k) with --columns choosing columns by index) or a "
              "triangle mesh (.off/.obj/.ply/.stl) whose vertex (x, y) is the domain and z "
              "the height; holes and non-convex boundaries of a mesh are kept.");
  cl.input(job.input, "FILE", "scattered points (.xyz, .csv, .npy) or triangle mesh");
  cl.text(job.columns, "columns", "X,Y,Z",
          "the header names of the x, y and z columns of a .csv input, or their indices "
          "(from 0) in a .npy array (and of zx, zy with --gradients); default: the columns "
          "named x, y, z, or all the columns of an (n, 3) array");
  cl.text(job.fit, "fit", "MODE",
          "adaptive (interpolate; local polynomials where they resolve the data, "
          "least thin-plate energy with a tension toward the piecewise linear "
          "interpolant where they do not: accurate on dense and sparse data), local (interpolate; "
          "every prescribed point from the local polynomial of its "
          "nearest vertex, a weighted least-squares fit of degree up to --degree: "
          "reproduces polynomials of that degree where the data determine them), energy "
          "(interpolate with the least thin-plate energy: the fairest surface, best on "
          "sparse data), lsq "
          "(interpolate; all control points closest to the local "
          "polynomials, global solve), tangent (interpolate values and estimated "
          "gradients), interpolate (corners through the data, polar blend elsewhere), "
          "approximate (Xu's polar blend of the vertex data)");
  cl.integer(job.degree, "degree", "D",
             "largest degree of the local polynomial fits of --fit adaptive, local and "
             "lsq (0..5; "
             "lowered where the neighbourhood does not determine it)",
             0, 5);
  cl.text(job.degree_selection, "degree-selection", "RULE",
          "how each vertex's degree is chosen: cv (leave-one-out cross-validation, "
          "the lowest degree predicting nearly as well as the best) or largest");
  cl.number(job.smoothing, "smoothing", "LAMBDA",
            "with --fit energy: stop interpolating and minimise sum of squared residuals "
            "+ LAMBDA h^2 thin-plate energy (h^2 the area per data point; 0 interpolates)");
  double tension = 0;
  cl.number(tension, "tension", "TAU",
            "with --fit adaptive or energy: add (TAU / h^2) times the integral of |grad s - "
            "grad g|^2 to the thin-plate energy, g the piecewise linear interpolant of the "
            "data (larger: closer to g, less overshoot; 0: the thin plate alone); default 2 "
            "for adaptive (times each vertex's distrust of its polynomial), 0 for energy");
  cl.flag(job.gradients, "gradients",
          "the input has known gradients, 'x y z zx zy' per line: the spline "
          "interpolates them at every vertex");
  cl.flag(job.rescale, "rescale",
          "triangulate and fit with y scaled by the power of two that makes its extent "
          "closest to x's (for coordinates in different units, like scipy's "
          "rescale=True); the spline is returned over the data's own coordinates");
  cl.text(job.fix, "fix", "FIX",
          "degenerate frames: reroute (local re-routing) or perturb "
          "(move vertices slightly)");
  cl.flag(job.exact, "exact", "exact rational arithmetic: the certificate is a proof");
  cl.flag(job.dimension, "dimension",
          "also prove dim S^1_5 exactly: the plan's rules imply every C^1 condition "
          "(checked in exact rationals: dim >= free parameters) and the rank of the C^1 "
          "conditions modulo a prime bounds it from above (another prime, then the slow "
          "rational rank, when they disagree); about 3 CPU seconds per 10^4 points");
  cl.output(job.save, "output", "FILE.spline", "save the spline (domain and control points)", {},
            {"save"});
  cl.report(job.report);
  cl.output(job.mesh, "mesh", "FILE", "write the tessellated surface (.ply/.off/.obj)",
            mesh_file_output);
  cl.integer(job.levels, "levels", "L", "4-split levels of the tessellation (0..8)", 0, 8);
  cl.text(job.query, "query", "FILE.xy",
          "evaluate at these points ('x y' per line, or the columns 0 and 1 of a .npy array)");
  cl.output(job.values, "values", "OUT.txt",
            "one value per query point, 'nan' outside the domain ('-': stdout)", {{}, true});
  if (!cl.parse(args))
    return 0;
  if (cl.given("tension"))
    job.tension = tension;
  if (job.input.empty())
    throw Usage_error("missing --input FILE (see 'tspline c1 --help'; 'tspline demo' needs none)");
  if (job.query.empty() != job.values.empty())
    throw Usage_error("--query and --values go together");
  run_c1_job(job, cl.summary_stream());
  return 0;
}

int run_certify(const std::vector<std::string>& args) {
  std::string input, report;
  double tolerance = -1.0; // < 0: exact verdict
  Command_line cl("certify");
  cl.describe(
      "Reads a saved spline (format 'tspline-spline 1', see the manual) and checks "
      "Xu's C^1 conditions (3.4) and (3.5) on every interior edge with exact rational "
      "arithmetic; or a saved pseudo-AG^1 surface (FILE.surface, 'tspline-surface 1'): "
      "C^0 on every edge, the middle diamonds of each edge on one relation (solved from "
      "the nets), G^1 at every vertex. The verdict is 'proof' when every condition holds exactly, "
      "'within_tolerance' when --tolerance accepts nonzero residuals (not a proof), "
      "'failed' otherwise. Exit status 0 for proof and within_tolerance, 1 for failed "
      "(the failing edges are named); a spline saved by a double build fails without "
      "--tolerance (its residuals are round-off; 'tspline c1' prints the tolerance it "
      "used).");
  cl.input(input, "FILE", "the spline (.spline) or surface (.surface) to check", true);
  cl.report(report, "write the per-edge results as JSON");
  cl.number(tolerance, "tolerance", "T",
            "accept edges whose exact residual is at most T (for splines built in double)", false);
  if (!cl.parse(args))
    return 0;
  if (input.empty())
    throw Usage_error("missing argument FILE.spline (or --input FILE.spline, or a .surface)");
  if (cl.given("tolerance") && !(tolerance >= 0))
    throw Usage_error("--tolerance must be a finite number >= 0");
  if (lowercase_extension(input) == "surface") {
    const Surface_certify_result result =
        run_certify_surface_job(input, tolerance, cl.summary_stream());
    if (!report.empty())
      write_json_report(report, result.report);
    if (!result.certified)
      std::cerr << "tspline certify: NOT pseudo-AG^1: the failing edges are listed above\n";
    return result.certified ? 0 : 1;
  }
  const Certify_result result = run_certify_job(input, tolerance, cl.summary_stream());
  if (!report.empty())
    write_json_report(report, result.report);
  if (!result.certified)
    std::cerr << "tspline certify: NOT C^1: the failing edges are listed above"
              << (result.round_off_hint.empty() ? "" : "; " + result.round_off_hint) << "\n";
  return result.certified ? 0 : 1;
}

} // namespace tspline

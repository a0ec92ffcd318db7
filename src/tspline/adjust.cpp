// tspline adjust and tspline mann: argument handling; the work is in mann_job.cpp.

#include "cli.h"
#include "commands.h"
#include "mann_job.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_adjust(const std::vector<std::string>& args) {
  Argument_parser parser("adjust", std::string(command_summary("adjust")));
  parser.describe(
      "Reads a patch network (a 'tspline-spline 1' file: a planar triangulation and one Bezier "
      "patch of any degree per triangle, functional or parametric) exactly, and raises it to C^k "
      "across every interior edge with Mann's averaging adjustment: first the C^k conditions "
      "around each vertex, then for l = 0..k the order-l conditions of every edge. Points that "
      "already meet the conditions are not moved: a C^k network is returned unchanged.");
  parser.describe("The degree must be at least 4k+1 (Mann 3.1): C^1 needs quintics, C^2 degree 9. "
                  "The result is certified exactly (C^k, and C^1 for the report). Exit status 0 "
                  "when the result is certified C^k.");
  parser.add_option("input", "NETWORK.spline", "the patch network to adjust");
  parser.add_option("order", "K", "the continuity order k to reach (0 <= 4k+1 <= degree)");
  parser.add_option("output", "FILE.spline", "write the adjusted network (exact numbers)");
  parser.add_option("report", "FILE.json",
                    "write a JSON report (continuity before and after, moved control points)");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  if (!parsed.has("input"))
    throw Usage_error("missing --input NETWORK.spline");
  if (!parsed.has("order"))
    throw Usage_error("missing --order K");
  Adjust_job job;
  job.input = parsed.value("input");
  job.order = parsed.integer_in("order", 0, 20);
  if (parsed.has("output"))
    job.output = parsed.value("output");
  if (parsed.has("report"))
    job.report = parsed.value("report");
  const Job_result result = run_adjust_job(job, std::cout);
  if (!result.certified)
    std::cerr << "tspline adjust: the adjusted network is NOT C^" << job.order << "\n";
  return result.certified ? 0 : 1;
}

int run_mann(const std::vector<std::string>& args) {
  Argument_parser parser("mann", std::string(command_summary("mann")));
  parser.describe(
      "Builds Mann's simple interpolant: derivatives up to order floor(2n/3) are estimated at "
      "every data point by local polynomial least squares (an estimate: exact only for data from "
      "a polynomial of that degree), each patch's control points are set from the Taylor "
      "polynomial of the nearest vertex (averaged on ties), giving a C^0 network, and the "
      "averaging adjustment raises it to "
      "C^floor((n-1)/4) (C^1 for the default quintic). The result is certified C^1 (exactly "
      "with --exact). Precision: data from a polynomial of degree floor(2n/3) (3 for the "
      "default quintic) are reproduced exactly, since the estimated derivatives are then "
      "exact; Mann's degree-n precision needs exact derivatives, which scattered data do not "
      "give. Evaluate a saved network with 'tspline eval'.");
  parser.describe("Input: '.xyz' (one 'x y z' per line, Delaunay triangulation of (x, y)) or a "
                  "triangle mesh (.off/.obj/.ply/.stl) whose vertex (x, y) is the domain and z "
                  "the height.");
  parser.add_option("input", "FILE", "scattered points (.xyz) or triangle mesh");
  parser.add_option("degree", "N", "patch degree, 5..13 (C^1 from 5, C^2 from 9)", "5");
  parser.add_switch("exact", "exact rational arithmetic: the certificate is a proof");
  parser.add_option("report", "FILE.json", "write the JSON report");
  parser.add_option("mesh", "FILE", "write the tessellated surface (.ply/.off/.obj)");
  parser.add_option("levels", "L", "4-split levels of the tessellation (0..8)", "3");
  parser.add_option("save", "FILE.spline", "save the patch network");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  if (!parsed.has("input"))
    throw Usage_error("missing --input FILE");
  Mann_job job;
  job.input = parsed.value("input");
  job.degree = parsed.integer_in("degree", 5, 13, " (C^1 needs degree 4k+1 = 5)");
  job.levels = parsed.integer_in("levels", 0, 8);
  job.exact = parsed.is_set("exact");
  for (const auto& [name, field] : {std::pair<const char*, std::string*>{"report", &job.report},
                                    {"mesh", &job.mesh},
                                    {"save", &job.save}})
    if (parsed.has(name))
      *field = parsed.value(name);
  const Job_result result = run_mann_job(job, std::cout);
  if (!result.certified)
    std::cerr << "tspline mann: the interpolant failed its C^1 certificate\n";
  return result.certified ? 0 : 1;
}

} // namespace tspline

// tspline adjust and tspline mann: argument handling; the work is in mann_job.cpp.

#include "command_line.h"
#include "commands.h"
#include "files.h"
#include "mann_job.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_adjust(const std::vector<std::string>& args) {
  Adjust_job job;
  Command_line cl("adjust");
  cl.describe(
      "Reads a patch network (a 'tspline-spline 1' file: a planar triangulation and one Bezier "
      "patch of any degree per triangle, functional or parametric) exactly, and raises it to C^k "
      "across every interior edge with Mann's averaging adjustment: first the C^k conditions "
      "around each vertex, then for l = 0..k the order-l conditions of every edge. Points that "
      "already meet the conditions are not moved: a C^k network is returned unchanged.");
  cl.describe("The degree must be at least 4k+1 (Mann 3.1): C^1 needs quintics, C^2 degree 9. "
              "The result is certified exactly (C^k, and C^1 for the report). Exit status 0 "
              "when the result is certified C^k.");
  cl.input(job.input, "NETWORK.spline", "the patch network to adjust");
  cl.integer(job.order, "order", "K", "the continuity order k to reach (0 <= 4k+1 <= degree)", 0,
             20, "", false);
  cl.output(job.output, "output", "FILE.spline", "write the adjusted network (exact numbers)", {});
  cl.report(job.report, "write a JSON report (continuity before and after, moved control points)");
  if (!cl.parse(args))
    return 0;
  if (job.input.empty())
    throw Usage_error("missing --input NETWORK.spline");
  if (!cl.given("order"))
    throw Usage_error("missing --order K");
  const Job_result result = run_adjust_job(job, cl.summary_stream());
  if (!result.certified)
    std::cerr << "tspline adjust: the adjusted network is NOT C^" << job.order << "\n";
  return result.certified ? 0 : 1;
}

int run_mann(const std::vector<std::string>& args) {
  Mann_job job;
  Command_line cl("mann");
  cl.describe(
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
  cl.describe("Input: '.xyz' (one 'x y z' per line, Delaunay triangulation of (x, y)), '.npy' "
              "(an (n, 3) array, or columns chosen with --columns) or a "
              "triangle mesh (.off/.obj/.ply/.stl) whose vertex (x, y) is the domain and z "
              "the height.");
  cl.input(job.input, "FILE", "scattered points (.xyz, .npy) or triangle mesh");
  cl.text(job.columns, "columns", "I,J,K",
          "the indices (from 0) of the x, y and z columns of a .npy input; default: all three "
          "of an (n, 3) array");
  cl.integer(job.degree, "degree", "N", "patch degree, 5..13 (C^1 from 5, C^2 from 9)", 5, 13,
             " (C^1 needs degree 4k+1 = 5)");
  cl.flag(job.exact, "exact", "exact rational arithmetic: the certificate is a proof");
  cl.output(job.save, "output", "FILE.spline", "save the patch network", {}, {"save"});
  cl.report(job.report);
  cl.output(job.mesh, "mesh", "FILE", "write the tessellated surface (.ply/.off/.obj)",
            mesh_file_output);
  cl.integer(job.levels, "levels", "L", "4-split levels of the tessellation (0..8)", 0, 8);
  if (!cl.parse(args))
    return 0;
  if (job.input.empty())
    throw Usage_error("missing --input FILE");
  if (!job.columns.empty() && lowercase_extension(job.input) != "npy")
    throw Usage_error("--columns chooses the columns of a .npy input");
  const Job_result result = run_mann_job(job, cl.summary_stream());
  if (!result.certified)
    std::cerr << "tspline mann: the interpolant failed its C^1 certificate\n";
  return result.certified ? 0 : 1;
}

} // namespace tspline

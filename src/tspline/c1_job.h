// The main job of tspline (subcommand `c1`, and `demo` on embedded data): Xu's C^1 quintic
// spline from scattered data or a triangulated height field. The heavy CGAL instantiations
// live in c1_job.cpp only.

#ifndef TSPLINE_C1_JOB_H
#define TSPLINE_C1_JOB_H

#include "cli.h"

#include <ostream>
#include <optional>
#include <string>

namespace tspline {

struct C1_job {
  std::string input;   // .xyz or .csv scattered data or a mesh (OFF/OBJ/PLY/STL); empty: demo data
  std::string columns; // .csv: the header names of x,y,z (and zx,zy); empty: x,y,z
  std::string fit =
      "adaptive"; // adaptive | local | energy | lsq | tangent | interpolate | approximate
  int degree = 5; // largest degree of the local polynomials (local, lsq)
  std::string degree_selection = "cv"; // cv (cross-validation) | largest
  double smoothing = 0;                // energy fit: lambda of misfit + lambda h^2 energy
  std::optional<double> tension;       // adaptive and energy fits; unset: the fit's default
  bool gradients = false;              // the input has 'x y z zx zy': interpolate gradients too
  bool rescale = false;                // fit with y scaled by a power of two like x's extent
  std::string fix = "reroute";         // reroute | perturb
  bool exact = false;                  // exact rational arithmetic (a proof of C^1)
  bool dimension = false;              // compute the exact rank dimension of S^1_5
  std::string report;                  // JSON report path
  std::string mesh;                    // tessellated mesh path (.ply/.off/.obj)
  int levels = 3;                      // 4-split levels of the tessellation
  std::string save;                    // .spline path
  std::string query;                   // query points (x y per line)
  std::string values;                  // output of the query values
  bool quiet = false;                  // no summary on `out`
};

// Runs the job, writes the requested files, prints a summary on `out` and returns the
// report. Throws on bad input (CGAL::Triangular_spline::Invalid_input) or I/O failure.
Json run_c1_job(const C1_job& job, std::ostream& out);

struct Certify_result {
  Json report;
  bool certified = false;     // proof or within the tolerance
  std::string round_off_hint; // set when a failure looks like the round-off of a double build
};

// Re-checks a saved spline exactly; prints a summary, returns the report. `tolerance` < 0:
// exact verdict; otherwise edges whose exact residual is at most `tolerance` pass.
Certify_result run_certify_job(const std::string& path, double tolerance, std::ostream& out);

} // namespace tspline

#endif // TSPLINE_C1_JOB_H

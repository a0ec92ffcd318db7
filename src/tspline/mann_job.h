// Mann's continuity adjustment and interpolant for tspline (subcommands `adjust` and
// `mann`). The heavy CGAL instantiations live in mann_job.cpp only.

#ifndef TSPLINE_MANN_JOB_H
#define TSPLINE_MANN_JOB_H

#include "cli.h"

#include <ostream>
#include <string>

namespace tspline {

struct Adjust_job {
  std::string input;  // a tspline-spline file (any degree, dimension 1 or 3)
  int order = 1;      // the continuity order k to reach
  std::string output; // adjusted spline file (exact numbers); empty: not written
  std::string report; // JSON report path; empty: none
};

struct Job_result {
  Json report;
  bool certified = false; // the result meets what was asked (exit status 0)
};

// Reads the network exactly, adjusts it to C^k, certifies C^k (and C^1) exactly, writes the
// requested files and prints a summary on `out`. Throws on bad input.
Job_result run_adjust_job(const Adjust_job& job, std::ostream& out);

struct Mann_job {
  std::string input;   // .xyz or .npy scattered data or a mesh (OFF/OBJ/PLY/STL)
  std::string columns; // .npy: the indices of the x,y,z columns; empty: an (n, 3) array
  int degree = 5;      // patch degree n; the continuity is floor((n-1)/4)
  bool exact = false;  // exact rational arithmetic (the C^1 certificate is a proof)
  std::string report;  // JSON report path
  std::string mesh;    // tessellated mesh path (.ply/.off/.obj)
  int levels = 3;      // 4-split levels of the tessellation
  std::string save;    // .spline path
};

// Estimates vertex derivatives, builds Mann's interpolant, certifies it, writes the
// requested files and prints a summary on `out`. Throws on bad input.
Job_result run_mann_job(const Mann_job& job, std::ostream& out);

} // namespace tspline

#endif // TSPLINE_MANN_JOB_H

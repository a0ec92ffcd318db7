// Xu's pseudo-AG^1 surfaces for tspline (subcommand `pseudo-ag1`). The heavy CGAL
// instantiations live in pseudo_ag1_job.cpp only.

#ifndef TSPLINE_PSEUDO_AG1_JOB_H
#define TSPLINE_PSEUDO_AG1_JOB_H

#include "cli.h"

#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>

#include <ostream>
#include <string>

namespace tspline {

struct Pseudo_ag1_job {
  std::string input; // a closed triangle mesh (.off/.ply/.obj/.stl); or
  std::string shape; // a solid of the thesis or of the tests (see --help)
  std::string preset = "smooth";
  CGAL::Triangular_spline::Pseudo_AG1_options options; // the preset with the overrides applied
  bool exact = false;         // exact rational arithmetic (needs rational options)
  int samples = 15;           // interior samples per edge for the normal jumps
  int levels = -1;            // 4-splits per face of the measured tessellation; < 0: automatic
  int mesh_levels = 3;        // 4-splits per face of --output
  bool compare = true;        // measure PN triangles and Fang's order-1 blend on the same mesh
  bool per_edge = false;      // list every edge in the report
  std::string mesh;           // tessellated surface (.ply/.off/.obj); empty: none
  bool split_normals = false; // --output: each face its own points and normals (not closed)
  std::string save;           // .surface file; empty: none
  std::string report;         // JSON report; empty: none
  // Xu 6.1's global AG^1 system, solved by the walk (AG1.md 5.2): report and surface
  std::string ag1_system;                // JSON report of the walk; empty: not solved
  std::string ag1_save;                  // .surface file of its AG^1 surface; empty: none
  long long ag1_start = 0;               // start vertex
  std::string ag1_umbrella = "centroid"; // start umbrella: centroid or projected
};

// Builds, certifies and measures the surface, compares, writes the requested files, prints a
// summary on `out` and returns the report. Throws on bad input.
Json run_pseudo_ag1_job(const Pseudo_ag1_job& job, std::ostream& out);

// Certifies a saved .surface file (tspline certify FILE.surface): read exactly, the edge
// relations solved from the nets, every diamond and vertex checked. `tolerance` < 0: exact
// verdict. Prints a summary; returns the report and whether it passed.
struct Surface_certify_result {
  Json report;
  bool certified = false;
};
Surface_certify_result run_certify_surface_job(const std::string& path, double tolerance,
                                               std::ostream& out);

// The names accepted by --shape.
std::string pseudo_ag1_shape_names();

} // namespace tspline

#endif // TSPLINE_PSEUDO_AG1_JOB_H

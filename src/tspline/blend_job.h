// Fang's generalized blending mesh interpolation for tspline (subcommand `blend`). The
// heavy CGAL instantiations live in blend_job.cpp only.

#ifndef TSPLINE_BLEND_JOB_H
#define TSPLINE_BLEND_JOB_H

#include "cli.h"

#include <ostream>
#include <string>

namespace tspline {

struct Blend_job {
  std::string input;                    // a polygon mesh (.off/.ply/.obj/.stl); or
  std::string shape;                    // a test mesh of Fang ch. 8 (see --help)
  std::string scheme = "fang";          // fang | nielson (the comparator of Fang §5.4)
  unsigned seed = 1;                    // for the random test meshes
  int order = 2;                        // the blending order d >= 0
  std::string variant = "open";         // basic | vertex | open
  std::string vertex_surface = "least"; // least (de Boor-Ron) | lsq | normals
  int least_squares_degree = 2;         // degree of the lsq vertex surfaces
  int normals_degree = 4;               // least degree of the normals vertex surfaces
  int resolution = 8;                   // segments per input edge of the tessellation
  int samples = 3;                      // measured points per edge
  std::string mesh;                     // tessellated surface (.ply/.off/.obj); empty: none
  std::string report;                   // JSON report; empty: none
};

// Builds the surface, measures its continuity and curvature, writes the requested files,
// prints a summary on `out` and returns the report. Throws on bad input.
Json run_blend_job(const Blend_job& job, std::ostream& out);

// The names accepted by --shape.
std::string blend_shape_names();

} // namespace tspline

#endif // TSPLINE_BLEND_JOB_H

// tspline render (and the pictures of `tspline demo`): reading a spline or a mesh,
// tessellating, rendering to PNG, coloured PLY, JSON report. The CGAL instantiations live in
// render_job.cpp only; the rasteriser is the tspline_render library.

#ifndef TSPLINE_RENDER_JOB_H
#define TSPLINE_RENDER_JOB_H

#include "cli.h"
#include "render/render.h"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace tspline {

struct Render_job {
  std::string input;         // .spline (tessellated, exact curvature) or .ply/.off/.obj/.stl mesh
  std::string output;        // .png
  std::optional<int> levels; // 4-split levels for a .spline; none: about 2.6e5 triangles
  std::string ply;           // coloured PLY (curvature colours and scalars)
  std::string report;        // JSON report
  render::Options options;
  bool quiet = false; // no summary line on `out`
  // .surface only: every patch its own normals at shared points (creases show), and in
  // Mode::Net only the umbrellas (corner points, stars, spokes, rims: Xu's Fig. 6.10)
  bool split_normals = false;
  bool umbrellas = false;
};

// Runs the job, writes the files, prints one summary line on `out` and returns the report.
// Throws on bad input or I/O failure (one-line messages).
Json run_render_job(const Render_job& job, std::ostream& out);

// The pictures that end `tspline demo`: shaded, curvature and isophotes of the spline saved
// in `spline_path`, and the control net of a small C^1 spline built here (prescribed and
// propagated points in different colours), 640x480 PNGs in `dir`.
void render_demo_pictures(const std::filesystem::path& dir, const std::string& spline_path,
                          std::ostream& out);

} // namespace tspline

#endif // TSPLINE_RENDER_JOB_H

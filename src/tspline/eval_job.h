// tspline eval: values, gradients and Hessians of a saved spline at query points or on a grid.
// The heavy CGAL instantiations live in eval_job.cpp only.

#ifndef TSPLINE_EVAL_JOB_H
#define TSPLINE_EVAL_JOB_H

#include <ostream>
#include <string>
#include <utility>

namespace tspline {

// A regular grid of nodes: NX columns from XMIN to XMAX (both included), NY rows likewise.
struct Eval_grid {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  long long nx = 0, ny = 0;
};

struct Eval_job {
  std::string input;           // a tspline-spline file of dimension 1
  std::string query;           // 'x y' per line; empty: use `grid`
  bool use_grid = false;       // evaluate on `grid` instead of `query`
  Eval_grid grid;              // checked by the caller (ranges, sizes)
  int derivatives = 0;         // 0: z; 1: z, zx, zy; 2: and zxx, zxy, zyy
  std::string outside = "nan"; // nan | nearest | linear
  bool exact = false;          // read and evaluate in exact rationals
  std::string output;          // CSV, '-' for stdout, or .asc / .tif (grid only)
};

// Reads the spline, evaluates, writes the output and (unless the output is stdout) prints a
// one-line summary on `out`. Throws on bad input (Invalid_input, Usage_error) or I/O failure.
void run_eval_job(const Eval_job& job, std::ostream& out);

// The grid's cell size for an ESRI ASCII grid; throws Usage_error when the cells are not
// square (the format has one cellsize) or undefined (a 1 x 1 grid).
double ascii_grid_cellsize(const Eval_grid& grid);

// The pixel width and height of a GeoTIFF of the grid (the node spacing; square where the grid
// has one row or column); throws Usage_error for a 1 x 1 grid.
std::pair<double, double> geotiff_pixel_size(const Eval_grid& grid);

} // namespace tspline

#endif // TSPLINE_EVAL_JOB_H

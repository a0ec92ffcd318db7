// tspline eval: argument handling; the work is in eval_job.cpp.

#include "command_line.h"
#include "commands.h"
#include "eval_job.h"
#include "files.h"
#include "geotiff.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

namespace tspline {

namespace {

// Splits "a,b,c" at the commas (empty fields kept, so that "1,,2" is an error).
std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> fields(1);
  for (const char c : text) {
    if (c == ',')
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

double grid_number(const std::string& token, const char* name) {
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if (token.empty() || end != token.c_str() + token.size() || errno == ERANGE || !std::isfinite(x))
    throw Usage_error(std::string("--grid: ") + name + " must be a finite number, not '" + token +
                      "'");
  return x;
}

long long grid_count(const std::string& token, const char* name) {
  // Above 10^6 nodes per axis a grid is a mistake, and the product stays far from overflow.
  const long long max = 1000000;
  errno = 0;
  char* end = nullptr;
  const long long n = std::strtoll(token.c_str(), &end, 10);
  if (token.empty() || end != token.c_str() + token.size() || errno == ERANGE)
    throw Usage_error(std::string("--grid: ") + name + " must be an integer, not '" + token + "'");
  if (n < 1 || n > max)
    throw Usage_error(std::string("--grid: ") + name + " must be between 1 and " +
                      std::to_string(max) + ", not " + token);
  return n;
}

Eval_grid parse_grid(const std::string& text) {
  const std::vector<std::string> f = split_commas(text);
  if (f.size() != 6)
    throw Usage_error("--grid expects XMIN,XMAX,YMIN,YMAX,NX,NY (6 values), not '" + text + "'");
  Eval_grid g;
  g.xmin = grid_number(f[0], "XMIN");
  g.xmax = grid_number(f[1], "XMAX");
  g.ymin = grid_number(f[2], "YMIN");
  g.ymax = grid_number(f[3], "YMAX");
  g.nx = grid_count(f[4], "NX");
  g.ny = grid_count(f[5], "NY");
  const long long max_nodes = 100000000;
  if (g.nx * g.ny > max_nodes)
    throw Usage_error("--grid: NX * NY = " + std::to_string(g.nx * g.ny) + " nodes, more than " +
                      std::to_string(max_nodes));
  for (const auto& [low, high, n, axis] :
       {std::make_tuple(g.xmin, g.xmax, g.nx, "X"), std::make_tuple(g.ymin, g.ymax, g.ny, "Y")}) {
    const std::string a(axis);
    if (low > high)
      throw Usage_error("--grid: " + a + "MIN > " + a + "MAX (reversed range)");
    if (n > 1 && !(low < high))
      throw Usage_error("--grid: N" + a + " > 1 needs " + a + "MIN < " + a + "MAX");
    if (n == 1 && low != high)
      throw Usage_error("--grid: N" + a + " = 1 needs " + a + "MIN = " + a + "MAX (one line)");
  }
  return g;
}

} // namespace

int run_eval(const std::vector<std::string>& args) {
  Eval_job job;
  std::string grid;
  Command_line cl("eval");
  cl.describe(
      "Evaluates a saved functional spline (a 'tspline-spline 1' file of dimension 1, as written "
      "by 'tspline c1 --output', 'tspline mann --output' and 'tspline adjust --output') and its "
      "derivatives at query points or on a regular grid. Output: CSV with the header "
      "'x,y,z[,zx,zy[,zxx,zxy,zyy]]' (numbers as the shortest decimals that read back to the same doubles, 'nan' where there is no value), or, "
      "with --grid and an output ending in .asc, an ESRI ASCII grid of the values (square "
      "cells, rows from north to south, NODATA_value -9999; the cells are centred on the grid "
      "nodes), or, with --grid and an output ending in .tif, a GeoTIFF (where tspline was built "
      "with GDAL): one float64 band per column (z, zx, zy, zxx, zxy, zyy), rows from north to "
      "south, pixels centred on the nodes, NaN as no-data, no coordinate reference system.");
  cl.describe(
      "Points outside a boundary edge by a rounding error (at most 1e-9 of the edge's length, "
      "or 1e-13 of the largest coordinate) are evaluated on the edge. Farther points get "
      "--outside: nan, the spline at the nearest boundary point (nearest), or the linear "
      "extrapolation from that point with its gradient (linear, Hessian 0). On an edge or at a "
      "vertex the derivatives are those of one incident patch.");
  cl.input(job.input, "FILE.spline", "the spline to evaluate (dimension 1)");
  cl.text(job.query, "query", "FILE.xy",
          "query points, 'x y' per line (a third column, as in .xyz files, is ignored), or "
          "a .npy array (its columns 0 and 1)");
  cl.text(grid, "grid", "XMIN,XMAX,YMIN,YMAX,NX,NY",
          "a regular grid of NX x NY nodes, both ends included (CSV rows: x fastest, y "
          "increasing)");
  cl.integer(job.derivatives, "derivatives", "D", "0: z; 1: also zx, zy; 2: also zxx, zxy, zyy", 0,
             2);
  cl.text(job.outside, "outside", "MODE", "nan, nearest or linear (see above)");
  cl.flag(job.exact, "exact",
          "read and evaluate in exact rational arithmetic (slower; the "
          "printed numbers are the exact results rounded to double)");
  cl.output(job.output, "output", "OUT",
            "CSV file, '-' for stdout, or FILE.asc or FILE.tif with --grid", {{}, true});
  if (!cl.parse(args))
    return 0;
  if (job.input.empty())
    throw Usage_error("missing --input FILE.spline");
  if (cl.given("query") == cl.given("grid"))
    throw Usage_error("give exactly one of --query FILE.xy and --grid XMIN,XMAX,YMIN,YMAX,NX,NY");
  if (job.output.empty())
    throw Usage_error("missing --output OUT (a CSV file, '-' for stdout, or FILE.asc)");
  if (job.outside != "nan" && job.outside != "nearest" && job.outside != "linear")
    throw Usage_error("--outside must be nan, nearest or linear, not '" + job.outside + "'");
  if (!cl.given("query")) {
    job.use_grid = true;
    job.grid = parse_grid(grid);
  }
  const std::string extension = lowercase_extension(job.output);
  if (extension == "tif" || extension == "tiff") {
    if (!geotiff_available())
      throw Usage_error(geotiff_unavailable_message());
    if (!job.use_grid)
      throw Usage_error("a GeoTIFF (.tif) output needs --grid");
    geotiff_pixel_size(job.grid); // checked before the spline is read
  }
  if (extension == "asc") {
    if (!job.use_grid)
      throw Usage_error("an ESRI ASCII grid (.asc) output needs --grid");
    if (job.derivatives > 0)
      throw Usage_error("an ESRI ASCII grid (.asc) holds the values only: use a CSV output for "
                        "--derivatives " +
                        std::to_string(job.derivatives));
    ascii_grid_cellsize(job.grid); // square cells, checked before the spline is read
  }
  run_eval_job(job, cl.summary_stream());
  return 0;
}

} // namespace tspline

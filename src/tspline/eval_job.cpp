// tspline eval: read a saved spline, locate and evaluate jets (value, gradient, Hessian),
// write CSV, an ESRI ASCII grid or a GeoTIFF. Instantiated for double and for exact rationals.

#include "eval_job.h"
#include "cli.h"
#include "files.h"
#include "geotiff.h"
#include "point_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/internal/text.h>
#include <CGAL/Triangular_spline/evaluate.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <type_traits>

namespace tspline {

namespace {

namespace TS = CGAL::Triangular_spline;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

// Points per evaluation chunk: bounds memory for large grids, output streams as it goes.
constexpr std::size_t chunk_size = 1 << 16;

// Node i of n from low to high; the last node is `high` exactly.
double node(double low, double high, long long i, long long n) {
  if (n <= 1)
    return low;
  if (i == n - 1)
    return high;
  return low + (high - low) * (double(i) / double(n - 1));
}

// The double nearest to x: CGAL::to_double() of an exact rational truncates, and the CSV of an
// exact evaluation should print the exact result correctly rounded.
template <class FT>
double nearest_double(const FT& x) {
  const double d = CGAL::to_double(x);
  if constexpr (std::is_floating_point<FT>::value) {
    return d;
  } else {
    double best = d;
    FT error = CGAL::abs(FT(d) - x);
    for (const double c : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)}) {
      const FT e = CGAL::abs(FT(c) - x);
      if (std::isfinite(c) && e < error) {
        best = c;
        error = e;
      }
    }
    return best;
  }
}

void append_number(std::string& text, double x) {
  TS::internal::append_double(text, x);
}

struct Counts {
  std::size_t points = 0, inside = 0, outside = 0;
};

template <class K>
class Evaluator {
public:
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  using Jet = TS::Point_jet<FT>;

  Evaluator(const std::string& input, int derivatives, TS::Outside outside)
      : m_file(read(input)), m_locator(m_file.domain()), m_derivatives(derivatives),
        m_outside(outside) {}

  // Jets of `points` (NaN-free where a value exists); counts inside and outside points.
  std::vector<std::optional<Jet>> evaluate(const std::vector<Point_2>& points) {
    // Strictly first, then the outside mode on the misses only: the counts come for free.
    std::vector<std::optional<Jet>> jets =
        TS::evaluate_jets(m_file, m_locator, points, TS::Outside::NO_VALUE, m_derivatives);
    std::vector<Point_2> missed;
    std::vector<std::size_t> where;
    for (std::size_t q = 0; q < jets.size(); ++q)
      if (!jets[q]) {
        missed.push_back(points[q]);
        where.push_back(q);
      }
    m_counts.points += points.size();
    m_counts.outside += missed.size();
    m_counts.inside += points.size() - missed.size();
    if (m_outside != TS::Outside::NO_VALUE && !missed.empty()) {
      auto extended = TS::evaluate_jets(m_file, m_locator, missed, m_outside, m_derivatives);
      for (std::size_t k = 0; k < missed.size(); ++k)
        jets[where[k]] = std::move(extended[k]);
    }
    return jets;
  }

  const TS::Spline_file<K, FT>& file() const { return m_file; }
  const Counts& counts() const { return m_counts; }

private:
  static TS::Spline_file<K, FT> read(const std::string& path) {
    std::ifstream in = open_input(path);
    if (TS::spline_file_dimension(in) == 3)
      throw TS::Invalid_input("'" + path +
                              "' holds a parametric spline (dimension 3): eval needs a "
                              "functional spline z = f(x, y) (dimension 1)");
    return TS::read_spline_file<K, FT>(in, path);
  }

  TS::Spline_file<K, FT> m_file;
  TS::Domain_locator<K> m_locator;
  int m_derivatives;
  TS::Outside m_outside;
  Counts m_counts;
};

// Appends CSV lines "x,y,z[,zx,zy[,zxx,zxy,zyy]]" for the points and their jets.
template <class K>
void append_csv(std::string& text, const std::vector<typename K::Point_2>& points,
                const std::vector<std::optional<TS::Point_jet<typename K::FT>>>& jets,
                int derivatives) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t q = 0; q < points.size(); ++q) {
    append_number(text, nearest_double(points[q].x()));
    text += ',';
    append_number(text, nearest_double(points[q].y()));
    const auto& jet = jets[q];
    text += ',';
    append_number(text, jet ? nearest_double(jet->value) : nan);
    if (derivatives >= 1)
      for (std::size_t i = 0; i < 2; ++i) {
        text += ',';
        append_number(text, jet ? nearest_double(jet->gradient[i]) : nan);
      }
    if (derivatives >= 2)
      for (std::size_t i = 0; i < 3; ++i) {
        text += ',';
        append_number(text, jet ? nearest_double(jet->hessian[i]) : nan);
      }
    text += '\n';
  }
}

void write_text(std::ostream& output, const std::string& text, const std::string& name) {
  output.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!output)
    throw std::runtime_error("cannot write '" + name + "'");
}

template <class K>
void run(const Eval_job& job, std::ostream& out) {
  using Point_2 = typename K::Point_2;
  const TS::Outside outside = job.outside == "nearest"  ? TS::Outside::NEAREST
                              : job.outside == "linear" ? TS::Outside::LINEAR
                                                        : TS::Outside::NO_VALUE;
  Stopwatch clock;
  Evaluator<K> evaluator(job.input, job.derivatives, outside);
  const double read_seconds = clock.lap();

  // Queries first: a bad query file leaves no half-written output behind.
  std::vector<Point_2> points;
  if (!job.use_grid) {
    points = read_query_file<K>(job.query);
  }

  const bool to_stdout = job.output == "-";
  const std::string extension = lowercase_extension(job.output);
  const bool ascii_grid = job.use_grid && extension == "asc";
  const bool geotiff = job.use_grid && (extension == "tif" || extension == "tiff");
  // GeoTIFF: one float64 band per output column (z; zx, zy; zxx, zxy, zyy)
  std::vector<std::string> bands{"z"};
  if (job.derivatives >= 1)
    bands.insert(bands.end(), {"zx", "zy"});
  if (job.derivatives >= 2)
    bands.insert(bands.end(), {"zxx", "zxy", "zyy"});
  std::optional<Geotiff_writer> tiff;
  if (geotiff) {
    const auto [dx, dy] = geotiff_pixel_size(job.grid);
    tiff.emplace(job.output, job.grid.nx, job.grid.ny, bands, job.grid.xmin, job.grid.ymax, dx, dy);
  }
  std::ofstream file;
  if (!to_stdout && !geotiff)
    file = open_output(job.output);
  std::ostream& output = to_stdout ? std::cout : file;
  const std::string name = to_stdout ? std::string("stdout") : job.output;

  double evaluate_seconds = 0;
  std::string text;
  if (!ascii_grid && !geotiff) {
    text = "x,y,z";
    if (job.derivatives >= 1)
      text += ",zx,zy";
    if (job.derivatives >= 2)
      text += ",zxx,zxy,zyy";
    text += '\n';
  }
  if (!job.use_grid) {
    for (std::size_t begin = 0; begin < points.size(); begin += chunk_size) {
      const std::vector<Point_2> chunk(points.begin() + static_cast<std::ptrdiff_t>(begin),
                                       points.begin() + static_cast<std::ptrdiff_t>((std::min)(
                                                            points.size(), begin + chunk_size)));
      Stopwatch timer;
      const auto jets = evaluator.evaluate(chunk);
      evaluate_seconds += timer.lap();
      append_csv<K>(text, chunk, jets, job.derivatives);
      write_text(output, text, name);
      text.clear();
    }
  } else {
    const Eval_grid& g = job.grid;
    if (ascii_grid) {
      const double cellsize = ascii_grid_cellsize(g);
      text += "ncols " + std::to_string(g.nx) + "\nnrows " + std::to_string(g.ny) + "\nxllcorner ";
      append_number(text, g.xmin - cellsize / 2);
      text += "\nyllcorner ";
      append_number(text, g.ymin - cellsize / 2);
      text += "\ncellsize ";
      append_number(text, cellsize);
      text += "\nNODATA_value -9999\n";
    }
    // CSV rows go south to north; ESRI grids and GeoTIFF list rows from north to south.
    const long long rows_per_chunk = (std::max)(1LL, static_cast<long long>(chunk_size) / g.nx);
    std::vector<Point_2> chunk;
    for (long long first = 0; first < g.ny; first += rows_per_chunk) {
      const long long last = (std::min)(g.ny, first + rows_per_chunk);
      chunk.clear();
      for (long long r = first; r < last; ++r) {
        const long long j = ascii_grid || geotiff ? g.ny - 1 - r : r;
        const double y = node(g.ymin, g.ymax, j, g.ny);
        for (long long i = 0; i < g.nx; ++i)
          chunk.emplace_back(node(g.xmin, g.xmax, i, g.nx), y);
      }
      Stopwatch timer;
      const auto jets = evaluator.evaluate(chunk);
      evaluate_seconds += timer.lap();
      if (geotiff) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::vector<std::vector<double>> values(bands.size(), std::vector<double>(chunk.size()));
        for (std::size_t q = 0; q < chunk.size(); ++q) {
          const auto& jet = jets[q];
          values[0][q] = jet ? nearest_double(jet->value) : nan;
          for (std::size_t i = 0; i < 2 && job.derivatives >= 1; ++i)
            values[1 + i][q] = jet ? nearest_double(jet->gradient[i]) : nan;
          for (std::size_t i = 0; i < 3 && job.derivatives >= 2; ++i)
            values[3 + i][q] = jet ? nearest_double(jet->hessian[i]) : nan;
        }
        tiff->write_rows(first, last - first, values);
        continue;
      }
      if (ascii_grid) {
        for (std::size_t q = 0; q < chunk.size(); ++q) {
          if (jets[q])
            append_number(text, nearest_double(jets[q]->value));
          else
            text += "-9999";
          text += (q + 1) % static_cast<std::size_t>(g.nx) == 0 ? '\n' : ' ';
        }
      } else {
        append_csv<K>(text, chunk, jets, job.derivatives);
      }
      write_text(output, text, name);
      text.clear();
    }
  }
  if (geotiff) {
    tiff->close();
  } else {
    write_text(output, text, name);
    output.flush();
    if (!output)
      throw std::runtime_error("cannot write '" + name + "'");
  }

  if (to_stdout)
    return; // stdout holds the data only
  const Counts& c = evaluator.counts();
  const auto& f = evaluator.file();
  std::ostringstream summary;
  summary.precision(3);
  summary << "spline " << job.input << ": " << f.domain().number_of_faces() << " patches of degree "
          << f.degree() << " (read in " << read_seconds << " s, "
          << (job.exact ? "exact" : "double") << " arithmetic)\n"
          << "evaluated " << c.points << " points (" << c.inside << " in the domain, " << c.outside
          << " outside: " << job.outside << ") in " << evaluate_seconds << " s";
  if (evaluate_seconds > 0)
    summary << " (" << double(c.points) / evaluate_seconds << " points/s)";
  summary << "\nwrote " << job.output << " ("
          << (ascii_grid ? std::string("ESRI ASCII grid")
              : geotiff  ? "GeoTIFF, " + std::to_string(bands.size()) + " float64 band" +
                              (bands.size() > 1 ? "s" : "")
                        : "CSV, derivatives " + std::to_string(job.derivatives))
          << ")\n";
  out << summary.str();
}

} // namespace

double ascii_grid_cellsize(const Eval_grid& g) {
  const double dx = g.nx > 1 ? (g.xmax - g.xmin) / double(g.nx - 1) : 0;
  const double dy = g.ny > 1 ? (g.ymax - g.ymin) / double(g.ny - 1) : 0;
  if (dx == 0 && dy == 0)
    throw Usage_error("an ESRI ASCII grid needs NX > 1 or NY > 1 (its cell size comes from the "
                      "node spacing)");
  if (dx > 0 && dy > 0 && std::abs(dx - dy) > 1e-9 * (std::max)(dx, dy)) {
    std::ostringstream message;
    message.precision(17);
    message << "an ESRI ASCII grid has square cells, but the x spacing " << dx
            << " differs from the y spacing " << dy
            << ": choose NX, NY with (XMAX-XMIN)/(NX-1) = (YMAX-YMIN)/(NY-1), or write CSV";
    throw Usage_error(message.str());
  }
  return dx > 0 ? dx : dy;
}

std::pair<double, double> geotiff_pixel_size(const Eval_grid& g) {
  const double dx = g.nx > 1 ? (g.xmax - g.xmin) / double(g.nx - 1) : 0;
  const double dy = g.ny > 1 ? (g.ymax - g.ymin) / double(g.ny - 1) : 0;
  if (dx == 0 && dy == 0)
    throw Usage_error("a GeoTIFF needs NX > 1 or NY > 1 (its pixel size comes from the node "
                      "spacing)");
  // one row or one column: square pixels
  return {dx > 0 ? dx : dy, dy > 0 ? dy : dx};
}

void run_eval_job(const Eval_job& job, std::ostream& out) {
  if (job.exact)
    run<Exact>(job, out);
  else
    run<Fast>(job, out);
}

} // namespace tspline

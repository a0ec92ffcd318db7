// tspline render: argument handling; the work is in render_job.cpp and the tspline_render
// library.

#include "cli.h"
#include "commands.h"
#include "render_job.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace tspline {
namespace {

// "a,b[,c...]" -> exactly `count` finite numbers; `what` names the option for the message.
std::vector<double> number_list(const std::string& text, std::size_t count, const std::string& what,
                                const std::string& form) {
  std::vector<double> numbers;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    const std::string item = text.substr(begin, comma == std::string::npos ? comma : comma - begin);
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || errno == ERANGE ||
        !std::isfinite(value))
      throw Usage_error("option '--" + what + "' expects " + form + ", got '" + text + "'");
    numbers.push_back(value);
    if (comma == std::string::npos)
      break;
    begin = comma + 1;
  }
  if (numbers.size() != count)
    throw Usage_error("option '--" + what + "' expects " + form + ", got '" + text + "'");
  return numbers;
}

// "WxH" with 1 <= W, H <= 16384.
void parse_size(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  auto dimension = [&text](const std::string& item) {
    if (item.empty() || item.size() > 5 ||
        item.find_first_not_of("0123456789") != std::string::npos)
      return -1;
    return std::atoi(item.c_str());
  };
  width = x == std::string::npos ? -1 : dimension(text.substr(0, x));
  height = x == std::string::npos ? -1 : dimension(text.substr(x + 1));
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw Usage_error("option '--size' expects WxH with 1 <= W, H <= 16384 (e.g. 800x600), got '" +
                      text + "'");
}

} // namespace

int run_render(const std::vector<std::string>& args) {
  Argument_parser parser("render", std::string(command_summary("render")));
  parser.describe(
      "Draws a surface into a PNG without a display. A .spline file (from 'tspline c1 --save' "
      "or 'tspline demo') is tessellated and its normals and Gaussian curvature come from the "
      "exact derivatives of the patches; a mesh (.ply/.off/.obj/.stl) is drawn as it is, with "
      "normals estimated when it has none.");
  parser.describe(
      "Modes: shaded (Blinn-Phong, two-sided); curvature (Gaussian curvature K, Fang's colours: "
      "green 0, yellow to red positive, cyan to blue negative, colour bar with the range); "
      "isophotes (black and white bands of |n.e|, e the direction to the eye or --light, "
      "Fang 2.3); net (the control net over a light surface: corners red squares, stars "
      "magenta, edge-middle blue, inner grey; when known, a green ring marks a prescribed "
      "point and an amber ring a propagated one, as in 'tspline demo').");
  parser.add_option("input", "FILE", "a .spline file or a triangle mesh (.ply/.off/.obj/.stl)");
  parser.add_option("out", "FILE.png", "the picture to write");
  parser.add_option("mode", "MODE", "shaded, curvature, isophotes or net", "shaded");
  parser.add_option("view", "AZ,EL",
                    "azimuth and elevation in degrees (0,0: from -y with z up; 0,90: from above)",
                    "-35,35");
  parser.add_option("size", "WxH", "picture size in pixels", "800x600");
  parser.add_option("levels", "L",
                    "4-split levels of a .spline's tessellation, 0..8 (default: about 2.6e5 "
                    "triangles)");
  parser.add_option("bands", "N", "isophotes: number of bands of |n.e| in [0, 1]", "12");
  parser.add_option("range", "R",
                    "curvature: colours saturate at |K| = R (default: 98th percentile of |K|)");
  parser.add_option("light", "X,Y,Z",
                    "direction towards the light, world coordinates (default: above left of "
                    "the eye); isophotes then use it as e");
  parser.add_option("samples", "S", "supersampling: S x S samples per pixel, 1..4", "2");
  parser.add_switch("perspective", "perspective projection (default: orthographic)");
  parser.add_switch("no-legend", "no colour bar or marker key");
  parser.add_option("ply", "FILE.ply",
                    "also write the mesh as PLY with per-vertex curvature colours (red green "
                    "blue) and curvature scalars, for MeshLab/ParaView");
  parser.add_option("report", "FILE.json", "write a JSON report");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  if (!parsed.has("input"))
    throw Usage_error("missing --input FILE");
  if (!parsed.has("out"))
    throw Usage_error("missing --out FILE.png");

  Render_job job;
  job.input = parsed.value("input");
  job.output = parsed.value("out");
  try {
    job.options.mode = render::parse_mode(parsed.value("mode"));
  } catch (const std::invalid_argument& e) {
    throw Usage_error(e.what());
  }
  const std::vector<double> view = number_list(parsed.value("view"), 2, "view", "AZ,EL in degrees");
  job.options.azimuth = view[0];
  job.options.elevation = view[1];
  parse_size(parsed.value("size"), job.options.width, job.options.height);
  if (parsed.has("levels"))
    job.levels = parsed.integer_in("levels", 0, 8);
  job.options.bands = parsed.integer_in("bands", 1, 1000);
  if (parsed.has("range")) {
    const double range = parsed.number("range");
    if (!(range > 0))
      throw Usage_error("--range must be positive");
    job.options.curvature_range = range;
  }
  if (parsed.has("light")) {
    const std::vector<double> l = number_list(parsed.value("light"), 3, "light", "X,Y,Z");
    if (l[0] == 0 && l[1] == 0 && l[2] == 0)
      throw Usage_error("--light must not be the zero vector");
    job.options.light = render::Vector{l[0], l[1], l[2]};
  }
  job.options.supersampling = parsed.integer_in("samples", 1, 4);
  job.options.perspective = parsed.is_set("perspective");
  job.options.legend = !parsed.is_set("no-legend");
  if (parsed.has("ply"))
    job.ply = parsed.value("ply");
  if (parsed.has("report"))
    job.report = parsed.value("report");
  run_render_job(job, std::cout);
  return 0;
}

} // namespace tspline

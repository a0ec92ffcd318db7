// tspline render: argument handling; the work is in render_job.cpp and the tspline_render
// library.

#include "command_line.h"
#include "commands.h"
#include "files.h"
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
  Render_job job;
  std::string mode = "shaded", view = "-35,35", size = "800x600", light;
  int levels = 0;
  double range = 0;
  bool perspective = false, no_legend = false;
  Command_line cl("render");
  cl.describe(
      "Draws a surface into a PNG without a display. A .spline file (from 'tspline c1 --output' "
      "or 'tspline demo') is tessellated and its normals and Gaussian curvature come from the "
      "exact derivatives of the patches; so is a closed surface (.surface, from 'tspline "
      "pseudo-ag1 --save'); a mesh (.ply/.off/.obj/.stl) is drawn as it is, with normals "
      "estimated when it has none.");
  cl.describe(
      "Modes: shaded (Blinn-Phong, two-sided); curvature (Gaussian curvature K, Fang's colours: "
      "green 0, yellow to red positive, cyan to blue negative, colour bar with the range); "
      "isophotes (black and white bands of |n.e|, e the direction to the eye or --light, "
      "Fang 2.3); net (the control net over a light surface: corners red squares, stars "
      "magenta, edge-middle blue, inner grey; when known, a green ring marks a prescribed "
      "point and an amber ring a propagated one, as in 'tspline demo'; for a .surface Xu's "
      "Fig. 6.9 colours: corners red, stars magenta, prescribed inner points green, propagated "
      "edge-middle points yellow); jump (.surface only: shaded, every input edge drawn on "
      "the surface in the colour of its largest normal jump, green 0 through yellow to red, "
      "colour bar in degrees).");
  cl.input(job.input, "FILE",
           "a .spline or .surface file, or a triangle mesh (.ply/.off/.obj/.stl)");
  cl.output(job.output, "output", "FILE.png", "the picture to write", {{"png"}}, {"out"});
  cl.text(mode, "mode", "MODE", "shaded, curvature, isophotes, net or jump");
  cl.text(view, "view", "AZ,EL",
          "azimuth and elevation in degrees (0,0: from -y with z up; 0,90: from above)");
  cl.text(size, "size", "WxH", "picture size in pixels");
  cl.integer(levels, "levels", "L",
             "4-split levels of a .spline's or .surface's tessellation, 0..8 (default: about "
             "2.6e5 triangles)",
             0, 8, "", false);
  cl.integer(job.options.bands, "bands", "N", "isophotes: number of bands of |n.e| in [0, 1]", 1,
             1000);
  cl.number(range, "range", "R",
            "curvature: colours saturate at |K| = R (default: 98th percentile of |K|); jump: at "
            "R degrees (default: the largest jump, at least 1)",
            false);
  cl.text(light, "light", "X,Y,Z",
          "direction towards the light, world coordinates (default: above left of "
          "the eye); isophotes then use it as e");
  cl.integer(job.options.supersampling, "samples", "S",
             "supersampling: S x S samples per pixel, 1..4", 1, 4);
  cl.flag(perspective, "perspective", "perspective projection (default: orthographic)");
  cl.flag(no_legend, "no-legend", "no colour bar or marker key");
  cl.flag(job.split_normals, "split-normals",
          ".surface: every patch shaded with its own normals, so that the tangent-plane jumps "
          "across edges show as creases");
  cl.flag(job.umbrellas, "umbrellas",
          ".surface, --mode net: only the umbrellas, each vertex's corner point and stars "
          "joined (they lie in its corner plane: Xu's Fig. 6.10)");
  cl.output(job.ply, "ply", "FILE.ply",
            "also write the mesh as PLY with per-vertex curvature colours (red green "
            "blue) and curvature scalars, for MeshLab/ParaView",
            {{"ply"}});
  cl.report(job.report, "write a JSON report");
  if (!cl.parse(args))
    return 0;
  if (job.input.empty())
    throw Usage_error("missing --input FILE");
  if ((job.split_normals || job.umbrellas) && lowercase_extension(job.input) != "surface")
    throw Usage_error(std::string(job.split_normals ? "--split-normals" : "--umbrellas") +
                      " needs a .surface input");
  if (job.umbrellas && mode != "net")
    throw Usage_error("--umbrellas needs --mode net");
  if (job.output.empty())
    throw Usage_error("missing --output FILE.png");

  try {
    job.options.mode = render::parse_mode(mode);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(e.what());
  }
  const std::vector<double> angles = number_list(view, 2, "view", "AZ,EL in degrees");
  job.options.azimuth = angles[0];
  job.options.elevation = angles[1];
  parse_size(size, job.options.width, job.options.height);
  if (cl.given("levels"))
    job.levels = levels;
  if (cl.given("range")) {
    if (!(range > 0))
      throw Usage_error("--range must be positive");
    if (job.options.mode == render::Mode::Jump)
      job.options.jump_range = range;
    else
      job.options.curvature_range = range;
  }
  if (cl.given("light")) {
    const std::vector<double> l = number_list(light, 3, "light", "X,Y,Z");
    if (l[0] == 0 && l[1] == 0 && l[2] == 0)
      throw Usage_error("--light must not be the zero vector");
    job.options.light = render::Vector{l[0], l[1], l[2]};
  }
  job.options.perspective = perspective;
  job.options.legend = !no_legend;
  run_render_job(job, cl.summary_stream());
  return 0;
}

} // namespace tspline

// tspline demo: the main job (Xu's C^1 quintic spline, certified exactly) on an embedded
// data set with a hole, a re-entrant corner and straight boundaries, no input needed.

#include "c1_job.h"
#include "command_line.h"
#include "commands.h"
#include "render_job.h"

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_demo(const std::vector<std::string>& args) {
  C1_job job;
  std::string output = "out/demo";
  Command_line cl("demo");
  cl.describe("Builds Xu's C^1 quintic spline over an embedded L-shaped domain with a square "
              "hole, whose straight boundaries produce degenerate frames, in exact rational "
              "arithmetic; certifies C^1 on every interior edge; writes the tessellated "
              "surface, the spline and a JSON report.");
  cl.output(output, "output", "DIR", "directory for the output files, created if needed",
            {{}, false, true}, {"output-dir"});
  cl.integer(job.levels, "levels", "L", "4-split levels of the tessellated surface (0..8)", 0, 8);
  if (!cl.parse(args))
    return 0;
  const std::filesystem::path dir = output;
  std::filesystem::create_directories(dir);

  job.exact = true;
  job.fit = "adaptive"; // local quintic fits where they resolve the data, least energy elsewhere
  job.dimension = true;
  job.mesh = (dir / "demo_surface.ply").string();
  job.report = (dir / "demo_report.json").string();
  job.save = (dir / "demo.spline").string();
  std::cout << "tspline demo: the main job on embedded data\n\n";
  run_c1_job(job, std::cout);
  std::cout << "\nwrote " << job.mesh << ", " << job.save << " and " << job.report << "\n";
  render_demo_pictures(dir, job.save, std::cout);
  return 0;
}

} // namespace tspline

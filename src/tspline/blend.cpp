// tspline blend: argument handling; the work is in blend_job.cpp.

#include "blend_job.h"
#include "cli.h"
#include "commands.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_blend(const std::vector<std::string>& args) {
  Argument_parser parser("blend", std::string(command_summary("blend")));
  parser.describe(
      "Fang's generalized blending (PhD thesis, Waterloo 2023): a surface through the "
      "vertices of a polygon mesh with their normals, one blended patch per face, C^d across "
      "the edges (edge frames) and, for the improved variants, at the vertices (vertex "
      "frames). Vertex surfaces are polynomial interpolants of each vertex and its "
      "neighbours, edge surfaces blend two of them, face surfaces blend their edges' "
      "(triangles: barycentric indicators; convex polygons: distances to the sides).");
  parser.describe("Input: a closed or bordered polygon mesh (.off/.ply/.obj/.stl) with "
                  "consistently oriented faces; vertex normals are read from NOFF files and "
                  "PLY nx/ny/nz properties, otherwise estimated from the faces. Or --shape: "
                  "one of the test meshes of the thesis' ch. 8: " +
                  blend_shape_names() + ".");
  parser.describe("The continuity is measured, not assumed: the report gives the largest "
                  "jump of the derivatives of each order 0..d across the edges and at the "
                  "vertices, the normal angle jump, the interpolation error at the vertices "
                  "and the Gaussian curvature range.");
  parser.add_option("input", "MESH", "the polygon mesh to interpolate");
  parser.add_option("shape", "NAME", "a test mesh of ch. 8 instead of --input");
  parser.add_option("seed", "N", "seed of the random test meshes (perturbed, mixed)", "1");
  parser.add_option("order", "d", "blending order: derivatives up to d are inherited", "2");
  parser.add_option("variant", "V",
                    "basic (ch. 5), vertex (vertex continuity, 6.1) or open (open-set "
                    "continuity, 6.2)",
                    "open");
  parser.add_option("vertex-surface", "M",
                    "least (de Boor-Ron least interpolant, as the thesis), lsq (least-squares "
                    "polynomial through the vertex) or normals (through the vertex and its "
                    "neighbours, fitting their normals: more accurate on coarse meshes)",
                    "least");
  parser.add_option("lsq-degree", "n", "degree of the lsq vertex surfaces", "2");
  parser.add_option("normals-degree", "n",
                    "least degree of the normals vertex surfaces (raised for high valence)", "4");
  parser.add_option("resolution", "N", "tessellation and curvature grid: segments per edge", "8");
  parser.add_option("samples", "S", "measured points per edge", "3");
  parser.add_option("mesh", "OUT",
                    "write the tessellated surface (.ply/.off/.obj) with "
                    "normals and curvatures");
  parser.add_option("report", "FILE.json", "write the JSON report");
  const Parsed_arguments parsed = parser.parse(args);
  if (parsed.help_requested()) {
    std::cout << parser.help();
    return 0;
  }
  Blend_job job;
  if (parsed.has("input") == parsed.has("shape"))
    throw Usage_error("give exactly one of --input MESH and --shape NAME");
  if (parsed.has("input"))
    job.input = parsed.value("input");
  if (parsed.has("shape"))
    job.shape = parsed.value("shape");
  job.order = parsed.integer_in("order", 0, 20, " (the blending order d >= 0)");
  job.variant = parsed.value("variant");
  if (job.variant != "basic" && job.variant != "vertex" && job.variant != "open")
    throw Usage_error("--variant must be basic, vertex or open");
  job.vertex_surface = parsed.value("vertex-surface");
  if (job.vertex_surface != "least" && job.vertex_surface != "lsq" &&
      job.vertex_surface != "normals")
    throw Usage_error("--vertex-surface must be least, lsq or normals");
  job.least_squares_degree = parsed.integer_in("lsq-degree", 1, 8);
  job.normals_degree = parsed.integer_in("normals-degree", 2, 8);
  job.resolution = parsed.integer_in("resolution", 1, 256);
  job.samples = parsed.integer_in("samples", 1, 100);
  const long long seed = parsed.integer("seed");
  if (seed < 0 || seed > 4294967295LL)
    throw Usage_error("--seed must be a non-negative 32-bit integer");
  job.seed = static_cast<unsigned>(seed);
  if (parsed.has("mesh"))
    job.mesh = parsed.value("mesh");
  if (parsed.has("report"))
    job.report = parsed.value("report");
  run_blend_job(job, std::cout);
  return 0;
}

} // namespace tspline

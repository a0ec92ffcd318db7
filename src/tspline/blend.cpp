// tspline blend: argument handling; the work is in blend_job.cpp.

#include "blend_job.h"
#include "command_line.h"
#include "commands.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {

int run_blend(const std::vector<std::string>& args) {
  Blend_job job;
  Command_line cl("blend");
  cl.describe(
      "Fang's generalized blending (PhD thesis, Waterloo 2023): a surface through the "
      "vertices of a polygon mesh with their normals, one blended patch per face, C^d across "
      "the edges (edge frames) and, for the improved variants, at the vertices (vertex "
      "frames). Vertex surfaces are polynomial interpolants of each vertex and its "
      "neighbours, edge surfaces blend two of them, face surfaces blend their edges' "
      "(triangles: barycentric indicators; convex polygons: distances to the sides).");
  cl.describe("Input: a closed or bordered polygon mesh (.off/.ply/.obj/.stl) with "
              "consistently oriented faces; vertex normals are read from NOFF files and "
              "PLY nx/ny/nz properties, otherwise estimated from the faces. Or --shape: "
              "one of the test meshes of the thesis' ch. 8: " +
              blend_shape_names() + ".");
  cl.describe("The continuity is measured, not assumed: the report gives the largest "
              "jump of the derivatives of each order 0..d across the edges and at the "
              "vertices, the normal angle jump, the interpolation error at the vertices "
              "and the Gaussian curvature range.");
  cl.input(job.input, "MESH", "the polygon mesh to interpolate");
  cl.text(job.shape, "shape", "NAME", "a test mesh of ch. 8 instead of --input");
  cl.integer(job.seed, "seed", "N", "seed of the random test meshes (perturbed, mixed)", 0,
             4294967295LL);
  cl.text(job.scheme, "scheme", "S",
          "fang (the default) or nielson: Nielson's G^1 side-vertex interpolant (1987) of "
          "the same vertices and normals, Fang's comparator in §5.4 (triangle meshes; "
          "--order, --variant and the vertex surfaces do not apply)");
  cl.integer(job.order, "order", "d", "blending order: derivatives up to d are inherited", 0, 20,
             " (the blending order d >= 0)");
  cl.text(job.variant, "variant", "V",
          "basic (ch. 5), vertex (vertex continuity, 6.1) or open (open-set "
          "continuity, 6.2)");
  cl.text(job.vertex_surface, "vertex-surface", "M",
          "least (de Boor-Ron least interpolant, as the thesis), lsq (least-squares "
          "polynomial through the vertex) or normals (through the vertex and its "
          "neighbours, fitting their normals: more accurate on coarse meshes)");
  cl.integer(job.least_squares_degree, "lsq-degree", "n", "degree of the lsq vertex surfaces", 1,
             8);
  cl.integer(job.normals_degree, "normals-degree", "n",
             "least degree of the normals vertex surfaces (raised for high valence)", 2, 8);
  cl.integer(job.resolution, "resolution", "N",
             "tessellation and curvature grid: segments per edge", 1, 256);
  cl.integer(job.samples, "samples", "S", "measured points per edge", 1, 100);
  cl.output(job.mesh, "output", "MESH.ply",
            "write the tessellated surface (.ply/.off/.obj) with "
            "normals and curvatures",
            mesh_file_output, {"mesh"});
  cl.report(job.report);
  if (!cl.parse(args))
    return 0;
  if (job.input.empty() == job.shape.empty())
    throw Usage_error("give exactly one of --input MESH and --shape NAME");
  if (job.scheme != "fang" && job.scheme != "nielson")
    throw Usage_error("--scheme must be fang or nielson");
  if (job.variant != "basic" && job.variant != "vertex" && job.variant != "open")
    throw Usage_error("--variant must be basic, vertex or open");
  if (job.vertex_surface != "least" && job.vertex_surface != "lsq" &&
      job.vertex_surface != "normals")
    throw Usage_error("--vertex-surface must be least, lsq or normals");
  run_blend_job(job, cl.summary_stream());
  return 0;
}

} // namespace tspline

// tspline pseudo-ag1: argument handling; the work is in pseudo_ag1_job.cpp.

#include "command_line.h"
#include "commands.h"
#include "pseudo_ag1_job.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace tspline {

namespace {

namespace TS = CGAL::Triangular_spline;

template <class Enum>
Enum choice(const std::string& option, const std::string& value,
            const std::vector<std::pair<std::string, Enum>>& choices) {
  std::string names;
  for (const auto& [name, e] : choices) {
    if (value == name)
      return e;
    names += (names.empty() ? "" : ", ") + name;
  }
  throw Usage_error("--" + option + " must be one of " + names + ", not '" + value + "'");
}

} // namespace

int run_pseudo_ag1(const std::vector<std::string>& args) {
  Pseudo_ag1_job job;
  Command_line cl("pseudo-ag1");
  cl.describe("Xu's pseudo-AG^1 surfaces (PhD thesis, 2002, ch. 5-6): one quintic Bezier patch "
              "per face of a closed triangle mesh; C^0 everywhere, G^1 at every vertex (each "
              "vertex's corner point and stars lie in its corner plane), the three middle "
              "diamonds of every edge on one affine relation. Tangent planes jump inside edges "
              "whose end diamonds disagree with it: the report measures these jumps, it does "
              "not hide them.");
  cl.describe("Input: a closed, manifold triangle mesh (.off/.ply/.obj/.stl); components are "
              "oriented outward. Or --shape: " +
              pseudo_ag1_shape_names() + ".");
  cl.describe("Presets: smooth (the default: thesis with the averaged diamond map that 6.2.2 "
              "suggests, kept away from thin diamonds; 1.1 to 2.2 times smaller mean normal jumps "
              "on real meshes), thesis (the "
              "method of 6.2 as written: area-weighted normals, planes half-way, "
              "raised or lowered by the mean dihedral angle, umbrella stars, offsets, "
              "parallelogram edge maps), "
              "chapter5 (the preliminary method of 5.4: planes through the centroids, projected "
              "stars, no offsets; inside the input), exact (rational steps only: computed and "
              "certified in exact rational arithmetic). Options after --preset override it.");
  cl.input(job.input, "MESH", "the closed triangle mesh");
  cl.text(job.shape, "shape", "NAME", "a test solid instead of --input");
  cl.text(job.preset, "preset", "P", "smooth, thesis, chapter5 or exact");
  std::string normal, placement, lengths, angles, rotation, shrink, inner, edge_map, flip, offsets;
  double tau = 0, gain = 0, threshold = 0, scale = 0;
  bool no_recentering = false, no_compare = false, use_double = false;
  cl.text(normal, "normal", "N", "corner-plane normal: area, average or centroid");
  cl.number(tau, "tau", "T", "plane position: 0 through the vertex, 1 through the centroid", false);
  cl.number(gain, "undulation-gain", "K", "raise/lower gain (0 disables)", false);
  cl.number(threshold, "threshold-deg", "DEG", "mean dihedral angle threshold (144)", false);
  cl.text(placement, "placement", "P", "stars: umbrella or projection");
  cl.text(lengths, "lengths", "L", "umbrella lengths: rigid, proportional or equal");
  cl.text(angles, "angles", "A", "umbrella angles: proportional or equal");
  cl.text(rotation, "rotation", "R", "umbrella rotation: least-squares or first-star");
  cl.flag(no_recentering, "no-recentering", "keep corners outside their star polygon");
  cl.number(scale, "star-scale", "S", "star scale in (0, 1]", false);
  cl.text(shrink, "shrink", "M", "star shrinking: none or auto");
  cl.text(offsets, "offsets", "S,I,F", "offsets of the stars, inner and flip points");
  cl.text(inner, "inner", "I", "corner-inner points: offset or cross-edge");
  cl.text(edge_map, "edge-map", "M", "parallelogram or averaged");
  cl.text(flip, "flip", "F", "symmetric, larger-face or lower-index");
  double least_weight = 0.4;
  cl.number(least_weight, "min-weight", "W",
            "averaged edge maps: keep the parallelogram where -lambda, mu or nu of the average "
            "is below W (thin diamonds throw the edge-middle points far: spikes)",
            false);
  cl.flag(job.exact, "exact", "exact rational arithmetic (rational options only)");
  cl.flag(use_double, "double", "double arithmetic even for the exact preset");
  cl.integer(job.samples, "samples", "K", "interior samples per edge for the normal jumps", 1,
             1000);
  cl.integer(job.levels, "levels", "L",
             "4-splits per face of the measured tessellation (default: 3, fewer above 15,000 "
             "faces, so that it stays below 10^6 triangles)",
             0, 6, "", false);
  cl.integer(job.mesh_levels, "mesh-levels", "L", "4-splits per face of --output", 0, 8);
  cl.flag(no_compare, "no-compare", "skip the PN-triangle and Fang comparators");
  cl.flag(job.per_edge, "per-edge", "list every edge in the report");
  cl.output(job.mesh, "output", "MESH.ply",
            "write the tessellated surface (.ply/.off/.obj) with normals and Gaussian curvature",
            mesh_file_output, {"mesh"});
  cl.flag(job.split_normals, "split-normals",
          "--output: every face its own copies of its edge points with its own normals (not "
          "closed; shading shows the tangent-plane jumps)");
  cl.output(job.save, "save", "F.surface", "write the control nets (tspline-surface format)",
            Output_rule{{"surface"}, false, false});
  cl.report(job.report);
  cl.output(job.ag1_system, "ag1-system", "OUT.json",
            "solve Xu 6.1's global AG^1 system by the walk from --ag1-start and write its report "
            "(relations, residuals, inadmissible edges, folds); exact with --exact",
            Output_rule{{"json"}, false, false});
  cl.integer(job.ag1_start, "ag1-start", "V", "start vertex of the walk", 0, 1LL << 40);
  cl.text(job.ag1_umbrella, "ag1-umbrella", "U",
          "start umbrella: centroid (the thesis's regular one) or projected (the mesh's star)");
  cl.output(job.ag1_save, "ag1-save", "F.surface",
            "write the AG^1 surface of the walk's solution (needs --ag1-system)",
            Output_rule{{"surface"}, false, false});
  if (!cl.parse(args))
    return 0;
  if (job.split_normals && job.mesh.empty())
    throw Usage_error("--split-normals needs --output");
  if (job.ag1_umbrella != "centroid" && job.ag1_umbrella != "projected")
    throw Usage_error("--ag1-umbrella must be centroid or projected, not '" + job.ag1_umbrella +
                      "'");
  if (job.ag1_system.empty() &&
      (cl.given("ag1-start") || cl.given("ag1-umbrella") || !job.ag1_save.empty()))
    throw Usage_error("--ag1-start, --ag1-umbrella and --ag1-save need --ag1-system");
  if (job.input.empty() == job.shape.empty())
    throw Usage_error("give exactly one of --input MESH and --shape NAME");
  try {
    job.options = TS::pseudo_AG1_preset(job.preset);
  } catch (const TS::Invalid_input&) {
    throw Usage_error("--preset must be smooth, thesis, chapter5 or exact, not '" + job.preset +
                      "'");
  }
  auto& o = job.options;
  if (cl.given("normal"))
    o.normal = choice<TS::Corner_plane_normal>("normal", normal,
                                               {{"area", TS::Corner_plane_normal::AREA_WEIGHTED},
                                                {"average", TS::Corner_plane_normal::AVERAGE},
                                                {"centroid", TS::Corner_plane_normal::CENTROID}});
  if (cl.given("tau"))
    o.plane_position = tau;
  if (cl.given("undulation-gain"))
    o.undulation_gain = gain;
  if (cl.given("threshold-deg"))
    o.undulation_threshold = threshold * CGAL_PI / 180;
  if (cl.given("placement"))
    o.placement = choice<TS::Star_placement>("placement", placement,
                                             {{"umbrella", TS::Star_placement::UMBRELLA},
                                              {"projection", TS::Star_placement::PROJECTION}});
  if (cl.given("lengths"))
    o.lengths = choice<TS::Umbrella_lengths>("lengths", lengths,
                                             {{"rigid", TS::Umbrella_lengths::RIGID},
                                              {"proportional", TS::Umbrella_lengths::PROPORTIONAL},
                                              {"equal", TS::Umbrella_lengths::EQUAL}});
  if (cl.given("angles"))
    o.angles = choice<TS::Umbrella_angles>("angles", angles,
                                           {{"proportional", TS::Umbrella_angles::PROPORTIONAL},
                                            {"equal", TS::Umbrella_angles::EQUAL}});
  if (cl.given("rotation"))
    o.rotation =
        choice<TS::Umbrella_rotation>("rotation", rotation,
                                      {{"least-squares", TS::Umbrella_rotation::LEAST_SQUARES},
                                       {"first-star", TS::Umbrella_rotation::FIRST_STAR}});
  if (no_recentering)
    o.recentering = false;
  if (cl.given("star-scale"))
    o.star_scale = scale;
  if (cl.given("shrink"))
    o.automatic_shrinking = choice<bool>("shrink", shrink, {{"none", false}, {"auto", true}});
  if (cl.given("offsets")) {
    std::vector<double> v;
    std::stringstream in(offsets);
    std::string item;
    while (std::getline(in, item, ',')) {
      char* end = nullptr;
      const double x = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || !std::isfinite(x) || x < 0)
        throw Usage_error("--offsets must be three non-negative numbers S,I,F, not '" + offsets +
                          "'");
      v.push_back(x);
    }
    if (v.size() != 3)
      throw Usage_error("--offsets must be three non-negative numbers S,I,F, not '" + offsets +
                        "'");
    o.offsets = {{v[0], v[1], v[2]}};
  }
  if (cl.given("inner"))
    o.inner = choice<TS::Inner_placement>("inner", inner,
                                          {{"offset", TS::Inner_placement::NORMAL_OFFSET},
                                           {"cross-edge", TS::Inner_placement::CROSS_EDGE_PLANES}});
  if (cl.given("edge-map"))
    o.edge_map = choice<TS::Edge_map>("edge-map", edge_map,
                                      {{"parallelogram", TS::Edge_map::PARALLELOGRAM},
                                       {"averaged", TS::Edge_map::AVERAGED_DIAMOND}});
  if (cl.given("flip"))
    o.flips = choice<TS::Flip_rule>("flip", flip,
                                    {{"symmetric", TS::Flip_rule::SYMMETRIC},
                                     {"larger-face", TS::Flip_rule::LARGER_FACE},
                                     {"lower-index", TS::Flip_rule::LOWER_INDEX_FACE}});
  if (cl.given("min-weight"))
    o.min_averaged_weight = least_weight;
  if (job.exact && use_double)
    throw Usage_error("give at most one of --exact and --double");
  if (job.preset == "exact" && !use_double)
    job.exact = true;
  if (job.exact && !o.is_rational())
    throw Usage_error("--exact needs rational options (projection placement, no offsets, "
                      "undulation gain 0, area or centroid normals, offset inner points, no "
                      "shrinking): start from --preset exact or chapter5");
  job.compare = !no_compare;
  run_pseudo_ag1_job(job, cl.summary_stream());
  return 0;
}

} // namespace tspline

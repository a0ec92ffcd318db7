// Fang §5.4 in a few lines: Nielson's side-vertex interpolant (the comparator) and Fang's
// blend (improved variant, d = 0, 1, 2) of the same mesh and normals, measured the same way:
// normal jumps across the edges, Gaussian curvature range, and the largest jump of the
// Gaussian curvature across an edge, which G^1 (and C^1) surfaces do not control. Input: a
// test mesh of Fang's ch. 8 by name (argv[1]; "ellipsoid" by default, "perturbed" is Fang's
// other mesh of §5.4).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/blending_sampler.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/Comparators/Nielson_side_vertex.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
namespace TS = CGAL::Triangular_spline;

// The largest |K| difference between the two faces of an edge, at its midpoint.
template <class Sampler>
double curvature_jump(const Mesh& mesh, const Sampler& sampler) {
  double jump = 0;
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e), o = mesh.opposite(h);
    const double a =
        sampler(mesh.face(h), TS::internal::weights_on_halfedge(mesh, h, 0.5)).gaussian;
    const double b =
        sampler(mesh.face(o), TS::internal::weights_on_halfedge(mesh, o, 0.5)).gaussian;
    jump = std::max(jump, std::abs(a - b));
  }
  return jump;
}

template <class Sampler>
void report(const std::string& name, const Mesh& mesh, const Sampler& sampler) {
  // 15 samples per edge, 4^3 triangles per face, no self-intersection test
  const TS::Closed_surface_measures m = TS::measure_closed_surface(mesh, sampler, 15, 3, false);
  std::cout << name << ": normal jump max " << m.max_jump_deg << " deg, mean " << m.mean_jump_deg
            << " deg; K in [" << m.gaussian_min << ", " << m.gaussian_max
            << "]; K jump at edge midpoints " << curvature_jump(mesh, sampler) << "\n";
}

int main(int argc, char* argv[]) {
  const std::string shape = argc > 1 ? argv[1] : "ellipsoid";
  // the test mesh with its normals in "v:normal" (estimated from the faces if it has none,
  // by both constructions in the same way)
  const Mesh mesh = TS::blending_test_mesh<Point_3>(shape);

  // Nielson: G^1 by construction; the surface is its own sampler.
  const TS::Nielson_side_vertex_surface<Point_3> nielson(mesh);
  report("Nielson", mesh, nielson);

  for (int d = 0; d <= 2; ++d) {
    TS::Mesh_blending_options options;
    options.order = d;
    options.variant = TS::Blending_variant::OPEN_SET;
    const TS::Mesh_blending_surface<Point_3> fang(mesh, options);
    report("Fang d = " + std::to_string(d), mesh, TS::Mesh_blending_sampler<Point_3>(fang));
  }

  // Nielson's surface is tangent-plane continuous up to round-off.
  return TS::measure_closed_surface(mesh, nielson, 5, 1, false).max_jump_deg < 1e-9 ? EXIT_SUCCESS
                                                                                    : EXIT_FAILURE;
}

// Fang's generalized blending: interpolate the vertices and normals of a polygon mesh with a
// surface that is C^d across the edges and at the vertices (improved variant), measure that
// continuity, and tessellate the surface. Input: a polygon mesh file (argv[1], read with
// CGAL::IO::read_polygon_mesh(); its vertex normals are then estimated from the faces) or, by
// default, the icosahedron of Fang's ch. 8 with its exact normals.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/blending_continuity.h>
#include <CGAL/Triangular_spline/Blending/blending_functions.h>
#include <CGAL/Triangular_spline/Blending/blending_parameters.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>

#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
namespace TS = CGAL::Triangular_spline;
namespace TSP = CGAL::Triangular_spline::parameters;

int main(int argc, char* argv[]) {
  // 1. The blending functions themselves (Def. 3.4): three indicators, order d = 2. On a
  //    side (one indicator zero) the inherited function has weight 1; they sum to one.
  const std::vector<double> f = TS::blending_functions(std::vector<double>{0.2, 0.3, 0.5}, 2);
  std::cout << "f^{3,2}(0.2, 0.3, 0.5) = " << f[0] << " " << f[1] << " " << f[2] << "\n";

  // 2. The input mesh, with per-vertex normals in the property map "v:normal".
  Mesh mesh;
  if (argc > 1) {
    if (!CGAL::IO::read_polygon_mesh(argv[1], mesh)) {
      std::cerr << "cannot read " << argv[1] << "\n";
      return EXIT_FAILURE;
    }
  } else {
    mesh = TS::blending_test_mesh<Point_3>("icosahedron");
  }

  // 3. The surface: blending order 2 (curvature continuous), open-set variant (§6.2),
  //    de Boor-Ron least vertex surfaces, as named parameters (ours are free functions that
  //    append to a pack: CGAL 5.5's list of member functions is closed).
  const TS::Mesh_blending_surface<Point_3> surface = TS::make_blending_surface(
      mesh, TSP::blending_order(2, TSP::blending_variant(TS::Blending_variant::OPEN_SET,
                                                         TSP::vertex_surface_method(
                                                             TS::Vertex_surface_method::LEAST))));

  // Evaluate face 0 at barycentric parameters (1/3, 1/3, 1/3), with its curvature.
  const Point_3 p = surface.evaluate(*mesh.faces().begin(), 1.0 / 3, 1.0 / 3);
  const TS::Surface_curvature k = TS::surface_curvature(surface.derivatives(0, 1.0 / 3, 1.0 / 3));
  std::cout << "centre of face 0: " << p << ", Gaussian curvature " << k.gaussian << "\n";

  // 4. Measured continuity: derivative jumps of each order across edges and at vertices.
  const TS::Blending_continuity c = TS::measure_blending_continuity(surface);
  for (int order = 0; order <= c.measured_order; ++order)
    std::cout << "order " << order << ": edge jump " << c.max_edge_jump[order] << ", vertex jump "
              << c.max_vertex_jump[order] << "\n";
  std::cout << "interpolation error at the vertices: " << c.max_position_error << " (position), "
            << c.max_normal_error_deg << " degrees (normal)\n";

  // 5. Tessellation: 8 segments per edge, normals and curvatures as vertex properties.
  Mesh out;
  const TS::Blending_tessellation_statistics stats = surface.tessellate(out, 8);
  std::cout << "tessellation: " << stats.vertices << " vertices, " << stats.faces
            << " triangles, Gaussian curvature in [" << stats.min_gaussian_curvature << ", "
            << stats.max_gaussian_curvature << "]\n";

  const double tolerance = 1e-9 * c.size;
  for (int order = 0; order <= c.measured_order; ++order)
    if (c.max_edge_jump[order] > tolerance || c.max_vertex_jump[order] > tolerance)
      return EXIT_FAILURE;
  return EXIT_SUCCESS;
}

// Xu's C^1 quintic spline over scattered data: Delaunay domain, prescription and
// propagation, exact certificate, a local edit, tessellation.
// Usage: c1_quintic_spline [points.xyz]   (default: a small embedded data set)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/Xu/Spline_space.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/gmp_small_block_pool.h>
#include <CGAL/Triangular_spline/Xu/make_c1_quintic_spline.h>
#include <CGAL/Triangular_spline/tessellate.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>; // exact: the certificate is a proof
using Spline = CGAL::Triangular_spline::C1_quintic_spline<Kernel>;
namespace TS = CGAL::Triangular_spline;

int main(int argc, char* argv[]) {
  // Exact splines are made of millions of small GMP integers on large inputs: pooled, they
  // take about two thirds of the time and memory (first thing, before other threads).
  TS::use_gmp_small_block_pool();
  // x y z per line. Vertices on the lines through (1,1) give degenerate frames (an edge end
  // collinear with the apexes of its two triangles), which the plan re-routes.
  const char* embedded = "0 0 0\n2 0 1\n0 2 1\n2 2 2\n1 1 1.25\n3 1 1.5\n1 3 1.5\n3 3 2.5\n";
  std::ifstream file;
  std::istringstream text(embedded);
  if (argc > 1)
    file.open(argv[1]);
  std::istream& input = argc > 1 ? static_cast<std::istream&>(file) : text;
  if (!input) {
    std::cerr << "cannot open " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const TS::Scattered_data<Kernel> data =
      TS::read_xyz<Kernel>(input, argc > 1 ? argv[1] : "embedded");
  auto [domain, heights] = TS::delaunay_domain(data);

  // One call: the plan (free control points and propagation rules; degenerate frames, and
  // thin ones whose weights would exceed the bound, re-routed) and the package's default fit:
  // corners through the data, every other free point from the local polynomial (degree up to
  // 5, chosen by cross-validation) of its nearest vertex where that polynomial resolves the
  // data, from the least thin-plate energy where it does not; then propagation.
  TS::Fit_statistics fit;
  Spline spline =
      TS::make_c1_quintic_spline(std::move(domain), heights, TS::parameters::fit_statistics(fit));
  std::cout << spline.domain().number_of_faces() << " triangles, "
            << spline.degenerate_frames().size() << " degenerate frames, "
            << spline.rerouted_frames().size() << " re-routed edge ends, "
            << spline.singular_vertices().size() << " singular vertices, "
            << spline.number_of_free_parameters() << " free control points";
  // The rank of the C^1 conditions modulo a prime bounds dim S^1_5 from above; the free count
  // bounds it from below: equal, they prove it (the rational rank takes minutes here).
  const TS::Dimension_bound bound = TS::spline_dimension_upper_bound(spline.domain());
  std::cout << (bound.upper_bound == spline.number_of_free_parameters() ? " (= dim S^1_5, proven)"
                                                                        : " (dim S^1_5 unproven)");
  std::cout << ", largest propagation weight " << spline.max_propagation_weight() << "\n";

  std::cout << "local polynomial degrees 0..5 at";
  for (std::size_t count : fit.vertices_by_degree)
    std::cout << " " << count;
  std::cout << " vertices; " << fit.vertices_by_trust[0] << " follow their polynomial, "
            << fit.vertices_by_trust[1] << " are blended with, " << fit.vertices_by_trust[2]
            << " replaced by the least-energy surface\n";

  // The spline is exact: the certificate is a proof, or names the edges that fail.
  TS::Continuity_certificate certificate = TS::certify_continuity(spline, 1);
  std::cout << "C^1 certificate over " << certificate.interior_edges
            << " interior edges: " << TS::verdict_name(certificate.verdict) << "\n";

  // Local control: move the corner point of an interior vertex; only its neighbourhood is
  // recomputed.
  std::uint32_t v = 0;
  while (spline.domain().is_boundary_vertex(v))
    ++v;
  const Spline::Slot s = spline.vertex_slot(v);
  const std::vector<Spline::Slot> changed = spline.edit(s, spline.value(s) + Kernel::FT(1, 10));
  std::cout << "edited the corner of vertex " << v << ": " << changed.size()
            << " control points recomputed\n";
  certificate = TS::certify_continuity(spline, 1);
  std::cout << "after the edit: " << (certificate.certified ? "still C^1 (exact)" : "NOT C^1")
            << "\n";

  // Triangle mesh of the surface, 3 levels of 4-split per patch, with exact normals.
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  const TS::Tessellation_statistics stats = TS::tessellate(spline, 3, mesh);
  TS::write_mesh("c1_quintic_spline.off", mesh);
  std::cout << "wrote c1_quintic_spline.off (" << stats.faces << " triangles)\n";
  return certificate.certified ? EXIT_SUCCESS : EXIT_FAILURE;
}

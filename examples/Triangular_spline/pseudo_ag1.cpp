// Xu's pseudo-AG^1 surface over a closed triangle mesh: build it, prove its continuity
// exactly, measure how far it is from G^1 along the edges, and write it. Input: a closed
// triangle mesh (argv[1], read with CGAL::IO::read_polygon_mesh()) or, by default, the
// regular octahedron.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>
#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <cassert>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace TS = CGAL::Triangular_spline;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

int main(int argc, char* argv[]) {
  CGAL::Surface_mesh<Epick::Point_3> mesh;
  if (argc > 1) {
    if (!CGAL::IO::read_polygon_mesh(argv[1], mesh)) {
      std::cerr << "cannot read " << argv[1] << "\n";
      return EXIT_FAILURE;
    }
  } else {
    mesh = TS::thesis_polyhedron<Epick>("octahedron");
  }

  // 1. The method of the thesis (§6.2), in double: corner planes half-way between each vertex
  //    and the centroid of its star, umbrella stars, offsets against undulations.
  const TS::Pseudo_AG1_surface<Epick> surface(mesh);
  const TS::Pseudo_AG1_certificate residuals = TS::certify_pseudo_AG1(surface);
  std::cout << "thesis preset: " << residuals.middle_edges << "/" << residuals.edges
            << " edges with their middle diamonds on one relation, G^1 at " << residuals.g1_vertices
            << "/" << residuals.vertices << " vertices (tolerance " << residuals.tolerance << ")\n";

  // 2. How far from G^1 along the edges: normal jumps from the exact patch derivatives, and
  //    the shape against the input.
  const TS::Patch_sampler<TS::Pseudo_AG1_surface<Epick>> sampler(surface);
  const TS::Closed_surface_measures m = TS::measure_closed_surface(surface.mesh(), sampler);
  std::cout << "normal jump across edges: max " << m.max_jump_deg << " deg, mean "
            << m.mean_jump_deg << " deg; at vertices " << m.vertex_max_jump_deg
            << " deg; volume ratio " << m.volume_ratio << "\n";

  // 3. The rational preset in exact arithmetic: the certificate is a proof. Only for small
  //    meshes with rational coordinates (every double is one).
  if (argc == 1) {
    CGAL::Surface_mesh<Exact::Point_3> exact_mesh = TS::thesis_polyhedron<Exact>("octahedron");
    const TS::Pseudo_AG1_surface<Exact> exact(exact_mesh, TS::Pseudo_AG1_options::exact());
    const TS::Pseudo_AG1_certificate proof = TS::certify_pseudo_AG1(exact);
    std::cout << "exact preset: pseudo-AG^1 " << (proof.pseudo_AG1() ? "proved" : "FAILED") << " ("
              << proof.ag1_edges << " of " << proof.edges << " edges AG^1)\n";
    assert(proof.exact && proof.pseudo_AG1());

    // 4. Saved and read back exactly; the certificate of the file solves the relations
    //    from the control nets alone.
    std::stringstream file;
    TS::write_surface_file(file, exact);
    const TS::Surface_file<Exact> read = TS::read_surface_file<Exact>(file, "octahedron.surface");
    const TS::Pseudo_AG1_view<TS::Surface_file<Exact>> view(read);
    assert(TS::certify_pseudo_AG1(view).pseudo_AG1());
  }

  // 5. A watertight tessellation (shared edge points) for display.
  const TS::Closed_tessellation t = TS::tessellate_closed_surface(surface.mesh(), sampler, 3);
  std::cout << "tessellation: " << t.mesh.number_of_vertices() << " vertices, "
            << t.mesh.number_of_faces() << " triangles, closed: " << std::boolalpha
            << CGAL::is_closed(t.mesh) << "\n";
  return residuals.pseudo_AG1() ? EXIT_SUCCESS : EXIT_FAILURE;
}

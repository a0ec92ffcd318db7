// Bézier triangles: build Enneper's surface exactly as a cubic patch (Xu §2.7.2), read its
// control net (Xu Table 2.2), evaluate it, take derivatives and curvature, subdivide it.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/differential_geometry.h>

#include <cstdlib>
#include <iostream>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Kernel::FT;
using Point_2 = Kernel::Point_2;
using Vector_3 = Kernel::Vector_3;
namespace TS = CGAL::Triangular_spline;

int main() {
  // F(u,v) = (u - u^3/3 + u v^2, v - v^3/3 + u^2 v, u^2 - v^2), a cubic polynomial surface;
  // Polynomial_surface::set_coefficient() builds any other one the same way.
  const TS::Polynomial_surface<Kernel, Vector_3> enneper = TS::enneper_surface<Kernel>();

  // Control net over the frame r = (1,0), s = (0,1), t = (0,0): exact rationals.
  const TS::Bezier_triangle<Kernel, Vector_3> patch =
      enneper.to_bezier(3, Point_2(1, 0), Point_2(0, 1), Point_2(0, 0));
  std::cout << "Enneper's surface, control points f(r^i s^j t^k):\n";
  for (const TS::Multi_index& index : TS::multi_indices(patch.degree()))
    std::cout << "  b_" << index.i << index.j << index.k << " = (" << patch.control_point(index)
              << ")  [" << TS::role_name(TS::role(index)) << "]\n";

  // Evaluation, the blossom, and derivatives are exact.
  const Point_2 a(FT(1) / FT(4), FT(1) / FT(2));
  std::cout << "F(1/4, 1/2)         = (" << patch.evaluate(a) << ")\n";
  std::cout << "f(r, s, a)          = (" << patch.blossom({Point_2(1, 0), Point_2(0, 1), a})
            << ")\n";
  std::cout << "dF/du (1/4, 1/2)    = (" << patch.partial_derivative(a, 1, 0) << ")\n";

  // Enneper's surface is minimal: mean curvature 0 everywhere (up to double round-off).
  const TS::Surface_curvature c = TS::surface_curvature(patch, a);
  std::cout << "Gaussian curvature  = " << c.gaussian << "\nmean curvature      = " << c.mean
            << "\n";

  // Midpoint subdivision and degree elevation represent the same polynomial exactly.
  const auto quarters = patch.subdivide();
  const auto elevated = patch.elevate_degree();
  const bool same =
      quarters[3].evaluate(a) == patch.evaluate(a) && elevated.evaluate(a) == patch.evaluate(a);
  std::cout << "subdivision and elevation reproduce F exactly: " << (same ? "yes" : "no") << "\n";
  return same && std::abs(c.mean) < 1e-12 ? EXIT_SUCCESS : EXIT_FAILURE;
}

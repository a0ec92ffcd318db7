// Built against an installed Triangular_spline: a light header (no triangulation, no Eigen
// solve) so that the test compiles in seconds. Exit status 0 iff the value is right.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Bezier_triangle.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
  using K = CGAL::Simple_cartesian<double>;
  // Degree 1 over r = (0,0), s = (1,0), t = (0,1) with the values of x + 2y at the corners:
  // the plane itself. The net lists b_001 (t), b_010 (s), b_100 (r): 2, 1, 0.
  const CGAL::Triangular_spline::Bezier_triangle<K, double> plane(
      1, K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(0, 1), std::vector<double>{2, 1, 0});
  const double z = plane.evaluate(K::Point_2(0.25, 0.5));
  std::cout << "Triangular_spline " << TRIANGULAR_SPLINE_VERSION << ": F(0.25, 0.5) = " << z
            << "\n";
  return std::abs(z - 1.25) < 1e-15 ? 0 : 1;
}

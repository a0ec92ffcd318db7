// Mann's continuity adjustment: two quintic patches that meet only C^0 are raised to C^1 by
// averaging (the Foley-Opitz step), a pair cut from one polynomial is left untouched, and
// Mann's interpolant reproduces quintic data over a small triangulation and is certified
// C^1, all in exact rational arithmetic.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Mann/Continuity_adjustment.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>

#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Kernel::FT;
using Point_2 = Kernel::Point_2;
namespace TS = CGAL::Triangular_spline;

// A quintic with small rational coefficients.
TS::Polynomial_surface<Kernel> sample_quintic() {
  TS::Polynomial_surface<Kernel> p(5);
  int c = 1;
  for (int h = 0; h <= 5; ++h)
    for (int k = 0; h + k <= 5; ++k, ++c)
      p.set_coefficient(h, k, FT(c % 7 - 3) / FT(c % 4 + 1));
  return p;
}

int main() {
  bool ok = true;
  // A over (p, r, s), B over (q, r, s): the shared edge rs is found by exact comparison.
  const Point_2 p(0, 0), r(3, 1), s(1, 2), q(4, 3);
  const TS::Polynomial_surface<Kernel> P = sample_quintic();

  // 1. A pair cut from one polynomial already meets C^1: nothing moves, bit for bit.
  auto A = P.to_bezier(5, p, r, s);
  auto B = P.to_bezier(5, q, r, s);
  TS::Join_adjustment moved = TS::adjust_join(A, B, 1);
  std::cout << "same polynomial: " << moved.first_touched.size() + moved.second_touched.size()
            << " control points moved\n";
  ok = ok && !moved.changed();

  // 2. Bend B's first row: still C^0, no longer C^1. The adjustment moves row 1 of each
  //    patch (one point per condition) and restores C^1 exactly.
  B.set_control_point(TS::Multi_index{1, 2, 2}, B.control_point(1, 2, 2) + FT(1) / FT(10));
  std::cout << "after the edit: C^" << TS::check_join(A, B, 5).achieved_order << "\n";
  moved = TS::adjust_join(A, B, 1);
  const bool c1 = TS::is_Ck_join(A, B, 1);
  std::cout << "after the adjustment: C^1 " << (c1 ? "holds" : "FAILS") << ", moved "
            << moved.first_touched.size() << " + " << moved.second_touched.size()
            << " control points\n";
  ok = ok && c1 && moved.changed();

  // 3. Mann's interpolant over a small triangulation, from the Taylor polynomials of P at
  //    the vertices: it reproduces P and is C^1.
  const std::vector<Point_2> points{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}, {1, 3}};
  const TS::Planar_domain<Kernel> domain(
      points, {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 5, 4}}, {{2, 3, 5}}, {{3, 0, 5}}, {{0, 4, 5}}});
  std::vector<TS::Polynomial_surface<Kernel>> jets;
  for (const Point_2& v : domain.points())
    jets.push_back(TS::taylor_polynomial(P, v));
  const TS::Mann_interpolant<Kernel> interpolant = TS::mann_interpolant(domain, jets);
  bool reproduces = true;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const Point_2 x = CGAL::centroid(points[domain.face(f)[0]], points[domain.face(f)[1]],
                                     points[domain.face(f)[2]]);
    reproduces = reproduces && interpolant.patch(f).evaluate(x) == P.evaluate(x);
  }
  const TS::Continuity_certificate certificate = TS::certify_continuity(interpolant, 1);
  std::cout << "interpolant of a quintic: reproduces it " << (reproduces ? "exactly" : "NOT")
            << "; C^1 certificate: " << TS::verdict_name(certificate.verdict) << "\n";
  ok = ok && reproduces && certificate.certified;

  // 4. General vertex data (here cubic Taylor polynomials of unrelated cubics): the C^0
  //    network is repaired to C^1 by moving one point per patch and edge.
  std::vector<TS::Polynomial_surface<Kernel>> other;
  for (std::size_t v = 0; v < domain.number_of_vertices(); ++v) {
    TS::Polynomial_surface<Kernel> cubic(3);
    cubic.set_coefficient(0, 0, FT(int(v)));
    cubic.set_coefficient(2, 1, FT(int(v % 3)) - 1);
    cubic.set_coefficient(0, 3, FT(1) / FT(int(v) + 1));
    other.push_back(cubic);
  }
  const TS::Mann_interpolant<Kernel> repaired = TS::mann_interpolant(domain, other);
  const bool repaired_c1 =
      TS::certify_continuity(repaired, 1).verdict == TS::Certificate_verdict::PROOF;
  std::cout << "general data: " << repaired.adjustment.number_of_touched_points()
            << " control points moved over " << repaired.adjustment.number_of_changed_edges()
            << " edges, C^1 " << (repaired_c1 ? "certified" : "FAILED") << "\n";
  ok = ok && repaired_c1;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

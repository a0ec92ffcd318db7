// C^k joins: two quintic patches over adjacent triangles, tested for continuity exactly
// (Xu Lemma 3.1.4, Lai's conditions), then a control point is moved and the test reports
// which condition fails and by how much. A double patch pair is certified by converting
// it exactly.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <cstdlib>
#include <iostream>

using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace TS = CGAL::Triangular_spline;

template <class K>
TS::Polynomial_surface<K> sample_polynomial() {
  TS::Polynomial_surface<K> p(5);
  int c = 1;
  for (int h = 0; h <= 5; ++h)
    for (int k = 0; h + k <= 5; ++k, ++c)
      p.set_coefficient(h, k, typename K::FT(c % 7 - 3) / typename K::FT(c % 4 + 1));
  return p;
}

int main() {
  using Point_2 = Exact::Point_2;
  // A = (p, r, s), B = (q, r, s): shared edge rs, apexes on opposite sides.
  const Point_2 p(0, 0), r(3, 1), s(1, 2), q(4, 3);
  const TS::Polynomial_surface<Exact> polynomial = sample_polynomial<Exact>();
  const auto A = polynomial.to_bezier(5, p, r, s);
  auto B = polynomial.to_bezier(5, q, r, s);

  // Cut from one polynomial: C^5, the highest order a quintic pair can have.
  TS::Join_report report = TS::check_join(A, B, 5, TS::Join_conditions::LAI);
  std::cout << "same polynomial: C^" << report.achieved_order << " (exact: " << std::boolalpha
            << report.exact << ")\n";

  // Move b_{1,2,2} of B (one copy of q: a C^1 condition) by 1/10.
  B.set_control_point(TS::Multi_index{1, 2, 2},
                      B.control_point(1, 2, 2) + Exact::FT(1) / Exact::FT(10));
  report = TS::check_join(A, B, 1);
  std::cout << "after the edit: C^1 " << (report.holds ? "holds" : "fails") << ", achieved C^"
            << report.achieved_order << "\n";
  for (const TS::Join_condition& c : report.conditions)
    if (!c.satisfied)
      std::cout << "  violated: f(q^" << c.q_count << " r^" << c.r_count << " s^" << c.s_count
                << ") differs by " << c.residual << "\n";

  // The same test in double reports residuals; converting the double nets to exact
  // rationals (exact conversion) gives a proof either way.
  const TS::Polynomial_surface<Fast> fast = sample_polynomial<Fast>();
  const auto Af = fast.to_bezier(5, Fast::Point_2(0, 0), Fast::Point_2(3, 1), Fast::Point_2(1, 2));
  const auto Bf = fast.to_bezier(5, Fast::Point_2(4, 3), Fast::Point_2(3, 1), Fast::Point_2(1, 2));
  std::cout << "double nets: largest C^1 residual " << TS::join_residual(Af, Bf, 1) << "\n";
  const bool proved = TS::is_Ck_join(TS::convert_patch<Exact>(Af), TS::convert_patch<Exact>(Bf), 1);
  std::cout << "double nets, converted exactly: C^1 " << (proved ? "proved" : "refuted")
            << " (rounding in double breaks exact continuity unless the data is dyadic)\n";
  return report.achieved_order == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

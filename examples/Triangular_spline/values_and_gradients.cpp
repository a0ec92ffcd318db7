// From scattered points to values, gradients and Hessians: Delaunay domain, C^1 quintic
// spline fitted with local polynomials, then evaluate_jets() at a few points (inside, on the
// hull up to rounding, and outside with linear extrapolation).
// The data come from a cubic, which the fit reproduces exactly in exact arithmetic: every
// printed jet equals the cubic's, and the program checks it.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/Xu/fit_vertex_data.h>

#include <cstdlib>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Kernel::FT;
using Point_2 = Kernel::Point_2;
namespace TS = CGAL::Triangular_spline;

// f = x^3 - 2 x y^2 + y / 2 + 1 and its exact derivatives
FT f(const Point_2& p) {
  const FT x = p.x(), y = p.y();
  return x * x * x - 2 * x * y * y + y / 2 + 1;
}
TS::Point_jet<FT> jet_of_f(const Point_2& p) {
  const FT x = p.x(), y = p.y();
  return {f(p), {{3 * x * x - 2 * y * y, -4 * x * y + FT(1) / 2}}, {{6 * x, -4 * y, -4 * x}}};
}

int main() {
  // 40 scattered points with rational coordinates in [0, 1]^2 (a deterministic sequence)
  TS::Scattered_data<Kernel> data;
  for (int k = 0; k < 40; ++k) {
    const Point_2 p(FT((k * 37) % 101) / 100, FT((k * 61) % 103) / 102);
    data.points.push_back(p);
    data.values.push_back(f(p));
  }
  auto [domain, heights] = TS::delaunay_domain(data);

  // The spline: corners interpolate, the other free points come from local polynomials.
  TS::C1_quintic_spline<Kernel> spline(std::move(domain), TS::Corner_frame::CORNER_AND_TWO_STARS);
  TS::fit_vertex_data(spline, heights, TS::Fit::LOCAL_POLYNOMIAL, 3);

  // Locate-and-evaluate: one locator per domain, then any number of queries.
  const TS::Domain_locator<Kernel> locator(spline.domain());
  // A point 1e-12 of an edge length outside a hull edge, as rounding leaves it: it snaps to
  // the edge and gets the value at its projection, the edge's midpoint.
  const auto& d = spline.domain();
  std::uint32_t e = 0;
  while (!d.is_boundary_edge(e))
    ++e;
  const Point_2 &a = d.point(d.edge(e)[0]), &b = d.point(d.edge(e)[1]);
  const std::uint32_t face =
      d.edge_faces(e)[0] != d.null_index ? d.edge_faces(e)[0] : d.edge_faces(e)[1];
  const Point_2 mid = CGAL::midpoint(a, b);
  Kernel::Vector_2 out(b.y() - a.y(), a.x() - b.x());
  if ((d.point(d.opposite_vertex(face, e)) - mid) * out > 0)
    out = -out;
  const Point_2 rounded = mid + out * (FT(1) / FT(1000000) / FT(1000000));

  // query -> where the spline's jet should equal the cubic's (none: outside)
  const std::vector<std::pair<Point_2, std::optional<Point_2>>> cases{
      {Point_2(FT(1) / 2, FT(1) / 2), Point_2(FT(1) / 2, FT(1) / 2)},
      {Point_2(FT(3) / 10, FT(7) / 10), Point_2(FT(3) / 10, FT(7) / 10)},
      {rounded, mid},
      {Point_2(2, FT(1) / 2), std::nullopt}};
  std::vector<Point_2> queries;
  for (const auto& c : cases)
    queries.push_back(c.first);
  const auto jets = TS::evaluate_jets(spline, locator, queries, TS::Outside::LINEAR,
                                      /*order=*/2);

  bool all_exact = true;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const auto& jet = jets[q];
    std::cout << "at (" << CGAL::to_double(queries[q].x()) << ", "
              << CGAL::to_double(queries[q].y()) << "): ";
    if (!jet) {
      std::cout << "no value\n";
      all_exact = false;
      continue;
    }
    std::cout << "z = " << CGAL::to_double(jet->value) << ", gradient ("
              << CGAL::to_double(jet->gradient[0]) << ", " << CGAL::to_double(jet->gradient[1])
              << "), Hessian (" << CGAL::to_double(jet->hessian[0]) << ", "
              << CGAL::to_double(jet->hessian[1]) << ", " << CGAL::to_double(jet->hessian[2])
              << ")\n";
    if (cases[q].second) {
      // in the domain the spline is the cubic, derivatives included, exactly
      const TS::Point_jet<FT> expected = jet_of_f(*cases[q].second);
      const bool exact = jet->value == expected.value && jet->gradient == expected.gradient &&
                         jet->hessian == expected.hessian;
      all_exact = all_exact && exact;
      std::cout << (exact ? "  = the cubic's, exactly\n" : "  DIFFERS from the cubic\n");
    } else {
      std::cout << "  outside: linear extrapolation from the nearest boundary point\n";
    }
  }
  return all_exact ? EXIT_SUCCESS : EXIT_FAILURE;
}

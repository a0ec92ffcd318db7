// The library showcase run by `tspline demo` until the main job lands: Enneper's surface
// checked against Xu's Table 2.2, and an exact C^k join test of two quintic patches.

#include "cli.h"
#include "commands.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/continuity.h>

#include <fstream>
#include <ostream>
#include <sstream>

namespace tspline {

namespace {

using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Exact::FT;
using Point_2 = Exact::Point_2;
using Vector_3 = Exact::Vector_3;
namespace TS = CGAL::Triangular_spline;

std::string to_text(const Vector_3& v) {
  std::ostringstream out;
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

// Xu §2.7.2 and Table 2.2; returns whether every control point matches.
bool enneper(std::ostream& out, Json& report) {
  const FT third = FT(1) / FT(3), two_thirds = FT(2) / FT(3);
  const auto patch =
      TS::enneper_surface<Exact>().to_bezier(3, Point_2(1, 0), Point_2(0, 1), Point_2(0, 0));
  const std::vector<std::pair<TS::Multi_index, Vector_3>> table = {
      {{3, 0, 0}, Vector_3(two_thirds, 0, 1)},
      {{2, 1, 0}, Vector_3(two_thirds, two_thirds, third)},
      {{2, 0, 1}, Vector_3(two_thirds, 0, third)},
      {{1, 2, 0}, Vector_3(two_thirds, two_thirds, -third)},
      {{1, 1, 1}, Vector_3(third, third, 0)},
      {{1, 0, 2}, Vector_3(third, 0, 0)},
      {{0, 3, 0}, Vector_3(0, two_thirds, -1)},
      {{0, 2, 1}, Vector_3(0, two_thirds, -third)},
      {{0, 1, 2}, Vector_3(0, third, 0)},
      {{0, 0, 3}, Vector_3(0, 0, 0)}};
  out << "Enneper's surface as a cubic Bezier triangle over r=(1,0), s=(0,1), t=(0,0):\n";
  bool all = true;
  Json points = Json::array();
  for (const auto& [index, expected] : table) {
    const Vector_3& b = patch.control_point(index);
    const bool same = (b == expected);
    all = all && same;
    out << "  f(r^" << index.i << " s^" << index.j << " t^" << index.k << ") = " << to_text(b)
        << (same ? "" : "   <-- differs from Xu Table 2.2") << "\n";
    Json row = Json::object();
    row.set("index", std::to_string(index.i) + std::to_string(index.j) + std::to_string(index.k));
    row.set("value", to_text(b));
    row.set("matches_table", same);
    points.push_back(row);
  }
  out << "  Xu Table 2.2 reproduced exactly: " << (all ? "yes" : "NO") << "\n\n";
  report.set("enneper_control_points", points);
  report.set("enneper_matches_xu_table_2_2", all);
  return all;
}

// Two quintics cut from one polynomial join C^5; one edited control point drops it to C^0.
bool join_test(std::ostream& out, Json& report) {
  TS::Polynomial_surface<Exact> polynomial(5);
  int c = 1;
  for (int h = 0; h <= 5; ++h)
    for (int k = 0; h + k <= 5; ++k, ++c)
      polynomial.set_coefficient(h, k, FT(c % 7 - 3) / FT(c % 4 + 1));
  const Point_2 p(0, 0), r(3, 1), s(1, 2), q(4, 3);
  const auto A = polynomial.to_bezier(5, p, r, s);
  auto B = polynomial.to_bezier(5, q, r, s);
  const TS::Join_report intact = TS::check_join(A, B, 5, TS::Join_conditions::Lai);
  B.set_control_point(TS::Multi_index{1, 2, 2}, B.control_point(1, 2, 2) + FT(1) / FT(10));
  const TS::Join_report edited = TS::check_join(A, B, 1);
  out << "Two quintic patches over (0,0),(3,1),(1,2) and (4,3),(3,1),(1,2):\n"
      << "  cut from one polynomial: exactly C^" << intact.achieved_order << " (Lai's conditions, "
      << intact.conditions.size() << " blossom comparisons)\n"
      << "  after moving b_122 of the second patch by 1/10: C^1 "
      << (edited.holds ? "holds" : "fails") << ", largest residual " << edited.max_residual
      << "\n\n";
  report.set("join_intact_order", intact.achieved_order);
  report.set("join_edited_order", edited.achieved_order);
  report.set("join_edited_max_residual", edited.max_residual);
  return intact.achieved_order == 5 && edited.achieved_order == 0;
}

} // namespace

int run_core_showcase(std::ostream& out, const std::filesystem::path& dir) {
  Json report = Json::object();
  const bool ok_enneper = enneper(out, report);
  const bool ok_join = join_test(out, report);
  const std::filesystem::path file = dir / "core_showcase.json";
  std::ofstream json(file);
  if (!json)
    throw std::runtime_error("cannot write " + file.string());
  report.write(json);
  json << "\n";
  out << "report written to " << file.string() << "\n";
  return ok_enneper && ok_join ? 0 : 1;
}

} // namespace tspline

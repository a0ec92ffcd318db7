// Nielson's side-vertex interpolant (Comparators/Nielson_side_vertex.h), the comparator of
// Fang's mesh blending: interpolation, shared boundary curves, G^1 across edges and at
// vertices, reproduction of planes and of a sphere's normals, bad input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Triangular_spline/Comparators/Nielson_side_vertex.h>
#include <CGAL/Triangular_spline/closed_surface.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace {

namespace TS = CGAL::Triangular_spline;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Epick::Point_3;
using Vector_3 = Epick::Vector_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Nielson = TS::Nielson_side_vertex_surface<Point_3>;
using Vec3 = std::array<double, 3>;

double angle_deg(const Vec3& a, const Vec3& b) {
  return TS::internal::closed_angle_deg(a, b);
}

Vec3 unit_normal(const TS::Surface_derivatives& d) {
  return TS::surface_curvature(d).normal;
}

// The weights of face f giving weight `x` to vertex a, `1 - x` to vertex b, 0 to the third.
std::array<double, 3> on_edge(const Nielson& s, std::size_t f, std::size_t a, std::size_t b,
                              double x, double y) {
  std::array<double, 3> w{{0, 0, 0}};
  for (std::size_t c = 0; c < 3; ++c) {
    if (s.face_vertices(f)[c] == a)
      w[c] = x;
    if (s.face_vertices(f)[c] == b)
      w[c] = y;
  }
  return w;
}

// A planar 3x3 grid of squares, each cut into two triangles, on the plane z = 0.3x - 0.2y.
Mesh planar_grid(bool with_normals) {
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i)
      v.push_back(m.add_vertex(Point_3(i + 0.1 * j, j, 0.3 * (i + 0.1 * j) - 0.2 * j)));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const std::size_t a = std::size_t(4 * j + i);
      m.add_face(v[a], v[a + 1], v[a + 5]);
      m.add_face(v[a], v[a + 5], v[a + 4]);
    }
  if (with_normals) {
    auto n = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:normal").first;
    for (auto x : m.vertices())
      n[x] = Vector_3(-0.3, 0.2, 1) * 2.5; // not unit on purpose
  }
  return m;
}

TEST(NielsonSideVertex, InterpolatesVerticesAndIsContinuousThere) {
  for (const char* name : {"icosahedron", "perturbed", "franke4"}) {
    const Mesh mesh = TS::blending_test_mesh<Point_3>(name);
    const Nielson s(mesh);
    for (auto f : mesh.faces())
      for (std::size_t c = 0; c < 3; ++c) {
        std::array<double, 3> w{{0, 0, 0}};
        w[c] = 1;
        const Point_3 p = mesh.point(Mesh::Vertex_index(Mesh::size_type(s.face_vertices(f)[c])));
        EXPECT_EQ(s.evaluate(f, w), p) << name;
        // the blend itself tends to the vertex (the corner is a limit, not a special value)
        w[c] = 1 - 2e-9;
        w[(c + 1) % 3] = w[(c + 2) % 3] = 1e-9;
        EXPECT_LT(std::sqrt(CGAL::squared_distance(s.evaluate(f, w), p)), 1e-8) << name;
      }
  }
}

TEST(NielsonSideVertex, BoundaryCurvesSharedByBothFaces) {
  for (const char* name : {"ellipsoid", "torus", "franke4"}) {
    const Mesh mesh = TS::blending_test_mesh<Point_3>(name);
    const Nielson s(mesh);
    std::size_t interior = 0;
    for (auto e : mesh.edges()) {
      const auto h = mesh.halfedge(e);
      const std::array<std::size_t, 2> ab = s.edge_vertices(std::size_t(e));
      const std::array<Vec3, 4>& c = s.edge_curve(std::size_t(e));
      for (double t : {0.1, 0.37, 0.5, 0.81}) {
        // the Bézier curve by de Casteljau: an independent evaluation
        Vec3 q;
        for (std::size_t k = 0; k < 3; ++k) {
          const double a = c[0][k] + t * (c[1][k] - c[0][k]), b = c[1][k] + t * (c[2][k] - c[1][k]),
                       d = c[2][k] + t * (c[3][k] - c[2][k]);
          const double ab2 = a + t * (b - a), bd = b + t * (d - b);
          q[k] = ab2 + t * (bd - ab2);
        }
        std::vector<Vec3> points;
        for (auto g : {mesh.face(h), mesh.face(mesh.opposite(h))}) {
          if (g == Mesh::null_face())
            continue;
          points.push_back(
              s.point(std::size_t(g), on_edge(s, std::size_t(g), ab[0], ab[1], 1 - t, t)));
          for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(points.back()[k], q[k], 1e-14) << name;
        }
        if (points.size() == 2) {
          ++interior;
          EXPECT_EQ(points[0], points[1]) << name << ": C^0 must be exact in double";
        }
      }
    }
    EXPECT_GT(interior, 0u);
  }
}

TEST(NielsonSideVertex, G1AcrossEdgesAndAtVertices) {
  for (const char* name : {"icosahedron", "ellipsoid", "torus", "perturbed"}) {
    const Mesh mesh = TS::blending_test_mesh<Point_3>(name);
    const Nielson s(mesh);
    const TS::Closed_surface_measures m = TS::measure_closed_surface(mesh, s, 7, 1, false);
    EXPECT_LT(m.max_jump_deg, 1e-9) << name;
    EXPECT_EQ(m.singular_samples, 0u) << name;
    EXPECT_EQ(m.folded_samples, 0u) << name;
    // not the input mesh: the surface bulges out of a convex polyhedron
    if (std::string(name) == "icosahedron") {
      EXPECT_GT(m.volume_ratio, 1.05);
    }
    // G^1 at the vertices: the derivative normal of every face at its corners (the limit
    // derivatives) and nearby is the vertex normal
    for (auto f : mesh.faces())
      for (std::size_t c = 0; c < 3; ++c) {
        const Vec3& n = s.vertex_normal(s.face_vertices(f)[c]);
        std::array<double, 3> w{{0, 0, 0}};
        w[c] = 1;
        EXPECT_LT(angle_deg(unit_normal(s.derivatives(f, w)), n), 1e-9) << name;
        w[c] = 1 - 2e-7;
        w[(c + 1) % 3] = 0.5e-7;
        w[(c + 2) % 3] = 1.5e-7;
        EXPECT_LT(angle_deg(unit_normal(s.derivatives(f, w)), n), 1e-3) << name;
      }
  }
}

TEST(NielsonSideVertex, G1AcrossInteriorEdgesOfAnOpenMesh) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("franke8");
  const Nielson s(mesh);
  double worst = 0;
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e);
    if (mesh.is_border(e))
      continue;
    const std::array<std::size_t, 2> ab = s.edge_vertices(std::size_t(e));
    for (double t : {0.2, 0.5, 0.7}) {
      const std::size_t f = std::size_t(mesh.face(h)), g = std::size_t(mesh.face(mesh.opposite(h)));
      worst = std::max(worst, angle_deg(s.sample(f, on_edge(s, f, ab[0], ab[1], 1 - t, t)).normal,
                                        s.sample(g, on_edge(s, g, ab[0], ab[1], 1 - t, t)).normal));
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(NielsonSideVertex, ReproducesSphereNormalsAtVertices) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("icosahedron"); // unit sphere, exact normals
  const Nielson s(mesh);
  for (auto f : mesh.faces())
    for (std::size_t c = 0; c < 3; ++c) {
      const auto v = Mesh::Vertex_index(Mesh::size_type(s.face_vertices(f)[c]));
      const Vec3 radial{{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}};
      std::array<double, 3> w{{0, 0, 0}};
      w[c] = 1;
      EXPECT_LT(angle_deg(s.sample(std::size_t(f), w).normal, radial), 1e-12);
      EXPECT_LT(angle_deg(unit_normal(s.derivatives(std::size_t(f), w)), radial), 1e-9);
    }
}

TEST(NielsonSideVertex, PlanarInputGivesTheFlatTriangles) {
  for (bool given : {true, false}) {
    const Mesh mesh = planar_grid(given);
    const Nielson s(mesh);
    EXPECT_EQ(s.has_estimated_normals(), !given);
    for (auto f : mesh.faces()) {
      const auto& c = s.face_vertices(std::size_t(f));
      for (const std::array<double, 3>& w :
           {std::array<double, 3>{{0.2, 0.3, 0.5}}, std::array<double, 3>{{0, 0.4, 0.6}},
            std::array<double, 3>{{0.9, 0.05, 0.05}}, std::array<double, 3>{{1, 0, 0}}}) {
        Vec3 flat{{0, 0, 0}};
        for (std::size_t a = 0; a < 3; ++a) {
          const Point_3& p = mesh.point(Mesh::Vertex_index(Mesh::size_type(c[a])));
          flat[0] += w[a] * p.x();
          flat[1] += w[a] * p.y();
          flat[2] += w[a] * p.z();
        }
        const Vec3 p = s.point(std::size_t(f), w);
        for (std::size_t k = 0; k < 3; ++k)
          EXPECT_NEAR(p[k], flat[k], 1e-13);
        const TS::Surface_sample x = s.sample(std::size_t(f), w);
        EXPECT_NEAR(x.gaussian, 0, 1e-10);
        EXPECT_LT(angle_deg(x.normal, Vec3{{-0.3, 0.2, 1}}), 1e-9);
      }
    }
  }
}

TEST(NielsonSideVertex, BadInputIsRejected) {
  auto message = [](const Mesh& mesh) -> std::string {
    try {
      const Nielson s(mesh);
    } catch (const TS::Invalid_input& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(TS::blending_test_mesh<Point_3>("cube")).find("not 3"), std::string::npos);
  EXPECT_NE(message(Mesh()).find("no face"), std::string::npos);
  Mesh zero = TS::blending_test_mesh<Point_3>("icosahedron");
  auto n = zero.property_map<Mesh::Vertex_index, Vector_3>("v:normal").first;
  n[*zero.vertices().begin()] = Vector_3(0, 0, 0);
  EXPECT_NE(message(zero).find("zero"), std::string::npos);
  Mesh against = TS::blending_test_mesh<Point_3>("icosahedron");
  auto m = against.property_map<Mesh::Vertex_index, Vector_3>("v:normal").first;
  m[*against.vertices().begin()] = -m[*against.vertices().begin()];
  EXPECT_NE(message(against).find("against"), std::string::npos);
  Mesh garbage = TS::blending_test_mesh<Point_3>("icosahedron");
  garbage.remove_face(*garbage.faces().begin());
  EXPECT_NE(message(garbage).find("removed"), std::string::npos);
}

} // namespace

// Tests of the named parameters of the generalized blending (blending_parameters.h): each
// parameter reaches its option, the vertex normal and point maps replace the mesh's own, and
// our parameters combine with CGAL's in both orders. And the generic PolygonMesh input of
// Mesh_blending_surface: a Polyhedron_3 gives the Surface_mesh's surface bit for bit, a
// normal map gives the "v:normal" surface, bad input is Invalid_input.
#include "test_support.h"

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Blending/blending_parameters.h>
#include <CGAL/Triangular_spline/Blending/test_meshes.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using namespace ts_test;
namespace TSP = CGAL::Triangular_spline::parameters;
using Point_3 = Epick::Point_3;
using Vector_3 = Epick::Vector_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Blending_surface = TS::Mesh_blending_surface<Point_3>;

// Wrong-typed values do not compile (an enum class does not convert to int, nor an int to
// an enum class).
template <class A, class = void>
struct Accepts_order : std::false_type {};
template <class A>
struct Accepts_order<A, std::void_t<decltype(TSP::blending_order(std::declval<A>()))>>
    : std::true_type {};
template <class A, class = void>
struct Accepts_variant : std::false_type {};
template <class A>
struct Accepts_variant<A, std::void_t<decltype(TSP::blending_variant(std::declval<A>()))>>
    : std::true_type {};
static_assert(Accepts_order<int>::value, "");
static_assert(!Accepts_order<TS::Blending_variant>::value, "");
static_assert(!Accepts_order<const char*>::value, "");
static_assert(Accepts_variant<TS::Blending_variant>::value, "");
static_assert(!Accepts_variant<int>::value, "");
static_assert(!Accepts_variant<TS::Vertex_surface_method>::value, "");

// Parameters spread over the faces and their interiors (barycentric (a, b) of triangles).
std::vector<std::pair<std::size_t, std::array<double, 2>>>
sample_points(const Blending_surface& s) {
  const std::vector<std::array<double, 2>> ab{
      {{1.0 / 3, 1.0 / 3}}, {{0.2, 0.7}}, {{0.05, 0.1}}, {{0.6, 0.3}}, {{0.45, 0.05}}};
  std::vector<std::pair<std::size_t, std::array<double, 2>>> points;
  const std::size_t F = s.number_of_faces();
  for (std::size_t f : {std::size_t(0), F / 3, F / 2, F - 1})
    for (const auto& p : ab)
      points.push_back({f, p});
  return points;
}

// The largest coordinate difference between two surfaces (of the same mesh) at the samples.
double max_difference(const Blending_surface& s, const Blending_surface& t) {
  double d = 0;
  for (const auto& [f, p] : sample_points(s)) {
    const std::array<double, 3> a = s.face_surface(f, p[0], p[1]);
    const std::array<double, 3> b = t.face_surface(f, p[0], p[1]);
    for (std::size_t c = 0; c < 3; ++c)
      d = (std::max)(d, std::fabs(a[c] - b[c]));
  }
  return d;
}

// The largest coordinate difference between the vertex surfaces of two surfaces (of the same
// mesh) around their vertices: all of them, where sampling faces could miss a change.
double max_vertex_surface_difference(const Blending_surface& s, const Blending_surface& t) {
  double d = 0;
  for (std::size_t v = 0; v < s.number_of_vertices(); ++v)
    for (const std::array<double, 2>& xy : {std::array<double, 2>{{0.3, 0.2}}, {{-0.4, 0.5}}}) {
      const std::array<double, 3> a = s.vertex_surface(v, xy[0], xy[1]);
      const std::array<double, 3> b = t.vertex_surface(v, xy[0], xy[1]);
      for (std::size_t c = 0; c < 3; ++c)
        d = (std::max)(d, std::fabs(a[c] - b[c]));
    }
  return d;
}

::testing::AssertionResult bitwise_equal(const Blending_surface& s, const Blending_surface& t) {
  for (const auto& [f, p] : sample_points(s))
    if (s.face_surface(f, p[0], p[1]) != t.face_surface(f, p[0], p[1]))
      return ::testing::AssertionFailure()
             << "face " << f << " differs at (" << p[0] << ", " << p[1] << ")";
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult same_options(const TS::Mesh_blending_options& a,
                                        const TS::Mesh_blending_options& b) {
  if (a.order == b.order && a.variant == b.variant && a.vertex_surface == b.vertex_surface &&
      a.least_squares_degree == b.least_squares_degree && a.normals_degree == b.normals_degree &&
      a.least_tolerance == b.least_tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "options differ: order " << a.order << " / " << b.order << ", variant "
         << TS::to_string(a.variant) << " / " << TS::to_string(b.variant)
         << ", least-squares degree " << a.least_squares_degree << " / " << b.least_squares_degree
         << ", normals degree " << a.normals_degree << " / " << b.normals_degree << ", tolerance "
         << a.least_tolerance << " / " << b.least_tolerance;
}

std::array<double, 3> unit(const Vector_3& n) {
  const double length = std::sqrt(n.squared_length());
  return {{n.x() / length, n.y() / length, n.z() / length}};
}

// n rotated by `angle` about the fixed unit `axis` (Rodrigues), then scaled: a set of normals
// close to the mesh's (so they still agree with the face orientation) but not equal to them.
Vector_3 rotated(const Vector_3& n, const Vector_3& axis, double angle, double scale) {
  const Vector_3 r = n * std::cos(angle) + CGAL::cross_product(axis, n) * std::sin(angle) +
                     axis * ((axis * n) * (1 - std::cos(angle)));
  return r * scale;
}

Vector_3 generic_axis() {
  const Vector_3 a(1, 2, 3);
  return a / std::sqrt(a.squared_length());
}

TEST(BlendingParameters, DefaultPackGivesDefaultOptions) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const Blending_surface reference(mesh);
  EXPECT_TRUE(same_options(TS::blending_options(), TS::Mesh_blending_options{}));
  EXPECT_TRUE(same_options(TS::blending_options(CGAL::parameters::default_values()),
                           TS::Mesh_blending_options{}));
  // CGAL's parameters are not options
  EXPECT_TRUE(same_options(TS::blending_options(CGAL::parameters::vertex_normal_map(
                               mesh.property_map<Vertex, Vector_3>("v:normal").first)),
                           TS::Mesh_blending_options{}));

  const Blending_surface plain = TS::make_blending_surface(mesh);
  const Blending_surface with_defaults =
      TS::make_blending_surface(mesh, CGAL::parameters::default_values());
  const Blending_surface ours_defaults = TS::make_blending_surface(mesh, TSP::default_values());
  for (const Blending_surface* s : {&plain, &with_defaults, &ours_defaults}) {
    EXPECT_TRUE(same_options(s->options(), TS::Mesh_blending_options{}));
    EXPECT_FALSE(s->has_estimated_normals());
    EXPECT_TRUE(bitwise_equal(*s, reference));
  }
}

TEST(BlendingParameters, EachParameterSetsItsOption) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const Blending_surface reference(mesh);
  // a real change of the surface, far above round-off
  const double changed = 1e-6;

  TS::Mesh_blending_options expected;
  expected.order = 1;
  const Blending_surface order1 = TS::make_blending_surface(mesh, TSP::blending_order(1));
  EXPECT_TRUE(same_options(order1.options(), expected));
  EXPECT_EQ(order1.order(), 1);
  EXPECT_GT(max_difference(order1, reference), changed);
  // an explicit default changes nothing
  EXPECT_TRUE(bitwise_equal(TS::make_blending_surface(mesh, TSP::blending_order(2)), reference));

  expected = {};
  expected.variant = TS::Blending_variant::BASIC;
  const Blending_surface basic =
      TS::make_blending_surface(mesh, TSP::blending_variant(TS::Blending_variant::BASIC));
  EXPECT_TRUE(same_options(basic.options(), expected));
  EXPECT_EQ(basic.variant(), TS::Blending_variant::BASIC);
  EXPECT_GT(max_difference(basic, reference), changed);

  expected = {};
  expected.vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES;
  const Blending_surface squares = TS::make_blending_surface(
      mesh, TSP::vertex_surface_method(TS::Vertex_surface_method::LEAST_SQUARES));
  EXPECT_TRUE(same_options(squares.options(), expected));
  EXPECT_GT(max_difference(squares, reference), changed);

  // the degree only matters for least-squares vertex surfaces
  expected.least_squares_degree = 3;
  const Blending_surface cubic = TS::make_blending_surface(
      mesh, TSP::least_squares_degree(
                3, TSP::vertex_surface_method(TS::Vertex_surface_method::LEAST_SQUARES)));
  EXPECT_TRUE(same_options(cubic.options(), expected));
  EXPECT_GT(max_difference(cubic, squares), changed);
  expected = {};
  expected.least_squares_degree = 3;
  EXPECT_TRUE(same_options(TS::make_blending_surface(mesh, TSP::least_squares_degree(3)).options(),
                           expected));

  // the degree of the normals-fitting vertex surfaces
  expected = {};
  expected.vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES_NORMALS;
  const Blending_surface normals4 = TS::make_blending_surface(
      mesh, TSP::vertex_surface_method(TS::Vertex_surface_method::LEAST_SQUARES_NORMALS));
  EXPECT_TRUE(same_options(normals4.options(), expected));
  expected.normals_degree = 5;
  const Blending_surface normals5 = TS::make_blending_surface(
      mesh, TSP::normals_degree(
                5, TSP::vertex_surface_method(TS::Vertex_surface_method::LEAST_SQUARES_NORMALS)));
  EXPECT_TRUE(same_options(normals5.options(), expected));
  EXPECT_GT(max_difference(normals5, normals4), changed);

  // a coarse rank threshold: nearly dependent degree blocks of the least interpolant drop
  // out at some vertices (few: hence all vertex surfaces are compared)
  expected = {};
  expected.least_tolerance = 0.1;
  const Blending_surface coarse =
      TS::make_blending_surface(mesh, TSP::least_interpolant_tolerance(0.1));
  EXPECT_TRUE(same_options(coarse.options(), expected));
  EXPECT_GT(max_vertex_surface_difference(coarse, reference), changed);
  EXPECT_EQ(
      max_vertex_surface_difference(
          TS::make_blending_surface(mesh, TSP::least_interpolant_tolerance(1e-10)), reference),
      0);

  // all at once, in a chain of ours
  expected.order = 3;
  expected.variant = TS::Blending_variant::VERTEX_CONTINUITY;
  expected.vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES;
  expected.least_squares_degree = 4;
  expected.least_tolerance = 1e-6;
  const auto all = TSP::blending_order(
      3, TSP::blending_variant(
             TS::Blending_variant::VERTEX_CONTINUITY,
             TSP::vertex_surface_method(
                 TS::Vertex_surface_method::LEAST_SQUARES,
                 TSP::least_squares_degree(4, TSP::least_interpolant_tolerance(1e-6)))));
  EXPECT_TRUE(same_options(TS::blending_options(all), expected));
  EXPECT_TRUE(same_options(TS::make_blending_surface(mesh, all).options(), expected));
  // a parameter given twice: the last one appended wins, as for CGAL's
  EXPECT_EQ(TS::blending_options(TSP::blending_order(1, TSP::blending_order(4))).order, 1);
}

// Normals passed as a std::map-backed map or as another property of the mesh replace
// "v:normal"; they are normalised like the mesh's own.
TEST(BlendingParameters, VertexNormalMapOverridesTheProperty) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const auto own = mesh.property_map<Vertex, Vector_3>("v:normal");
  ASSERT_TRUE(own.second);
  const Blending_surface reference(mesh);

  std::map<Vertex, Vector_3> table;
  Mesh with_property = mesh;
  auto property = with_property.add_property_map<Vertex, Vector_3>("v:tilted").first;
  for (Vertex v : mesh.vertices()) {
    table[v] = rotated(own.first[v], generic_axis(), 0.1, 2.5);
    property[v] = table[v];
  }
  const Blending_surface from_table = TS::make_blending_surface(
      mesh, CGAL::parameters::vertex_normal_map(boost::make_assoc_property_map(table)));
  // the property map is keyed on the same vertex indices as `mesh`
  const Blending_surface from_property =
      TS::make_blending_surface(mesh, CGAL::parameters::vertex_normal_map(property));

  for (const Blending_surface* s : {&from_table, &from_property}) {
    EXPECT_FALSE(s->has_estimated_normals());
    double largest_change = 0;
    for (Vertex v : mesh.vertices()) {
      const std::array<double, 3> given = unit(table[v]), original = unit(own.first[v]);
      const std::array<double, 3>& used = s->vertex_normal(static_cast<std::size_t>(v));
      double change = 0;
      for (std::size_t c = 0; c < 3; ++c) {
        // normalising the same vector: equal up to a few ulps
        EXPECT_NEAR(used[c], given[c], 4e-16) << "vertex " << v;
        change = (std::max)(change, std::fabs(used[c] - original[c]));
      }
      // a rotation by 0.1 about an axis no normal is parallel to moves every normal
      EXPECT_GT(change, 1e-3) << "vertex " << v;
      largest_change = (std::max)(largest_change, change);
    }
    EXPECT_GT(largest_change, 0.05);
    EXPECT_GT(max_difference(*s, reference), 1e-6);
  }
  EXPECT_TRUE(bitwise_equal(from_table, from_property));
  // the input mesh is untouched
  EXPECT_TRUE(bitwise_equal(TS::make_blending_surface(mesh), reference));

  // a mesh without normals gets them from the map instead of estimating them
  const Mesh perturbed = TS::blending_test_mesh<Point_3>("perturbed");
  ASSERT_FALSE((perturbed.property_map<Vertex, Vector_3>("v:normal").second));
  std::map<Vertex, Vector_3> radial;
  for (Vertex v : perturbed.vertices())
    radial[v] = perturbed.point(v) - CGAL::ORIGIN;
  const Blending_surface estimated = TS::make_blending_surface(perturbed);
  const Blending_surface given = TS::make_blending_surface(
      perturbed, CGAL::parameters::vertex_normal_map(boost::make_assoc_property_map(radial)));
  EXPECT_TRUE(estimated.has_estimated_normals());
  EXPECT_FALSE(given.has_estimated_normals());
  for (Vertex v : perturbed.vertices())
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(given.vertex_normal(static_cast<std::size_t>(v))[c], unit(radial[v])[c], 4e-16);
}

// Moved points give the surface moved by the same vector.
TEST(BlendingParameters, VertexPointMapTranslatesTheSurface) {
  const Vector_3 t(0.75, -1.5, 2.25);
  for (const char* name : {"ellipsoid", "perturbed"}) { // given and estimated normals
    const Mesh mesh = TS::blending_test_mesh<Point_3>(name);
    std::map<Vertex, Point_3> moved;
    for (Vertex v : mesh.vertices())
      moved[v] = mesh.point(v) + t;
    const Blending_surface reference(mesh);
    const Blending_surface translated = TS::make_blending_surface(
        mesh, CGAL::parameters::vertex_point_map(boost::make_assoc_property_map(moved)));
    EXPECT_EQ(translated.has_estimated_normals(), reference.has_estimated_normals()) << name;
    for (Vertex v : mesh.vertices()) {
      const std::array<double, 3>& p = translated.vertex_position(static_cast<std::size_t>(v));
      EXPECT_EQ(Point_3(p[0], p[1], p[2]), moved[v]) << name;
    }
    // The construction is translation invariant only in exact arithmetic: frames, heights
    // and estimated normals come from coordinate differences, which round differently once
    // the coordinates are shifted (their ulps grow with |t|). Observed: ~2e-15 here; 1e-12
    // relative to the extent of the data leaves room for other compilers and libms.
    const double scale = 4 + std::sqrt(t.squared_length());
    double largest = 0;
    for (const auto& [f, ab] : sample_points(reference)) {
      const std::array<double, 3> p = reference.face_surface(f, ab[0], ab[1]);
      const std::array<double, 3> q = translated.face_surface(f, ab[0], ab[1]);
      for (std::size_t c = 0; c < 3; ++c)
        largest = (std::max)(largest, std::fabs(q[c] - (p[c] + t[static_cast<int>(c)])));
    }
    EXPECT_LE(largest, 1e-12 * scale) << name;
  }
}

TEST(BlendingParameters, InvalidValuesThrow) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("icosahedron");
  EXPECT_THROW(TS::make_blending_surface(mesh, TSP::blending_order(-1)), TS::Invalid_input);
  EXPECT_THROW(
      TS::make_blending_surface(
          mesh, TSP::least_squares_degree(
                    0, TSP::vertex_surface_method(TS::Vertex_surface_method::LEAST_SQUARES))),
      TS::Invalid_input);
  // also with given normals
  EXPECT_THROW(TS::make_blending_surface(
                   mesh, TSP::blending_order(
                             -1, CGAL::parameters::vertex_normal_map(
                                     mesh.property_map<Vertex, Vector_3>("v:normal").first))),
               TS::Invalid_input);
  // a zero normal given through the map is the constructor's error too
  std::map<Vertex, Vector_3> zero;
  for (Vertex v : mesh.vertices())
    zero[v] = Vector_3(0, 0, 0);
  EXPECT_THROW(TS::make_blending_surface(
                   mesh, CGAL::parameters::vertex_normal_map(boost::make_assoc_property_map(zero))),
               TS::Invalid_input);
}

// Ours appended to CGAL's, CGAL's member functions on ours, and CGAL's through our
// namespace: all give the same surface.
TEST(BlendingParameters, CombinesWithCgalParameters) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const auto own = mesh.property_map<Vertex, Vector_3>("v:normal").first;
  std::map<Vertex, Vector_3> table;
  std::map<Vertex, Point_3> points;
  for (Vertex v : mesh.vertices()) {
    table[v] = rotated(own[v], generic_axis(), 0.05, 1);
    points[v] = mesh.point(v) + Vector_3(0, 0, 1);
  }
  const auto normals = boost::make_assoc_property_map(table);
  const auto moved = boost::make_assoc_property_map(points);

  const Blending_surface cgal_inside = TS::make_blending_surface(
      mesh, TSP::blending_order(1, CGAL::parameters::vertex_normal_map(normals)));
  const Blending_surface cgal_outside =
      TS::make_blending_surface(mesh, TSP::blending_order(1).vertex_normal_map(normals));
  const Blending_surface through_ours =
      TS::make_blending_surface(mesh, TSP::vertex_normal_map(normals).vertex_point_map(moved));
  TS::Mesh_blending_options expected;
  expected.order = 1;
  for (const Blending_surface* s : {&cgal_inside, &cgal_outside}) {
    EXPECT_TRUE(same_options(s->options(), expected));
    for (Vertex v : mesh.vertices())
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(s->vertex_normal(static_cast<std::size_t>(v))[c], unit(table[v])[c], 4e-16);
  }
  EXPECT_TRUE(bitwise_equal(cgal_inside, cgal_outside));
  EXPECT_TRUE(same_options(through_ours.options(), TS::Mesh_blending_options{}));

  // several of each, interleaved, in both orders
  const Blending_surface mixed_a = TS::make_blending_surface(
      mesh,
      TSP::blending_variant(TS::Blending_variant::BASIC,
                            TSP::blending_order(1, CGAL::parameters::vertex_normal_map(normals)))
          .vertex_point_map(moved));
  const Blending_surface mixed_b = TS::make_blending_surface(
      mesh,
      TSP::blending_order(1, CGAL::parameters::vertex_point_map(moved).vertex_normal_map(normals))
          .vertex_normal_map(normals)); // duplicates are harmless
  const Blending_surface mixed_c = TS::make_blending_surface(
      mesh, TSP::blending_variant(TS::Blending_variant::BASIC, TSP::blending_order(1))
                .vertex_point_map(moved)
                .vertex_normal_map(normals));
  expected.variant = TS::Blending_variant::BASIC;
  EXPECT_TRUE(same_options(mixed_a.options(), expected));
  EXPECT_TRUE(same_options(mixed_c.options(), expected));
  EXPECT_TRUE(bitwise_equal(mixed_a, mixed_c));
  for (const Blending_surface* s : {&mixed_a, &mixed_b, &mixed_c, &through_ours})
    for (Vertex v : mesh.vertices()) {
      const std::array<double, 3>& p = s->vertex_position(static_cast<std::size_t>(v));
      EXPECT_EQ(Point_3(p[0], p[1], p[2]), points[v]);
      EXPECT_NEAR(s->vertex_normal(static_cast<std::size_t>(v))[0], unit(table[v])[0], 4e-16);
    }
  EXPECT_EQ(mixed_b.order(), 1);
  EXPECT_EQ(mixed_b.variant(), TS::Blending_variant::OPEN_SET);
}

// --- any PolygonMesh ---

using Polyhedron = CGAL::Polyhedron_3<Epick>;
using Polyhedron_vertex = Polyhedron::Vertex_handle;

// A read-only property map over a std::map.
template <class Map>
boost::const_associative_property_map<Map> const_map(const Map& m) {
  return boost::const_associative_property_map<Map>(m);
}

// The Polyhedron_3 of mesh arrays, its faces added by CGAL::Euler::add_face() in the order
// to_surface_mesh() adds them (the same algorithm, so the same halfedge structure); its
// normals, if any, in a map.
Polyhedron to_polyhedron(const TS::Blending_mesh_data& data,
                         std::map<Polyhedron_vertex, Vector_3>& normals) {
  Polyhedron p;
  std::vector<Polyhedron_vertex> vertices;
  for (const auto& q : data.points)
    vertices.push_back(CGAL::add_vertex(Point_3(q[0], q[1], q[2]), p));
  for (std::size_t i = 0; i < data.normals.size(); ++i)
    normals[vertices[i]] = Vector_3(data.normals[i][0], data.normals[i][1], data.normals[i][2]);
  for (const auto& f : data.faces) {
    std::vector<Polyhedron_vertex> face;
    for (std::size_t i : f)
      face.push_back(vertices[i]);
    if (CGAL::Euler::add_face(face, p) == boost::graph_traits<Polyhedron>::null_face())
      ADD_FAILURE() << "Polyhedron_3 rejected a face";
  }
  return p;
}

// Parameters inside every face: barycentric for triangles, inside the unit-distance disc of
// the face frame (which the strictly convex projected polygon contains near its centre)
// for the others.
std::vector<std::array<double, 2>> face_samples(const Blending_surface& s, std::size_t f) {
  if (s.face_size(f) == 3)
    return {{{1.0 / 3, 1.0 / 3}}, {{0.2, 0.7}}, {{0.05, 0.1}}, {{0.9, 0.05}}};
  return {{{0, 0}}, {{0.2, 0.1}}, {{-0.3, 0.25}}, {{0.05, -0.4}}};
}

::testing::AssertionResult identical(const Blending_surface& s, const Blending_surface& t) {
  if (s.number_of_vertices() != t.number_of_vertices() ||
      s.number_of_edges() != t.number_of_edges() || s.number_of_faces() != t.number_of_faces())
    return ::testing::AssertionFailure() << "different numbers of elements";
  for (std::size_t v = 0; v < s.number_of_vertices(); ++v)
    if (s.vertex_position(v) != t.vertex_position(v) || s.vertex_normal(v) != t.vertex_normal(v) ||
        s.vertex_scale(v) != t.vertex_scale(v))
      return ::testing::AssertionFailure() << "vertex " << v << " differs";
  for (std::size_t e = 0; e < s.number_of_edges(); ++e)
    if (s.edge_vertices(e) != t.edge_vertices(e) || s.edge_sides(e) != t.edge_sides(e))
      return ::testing::AssertionFailure() << "edge " << e << " differs";
  for (std::size_t f = 0; f < s.number_of_faces(); ++f) {
    if (s.face_size(f) != t.face_size(f))
      return ::testing::AssertionFailure() << "face " << f << " differs";
    for (std::size_t c = 0; c < s.face_size(f); ++c)
      if (s.face_vertex(f, c) != t.face_vertex(f, c) ||
          s.face_to_vertex_frame(f, c) != t.face_to_vertex_frame(f, c))
        return ::testing::AssertionFailure() << "corner " << c << " of face " << f << " differs";
    for (const auto& p : face_samples(s, f)) {
      if (s.face_surface(f, p[0], p[1]) != t.face_surface(f, p[0], p[1]))
        return ::testing::AssertionFailure()
               << "face " << f << " differs at (" << p[0] << ", " << p[1] << ")";
      const TS::Surface_derivatives a = s.derivatives(f, p[0], p[1]);
      const TS::Surface_derivatives b = t.derivatives(f, p[0], p[1]);
      if (a.fx != b.fx || a.fy != b.fy || a.fxx != b.fxx || a.fxy != b.fxy || a.fyy != b.fyy)
        return ::testing::AssertionFailure() << "the derivatives of face " << f << " differ";
    }
  }
  return ::testing::AssertionSuccess();
}

// A Polyhedron_3 is read through the same BGL functions in the same order as a Surface_mesh
// with the same halfedge structure, so the arithmetic is the same: the surfaces are equal
// bit for bit, and so are their tessellations. Given normals (map), estimated normals,
// borders, quads, pentagons, mixed faces; the three variants.
TEST(BlendingPolygonMesh, PolyhedronGivesTheSurfaceMeshSurface) {
  std::vector<TS::Mesh_blending_options> variants(3);
  variants[1].order = 1;
  variants[1].variant = TS::Blending_variant::BASIC;
  variants[2].order = 3;
  variants[2].variant = TS::Blending_variant::VERTEX_CONTINUITY;
  variants[2].vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES_NORMALS;
  for (const char* name : {"ellipsoid", "perturbed", "franke4", "cube", "dodecahedron", "mixed"}) {
    const TS::Blending_mesh_data data = TS::blending_test_mesh_data(name);
    const Mesh mesh = TS::to_surface_mesh<Point_3>(data);
    std::map<Polyhedron_vertex, Vector_3> normals;
    const Polyhedron polyhedron = to_polyhedron(data, normals);
    for (const TS::Mesh_blending_options& options : variants) {
      const Blending_surface reference(mesh, options);
      const Blending_surface from_polyhedron =
          normals.empty() ? Blending_surface(polyhedron, options)
                          : Blending_surface(polyhedron, options,
                                             CGAL::parameters::vertex_normal_map(
                                                 boost::make_assoc_property_map(normals)));
      EXPECT_EQ(from_polyhedron.has_estimated_normals(), data.normals.empty()) << name;
      EXPECT_TRUE(identical(from_polyhedron, reference)) << name;
      Mesh a, b;
      const TS::Blending_tessellation_statistics sa = reference.tessellate(a, 3);
      const TS::Blending_tessellation_statistics sb = from_polyhedron.tessellate(b, 3);
      ASSERT_EQ(sa.vertices, sb.vertices) << name;
      EXPECT_EQ(sa.min_gaussian_curvature, sb.min_gaussian_curvature) << name;
      EXPECT_EQ(sa.max_gaussian_curvature, sb.max_gaussian_curvature) << name;
      std::size_t differing = 0;
      for (auto v : a.vertices())
        differing += a.point(v) != b.point(v);
      EXPECT_EQ(differing, 0u) << name;
    }
  }
  // the one-call entry point deduces the point type from the Polyhedron's point map
  const TS::Blending_mesh_data data = TS::blending_test_mesh_data("ellipsoid");
  std::map<Polyhedron_vertex, Vector_3> normals;
  const Polyhedron polyhedron = to_polyhedron(data, normals);
  const Blending_surface made = TS::make_blending_surface(
      polyhedron, TSP::blending_order(1, CGAL::parameters::vertex_normal_map(
                                             boost::make_assoc_property_map(normals))));
  TS::Mesh_blending_options order1;
  order1.order = 1;
  EXPECT_TRUE(identical(made, Blending_surface(TS::to_surface_mesh<Point_3>(data), order1)));
}

// Normals given through vertex_normal_map are those of the property "v:normal": the same
// surface bit for bit, on a mesh without the property.
TEST(BlendingPolygonMesh, NormalMapEqualsTheNormalProperty) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const auto property = mesh.property_map<Vertex, Vector_3>("v:normal");
  ASSERT_TRUE(property.second);
  Mesh bare = mesh;
  auto copied = bare.property_map<Vertex, Vector_3>("v:normal").first;
  bare.remove_property_map(copied);
  ASSERT_FALSE((bare.property_map<Vertex, Vector_3>("v:normal").second));
  const Blending_surface reference(mesh); // the convenience constructor: "v:normal"
  const Blending_surface from_map(bare, TS::Mesh_blending_options{},
                                  CGAL::parameters::vertex_normal_map(property.first));
  EXPECT_FALSE(reference.has_estimated_normals());
  EXPECT_FALSE(from_map.has_estimated_normals());
  EXPECT_TRUE(identical(from_map, reference));
  // the generic constructor reads "v:normal" of a Surface_mesh as well
  EXPECT_TRUE(identical(
      Blending_surface(mesh, TS::Mesh_blending_options{}, CGAL::parameters::default_values()),
      reference));
  // without either, the normals are estimated: a different surface
  const Blending_surface estimated(bare);
  EXPECT_TRUE(estimated.has_estimated_normals());
  EXPECT_GT(max_difference(estimated, reference), 1e-6);
}

// A vertex_index_map renumbers the vertices, normals from "v:normal" included; the surface
// is the same, bit for bit.
TEST(BlendingPolygonMesh, VertexIndexMapRenumbersTheVertices) {
  const Mesh mesh = TS::blending_test_mesh<Point_3>("ellipsoid");
  const std::size_t n = mesh.number_of_vertices();
  std::map<Vertex, std::size_t> reversed;
  for (Vertex v : mesh.vertices())
    reversed[v] = n - 1 - static_cast<std::size_t>(v);
  const Blending_surface reference(mesh);
  const Blending_surface renumbered(
      mesh, TS::Mesh_blending_options{},
      CGAL::parameters::vertex_index_map(boost::make_assoc_property_map(reversed)));
  EXPECT_FALSE(renumbered.has_estimated_normals());
  for (std::size_t v = 0; v < n; ++v) {
    EXPECT_EQ(renumbered.vertex_position(n - 1 - v), reference.vertex_position(v)) << v;
    EXPECT_EQ(renumbered.vertex_normal(n - 1 - v), reference.vertex_normal(v)) << v;
  }
  for (std::size_t f = 0; f < reference.number_of_faces(); ++f)
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(renumbered.face_vertex(f, c), n - 1 - reference.face_vertex(f, c));
  EXPECT_TRUE(bitwise_equal(renumbered, reference));
}

// Bad input through the generic path: the documented Invalid_input, naming the problem.
TEST(BlendingPolygonMesh, BadInputIsInvalidInput) {
  auto message = [](auto build) -> std::string {
    try {
      build();
    } catch (const TS::Invalid_input& e) {
      return e.what();
    }
    return "accepted";
  };
  auto says = [](const std::string& what, const std::string& part) {
    return what.find(part) != std::string::npos ? ::testing::AssertionSuccess()
                                                : ::testing::AssertionFailure() << what;
  };
  const TS::Mesh_blending_options options;
  // no faces: an empty Polyhedron_3; vertices only
  EXPECT_TRUE(says(message([&] { Blending_surface(Polyhedron(), options); }), "no face"));
  Mesh points_only;
  points_only.add_vertex(Point_3(0, 0, 0));
  points_only.add_vertex(Point_3(1, 0, 0));
  EXPECT_TRUE(says(message([&] { Blending_surface(points_only, options); }), "no face"));
  // a vertex without faces: not a valid polygon mesh for CGAL already
  Mesh isolated = TS::blending_test_mesh<Point_3>("octahedron");
  isolated.add_vertex(Point_3(5, 5, 5));
  EXPECT_TRUE(says(
      message([&] { Blending_surface(isolated, options, CGAL::parameters::default_values()); }),
      "not a valid polygon mesh"));

  const TS::Blending_mesh_data ico = TS::blending_test_mesh_data("icosahedron");
  std::map<Polyhedron_vertex, Vector_3> radial;
  const Polyhedron polyhedron = to_polyhedron(ico, radial);
  auto with_normals = [&](const std::map<Polyhedron_vertex, Vector_3>& normals) {
    return message([&] {
      Blending_surface(polyhedron, options,
                       CGAL::parameters::vertex_normal_map(const_map(normals)));
    });
  };
  // zero, non-finite and reversed normals
  std::map<Polyhedron_vertex, Vector_3> bad = radial;
  bad.begin()->second = Vector_3(0, 0, 0);
  EXPECT_TRUE(says(with_normals(bad), "is zero or not finite"));
  bad.begin()->second = Vector_3(std::numeric_limits<double>::quiet_NaN(), 0, 1);
  EXPECT_TRUE(says(with_normals(bad), "is zero or not finite"));
  bad.begin()->second = -radial.begin()->second;
  EXPECT_TRUE(says(with_normals(bad), "points against the orientation"));
  // a position that is not finite, through the vertex point map
  std::map<Polyhedron_vertex, Point_3> moved;
  for (Polyhedron_vertex v : vertices(polyhedron))
    moved[v] = v->point();
  moved.begin()->second = Point_3(std::numeric_limits<double>::infinity(), 0, 0);
  EXPECT_TRUE(says(message([&] {
                     Blending_surface(polyhedron, options,
                                      CGAL::parameters::vertex_point_map(const_map(moved)));
                   }),
                   "not finite"));
  // faces with more than three sides are supported only where they project to strictly
  // convex polygons
  TS::Blending_mesh_data dart;
  dart.points = {{{0, 0, 0}}, {{2, 0, 0}}, {{0.5, 0.5, 0}}, {{0, 2, 0}}};
  dart.faces = {{0, 1, 2, 3}};
  std::map<Polyhedron_vertex, Vector_3> none;
  const Polyhedron dart_polyhedron = to_polyhedron(dart, none);
  EXPECT_TRUE(
      says(message([&] { Blending_surface(dart_polyhedron, options); }), "not strictly convex"));
  // removed elements: the generic path refuses them (maps keyed on the mesh could not follow
  // a copy); the convenience constructor builds from the collected copy, as before
  Mesh garbage = TS::blending_test_mesh<Point_3>("pentakis");
  CGAL::Euler::remove_face(garbage.halfedge(*garbage.faces().begin()), garbage);
  ASSERT_TRUE(garbage.has_garbage());
  EXPECT_TRUE(says(message([&] { TS::make_blending_surface(garbage); }), "removed elements"));
  Mesh collected = garbage;
  collected.collect_garbage();
  EXPECT_TRUE(identical(Blending_surface(garbage), Blending_surface(collected)));
}

} // namespace

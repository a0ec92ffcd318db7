// Bridge from Bézier patches to the renderer's control-net overlay. Header-only (templates
// over the CGAL kernel and the patch value type); include it where patches are at hand.

#ifndef TSPLINE_RENDER_CONTROL_NET_H
#define TSPLINE_RENDER_CONTROL_NET_H

#include "render/render.h"

#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <map>
#include <type_traits>
#include <utility>

namespace tspline::render {

// The status of every control point is unknown (e.g. a spline read from a file).
struct Unknown_status {
  template <class Face>
  Point_status operator()(Face, const CGAL::Triangular_spline::Multi_index&) const {
    return Point_status::Unknown;
  }
};

inline Point_role point_role(const CGAL::Triangular_spline::Multi_index& index) {
  using CGAL::Triangular_spline::Control_point_role;
  switch (CGAL::Triangular_spline::role(index)) {
  case Control_point_role::CORNER:
    return Point_role::Corner;
  case Control_point_role::STAR:
    return Point_role::Star;
  case Control_point_role::EDGE_MIDDLE:
    return Point_role::Edge_middle;
  default:
    return Point_role::Inner;
  }
}

namespace internal {

// Adds the points and grid segments of one patch; points and segments already seen (shared
// with a neighbouring patch) are skipped. `status(index)` is the point's status.
class Net_builder {
public:
  explicit Net_builder(Net& net) : m_net(net) {}

  template <class Bezier, class Status>
  void add_patch(const Bezier& bezier, Status status) {
    namespace TS = CGAL::Triangular_spline;
    using Value = typename Bezier::Value_type;
    const int m = bezier.degree();
    auto position = [&](const TS::Multi_index& index) -> Vector {
      const Value& value = bezier.control_point(index);
      if constexpr (TS::Value_traits<Value>::dimension == 1) {
        double x = 0, y = 0;
        for (int v = 0; v < 3; ++v) {
          const double w = m == 0 ? 1.0 / 3 : double(index[v]) / m;
          x += w * CGAL::to_double(bezier.vertex(v).x());
          y += w * CGAL::to_double(bezier.vertex(v).y());
        }
        return {x, y, CGAL::to_double(value)};
      } else {
        return {CGAL::to_double(value.x()), CGAL::to_double(value.y()), CGAL::to_double(value.z())};
      }
    };
    for (const TS::Multi_index& index : TS::multi_indices(m)) {
      const Vector p = position(index);
      if (m_seen_points.emplace(p, m_net.points.size()).second)
        m_net.points.push_back({p, point_role(index), status(index)});
    }
    auto add_segment = [&](const TS::Multi_index& a, const TS::Multi_index& b) {
      Vector p = position(a), q = position(b);
      if (q < p)
        std::swap(p, q);
      if (m_seen_segments.emplace(std::make_pair(p, q), true).second)
        m_net.segments.push_back({{p, q}});
    };
    if (m == 0)
      return;
    for (const TS::Multi_index& t : TS::multi_indices(m - 1)) {
      const TS::Multi_index a{t.i + 1, t.j, t.k}, b{t.i, t.j + 1, t.k}, c{t.i, t.j, t.k + 1};
      add_segment(a, b);
      add_segment(b, c);
      add_segment(c, a);
    }
  }

private:
  Net& m_net;
  std::map<Vector, std::size_t> m_seen_points;
  std::map<std::pair<Vector, Vector>, bool> m_seen_segments;
};

} // namespace internal

// The control nets of the patches of a TriangularSplineNetwork: every patch's points and the
// edges of its triangular grid, b_{i+1,j,k}-b_{i,j+1,k}-b_{i,j,k+1} for i+j+k = m-1. A
// functional patch's point b_{ijk} sits at ((i r + j s + k t)/m, value) over its domain
// triangle (r, s, t); a parametric patch's point is its value. Points and segments shared by
// neighbouring patches appear once. `status(f, index)` says whether b_index of patch f was
// prescribed or propagated.
template <class Network, class Status = Unknown_status>
Net control_net(const Network& network, Status status = Status()) {
  Net net;
  internal::Net_builder builder(net);
  const std::size_t faces = network.domain().number_of_faces();
  for (std::size_t f = 0; f < faces; ++f) {
    // binds to a stored patch, or extends the life of a computed one
    const auto& bezier = network.patch(static_cast<typename Network::Index>(f));
    builder.add_patch(bezier, [&](const CGAL::Triangular_spline::Multi_index& index) {
      return status(f, index);
    });
  }
  return net;
}

// The control net of a surface over a closed mesh (a class with mesh() and patch(f), such as
// CGAL::Triangular_spline::Surface_file or Pseudo_AG1_surface), patches in face order.
template <class Surface, class Status = Unknown_status>
Net closed_surface_control_net(const Surface& surface, Status status = Status()) {
  Net net;
  internal::Net_builder builder(net);
  for (auto f : surface.mesh().faces())
    builder.add_patch(surface.patch(f), [&](const CGAL::Triangular_spline::Multi_index& index) {
      return status(f, index);
    });
  return net;
}

// The umbrellas of a surface over a closed mesh (Xu's Fig. 6.10): each vertex's corner point
// and its stars, with the spokes corner-star and the rims star-star of every face. For a
// pseudo-AG^1 surface each umbrella lies in its vertex's corner plane, which is what makes the
// surface G^1 there.
template <class Surface>
Net closed_surface_umbrellas(const Surface& surface) {
  namespace TS = CGAL::Triangular_spline;
  Net net;
  std::map<Vector, std::size_t> seen;
  auto position = [](const auto& value) -> Vector {
    return {CGAL::to_double(value.x()), CGAL::to_double(value.y()), CGAL::to_double(value.z())};
  };
  for (auto f : surface.mesh().faces()) {
    const auto& patch = surface.patch(f);
    const int m = patch.degree();
    if (m < 1)
      continue;
    for (int c = 0; c < 3; ++c) {
      // the corner b_{m e_c} and its stars b_{(m-1) e_c + e_d}, d != c
      auto index = [&](int main, int other) {
        std::array<int, 3> a{{0, 0, 0}};
        a[std::size_t(c)] = main;
        if (other >= 0)
          a[std::size_t(other)] = 1;
        return TS::Multi_index{a[0], a[1], a[2]};
      };
      const int d = (c + 1) % 3, e = (c + 2) % 3;
      const std::array<Vector, 3> p{{position(patch.control_point(index(m, -1))),
                                     position(patch.control_point(index(m - 1, d))),
                                     position(patch.control_point(index(m - 1, e)))}};
      for (std::size_t k = 0; k < 3; ++k)
        if (seen.emplace(p[k], net.points.size()).second)
          net.points.push_back(
              {p[k], k == 0 ? Point_role::Corner : Point_role::Star, Point_status::Unknown});
      net.segments.push_back({{p[0], p[1]}});
      net.segments.push_back({{p[0], p[2]}});
      net.segments.push_back({{p[1], p[2]}});
    }
  }
  return net;
}

// The roles of Xu's pseudo-AG^1 construction (Fig. 6.9, §6.2): the stars and the inner points
// (corner-inner and flips) are prescribed, the edge-middle points propagated through the edge's
// affine relation; corners come from the corner planes and keep their role colour.
struct Pseudo_AG1_status {
  template <class Face>
  Point_status operator()(Face, const CGAL::Triangular_spline::Multi_index& index) const {
    switch (point_role(index)) {
    case Point_role::Star:
    case Point_role::Inner:
      return Point_status::Prescribed;
    case Point_role::Edge_middle:
      return Point_status::Propagated;
    case Point_role::Corner:
      break;
    }
    return Point_status::Unknown;
  }
};

} // namespace tspline::render

#endif // TSPLINE_RENDER_CONTROL_NET_H

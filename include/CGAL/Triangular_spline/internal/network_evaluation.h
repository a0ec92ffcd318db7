// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_NETWORK_EVALUATION_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_NETWORK_EVALUATION_H

// How evaluate.h reads a TriangularSplineNetwork: its patch and value types, a located
// query in the coordinates of its patch, and the loop over located queries.

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/internal/de_casteljau.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/Algebraic_structure_traits.h>

#include <CGAL/assertions.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The patch type of a TriangularSplineNetwork.
template <class Network>
using Network_patch_t =
    std::remove_cv_t<std::remove_reference_t<decltype(std::declval<const Network&>().patch(
        std::declval<typename Network::Index>()))>>;

// The value type of a TriangularSplineNetwork's patches.
template <class Network>
using Network_value_t = typename Network_patch_t<Network>::Value_type;

// Whether a network writes a face's control net over the face's vertex order without
// building its patch (`C1_quintic_spline::face_net()`).
template <class Network, class Net, class = void>
struct Has_face_net : std::false_type {};
template <class Network, class Net>
struct Has_face_net<Network, Net,
                    std::void_t<decltype(std::declval<const Network&>().face_net(
                        std::declval<typename Network::Index>(), std::declval<Net&>()))>>
    : std::true_type {};

// The barycentric directions, over the triangle (r, s, t), of the unit vectors e_x and e_y,
// computed as `Bezier_triangle::barycentric_direction()` does (the same operations, so the
// same bits): the derivatives of a net read without its patch.
template <class Point_2>
auto unit_directions(const Point_2& r, const Point_2& s, const Point_2& t) {
  using FT = std::decay_t<decltype(r.x())>;
  const FT sx = s.x() - r.x(), sy = s.y() - r.y(), tx = t.x() - r.x(), ty = t.y() - r.y();
  const FT inverse_area2 = FT(1) / (sx * ty - sy * tx);
  auto direction = [&](const FT& ux, const FT& uy) {
    const FT mu = (ux * ty - uy * tx) * inverse_area2;
    const FT nu = (sx * uy - sy * ux) * inverse_area2;
    return std::array<FT, 3>{{-mu - nu, mu, nu}};
  };
  return std::make_pair(direction(FT(1), FT(0)), direction(FT(0), FT(1)));
}

// From this many queries on, evaluation runs on all cores (inexact number types) and
// reorders queries in no spatial order: a thread costs about 50 microseconds, a query
// about 0.3.
constexpr std::size_t many_queries = 20000;

// The threads for n queries: all cores for inexact number types, one for exact ones.
template <class GeomTraits>
std::size_t query_threads(std::size_t n) {
  return CGAL::Algebraic_structure_traits<typename GeomTraits::FT>::Is_exact::value
             ? 1
             : thread_count(n, many_queries);
}

// A patch source reading the network (by reference when the network returns references).
template <class Network>
auto patch_source(const Network& network) {
  return [&network](typename Network::Index f) -> decltype(auto) { return network.patch(f); };
}

// The locator must number the faces as the network's domain does: built on it, or on an
// identical copy (checked cheaply).
template <class Network, class GeomTraits>
bool is_locator_of(const Network& network, const Domain_locator<GeomTraits>& locator) {
  return &locator.domain() == &network.domain() ||
         (locator.domain().number_of_faces() == network.domain().number_of_faces() &&
          locator.domain().number_of_vertices() == network.domain().number_of_vertices());
}

// Converts barycentric weights w.r.t. the vertices of a domain face (face(f) order) into
// weights w.r.t. the vertices of the patch of that face, which may list the same three
// points in another order. Matching is by exact point equality, so exact zeros and grid
// weights carry over unchanged; if the patch is over another triangle, the point is
// rebuilt and its coordinates are recomputed with respect to the patch.
template <class GeomTraits, class Value>
class Face_to_patch {
public:
  using FT = typename GeomTraits::FT;
  using Point_2 = typename GeomTraits::Point_2;
  using Weights = std::array<FT, 3>;

  Face_to_patch(const Planar_domain<GeomTraits>& domain,
                typename Planar_domain<GeomTraits>::Index f,
                const Bezier_triangle<GeomTraits, Value>& patch)
      : m_patch(patch) {
    const auto& t = domain.face(f);
    std::array<bool, 3> used{{false, false, false}};
    for (std::size_t c = 0; c < 3; ++c) {
      m_corners[c] = &domain.point(t[c]);
      m_to_patch[c] = 3;
      for (std::size_t v = 0; v < 3; ++v)
        if (!used[v] && patch.vertex(static_cast<int>(v)) == *m_corners[c]) {
          m_to_patch[c] = v;
          used[v] = true;
          break;
        }
      m_matched = m_matched && m_to_patch[c] < 3;
    }
  }

  // returns the domain point with face weights `w`
  Point_2 point(const Weights& w) const {
    const FT x = w[0] * m_corners[0]->x() + w[1] * m_corners[1]->x() + w[2] * m_corners[2]->x();
    const FT y = w[0] * m_corners[0]->y() + w[1] * m_corners[1]->y() + w[2] * m_corners[2]->y();
    return Point_2(x, y);
  }

  // returns the weights of the same point w.r.t. the patch's vertices
  Weights patch_weights(const Weights& w) const {
    if (!m_matched)
      return m_patch.barycentric_coordinates(point(w));
    Weights result;
    for (std::size_t c = 0; c < 3; ++c)
      result[m_to_patch[c]] = w[c];
    return result;
  }

  Value evaluate(const Weights& w) const { return m_patch.evaluate_barycentric(patch_weights(w)); }

  // derivatives w.r.t. (x, y) do not depend on the order of the patch's vertices
  Point_jet<Value> jet(const Weights& w, int order) const {
    return m_patch.jet_barycentric(patch_weights(w), order);
  }

  bool matched() const { return m_matched; }

private:
  const Bezier_triangle<GeomTraits, Value>& m_patch;
  std::array<const Point_2*, 3> m_corners;
  std::array<std::size_t, 3> m_to_patch;
  bool m_matched = true;
};

// The face of the thread's previous query, the hint of the next one's location, restarted
// at every block of parallel_for_index(): a block runs on one thread in order, so each
// query's hint, and the face an edge point falls in, do not depend on the number of threads.
template <class GeomTraits>
typename Planar_domain<GeomTraits>::Index& previous_face(const Domain_locator<GeomTraits>&,
                                                         std::size_t q) {
  thread_local typename Planar_domain<GeomTraits>::Index face;
  if (q % parallel_block == 0)
    face = Planar_domain<GeomTraits>::null_index;
  return face;
}

// The order in which to evaluate the queries: from 20000 queries on, a counting sort by the
// locator's bucket (O(n), stable), so that consecutive queries share triangles, patches and
// buckets in the cache and the previous face is a good hint (random queries ran 2.6 times
// slower than the same queries Hilbert-sorted). Empty, for the input order, for fewer
// queries and for queries already in spatial order (a quarter of them in the bucket of the
// one before: grids and sorted points, whose own order keeps the cache better than rows of
// buckets do: Hilbert-sorted queries lost 15% to the sort). That fraction is estimated from
// 4096 evenly spaced pairs of consecutive queries: the buckets of all of them, on one core
// before the evaluation on all, took a tenth of the time of sorted queries.
template <class GeomTraits>
std::vector<std::size_t>
evaluation_order(const Domain_locator<GeomTraits>& locator,
                 const std::vector<typename GeomTraits::Point_2>& queries) {
  std::vector<std::size_t> order;
  const std::size_t n = queries.size();
  if (n < many_queries)
    return order;
  constexpr std::size_t pairs = 4096;
  std::size_t same = 0;
  for (std::size_t k = 0; k < pairs; ++k) {
    const std::size_t q = 1 + k * (n - 1) / pairs;
    same += locator.bucket(queries[q]) == locator.bucket(queries[q - 1]) ? 1 : 0;
  }
  if (4 * same >= pairs)
    return order;
  const std::size_t B = locator.number_of_buckets();
  std::vector<std::size_t> key(n), start(B + 2, 0);
  for (std::size_t q = 0; q < n; ++q) {
    key[q] = locator.bucket(queries[q]);
    ++start[key[q] + 1];
  }
  for (std::size_t b = 0; b <= B; ++b)
    start[b + 1] += start[b];
  order.resize(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q)
    order[start[key[q]]++] = q;
  return order;
}

// A number per evaluation call, for face_net_of(): a network's values may change between
// calls, not during one.
inline std::uint64_t new_evaluation_call() {
  static std::atomic<std::uint64_t> calls{0};
  return ++calls;
}

// network.face_net(face, net), through the thread's copy of the net of its previous face in
// the same evaluation call `call`: spatially ordered queries fall in one face several times
// in a row (10^6 Hilbert-sorted queries on 2 10^5 faces: about five), and reading a net
// from the spline's slots cost two thirds of its de Casteljau steps. Only for values that
// are plain bits (a thread's cache of exact values would outlive their allocator).
template <class Network, class Net>
void face_net_of(const Network& network, typename Network::Index face, std::uint64_t call,
                 Net& net) {
  using Value = typename Net::value_type;
  if constexpr (std::is_trivially_copyable_v<Value>) {
    struct Cache {
      std::uint64_t call = 0;
      typename Network::Index face{};
      Net net;
    };
    thread_local Cache cache;
    if (cache.call != call || cache.face != face) {
      network.face_net(face, cache.net);
      cache.call = call;
      cache.face = face;
    }
    net = cache.net;
  } else {
    network.face_net(face, net);
  }
}

// Calls f(q, location) for every query q, location being `locator.locate_snapped()` of it
// (std::nullopt outside): in `evaluation_order()`, each query hinted with the face of the one
// before, on all cores for inexact number types (f must then be safe to call concurrently
// for distinct q, e.g. write only entry q of a result). The loop of every evaluation.
template <class GeomTraits, class F>
void for_each_query_location(const Domain_locator<GeomTraits>& locator,
                             const std::vector<typename GeomTraits::Point_2>& queries, const F& f) {
  const std::vector<std::size_t> order = evaluation_order(locator, queries);
  parallel_for_index(queries.size(), query_threads<GeomTraits>(queries.size()), [&](std::size_t i) {
    const std::size_t q = order.empty() ? i : order[i];
    auto& hint = previous_face(locator, i);
    const auto location = locator.locate_snapped(queries[q], hint);
    if (location)
      hint = location->face;
    f(q, location);
  });
}

// Locates each query and calls callback(q, &value), or callback(q, nullptr) outside, as
// for_each_query_location() does (callback must be safe to call concurrently for distinct q).
template <class Network, class GeomTraits, class Callback>
void for_each_location(const Network& network, const Domain_locator<GeomTraits>& locator,
                       const std::vector<typename GeomTraits::Point_2>& queries,
                       Callback callback) {
  CGAL_precondition(is_locator_of(network, locator));
  using Patch = Network_patch_t<Network>;
  using Value = typename Patch::Value_type;
  const auto& domain = network.domain();
  auto patch = patch_source(network);
  const std::uint64_t call = new_evaluation_call();
  for_each_query_location(locator, queries, [&](std::size_t q, const auto& location) {
    if (!location) {
      callback(q, nullptr);
      return;
    }
    if constexpr (Has_face_net<Network, Scratch_net<Value>>::value) {
      // the net straight from the network, over the face's own vertex order: the same
      // de Casteljau steps as the patch's, without building a patch per query
      Scratch_net<Value> net;
      face_net_of(network, location->face, call, net);
      if constexpr (std::is_floating_point_v<Value> &&
                    std::is_same_v<Value, std::decay_t<decltype(location->barycentric[0])>>)
        if (network.degree() == 5) { // Xu's quintics
          const Value value = de_casteljau_value<5>(net.data(), location->barycentric);
          callback(q, &value);
          return;
        }
      for (int l = 0; l < network.degree(); ++l)
        de_casteljau_step(net, network.degree() - l, location->barycentric);
      callback(q, &net[0]);
    } else {
      // binds to the source's reference, or extends the life of the returned patch
      const Patch& bezier = patch(location->face);
      const Face_to_patch<GeomTraits, Value> frame(domain, location->face, bezier);
      const Value value = frame.evaluate(location->barycentric);
      callback(q, &value);
    }
  });
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_NETWORK_EVALUATION_H

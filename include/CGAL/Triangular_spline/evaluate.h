// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_EVALUATE_H
#define CGAL_TRIANGULAR_SPLINE_EVALUATE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/internal/network_evaluation.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineSplines
  \brief evaluates a functional (height) spline at query points.

  Each query is located in the domain with `locator.locate_snapped()` (a point outside a
  boundary edge by no more than a rounding error is evaluated on the edge, see
  `Domain_locator`); the patch of the triangle found is
  evaluated by de Casteljau's algorithm at the point's barycentric coordinates with
  respect to the patch's own vertices (the patch may list the triangle's vertices in any
  order). Points on an edge or at a vertex are evaluated in one incident patch: for a
  continuous spline every incident patch gives the same value.

  With an inexact number type the queries are shared among all cores from 20000 queries on
  (`network.patch()` is then called concurrently, as `certify_continuity()` does); each
  result is computed as on one thread. Queries in no spatial order are evaluated bucket by
  bucket of the locator (a counting sort), and each query first tries the triangle of the
  one before (`Domain_locator::locate_snapped()` with a hint), so that neighbouring queries
  share the cache; queries already in spatial order (a grid, points sorted with
  `CGAL::hilbert_sort()`) keep their order and still run about twice as fast as random ones.

  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork` with scalar values
  \param network the spline
  \param locator a locator built on `network.domain()` (or an identical domain)
  \param queries the query points
  \return one value per query, in input order: the height converted to `double`
  (computed exactly first when `FT` is exact), or a quiet NaN where the query is outside
  the domain or in a hole (beyond the snapping tolerance), or not finite
  \pre `locator` was built on `network.domain()` or an identical domain
*/
template <class TriangularSplineNetwork>
std::vector<double> evaluate_functional(
    const TriangularSplineNetwork& network,
    const Domain_locator<typename TriangularSplineNetwork::Geom_traits>& locator,
    const std::vector<typename TriangularSplineNetwork::Geom_traits::Point_2>& queries) {
  using Value = internal::Network_value_t<TriangularSplineNetwork>;
  static_assert(Value_traits<Value>::dimension == 1,
                "evaluate_functional() needs functional (scalar) patches; use evaluate_at()");
  std::vector<double> values(queries.size(), std::numeric_limits<double>::quiet_NaN());
  internal::for_each_location(network, locator, queries, [&](std::size_t q, const Value* value) {
    if (value)
      values[q] = CGAL::to_double(*value);
  });
  return values;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief evaluates a spline (functional or parametric) at query points, in its own number
  type.

  Works as `evaluate_functional()` but returns the exact patch values (`FT` for a
  functional spline, `Vector_3` for a parametric one).
  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork`
  \param network the spline
  \param locator a locator built on `network.domain()` (or an identical domain)
  \param queries the query points
  \return one entry per query, in input order: the value, or `std::nullopt` where the query
  is outside the domain, in a hole, or not finite
  \pre `locator` was built on `network.domain()` or an identical domain
*/
template <class TriangularSplineNetwork>
std::vector<std::optional<internal::Network_value_t<TriangularSplineNetwork>>>
evaluate_at(const TriangularSplineNetwork& network,
            const Domain_locator<typename TriangularSplineNetwork::Geom_traits>& locator,
            const std::vector<typename TriangularSplineNetwork::Geom_traits::Point_2>& queries) {
  using Value = internal::Network_value_t<TriangularSplineNetwork>;
  std::vector<std::optional<Value>> values(queries.size());
  internal::for_each_location(network, locator, queries, [&](std::size_t q, const Value* value) {
    if (value)
      values[q] = *value;
  });
  return values;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief evaluates a spline at one point: the value, or `std::nullopt` outside the domain
  (see the overload for many points).
  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork`
  \param network the spline network
  \param locator the point locator of the network's domain
  \param query the query point
  \returns the value, or `std::nullopt` outside the domain
*/
template <class TriangularSplineNetwork>
std::optional<internal::Network_value_t<TriangularSplineNetwork>>
evaluate_at(const TriangularSplineNetwork& network,
            const Domain_locator<typename TriangularSplineNetwork::Geom_traits>& locator,
            const typename TriangularSplineNetwork::Geom_traits::Point_2& query) {
  return evaluate_at(network, locator,
                     std::vector<typename TriangularSplineNetwork::Geom_traits::Point_2>{query})
      .front();
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief what `evaluate_jets()` returns for a query outside the domain (beyond the snapping
  tolerance of `Domain_locator::locate_snapped()`) or in a hole.
*/
enum class Outside {
  /// no value (`std::nullopt`)
  NO_VALUE,
  /// the value, gradient and Hessian of the spline at the nearest boundary point \f$q\f$
  NEAREST,
  /// the linear extrapolation \f$F(q) + \nabla F(q) \cdot (p - q)\f$ from the nearest
  /// boundary point \f$q\f$: gradient \f$\nabla F(q)\f$, Hessian zero
  LINEAR
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief evaluates the value, gradient and Hessian of a spline at query points, locating
  included: the one call to get values and derivatives from any spline whose patches are
  `Bezier_triangle`s over a `Planar_domain` (a `C1_quintic_spline`, a spline read with
  `read_spline_file()`, a network raised by `adjust_network()`, a `Mann_interpolant`).

  Each query is located with `locator.locate_snapped()`, so points on a boundary edge up to
  rounding get a value; the patch of the triangle found gives the jet
  (`Bezier_triangle::jet_barycentric()`), with derivatives taken with respect to the
  domain coordinates \f$(x, y)\f$. On an edge or at a vertex the jet of one incident patch
  is returned: for a \f$C^1\f$ spline the value and gradient do not depend on the choice,
  the Hessian may (it is one-sided there). Queries outside are handled by `outside`.

  Every result is computed in `FT`: exact with `CGAL::Exact_rational`, rounded with
  `double` (use `CGAL::to_double()` on the members to print them). Inexact number types
  share the queries among all cores, as `evaluate_functional()` does.

  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork`
  \param network the spline
  \param locator a locator built on `network.domain()` (or an identical domain)
  \param queries the query points
  \param outside what to return outside the domain
  \param order the highest derivative order wanted (0, 1 or 2); higher derivatives are zero
  and are not computed
  \return one entry per query, in input order: the jet, or `std::nullopt` where the query is
  not finite, or outside the domain with `Outside::NO_VALUE`
  \pre `locator` was built on `network.domain()` or an identical domain
*/
template <class TriangularSplineNetwork>
std::vector<std::optional<Point_jet<internal::Network_value_t<TriangularSplineNetwork>>>>
evaluate_jets(const TriangularSplineNetwork& network,
              const Domain_locator<typename TriangularSplineNetwork::Geom_traits>& locator,
              const std::vector<typename TriangularSplineNetwork::Geom_traits::Point_2>& queries,
              Outside outside = Outside::NO_VALUE, int order = 2) {
  CGAL_precondition(internal::is_locator_of(network, locator));
  using GeomTraits = typename TriangularSplineNetwork::Geom_traits;
  using Patch = internal::Network_patch_t<TriangularSplineNetwork>;
  using Value = typename Patch::Value_type;
  using FT = typename GeomTraits::FT;
  const auto& domain = network.domain();
  auto patch = internal::patch_source(network);
  std::vector<std::optional<Point_jet<Value>>> jets(queries.size());
  const std::uint64_t call = internal::new_evaluation_call();
  const auto jet_at = [&](const typename Domain_locator<GeomTraits>::Location& location,
                          int jet_order) {
    if constexpr (internal::Has_face_net<TriangularSplineNetwork,
                                         internal::Scratch_net<Value>>::value) {
      // the net straight from the network, over the face's vertex order (what its patch
      // would compute, without building the patch)
      internal::Scratch_net<Value> net;
      internal::face_net_of(network, location.face, call, net);
      const auto& t = domain.face(location.face);
      const auto [dx, dy] =
          internal::unit_directions(domain.point(t[0]), domain.point(t[1]), domain.point(t[2]));
      return internal::jet_of_net(net, network.degree(), location.barycentric, dx, dy, jet_order);
    } else {
      // binds to the source's reference, or extends the life of the returned patch
      const Patch& bezier = patch(location.face);
      const internal::Face_to_patch<GeomTraits, Value> frame(domain, location.face, bezier);
      return frame.jet(location.barycentric, jet_order);
    }
  };
  // the queries are independent: on all cores for inexact number types, each writing its
  // own entry, so the result does not depend on the number of threads
  internal::for_each_query_location(locator, queries, [&](std::size_t q, const auto& location) {
    const auto& p = queries[q];
    if (location) {
      jets[q] = jet_at(*location, order);
      return;
    }
    if (outside == Outside::NO_VALUE)
      return;
    const auto nearest = locator.nearest_boundary_point(p);
    if (!nearest)
      return;
    // the extrapolated value needs the gradient even when only values are asked for
    Point_jet<Value> jet =
        jet_at(nearest->location, outside == Outside::LINEAR ? (std::max)(order, 1) : order);
    if (outside == Outside::LINEAR) {
      const FT dx = p.x() - nearest->point.x(), dy = p.y() - nearest->point.y();
      Value value = jet.value + dx * jet.gradient[0] + dy * jet.gradient[1];
      jet.value = std::move(value);
      const Value zero = Value_traits<Value>::zero();
      jet.hessian = {{zero, zero, zero}};
      if (order < 1)
        jet.gradient = {{zero, zero}};
    }
    jets[q] = std::move(jet);
  });
  return jets;
}

/*!
  \ingroup PkgTriangularSplineSplines
  \brief evaluates the value, gradient and Hessian of a spline at one point, locating
  included (see the overload for many points).
  \tparam TriangularSplineNetwork a model of `TriangularSplineNetwork`
  \param network the spline network
  \param locator the point locator of the network's domain
  \param query the query point
  \param outside what to return outside the domain
  \param order the highest derivative order wanted (0, 1 or 2); higher derivatives are zero
  \returns the value, gradient and Hessian, or `std::nullopt` outside the domain
*/
template <class TriangularSplineNetwork>
std::optional<Point_jet<internal::Network_value_t<TriangularSplineNetwork>>>
evaluate_jet(const TriangularSplineNetwork& network,
             const Domain_locator<typename TriangularSplineNetwork::Geom_traits>& locator,
             const typename TriangularSplineNetwork::Geom_traits::Point_2& query,
             Outside outside = Outside::NO_VALUE, int order = 2) {
  return evaluate_jets(network, locator,
                       std::vector<typename TriangularSplineNetwork::Geom_traits::Point_2>{query},
                       outside, order)
      .front();
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_EVALUATE_H

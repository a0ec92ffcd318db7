// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/thin_plate_energy.h>
#include <CGAL/Triangular_spline/internal/de_casteljau.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/centroid.h>
#include <CGAL/number_utils.h>

#include <array>
#include <optional>
#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The thin-plate energy of the degree-5 patch with net `net` (in the patch's order) over
// (r, s, u), and its value at the triangle's centroid, by the operations of the patch (its
// constructor's checks, Bezier_triangle::barycentric_coordinates(), its de Casteljau steps),
// hence the same bits; empty where the patch's constructor would throw. `net` is overwritten.
// Without `with_energy` the energy is zero (most of the work is the energy's).
template <class K, class Net>
std::optional<std::pair<typename K::FT, typename K::FT>>
energy_and_centroid_value_of_net(const K& traits, const typename K::Point_2& r,
                                 const typename K::Point_2& s, const typename K::Point_2& u,
                                 Net& net, bool with_energy = true) {
  using FT = typename K::FT;
  for (const auto* p : {&r, &s, &u})
    if (!CGAL::is_finite(p->x()) || !CGAL::is_finite(p->y()))
      return std::nullopt;
  if (traits.orientation_2_object()(r, s, u) == CGAL::COLLINEAR)
    return std::nullopt;
  // FT, not auto: an expression-template FT (gmpxx) would keep references to temporaries
  auto determinant = [](const auto& a, const auto& b) -> FT {
    return a.x() * b.y() - a.y() * b.x();
  };
  const FT area2 = determinant(s - r, u - r);
  if (CGAL::is_zero(area2) || !CGAL::is_finite(area2))
    return std::nullopt;
  const FT inverse_area2 = FT(1) / area2;
  const FT energy =
      with_energy
          ? thin_plate_energy_of_net<FT>(5, r, s, u,
                                         [&](std::size_t, const Multi_index& a) -> const FT& {
                                           return net[linear_index(a)];
                                         })
          : FT(0);
  const auto c = CGAL::centroid(r, s, u);
  const FT mu = determinant(c - r, u - r) * inverse_area2;
  const FT nu = determinant(s - r, c - r) * inverse_area2;
  const std::array<FT, 3> w{{FT(1) - mu - nu, mu, nu}};
  for (int l = 0; l < 5; ++l)
    de_casteljau_step(net, 5 - l, w);
  return std::make_pair(energy, net[0]);
}

// The thin-plate energy of face f's patch and the patch's value at the face's centroid, as
// thin_plate_energy(spline.patch(f)) and spline.patch(f).evaluate(centroid) give them, read
// on the face's net without building the patch: the same bits (test
// Plan.FaceMeasuresAreThePatchsBits). Empty where the patch's constructor would throw.
// tspline c1 takes both for every face; the patch's heap net and checks were most of that.
// Without `with_energy` the energy is zero.
template <class GeomTraits>
std::optional<std::pair<typename GeomTraits::FT, typename GeomTraits::FT>>
face_energy_and_centroid_value(const C1_quintic_spline<GeomTraits>& spline,
                               typename C1_quintic_spline<GeomTraits>::Index f,
                               bool with_energy = true) {
  const auto& domain = spline.domain();
  const auto& t = domain.face(f);
  Scratch_net<typename GeomTraits::FT> net;
  spline.face_net(f, net); // the patch's order
  return energy_and_centroid_value_of_net(domain.geom_traits(), domain.point(t[0]),
                                          domain.point(t[1]), domain.point(t[2]), net, with_energy);
}

// The same measures of convert_patch<Target>(spline.patch(f)), the patch converted to the
// kernel Target point by point and value by value (tspline c1 measures exact builds in
// double): the same bits, without building the exact patch and its copy. Empty where the
// converted patch's constructor would throw (a value or a triangle beyond Target's range).
template <class Target, class GeomTraits>
std::optional<std::pair<typename Target::FT, typename Target::FT>>
converted_face_energy_and_centroid_value(const C1_quintic_spline<GeomTraits>& spline,
                                         typename C1_quintic_spline<GeomTraits>::Index f,
                                         bool with_energy = true) {
  const CGAL::Cartesian_converter<GeomTraits, Target> convert;
  const auto& domain = spline.domain();
  const auto& t = domain.face(f);
  Scratch_net<typename GeomTraits::FT> own;
  spline.face_net(f, own);
  Scratch_net<typename Target::FT> net;
  for (const auto& v : own) {
    net.push_back(convert(v));
    if (!CGAL::is_finite(net.back()))
      return std::nullopt;
  }
  return energy_and_centroid_value_of_net(Target(), convert(domain.point(t[0])),
                                          convert(domain.point(t[1])), convert(domain.point(t[2])),
                                          net, with_energy);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H

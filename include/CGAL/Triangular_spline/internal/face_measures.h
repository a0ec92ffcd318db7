// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H

#include <CGAL/Triangular_spline/Xu/C1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/thin_plate_energy.h>
#include <CGAL/Triangular_spline/internal/de_casteljau.h>

#include <CGAL/centroid.h>
#include <CGAL/number_utils.h>

#include <array>
#include <optional>
#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The thin-plate energy of face f's patch and the patch's value at the face's centroid, as
// thin_plate_energy(spline.patch(f)) and spline.patch(f).evaluate(centroid) give them, read
// on the face's net without building the patch: the same operations (the patch's checks,
// Bezier_triangle::barycentric_coordinates(), its de Casteljau steps), hence the same bits
// (test Plan.FaceMeasuresAreThePatchsBits). Empty where the patch's constructor would throw.
// tspline c1 takes both for every face; the patch's heap net and checks were most of that.
template <class GeomTraits>
std::optional<std::pair<typename GeomTraits::FT, typename GeomTraits::FT>>
face_energy_and_centroid_value(const C1_quintic_spline<GeomTraits>& spline,
                               typename C1_quintic_spline<GeomTraits>::Index f) {
  using FT = typename GeomTraits::FT;
  const auto& domain = spline.domain();
  const auto& t = domain.face(f);
  const auto &r = domain.point(t[0]), &s = domain.point(t[1]), &u = domain.point(t[2]);
  for (const auto* p : {&r, &s, &u})
    if (!CGAL::is_finite(p->x()) || !CGAL::is_finite(p->y()))
      return std::nullopt;
  if (domain.geom_traits().orientation_2_object()(r, s, u) == CGAL::COLLINEAR)
    return std::nullopt;
  // FT, not auto: an expression-template FT (gmpxx) would keep references to temporaries
  auto determinant = [](const auto& a, const auto& b) -> FT {
    return a.x() * b.y() - a.y() * b.x();
  };
  const FT area2 = determinant(s - r, u - r);
  if (CGAL::is_zero(area2) || !CGAL::is_finite(area2))
    return std::nullopt;
  const FT inverse_area2 = FT(1) / area2;
  Scratch_net<FT> net;
  spline.face_net(f, net);
  const FT energy =
      thin_plate_energy_of_net<FT>(5, r, s, u, [&](std::size_t, const Multi_index& a) -> const FT& {
        return net[linear_index(a)]; // face_net() writes the patch's order
      });
  const auto c = CGAL::centroid(r, s, u);
  const FT mu = determinant(c - r, u - r) * inverse_area2;
  const FT nu = determinant(s - r, c - r) * inverse_area2;
  const std::array<FT, 3> w{{FT(1) - mu - nu, mu, nu}};
  for (int l = 0; l < 5; ++l)
    de_casteljau_step(net, 5 - l, w);
  return std::make_pair(energy, net[0]);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_FACE_MEASURES_H

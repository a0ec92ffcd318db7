// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_PATCH_NETWORK_H
#define CGAL_TRIANGULAR_SPLINE_PATCH_NETWORK_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief a planar domain with one Bézier patch per face, stored as given: the plain model of
  `TriangularSplineNetwork`.

  This is what a spline file holds (`read_spline_file()`), what Mann's constructions return,
  and how patches built by any other means (edited, adjusted, converted to another number
  type) are handed to `certify_continuity()`, `evaluate_jets()` or `tessellate()`.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric), see `Value_traits`
  \cgalModels `TriangularSplineNetwork`
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
class Patch_network {
public:
  /// the kernel
  using Geom_traits = GeomTraits;
  /// the control values
  using Value_type = Value;
  /// the triangulated domain
  using Domain = Planar_domain<Geom_traits>;
  /// index of a vertex, edge or face of the domain
  using Index = typename Domain::Index;
  /// the patch over one face
  using Patch = Bezier_triangle<Geom_traits, Value>;

  /*!
    takes `domain` and `patches`, `patches[f]` being the patch of face `f`.
    A patch may be over another triangle than its face: evaluation and tessellation
    re-express each point in the patch's triangle. `write_spline_file()` needs each patch
    over the three corners of its face (in any order) and throws `Invalid_input` otherwise;
    `certify_continuity()` compares the patches as they are, across the edge their
    triangles share, and throws `Invalid_input` if they share none.
    \throws Invalid_input if the numbers of patches and faces differ
    \param domain the triangulated planar domain
    \param patches the patches, `patches[f]` being the patch of face `f`
  */
  Patch_network(Domain domain, std::vector<Patch> patches)
      : m_domain(std::move(domain)), m_patches(std::move(patches)) {
    if (m_patches.size() != m_domain.number_of_faces())
      throw Invalid_input("patch network: " + std::to_string(m_patches.size()) +
                          " patches for a domain of " + std::to_string(m_domain.number_of_faces()) +
                          " faces");
  }

  /// returns the domain.
  /// \returns the domain
  const Domain& domain() const { return m_domain; }
  /// returns the patch of face `f`.
  /// \param f the index of a face
  /// \returns the patch of face `f`
  const Patch& patch(Index f) const { return m_patches[f]; }
  /// returns the patch of face `f`, for editing its control points.
  /// \param f the index of a face
  /// \returns the patch of face `f`, for editing its control points
  Patch& patch(Index f) { return m_patches[f]; }
  /// returns all patches, `patches()[f]` over face `f`.
  /// \returns all patches, `patches()[f]` over face `f`
  const std::vector<Patch>& patches() const { return m_patches; }
  /// returns all patches, for editing (the number must stay that of the faces).
  /// \returns all patches, for editing (the number must stay that of the faces)
  std::vector<Patch>& patches() { return m_patches; }
  /// returns the largest degree of the patches (0 without faces).
  /// \returns the largest degree of the patches (0 without faces)
  int degree() const {
    int n = 0;
    for (const Patch& p : m_patches)
      n = (std::max)(n, p.degree());
    return n;
  }

private:
  Domain m_domain;
  std::vector<Patch> m_patches;
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the patches of any `TriangularSplineNetwork` as a `Patch_network` (a copy:
  use it to edit the patches of a spline, or to keep them after the spline is gone).
  \tparam Network a model of `TriangularSplineNetwork`
  \param network the spline network
  \returns the patches of any `TriangularSplineNetwork` as a `Patch_network` (a copy: use it to edit
  the patches of a spline, or to keep them after the spline is gone)
*/
template <class Network>
auto make_patch_network(const Network& network) {
  using Domain = std::decay_t<decltype(network.domain())>;
  using Patch = std::decay_t<decltype(network.patch(typename Domain::Index(0)))>;
  std::vector<Patch> patches;
  patches.reserve(network.domain().number_of_faces());
  for (typename Domain::Index f = 0; f < network.domain().number_of_faces(); ++f)
    patches.push_back(network.patch(f));
  return Patch_network<typename Patch::Geom_traits, typename Patch::Value_type>(network.domain(),
                                                                                std::move(patches));
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_PATCH_NETWORK_H

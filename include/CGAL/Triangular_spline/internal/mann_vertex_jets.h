// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_MANN_VERTEX_JETS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_MANN_VERTEX_JETS_H

// The check of the vertex derivative data of mann_interpolant.h.

#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

// Declared here, defined (and documented) in Mann/mann_interpolant.h, which includes this
// header before its use.
constexpr int mann_derivative_order(int degree);

namespace internal {

template <class GeomTraits, class Value>
void check_vertex_jets(const Planar_domain<GeomTraits>& domain,
                       const std::vector<Polynomial_surface<GeomTraits, Value>>& jets, int degree) {
  const std::string where = "Mann interpolant: ";
  if (degree < 1)
    throw Invalid_input(where + "degree " + std::to_string(degree) + " (at least 1 is needed)");
  if (jets.size() != domain.number_of_vertices())
    throw Invalid_input(where + "derivative data for " + std::to_string(jets.size()) +
                        " vertices, but the domain has " +
                        std::to_string(domain.number_of_vertices()));
  const int needed = mann_derivative_order(degree);
  for (std::size_t v = 0; v < jets.size(); ++v) {
    if (jets[v].degree() < needed)
      throw Invalid_input(where + "vertex " + std::to_string(v) + " has derivatives up to order " +
                          std::to_string(jets[v].degree()) + ", degree " + std::to_string(degree) +
                          " patches need them up to order " + std::to_string(needed) +
                          " (floor(2n/3))");
    if (jets[v].degree() > degree)
      throw Invalid_input(where + "vertex " + std::to_string(v) + " has a Taylor polynomial of " +
                          "degree " + std::to_string(jets[v].degree()) +
                          ", above the patch degree " + std::to_string(degree));
  }
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_MANN_VERTEX_JETS_H

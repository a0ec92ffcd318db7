// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_RINGS_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_RINGS_H

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Ring distances from seed vertices (breadth first over the domain's edges): on entry
// ring[v] is 0 for the seeds, which `front` lists, and -1 elsewhere; on return ring[v] is
// the number of edges from v to the nearest seed where that is at most `rings`, -1 beyond.
// The adaptive fit's energy margin and the tile simulation's unchecked faces use it.
template <class Domain>
void grow_vertex_rings(const Domain& domain, std::vector<int>& ring,
                       std::vector<std::uint32_t> front, int rings) {
  std::vector<std::uint32_t> next;
  for (int r = 1; r <= rings; ++r) {
    next.clear();
    for (std::uint32_t u : front) {
      const auto [begin, end] = domain.neighbours(u);
      for (auto w = begin; w != end; ++w)
        if (ring[*w] < 0) {
          ring[*w] = r;
          next.push_back(std::uint32_t(*w));
        }
    }
    front.swap(next);
  }
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_VERTEX_RINGS_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_TAYLOR_JET_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_TAYLOR_JET_H

#include <algorithm>
#include <array>
#include <cstddef>

namespace CGAL {
namespace Triangular_spline {

// Declared here, defined (with its default order) in Blending/Taylor_jet.h, which includes
// this header: the helpers below are templates, instantiated after the definition.
template <class FT, int MaxOrder>
class Taylor_jet;

namespace internal {

// The value (constant term) of a number or a jet, used where a formula branches on the
// value at the expansion point (which indicators vanish there).
template <class T>
struct Jet_value {
  using Type = T;
  static const T& get(const T& x) { return x; }
};
template <class FT, int K>
struct Jet_value<Taylor_jet<FT, K>> {
  using Type = FT;
  static const FT& get(const Taylor_jet<FT, K>& x) { return x.value(); }
};

template <class T>
const typename Jet_value<T>::Type& value_of(const T& x) {
  return Jet_value<T>::get(x);
}

// Substitutes jets `du`, `dv` without constant term into the Taylor polynomial `j`:
// returns j(du, dv) (composition of truncated series).
template <class FT, int K>
Taylor_jet<FT, K> compose(const Taylor_jet<FT, K>& j, const Taylor_jet<FT, K>& du,
                          const Taylor_jet<FT, K>& dv) {
  using J = Taylor_jet<FT, K>;
  const int order = (std::min)(j.order(), (std::min)(du.order(), dv.order()));
  std::array<J, static_cast<std::size_t>(K + 1)> pu, pv;
  pu[0] = J(FT(1), order);
  pv[0] = J(FT(1), order);
  for (int e = 1; e <= order; ++e) {
    pu[static_cast<std::size_t>(e)] = pu[static_cast<std::size_t>(e - 1)] * du;
    pv[static_cast<std::size_t>(e)] = pv[static_cast<std::size_t>(e - 1)] * dv;
  }
  J r(FT(0), order);
  for (int k = 0; k <= order; ++k)
    for (int b = 0; b <= k; ++b) {
      const FT c = j.coefficient(k - b, b);
      if (c == FT(0))
        continue;
      r += pu[static_cast<std::size_t>(k - b)] * pv[static_cast<std::size_t>(b)] * c;
    }
  return r;
}

} // namespace internal

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_TAYLOR_JET_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_DE_CASTELJAU_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_DE_CASTELJAU_H

// The in-place de Casteljau step of Bezier_triangle.h, shared with the jets of tessellate.h.

#include <CGAL/Triangular_spline/Multi_index.h>

#include <boost/container/small_vector.hpp>

#include <array>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Scratch nets live on the stack up to degree 6 (28 values): evaluation is the hot path of
// tessellation and certification, and a heap allocation per call would dominate it.
template <class Value>
using Scratch_net = boost::container::small_vector<Value, 28>;

// One de Casteljau step, in place: the net of degree n becomes the net of degree n-1 of
// f(w, .), where w is given by its barycentric weights. The output position of (i,j) is
// lin(i,j,n) - i, never after any position still to be read, so no scratch is needed.
template <class FT, class Net>
void de_casteljau_step(Net& net, int n, const std::array<FT, 3>& w) {
  using Value = typename Net::value_type;
  std::size_t out = 0;
  for (int i = 0; i < n; ++i) {
    const std::size_t row = linear_index(i, 0, n);
    const std::size_t next_row = linear_index(i + 1, 0, n);
    for (int j = 0; j < n - i; ++j) {
      // b'_{i,j,k} = w0 b_{i+1,j,k} + w1 b_{i,j+1,k} + w2 b_{i,j,k+1}; the temporary keeps
      // expression-template number types (gmpxx) from reading a half-written target.
      Value v = w[0] * net[next_row + j] + w[1] * net[row + j + 1] + w[2] * net[row + j];
      net[out++] = std::move(v);
    }
  }
  net.resize(out);
}

// The value at w of the net of degree N in `net`: the N steps of de_casteljau_step(), the
// same operations in the same order (so the same bits), on an array of fixed size whose
// loops the compiler unrolls (the steps on a Scratch_net were a fifth of the time of
// Hilbert-sorted queries; two arrays in turn instead of one in place were no faster).
template <int N, class FT>
FT de_casteljau_value(const FT* net, const std::array<FT, 3>& w) {
  std::array<FT, std::size_t((N + 1) * (N + 2) / 2)> b;
  for (std::size_t k = 0; k < b.size(); ++k)
    b[k] = net[k];
  for (int n = N; n > 0; --n) {
    std::size_t out = 0;
    for (int i = 0; i < n; ++i) {
      const std::size_t row = linear_index(i, 0, n);
      const std::size_t next_row = linear_index(i + 1, 0, n);
      for (int j = 0; j < n - i; ++j)
        b[out++] = w[0] * b[next_row + j] + w[1] * b[row + j + 1] + w[2] * b[row + j];
    }
  }
  return b[0];
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_DE_CASTELJAU_H

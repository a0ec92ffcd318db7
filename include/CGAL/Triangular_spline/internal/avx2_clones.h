// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_AVX2_CLONES_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_AVX2_CLONES_H

// Hot double kernels compiled twice on x86-64: for the baseline instruction set (SSE2,
// which the package is built for) and for AVX2, chosen at run time by the processor. The
// AVX2 clone does the same operations on the same lanes, 256 bits at a time, and neither
// uses fused multiply-adds (AVX2 does not enable FMA: every product is rounded before it is
// added, as in the portable code), so both give the same bits. A kernel is cloned by
// calling its always-inlined body from a function marked
// CGAL_TRIANGULAR_SPLINE_AVX2_TARGET (GCC and Clang compile an inlined body for the
// target of the function it is inlined into).
//
// TRIANGULAR_SPLINE_SIMD=portable in the environment keeps every run on the portable code
// (paired timings, or a processor that reports AVX2 wrongly); tests switch the clones off
// with avx2_clones_allowed() to compare the two paths bit for bit.

#include <atomic>
#include <cstdlib>
#include <cstring>

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__) &&                              \
    !defined(CGAL_TRIANGULAR_SPLINE_NO_AVX2_CLONES)
#define CGAL_TRIANGULAR_SPLINE_AVX2_CLONES 1
#define CGAL_TRIANGULAR_SPLINE_AVX2_TARGET __attribute__((target("avx2")))
#else
#define CGAL_TRIANGULAR_SPLINE_AVX2_CLONES 0
#define CGAL_TRIANGULAR_SPLINE_AVX2_TARGET
#endif

#if defined(__GNUC__)
#define CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define CGAL_TRIANGULAR_SPLINE_ALWAYS_INLINE inline
#endif

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Whether the AVX2 clones may run (tests set false; nothing else changes it).
inline std::atomic<bool>& avx2_clones_allowed() {
  static std::atomic<bool> allowed{true};
  return allowed;
}

// Whether this run uses the AVX2 clones: built with them, the processor has AVX2, and
// neither TRIANGULAR_SPLINE_SIMD=portable nor a test said no.
inline bool use_avx2_clones() {
#if CGAL_TRIANGULAR_SPLINE_AVX2_CLONES
  static const bool available = [] {
    const char* simd = std::getenv("TRIANGULAR_SPLINE_SIMD");
    if (simd != nullptr && std::strcmp(simd, "portable") == 0)
      return false;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return available && avx2_clones_allowed().load(std::memory_order_relaxed);
#else
  return false;
#endif
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_AVX2_CLONES_H

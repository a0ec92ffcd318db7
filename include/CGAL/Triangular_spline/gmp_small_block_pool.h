// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_GMP_SMALL_BLOCK_POOL_H
#define CGAL_TRIANGULAR_SPLINE_GMP_SMALL_BLOCK_POOL_H

// An exact build keeps millions of GMP integers of one to four limbs (a rational control
// value, a propagation weight): each is a heap block of 8 to 32 bytes, which glibc's malloc
// serves from chunks of 32 to 48 bytes, with a lock-free but not free cache in front. The
// pool below serves those sizes from per-thread free lists carved from 64 KB slabs: no
// header (GMP passes every block's size back on free and realloc), no search, no
// coalescing. Measured on 10^5 six-decimal points (`tspline c1 --exact`, 0.65x the wall
// time, 433 instead of 705 MiB): see the manual, "Setting the Free Control Points".

#include <gmp.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// Blocks of 8, 16, 24 and 32 bytes (1 to 4 limbs). Only sizes that are multiples of 8 are
// pooled: GMP's integers always are, and a block the pool did not carve itself (allocated
// before the pool was installed) then has exactly its class's size. Other sizes (strings
// of mpz_get_str(nullptr, ...)) go to malloc().
constexpr std::size_t gmp_pool_classes = 4;

// Not under AddressSanitizer, which should see every block.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool gmp_pool_supported = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool gmp_pool_supported = false;
#else
constexpr bool gmp_pool_supported = true;
#endif
#else
constexpr bool gmp_pool_supported = true;
#endif
constexpr std::size_t gmp_pool_slab = 64 * 1024;

inline std::size_t gmp_pool_class(std::size_t size) {
  return size != 0 && size % 8 == 0 && size <= 8 * gmp_pool_classes ? size / 8 - 1
                                                                    : gmp_pool_classes;
}

struct Gmp_pool_block {
  Gmp_pool_block* next;
};
struct Gmp_pool_list {
  Gmp_pool_block* head = nullptr;
  Gmp_pool_block* tail = nullptr;
  std::size_t count = 0;
  void push(void* p) {
    auto* b = static_cast<Gmp_pool_block*>(p);
    b->next = head;
    if (head == nullptr)
      tail = b;
    head = b;
    ++count;
  }
  void* pop() {
    Gmp_pool_block* b = head;
    head = b->next;
    if (head == nullptr)
      tail = nullptr;
    --count;
    return b;
  }
};

// Free lists of threads that have ended, and blocks freed after their thread's cache ended
// (thread_local and static destructors at exit). Never destroyed: a block may be freed
// during the process's last static destructors.
struct Gmp_pool_shared {
  std::mutex mutex;
  std::array<std::vector<Gmp_pool_list>, gmp_pool_classes> lists;
  std::vector<std::pair<char*, std::size_t>> slabs; // the uncarved rest of ended threads' slabs
};
inline Gmp_pool_shared& gmp_pool_shared() {
  static Gmp_pool_shared* shared = new Gmp_pool_shared;
  return *shared;
}

// Trivially destructible: the guard below hands its lists over when the thread ends.
struct Gmp_pool_cache {
  std::array<Gmp_pool_list, gmp_pool_classes> lists{};
  char* slab = nullptr;
  std::size_t slab_left = 0;
  bool guarded = false;
  bool ended = false;
};
inline thread_local Gmp_pool_cache gmp_pool_cache;

struct Gmp_pool_guard {
  ~Gmp_pool_guard() {
    Gmp_pool_cache& cache = gmp_pool_cache;
    Gmp_pool_shared& shared = gmp_pool_shared();
    const std::lock_guard<std::mutex> lock(shared.mutex);
    for (std::size_t c = 0; c < gmp_pool_classes; ++c)
      if (cache.lists[c].count > 0) {
        shared.lists[c].push_back(cache.lists[c]);
        cache.lists[c] = Gmp_pool_list();
      }
    if (cache.slab_left >= 8)
      shared.slabs.emplace_back(cache.slab, cache.slab_left);
    cache.slab_left = 0;
    cache.ended = true;
  }
};
inline thread_local Gmp_pool_guard gmp_pool_guard;

// GMP's functions cannot recover from a failed allocation (nor let an exception through):
// like GMP's own allocator, end the process with a message.
inline void* gmp_pool_malloc(std::size_t size) {
  void* p = std::malloc(size);
  if (p == nullptr) {
    std::fputs("GNU MP: Cannot allocate memory (Triangular_spline's small-block pool)\n", stderr);
    std::abort();
  }
  return p;
}

inline void* gmp_pool_allocate(std::size_t size) {
  const std::size_t c = gmp_pool_class(size);
  if (c == gmp_pool_classes)
    return gmp_pool_malloc(size);
  Gmp_pool_cache& cache = gmp_pool_cache;
  if (cache.lists[c].count > 0)
    return cache.lists[c].pop();
  if (cache.ended) // after this thread's cache was handed over
    return gmp_pool_malloc(8 * (c + 1));
  if (!cache.guarded) {
    (void)&gmp_pool_guard; // constructs it: its destructor runs when the thread ends
    cache.guarded = true;
  }
  const std::size_t bytes = 8 * (c + 1);
  if (cache.slab_left < bytes) {
    // a list an ended thread left behind, else the rest of its slab, else a new slab
    Gmp_pool_shared& shared = gmp_pool_shared();
    const std::lock_guard<std::mutex> lock(shared.mutex);
    if (!shared.lists[c].empty()) {
      cache.lists[c] = shared.lists[c].back();
      shared.lists[c].pop_back();
      return cache.lists[c].pop(); // (lists are handed over non-empty)
    }
    if (!shared.slabs.empty() && shared.slabs.back().second >= bytes) {
      std::tie(cache.slab, cache.slab_left) = shared.slabs.back();
      shared.slabs.pop_back();
    } else {
      cache.slab = static_cast<char*>(gmp_pool_malloc(gmp_pool_slab));
      cache.slab_left = gmp_pool_slab;
    }
  }
  void* p = cache.slab;
  cache.slab += bytes;
  cache.slab_left -= bytes;
  return p;
}

inline void gmp_pool_free(void* p, std::size_t size) {
  const std::size_t c = gmp_pool_class(size);
  if (c == gmp_pool_classes) {
    std::free(p);
    return;
  }
  Gmp_pool_cache& cache = gmp_pool_cache;
  if (cache.ended) {
    Gmp_pool_shared& shared = gmp_pool_shared();
    const std::lock_guard<std::mutex> lock(shared.mutex);
    if (shared.lists[c].empty())
      shared.lists[c].emplace_back();
    shared.lists[c].back().push(p);
    return;
  }
  if (!cache.guarded) {
    (void)&gmp_pool_guard;
    cache.guarded = true;
  }
  cache.lists[c].push(p);
}

inline void* gmp_pool_reallocate(void* p, std::size_t old_size, std::size_t new_size) {
  const std::size_t old_class = gmp_pool_class(old_size), new_class = gmp_pool_class(new_size);
  if (old_class == gmp_pool_classes && new_class == gmp_pool_classes) {
    void* q = std::realloc(p, new_size);
    if (q == nullptr) {
      std::fputs("GNU MP: Cannot reallocate memory (Triangular_spline's small-block pool)\n",
                 stderr);
      std::abort();
    }
    return q;
  }
  if (old_class == new_class)
    return p;
  void* q = gmp_pool_allocate(new_size);
  std::memcpy(q, p, old_size < new_size ? old_size : new_size);
  gmp_pool_free(p, old_size);
  return q;
}

} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  makes GMP (and through it `mpq_class`, `CGAL::Gmpq` and MPFR) take its blocks of 8 to 32
  bytes, the integers of one to four limbs that exact builds are made of, from per-thread
  pools instead of `malloc()`. An exact build of \f$10^5\f$ points then takes about two
  thirds of the time and of the memory (see the manual); double builds do not change.

  Call it once, at the start of a program, before other threads use GMP. Blocks the pools
  hold are reused by GMP but not returned to the system until the process ends; the pools
  cannot be uninstalled (a block they served must never reach `free()`), so no library
  may install GMP memory functions of its own later in the process (Python's gmpy2 does
  at import: not in a Python extension). Does nothing and returns `false` if the program
  already installed GMP memory functions of its own, and in builds with AddressSanitizer
  (which then sees every block).
  \returns whether the pools are now GMP's allocator
*/
inline bool use_gmp_small_block_pool() {
  if constexpr (!internal::gmp_pool_supported)
    return false;
  void* (*allocate)(std::size_t);
  void* (*reallocate)(void*, std::size_t, std::size_t);
  void (*release)(void*, std::size_t);
  mp_get_memory_functions(&allocate, &reallocate, &release);
  if (allocate == &internal::gmp_pool_allocate)
    return true;
  void* (*default_allocate)(std::size_t);
  mp_set_memory_functions(nullptr, nullptr, nullptr); // GMP's defaults, to compare with
  mp_get_memory_functions(&default_allocate, nullptr, nullptr);
  if (allocate != default_allocate) {
    mp_set_memory_functions(allocate, reallocate, release);
    return false;
  }
  mp_set_memory_functions(&internal::gmp_pool_allocate, &internal::gmp_pool_reallocate,
                          &internal::gmp_pool_free);
  return true;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_GMP_SMALL_BLOCK_POOL_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_H

// Independent per-index work on all cores. Each index is handled by exactly one thread and
// writes only its own results, so the output does not depend on the number of threads.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

// The most threads thread_count() gives (0: one per core). Tests set 1 to compare a parallel
// result with the one-thread result bit for bit; nothing else changes it.
inline std::size_t& thread_limit() {
  static std::size_t limit = 0;
  return limit;
}

// The threads for n independent items: one per core, but none for fewer than `grain` items
// each (a thread costs about 50 microseconds to start).
inline std::size_t thread_count(std::size_t n, std::size_t grain) {
  std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
  if (thread_limit() > 0)
    cores = (std::min)(cores, thread_limit());
  return (std::min)(cores, n / (std::max<std::size_t>)(grain, 1) + 1);
}

// The indices of one block of parallel_for_index() run on one thread, in increasing order:
// a caller may append the results of a block's indices to that block's own buffer.
constexpr std::size_t parallel_block = 1024;

// Calls f(i) for every i in [0, n), in blocks of `block` (default `parallel_block`; smaller
// for items of exact arithmetic, which cost a thousand times more) over `threads` threads
// (1: the calling thread only). Each thread takes the next block not yet taken: on a
// machine whose cores are shared (a virtual machine's, half their time stolen), a fixed
// share of the blocks per thread left one core working alone at the end of each loop (0.15
// s of an exact plan's 3.7 s at 10^5 points). An exception thrown by f is rethrown
// after every thread has stopped: the one of the smallest index, as a serial loop would have
// thrown it.
template <class F>
void parallel_for_index(std::size_t n, std::size_t threads, const F& f,
                        std::size_t block = parallel_block) {
  threads = (std::max<std::size_t>)(threads, 1);
  block = (std::max<std::size_t>)(block, 1);
  if (threads == 1) {
    for (std::size_t i = 0; i < n; ++i)
      f(i);
    return;
  }
  std::vector<std::exception_ptr> error(threads);
  std::vector<std::size_t> error_at(threads, n);
  std::atomic<std::size_t> next{0}; // the next block to take
  const std::size_t blocks = n / block + (n % block != 0 ? 1 : 0);
  auto run = [&](std::size_t t) {
    for (std::size_t b; (b = next.fetch_add(1, std::memory_order_relaxed)) < blocks;) {
      const std::size_t first = b * block, last = (std::min)(n, first + block);
      for (std::size_t i = first; i < last; ++i) {
        try {
          f(i);
        } catch (...) {
          error[t] = std::current_exception();
          error_at[t] = i;
          return;
        }
      }
    }
  };
  std::vector<std::thread> workers;
  for (std::size_t t = 1; t < threads; ++t)
    workers.emplace_back(run, t);
  run(0);
  for (std::thread& worker : workers)
    worker.join();
  std::size_t first = threads;
  for (std::size_t t = 0; t < threads; ++t)
    if (error[t] && (first == threads || error_at[t] < error_at[first]))
      first = t;
  if (first != threads)
    std::rethrow_exception(error[first]);
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_H

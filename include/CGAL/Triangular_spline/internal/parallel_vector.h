// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_VECTOR_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_VECTOR_H

// A vector whose appended ranges are constructed on all cores. std::vector constructs its
// elements on one: an exact plan's 1.3 million stored rules (10^5 points) of three GMP
// fractions each were allocated, and their 150 MB first touched, by one thread while the
// other core waited. The interface is the part of std::vector the plans use, plus
// append_groups().

#include <CGAL/Triangular_spline/internal/parallel.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

template <class T>
class Parallel_vector {
public:
  Parallel_vector() = default;
  Parallel_vector(const Parallel_vector& other) {
    reserve(other.m_size);
    std::uninitialized_copy(other.begin(), other.end(), m_data);
    m_size = other.m_size;
  }
  Parallel_vector(Parallel_vector&& other) noexcept { swap(other); }
  Parallel_vector& operator=(Parallel_vector other) noexcept {
    swap(other);
    return *this;
  }
  ~Parallel_vector() {
    clear();
    ::operator delete(m_data);
  }
  void swap(Parallel_vector& other) noexcept {
    std::swap(m_data, other.m_data);
    std::swap(m_size, other.m_size);
    std::swap(m_capacity, other.m_capacity);
  }

  std::size_t size() const { return m_size; }
  std::size_t capacity() const { return m_capacity; }
  bool empty() const { return m_size == 0; }
  T& operator[](std::size_t i) { return m_data[i]; }
  const T& operator[](std::size_t i) const { return m_data[i]; }
  T* begin() { return m_data; }
  T* end() { return m_data + m_size; }
  const T* begin() const { return m_data; }
  const T* end() const { return m_data + m_size; }

  void clear() noexcept {
    std::destroy(m_data, m_data + m_size);
    m_size = 0;
  }
  void reserve(std::size_t n) {
    if (n > m_capacity)
      reallocate(n);
  }
  void shrink_to_fit() {
    if (m_capacity > m_size)
      reallocate(m_size);
  }
  // T{arguments...}: aggregates too
  template <class... Arguments>
  T& emplace_back(Arguments&&... arguments) {
    if (m_size == m_capacity)
      reallocate((std::max)(std::size_t(16), 2 * m_capacity));
    T* made = ::new (static_cast<void*>(m_data + m_size)) T{std::forward<Arguments>(arguments)...};
    ++m_size;
    return *made;
  }

  // Appends first.back() elements in groups on up to `threads` threads: group g's elements
  // [first[g], first[g + 1]) (first[0] == 0) are made by make(g, at, made), which constructs
  // them in order with placement new at at + made, incrementing `made` after each (so that
  // an exception leaves a count of what to destroy). A group runs on one thread.
  template <class Make>
  void append_groups(const std::vector<std::size_t>& first, std::size_t threads, const Make& make) {
    const std::size_t groups = first.empty() ? 0 : first.size() - 1;
    if (groups == 0)
      return;
    reserve(m_size + first.back());
    std::vector<std::uint32_t> made(groups, 0);
    T* const base = m_data + m_size;
    try {
      parallel_for_index(
          groups, threads,
          [&](std::size_t g) {
            make(g, base + first[g], made[g]);
            if (made[g] != first[g + 1] - first[g])
              throw std::logic_error("Parallel_vector: a group made " + std::to_string(made[g]) +
                                     " elements of " + std::to_string(first[g + 1] - first[g]));
          },
          256);
    } catch (...) {
      for (std::size_t g = 0; g < groups; ++g)
        std::destroy(base + first[g], base + first[g] + made[g]);
      throw;
    }
    m_size += first.back();
  }

private:
  void reallocate(std::size_t n) {
    T* data = static_cast<T*>(::operator new(n * sizeof(T)));
    std::size_t moved = 0;
    try {
      for (; moved < m_size; ++moved)
        ::new (static_cast<void*>(data + moved)) T(std::move(m_data[moved]));
    } catch (...) {
      std::destroy(data, data + moved);
      ::operator delete(data);
      throw;
    }
    std::destroy(m_data, m_data + m_size);
    ::operator delete(m_data);
    m_data = data;
    m_capacity = n;
  }

  T* m_data = nullptr;
  std::size_t m_size = 0;
  std::size_t m_capacity = 0;
};

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_PARALLEL_VECTOR_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_INTERNAL_PLAN_CERTIFICATE_H
#define CGAL_TRIANGULAR_SPLINE_INTERNAL_PLAN_CERTIFICATE_H

// The exact proof that a C^1 quintic spline's plan parametrises a family of C^1 splines with
// one parameter per free slot, i.e. dim S^1_5 >= the free count (Spline_space.h).
//
// The plan is a list of rules value(target) = sum w_k value(source_k) in evaluation order.
// If every non-free slot is the target of exactly one rule whose sources come earlier, the
// splines the plan produces are exactly the solutions of the rule equations, a space of
// dimension = free count (the free values are read back unchanged). That space lies in the
// C^1 space iff each C^1 condition is a linear combination of the rule equations: substitute,
// in each condition, the latest rule target by its sources until only free slots remain;
// the condition is implied iff every remaining coefficient is exactly zero. This is a check
// of the weights actually computed, not an appeal to the construction's theory.

#include <CGAL/Triangular_spline/internal/continuity_conditions.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {

struct Plan_check {
  bool valid = false;            // every non-free slot has exactly one rule, sources earlier
  bool implies_c1 = false;       // every C^1 condition reduces to zero over the rules
  std::size_t conditions = 0;    // C^1 conditions checked
  std::size_t failed = 0;        // conditions that did not reduce to zero
  std::size_t substitutions = 0; // rule substitutions made (the work done)
};

// `Spline` is a C1_quintic_spline over an exact kernel (its rule weights are exact).
template <class Spline>
Plan_check check_plan_implies_c1(const Spline& spline) {
  using FT = typename Spline::FT;
  using Slot = typename Spline::Slot;
  Plan_check result;
  const auto& rules = spline.rules();
  // The control points, and the auxiliary slots after them (partial sums of the rules of
  // near-singular vertices), each the target of a rule.
  std::size_t slots = spline.number_of_slots();
  for (const auto& r : rules)
    slots = (std::max)(slots, std::size_t(r.target) + 1);
  // position[s]: 1 + the index of the rule computing s, 0 for a free slot.
  std::vector<std::uint32_t> position(slots, 0);
  for (std::size_t i = 0; i < rules.size(); ++i) {
    const auto& r = rules[i];
    if (r.target >= slots || spline.is_free(r.target) || position[r.target] != 0)
      return result; // a free slot overwritten, or two rules for one slot
    for (int k = 0; k < r.size(); ++k) {
      const Slot s = r.sources[std::size_t(k)];
      if (s >= slots || (!spline.is_free(s) && (position[s] == 0 || position[s] > i)))
        return result; // a source not computed before the rule
    }
    position[r.target] = static_cast<std::uint32_t>(i + 1);
  }
  for (std::size_t s = 0; s < slots; ++s)
    if (!spline.is_free(s) && position[s] == 0)
      return result; // a slot neither free nor computed
  result.valid = true;

  std::vector<std::vector<std::pair<std::uint32_t, FT>>> conditions;
  for_each_c1_condition(spline.domain(), [&](auto row) { conditions.push_back(std::move(row)); });
  result.conditions = conditions.size();
  std::atomic<std::size_t> failed{0}, substitutions{0};
  // Each condition alone, on all cores; scratch per thread (a slot's place in the current
  // combination, reset after each condition).
  parallel_for_index(conditions.size(), thread_count(conditions.size(), 2000), [&](std::size_t c) {
    thread_local std::vector<int> place;
    thread_local std::vector<std::pair<Slot, FT>> terms;
    thread_local std::vector<std::pair<std::uint32_t, Slot>> heap; // (position, slot)
    if (place.size() < slots)
      place.assign(slots, -1);
    terms.clear();
    heap.clear();
    auto add = [&](Slot s, const FT& coefficient) {
      if (place[s] < 0) {
        place[s] = static_cast<int>(terms.size());
        terms.emplace_back(s, coefficient);
        if (position[s] != 0) {
          heap.emplace_back(position[s], s);
          std::push_heap(heap.begin(), heap.end());
        }
      } else {
        terms[std::size_t(place[s])].second += coefficient;
      }
    };
    for (const auto& [s, coefficient] : conditions[c])
      add(s, coefficient);
    std::size_t count = 0;
    // Latest target first: its coefficient is final, as every rule that names it as a source
    // comes later and has been substituted already.
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end());
      const Slot s = heap.back().second;
      heap.pop_back();
      const FT coefficient = terms[std::size_t(place[s])].second;
      terms[std::size_t(place[s])].second = FT(0);
      if (CGAL::is_zero(coefficient))
        continue;
      const auto& r = rules[position[s] - 1];
      for (int k = 0; k < r.size(); ++k)
        add(r.sources[std::size_t(k)], coefficient * r.weights[std::size_t(k)]);
      ++count;
    }
    bool zero = true;
    for (const auto& [s, coefficient] : terms) {
      zero = zero && CGAL::is_zero(coefficient);
      place[s] = -1;
    }
    if (!zero)
      ++failed;
    substitutions += count;
  });
  result.failed = failed;
  result.substitutions = substitutions;
  result.implies_c1 = result.failed == 0;
  return result;
}

} // namespace internal
} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_INTERNAL_PLAN_CERTIFICATE_H

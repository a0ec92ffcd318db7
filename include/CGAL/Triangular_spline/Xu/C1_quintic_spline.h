// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_XU_C1_QUINTIC_SPLINE_H
#define CGAL_TRIANGULAR_SPLINE_XU_C1_QUINTIC_SPLINE_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/Domain/Planar_domain.h>
#include <CGAL/Triangular_spline/Multi_index.h>
#include <CGAL/Triangular_spline/Value_traits.h>
#include <CGAL/Triangular_spline/Xu/degenerate_frames.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/frame_degeneracy.h>
#include <CGAL/Triangular_spline/internal/filtered_orientation.h>
#include <CGAL/Triangular_spline/internal/parallel.h>
#include <CGAL/Triangular_spline/internal/parallel_vector.h>
#include <CGAL/Triangular_spline/internal/release.h>
#include <CGAL/Triangular_spline/internal/spline_plan.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Exact_rational.h>

#include <boost/container/small_vector.hpp>
#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {
namespace internal {
// Tests only: false leaves the dependency cycles that single faces close to order_rules()
// and a new round of the plan, as for any other cycle (the plans must be the same).
inline bool& break_face_cycles_first() {
  static bool first = true;
  return first;
}
// Work for the C1_quintic_spline constructor to do beside its plan: f(domain, planned).
template <class F>
struct While_planning {
  F f;
};
template <class F>
While_planning<F> while_planning(F f) {
  return {std::move(f)};
}
} // namespace internal

/*!
  \ingroup PkgTriangularSplineSplines
  \brief which three points of a corner region (the corner point and its star, Xu §4.1.2)
  are prescribed.
*/
enum class Corner_frame {
  /// three star points spread evenly around the vertex (Xu Fig.\ 4.1): the corner point
  /// itself is propagated, so the spline approximates the vertex data
  SYMMETRIC_STARS,
  /// the corner point and the two star points whose directions are closest to orthogonal:
  /// the corner can be forced through a data value (interpolation, Xu §4.4.2)
  CORNER_AND_TWO_STARS
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief the role of a control-point slot (SPEC §3): each control point of the spline is
  stored once, in the slot of the vertex, edge or face it belongs to.
*/
enum class Slot_kind {
  CORNER,       ///< \f$f(v^5)\f$, one per vertex
  STAR,         ///< \f$f(v^4 w)\f$, two per edge
  EDGE_MIDDLE,  ///< \f$f(v^3 w^2)\f$, two per edge
  CORNER_INNER, ///< \f$f(a^3 b c)\f$, three per face
  MIDDLE_INNER, ///< \f$f(a b^2 c^2)\f$ (the flip points of interior edges), three per face
  AUXILIARY     ///< not a control point: a partial sum of a rule of more than three sources
};

/*!
  \ingroup PkgTriangularSplineSplines
  \brief Xu's C^1 quintic spline over a planar triangulation (Xu ch. 3, 4, 7), built by
  prescribing a minimal determining set of control points and propagating the others.

  <b>Storage.</b> Control points shared by patches are stored once: one slot per vertex
  (corner), four per edge (star, edge-middle, edge-middle, star, from the edge's smaller
  vertex index to the larger), six per face (three corner-inner, three middle-inner),
  about 12.5 values per face. The patch of a face is a view over its 21 slots (`patch()`),
  so C^0 continuity holds by construction.

  <b>Plan.</b> The prescription is data: every slot is either free or computed by a
  `Rule`, an affine combination of two or three earlier slots with coefficients that are
  barycentric coordinates of domain points (ratios of 2x2 determinants, Xu §4.2). Rules
  are stored in evaluation order: corner regions (Lemma 3.3.2), corner-inner constraints
  at degenerate frames, edge-middle points from both ends of each edge (condition 3.5
  solved for the edge point), edge-middle points of re-routed ends, and finally the
  second flip point of every interior edge. The free slots are, per vertex, three
  non-collinear points of its corner region; per face its three corner-inner points; per
  interior edge one flip point; per boundary edge its two edge-middle points and the
  middle-inner point next to it.

  <b>Degenerate frames</b> (Xu §4.4.4) are detected with exact predicates and re-routed:
  the edge-middle point next to a degenerate end is solved from the middle diamond (both
  flip points free), and the diamond at the degenerate end becomes a constraint fixing one
  corner-inner point from its neighbour. Around a singular vertex the four constraints form
  a cycle of which one is implied: one corner-inner point stays free, which is the extra
  dimension \f$\sigma\f$. No rule ever divides by zero; the free count is
  \f$3V + 3F + E_I + 3E_B + \sigma\f$. Thin frames (regular weights above
  `propagation_weight_bound`) are re-routed the same way. At a near-singular vertex (every
  edge end thin or degenerate, the vertex not singular) the cycle of links cannot be closed,
  and the one link left regular is written directly in the free data, a rule of up to eight
  sources whose partial sums live in auxiliary slots: no weight grows as the vertex nears
  singularity.

  Domain points are those of `GeomTraits`; all geometric decisions use its exact
  predicates. With an exact number type every coefficient and every control point is
  exact.

  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (heights over the plane) or `GeomTraits::Vector_3`
  (parametric surfaces)
  \cgalModels `TriangularSplineNetwork`
*/
template <class GeomTraits, class Value = typename GeomTraits::FT>
class C1_quintic_spline {
public:
  /// \name Types
  /// @{

  /// the kernel
  using Geom_traits = GeomTraits;
  /// the number type
  using FT = typename Geom_traits::FT;
  /// the point type of the domain plane
  using Point_2 = typename Geom_traits::Point_2;
  /// the triangulated domain
  using Domain = Planar_domain<Geom_traits>;
  /// index of a vertex, edge or face of the domain
  using Index = typename Domain::Index;
  /// index of a control-point slot
  using Slot = std::uint32_t;
  /// the quintic patch over one face
  using Patch = Bezier_triangle<Geom_traits, Value>;
  /// a degenerate frame found in the domain
  using Degenerate_frame = Degenerate_frame_t<Index>;
  /// the bound on the weights of the edge rules: an edge end whose regular rule (Xu's
  /// condition 3.5 solved for its edge-middle point) would use a weight above it is
  /// re-routed as a thin frame, where every weight is at most about 2. At a near-singular
  /// vertex, whose cycle of re-routed links cannot be closed, the one link left regular is
  /// written in the free data (`number_of_auxiliary_slots()`), with weights of about 10
  /// however close the vertex is to singular.
  ///
  /// Two kinds of rule can still exceed it, each a property of thin triangles rather than of
  /// a frame (on random points about 1.5 rules in 10^3 faces); their weights stay below
  /// \f$8/\sin\theta\f$, \f$\theta\f$ the smallest angle of the triangles at the vertices of
  /// the rule's points (measured on random points and jittered grids, and tested), as the
  /// stability constants of Lai and Schumaker's minimal determining sets, which depend on the
  /// smallest angle alone:
  /// - star points: the affine image of a vertex's three prescribed points; large where
  ///   every edge at the vertex is close to one line (a vertex on a nearly straight hull).
  ///   These cannot amplify inconsistent data: any three values lie on one plane.
  /// - flip points of an edge whose two triangles are both thin across it (a fan of
  ///   slivers): the middle diamond is solved for the larger flip coefficient, so the
  ///   weight is the ratio of the quadrilateral's largest sub-triangle to the larger face,
  ///   about 1/sin of the faces' smallest angle. Re-routing the edge moves the same ratio
  ///   into the corner-inner links (a few of which also exceed the bound).
  static constexpr double propagation_weight_bound = 16;
  /// an invalid slot index, marking an unused source of a `Rule`
  static constexpr Slot null_slot = (std::numeric_limits<Slot>::max)();
  /// the domain vertices and multiplicities of a control point's blossom argument (at most
  /// three entries, no allocation)
  using Polar_label = boost::container::static_vector<std::pair<Index, int>, 3>;

  /// how a dependent slot is computed: `value(target) = sum weights[i] * value(sources[i])`
  /// over the first `size()` sources (the weights of a control point's rule sum to one; a
  /// partial sum in an auxiliary slot is a linear combination)
  struct Rule {
    Slot target;                 ///< the dependent slot computed by the rule
    std::array<Slot, 3> sources; ///< the source slots; an unused third one is `null_slot`
    std::array<FT, 3> weights;   ///< the coefficients of the sources
    /// the number of sources used (2 or 3); derived, not stored: a rule of `double`s is
    /// 40 bytes instead of 48 (14 million rules at 10^6 points)
    int size() const { return sources[2] == null_slot ? 2 : 3; }
  };
  /// @}

  /// \name Creation
  /// @{

  /*!
    builds the plan of the spline over `domain`; all control values start at zero.
    \param domain the triangulated domain, copied into the spline
    \param frame which points of each corner region are prescribed
  */
  explicit C1_quintic_spline(Domain domain, Corner_frame frame = Corner_frame::SYMMETRIC_STARS)
      : m_domain(std::move(domain)), m_frame(frame) {
    count_control_slots();
    build_plan();
  }
  /// \cond SKIP_IN_MANUAL
  // As above, calling meanwhile(domain(), planned) on another thread while the plan is built
  // (which reads the domain only); `planned` is set once the plan is done, and the work
  // should then stop soon. make_c1_quintic_spline() fits local polynomials there, on the
  // core that the plan's serial stretches leave idle. `meanwhile` must not throw. If no
  // thread can be started it is not called.
  template <class Meanwhile>
  C1_quintic_spline(Domain domain, Corner_frame frame,
                    internal::While_planning<Meanwhile> meanwhile)
      : m_domain(std::move(domain)), m_frame(frame) {
    count_control_slots();
    std::atomic<bool> planned{false};
    std::thread worker;
    try {
      worker = std::thread([&] { meanwhile.f(std::as_const(m_domain), std::as_const(planned)); });
    } catch (const std::system_error&) {
    }
    auto stop = [&] {
      planned.store(true, std::memory_order_relaxed);
      if (worker.joinable())
        worker.join();
    };
    try {
      build_plan();
    } catch (...) {
      stop(); // it reads the domain, which unwinding destroys
      throw;
    }
    stop();
  }
  /// \endcond
  /// @}

  /// \name Slots
  /// @{

  /// returns the domain.
  /// \returns the domain
  const Domain& domain() const { return m_domain; }
  /// returns the choice of prescribed points in the corner regions.
  /// \returns the choice of prescribed points in the corner regions
  Corner_frame corner_frame() const { return m_frame; }
  /// returns the number of control-point slots, \f$V + 4E + 6F\f$.
  /// \returns the number of control-point slots, \f$V + 4E + 6F\f$
  std::size_t number_of_slots() const { return m_control_slots; }
  /// returns the number of auxiliary slots: they follow the control points (slots
  /// `number_of_slots()` and up) and hold partial sums of the rules of more than three
  /// sources, which close the links of `near_singular_vertices()` (two per such vertex,
  /// none on most domains). They are neither free nor control points.
  /// \returns the number of auxiliary slots
  std::size_t number_of_auxiliary_slots() const { return m_values.size() - m_control_slots; }
  /// the corner slot of vertex `v`
  /// \param v the index of a vertex
  /// \returns the corner slot of `v`
  Slot vertex_slot(Index v) const { return internal::quintic_vertex_slot(m_domain, v); }
  /// slot `t` (0..3) of edge `e` = (lo, hi): \f$f(lo^{4-t} hi^{1+t})\f$
  /// \param e the index of an edge
  /// \param t the position along the edge, 0..3
  /// \returns slot `t` of edge `e`
  Slot edge_slot(Index e, int t) const { return internal::quintic_edge_slot(m_domain, e, t); }
  /// slot `t` (0..5) of face `f` = (a, b, c): t < 3 the corner-inner point at vertex t,
  /// t >= 3 the middle-inner point next to the edge opposite vertex t-3
  /// \param f the index of a face
  /// \param t the position in the face, 0..5
  /// \returns slot `t` of face `f`
  Slot face_slot(Index f, int t) const { return internal::quintic_face_slot(m_domain, f, t); }

  /// returns the slot holding \f$b_{i,j,k}\f$ of the patch of face `f` over
  /// (`face(f)[0]`, `face(f)[1]`, `face(f)[2]`)
  /// \param f the index of a face
  /// \param index the multi-index of a control point
  /// \returns the slot of \f$b_{i,j,k}\f$
  Slot slot(Index f, const Multi_index& index) const {
    return internal::quintic_slot(m_domain, f, index);
  }

  /// returns the role of slot `s`
  /// \param s a control-point slot
  /// \returns the role of slot `s`
  Slot_kind kind(Slot s) const {
    const std::size_t V = m_domain.number_of_vertices(), E = m_domain.number_of_edges();
    if (s >= m_control_slots)
      return Slot_kind::AUXILIARY;
    if (s < V)
      return Slot_kind::CORNER;
    if (s < V + 4 * E) {
      const std::size_t t = (s - V) % 4;
      return (t == 0 || t == 3) ? Slot_kind::STAR : Slot_kind::EDGE_MIDDLE;
    }
    return (s - V - 4 * E) % 6 < 3 ? Slot_kind::CORNER_INNER : Slot_kind::MIDDLE_INNER;
  }

  /// returns the polar label of slot `s`: the domain vertices and multiplicities
  /// (summing to 5) of the blossom argument \f$f(u^a v^b w^c)\f$ whose value it holds
  /// \pre `s < number_of_slots()` (auxiliary slots have no label)
  /// \param s a control-point slot
  /// \returns the polar label of `s`
  Polar_label polar_label(Slot s) const {
    CGAL_precondition(s < m_control_slots);
    const std::size_t V = m_domain.number_of_vertices(), E = m_domain.number_of_edges();
    if (s < V)
      return {{static_cast<Index>(s), 5}};
    if (s < V + 4 * E) {
      const std::size_t e = (s - V) / 4;
      const int t = static_cast<int>((s - V) % 4);
      const auto& ends = m_domain.edge(static_cast<Index>(e));
      return {{ends[0], 4 - t}, {ends[1], 1 + t}};
    }
    const std::size_t f = (s - V - 4 * E) / 6;
    const int t = static_cast<int>((s - V - 4 * E) % 6);
    const auto& v = m_domain.face(static_cast<Index>(f));
    if (t < 3)
      return {{v[std::size_t(t)], 3},
              {v[std::size_t((t + 1) % 3)], 1},
              {v[std::size_t((t + 2) % 3)], 1}};
    const int u = t - 3;
    return {
        {v[std::size_t(u)], 1}, {v[std::size_t((u + 1) % 3)], 2}, {v[std::size_t((u + 2) % 3)], 2}};
  }

  /// returns the domain point of slot `s` (its polar label averaged): where the control
  /// point sits over the plane in a picture of the control net
  /// \param s a control-point slot
  /// \returns the domain point of `s`
  Point_2 domain_point(Slot s) const {
    FT x(0), y(0);
    for (const auto& [v, m] : polar_label(s)) {
      x = x + FT(m) * m_domain.point(v).x();
      y = y + FT(m) * m_domain.point(v).y();
    }
    return Point_2(x / FT(5), y / FT(5));
  }
  /// @}

  /// \name Plan
  /// @{

  /// returns `true` iff slot `s` is a free parameter (not computed by a rule).
  /// \param s a control-point slot
  /// \returns `true` iff slot `s` is a free parameter (not computed by a rule)
  bool is_free(Slot s) const { return m_free[s] != 0; }

  /*!
    \brief the free slots of a spline in increasing order, as returned by `free_slots()`: a
    forward range (`begin()`, `end()`, `size()`, `empty()`, comparable with `==`) read from
    the plan's byte per slot rather than a list (4 bytes per free slot, 48 MB at
    \f$10^6\f$ points). Valid as long as the spline object.
  */
  class Free_slots {
  public:
    /// a forward iterator over the free slots, dereferencing to a `Slot`
    class iterator {
    public:
      using iterator_category = std::forward_iterator_tag;
      using value_type = Slot;
      using difference_type = std::ptrdiff_t;
      using pointer = const Slot*;
      using reference = Slot;
      iterator() = default;
      Slot operator*() const { return static_cast<Slot>(m_at); }
      iterator& operator++() {
        ++m_at;
        skip();
        return *this;
      }
      iterator operator++(int) {
        iterator old = *this;
        ++*this;
        return old;
      }
      friend bool operator==(const iterator& a, const iterator& b) { return a.m_at == b.m_at; }
      friend bool operator!=(const iterator& a, const iterator& b) { return a.m_at != b.m_at; }

    private:
      friend class Free_slots;
      iterator(const char* free, std::size_t at, std::size_t end)
          : m_free(free), m_at(at), m_end(end) {
        skip();
      }
      void skip() {
        while (m_at < m_end && !m_free[m_at])
          ++m_at;
      }
      const char* m_free = nullptr;
      std::size_t m_at = 0, m_end = 0;
    };
    /// the same iterator
    using const_iterator = iterator;
    /// returns an iterator to the first free slot
    iterator begin() const { return iterator(m_spline->m_free.data(), 0, m_spline->m_free.size()); }
    /// returns the past-the-end iterator
    iterator end() const {
      const std::size_t n = m_spline->m_free.size();
      return iterator(m_spline->m_free.data(), n, n);
    }
    /// returns the number of free slots
    std::size_t size() const { return m_spline->m_number_of_free; }
    /// returns whether no slot is free
    bool empty() const { return size() == 0; }
    /// whether both ranges hold the same slots
    friend bool operator==(const Free_slots& a, const Free_slots& b) {
      return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), b.end());
    }

  private:
    friend class C1_quintic_spline;
    explicit Free_slots(const C1_quintic_spline* spline) : m_spline(spline) {}
    const C1_quintic_spline* m_spline;
  };
  /// returns the free slots in increasing order
  /// \returns the free slots in increasing order
  Free_slots free_slots() const { return Free_slots(this); }
  /// returns the number of free slots.
  /// \returns the number of free slots
  std::size_t number_of_free_parameters() const { return m_number_of_free; }
  /// returns the number of rules (dependent slots, and partial sums in auxiliary slots)
  /// \returns the number of rules
  std::size_t number_of_rules() const { return m_rule_refs.size(); }
  /// returns rule `i` in evaluation order. In `double` the spline stores only the rules of
  /// re-routed frames and of near-singular vertices; every other rule (corner regions,
  /// edge-middle points of regular ends, flip points) is rebuilt from the domain when read,
  /// with the very weights the plan computed: 4 bytes per rule instead of 40 (a `tspline c1`
  /// run on 10^6 random points peaks at 781 MB instead of 1286 MB). Exact number types keep
  /// every rule.
  /// \pre `i < number_of_rules()`
  /// \param i the position of the rule in evaluation order
  /// \returns the rule
  Rule rule(std::size_t i) const { return rule_of_ref(m_rule_refs[i], true); }
  /// returns the number of rules stored with their weights (`rule()`); the others are
  /// rebuilt from the domain when read
  /// \returns the number of stored rules
  std::size_t number_of_stored_rules() const { return m_explicit_rules.size(); }
  /// calls `f(rule)` for every rule in evaluation order, without a copy of the plan.
  /// \param f a function object taking a `const Rule&`
  template <class F>
  void for_each_rule(F&& f) const {
    for (const std::uint32_t ref : m_rule_refs) {
      if (ref & explicit_rule_bit)
        f(m_explicit_rules[ref & ~explicit_rule_bit]);
      else
        f(implicit_rule(ref, true));
    }
  }
  /// returns a copy of the rules in evaluation order (`rule()`); prefer `for_each_rule()`
  /// on large domains, which copies nothing
  /// \returns the rules in evaluation order
  std::vector<Rule> rules() const {
    std::vector<Rule> all;
    all.reserve(m_rule_refs.size());
    for_each_rule([&](const Rule& r) { all.push_back(r); });
    return all;
  }
  /// returns the degenerate frames found in the domain (`find_degenerate_frames()`)
  /// \returns the degenerate frames found in the domain (`find_degenerate_frames()`)
  const std::vector<Degenerate_frame>& degenerate_frames() const { return m_degenerate.frames; }
  /// returns the edge ends the plan re-routes: one per edge with a degenerate frame, and the
  /// thin frames (`Degenerate_frame_t::thin`), whose regular rule would have weights above
  /// `propagation_weight_bound`
  /// \returns the re-routed edge ends
  const std::vector<Degenerate_frame>& rerouted_frames() const { return m_frames; }
  /// returns the largest absolute coefficient of any rule: how much the propagation can
  /// amplify a change of a prescribed point (1 for a value copied unchanged)
  /// \returns the largest absolute rule coefficient
  double max_propagation_weight() const { return m_max_weight; }
  /// returns the largest absolute coefficient of the rules computing slots of kind `k`
  /// (where the largest weights are: `Slot_kind::AUXILIARY` for the partial sums of
  /// near-singular vertices)
  /// \param k a slot kind
  /// \returns the largest absolute rule coefficient of that kind (0 if no rule)
  double max_propagation_weight(Slot_kind k) const { return m_max_weight_by_kind[std::size_t(k)]; }
  /// returns the number of rules computing slots of kind `k` whose largest absolute
  /// coefficient exceeds `propagation_weight_bound`
  /// \param k a slot kind
  /// \returns the number of such rules
  std::size_t number_of_rules_above_weight_bound(Slot_kind k) const {
    return m_above_bound_by_kind[std::size_t(k)];
  }
  /// returns an estimate of how much the propagation amplifies inconsistent prescribed
  /// points: the largest absolute control value when every corner region is zero and every
  /// other free point is an independent sign (a fixed hash of its slot; one pass over the
  /// rules, in `float`). With `double` values the first `propagate()` of the plan computes it
  /// beside the control values, sharing their rules' weights (a pass of its own was about 6% of a
  /// `tspline c1` run at \f$10^6\f$ points); before that, and with other value types, it is
  /// computed here (the same value: the same operations in the same order). A single
  /// weight need not amplify: weights that combine points whose deviations cancel do not
  /// (the closing link of a vertex 1e-8 degrees from singular, solved alone, had weights of
  /// 1e10 and this estimate 4). Corner regions are
  /// left out because any three values are one plane: their weights extrapolate a tangent
  /// plane, they cannot amplify an inconsistency. With every weight at most the bound the
  /// estimate stays below about twice the bound (a rule's weights sum to one).
  /// \returns the estimated amplification (0 if no point outside the corner regions is free)
  double propagation_amplification() const {
    if (m_amplification)
      return *m_amplification;
    // float: an estimate, half the memory; not initialised: amplification_signs() fills it
    const std::unique_ptr<float[]> x(new float[m_free.size()]);
    return amplification_in(x.get());
  }
  /// returns how often the plan was built: 1, plus one rebuild per round of dependency
  /// cycles broken (a thin re-routing makes corner-inner points at one end depend on those
  /// at the other end; a chain of them can close a cycle, and then the least thin
  /// re-routing on it goes back to its regular rule)
  /// \returns the number of plan builds
  int plan_rounds() const { return m_plan_rounds; }
  /// returns the near-singular vertices: interior vertices at which every edge is thin or
  /// degenerate, but not every one degenerate (those are singular; such a vertex has degree
  /// 4, its edges close to two lines). Their re-routed links would close a cycle that, unlike
  /// a singular vertex's, is not implied, so the thinnest link keeps its regular condition.
  /// Solved alone for its edge-middle point that condition has weights of about
  /// \f$1/\delta\f$, \f$\delta\f$ the sine of the angle by which the vertex misses being
  /// singular; the plan writes the point in the free data instead (the frame's three points,
  /// the other links' edge-middle points), with coefficients of about 10, computed exactly.
  /// \returns the near-singular vertices, each once
  const std::vector<Index>& near_singular_vertices() const { return m_near_singular; }
  /// returns the interior singular vertices (each adds one free parameter)
  /// \returns the interior singular vertices (each adds one free parameter)
  const std::vector<Index>& singular_vertices() const { return m_degenerate.singular_vertices; }
  /// @}

  /// \name Control values
  /// @{

  /// returns the control value held by slot `s`.
  /// \param s a control-point slot
  /// \returns the control value held by slot `s`
  const Value& value(Slot s) const { return m_values[s]; }
  /// returns the values of all slots, indexed by slot: the `number_of_slots()` control
  /// values, then the `number_of_auxiliary_slots()` partial sums.
  /// \returns the values of all slots, indexed by slot
  const std::vector<Value>& values() const { return m_values; }

  /// sets the free slot `s` without propagating (use `propagate()` after a batch).
  /// \throws Invalid_input if `s` is not free or `v` is not finite
  /// \param s a control-point slot
  /// \param v the new value
  void set_free_value(Slot s, const Value& v) {
    check_free(s, v);
    m_values[s] = v;
  }

  /*!
    moves the spline onto `image`, the image of its domain under an affine map with positive
    determinant: the same vertices and the same triangles, in the same order. Every control
    value and the plan are kept. The \f$C^1\f$ conditions (Xu (3.4), (3.5)) and hence the
    propagation weights are barycentric, so they are invariant under such maps: the spline
    stays \f$C^1\f$, exactly when the map is exact (a scaling by powers of two is, in
    `double` too). This is how a spline is fitted in rescaled coordinates (`tspline c1
    --rescale`) and returned over the data's own.
    \pre `image` is an affine image of `domain()` (certify the result when unsure)
    \throws Invalid_input if `image` has other vertices or triangles
    \param image the image of the domain, with the same vertices and triangles in the same order
  */
  void map_domain(Domain image) {
    if (image.number_of_vertices() != m_domain.number_of_vertices() ||
        image.number_of_faces() != m_domain.number_of_faces())
      throw Invalid_input("map_domain: the image has other vertex or face counts");
    for (Index f = 0; f < m_domain.number_of_faces(); ++f)
      if (image.face(f) != m_domain.face(f))
        throw Invalid_input("map_domain: triangle " + std::to_string(f) +
                            " differs (vertices or orientation) in the image");
    m_domain = std::move(image);
    m_amplification.reset(); // (the implicit rules' weights follow the points)
  }

  /// computes every dependent slot from the free ones, in plan order (with an exact number
  /// type, the rules of one depth on all cores: the same values).
  void propagate() {
    const std::size_t R = m_rule_refs.size();
    if constexpr (Algebraic_structure_traits<FT>::Is_exact::value) {
      const std::size_t threads = internal::thread_count(R, 2000);
      if (threads > 1) {
        propagate_by_depth(threads);
        return;
      }
      for (const std::uint32_t ref : m_rule_refs)
        apply_ref(ref);
    } else {
      double largest = 0;
      if (std::is_same_v<Value, double> && !m_amplification) {
        // propagation_amplification() on the way: the weights are computed once for both
        const std::unique_ptr<float[]> x(new float[m_free.size()]);
        const bool signs = amplification_signs(x.get());
        for_each_rule_in_runs(
            [&](const Rule& r, double& block_largest) {
              apply(r);
              amplification_step(r, x.get(), block_largest);
            },
            largest);
        m_amplification = signs ? (std::max)(largest, 1.0) : largest;
        return;
      }
      for_each_rule_in_runs([&](const Rule& r, double&) { apply(r); }, largest);
    }
  }

  /*!
    sets the free slot `s` to `v` and re-propagates only what depends on it (Xu §4.3:
    corner regions, then edge halves, then flip points, following the plan order).
    \return the slots whose value was recomputed, `s` first
    \param s a control-point slot
    \param v the new value
  */
  std::vector<Slot> edit(Slot s, const Value& v) {
    return edit(std::vector<std::pair<Slot, Value>>{{s, v}});
  }

  /// sets several free slots and re-propagates what depends on any of them, each
  /// dependent slot once, in plan order (corners, edges, flips); returns the edited and
  /// recomputed slots.
  /// \param changes the pairs (free slot, new value)
  /// \returns the edited and recomputed slots
  std::vector<Slot> edit(const std::vector<std::pair<Slot, Value>>& changes) {
    if (m_dependent_offsets.empty())
      build_dependents();
    std::vector<Slot> changed;
    std::vector<std::size_t> heap; // rule positions, smallest first
    auto enqueue_dependents = [&](Slot x) {
      for (std::size_t i = m_dependent_offsets[x]; i < m_dependent_offsets[x + 1]; ++i) {
        const std::size_t r = m_dependents[i];
        if (!m_queued[r]) {
          m_queued[r] = 1;
          heap.push_back(r);
          std::push_heap(heap.begin(), heap.end(), std::greater<std::size_t>());
        }
      }
    };
    for (const auto& [s, v] : changes) {
      check_free(s, v);
      m_values[s] = v;
      changed.push_back(s);
      enqueue_dependents(s);
    }
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<std::size_t>());
      const std::size_t r = heap.back();
      heap.pop_back();
      m_queued[r] = 0;
      const Rule rule = rule_of_ref(m_rule_refs[r], true);
      apply(rule);
      changed.push_back(rule.target);
      enqueue_dependents(rule.target);
    }
    return changed;
  }

  /// returns 5, the degree of the patches.
  /// \returns 5, the degree of the patches
  int degree() const { return 5; }

  /// writes the 21 control values of the patch of face `f` (over `face(f)`, in
  /// `Bezier_triangle::linear_index()` order) to `net`: the patch's net without building the
  /// patch (evaluation reads it once per query).
  /// \param f the index of a face
  /// \param net receives the control values
  template <class Net>
  void face_net(Index f, Net& net) const {
    // Where each of the 21 points lives, by the rules of `slot()`, once: a corner (vertex
    // v), a point of the edge opposite v (`count`: copies of the next vertex of the face), or
    // a face point. Per face only its three edges are then read (evaluation reads one net
    // per query, and 21 calls of `slot()` cost more than the de Casteljau steps).
    struct Place {
      int kind, v, count; // kind 0: corner v, 1: edge opposite v, 2: face slot v
    };
    static const std::array<Place, 21> places = [] {
      std::array<Place, 21> result{};
      std::size_t k = 0;
      for (const Multi_index& index : multi_indices(5)) {
        Place place{-1, 0, 0};
        for (int v = 0; v < 3 && place.kind < 0; ++v)
          if (index[v] == 5)
            place = {0, v, 0};
        for (int v = 0; v < 3 && place.kind < 0; ++v)
          if (index[v] == 0)
            place = {1, v, index[(v + 1) % 3]};
        for (int v = 0; v < 3 && place.kind < 0; ++v)
          if (index[v] == 3)
            place = {2, v, 0};
        for (int v = 0; v < 3 && place.kind < 0; ++v)
          if (index[v] == 1)
            place = {2, 3 + v, 0};
        result[k++] = place;
      }
      return result;
    }();
    const auto& t = m_domain.face(f);
    std::array<Index, 3> edge;
    std::array<bool, 3> next_is_low; // edge opposite v starts at the vertex after v
    for (int v = 0; v < 3; ++v) {
      edge[std::size_t(v)] = m_domain.face_edge(f, v);
      next_is_low[std::size_t(v)] =
          m_domain.edge(edge[std::size_t(v)])[0] == t[std::size_t((v + 1) % 3)];
    }
    net.clear();
    for (const Place& place : places) {
      Slot s = 0;
      if (place.kind == 0)
        s = vertex_slot(t[std::size_t(place.v)]);
      else if (place.kind == 1)
        s = edge_slot(edge[std::size_t(place.v)],
                      4 - (next_is_low[std::size_t(place.v)] ? place.count : 5 - place.count));
      else
        s = face_slot(f, place.v);
      net.push_back(m_values[s]);
    }
  }

  /// returns the quintic patch of face `f` over (`face(f)[0]`, `face(f)[1]`, `face(f)[2]`).
  /// \param f the index of a face
  /// \returns the quintic patch of face `f` over (`face(f)[0]`, `face(f)[1]`, `face(f)[2]`)
  Patch patch(Index f) const {
    std::vector<Value> net;
    net.reserve(21);
    face_net(f, net);
    const auto& t = m_domain.face(f);
    return Patch(5, m_domain.point(t[0]), m_domain.point(t[1]), m_domain.point(t[2]),
                 std::move(net), m_domain.geom_traits());
  }
  /// @}

private:
  static Value zero() { return Value_traits<Value>::zero(); }

  void check_free(Slot s, const Value& v) const {
    if (s >= m_values.size())
      throw Invalid_input("spline: slot " + std::to_string(s) + " does not exist");
    if (!m_free[s])
      throw Invalid_input("spline: slot " + std::to_string(s) +
                          " is propagated, not prescribed; only free control points can be set");
    if (!is_finite_value(v))
      throw Invalid_input("spline: non-finite control value for slot " + std::to_string(s));
  }

  // The rules by depth (free slots have depth 0, a rule's target one more than its deepest
  // source): the plan order computes every source first, so a rule reads only slots of
  // smaller depths, and the rules of one depth can run in parallel with the values of the
  // plan order. The rules of depth d are order[start[d]] .. order[start[d + 1] - 1]
  // (indices into m_rule_refs, in plan order); false, with nothing set, when a slot is
  // computed twice (then only the plan order is right).
  bool rules_by_depth(std::vector<std::size_t>& start, std::vector<std::uint32_t>& order) const {
    const std::size_t R = m_rule_refs.size();
    std::vector<std::uint32_t> slot_depth(m_values.size(), 0), depth(R);
    std::uint32_t deepest = 0;
    for (std::size_t i = 0; i < R; ++i) {
      bool twice = false;
      with_rule(m_rule_refs[i], false, [&](const Rule& r) {
        std::uint32_t d = 0;
        for (int j = 0; j < r.size(); ++j)
          d = (std::max)(d, slot_depth[r.sources[std::size_t(j)]]);
        twice = slot_depth[r.target] != 0;
        depth[i] = slot_depth[r.target] = d + 1;
        deepest = (std::max)(deepest, d + 1);
      });
      if (twice)
        return false;
    }
    start.assign(std::size_t(deepest) + 2, 0);
    for (std::uint32_t d : depth)
      ++start[d + 1];
    for (std::size_t d = 1; d < start.size(); ++d)
      start[d] += start[d - 1];
    order.resize(R);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < R; ++i)
      order[fill[depth[i]]++] = static_cast<std::uint32_t>(i);
    return true;
  }

  // Exact rules cost about a tenth of a millisecond each (sums of fractions of thousands of
  // digits from the local polynomials): propagate() runs them depth by depth on all cores.
  void propagate_by_depth(std::size_t threads) {
    std::vector<std::size_t> start;
    std::vector<std::uint32_t> order;
    if (!rules_by_depth(start, order)) {
      for (const std::uint32_t ref : m_rule_refs)
        apply_ref(ref);
      return;
    }
    for (std::size_t d = 1; d + 1 < start.size(); ++d)
      internal::parallel_for_index(
          start[d + 1] - start[d], threads,
          [&](std::size_t k) { apply_ref(m_rule_refs[order[start[d] + k]]); }, 16);
  }

  void apply(const Rule& r) {
    if constexpr (!CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
      // Rounded sums depend on their order, and the order of a rule's sources follows the
      // vertex numbering: the terms are added in increasing order of their values, so a
      // tile numbered otherwise computes the very bits of the whole set (two terms commute
      // in any case). Exact sums need no order.
      using VT = Value_traits<Value>;
      std::array<FT, std::size_t(VT::dimension)> sum;
      for (int k = 0; k < VT::dimension; ++k) {
        std::array<FT, 3> t;
        for (int i = 0; i < r.size(); ++i)
          t[std::size_t(i)] =
              r.weights[std::size_t(i)] * VT::coordinate(m_values[r.sources[std::size_t(i)]], k);
        if (r.size() == 2) {
          sum[std::size_t(k)] = t[0] + t[1];
          continue;
        }
        if (t[1] < t[0])
          std::swap(t[0], t[1]);
        if (t[2] < t[1])
          std::swap(t[1], t[2]);
        if (t[1] < t[0])
          std::swap(t[0], t[1]);
        sum[std::size_t(k)] = (t[0] + t[1]) + t[2];
      }
      m_values[r.target] = VT::from_coordinates(sum);
#ifdef __GMP_PLUSPLUS__
    } else if constexpr (std::is_same_v<Value, mpq_class>) {
      // Summed in per-thread scratch integers over the common denominator Lw Lv, Lw the
      // least common multiple of the weights' denominators (a rule's weights share their
      // frame's determinant) and Lv of the values' (data of one decimal scale share theirs),
      // then reduced once, by gcd(N, Lw) and gcd(N / that, Lv): together they are
      // gcd(N, Lw Lv), prime by prime, so the result is canonical, from gcds of operands
      // half the size. (mpq_mul and mpq_add reduce by gcds at each of their five steps;
      // one reduction of the sum over the product of the terms' denominators took 1.26 times
      // as long, on the rules of 10^5 17-digit points.)
      static thread_local mpz_class N, Lw, Lv, g, t;
      auto w = [&](int i) { return r.weights[std::size_t(i)].get_mpq_t(); };
      auto v = [&](int i) { return m_values[r.sources[std::size_t(i)]].get_mpq_t(); };
      const int n = r.size();
      // the largest denominator if it is a multiple of the others, else their lcm
      auto lcm_into = [&](mpz_class& L, auto denominator) {
        int big = 0;
        for (int i = 1; i < n; ++i)
          if (mpz_cmp(denominator(i), denominator(big)) > 0)
            big = i;
        mpz_set(L.get_mpz_t(), denominator(big));
        for (int i = 0; i < n; ++i)
          if (i != big && !mpz_divisible_p(L.get_mpz_t(), denominator(i))) {
            mpz_gcd(g.get_mpz_t(), L.get_mpz_t(), denominator(i));
            mpz_divexact(t.get_mpz_t(), denominator(i), g.get_mpz_t());
            mpz_mul(L.get_mpz_t(), L.get_mpz_t(), t.get_mpz_t());
          }
      };
      lcm_into(Lw, [&](int i) { return mpq_denref(w(i)); });
      lcm_into(Lv, [&](int i) { return mpq_denref(v(i)); });
      mpz_set_ui(N.get_mpz_t(), 0);
      for (int i = 0; i < n; ++i) {
        mpz_mul(t.get_mpz_t(), mpq_numref(w(i)), mpq_numref(v(i)));
        if (mpz_cmp(Lw.get_mpz_t(), mpq_denref(w(i))) != 0) {
          mpz_divexact(g.get_mpz_t(), Lw.get_mpz_t(), mpq_denref(w(i)));
          mpz_mul(t.get_mpz_t(), t.get_mpz_t(), g.get_mpz_t());
        }
        if (mpz_cmp(Lv.get_mpz_t(), mpq_denref(v(i))) != 0) {
          mpz_divexact(g.get_mpz_t(), Lv.get_mpz_t(), mpq_denref(v(i)));
          mpz_mul(t.get_mpz_t(), t.get_mpz_t(), g.get_mpz_t());
        }
        mpz_add(N.get_mpz_t(), N.get_mpz_t(), t.get_mpz_t());
      }
      const mpq_ptr target = m_values[r.target].get_mpq_t();
      if (mpz_sgn(N.get_mpz_t()) == 0) {
        mpq_set_ui(target, 0, 1);
        return;
      }
      for (mpz_class* L : {&Lw, &Lv}) {
        mpz_gcd(g.get_mpz_t(), N.get_mpz_t(), L->get_mpz_t());
        if (mpz_cmp_ui(g.get_mpz_t(), 1) != 0) {
          mpz_divexact(N.get_mpz_t(), N.get_mpz_t(), g.get_mpz_t());
          mpz_divexact(L->get_mpz_t(), L->get_mpz_t(), g.get_mpz_t());
        }
      }
      mpz_set(mpq_numref(target), N.get_mpz_t());
      mpz_mul(mpq_denref(target), Lw.get_mpz_t(), Lv.get_mpz_t());
#endif
    } else {
      Value v = r.weights[0] * m_values[r.sources[0]] + r.weights[1] * m_values[r.sources[1]];
      if (r.size() == 3)
        v = v + r.weights[2] * m_values[r.sources[2]];
      m_values[r.target] = std::move(v);
    }
  }

  std::array<FT, 3> barycentric(const Point_2& x, const Point_2& a, const Point_2& b,
                                const Point_2& c) const {
    return internal::barycentric_weights(x, a, b, c);
  }

  // Appends a rule to the plan. An `implicit` rule is one implicit_rule() rebuilds from its
  // target with the same sources and weights: in double only its target is kept.
  // `largest`: largest_abs(weights) if the caller computed it already (on all cores).
  // The weights are swapped into the stored rule: the caller's array is left with zeros.
  void add_rule(Slot target, std::array<Slot, 3> sources, std::array<FT, 3>&& weights,
                bool implicit = false, double largest = -1) {
    note_weight(target, largest >= 0 ? largest : largest_abs(weights));
    if constexpr (!CGAL::Algebraic_structure_traits<FT>::Is_exact::value) {
      if (implicit) {
#ifdef CGAL_TRIANGULAR_SPLINE_CHECK_IMPLICIT_RULES
        const Rule r = implicit_rule(target, true);
        if (r.target != target || r.sources != sources || r.weights != weights)
          throw std::logic_error("implicit rule of slot " + std::to_string(target) +
                                 " differs from the plan's");
#endif
        m_rule_refs.push_back(target);
        return;
      }
    }
    CGAL_USE(implicit);
    m_rule_refs.push_back(explicit_rule_bit | static_cast<std::uint32_t>(m_explicit_rules.size()));
    // the weights swapped in: moving an exact rule in allocates six fractions anew
    Rule& rule = m_explicit_rules.emplace_back();
    rule.target = target;
    rule.sources = sources;
    using std::swap;
    for (std::size_t i = 0; i < 3; ++i)
      swap(rule.weights[i], weights[i]);
  }
  void add_rule(Slot target, std::array<Slot, 3> sources, const std::array<FT, 3>& weights) {
    std::array<FT, 3> copy = weights;
    add_rule(target, sources, std::move(copy));
  }
  void note_weight(Slot target, double largest) {
    const std::size_t k = std::size_t(kind(target));
    m_max_weight = (std::max)(m_max_weight, largest);
    m_max_weight_by_kind[k] = (std::max)(m_max_weight_by_kind[k], largest);
    m_above_bound_by_kind[k] += largest > propagation_weight_bound ? 1 : 0;
  }

  // Plans that store their rules make a step's rules on all cores, group by group
  // (Parallel_vector::append_groups(), `first` the groups' offsets): exact plans in
  // m_explicit_rules, where every rule is stored, and double plans that check their implicit
  // rules in `scratch`, from where list_made_rule() passes them to add_rule(). Returns the
  // index of the step's first rule. The listing then runs in plan order, as before.
  static constexpr bool exact_plan = CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  template <class Make>
  std::size_t make_rules(internal::Parallel_vector<Rule>& scratch,
                         const std::vector<std::size_t>& first, const Make& make) {
    internal::Parallel_vector<Rule>& into = exact_plan ? m_explicit_rules : scratch;
    if constexpr (!exact_plan)
      scratch.clear();
    const std::size_t base = into.size();
    into.append_groups(first, internal::thread_count(first.back(), 1000), make);
    return base;
  }
  void list_made_rule(internal::Parallel_vector<Rule>& scratch, std::size_t index, bool implicit,
                      double largest) {
    if constexpr (exact_plan) {
      CGAL_USE(implicit);
      note_weight(m_explicit_rules[index].target, largest);
      m_rule_refs.push_back(explicit_rule_bit | static_cast<std::uint32_t>(index));
    } else {
      Rule& r = scratch[index];
      add_rule(r.target, r.sources, std::move(r.weights), implicit, largest);
    }
  }

  // Double plans keep their regular rules implicit, so build_plan_once() computes those
  // rules' weights only for the statistics (largest weight by role, count above the bound),
  // and the frame choices and flip decisions they follow from: per vertex and per edge on
  // all cores, before listing the rules in order. Exact plans store every rule with its
  // weights and list them serially, as do builds that check each implicit rule.
#ifdef CGAL_TRIANGULAR_SPLINE_CHECK_IMPLICIT_RULES
  static constexpr bool parallel_plan = false;
#else
  static constexpr bool parallel_plan = !CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
#endif
  // The statistics add_rule() keeps, gathered per block of parallel_for_index() (a block
  // runs on one thread) and merged in any order: maxima and counts.
  struct Weight_statistics {
    double largest = 0;
    std::array<double, 6> by_kind{};
    std::array<std::size_t, 6> above{};
  };
  void count_weight(Weight_statistics& w, Slot target, double largest) const {
    const std::size_t k = std::size_t(kind(target));
    w.largest = (std::max)(w.largest, largest);
    w.by_kind[k] = (std::max)(w.by_kind[k], largest);
    w.above[k] += largest > propagation_weight_bound ? 1 : 0;
  }
  static void add_weights(Weight_statistics& into, const std::vector<Weight_statistics>& blocks) {
    for (const Weight_statistics& w : blocks) {
      into.largest = (std::max)(into.largest, w.largest);
      for (std::size_t k = 0; k < 6; ++k) {
        into.by_kind[k] = (std::max)(into.by_kind[k], w.by_kind[k]);
        into.above[k] += w.above[k];
      }
    }
  }
  void merge_weights(const std::vector<Weight_statistics>& blocks) {
    Weight_statistics total{m_max_weight, m_max_weight_by_kind, m_above_bound_by_kind};
    add_weights(total, blocks);
    m_max_weight = total.largest;
    m_max_weight_by_kind = total.by_kind;
    m_above_bound_by_kind = total.above;
  }
  // Runs f(i, statistics of i's block) for i in [0, n) on all cores, then merges the
  // statistics.
  template <class F>
  void parallel_with_weights(std::size_t n, const F& f) {
    std::vector<Weight_statistics> blocks((n + internal::parallel_block - 1) /
                                          internal::parallel_block);
    internal::parallel_for_index(n, internal::thread_count(n, 20000), [&](std::size_t i) {
      f(i, blocks[i / internal::parallel_block]);
    });
    merge_weights(blocks);
  }

  // Sets x[s] (one entry per slot) to an independent sign at the free slots outside the
  // corner regions, to zero elsewhere; returns whether any slot has a sign. A sign is a bit
  // of a hash of s, which any core computes: the first touch of x (100 MB at 10^6 points)
  // and a serial random sequence had taken 0.25 s on one core.
  template <class Number>
  bool amplification_signs(Number* x) const {
    const std::size_t n = m_free.size();
    constexpr std::size_t block = std::size_t(1) << 16;
    std::atomic<bool> any{false};
    auto fill = [&](std::size_t b) {
      bool signs = false;
      for (std::size_t s = b * block; s < (std::min)(n, (b + 1) * block); ++s) {
        const Slot_kind k = kind(Slot(s));
        const bool sign = m_free[s] && k != Slot_kind::CORNER && k != Slot_kind::STAR;
        x[s] = sign ? (positive_sign(s) ? Number(1) : Number(-1)) : Number(0);
        signs = signs || sign;
      }
      if (signs)
        any.store(true, std::memory_order_relaxed);
    };
    internal::parallel_for_index((n + block - 1) / block, internal::thread_count(n, 1000000), fill,
                                 1);
    return any.load();
  }
  // the top bit of splitmix64's finaliser of s
  static bool positive_sign(std::size_t s) {
    std::uint64_t z = std::uint64_t(s) + 0x9e3779b97f4a7c15u;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return ((z ^ (z >> 31)) >> 63) != 0;
  }
  template <class Number>
  static void amplification_step(const Rule& r, Number* x, double& largest) {
    double v = 0;
    for (int i = 0; i < r.size(); ++i)
      v += CGAL::to_double(r.weights[std::size_t(i)]) * x[r.sources[std::size_t(i)]];
    x[r.target] = static_cast<Number>(v);
    largest = (std::max)(largest, std::abs(v));
  }
  // propagation_amplification() with x (one entry per slot, any content) as the values. A
  // free slot keeps its sign (no rule targets it): they count as 1 in the largest value.
  template <class Number>
  double amplification_in(Number* x) const {
    double largest = amplification_signs(x) ? 1.0 : 0.0;
    // Stored rules (exact plans: every rule) depth by depth on all cores: converting their
    // weights to double is most of the work. Each rule computes what it would in plan order,
    // and the largest is a maximum.
    std::vector<std::size_t> start;
    std::vector<std::uint32_t> order;
    const std::size_t threads = internal::thread_count(m_rule_refs.size(), 20000);
    if (threads > 1 && m_explicit_rules.size() == m_rule_refs.size() &&
        rules_by_depth(start, order)) {
      constexpr std::size_t block = 1024;
      std::vector<double> block_largest;
      for (std::size_t d = 1; d + 1 < start.size(); ++d) {
        const std::size_t first = start[d], count = start[d + 1] - first;
        block_largest.assign((count + block - 1) / block, 0.0);
        internal::parallel_for_index(
            block_largest.size(), threads,
            [&](std::size_t b) {
              for (std::size_t k = b * block; k < (std::min)(count, (b + 1) * block); ++k)
                amplification_step(
                    m_explicit_rules[m_rule_refs[order[first + k]] & ~explicit_rule_bit], x,
                    block_largest[b]);
            },
            1);
        for (double m : block_largest)
          largest = (std::max)(largest, m);
      }
      return largest;
    }
    for_each_rule_in_runs(
        [&](const Rule& r, double& block_largest) { amplification_step(r, x, block_largest); },
        largest);
    return largest;
  }

  // Calls f(rule, block_max) for every rule, in evaluation order except that the implicit
  // rules of one kind in a row run on all cores: they never read each other's targets
  // (corner rules read their frame, edge-middle rules corner-inner and star points, flip
  // rules a free flip and edge-middle points), so each computes what it would in plan order.
  // f may raise block_max; `largest` ends as the largest of them all (a maximum, whatever
  // the blocks).
  template <class F>
  void for_each_rule_in_runs(const F& f, double& largest) const {
    const std::size_t R = m_rule_refs.size();
    constexpr std::size_t block = 4096;
    std::vector<double> block_largest;
    for (std::size_t begin = 0; begin < R;) {
      const std::uint32_t first = m_rule_refs[begin];
      if (first & explicit_rule_bit) {
        f(m_explicit_rules[first & ~explicit_rule_bit], largest);
        ++begin;
        continue;
      }
      const int group = implicit_group(first);
      std::size_t end = begin + 1;
      while (end < R && !(m_rule_refs[end] & explicit_rule_bit) &&
             implicit_group(m_rule_refs[end]) == group)
        ++end;
      const std::size_t blocks = (end - begin + block - 1) / block;
      block_largest.assign(blocks, 0.0);
      internal::parallel_for_index(
          blocks, internal::thread_count(end - begin, 20000),
          [&](std::size_t b) {
            const std::size_t last = (std::min)(end, begin + (b + 1) * block);
            for (std::size_t i = begin + b * block; i < last; ++i)
              f(implicit_rule(m_rule_refs[i], true), block_largest[b]);
          },
          1);
      for (const double m : block_largest)
        largest = (std::max)(largest, m);
      begin = end;
    }
  }

  // The rule a reference stands for; without `weights` only its target and sources (the
  // weights are then zero).
  Rule rule_of_ref(std::uint32_t ref, bool weights) const {
    if (ref & explicit_rule_bit)
      return m_explicit_rules[ref & ~explicit_rule_bit];
    return implicit_rule(ref, weights);
  }
  // f(rule) without copying a stored rule (an exact one's weights are fractions)
  template <class F>
  void with_rule(std::uint32_t ref, bool weights, const F& f) const {
    if (ref & explicit_rule_bit)
      f(m_explicit_rules[ref & ~explicit_rule_bit]);
    else
      f(implicit_rule(ref, weights));
  }
  void apply_ref(std::uint32_t ref) {
    if (ref & explicit_rule_bit)
      apply(m_explicit_rules[ref & ~explicit_rule_bit]);
    else
      apply(implicit_rule(ref, true));
  }
  // 0: corner region (corner or star target), 1: edge-middle point, 2: flip point.
  int implicit_group(Slot target) const {
    const std::size_t V = m_domain.number_of_vertices(), E = m_domain.number_of_edges();
    if (target < V)
      return 0;
    if (target < V + 4 * E) {
      const std::size_t t = (target - V) % 4;
      return (t == 0 || t == 3) ? 0 : 1;
    }
    return 2;
  }

  // The rule of `target` as build_plan_once() made it when it kept it implicit:
  // - a corner or star point from the three free points of its vertex's corner region, in
  //   the order choose_frame() gave them (m_frame_order), weights the barycentric
  //   coordinates of its region point (the vertex, or the star's neighbour) in theirs;
  // - the edge-middle point next to a regular end r of an interior edge (r, s) from
  //   (CI_left, star_r, CI_right), weights those of s in (p_left, r, p_right);
  // - the flip point of a face from the edge's free flip point and its two edge-middle
  //   points, weights those of its apex in (the other apex, lo, hi).
  Rule implicit_rule(Slot target, bool weights) const {
    const std::size_t V = m_domain.number_of_vertices(), E = m_domain.number_of_edges();
    Rule r{target, {{null_slot, null_slot, null_slot}}, {{FT(0), FT(0), FT(0)}}};
    if (target < V + 4 * E) {
      const std::size_t t = target < V ? 0 : (target - V) % 4;
      if (target < V || t == 0 || t == 3) {
        Index v;
        const Point_2* x;
        if (target < V) {
          v = static_cast<Index>(target);
          x = &m_domain.point(v);
        } else {
          const auto& ends = m_domain.edge(static_cast<Index>((target - V) / 4));
          v = ends[t == 0 ? 0 : 1];
          x = &m_domain.point(ends[t == 0 ? 1 : 0]);
        }
        const auto [nb, ne] = m_domain.neighbours(v);
        const auto [eb, ee] = m_domain.star_edges(v);
        CGAL_USE(ne);
        std::array<Slot, 3> slot;
        std::array<const Point_2*, 3> point;
        std::size_t found = 0;
        if (m_free[vertex_slot(v)]) {
          slot[0] = vertex_slot(v);
          point[0] = &m_domain.point(v);
          found = 1;
        }
        for (auto e = eb; found < 3 && e != ee; ++e) {
          const Slot s = star_slot(*e, v);
          if (m_free[s]) {
            slot[found] = s;
            point[found] = &m_domain.point(nb[e - eb]);
            ++found;
          }
        }
        CGAL_assertion(found == 3);
        const auto& p = frame_permutations[m_frame_order[v]];
        r.sources = {{slot[p[0]], slot[p[1]], slot[p[2]]}};
        if (weights)
          r.weights = barycentric(*x, *point[p[0]], *point[p[1]], *point[p[2]]);
        return r;
      }
      const Index e = static_cast<Index>((target - V) / 4);
      const auto& ends = m_domain.edge(e);
      const Index near = ends[t == 1 ? 0 : 1], far = ends[t == 1 ? 1 : 0];
      const auto& ef = m_domain.edge_faces(e);
      r.sources = {
          {corner_inner_slot(ef[0], near), star_slot(e, near), corner_inner_slot(ef[1], near)}};
      if (weights)
        r.weights =
            barycentric(m_domain.point(far), m_domain.point(m_domain.opposite_vertex(ef[0], e)),
                        m_domain.point(near), m_domain.point(m_domain.opposite_vertex(ef[1], e)));
      return r;
    }
    const std::size_t position = (target - V - 4 * E) % 6;
    CGAL_assertion(position >= 3);
    const Index f = static_cast<Index>((target - V - 4 * E) / 6);
    const Index e = m_domain.face_edge(f, int(position) - 3);
    const auto& ef = m_domain.edge_faces(e);
    const Index other = ef[0] == f ? ef[1] : ef[0];
    const auto& ends = m_domain.edge(e);
    r.sources = {{flip_slot(other, e), edge_middle_slot(e, ends[0]), edge_middle_slot(e, ends[1])}};
    if (weights)
      r.weights = barycentric(m_domain.point(m_domain.opposite_vertex(f, e)),
                              m_domain.point(m_domain.opposite_vertex(other, e)),
                              m_domain.point(ends[0]), m_domain.point(ends[1]));
    return r;
  }
  // The orders of a frame's three positions (increasing in the region) that choose_frame()
  // can give.
  static constexpr std::array<std::array<std::size_t, 3>, 6> frame_permutations = {
      {{{0, 1, 2}}, {{0, 2, 1}}, {{1, 0, 2}}, {{1, 2, 0}}, {{2, 0, 1}}, {{2, 1, 0}}}};
  static std::uint8_t frame_order_code(const std::array<std::size_t, 3>& frame) {
    std::array<std::size_t, 3> sorted = frame;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint8_t c = 0; c < 6; ++c) {
      const auto& p = frame_permutations[c];
      if (sorted[p[0]] == frame[0] && sorted[p[1]] == frame[1] && sorted[p[2]] == frame[2])
        return c;
    }
    CGAL_error_msg("a frame repeats a position");
    return 0;
  }

  // The star slot of vertex v on edge e (v must be an end of e).
  Slot star_slot(Index e, Index v) const {
    return m_domain.edge(e)[0] == v ? edge_slot(e, 0) : edge_slot(e, 3);
  }
  Slot edge_middle_slot(Index e, Index near) const {
    return m_domain.edge(e)[0] == near ? edge_slot(e, 1) : edge_slot(e, 2);
  }
  int position_in_face(Index f, Index v) const {
    const auto& t = m_domain.face(f);
    return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
  }
  Slot corner_inner_slot(Index f, Index v) const {
    return face_slot(f, position_in_face(f, v));
  }
  Slot flip_slot(Index f, Index e) const {
    for (int i = 0; i < 3; ++i)
      if (m_domain.face_edge(f, i) == e)
        return face_slot(f, 3 + i);
    return null_slot;
  }

  // The three prescribed points of v's corner region, as positions in the region list
  // (0 = the corner, 1 + i = the star towards neighbour i). Exact non-collinearity is
  // required; among valid frames, well-shaped ones are preferred: the propagated points are
  // extrapolated from the frame, and a thin frame amplifies data noise and round-off.
  std::array<std::size_t, 3> choose_frame(Index v) const {
    const auto [nb, ne] = m_domain.neighbours(v);
    const std::size_t d = static_cast<std::size_t>(ne - nb);
    auto vertex_of = [&](std::size_t k) { return k == 0 ? v : nb[k - 1]; };
    auto point_of = [&](std::size_t k) -> const Point_2& { return m_domain.point(vertex_of(k)); };
    // Orientation, not collinear_2: the same exact test, statically filtered by Epick (by
    // intervals around the domain's coordinates for GMP rationals).
    auto collinear = [&](std::size_t i, std::size_t j, std::size_t k) {
      return m_domain.orientation(vertex_of(i), vertex_of(j), vertex_of(k)) == CGAL::COLLINEAR;
    };
    // to_double(point j - point i) of two region points, i != j. The frames tried share
    // their sides: each pair's difference is computed once (an exact subtraction reduces
    // by gcds; internal::to_double_of_difference() skips them), the reverse pair's negated,
    // which is its very bits: truncation and rounding to nearest are odd. (A double
    // subtraction is cheaper than the cache.)
    const std::size_t cached =
        CGAL::Algebraic_structure_traits<FT>::Is_exact::value && d + 1 <= 24 ? d + 1 : 0;
    boost::container::small_vector<std::array<double, 2>, 66> differences(
        cached * (cached - 1) / 2, {{std::numeric_limits<double>::quiet_NaN(), 0.0}});
    auto difference = [&](std::size_t i, std::size_t j) {
      const std::size_t lo = (std::min)(i, j), hi = (std::max)(i, j);
      auto compute = [&] {
        const Point_2 &a = point_of(lo), &b = point_of(hi);
        return std::array<double, 2>{{internal::to_double_of_difference(b.x(), a.x()),
                                      internal::to_double_of_difference(b.y(), a.y())}};
      };
      std::array<double, 2> u;
      if (hi < cached) {
        std::array<double, 2>& known = differences[hi * (hi - 1) / 2 + lo];
        if (std::isnan(known[0]))
          known = compute();
        u = known;
      } else {
        u = compute();
      }
      return i < j ? u : std::array<double, 2>{{-u[0], -u[1]}};
    };
    // Smallest |sine| of the three angles of the frame triangle (0 if exactly collinear).
    auto quality = [&](const std::array<std::size_t, 3>& f) {
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || collinear(f[0], f[1], f[2]))
        return 0.0;
      double worst = 1;
      for (int i = 0; i < 3; ++i) {
        const std::size_t a = f[std::size_t(i)], b = f[std::size_t((i + 1) % 3)],
                          c = f[std::size_t((i + 2) % 3)];
        const auto [ux, uy] = difference(a, b);
        const auto [wx, wy] = difference(a, c);
        const double sine =
            std::abs(ux * wy - uy * wx) / (internal::length_2(ux, uy) * internal::length_2(wx, wy));
        worst = (std::min)(worst, sine);
      }
      // Exactly non-collinear but degenerate in double: still valid, ranked last.
      return (std::max)(worst, 1e-300);
    };
    if (d == 2) // an ear: the whole region is free
      return {{0, 1, 2}};
    // The searches below take the first of equally good frames (and sample the pairs of
    // vertices of degree above 16), so around an interior vertex they start at the
    // neighbour with the lexicographically smallest point, not where the numbering starts
    // the rotation. A boundary vertex's rotation starts on the boundary.
    std::size_t first = 0;
    if (!m_domain.is_boundary_vertex(v))
      for (std::size_t k = 1; k < d; ++k) {
        const Point_2 &p = m_domain.point(nb[k]), &q = m_domain.point(nb[first]);
        if (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()))
          first = k;
      }
    auto at = [&](std::size_t t) { return 1 + (first + t - 1) % d; }; // t = 1..d
    // Good enough for a symmetric frame: no angle below about 6 degrees.
    const double acceptable = 0.1;
    std::array<std::size_t, 3> best{{0, 0, 0}};
    double best_quality = 0;
    auto consider = [&](const std::array<std::size_t, 3>& f) {
      const double q = quality(f);
      if (q > best_quality) {
        best_quality = q;
        best = f;
      }
      return q;
    };
    if (m_frame == Corner_frame::SYMMETRIC_STARS) {
      const bool boundary = m_domain.is_boundary_vertex(v);
      // Stars spread evenly: interior i, i+d/3, i+2d/3; boundary both ends and a middle one.
      // The best-shaped of them (the first acceptable one depended on where the rotation
      // starts).
      const std::size_t shifts = boundary ? d - 2 : d;
      for (std::size_t shift = 0; shift < shifts; ++shift) {
        const std::array<std::size_t, 3> f =
            boundary ? std::array<std::size_t, 3>{{1, 1 + ((d - 1) / 2 + shift) % (d - 2) + 1, d}}
                     : std::array<std::size_t, 3>{{at(1 + shift), at(1 + (shift + (d + 1) / 3) % d),
                                                   at(1 + (shift + (2 * d + 1) / 3) % d)}};
        consider(f);
      }
      if (best_quality >= acceptable)
        return best;
      // No good symmetric frame: the best triple of stars, if any is acceptable.
      for (std::size_t i = 1; i <= d && d <= 16; ++i)
        for (std::size_t j = i + 1; j <= d; ++j)
          for (std::size_t k = j + 1; k <= d; ++k)
            consider({{at(i), at(j), at(k)}});
      if (best_quality >= acceptable)
        return best;
    }
    // The corner and two stars: the pair that extrapolates least, i.e. whose largest
    // barycentric weight over the region is smallest (the propagation weights of the
    // corner region); a face always gives a valid pair.
    // on the stack for all but rare high-degree vertices (one allocation per vertex before)
    boost::container::small_vector<std::array<double, 2>, 24> offsets(d + 1);
    const double vx = CGAL::to_double(point_of(0).x()), vy = CGAL::to_double(point_of(0).y());
    for (std::size_t k = 1; k <= d; ++k)
      offsets[k] = {{CGAL::to_double(point_of(k).x()) - vx, CGAL::to_double(point_of(k).y()) - vy}};
    double best_cost = std::numeric_limits<double>::infinity();
    auto consider_pair = [&](std::size_t i, std::size_t j) {
      if (collinear(0, i, j))
        return;
      // Weights of w in (v, w_i, w_j): solve [a b] (mu, nu) = w - v.
      const auto &a = offsets[i], &b = offsets[j];
      const double det = a[0] * b[1] - a[1] * b[0];
      double cost = 1;
      for (std::size_t k = 1; k <= d && cost < best_cost; ++k) {
        const double mu = (offsets[k][0] * b[1] - offsets[k][1] * b[0]) / det;
        const double nu = (a[0] * offsets[k][1] - a[1] * offsets[k][0]) / det;
        cost = (std::max)({cost, std::abs(mu), std::abs(nu), std::abs(1 - mu - nu)});
      }
      if (!(cost >= best_cost)) { // NaN (det rounded to 0) never wins
        best_cost = cost;
        best = {{0, i, j}};
      }
    };
    const std::size_t stride = d <= 16 ? 1 : d / 16;
    for (std::size_t i = 1; i < d; ++i) // consecutive neighbours span a face: always valid
      consider_pair(at(i), at(i + 1));
    for (std::size_t i = 1; i <= d; i += stride)
      for (std::size_t j = i + 2; j <= d; ++j)
        consider_pair(at(i), at(j));
    if (!std::isfinite(best_cost)) // every cost NaN in double: the best-shaped pair
      for (std::size_t i = 1; i < d; ++i)
        consider({{0, at(i), at(i + 1)}});
    CGAL_assertion(best[1] != best[2]);
    return best;
  }

  // How the edge-middle point next to end `vertex` of an interior edge is computed.
  // A link of step 2 as emitted: position i (between star faces i-1 and i), and which of its
  // two corner-inner points it was solved for.
  struct Emitted_link {
    std::size_t position;
    bool solve_before;
  };

  enum class End_route : unsigned char {
    REGULAR,    // from the corner diamond at the end (the usual rule)
    DEGENERATE, // apexes exactly collinear with the end (or up to rounding in double)
    THIN        // not collinear, but the regular rule's weights exceed the bound
  };
  struct Edge_route {
    Index end = Domain::null_index; // the re-routed end, or null_index
    End_route kind = End_route::REGULAR;
    double regular_weight = 0; // largest |weight| the regular rule at `end` would have
    std::array<FT, 3> mu;      // end = mu0 apex_left + mu1 other end + mu2 apex_right
  };

  static double largest_abs(const std::array<FT, 3>& w) {
    double m = 0;
    for (const FT& x : w)
      m = (std::max)(m, std::abs(CGAL::to_double(x)));
    return m;
  }

  // Step 5 of build_plan_once() by edge: which flip point is free (1 the left one, 2 the
  // right one, 0 not chosen here), the other's rule weights and their largest_abs().
  struct Flip_choices {
    std::vector<unsigned char> free_flip;
    std::vector<std::optional<std::array<FT, 3>>> weights;
    std::vector<double> largest;
  };

#if defined(__GMP_PLUSPLUS__) && defined(__SIZEOF_INT128__)
  // Step 5's choice for edge e from the quad of its apexes and ends (0 = left apex, 1 =
  // right apex, 2 and 3 the ends): the rule with the smaller largest weight, as
  // build_plan_once() chooses it from both rules' exact weights. Only the chosen rule's
  // weights are made: the double quotients of the determinants decide unless the two
  // largest weights are within 1e-12 of each other (their error is below 1e-15), and then
  // both rules' exact weights do.
  static void choose_flip(internal::Barycentric_quad& quad, std::size_t e, Flip_choices& flips) {
    const double right_approximate = quad.approximate_largest(1, 0, 2, 3),
                 left_approximate = quad.approximate_largest(0, 1, 2, 3);
    bool left_free;
    std::optional<std::array<FT, 3>> chosen;
    if (std::abs(right_approximate - left_approximate) >
        1e-12 * (std::max)(right_approximate, left_approximate)) {
      left_free = !(left_approximate < right_approximate);
      chosen = left_free ? quad.weights(1, 0, 2, 3) : quad.weights(0, 1, 2, 3);
    } else {
      std::optional<std::array<FT, 3>> right_from_left = quad.weights(1, 0, 2, 3),
                                       left_from_right = quad.weights(0, 1, 2, 3);
      if (!right_from_left || !left_from_right)
        return;
      left_free = !(largest_abs(*left_from_right) < largest_abs(*right_from_left));
      chosen = std::move(left_free ? right_from_left : left_from_right);
    }
    if (!chosen)
      return;
    flips.largest[e] = largest_abs(*chosen);
    flips.weights[e] = std::move(*chosen);
    flips.free_flip[e] = left_free ? 1 : 2;
  }
#endif

  // Chooses, per interior edge, the end (if any) whose edge-middle point is re-routed
  // through the middle diamond: exactly degenerate ends (and, in double, ends collinear up
  // to rounding) always; otherwise the end whose regular weights exceed
  // `propagation_weight_bound`, the larger one if both do. `allow_thin[e] == 0` forbids
  // re-routing a thin frame of edge e (used to break the rare dependency cycles).
  // `middle` (plans that store their rules): the regular rule's weights of both ends of
  // every interior edge, index 2e + side, where computed (not at exactly degenerate ends);
  // step 3 of build_plan_once() takes them instead of computing them again.
  // `flips` (with `middle`): step 5's choice of flip rule and its weights, by edge, where
  // computed with the edge-middle weights (internal::Barycentric_quad: GMP rationals that
  // fit in 128-bit determinants).
  std::vector<Edge_route>
  route_edges(const std::vector<char>& allow_thin,
              std::vector<std::optional<std::array<FT, 3>>>* middle = nullptr,
              std::vector<double>* middle_largest = nullptr, Flip_choices* flips = nullptr) const {
    const Index E = static_cast<Index>(m_domain.number_of_edges());
    std::vector<Edge_route> routes(E);
    if (middle) {
      middle->assign(2 * std::size_t(E), std::nullopt);
      middle_largest->assign(2 * std::size_t(E), -1.0);
    }
    if (flips) {
      flips->free_flip.assign(E, 0);
      flips->weights.assign(E, std::nullopt);
      flips->largest.assign(E, -1.0);
    }
    std::vector<char> exact_end(2 * std::size_t(E), 0), numerical_end(2 * std::size_t(E), 0);
    for (const auto& d : m_degenerate.frames) {
      const int side = m_domain.edge(d.edge)[0] == d.vertex ? 0 : 1;
      (d.numerical ? numerical_end : exact_end)[2 * std::size_t(d.edge) + std::size_t(side)] = 1;
    }
    // (each edge's route on its own, on all cores)
    internal::parallel_for_index(
        E, internal::thread_count(E, parallel_plan ? 20000 : 1000), [&](std::size_t i) {
          const Index e = static_cast<Index>(i);
          if (m_domain.is_boundary_edge(e))
            return;
          const auto& ends = m_domain.edge(e);
          const auto& ef = m_domain.edge_faces(e);
          const Point_2& pl = m_domain.point(m_domain.opposite_vertex(ef[0], e));
          const Point_2& pr = m_domain.point(m_domain.opposite_vertex(ef[1], e));
#if defined(__GMP_PLUSPLUS__) && defined(__SIZEOF_INT128__)
          // the four points 0 = pl, 1 = pr, 2 = ends[0], 3 = ends[1] (Barycentric_quad)
          [[maybe_unused]] std::optional<internal::Barycentric_quad> quad;
          if constexpr (std::is_same_v<FT, mpq_class>)
            if (flips) {
              const Point_2 &lo = m_domain.point(ends[0]), &hi = m_domain.point(ends[1]);
              quad = internal::Barycentric_quad::make(
                  {{&pl.x(), &pl.y(), &pr.x(), &pr.y(), &lo.x(), &lo.y(), &hi.x(), &hi.y()}});
              if (quad)
                choose_flip(*quad, i, *flips);
            }
#endif
          std::array<double, 2> weight{{0, 0}};
          for (int side = 0; side < 2; ++side) {
            const std::size_t k = 2 * std::size_t(e) + std::size_t(side);
            const Point_2& r = m_domain.point(ends[std::size_t(side)]);
            const Point_2& other = m_domain.point(ends[std::size_t(1 - side)]);
            if (exact_end[k]) {
              weight[std::size_t(side)] = std::numeric_limits<double>::infinity();
            } else {
              std::array<FT, 3> w;
              bool computed = false;
#if defined(__GMP_PLUSPLUS__) && defined(__SIZEOF_INT128__)
              if constexpr (std::is_same_v<FT, mpq_class>)
                if (quad)
                  if (auto q = side == 0 ? quad->weights(3, 0, 2, 1) : quad->weights(2, 0, 3, 1)) {
                    w = std::move(*q);
                    computed = true;
                  }
#endif
              if (!computed)
                w = barycentric(other, pl, r, pr);
              weight[std::size_t(side)] = largest_abs(w);
              if (middle) {
                (*middle)[k] = std::move(w);
                (*middle_largest)[k] = weight[std::size_t(side)];
              }
            }
            if (numerical_end[k]) // ranked after exact ends, before every thin one
              weight[std::size_t(side)] = (std::numeric_limits<double>::max)();
          }
          const int side = weight[1] > weight[0] ? 1 : 0;
          const std::size_t k = 2 * std::size_t(e) + std::size_t(side);
          const Index r = ends[std::size_t(side)];
          Edge_route route;
          if (exact_end[k] || numerical_end[k])
            route.kind = End_route::DEGENERATE;
          else if (weight[std::size_t(side)] > propagation_weight_bound && allow_thin[e])
            route.kind = End_route::THIN;
          else
            return;
          route.end = r;
          route.regular_weight = weight[std::size_t(side)];
          route.mu =
              barycentric(m_domain.point(r), pl, m_domain.point(ends[std::size_t(1 - side)]), pr);
          routes[e] = route;
        });
    return routes;
  }

  void count_control_slots() {
    const std::size_t V = m_domain.number_of_vertices(), E = m_domain.number_of_edges(),
                      F = m_domain.number_of_faces();
    // A rule is kept as one 32-bit reference whose top bit tells stored from implicit.
    if (V + 4 * E + 6 * F >= explicit_rule_bit)
      throw Invalid_input("spline: domain too large: more than 2^31 control points (about "
                          "1.7e8 vertices)");
    m_control_slots = V + 4 * E + 6 * F;
  }

  void build_plan() {
    m_degenerate = find_degenerate_frames(m_domain);
    std::vector<char> allow_thin(m_domain.number_of_edges(), 1);
    // A thin re-routing makes corner-inner points depend on an edge-middle point of the
    // other end; chains of such ends could close a cycle. Then the least thin re-routing on
    // each cycle is dropped and the plan rebuilt (exact degenerate ones never depend on edge
    // points, so this ends).
    // The corner regions' frames do not depend on the re-routings: chosen once for all
    // rounds (in double, where they are chosen apart from the rules; both sets of 10^6
    // points measured needed a second round).
    std::vector<std::array<std::uint32_t, 3>> frames;
    Weight_statistics corner_weights;
    choose_frames(frames, parallel_plan ? &corner_weights : nullptr);
    for (;;) {
      ++m_plan_rounds;
      m_rule_refs.clear();
      m_explicit_rules.clear();
      m_max_weight = 0;
      m_max_weight_by_kind.fill(0);
      m_above_bound_by_kind.fill(0);
      // Auxiliary slots are made anew by each round, counted by m_free; the values are
      // allocated once the count is known (growing them by the auxiliary slots reallocated
      // and copied all control values: 200 MB at 10^6 points).
      m_free.assign(m_control_slots, 0);
      std::vector<Index> thin_edge_of_rule;
      merge_weights({corner_weights});
      build_plan_once(frames, allow_thin, thin_edge_of_rule);
      if (order_rules(thin_edge_of_rule, allow_thin))
        break;
    }
    internal::release(frames);
    if (m_free.size() >= explicit_rule_bit)
      throw Invalid_input("spline: domain too large: more than 2^31 slots");
    // Appended to (auxiliary slots, stored rules, re-routed frames): a doubled capacity
    // would last as long as the spline (100 MB at 10^6 points).
    m_free.shrink_to_fit();
    m_rule_refs.shrink_to_fit();
    // (An exact plan's stored rules were reserved nearly right and the rest never touched:
    // shrinking would copy every rule.)
    if (m_explicit_rules.capacity() - m_explicit_rules.size() > m_explicit_rules.size() / 8)
      m_explicit_rules.shrink_to_fit();
    m_frames.shrink_to_fit();
    bool assigned = false;
#ifdef __GMP_PLUSPLUS__
    if constexpr (std::is_same_v<Value, mpq_class>) {
      // A default fraction is zero and allocates only its denominator: half the time of
      // 2.5 million copies of a zero (10^5 points).
      m_values.clear();
      m_values.resize(m_free.size());
      assigned = true;
    }
#endif
    if (!assigned)
      m_values.assign(m_free.size(), zero());
    m_amplification.reset(); // (the first propagate() of doubles computes it)
    m_number_of_free = m_free.size() - std::size_t(std::count(m_free.begin(), m_free.end(), 0));
  }

  Slot region_slot(Index v, std::size_t k) const {
    return k == 0 ? vertex_slot(v) : star_slot(m_domain.star_edges(v).first[k - 1], v);
  }
  const Point_2& region_point(Index v, std::size_t k) const {
    return k == 0 ? m_domain.point(v) : m_domain.point(m_domain.neighbours(v).first[k - 1]);
  }

  // The frame of every corner region (choose_frame()) on all cores, and in `weights` (if
  // given: plans whose rules stay implicit) the statistics of the corner regions' rules.
  void choose_frames(std::vector<std::array<std::uint32_t, 3>>& frames,
                     Weight_statistics* weights) {
    const std::size_t V = m_domain.number_of_vertices();
    frames.resize(V);
    std::vector<Weight_statistics> blocks((V + internal::parallel_block - 1) /
                                          internal::parallel_block);
    internal::parallel_for_index(
        V, internal::thread_count(V, weights ? 20000 : 1000), [&](std::size_t i) {
          Weight_statistics& w = blocks[i / internal::parallel_block];
          const Index v = static_cast<Index>(i);
          const std::array<std::size_t, 3> frame = choose_frame(v);
          frames[i] = {{std::uint32_t(frame[0]), std::uint32_t(frame[1]), std::uint32_t(frame[2])}};
          if (!weights)
            return;
          const Point_2 &a = region_point(v, frame[0]), &b = region_point(v, frame[1]),
                        &c = region_point(v, frame[2]);
          const std::size_t size = 1 + m_domain.degree(v);
          for (std::size_t k = 0; k < size; ++k)
            if (k != frame[0] && k != frame[1] && k != frame[2])
              count_weight(w, region_slot(v, k),
                           largest_abs(barycentric(region_point(v, k), a, b, c)));
        });
    if (weights) {
      *weights = {};
      add_weights(*weights, blocks);
    }
  }

  // Destroys the engaged values on all cores, then frees the vector: destroying the exact
  // plan's millions of weights (GMP limbs) one by one was a serial step.
  template <class T>
  static void release_in_parallel(std::vector<std::optional<T>>& v) {
    internal::parallel_for_index(
        v.size(), internal::thread_count(v.size(), 1000), [&](std::size_t i) { v[i].reset(); },
        256);
    internal::release(v);
  }

  // A link of step 2 of build_plan_once(): at a re-routed end r of edge `edge`, the corner
  // diamond ties the corner-inner points of the two faces beside the edge.
  struct Link {
    Index edge;
    std::size_t position;                // i: the link between star faces i-1 and i
    std::size_t face_before, face_after; // positions in the star of r
    FT mu_before, mu_after, mu_edge;     // star = mu_before CI_before + mu_edge EM + ...
    bool with_edge_point;
  };
  // Step 2 of build_plan_once() at vertex r: the links of r's re-routed edges, in paths,
  // each solved for one of its corner-inner points: solve(link, solve_before) in emission
  // order. Returns the closing edge of a near-singular r (null_index for any other). Changes
  // only routes that end at r, as the near-singular case asks; `path` is scratch space.
  template <class Solve>
  Index solve_links_at(Index r, std::vector<Edge_route>& routes,
                       const std::vector<char>& allow_thin, std::vector<Link>& path,
                       const Solve& solve) const {
    const auto [fb, fe] = m_domain.star_faces(r);
    const auto [eb, ee] = m_domain.star_edges(r);
    const auto [nb, ne] = m_domain.neighbours(r);
    const std::size_t k = static_cast<std::size_t>(fe - fb);
    const bool boundary = m_domain.is_boundary_vertex(r);
    auto linked = [&](std::size_t i) {
      return !(boundary && (i == 0 || i == k)) && routes[eb[i % k]].end == r;
    };
    std::size_t links = 0;
    for (std::size_t i = 0; i < k; ++i)
      links += linked(i) ? 1 : 0;
    if (links == 0)
      return Domain::null_index;
    Index closing = Domain::null_index; // the regular link of a near-singular vertex
    if (!boundary && links == k) {
      // A full cycle: implied only if every link is degenerate (a singular vertex).
      std::size_t thinnest = k;
      for (std::size_t i = 0; i < k; ++i) {
        const Edge_route& route = routes[eb[i]];
        if (route.kind == End_route::THIN &&
            (thinnest == k || route.regular_weight < routes[eb[thinnest]].regular_weight))
          thinnest = i;
      }
      if (thinnest != k) {
        routes[eb[thinnest]] = Edge_route();
        closing = eb[thinnest];
        // The closing rule relies on an exact cancellation of terms of about 1/delta, so
        // every other link at r must hold exactly too: an end degenerate only up to
        // rounding (its edge-point term, about delta times a value, dropped) would have
        // that term multiplied by 1/delta (measured: errors of 5e-3 on a grid jittered by
        // 1e-14). Such an end is linked with its edge point, as a thin end, unless that
        // closed a dependency cycle.
        for (std::size_t i = 0; i < k; ++i) {
          Edge_route& route = routes[eb[i]];
          if (route.kind == End_route::DEGENERATE && !std::isinf(route.regular_weight) &&
              allow_thin[eb[i]])
            route.kind = End_route::THIN;
        }
      }
    }
    // Start after an unlinked position, so that paths are not cut in two.
    std::size_t start = 0;
    if (!boundary) {
      while (start < k && linked(start))
        ++start;
      if (start == k)
        start = 0; // singular vertex: link 0 is the implied one
    }
    auto make_link = [&](std::size_t i) {
      const Index e = eb[i % k];
      const Edge_route& route = routes[e];
      const std::size_t before = (i + k - 1) % k, after = i % k;
      const Point_2& p_before = m_domain.point(nb[(i + k - 1) % k]);
      const Point_2& p_after = m_domain.point(nb[(i + 1) % (boundary ? k + 1 : k)]);
      Link link{e, i % k, before, after, FT(0), FT(0), FT(0), false};
      if (route.kind == End_route::DEGENERATE) {
        // r = (1-t) p_before + t p_after (t by projection: exact when r is on the segment,
        // the nearest point of the segment for a frame collinear up to rounding)
        const Point_2& pr = m_domain.point(r);
        const FT dx = p_after.x() - p_before.x(), dy = p_after.y() - p_before.y();
        const FT t =
            ((pr.x() - p_before.x()) * dx + (pr.y() - p_before.y()) * dy) / (dx * dx + dy * dy);
        link.mu_before = FT(1) - t;
        link.mu_after = t;
      } else {
        const auto& ef = m_domain.edge_faces(e);
        const bool left_before = ef[0] == fb[before];
        link.mu_before = left_before ? route.mu[0] : route.mu[2];
        link.mu_after = left_before ? route.mu[2] : route.mu[0];
        link.mu_edge = route.mu[1];
        link.with_edge_point = true;
      }
      return link;
    };
    auto emit_path = [&]() {
      if (path.empty())
        return;
      // Root position rho in 0..L: links j < rho are solved for their face before, the
      // others for their face after.
      const std::size_t L = path.size();
      auto cost = [](const FT& solved, const FT& other, const FT& edge) {
        const double d = std::abs(CGAL::to_double(solved));
        if (CGAL::is_zero(solved))
          return std::numeric_limits<double>::infinity();
        return (std::max)(
            {1 / d, std::abs(CGAL::to_double(other)) / d, std::abs(CGAL::to_double(edge)) / d});
      };
      std::size_t best_root = 0;
      double best_cost = std::numeric_limits<double>::infinity();
      for (std::size_t rho = 0; rho <= L; ++rho) {
        double worst = 0;
        for (std::size_t j = 0; j < L; ++j)
          worst = (std::max)(worst,
                             j < rho ? cost(path[j].mu_before, path[j].mu_after, path[j].mu_edge)
                                     : cost(path[j].mu_after, path[j].mu_before, path[j].mu_edge));
        if (worst < best_cost) {
          best_cost = worst;
          best_root = rho;
        }
      }
      // Away from the root: backwards from rho - 1, forwards from rho.
      for (std::size_t j = best_root; j-- > 0;)
        solve(path[j], true);
      for (std::size_t j = best_root; j < L; ++j)
        solve(path[j], false);
      path.clear();
    };
    for (std::size_t step = 1; step < k + (boundary ? 0 : 1); ++step) {
      const std::size_t i = (start + step) % k; // the link between faces i-1 and i
      const bool skip = !boundary && step == k; // back at start: not a link by choice
      if (!skip && linked(i) && !(boundary && i == 0))
        path.push_back(make_link(i));
      else
        emit_path();
    }
    emit_path();
    return closing;
  }

  // The dependency cycles of step 2 that one face closes, broken before any rule is listed.
  // When each edge of a face is re-routed at a different corner, the face's corner-inner
  // point at such a corner r, if r's link solves for it, reads r's edge-middle point; that
  // point reads (step 4) the edge-middle point at the other end s, which reads (step 3) the
  // corner-inner points at s of both faces beside the edge, this face's among them: around
  // the face, a cycle. order_rules() finds it only once every rule is listed, and the whole
  // plan was then built again: random points had two or three such faces per 10^6 points,
  // and most sets of 10^6 measured took two rounds (a tenth of a c1 run). Here each such
  // face's least thin edge (by regular_weight(), as order_rules() chooses) loses its
  // re-routing, as in order_rules()' next round, until no face closes a cycle; order_rules()
  // still finds any other cycle.
  void break_face_cycles(std::vector<Edge_route>& routes, std::vector<char>& allow_thin) const {
    if (!internal::break_face_cycles_first())
      return;
    const Index F = static_cast<Index>(m_domain.number_of_faces());
    std::vector<Link> path;
    std::vector<std::pair<Index, Edge_route>> saved;
    std::vector<Index> least;
    // Whether r's link of edge e solves for the corner-inner point of face f through r's
    // edge-middle point (the routes that solve_links_at() changes at r are put back).
    auto solves_through_edge_point = [&](Index r, Index e, Index f) {
      const auto [fb, fe] = m_domain.star_faces(r);
      const auto [eb, ee] = m_domain.star_edges(r);
      saved.clear();
      for (auto it = eb; it != ee; ++it)
        saved.emplace_back(*it, routes[*it]);
      bool found = false;
      solve_links_at(r, routes, allow_thin, path, [&, fb = fb](const Link& link, bool before) {
        if (link.edge == e)
          found = link.with_edge_point && fb[before ? link.face_before : link.face_after] == f;
      });
      for (auto& [edge, route] : saved)
        routes[edge] = std::move(route);
      return found;
    };
    for (;;) {
      least.clear();
      for (Index f = 0; f < F; ++f) {
        const auto& corners = m_domain.face(f);
        std::array<Index, 3> edge; // the face's edge re-routed at corner i
        bool cycle = true;
        for (int i = 0; i < 3 && cycle; ++i) {
          const Index e1 = m_domain.face_edge(f, (i + 1) % 3),
                      e2 = m_domain.face_edge(f, (i + 2) % 3);
          const Index r = corners[std::size_t(i)];
          const bool at1 = routes[e1].end == r, at2 = routes[e2].end == r;
          cycle = at1 != at2;
          edge[std::size_t(i)] = at1 ? e1 : e2;
        }
        for (int i = 0; i < 3 && cycle; ++i)
          cycle = solves_through_edge_point(corners[std::size_t(i)], edge[std::size_t(i)], f);
        if (!cycle)
          continue;
        Index e = edge[0];
        double w = regular_weight(e);
        for (int i = 1; i < 3; ++i) {
          const double wi = regular_weight(edge[std::size_t(i)]);
          if (wi < w) {
            w = wi;
            e = edge[std::size_t(i)];
          }
        }
        least.push_back(e);
      }
      if (least.empty())
        return;
      for (const Index e : least) {
        allow_thin[e] = 0;
        if (routes[e].kind == End_route::THIN)
          routes[e] = Edge_route(); // what route_edges() gives without the re-routing
      }
    }
  }

  // One round of the plan; `frames` the corner regions' frames (choose_frames()).
  // Plans that store their rules (exact ones) compute the rules' weights on all cores too,
  // corner regions by vertex, edge points by edge, before listing the rules in order: each
  // rule gets the very weights the serial listing computed.
  void build_plan_once(const std::vector<std::array<std::uint32_t, 3>>& frames,
                       std::vector<char>& allow_thin, std::vector<Index>& thin_edge_of_rule) {
    const Index V = static_cast<Index>(m_domain.number_of_vertices());
    const Index E = static_cast<Index>(m_domain.number_of_edges());
    const Index F = static_cast<Index>(m_domain.number_of_faces());
    m_rule_refs.reserve(3 * std::size_t(V) + 4 * std::size_t(E));
    m_frame_order.assign(V, 0);

    // 1. Corner regions (Lemma 3.3.2): every point of the region is the affine image of its
    // domain point under the map fixed by the three prescribed points.
    // (The frames, and in double their rules' weights for the statistics, on all cores.)
    auto is_frame = [](const std::array<std::uint32_t, 3>& frame, std::size_t k) {
      return k == frame[0] || k == frame[1] || k == frame[2];
    };
    // stored plans: vertex v's rules from corner_base + corner_first[v] on (make_rules())
    internal::Parallel_vector<Rule> scratch;
    std::vector<double> corner_largest; // largest_abs() of each, computed with it
    std::vector<std::size_t> corner_first;
    std::size_t corner_base = 0;
    if constexpr (!parallel_plan) {
      corner_first.assign(std::size_t(V) + 1, 0);
      for (Index v = 0; v < V; ++v) {
        std::size_t rules = 0;
        for (std::size_t k = 0; k <= m_domain.degree(v); ++k)
          rules += is_frame(frames[v], k) ? 0 : 1;
        corner_first[std::size_t(v) + 1] = corner_first[v] + rules;
      }
      corner_largest.resize(corner_first.back());
      // a third of the stored rules, the rest mostly one or two per edge; a store that grew
      // would move every rule on one core (each GMP fraction's move allocates)
      m_explicit_rules.reserve(corner_first.back() + 3 * std::size_t(E) + std::size_t(V) / 8);
      corner_base =
          make_rules(scratch, corner_first, [&](std::size_t i, Rule* at, std::uint32_t& made) {
            const Index v = static_cast<Index>(i);
            const auto& frame = frames[i];
            const Point_2 &a = region_point(v, frame[0]), &b = region_point(v, frame[1]),
                          &c = region_point(v, frame[2]);
            const std::array<Slot, 3> sources{
                {region_slot(v, frame[0]), region_slot(v, frame[1]), region_slot(v, frame[2])}};
            for (std::size_t k = 0; k <= m_domain.degree(v); ++k)
              if (!is_frame(frame, k)) {
                ::new (static_cast<void*>(at + made))
                    Rule{region_slot(v, k), sources, barycentric(region_point(v, k), a, b, c)};
                corner_largest[corner_first[i] + made] = largest_abs(at[made].weights);
                ++made;
              }
          });
    }
    for (Index v = 0; v < V; ++v) {
      const std::size_t size = 1 + m_domain.degree(v);
      const std::array<std::size_t, 3> frame{{frames[v][0], frames[v][1], frames[v][2]}};
      std::size_t next = parallel_plan ? 0 : corner_first[v];
      for (std::size_t k : frame)
        m_free[region_slot(v, k)] = 1;
      m_frame_order[v] = frame_order_code(frame);
      for (std::size_t k = 0; k < size; ++k) {
        if (k == frame[0] || k == frame[1] || k == frame[2])
          continue;
        if constexpr (parallel_plan)
          m_rule_refs.push_back(region_slot(v, k)); // implicit, weights counted above
        else {
          list_made_rule(scratch, corner_base + next, true, corner_largest[next]);
          ++next;
        }
      }
    }
    thin_edge_of_rule.assign(m_rule_refs.size(), Domain::null_index);

    internal::release(corner_largest);
    std::vector<std::optional<std::array<FT, 3>>> middle; // stored plans (route_edges())
    std::vector<double> middle_largest;
    Flip_choices flips;
    std::vector<Edge_route> routes = route_edges(allow_thin, parallel_plan ? nullptr : &middle,
                                                 &middle_largest, parallel_plan ? nullptr : &flips);
    break_face_cycles(routes, allow_thin);
    m_frames.clear();
    m_near_singular.clear();

    // 2. Corner-inner points at re-routed ends. At vertex r of a re-routed edge (r, s) the
    // corner diamond reads star = mu_l CI_l + mu_s EM_r + mu_r CI_r, with
    // r = mu_l apex_l + mu_s s + mu_r apex_r (mu_s = 0 when the frame is degenerate): a link
    // between the corner-inner points of the two faces. Around r the linked faces form paths
    // (or, at a singular vertex, a cycle whose last link is implied and skipped). In each
    // path one corner-inner point is free and the links are solved away from it; the free
    // one is chosen so that the largest coefficient 1/mu of the solved links is smallest.
    // A cycle closed by a thin link is not implied: its thinnest link goes back to the
    // regular rule.
    std::vector<char> inner_dependent(F * std::size_t(3), 0);
    std::vector<Link> path;
    std::vector<Emitted_link> emitted; // the links of r as solved, in emission order
    m_closing.clear();
    for (Index r = 0; r < V; ++r) {
      const auto [fb, fe] = m_domain.star_faces(r);
      emitted.clear();
      auto emit = [&, fb = fb](const Link& link, bool solve_before) {
        const std::size_t solved = solve_before ? link.face_before : link.face_after;
        const std::size_t other = solve_before ? link.face_after : link.face_before;
        const FT& mu_solved = solve_before ? link.mu_before : link.mu_after;
        const FT& mu_other = solve_before ? link.mu_after : link.mu_before;
        const Slot star = star_slot(link.edge, r);
        const Slot ci_other = corner_inner_slot(fb[other], r);
        if (link.with_edge_point)
          add_rule(corner_inner_slot(fb[solved], r),
                   {{star, ci_other, edge_middle_slot(link.edge, r)}},
                   {{FT(1) / mu_solved, -mu_other / mu_solved, -link.mu_edge / mu_solved}});
        else
          add_rule(corner_inner_slot(fb[solved], r), {{star, ci_other, null_slot}},
                   {{FT(1) / mu_solved, -mu_other / mu_solved, FT(0)}});
        thin_edge_of_rule.push_back(link.with_edge_point ? link.edge : Domain::null_index);
        inner_dependent[3 * std::size_t(fb[solved]) +
                        std::size_t(position_in_face(fb[solved], r))] = 1;
        emitted.push_back({link.position, solve_before});
      };
      const Index closing = solve_links_at(r, routes, allow_thin, path, emit);
      if (closing != Domain::null_index) {
        m_near_singular.push_back(r);
        m_closing.push_back({closing, r, closing_combination(r, closing, emitted, routes)});
      }
    }
    for (Index f = 0; f < F; ++f)
      for (int i = 0; i < 3; ++i)
        if (!inner_dependent[3 * std::size_t(f) + std::size_t(i)])
          m_free[face_slot(f, i)] = 1;

    // 3. Edge-middle points from each regular end r of an interior edge (r, s): the
    // diamond (CI_left, star_r, edge-middle near r, CI_right) is the image of
    // (p_left, r, s, p_right), so the edge point is the combination of s in (p_left, r, p_right).
    // The few closing links are flagged by edge: a search of all of them per edge end was
    // quadratic (a tenth of a c1 run at 10^6 points, 1354 near-singular vertices).
    std::vector<char> closing_edge(E, 0);
    for (const Closing& c : m_closing)
      closing_edge[c.edge] = 1;
    // the regular ends' rules (closing ones are stored): weights of s in (p_left, r, p_right)
    auto middle_weights = [&](Index e, int side) {
      const auto& ends = m_domain.edge(e);
      const auto& ef = m_domain.edge_faces(e);
      return barycentric(m_domain.point(ends[std::size_t(1 - side)]),
                         m_domain.point(m_domain.opposite_vertex(ef[0], e)),
                         m_domain.point(ends[std::size_t(side)]),
                         m_domain.point(m_domain.opposite_vertex(ef[1], e)));
    };
    auto implicit_middle = [&](Index e, int side) {
      const Index r = m_domain.edge(e)[std::size_t(side)];
      return !m_domain.is_boundary_edge(e) && routes[e].end != r &&
             !(closing_edge[e] && closing_of(e, r));
    };
    if constexpr (parallel_plan)
      parallel_with_weights(E, [&](std::size_t i, Weight_statistics& w) {
        const Index e = static_cast<Index>(i);
        for (int side = 0; side < 2; ++side)
          if (implicit_middle(e, side))
            count_weight(w, edge_middle_slot(e, m_domain.edge(e)[std::size_t(side)]),
                         largest_abs(middle_weights(e, side)));
      });
    // stored plans: edge e's regular rules from middle_base + middle_first[e] on
    std::vector<std::size_t> middle_first;
    std::size_t middle_base = 0;
    if constexpr (!parallel_plan) {
      middle_first.assign(std::size_t(E) + 1, 0);
      for (Index e = 0; e < E; ++e)
        middle_first[std::size_t(e) + 1] =
            middle_first[e] + (implicit_middle(e, 0) ? 1 : 0) + (implicit_middle(e, 1) ? 1 : 0);
      middle_base =
          make_rules(scratch, middle_first, [&](std::size_t i, Rule* at, std::uint32_t& made) {
            const Index e = static_cast<Index>(i);
            const auto& ef = m_domain.edge_faces(e);
            for (int side = 0; side < 2; ++side) {
              if (!implicit_middle(e, side))
                continue;
              const Index r = m_domain.edge(e)[std::size_t(side)];
              const std::size_t k = 2 * i + std::size_t(side);
              const Slot target = edge_middle_slot(e, r);
              const std::array<Slot, 3> sources{
                  {corner_inner_slot(ef[0], r), star_slot(e, r), corner_inner_slot(ef[1], r)}};
              if (middle[k]) {
                ::new (static_cast<void*>(at + made)) Rule{target, sources, std::move(*middle[k])};
              } else {
                ::new (static_cast<void*>(at + made))
                    Rule{target, sources, middle_weights(e, side)};
                middle_largest[k] = largest_abs(at[made].weights);
              }
              ++made;
            }
          });
    }
    for (Index e = 0; e < E; ++e) {
      const auto& ends = m_domain.edge(e);
      if (m_domain.is_boundary_edge(e)) {
        m_free[edge_slot(e, 1)] = m_free[edge_slot(e, 2)] = 1;
        const auto& ef = m_domain.edge_faces(e);
        const Index f = ef[0] != Domain::null_index ? ef[0] : ef[1];
        m_free[flip_slot(f, e)] = 1;
        continue;
      }
      [[maybe_unused]] std::size_t listed = 0; // of e's regular rules
      for (int side = 0; side < 2; ++side) {
        const Index r = ends[std::size_t(side)];
        if (routes[e].end == r)
          continue;
        if (const auto closing = closing_edge[e] ? closing_of(e, r) : nullptr) {
          add_wide_rule(edge_middle_slot(e, r), *closing, thin_edge_of_rule);
          continue;
        }
        if constexpr (parallel_plan) {
          m_rule_refs.push_back(edge_middle_slot(e, r)); // implicit, weights counted above
        } else {
          list_made_rule(scratch, middle_base + middle_first[e] + listed++, true,
                         middle_largest[2 * std::size_t(e) + std::size_t(side)]);
        }
        thin_edge_of_rule.push_back(Domain::null_index);
      }
    }

    // 4. Re-routed ends: the edge-middle point next to a re-routed end r comes from the
    // middle diamond (flip_left, edge-middle near r, edge-middle near s, flip_right), an
    // image of (p_left, r, s, p_right): EM_r = mu_l flip_l + mu_s EM_s + mu_r flip_r, with
    // the weights of the corner diamond's link (at most about 1 where the regular rule's are
    // large).
    for (Index e = 0; e < E; ++e) {
      const Edge_route& route = routes[e];
      if (route.end == Domain::null_index)
        continue;
      const Index r = route.end;
      const auto& ends = m_domain.edge(e);
      const Index s = ends[0] == r ? ends[1] : ends[0];
      const auto& ef = m_domain.edge_faces(e);
      m_free[flip_slot(ef[0], e)] = m_free[flip_slot(ef[1], e)] = 1;
      add_rule(edge_middle_slot(e, r),
               {{flip_slot(ef[0], e), edge_middle_slot(e, s), flip_slot(ef[1], e)}}, route.mu);
      thin_edge_of_rule.push_back(Domain::null_index);
      Degenerate_frame frame{e, r, m_domain.opposite_vertex(ef[0], e),
                             m_domain.opposite_vertex(ef[1], e), false};
      frame.numerical = !std::isinf(route.regular_weight) &&
                        route.regular_weight == (std::numeric_limits<double>::max)();
      frame.thin = route.kind == End_route::THIN && !frame.numerical;
      frame.regular_weight = route.regular_weight;
      m_frames.push_back(frame);
    }

    // 5. The second flip point of every regular interior edge: one flip point is the image
    // of its apex in the frame (other flip, edge-middle near lo, edge-middle near hi). Of the
    // two choices the one with the smaller largest weight is taken (Xu prescribes the flip
    // of the farther apex, which bounds the flip's own weight by 1 but not the edge points'
    // weights, which grow where the quadrilateral is far from convex).
    // (In double the choices, and the chosen rules' weights for the statistics, on all cores:
    // free_flip[e] 1 for the left flip, 2 for the right one.)
    auto flip_weights = [&](Index e, bool left_free) {
      const auto& ends = m_domain.edge(e);
      const auto& ef = m_domain.edge_faces(e);
      const Point_2& apex_left = m_domain.point(m_domain.opposite_vertex(ef[0], e));
      const Point_2& apex_right = m_domain.point(m_domain.opposite_vertex(ef[1], e));
      const Point_2 &lo = m_domain.point(ends[0]), &hi = m_domain.point(ends[1]);
      return left_free ? barycentric(apex_right, apex_left, lo, hi)
                       : barycentric(apex_left, apex_right, lo, hi);
    };
    auto regular_edge = [&](Index e) {
      return !m_domain.is_boundary_edge(e) && routes[e].end == Domain::null_index;
    };
    release_in_parallel(middle);
    // stored plans: the chosen rule's weights by edge, and their largest_abs(), where
    // route_edges() did not choose
    std::vector<unsigned char>& free_flip = flips.free_flip;
    std::vector<std::optional<std::array<FT, 3>>>& flip_weights_of = flips.weights;
    std::vector<double>& flip_largest = flips.largest;
    // stored plans: edge e's rule at flip_base + flip_first[e] (make_rules())
    std::vector<std::size_t> flip_first;
    std::size_t flip_base = 0;
    if constexpr (!parallel_plan) {
      flip_first.assign(std::size_t(E) + 1, 0);
      for (Index e = 0; e < E; ++e)
        flip_first[std::size_t(e) + 1] = flip_first[e] + (regular_edge(e) ? 1 : 0);
      flip_base =
          make_rules(scratch, flip_first, [&](std::size_t i, Rule* at, std::uint32_t& made) {
            const Index e = static_cast<Index>(i);
            if (!regular_edge(e))
              return;
            if (free_flip[i] == 0) {
              std::array<FT, 3> right_from_left = flip_weights(e, true);
              std::array<FT, 3> left_from_right = flip_weights(e, false);
              const double right = largest_abs(right_from_left),
                           left = largest_abs(left_from_right);
              const bool left_free = !(left < right);
              free_flip[i] = left_free ? 1 : 2;
              flip_weights_of[i] = std::move(left_free ? right_from_left : left_from_right);
              flip_largest[i] = left_free ? right : left;
            }
            const auto& ends = m_domain.edge(e);
            const auto& ef = m_domain.edge_faces(e);
            const bool left_free = free_flip[i] == 1;
            const Index free_face = left_free ? ef[0] : ef[1],
                        other_face = left_free ? ef[1] : ef[0];
            ::new (static_cast<void*>(at))
                Rule{flip_slot(other_face, e),
                     {{flip_slot(free_face, e), edge_middle_slot(e, ends[0]),
                       edge_middle_slot(e, ends[1])}},
                     std::move(*flip_weights_of[i])};
            ++made;
          });
    }
    if constexpr (parallel_plan) {
      free_flip.assign(E, 0);
      parallel_with_weights(E, [&](std::size_t i, Weight_statistics& w) {
        const Index e = static_cast<Index>(i);
        if (!regular_edge(e))
          return;
        const double right = largest_abs(flip_weights(e, true)),
                     left = largest_abs(flip_weights(e, false));
        const bool left_free = !(left < right);
        free_flip[i] = left_free ? 1 : 2;
        const auto& ef = m_domain.edge_faces(e);
        count_weight(w, flip_slot(left_free ? ef[1] : ef[0], e), left_free ? right : left);
      });
    }
    for (Index e = 0; e < E; ++e) {
      if (!regular_edge(e))
        continue;
      const auto& ef = m_domain.edge_faces(e);
      const bool left_free = free_flip[e] == 1;
      const Index free_face = left_free ? ef[0] : ef[1], other_face = left_free ? ef[1] : ef[0];
      m_free[flip_slot(free_face, e)] = 1;
      if constexpr (parallel_plan)
        m_rule_refs.push_back(flip_slot(other_face, e)); // implicit, weights counted above
      else
        list_made_rule(scratch, flip_base + flip_first[e], true, flip_largest[e]);
      thin_edge_of_rule.push_back(Domain::null_index);
    }
    release_in_parallel(flip_weights_of);
  }

  // The closing link of a near-singular vertex r (its edge `closing`, the one link left
  // regular): the edge-middle point next to r, solved from its corner diamond, would take
  // weights of about 1/delta (delta the sine of the angle by which r misses being singular).
  // Substituting the path's rules for the two corner-inner points and the frame's for the
  // star writes it directly in the free data: the three prescribed points of r's corner
  // region, the free corner-inner point (whose coefficient vanishes: around r the product of
  // the link ratios is (-1)^k, benchmark/near_singular_cycle.py) and the edge-middle points
  // of the other links. The 1/delta terms cancel, leaving coefficients of about 10. The
  // cancellation is computed exactly (in FT if it is exact, else in rationals from the
  // points' doubles, rounded once at the end), so the double build gets the correctly
  // rounded coefficients and the exact build the very value of the regular rule.
  std::vector<std::pair<Slot, FT>>
  closing_combination(Index r, Index closing, const std::vector<Emitted_link>& chain,
                      const std::vector<Edge_route>& routes) const {
    if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value)
      return closing_combination_in<FT>(r, closing, chain, routes);
    else
      return closing_combination_in<CGAL::Exact_rational>(r, closing, chain, routes);
  }

  template <class T>
  std::vector<std::pair<Slot, FT>>
  closing_combination_in(Index r, Index closing, const std::vector<Emitted_link>& chain,
                         const std::vector<Edge_route>& routes) const {
    using Point = std::array<T, 2>;
    using Combination = std::vector<std::pair<Slot, T>>;
    auto point = [&](Index v) -> Point {
      const Point_2& p = m_domain.point(v);
      if constexpr (std::is_same_v<T, FT>)
        return {{p.x(), p.y()}};
      else
        return {{T(CGAL::to_double(p.x())), T(CGAL::to_double(p.y()))}};
    };
    auto barycentric_of = [](const Point& x, const Point& a, const Point& b, const Point& c) {
      return internal::barycentric_of_coordinates(x, a, b, c);
    };
    auto add = [](Combination& to, const T& scale, const Combination& from) {
      for (const auto& [slot, c] : from) {
        const auto at = std::find_if(to.begin(), to.end(),
                                     [&, slot = slot](const auto& x) { return x.first == slot; });
        if (at == to.end())
          to.emplace_back(slot, scale * c);
        else
          at->second = at->second + scale * c;
      }
    };
    const auto [fb, fe] = m_domain.star_faces(r);
    const auto [eb, ee] = m_domain.star_edges(r);
    const auto [nb, ne] = m_domain.neighbours(r);
    const std::size_t k = static_cast<std::size_t>(fe - fb);
    auto face_position = [&](Index f) {
      return static_cast<std::size_t>(std::find(fb, fe, f) - fb);
    };
    // The star points of r in its frame (step 1).
    const std::array<std::size_t, 3> frame = choose_frame(r);
    auto region_slot = [&](std::size_t j) {
      return j == 0 ? vertex_slot(r) : star_slot(eb[j - 1], r);
    };
    auto region_point = [&](std::size_t j) { return j == 0 ? point(r) : point(nb[j - 1]); };
    auto star = [&](std::size_t i) {
      const std::size_t j = 1 + i;
      if (j == frame[0] || j == frame[1] || j == frame[2])
        return Combination{{region_slot(j), T(1)}};
      const auto w = barycentric_of(region_point(j), region_point(frame[0]), region_point(frame[1]),
                                    region_point(frame[2]));
      return Combination{{region_slot(frame[0]), w[0]},
                         {region_slot(frame[1]), w[1]},
                         {region_slot(frame[2]), w[2]}};
    };
    // The corner-inner points along the path (step 2's links, in the order they were solved),
    // starting from the free one.
    std::vector<Combination> inner(k);
    std::vector<char> solved(k, 0);
    for (const Emitted_link& link : chain)
      solved[link.solve_before ? (link.position + k - 1) % k : link.position] = 1;
    for (std::size_t f = 0; f < k; ++f)
      if (!solved[f])
        inner[f] = {{corner_inner_slot(fb[f], r), T(1)}};
    for (const Emitted_link& link : chain) {
      const std::size_t i = link.position, before = (i + k - 1) % k, after = i;
      const Index e = eb[i];
      T mu_before, mu_after, mu_edge(0);
      if (routes[e].kind == End_route::DEGENERATE) {
        const Point pb = point(nb[(i + k - 1) % k]), pa = point(nb[(i + 1) % k]), pr = point(r);
        const T dx = pa[0] - pb[0], dy = pa[1] - pb[1];
        const T t = ((pr[0] - pb[0]) * dx + (pr[1] - pb[1]) * dy) / (dx * dx + dy * dy);
        mu_before = T(1) - t;
        mu_after = t;
      } else {
        const auto& ef = m_domain.edge_faces(e);
        const auto& ends = m_domain.edge(e);
        const auto mu = barycentric_of(point(r), point(m_domain.opposite_vertex(ef[0], e)),
                                       point(ends[0] == r ? ends[1] : ends[0]),
                                       point(m_domain.opposite_vertex(ef[1], e)));
        const bool left_before = ef[0] == fb[before];
        mu_before = left_before ? mu[0] : mu[2];
        mu_after = left_before ? mu[2] : mu[0];
        mu_edge = mu[1];
      }
      const std::size_t target = link.solve_before ? before : after;
      const std::size_t other = link.solve_before ? after : before;
      const T& mu_solved = link.solve_before ? mu_before : mu_after;
      const T& mu_other = link.solve_before ? mu_after : mu_before;
      Combination c = star(i);
      for (auto& [slot, x] : c)
        x = x / mu_solved;
      add(c, -mu_other / mu_solved, inner[other]);
      if (!CGAL::is_zero(mu_edge))
        add(c, -mu_edge / mu_solved, Combination{{edge_middle_slot(e, r), T(1)}});
      inner[target] = std::move(c);
    }
    // The closing edge's corner diamond at r (step 3's regular rule), with the above
    // substituted.
    const auto& ef = m_domain.edge_faces(closing);
    const auto& ends = m_domain.edge(closing);
    const auto w = barycentric_of(point(ends[0] == r ? ends[1] : ends[0]),
                                  point(m_domain.opposite_vertex(ef[0], closing)), point(r),
                                  point(m_domain.opposite_vertex(ef[1], closing)));
    Combination result;
    add(result, w[0], inner[face_position(ef[0])]);
    add(result, w[1], star(static_cast<std::size_t>(std::find(eb, ee, closing) - eb)));
    add(result, w[2], inner[face_position(ef[1])]);
    std::vector<std::pair<Slot, FT>> out;
    for (const auto& [slot, c] : result)
      if (!CGAL::is_zero(c)) {
        if constexpr (std::is_same_v<T, FT>)
          out.emplace_back(slot, c);
        else
          out.emplace_back(slot, FT(CGAL::to_double(c)));
      }
    std::sort(out.begin(), out.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
  }

  // The combination replacing the regular rule of end r of edge e, if (e, r) is the closing
  // link of a near-singular vertex.
  const std::vector<std::pair<Slot, FT>>* closing_of(Index e, Index r) const {
    for (const Closing& c : m_closing)
      if (c.edge == e && c.vertex == r)
        return &c.combination;
    return nullptr;
  }

  // target = the combination, as a chain of rules of at most three sources: auxiliary slots
  // (after the control points) hold the partial sums.
  void add_wide_rule(Slot target, std::vector<std::pair<Slot, FT>> combination,
                     std::vector<Index>& thin_edge_of_rule) {
    // Rounded partial sums depend on how the terms are grouped: in double they are taken
    // in an order of their own (weight, then the points of the slot's polar label), not in
    // the order of the numbering, like the terms of apply().
    if constexpr (!CGAL::Algebraic_structure_traits<FT>::Is_exact::value)
      std::sort(combination.begin(), combination.end(), [&](const auto& a, const auto& b) {
        if (a.second != b.second)
          return a.second < b.second;
        return label_less(a.first, b.first);
      });
    std::size_t next = 0;
    Slot sum = null_slot; // the partial sum so far
    while (next < combination.size()) {
      std::array<Slot, 3> sources{{null_slot, null_slot, null_slot}};
      std::array<FT, 3> weights{{FT(0), FT(0), FT(0)}};
      std::size_t used = 0;
      if (sum != null_slot) {
        sources[0] = sum;
        weights[0] = FT(1);
        used = 1;
      }
      while (used < 3 && next < combination.size()) {
        sources[used] = combination[next].first;
        weights[used] = combination[next].second;
        ++used, ++next;
      }
      if (used == 1) { // a single source: a rule needs two
        sources[1] = sources[0];
        weights[1] = FT(0);
      }
      const bool last = next == combination.size();
      const Slot to = last ? target : static_cast<Slot>(m_free.size());
      if (!last)
        m_free.push_back(0); // the values are allocated after planning
      add_rule(to, sources, std::move(weights));
      thin_edge_of_rule.push_back(Domain::null_index);
      sum = to;
    }
  }

  // A strict order of control slots that does not depend on the numbering: their polar
  // labels, as (point, multiplicity) pairs in lexicographic order of the points, compared
  // lexicographically.
  bool label_less(Slot a, Slot b) const {
    struct Key {
      std::array<std::pair<const Point_2*, int>, 3> entries;
      std::size_t size = 0;
    };
    auto point_less = [](const Point_2& p, const Point_2& q) {
      return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
    };
    auto key = [&](Slot s) {
      Key k;
      for (const auto& [v, m] : polar_label(s))
        k.entries[k.size++] = {&m_domain.point(v), m};
      auto order = [&](std::size_t i, std::size_t j) { // a sorting network of three
        if (j < k.size && point_less(*k.entries[j].first, *k.entries[i].first))
          std::swap(k.entries[i], k.entries[j]);
      };
      order(0, 1);
      order(1, 2);
      order(0, 1);
      return k;
    };
    const Key ka = key(a), kb = key(b);
    for (std::size_t i = 0; i < (std::min)(ka.size, kb.size); ++i) {
      const auto &p = ka.entries[i], &q = kb.entries[i];
      if (point_less(*p.first, *q.first) || point_less(*q.first, *p.first))
        return point_less(*p.first, *q.first);
      if (p.second != q.second)
        return p.second < q.second;
    }
    return ka.size < kb.size;
  }

  // The largest regular weight of the two ends of interior edge e.
  double regular_weight(Index e) const {
    const auto& ends = m_domain.edge(e);
    const auto& ef = m_domain.edge_faces(e);
    const Point_2& pl = m_domain.point(m_domain.opposite_vertex(ef[0], e));
    const Point_2& pr = m_domain.point(m_domain.opposite_vertex(ef[1], e));
    const Point_2 &lo = m_domain.point(ends[0]), &hi = m_domain.point(ends[1]);
    return (std::max)(largest_abs(barycentric(hi, pl, lo, pr)),
                      largest_abs(barycentric(lo, pl, hi, pr)));
  }

  // Puts the rules in an order in which every source is computed before it is read (the
  // emission order where it already is one, then the rest depth-first). Returns false on a
  // dependency cycle, after forbidding the thin re-routing of the least thin edge on it (only
  // the part of the depth-first stack above the repeated rule is the cycle: forbidding every
  // thin edge on the stack left thousands of thin frames regular, with weights up to 10^3).
  bool order_rules(const std::vector<Index>& thin_edge_of_rule, std::vector<char>& allow_thin) {
    const std::size_t R = m_rule_refs.size();
    constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
    // a rule's target and sources (a stored rule read in place: copying an exact one's
    // weights was most of this function's time)
    struct Links {
      Slot target;
      std::array<Slot, 3> sources;
      int size() const { return sources[2] == null_slot ? 2 : 3; }
    };
    auto sources_of = [&](std::size_t i) {
      const std::uint32_t ref = m_rule_refs[i];
      if (ref & explicit_rule_bit) {
        const Rule& r = m_explicit_rules[ref & ~explicit_rule_bit];
        return Links{r.target, r.sources};
      }
      const Rule r = implicit_rule(ref, false);
      return Links{r.target, r.sources};
    };
    // 1. One pass in emission order: a rule whose sources are all free or computed by an
    // earlier kept rule stays where it is (all rules but those reading a thin link's edge
    // point, and what depends on them). Only the others need the depth-first search.
    std::vector<char> ready(m_free.size(), 0);
    for (std::size_t s = 0; s < m_free.size(); ++s)
      ready[s] = m_free[s];
    std::vector<unsigned char> state(R, 0); // 0 deferred, 1 on the stack, 2 done
    std::vector<std::uint32_t> deferred;
    // whether rule i stays; if so its target is ready
    auto keep = [&](std::size_t i) {
      const Links rule = sources_of(i);
      for (int j = 0; j < rule.size(); ++j)
        if (!ready[rule.sources[std::size_t(j)]])
          return false;
      ready[rule.target] = 1;
      state[i] = 2;
      return true;
    };
    // In double, a run of implicit rules of one kind on all cores: none reads another's
    // target (for_each_rule_in_runs()), so each sees what it would in order, and the
    // deferred ones are collected block by block in order: the same list as one thread's.
    constexpr std::size_t block = 4096;
    std::vector<std::vector<std::uint32_t>> deferred_in_block;
    for (std::size_t begin = 0; begin < R;) {
      const std::uint32_t first = m_rule_refs[begin];
      std::size_t end = begin + 1;
      if (parallel_plan && !(first & explicit_rule_bit)) {
        const int group = implicit_group(first);
        while (end < R && !(m_rule_refs[end] & explicit_rule_bit) &&
               implicit_group(m_rule_refs[end]) == group)
          ++end;
      }
      if (end - begin < 2 * block) {
        for (std::size_t i = begin; i < end; ++i)
          if (!keep(i))
            deferred.push_back(static_cast<std::uint32_t>(i));
      } else {
        const std::size_t blocks = (end - begin + block - 1) / block;
        deferred_in_block.assign(blocks, {});
        internal::parallel_for_index(
            blocks, internal::thread_count(end - begin, 20000),
            [&](std::size_t b) {
              const std::size_t last = (std::min)(end, begin + (b + 1) * block);
              for (std::size_t i = begin + b * block; i < last; ++i)
                if (!keep(i))
                  deferred_in_block[b].push_back(static_cast<std::uint32_t>(i));
            },
            1);
        for (const auto& d : deferred_in_block)
          deferred.insert(deferred.end(), d.begin(), d.end());
      }
      begin = end;
    }
    if (deferred.empty())
      return true;
    // 2. Depth-first over the deferred rules (the kept ones are done): their order after
    // the kept rules, or a dependency cycle. The deferred rules by target in an open-addressing
    // table (Fibonacci hashing, at most half full): a lookup is one or two reads of one array
    // (std::unordered_map took 0.7 s of the 1.5 s this step took at 10^6 random points, two
    // plan rounds). Every slot the search looks up is the target of a deferred rule: a slot
    // that is not ready is neither free nor computed by a kept rule.
    int shift = 32;
    while ((std::size_t(1) << (32 - shift)) < 2 * deferred.size())
      --shift;
    const std::size_t mask = (std::size_t(1) << (32 - shift)) - 1;
    std::vector<std::pair<Slot, std::uint32_t>> rule_of(mask + 1, {null_slot, none});
    auto cell_of = [&](Slot target) {
      std::size_t c = std::size_t(std::uint32_t(target * 2654435769u) >> shift);
      while (rule_of[c].first != null_slot && rule_of[c].first != target)
        c = (c + 1) & mask;
      return c;
    };
    for (std::uint32_t i : deferred) {
      const Slot target = sources_of(i).target;
      rule_of[cell_of(target)] = {target, i};
    }
    std::vector<std::uint32_t> order;
    order.reserve(deferred.size());
    // rule, next source to visit, its sources (computed once per visit, not once per step)
    struct Visit {
      std::uint32_t rule;
      int next, size;
      std::array<Slot, 3> sources;
    };
    std::vector<Visit> stack;
    auto visit = [&](std::uint32_t i) {
      const Links r = sources_of(i);
      stack.push_back({i, 0, r.size(), r.sources});
    };
    bool cycle = false;
    for (std::uint32_t root : deferred) {
      if (state[root])
        continue;
      visit(root);
      state[root] = 1;
      while (!stack.empty()) {
        Visit& top = stack.back();
        if (top.next < top.size) {
          const Slot slot = top.sources[std::size_t(top.next++)];
          if (ready[slot]) // free, or computed by a kept rule: no lookup
            continue;
          const std::uint32_t source = rule_of[cell_of(slot)].second;
          if (source == none || state[source] == 2)
            continue;
          if (state[source] == 1) {
            cycle = true;
            Index least = Domain::null_index;
            double least_weight = std::numeric_limits<double>::infinity();
            for (std::size_t i = stack.size(); i-- > 0;) {
              const Index e = thin_edge_of_rule[stack[i].rule];
              if (e != Domain::null_index) {
                const double w = regular_weight(e);
                if (w < least_weight) {
                  least_weight = w;
                  least = e;
                }
              }
              if (stack[i].rule == source)
                break;
            }
            CGAL_assertion(least != Domain::null_index); // only thin links close cycles
            if (least != Domain::null_index)
              allow_thin[least] = 0;
            continue;
          }
          state[source] = 1;
          visit(source); // invalidates `top`
          continue;
        }
        state[top.rule] = 2;
        order.push_back(top.rule);
        stack.pop_back();
      }
    }
    if (cycle)
      return false;
    // 3. The kept rules move up in place (a sorted copy of all rules was the largest
    // allocation of a whole c1 run), the deferred ones follow in their order.
    std::vector<std::uint32_t> moved;
    moved.reserve(order.size());
    for (std::uint32_t i : order)
      moved.push_back(m_rule_refs[i]);
    std::size_t w = 0;
    for (std::size_t i = 0, d = 0; i < R; ++i) {
      if (d < deferred.size() && deferred[d] == i) {
        ++d;
        continue;
      }
      m_rule_refs[w++] = m_rule_refs[i];
    }
    std::copy(moved.begin(), moved.end(), m_rule_refs.begin() + std::ptrdiff_t(w));
    return true;
  }

  // Reverse dependencies (slot -> rules reading it), built on the first local edit: a
  // spline that is only propagated never pays for them.
  void build_dependents() {
    m_dependent_offsets.assign(m_values.size() + 1, 0);
    const std::size_t R = m_rule_refs.size();
    for (std::size_t i = 0; i < R; ++i) {
      const Rule r = rule_of_ref(m_rule_refs[i], false);
      for (int j = 0; j < r.size(); ++j)
        ++m_dependent_offsets[r.sources[std::size_t(j)] + 1];
    }
    for (std::size_t s = 0; s < m_values.size(); ++s)
      m_dependent_offsets[s + 1] += m_dependent_offsets[s];
    m_dependents.assign(m_dependent_offsets.back(), 0);
    std::vector<std::size_t> fill(m_dependent_offsets.begin(), m_dependent_offsets.end() - 1);
    for (std::size_t i = 0; i < R; ++i) {
      const Rule r = rule_of_ref(m_rule_refs[i], false);
      for (int j = 0; j < r.size(); ++j)
        m_dependents[fill[r.sources[std::size_t(j)]]++] = static_cast<std::uint32_t>(i);
    }
    m_queued.assign(R, 0);
  }

  Domain m_domain;
  Corner_frame m_frame;
  std::size_t m_control_slots = 0; // V + 4E + 6F; auxiliary slots follow in m_values
  std::vector<Value> m_values;
  std::vector<char> m_free;
  std::size_t m_number_of_free = 0;
  // The plan's rules in evaluation order, one reference each: an implicit rule's target
  // (implicit_rule()), or explicit_rule_bit | its index in m_explicit_rules.
  static constexpr std::uint32_t explicit_rule_bit = std::uint32_t(1) << 31;
  std::vector<std::uint32_t> m_rule_refs;
  internal::Parallel_vector<Rule> m_explicit_rules;
  std::vector<std::uint8_t> m_frame_order; // frame_order_code() of each vertex's frame
  Degenerate_frame_analysis<Index> m_degenerate;
  std::vector<Degenerate_frame> m_frames;
  double m_max_weight = 0;
  std::optional<double> m_amplification;              // propagation_amplification(), once known
  std::array<double, 6> m_max_weight_by_kind{};       // by Slot_kind of the target
  std::array<std::size_t, 6> m_above_bound_by_kind{}; // rules above the bound, by kind
  int m_plan_rounds = 0; // plan builds: 1 + the rebuilds that broke dependency cycles
  std::vector<Index> m_near_singular;
  struct Closing {
    Index edge, vertex;
    std::vector<std::pair<Slot, FT>> combination;
  };
  std::vector<Closing> m_closing; // the closing links of the near-singular vertices
  std::vector<std::size_t> m_dependent_offsets;
  std::vector<std::uint32_t> m_dependents;
  std::vector<char> m_queued;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_XU_C1_QUINTIC_SPLINE_H

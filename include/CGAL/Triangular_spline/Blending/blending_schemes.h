// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SCHEMES_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SCHEMES_H

#include <CGAL/Triangular_spline/Blending/Taylor_jet.h>
#include <CGAL/Triangular_spline/Blending/blending_functions.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/blending_arithmetic.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the blended result \f$S = \sum_i f_i^{n,d,p} S_i\f$ (Fang, Def. 3.5) at
  one point, from the indicator values and the sub-function values there.

  \tparam T a number type or a `Taylor_jet` (then the result carries the derivatives)
  \tparam Value `T` or `std::array<T, D>` (a point or vector in \f$\mathbb{R}^D\f$)
  \tparam BlendingFunctions a blending-function policy, e.g. `Fang_blending_functions`
  \param indicators the indicator values at the point
  \param values the sub-function values \f$S_i\f$ at the point, one per indicator
  \param order the order
  \param functions the blending functions
  \returns the blended value \f$S\f$
*/
template <class T, class Value, class BlendingFunctions = Fang_blending_functions>
Value blend_values(const std::vector<T>& indicators, const std::vector<Value>& values, int order,
                   const BlendingFunctions& functions = BlendingFunctions()) {
  return internal::weighted_sum(functions(indicators, order), values);
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the triangular blending scheme (Fang, §4.2): three sub-surfaces over the
  barycentric domain, indicators \f$t = (u, v, w)\f$ (Def. 4.2), blending functions
  \f$f_i^{3,d,t}\f$ (Def. 4.3).

  A domain point is given by its first two barycentric coordinates \f$(u, v)\f$,
  \f$w = 1 - u - v\f$. Sub-surface \f$S_i\f$ is inherited, with its derivatives up to order
  \f$d\f$, on the side where \f$t_i = 0\f$ (Thm. 4.2); at a corner where \f$t_i = t_j = 0\f$
  the blend is defined when \f$S_i\f$ and \f$S_j\f$ agree there and inherits their common
  derivatives when they are \f$d\f$-th matched (Thms. 4.1, 4.3).

  Sub-surfaces are callables `s(u, v)` taking two `T` (numbers or `Taylor_jet`s of the
  coordinates) and returning `T` or `std::array<T, D>`. A generic lambda
  (`[](const auto& u, const auto& v) {...}`) gives values with numbers and exact derivatives
  of any order with jets.

  \tparam FT the number type of the domain coordinates
  \tparam BlendingFunctions a blending-function policy (`Fang_blending_functions`,
  `Extended_nielson_blending_functions`, `Shepard_blending_functions`)
*/
template <class FT, class BlendingFunctions = Fang_blending_functions>
class Triangular_blending_scheme {
public:
  /// the blending-function policy
  using Blending_functions = BlendingFunctions;
  /// the number of sub-surfaces
  static constexpr std::size_t number_of_sub_surfaces = 3;

  /// creates the scheme of order `order`.
  /// \throws Invalid_input if `order` < 0
  /// \param order the order
  /// \param functions the blending functions
  explicit Triangular_blending_scheme(int order, const BlendingFunctions& functions = {})
      : m_order(order), m_functions(functions) {
    internal::check_order(order, "Triangular_blending_scheme");
  }

  /// returns the blending order \f$d\f$.
  /// \returns the blending order \f$d\f$
  int order() const { return m_order; }

  /// returns the indicators \f$(u, v, 1 - u - v)\f$ (Def.\ 4.2).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param u the first parameter \f$u\f$
  /// \param v the second parameter \f$v\f$
  /// \returns the indicators
  template <class T>
  std::vector<T> indicators(const T& u, const T& v) const {
    const T w = FT(1) - u - v;
    return {u, v, w};
  }

  /// returns the blending functions \f$f_0, f_1, f_2\f$ at \f$(u, v)\f$ (Def.\ 4.3).
  /// \tparam T a number type or a `Taylor_jet`
  /// \param u the first parameter \f$u\f$
  /// \param v the second parameter \f$v\f$
  /// \returns the blending functions \f$f_0, f_1, f_2\f$ at \f$(u, v)\f$ (Def. 4.3)
  template <class T>
  std::vector<T> weights(const T& u, const T& v) const {
    return m_functions(indicators(u, v), m_order);
  }

  /// returns \f$\sum_i f_i(u,v)\, S_i(u,v)\f$ (Def.\ 4.6).
  /// \tparam T a number type or a `Taylor_jet`
  /// \tparam S0 a callable `s(u, v)`
  /// \tparam S1 a callable `s(u, v)`
  /// \tparam S2 a callable `s(u, v)`
  /// \param u the first parameter \f$u\f$
  /// \param v the second parameter \f$v\f$
  /// \param s0 the callable of the first sub-surface \f$S_0\f$
  /// \param s1 the callable of the second sub-surface \f$S_1\f$
  /// \param s2 the callable of the third sub-surface \f$S_2\f$
  /// \returns the blended value
  template <class T, class S0, class S1, class S2>
  auto blend(const T& u, const T& v, const S0& s0, const S1& s1, const S2& s2) const {
    using Value = std::decay_t<decltype(s0(u, v))>;
    const std::vector<Value> values{s0(u, v), s1(u, v), s2(u, v)};
    return internal::weighted_sum(weights(u, v), values);
  }

private:
  int m_order;
  BlendingFunctions m_functions;
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the binary blending scheme of Fang's edge surfaces (eqs. 5.6, 5.7): two
  sub-surfaces over a plane with coordinates \f$(x, y)\f$, indicators \f$b = (y, 1 - y)\f$;
  \f$S_0\f$ is inherited with its derivatives up to order \f$d\f$ on the line \f$y = 0\f$,
  \f$S_1\f$ on \f$y = 1\f$.

  With \f$n = 2\f$, Def. 3.4 reduces to
  \f$f_0 = (1-y)^{d+1} / (y^{d+1} + (1-y)^{d+1})\f$, \f$f_1 = 1 - f_0\f$.
  Sub-surfaces are callables as in `Triangular_blending_scheme`.
  \tparam FT a number type
  \tparam BlendingFunctions a blending-function policy, e.g. `Fang_blending_functions`
*/
template <class FT, class BlendingFunctions = Fang_blending_functions>
class Binary_blending_scheme {
public:
  /// the blending-function policy
  using Blending_functions = BlendingFunctions;
  /// the number of sub-surfaces
  static constexpr std::size_t number_of_sub_surfaces = 2;

  /// creates the scheme of order `order`.
  /// \throws Invalid_input if `order` < 0
  /// \param order the order
  /// \param functions the blending functions
  explicit Binary_blending_scheme(int order, const BlendingFunctions& functions = {})
      : m_order(order), m_functions(functions) {
    internal::check_order(order, "Binary_blending_scheme");
  }

  /// returns the blending order \f$d\f$.
  /// \returns the blending order \f$d\f$
  int order() const { return m_order; }

  /// returns the indicators \f$(y, 1 - y)\f$ (eq.\ 5.7); `x` is not used.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param y the \f$y\f$ coordinate
  /// \returns the indicators
  template <class T>
  std::vector<T> indicators(const T& /* x */, const T& y) const {
    const T other = FT(1) - y;
    return {y, other};
  }

  /// returns \f$f_0, f_1\f$ at \f$(x, y)\f$.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param x the \f$x\f$ coordinate
  /// \param y the \f$y\f$ coordinate
  /// \returns \f$f_0, f_1\f$ at \f$(x, y)\f$
  template <class T>
  std::vector<T> weights(const T& x, const T& y) const {
    return m_functions(indicators(x, y), m_order);
  }

  /// returns \f$f_0 S_0 + f_1 S_1\f$ at \f$(x, y)\f$ (eq.\ 5.6).
  /// \tparam T a number type or a `Taylor_jet`
  /// \tparam S0 a callable `s(u, v)`
  /// \tparam S1 a callable `s(u, v)`
  /// \param x the \f$x\f$ coordinate
  /// \param y the \f$y\f$ coordinate
  /// \param s0 the callable of the first sub-surface \f$S_0\f$
  /// \param s1 the callable of the second sub-surface \f$S_1\f$
  /// \returns the blended value
  template <class T, class S0, class S1>
  auto blend(const T& x, const T& y, const S0& s0, const S1& s1) const {
    using Value = std::decay_t<decltype(s0(x, y))>;
    const std::vector<Value> values{s0(x, y), s1(x, y)};
    return internal::weighted_sum(weights(x, y), values);
  }

private:
  int m_order;
  BlendingFunctions m_functions;
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief how `Multi_sided_blending_scheme` measures the distance to a side.
*/
enum class Side_distance {
  /// the Euclidean distance to the side's line (Fang, Def.\ 7.2); needs a square root of
  /// each side length, taken with `CGAL::approximate_sqrt()` (exact for `double`)
  EUCLIDEAN,
  /// the Euclidean distance times the side length (a 2x2 determinant): rational, so exact
  /// with an exact number type; same zero sets, hence the same inheritance (Thm.\ 7.1), but
  /// different blending functions when the sides have different lengths
  SCALED
};

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the multi-sided blending scheme (Fang, §7.1): \f$n \ge 3\f$ sub-surfaces over a
  strictly convex polygon \f$P_0 \dots P_{n-1}\f$ (counter-clockwise), with the indicators
  \f$m_i\f$ = distance to the line of side \f$B_i = P_i P_{i+1}\f$ (Def. 7.2).

  Sub-surface \f$S_i\f$ is inherited, with derivatives up to order \f$d\f$, on side
  \f$B_i\f$; at corner \f$P_i\f$ the sides \f$B_{i-1}\f$ and \f$B_i\f$ meet, and the blend
  there needs \f$S_{i-1}\f$ and \f$S_i\f$ to agree (Thm. 7.1). Strict convexity
  guarantees that inside the polygon at most two indicators vanish.

  \tparam GeomTraits a model of `Kernel` (its `FT` and `Point_2`)
  \tparam BlendingFunctions a blending-function policy
*/
template <class GeomTraits, class BlendingFunctions = Fang_blending_functions>
class Multi_sided_blending_scheme {
public:
  /// the kernel
  using Geom_traits = GeomTraits;
  /// its number type
  using FT = typename GeomTraits::FT;
  /// its 2D point type
  using Point_2 = typename GeomTraits::Point_2;
  /// the blending-function policy
  using Blending_functions = BlendingFunctions;

  /*!
    creates the scheme over `polygon`.
    \throws Invalid_input if `order` < 0, the polygon has fewer than 3 vertices, or is not
    strictly convex and counter-clockwise (three consecutive corners collinear or turning
    clockwise, or the boundary winding more than once) — the non-convex faces of Fang
    §9.1.4
    \param polygon the corners of the convex polygon, counter-clockwise
    \param order the order
    \param distance the distance to the side lines used as indicators
    \param functions the blending functions
  */
  Multi_sided_blending_scheme(std::vector<Point_2> polygon, int order,
                              Side_distance distance = Side_distance::EUCLIDEAN,
                              const BlendingFunctions& functions = {})
      : m_polygon(std::move(polygon)), m_order(order), m_functions(functions) {
    internal::check_order(order, "Multi_sided_blending_scheme");
    const std::size_t n = m_polygon.size();
    if (n < 3)
      throw Invalid_input("Multi_sided_blending_scheme: a polygon needs at least 3 corners, got " +
                          std::to_string(n));
    check_strictly_convex(m_polygon, "Multi_sided_blending_scheme");
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& a = m_polygon[i];
      const Point_2& b = m_polygon[(i + 1) % n];
      FT scale(1);
      if (distance == Side_distance::EUCLIDEAN) {
        const FT squared = (b.x() - a.x()) * (b.x() - a.x()) + (b.y() - a.y()) * (b.y() - a.y());
        scale = FT(CGAL::approximate_sqrt(squared));
      }
      // m_i(x, y) = (cross(b - a, p - a)) / scale = c0 + cx x + cy y
      const FT cx = -(b.y() - a.y()) / scale;
      const FT cy = (b.x() - a.x()) / scale;
      const FT c0 = -(cx * a.x() + cy * a.y());
      m_sides.push_back({{c0, cx, cy}});
    }
  }

  /// returns the number of sides \f$n\f$.
  /// \returns the number of sides \f$n\f$
  std::size_t number_of_sub_surfaces() const { return m_polygon.size(); }
  /// returns the polygon.
  /// \returns the polygon
  const std::vector<Point_2>& polygon() const { return m_polygon; }
  /// returns the blending order \f$d\f$.
  /// \returns the blending order \f$d\f$
  int order() const { return m_order; }

  /// returns the indicators \f$m_0, \dots, m_{n-1}\f$ at \f$(x, y)\f$: the signed distances to
  /// the side lines, positive inside.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param x the \f$x\f$ coordinate
  /// \param y the \f$y\f$ coordinate
  /// \returns the indicators
  template <class T>
  std::vector<T> indicators(const T& x, const T& y) const {
    std::vector<T> m;
    m.reserve(m_sides.size());
    for (const std::array<FT, 3>& s : m_sides) {
      const T value = x * s[1] + y * s[2] + s[0];
      m.push_back(value);
    }
    return m;
  }

  /// returns the blending functions \f$f_i^{n,d,m}\f$ at \f$(x, y)\f$.
  /// \tparam T a number type or a `Taylor_jet`
  /// \param x the \f$x\f$ coordinate
  /// \param y the \f$y\f$ coordinate
  /// \returns the blending functions \f$f_i^{n,d,m}\f$ at \f$(x, y)\f$
  template <class T>
  std::vector<T> weights(const T& x, const T& y) const {
    return m_functions(indicators(x, y), m_order);
  }

  /// returns \f$\sum_i f_i S_i\f$ at \f$(x, y)\f$ (eq.\ 7.1); `sub_surfaces` is a container of
  /// \f$n\f$ callables `s(x, y)` of one type (e.g.\ `std::function`).
  /// \tparam T a number type or a `Taylor_jet`
  /// \tparam Container a container of callables `s(x, y)`
  /// \param x the \f$x\f$ coordinate
  /// \param y the \f$y\f$ coordinate
  /// \param sub_surfaces the \f$n\f$ sub-surfaces, callables `s(x, y)`
  /// \returns the blended value
  template <class T, class Container>
  auto blend(const T& x, const T& y, const Container& sub_surfaces) const {
    using Value = std::decay_t<decltype((*sub_surfaces.begin())(x, y))>;
    std::vector<Value> values;
    for (const auto& s : sub_surfaces)
      values.push_back(s(x, y));
    return internal::weighted_sum(weights(x, y), values);
  }

  /// throws `Invalid_input` (prefixed by `who`) unless `polygon` is strictly convex and
  /// counter-clockwise; exact with exact predicates or an exact `FT`.
  /// \param polygon the corners of the polygon
  /// \param who the prefix of the error message
  static void check_strictly_convex(const std::vector<Point_2>& polygon, const std::string& who) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2& a = polygon[(i + n - 1) % n];
      const Point_2& b = polygon[i];
      const Point_2& c = polygon[(i + 1) % n];
      if (CGAL::orientation(a, b, c) != CGAL::LEFT_TURN)
        throw Invalid_input(who + ": the polygon is not strictly convex at corner " +
                            std::to_string(i) +
                            " (collinear or clockwise turn); Fang's multi-sided indicators "
                            "need convex faces (§7.1, §9.1.4)");
    }
    // all left turns: convex iff the boundary winds once (the corners are angularly sorted
    // around the first one)
    for (std::size_t i = 1; i + 1 < n; ++i)
      if (CGAL::orientation(polygon[0], polygon[i], polygon[i + 1]) != CGAL::LEFT_TURN)
        throw Invalid_input(who + ": the polygon winds more than once (self-intersecting)");
  }

private:
  std::vector<Point_2> m_polygon;
  int m_order;
  BlendingFunctions m_functions;
  std::vector<std::array<FT, 3>> m_sides;
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_SCHEMES_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_DIFFERENTIAL_GEOMETRY_H
#define CGAL_TRIANGULAR_SPLINE_DIFFERENTIAL_GEOMETRY_H

#include <CGAL/Triangular_spline/Bezier_triangle.h>
#include <CGAL/Triangular_spline/internal/array_vector_3.h>
#include <CGAL/Triangular_spline/internal/values_as_3d.h>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief the first and second partial derivatives of a patch at a point, as 3D vectors in
  `double`.

  For a functional patch \f$z = F(x,y)\f$ the surface is the graph \f$(x, y, F(x,y))\f$; for a
  parametric patch it is \f$F\f$ itself. The derivatives come from the exact blossom and are
  converted to `double` only at the end.
*/
struct Surface_derivatives {
  std::array<double, 3> fx, fy, fxx, fxy,
      fyy; ///< \f$\partial_x, \partial_y, \partial_{xx}, \partial_{xy}, \partial_{yy}\f$
  /// \var fx
  /// the first derivative \f$\partial_x\f$
  /// \var fy
  /// the first derivative \f$\partial_y\f$
  /// \var fxx
  /// the second derivative \f$\partial_{xx}\f$
  /// \var fxy
  /// the mixed second derivative \f$\partial_{xy}\f$
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief the differential-geometric quantities at a point: unit normal (oriented by
  \f$F_x \times F_y\f$, i.e. upward for a functional patch), Gaussian curvature \f$K\f$
  and mean curvature \f$H = (\kappa_1+\kappa_2)/2\f$ with respect to that normal.
*/
struct Surface_curvature {
  std::array<double, 3> normal; ///< unit normal; all zero where the surface is singular
  double gaussian = 0;          ///< \f$K = (LN - M^2)/(EG - F^2)\f$
  double mean = 0;              ///< \f$H = (EN - 2FM + GL)/(2(EG - F^2))\f$
  bool regular = true;          ///< `false` where \f$F_x \times F_y = 0\f$ (values are NaN)
};

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the first and second derivatives of the surface of `patch` at `a`.
  \tparam Value a scalar (graph surface) or a 3D vector type
  \tparam GeomTraits a model of `Kernel`
  \param patch the Bézier patch
  \param a the point of the domain plane
  \returns the first and second derivatives of the surface of `patch` at `a`
*/
template <class GeomTraits, class Value>
Surface_derivatives surface_derivatives(const Bezier_triangle<GeomTraits, Value>& patch,
                                        const typename GeomTraits::Point_2& a) {
  constexpr int dimension = Value_traits<Value>::dimension;
  static_assert(dimension == 1 || dimension == 3,
                "normals and curvatures need functional or 3D parametric patches");
  constexpr bool graph = (dimension == 1);
  Surface_derivatives d;
  d.fx = internal::as_3d(patch.partial_derivative(a, 1, 0), graph, 1, 0);
  d.fy = internal::as_3d(patch.partial_derivative(a, 0, 1), graph, 0, 1);
  d.fxx = internal::as_3d(patch.partial_derivative(a, 2, 0), graph, 0, 0);
  d.fxy = internal::as_3d(patch.partial_derivative(a, 1, 1), graph, 0, 0);
  d.fyy = internal::as_3d(patch.partial_derivative(a, 0, 2), graph, 0, 0);
  return d;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the unit normal, Gaussian and mean curvature from first and second
  derivatives (`double`).

  \f$EG - F^2\f$ is computed as \f$|F_x \times F_y|^2\f$, the same quantity without the
  cancellation of \f$EG - F^2\f$ on steep surfaces (where \f$E G\f$ and \f$F^2\f$ are both
  of size \f$|\nabla F|^4\f$).
  \param d the first and second derivatives
  \returns the unit normal, Gaussian and mean curvature from first and second derivatives (`double`)
*/
inline Surface_curvature surface_curvature(const Surface_derivatives& d) {
  Surface_curvature result;
  const std::array<double, 3> n = internal::cross(d.fx, d.fy);
  const double first = internal::dot(n, n);
  const double length = std::sqrt(first);
  if (!(length > 0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    result.normal = {{0, 0, 0}};
    result.gaussian = result.mean = nan;
    result.regular = false;
    return result;
  }
  result.normal = {{n[0] / length, n[1] / length, n[2] / length}};
  const double E = internal::dot(d.fx, d.fx), F = internal::dot(d.fx, d.fy),
               G = internal::dot(d.fy, d.fy);
  const double L = internal::dot(d.fxx, result.normal), M = internal::dot(d.fxy, result.normal),
               N = internal::dot(d.fyy, result.normal);
  result.gaussian = (L * N - M * M) / first;
  result.mean = (E * N - 2 * F * M + G * L) / (2 * first);
  return result;
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the unit normal, Gaussian and mean curvature of the surface of `patch` at
  `a`, from the exact first and second derivatives (square roots are taken in `double`).
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param patch the Bézier patch
  \param a the point of the domain plane
  \returns the unit normal, Gaussian and mean curvature of the surface of `patch` at `a`, from the
  exact first and second derivatives (square roots are taken in `double`)
*/
template <class GeomTraits, class Value>
Surface_curvature surface_curvature(const Bezier_triangle<GeomTraits, Value>& patch,
                                    const typename GeomTraits::Point_2& a) {
  return surface_curvature(surface_derivatives(patch, a));
}

/*!
  \ingroup PkgTriangularSplineCore
  \brief returns the unit normal of the surface of `patch` at `a` (see `surface_curvature()`),
  zero where the surface is singular.
  \tparam GeomTraits a model of `Kernel`
  \tparam Value `GeomTraits::FT` (functional) or a vector type (parametric)
  \param patch the Bézier patch
  \param a the point of the domain plane
  \returns the unit normal of the surface of `patch` at `a` (see `surface_curvature()`), zero where
  the surface is singular
*/
template <class GeomTraits, class Value>
std::array<double, 3> surface_normal(const Bezier_triangle<GeomTraits, Value>& patch,
                                     const typename GeomTraits::Point_2& a) {
  constexpr bool graph = (Value_traits<Value>::dimension == 1);
  const std::array<double, 3> n =
      internal::cross(internal::as_3d(patch.partial_derivative(a, 1, 0), graph, 1, 0),
                      internal::as_3d(patch.partial_derivative(a, 0, 1), graph, 0, 1));
  const double length = std::sqrt(internal::dot(n, n));
  if (!(length > 0))
    return {{0, 0, 0}};
  return {{n[0] / length, n[1] / length, n[2] / length}};
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_DIFFERENTIAL_GEOMETRY_H

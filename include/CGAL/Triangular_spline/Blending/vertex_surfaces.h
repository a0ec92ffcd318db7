// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_VERTEX_SURFACES_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_VERTEX_SURFACES_H

#include <CGAL/Triangular_spline/Blending/Interpolation_condition.h>
#include <CGAL/Triangular_spline/Polynomial_surface.h>
#include <CGAL/Triangular_spline/exceptions.h>
#include <CGAL/Triangular_spline/internal/vertex_surfaces.h>

#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the height functions \f$z = P(x, y)\f$ of the vertex surfaces in their vertex frames
  (Fang §5.2.1): the package's one bivariate polynomial class, `Polynomial_surface`, with
  `double` coefficients, evaluated on numbers or `Taylor_jet`s by its Horner
  `operator()` (exact derivatives come with the jets).

  Fang's frames need square roots, so the vertex surfaces are computed in `double` whatever
  the input kernel; `CGAL::Simple_cartesian<double>` only provides that number type.
  `coefficient(h, k)` and `set_coefficient(h, k, c)` require \f$h + k \le\f$ `degree()`.
*/
using Bivariate_polynomial = Polynomial_surface<CGAL::Simple_cartesian<double>>;

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns de Boor and Ron's least interpolant: the polynomial of the least space of
  the conditions that satisfies them (de Boor, Ron, *Computational aspects of polynomial
  interpolation in several variables*, Math. Comp. 58, 1992), which Fang uses for the vertex
  surfaces (§5.2.1).

  Each condition \f$\lambda\f$ has the generating function
  \f$g_\lambda(x) = \lambda_\theta(e^{\theta \cdot x}) = \sum_\alpha \lambda(\theta^\alpha)
  x^\alpha / \alpha!\f$ (\f$e^{p \cdot x}\f$ for a value at \f$p\f$, \f$x_1 e^{p\cdot x}\f$
  for \f$\partial_x\f$ at \f$p\f$). The least space is spanned by the least terms (lowest
  homogeneous parts) of all combinations of the \f$g_\lambda\f$. It is computed by Gaussian
  elimination by degree: at degree \f$k\f$ the rows still unassigned are combined (the
  orthogonal transformation of a column-pivoted QR of their degree-\f$k\f$ block) so that
  the first
  \f$r_k\f$ have independent degree-\f$k\f$ parts — these are least terms — and the others
  have none; the others go on to degree \f$k+1\f$. The interpolant is then the combination
  of the least terms that satisfies the conditions (a square system, solved by
  column-pivoted QR).

  The space has the properties that make it the natural choice: it depends only on the
  conditions (not on a coordinate choice or a degree), it is invariant under rotations, it
  has minimal degree, and it contains all polynomials of degree \f$k\f$ when the conditions
  are enough for them. For the data of a vertex of valence 6 (value and gradient at the
  vertex, values at the six neighbours) it is the quadratics plus three cubics.

  The rank decisions are made in `double` with the threshold `tolerance` (relative to the
  largest entry) on the pivots of the QR: nearly dependent degree blocks (for example neighbours
  almost on a conic) count as dependent, so that the interpolant does not take huge coefficients
  from round-off.

  \param conditions the conditions; they must be independent on polynomials (distinct
  points, at most one value per point)
  \param tolerance relative threshold for the rank decisions
  \throws Invalid_input if the conditions are dependent (they do not determine an interpolant)
  \returns de Boor and Ron's least interpolant
*/
inline Bivariate_polynomial
least_interpolant(const std::vector<Interpolation_condition>& conditions,
                  double tolerance = 1e-10) {
  const int N = static_cast<int>(conditions.size());
  if (N == 0)
    return Bivariate_polynomial(0);
  const int max_degree = N; // a least space of N conditions has degree < N
  const int columns = (max_degree + 1) * (max_degree + 2) / 2;
  auto column = [](int h, int k) { return (h + k) * (h + k + 1) / 2 + k; };
  // W(i, alpha) = lambda_i(x^alpha) / alpha!: the power series of g_lambda_i
  Eigen::MatrixXd W(N, columns);
  double largest = 0;
  for (int i = 0; i < N; ++i)
    for (int h = 0; h <= max_degree; ++h)
      for (int k = 0; h + k <= max_degree; ++k) {
        const double v =
            internal::apply_to_monomial(conditions[static_cast<std::size_t>(i)], h, k) /
            (internal::factorial(h) * internal::factorial(k));
        W(i, column(h, k)) = v;
        largest = (std::max)(largest, std::fabs(v));
      }
  const double threshold = tolerance * (std::max)(1.0, largest);

  std::vector<Bivariate_polynomial> basis; // the least terms
  int first_unassigned = 0;                // rows [first_unassigned, N) are not assigned
  for (int k = 0; k <= max_degree && first_unassigned < N; ++k) {
    const int m = N - first_unassigned;
    const int begin = column(k, 0);
    const Eigen::MatrixXd block = W.block(first_unassigned, begin, m, k + 1);
    // block * P = Q * R (column-pivoted Householder QR): Q^T is an orthogonal combination of
    // the rows whose first `rank` rows have independent degree-k parts and the others none
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(block);
    qr.setThreshold(threshold / (std::max)(1.0, qr.maxPivot()));
    const int rank = static_cast<int>(qr.rank());
    if (rank == 0)
      continue;
    const Eigen::MatrixXd Q = qr.householderQ();
    const Eigen::MatrixXd rotated = Q.transpose() * W.block(first_unassigned, 0, m, columns);
    W.block(first_unassigned, 0, m, columns) = rotated;
    for (int r = 0; r < rank; ++r) {
      Bivariate_polynomial q(k);
      for (int b = 0; b <= k; ++b)
        q.set_coefficient(k - b, b, W(first_unassigned + r, begin + b));
      basis.push_back(q);
    }
    // the remaining rows have (numerically) no degree-k part
    W.block(first_unassigned + rank, begin, m - rank, k + 1).setZero();
    first_unassigned += rank;
  }
  if (first_unassigned < N)
    throw Invalid_input("least_interpolant: the " + std::to_string(N) +
                        " conditions are not independent (coincident points?)");
  // p = sum_j c_j q_j with lambda_i(p) = y_i
  Eigen::MatrixXd A(N, N);
  Eigen::VectorXd y(N);
  int degree = 0;
  for (int i = 0; i < N; ++i) {
    y(i) = conditions[static_cast<std::size_t>(i)].value;
    for (int j = 0; j < N; ++j)
      A(i, j) = internal::apply(conditions[static_cast<std::size_t>(i)],
                                basis[static_cast<std::size_t>(j)]);
  }
  for (const Bivariate_polynomial& q : basis)
    degree = (std::max)(degree, q.degree());
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < N)
    throw Invalid_input("least_interpolant: singular interpolation system");
  const Eigen::VectorXd c = qr.solve(y);
  Bivariate_polynomial p(degree);
  for (int j = 0; j < N; ++j) {
    const Bivariate_polynomial& q = basis[static_cast<std::size_t>(j)];
    const int k = q.degree();
    for (int b = 0; b <= k; ++b)
      p.set_coefficient(k - b, b, p.coefficient(k - b, b) + c(j) * q.coefficient(k - b, b));
  }
  return p;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the polynomial of degree at most `degree` that satisfies the `exact`
  conditions and fits the `fitted` ones in the least-squares sense — the plain alternative
  to `least_interpolant()` for the vertex surfaces.

  The exact conditions are eliminated first (a particular solution and an orthonormal
  null-space basis of their matrix, from a column-pivoted QR), the fitted ones are then
  solved in the least-squares sense with minimum norm (complete orthogonal decomposition),
  so the problem may be under- or over-determined.

  \throws Invalid_input if `degree` < 0 or the exact conditions are inconsistent or
  dependent for this degree
  \param exact the conditions to meet exactly
  \param fitted the conditions to meet in the least-squares sense
  \param degree the largest degree of the polynomial
  \returns the fitted polynomial
*/
inline Bivariate_polynomial
least_squares_polynomial(const std::vector<Interpolation_condition>& exact,
                         const std::vector<Interpolation_condition>& fitted, int degree) {
  if (degree < 0)
    throw Invalid_input("least_squares_polynomial: negative degree");
  const int M = (degree + 1) * (degree + 2) / 2;
  auto row = [degree, M](const Interpolation_condition& c) {
    Eigen::RowVectorXd r(M);
    for (int h = 0; h <= degree; ++h)
      for (int k = 0; h + k <= degree; ++k)
        r((h + k) * (h + k + 1) / 2 + k) = internal::apply_to_monomial(c, h, k);
    return r;
  };
  const int E = static_cast<int>(exact.size()), L = static_cast<int>(fitted.size());
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(M);
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(M, M); // free directions
  if (E > 0) {
    Eigen::MatrixXd C(E, M);
    Eigen::VectorXd e(E);
    for (int i = 0; i < E; ++i) {
      C.row(i) = row(exact[static_cast<std::size_t>(i)]);
      e(i) = exact[static_cast<std::size_t>(i)].value;
    }
    // C^T P = Q [R; 0]: C = P R^T Q_1^T; x0 = Q_1 R^{-T} P^T e, null space Q_2
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C.transpose());
    if (qr.rank() < E)
      throw Invalid_input("least_squares_polynomial: the exact conditions are dependent for "
                          "degree " +
                          std::to_string(degree));
    const Eigen::MatrixXd Q = qr.householderQ();
    const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(E, E);
    const Eigen::VectorXd Pe = qr.colsPermutation().transpose() * e;
    const Eigen::VectorXd y = R.transpose().triangularView<Eigen::Lower>().solve(Pe);
    x0 = Q.leftCols(E) * y;
    Z = Q.rightCols(M - E);
  }
  Eigen::VectorXd x = x0;
  if (L > 0 && Z.cols() > 0) {
    Eigen::MatrixXd A(L, M);
    Eigen::VectorXd b(L);
    for (int i = 0; i < L; ++i) {
      A.row(i) = row(fitted[static_cast<std::size_t>(i)]);
      b(i) = fitted[static_cast<std::size_t>(i)].value;
    }
    const Eigen::MatrixXd AZ = A * Z;
    // minimum-norm least squares (the fit may be under-determined)
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(AZ);
    const Eigen::VectorXd t = cod.solve(Eigen::VectorXd(b - A * x0));
    x = x0 + Z * t;
  }
  Bivariate_polynomial p(degree);
  for (int h = 0; h <= degree; ++h)
    for (int k = 0; h + k <= degree; ++k)
      p.set_coefficient(h, k, x((h + k) * (h + k + 1) / 2 + k));
  return p;
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_VERTEX_SURFACES_H

// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_EXCEPTIONS_H
#define CGAL_TRIANGULAR_SPLINE_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineCore
  \brief is thrown when the input of a construction is invalid: a degenerate domain
  triangle, a control net of the wrong size, patches of different degrees, non-finite
  numbers, etc.

  The message names the offending object and says why it is rejected, so that the
  command-line tool can print it as one line. Violated preconditions of the library
  itself (programming errors) are reported by `CGAL::Failure_exception` instead.
*/
class Invalid_input : public std::invalid_argument {
public:
  /// creates the exception with the message `what`.
  /// \param what the message
  explicit Invalid_input(const std::string& what) : std::invalid_argument(what) {}
};

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_EXCEPTIONS_H

// The kernel of a harness: the CLI's double kernel, or with TSPLINE_FUZZ_EXACT the kernel of
// its --exact mode, so that one source serves both builds.

#ifndef TSPLINE_FUZZ_KERNEL_H
#define TSPLINE_FUZZ_KERNEL_H

#ifdef TSPLINE_FUZZ_EXACT
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
using Fuzz_kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
#else
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
using Fuzz_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
#endif

#endif // TSPLINE_FUZZ_KERNEL_H

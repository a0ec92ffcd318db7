// libFuzzer harness: read_query_points(), as `tspline c1 --query` and `tspline eval --query`
// read their query files. Invalid_input is the expected outcome of bad input.

#include <CGAL/Triangular_spline/IO/scattered_data.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    TS::read_query_points<K>(in, "fuzz.xy");
  } catch (const TS::Invalid_input&) {
  }
  return 0;
}

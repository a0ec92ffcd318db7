// libFuzzer harness: read_xyz() (with and without gradients) and delaunay_domain(), as
// `tspline c1` and `tspline mann` read a .xyz file. Invalid_input is the expected outcome
// of bad input; anything else escaping, or a sanitizer report, is a bug.

#include <CGAL/Triangular_spline/IO/scattered_data.h>

#include "fuzz_kernel.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace TS = CGAL::Triangular_spline;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (bool gradients : {false, true}) {
    std::istringstream in(text);
    try {
      const TS::Scattered_data<Fuzz_kernel> scattered =
          TS::read_xyz<Fuzz_kernel>(in, "fuzz.xyz", gradients);
      TS::delaunay_domain(scattered);
    } catch (const TS::Invalid_input&) {
    }
  }
  return 0;
}

// libFuzzer harness: read_spline_file() as the CLI calls it (certify, adjust, render, eval):
// spline_file_dimension() sniffs the header, then the file is read with heights or points
// as values. Invalid_input is the expected outcome of bad input.

#include <CGAL/Triangular_spline/IO/spline_file.h>

#include "fuzz_kernel.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace TS = CGAL::Triangular_spline;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // A string stream is seekable, like the CLI's file stream: check_fits() takes effect.
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    if (TS::spline_file_dimension(in) == 3)
      TS::read_spline_file<Fuzz_kernel, Fuzz_kernel::Vector_3>(in, "fuzz.spline");
    else
      TS::read_spline_file<Fuzz_kernel, Fuzz_kernel::FT>(in, "fuzz.spline");
  } catch (const TS::Invalid_input&) {
  }
  return 0;
}

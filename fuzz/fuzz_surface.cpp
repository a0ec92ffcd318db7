// libFuzzer harness: `tspline certify FILE.surface` without the CLI: read_surface_file() in
// exact arithmetic (as certify reads), then the relations solved from the nets and the
// certificate. Invalid_input is the expected outcome of bad input.

#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>

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
    const TS::Surface_file<Fuzz_kernel> file = TS::read_surface_file<Fuzz_kernel>(in, "fuzz");
    const TS::Pseudo_AG1_view<TS::Surface_file<Fuzz_kernel>> view(file);
    TS::certify_pseudo_AG1(view);
  } catch (const TS::Invalid_input&) {
  }
  return 0;
}

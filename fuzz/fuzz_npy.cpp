// libFuzzer harness: read_npy() and the conversions `tspline c1`, `mann` and `eval` apply to
// a .npy input (scattered_data_from_npy() with and without gradients, query_points_from_npy(),
// delaunay_domain()). The input is read once from a seekable stream (the file case, size
// checked before allocating) and once through a stream that cannot seek (read in blocks).
// Invalid_input is the expected outcome of bad input; anything else is a bug.

#include <CGAL/Triangular_spline/IO/npy.h>

#include "fuzz_kernel.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace TS = CGAL::Triangular_spline;

namespace {

class Unseekable_buffer : public std::stringbuf {
public:
  explicit Unseekable_buffer(const std::string& s) : std::stringbuf(s) {}

protected:
  pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override {
    return pos_type(off_type(-1));
  }
  pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(off_type(-1)); }
};

void convert(const TS::Npy_array& array) {
  for (const auto& columns :
       {std::vector<std::size_t>{0, 1, 2}, std::vector<std::size_t>{2, 0, 1, 1, 0}}) {
    try {
      const auto data = TS::scattered_data_from_npy<Fuzz_kernel>(array, "fuzz.npy", columns);
      TS::delaunay_domain(data);
    } catch (const TS::Invalid_input&) {
    }
  }
  try {
    TS::query_points_from_npy<Fuzz_kernel>(array, "fuzz.npy");
  } catch (const TS::Invalid_input&) {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream in(bytes);
    convert(TS::read_npy(in, "fuzz.npy"));
  } catch (const TS::Invalid_input&) {
  }
  try {
    Unseekable_buffer buffer(bytes);
    std::istream in(&buffer);
    TS::read_npy(in, "fuzz.npy");
  } catch (const TS::Invalid_input&) {
  }
  return 0;
}

// libFuzzer harness: the shared mesh reader, which takes a path and picks the format by its
// extension. Compiled once and linked into one fuzzer per format; each defines
// tspline_fuzz_mesh_extension (see CMakeLists.txt). Invalid_input is the expected outcome
// of bad input.

#include <CGAL/Triangular_spline/IO/mesh_io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

extern const char* const tspline_fuzz_mesh_extension; // ".off", ".obj", ".ply" or ".stl"

namespace {

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// One file per process (libFuzzer's -jobs/-fork run several), in memory when /dev/shm
// exists; written for every input and removed after it (libFuzzer may leave by _exit).
const std::string& input_path() {
  static const std::string path = [] {
    const char* tmp = std::getenv("TMPDIR");
    const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : tmp ? tmp : "/tmp";
    return dir + "/tspline_fuzz_" + std::to_string(getpid()) + tspline_fuzz_mesh_extension;
  }();
  return path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = input_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out)
      std::abort(); // the harness itself failed, not the reader
  }
  // tspline c1 and mann: the height field over its (x, y) projection.
  try {
    TS::read_mesh_domain<K>(path);
  } catch (const TS::Invalid_input&) {
  }
  // tspline blend: an OFF file's vertex normals are read too (CGAL's read_OFF).
  if (std::string(tspline_fuzz_mesh_extension) == ".off") {
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    std::vector<K::Vector_3> normals;
    try {
      TS::read_mesh_soup(path, points, polygons, &normals);
    } catch (const TS::Invalid_input&) {
    }
  }
  std::remove(path.c_str());
  return 0;
}

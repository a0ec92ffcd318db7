// tspline: command-line tool of the Triangular_spline package.
// A thin layer: this file dispatches to one function per subcommand.

#include "cli.h"
#include "commands.h"

#include <CGAL/Triangular_spline/gmp_small_block_pool.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

#ifndef TRIANGULAR_SPLINE_VERSION
#error                                                                                             \
    "TRIANGULAR_SPLINE_VERSION must be defined (it comes with the CGAL::Triangular_spline target)"
#endif

namespace {

struct Command {
  std::string_view name;
  std::string_view summary;
  int (*run)(const std::vector<std::string>& args);
};

const Command commands[] = {
    {"demo", "run the main job on an embedded data set (no input needed)", tspline::run_demo},
    {"c1", "C^1 quintic spline (Xu) from scattered data or a triangulated height field",
     tspline::run_c1},
    {"certify", "certify the C^1 continuity of a saved spline exactly", tspline::run_certify},
    {"pseudo-ag1", "pseudo-AG^1 surface (Xu) over a closed triangle mesh", tspline::run_pseudo_ag1},
    {"adjust", "adjust control points to C^k continuity (Mann)", tspline::run_adjust},
    {"mann", "C^1 interpolant with polynomial precision (Mann)", tspline::run_mann},
    {"blend", "generalized blending mesh interpolation (Fang)", tspline::run_blend},
    {"render", "PNG pictures and coloured meshes of a surface", tspline::run_render},
    {"eval", "values, gradients and Hessians of a saved spline at points or on a grid",
     tspline::run_eval},
};

const Command* find_command(std::string_view name) {
  for (const Command& command : commands)
    if (command.name == name)
      return &command;
  return nullptr;
}

void print_usage(std::ostream& out) {
  out << "usage: tspline <command> [options] [arguments]\n"
         "       tspline --help | --version\n"
         "\n"
         "Triangular Bezier spline surfaces (Triangular_spline " TRIANGULAR_SPLINE_VERSION ").\n"
         "\n"
         "commands:\n";
  std::size_t width = 0;
  for (const Command& command : commands)
    width = std::max(width, command.name.size());
  for (const Command& command : commands)
    out << "  " << command.name << std::string(width - command.name.size() + 2, ' ')
        << command.summary << '\n';
  out << "\nRun 'tspline <command> --help' for the options of a command.\n";
}

// Exception messages may span several lines (CGAL's do); print them on one.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  std::string result;
  for (const char c : text) {
    if (c == '\n')
      result += "; ";
    else if (c != '\r')
      result += c;
  }
  return result;
}

// Restarts the tool once with malloc tuned for its large arrays (glibc >= 2.35 reads
// GLIBC_TUNABLES at start-up only, hence the exec). A c1 run at 10^6 points touches 1.4 GB:
// - hugetlb=1 (not with --exact): large blocks on transparent huge pages; on 4 KB pages the
//   faults and TLB misses cost 8% of the CPU (paired runs: 34.0 s against 36.9 s), and at
//   10^7 points 175.7 s against 189.5 s of wall time (system 32 s against 46 s). Exact runs
//   fault their heap in phase after phase, on one core between parallel phases, and there
//   huge pages cost more than they save (10^5 17-digit points, --exact: 0.70 s of system
//   time against 1.28 s, build + certificate 0.85x the wall time);
// - a fixed mmap threshold of 4 MB: freed large blocks go back to the system instead of
//   being kept by glibc's dynamic threshold (about 100 MB of the peak at 10^6 points: 1318
//   against 1394 MB), while the global fits' windows, which allocate and free blocks of a
//   few hundred KB thousands of times, reuse the heap. A 128 KB threshold with no trimming
//   cost them 2.5 to 3 times the CPU in page faults and mmap/munmap (energy fit at 10^5
//   points: 91 s against 31 s);
// - a trim threshold of 1 GB: the heap keeps what it freed below that. Exact builds free and
//   reallocate their GMP integers' heap phase after phase; trimmed at 32 MB, the heap went
//   back to the system and every regrowth was faulted in again as zeroed huge pages (10^5
//   17-digit points, --exact: 0.94-1.11 s of system time against 0.47-0.51 s, four pairs).
//   Peaks and double runs did not change (10^6 points: 611 MB either way).
// Tunables of malloc the user set (any glibc.malloc.*, e.g. glibc.malloc.hugetlb=0 to keep
// a run under valgrind or heaptrack in one process) are kept as they are; where the exec
// fails, the run goes on as it is.
void tune_malloc(char* argv[]) {
#if defined(__linux__) && defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string value = tunables == nullptr ? "" : tunables;
  if (value.find("glibc.malloc.") != std::string::npos)
    return;
  bool exact = false;
  for (char** a = argv + 1; *a != nullptr; ++a)
    exact = exact || std::string_view(*a) == "--exact";
  value += std::string(value.empty() ? "" : ":") + "glibc.malloc.hugetlb=" + (exact ? "0" : "1") +
           ":glibc.malloc.mmap_threshold=4194304:glibc.malloc.trim_threshold=1073741824";
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
    execv("/proc/self/exe", argv);
#else
  (void)argv;
#endif
}

} // namespace

std::string_view tspline::command_summary(std::string_view name) {
  const Command* command = find_command(name);
  return command == nullptr ? std::string_view() : command->summary;
}

int main(int argc, char* argv[]) {
  if (argc < 2) {
    print_usage(std::cerr);
    return 2;
  }
  const std::string first = argv[1];
  if (first == "--help" || first == "-h") {
    print_usage(std::cout);
    return 0;
  }
  if (first == "--version") {
    std::cout << "tspline " TRIANGULAR_SPLINE_VERSION "\n";
    return 0;
  }
  if (!first.empty() && first[0] == '-') {
    std::cerr << "tspline: unknown option '" << first << "' (see 'tspline --help')\n";
    return 2;
  }
  const Command* command = find_command(first);
  if (command == nullptr) {
    std::cerr << "tspline: unknown command '" << first << "' (see 'tspline --help')\n";
    return 2;
  }

  tune_malloc(argv);
  // Exact builds keep millions of GMP integers of one to four limbs: pooled, they take 0.6x
  // the memory and 0.8x the time (10^5 points; no effect on double builds).
  CGAL::Triangular_spline::use_gmp_small_block_pool();
  const std::vector<std::string> args(argv + 2, argv + argc);
  const std::string prefix = "tspline " + std::string(command->name) + ": ";
  try {
    return command->run(args);
  } catch (const tspline::Usage_error& e) {
    std::cerr << prefix << one_line(e.what()) << " (see 'tspline " << command->name
              << " --help')\n";
    return 2;
  } catch (const std::exception& e) {
    // std::invalid_argument, std::runtime_error, CGAL::Failure_exception, ...
    std::cerr << prefix << "error: " << one_line(e.what()) << '\n';
    return 1;
  } catch (...) {
    std::cerr << prefix << "error: unknown exception\n";
    return 1;
  }
}

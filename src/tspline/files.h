// Small helpers shared by the subcommands: timing, file names, opening files with one-line
// errors. C++17 standard library only.

#ifndef TSPLINE_FILES_H
#define TSPLINE_FILES_H

#include <chrono>
#include <fstream>
#include <string>

namespace tspline {

// Seconds since construction or since the previous lap.
class Stopwatch {
public:
  double lap();

private:
  std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

// CPU seconds (user + system, every thread of the process, finished ones included) since
// construction or since the previous lap: what a stage costs on a shared machine, where wall
// time depends on the other jobs.
class Cpu_stopwatch {
public:
  double lap();

private:
  double m_last = now();
  static double now();
};

// The process's peak resident memory so far in MB (VmHWM of /proc/self/status); -1 where
// the system does not say (not Linux).
double peak_memory_mb();

// The extension of the file name (after the last dot of the last path component),
// lowercase; empty if there is none.
std::string lowercase_extension(const std::string& path);

// Writes "tspline <command>: <stage>..." on stderr when stderr is a terminal and the work is
// large enough to take about a second; silent otherwise (logs and pipes stay clean).
void progress(const std::string& command, const std::string& stage, bool large);

// Open a file or throw std::runtime_error("cannot open 'path'" / "cannot write 'path'").
std::ifstream open_input(const std::string& path);
std::ofstream open_output(const std::string& path);

} // namespace tspline

#endif // TSPLINE_FILES_H

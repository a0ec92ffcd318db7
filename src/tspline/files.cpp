#include "files.h"

#include <cctype>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <sys/resource.h>
#include <unistd.h>

namespace tspline {

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024; // "VmHWM:   123456 kB"
  return -1;
}

double Stopwatch::lap() {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - m_last).count();
  m_last = now;
  return s;
}

double Cpu_stopwatch::now() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0)
    return 0;
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double Cpu_stopwatch::lap() {
  const double now_seconds = now();
  const double s = now_seconds - m_last;
  m_last = now_seconds;
  return s;
}

std::string lowercase_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void progress(const std::string& command, const std::string& stage, bool large) {
  static const bool terminal = isatty(fileno(stderr)) != 0;
  if (terminal && large)
    std::cerr << "tspline " << command << ": " << stage << "..." << std::endl;
}

std::ifstream open_input(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot open '" + path + "'");
  return in;
}

std::ofstream open_output(const std::string& path) {
  std::ofstream out(path);
  if (!out)
    throw std::runtime_error("cannot write '" + path + "'");
  return out;
}

} // namespace tspline

#include "cli.h"

#include "files.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <sys/stat.h>
#include <unistd.h>

namespace tspline {

namespace {

std::string system_reason() {
  return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
}

} // namespace

void write_json_report(const std::string& path, const Json& report) {
  Json document = Json::object();
  document["format_version"] = report_format_version;
  for (auto it = report.begin(); it != report.end(); ++it)
    if (it.key() != "format_version")
      document[it.key()] = *it;
  // File names need not be UTF-8: replace bad bytes rather than throw after the work is done.
  const std::string text = document.dump(2, ' ', false, Json::error_handler_t::replace) + '\n';

  errno = 0;
  if (path == "-") {
    std::cout << text << std::flush;
    if (!std::cout)
      throw std::runtime_error("writing the report to stdout failed" + system_reason());
    return;
  }
  std::ofstream file(path);
  if (!file)
    throw std::runtime_error("cannot write '" + path + "'" + system_reason());
  file << text;
  file.close(); // flushes: a full disk shows up here
  if (!file)
    throw std::runtime_error("writing '" + path + "' failed" + system_reason());
}

void check_output_path(const std::string& path, const std::string& option,
                       const Output_rule& rule) {
  if (path.empty())
    throw Usage_error("option '" + option + "' needs a file name");
  if (path == "-") {
    if (rule.stdout_allowed)
      return;
    throw Usage_error("option '" + option + "' cannot write to stdout ('-'): give a file name");
  }
  struct stat status;
  const bool exists = ::stat(path.c_str(), &status) == 0;
  if (rule.directory) {
    if (exists && !S_ISDIR(status.st_mode))
      throw std::runtime_error("cannot write into '" + path + "': not a directory");
    return; // created, with its parents, by the command
  }
  if (!rule.extensions.empty()) {
    const std::string extension = lowercase_extension(path);
    if (std::find(rule.extensions.begin(), rule.extensions.end(), extension) ==
        rule.extensions.end()) {
      std::string allowed;
      for (std::size_t i = 0; i < rule.extensions.size(); ++i)
        allowed += (i == 0                            ? "."
                    : i + 1 == rule.extensions.size() ? " or ."
                                                      : ", .") +
                   rule.extensions[i];
      throw Usage_error("option '" + option + "' expects a file name ending in " + allowed +
                        ", got '" + path + "'");
    }
  }

  // Fail now rather than after a long computation; the write itself is checked again.
  errno = 0;
  if (exists) {
    if (S_ISDIR(status.st_mode))
      throw std::runtime_error("cannot write '" + path + "': it is a directory");
    if (::access(path.c_str(), W_OK) != 0)
      throw std::runtime_error("cannot write '" + path + "'" + system_reason());
    return;
  }
  std::string parent = std::filesystem::path(path).parent_path().string();
  if (parent.empty())
    parent = ".";
  if (::stat(parent.c_str(), &status) != 0 || !S_ISDIR(status.st_mode))
    throw std::runtime_error("cannot write '" + path + "': no directory '" + parent + "'");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error("cannot write '" + path + "'" + system_reason());
}

} // namespace tspline

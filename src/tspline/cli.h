// The report-writing and error layer shared by the subcommands of `tspline` and their jobs:
// the usage error, JSON reports (nlohmann-json) and the checks of output paths. The
// argument parser itself is in command_line.h (CLI11), which only the subcommands include.

#ifndef TSPLINE_CLI_H
#define TSPLINE_CLI_H

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace tspline {

// Bad command-line usage (unknown option, missing value, wrong number of
// arguments). `main` prints it on one line and exits with status 2.
class Usage_error : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

// Reports keep their keys in insertion order: readable, and stable to diff. Doubles are
// written so that they read back exactly; NaN and infinities are written as null.
using Json = nlohmann::ordered_json;

// The version of the layout of every JSON report, written first as "format_version".
// Raise it when a key is removed or changes meaning (adding keys keeps it).
constexpr int report_format_version = 1;

// Writes `report` (an object) to `path`, '-' for stdout, with "format_version" first.
// Throws std::runtime_error naming the path if the file cannot be opened or the write fails
// (checked after closing, so a full disk is an error, not a truncated report).
void write_json_report(const std::string& path, const Json& report);

// What an output option accepts. `extensions` empty: any name.
struct Output_rule {
  std::vector<std::string> extensions; // lowercase, without the dot
  bool stdout_allowed = false;         // '-' writes to stdout
  bool directory = false;              // the path is a directory, created if needed
};

// Meshes are written in the format their extension names (CGAL::Triangular_spline::write_mesh).
inline const Output_rule mesh_file_output{{"ply", "off", "obj"}, false, false};

// Checks an output path before any work is done: throws Usage_error for a wrong extension
// or '-' where stdout is not allowed, std::runtime_error ("cannot write 'PATH': ...") when the
// file could not be created (missing or unwritable directory, the path is a directory).
// `option` is the option's name with its dashes, for the messages.
void check_output_path(const std::string& path, const std::string& option, const Output_rule& rule);

} // namespace tspline

#endif // TSPLINE_CLI_H

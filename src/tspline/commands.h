// Entry points of the `tspline` subcommands, one file each; `main.cpp` holds
// the dispatch table. C++17 standard library only.

#ifndef TSPLINE_COMMANDS_H
#define TSPLINE_COMMANDS_H

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace tspline {

// Each returns the process exit status: 0 success, 1 failure, 3 not implemented.
// They may throw: `Usage_error` (exit 2) and any `std::exception` (exit 1) are
// turned into one line on stderr by `main`.
int run_demo(const std::vector<std::string>& args);
int run_c1(const std::vector<std::string>& args);
int run_certify(const std::vector<std::string>& args);
int run_pseudo_ag1(const std::vector<std::string>& args);
int run_adjust(const std::vector<std::string>& args);
int run_mann(const std::vector<std::string>& args);
int run_blend(const std::vector<std::string>& args);
int run_render(const std::vector<std::string>& args);
int run_eval(const std::vector<std::string>& args);

// The one-line summary of a subcommand from the dispatch table (empty if unknown).
std::string_view command_summary(std::string_view name);

} // namespace tspline

#endif // TSPLINE_COMMANDS_H

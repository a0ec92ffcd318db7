// Subcommands that are registered but not implemented yet. Each accepts
// --help and otherwise exits with status 3, naming the issue that tracks it.

#include "command_line.h"
#include "commands.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {
namespace {

int not_implemented(const std::string& command, int issue, const std::vector<std::string>& args) {
  // issue 0: planned (SPEC) but not yet tracked by an issue
  const std::string status =
      issue > 0 ? "not implemented yet (tracked in issue " + std::to_string(issue) + ")"
                : "not implemented yet (Xu ch. 5-6, SPEC section 4; no issue yet)";
  if (Command_line::help_requested(args)) {
    Command_line cl(command);
    cl.describe("Status: " + status + ".");
    std::cout << cl.help();
    return 0;
  }
  std::cerr << "tspline " << command << ": " << status << '\n';
  return 3;
}

} // namespace

int run_pseudo_ag1(const std::vector<std::string>& args) {
  return not_implemented("pseudo-ag1", 0, args);
}

} // namespace tspline

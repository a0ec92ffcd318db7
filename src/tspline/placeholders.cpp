// Subcommands that are registered but not implemented yet. Each accepts
// --help and otherwise exits with status 3, naming the issue that tracks it.

#include "cli.h"
#include "commands.h"

#include <iostream>
#include <string>
#include <vector>

namespace tspline {
namespace {

int not_implemented(const std::string& command, int issue, const std::vector<std::string>& args) {
  const std::string status = "not implemented yet (tracked in issue " + std::to_string(issue) + ")";
  for (const std::string& arg : args) {
    if (arg == "--")
      break;
    if (arg == "--help" || arg == "-h") {
      Argument_parser parser(command, std::string(command_summary(command)));
      parser.describe("Status: " + status + ".");
      std::cout << parser.help();
      return 0;
    }
  }
  std::cerr << "tspline " << command << ": " << status << '\n';
  return 3;
}

} // namespace

int run_pseudo_ag1(const std::vector<std::string>& args) {
  return not_implemented("pseudo-ag1", 3, args);
}
int run_adjust(const std::vector<std::string>& args) {
  return not_implemented("adjust", 4, args);
}
int run_mann(const std::vector<std::string>& args) {
  return not_implemented("mann", 4, args);
}
int run_blend(const std::vector<std::string>& args) {
  return not_implemented("blend", 5, args);
}
int run_render(const std::vector<std::string>& args) {
  return not_implemented("render", 6, args);
}

} // namespace tspline

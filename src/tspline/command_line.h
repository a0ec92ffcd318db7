// The arguments of one `tspline` subcommand, parsed with CLI11: the declarations every
// subcommand repeats (--input, --output, --report, ranged integers, finite numbers), the help
// text, deprecated spellings, and the checks of the output paths before any work is done.

#ifndef TSPLINE_COMMAND_LINE_H
#define TSPLINE_COMMAND_LINE_H

#include "cli.h"

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace tspline {

class Command_line {
public:
  // `command` names the subcommand; its summary comes from the dispatch table.
  explicit Command_line(std::string command);
  Command_line(const Command_line&) = delete; // CLI11 holds references to the members
  Command_line& operator=(const Command_line&) = delete;

  // A paragraph printed in the help after the summary.
  Command_line& describe(std::string paragraph);

  // The main input, --input VALUE; with `positional`, also accepted as the only argument.
  void input(std::string& target, const std::string& value_name, const std::string& help,
             bool positional = false);
  // An output file, --NAME VALUE, checked by `parse` (see check_output_path). `old_names`
  // are deprecated spellings: accepted, listed as such in the help, noted on stderr.
  void output(std::string& target, const std::string& name, const std::string& value_name,
              const std::string& help, Output_rule rule,
              const std::vector<std::string>& old_names = {});
  // --report FILE.json, '-' for stdout.
  void report(std::string& target, const std::string& help = "write the JSON report");

  // --NAME VALUE kept as text (choices are checked by the caller); a non-empty target is
  // shown as the default.
  void text(std::string& target, const std::string& name, const std::string& value_name,
            const std::string& help);
  // --NAME N: a decimal integer in [low, high], checked on the text before any conversion;
  // otherwise Usage_error "--NAME must be between LOW and HIGH<note>, not N".
  template <class Integer>
  void integer(Integer& target, const std::string& name, const std::string& value_name,
               const std::string& help, long long low, long long high, const std::string& note = "",
               bool show_default = true) {
    static_assert(std::is_integral_v<Integer>);
    add(name, target, value_name, help, show_default ? std::to_string(target) : "")
        ->check(integer_check(name, low, high, note));
  }
  // --NAME X: a finite number.
  void number(double& target, const std::string& name, const std::string& value_name,
              const std::string& help, bool show_default = true);
  // --NAME: a boolean switch.
  void flag(bool& target, const std::string& name, const std::string& help);

  // The option was given on the command line (under any of its spellings).
  bool given(const std::string& name) const;

  // Parses the arguments after the subcommand's name. Returns false when --help or -h came
  // before '--': the help is then printed on stdout and nothing else is checked. Otherwise
  // throws Usage_error (exit status 2) for bad usage, then checks every given output path.
  bool parse(const std::vector<std::string>& args);

  // The text printed for `tspline <command> --help`.
  std::string help() const;

  // Where the human-readable summary goes: stderr when an output is written to stdout.
  std::ostream& summary_stream() const;

  // --help or -h before '--'.
  static bool help_requested(const std::vector<std::string>& args);

private:
  struct Output {
    CLI::Option* option;
    std::vector<CLI::Option*> old_spellings;
    const std::string* target;
    Output_rule rule;
  };

  template <class T>
  CLI::Option* add(const std::string& name, T& target, const std::string& value_name,
                   const std::string& help, const std::string& default_text) {
    CLI::Option* option = app_.add_option("--" + name, target, help);
    option->type_name(value_name);
    if (!default_text.empty())
      option->default_str(default_text);
    return option;
  }
  static CLI::Validator integer_check(const std::string& name, long long low, long long high,
                                      const std::string& note);

  std::string command_;
  CLI::App app_;
  std::vector<std::string> paragraphs_;
  std::vector<Output> outputs_;
  std::string* input_ = nullptr;
  CLI::Option* input_option_ = nullptr;
  CLI::Option* positional_input_ = nullptr;
  std::string positional_value_;
  bool stdout_taken_ = false;
};

} // namespace tspline

#endif // TSPLINE_COMMAND_LINE_H

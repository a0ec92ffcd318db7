#include "command_line.h"

#include "commands.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <regex>
#include <sstream>
#include <utility>

namespace tspline {

namespace {

const char* const deprecated_group = "deprecated";

// CLI11's wording for a missing value ("--x: 1 required DIR missing") in ours.
std::string usage_message(const CLI::ParseError& error) {
  static const std::regex missing_value("^(\\S+): [0-9]+ required (.*) missing$");
  std::smatch match;
  const std::string what = error.what();
  if (std::regex_match(what, match, missing_value))
    return "option '" + match[1].str() + "' requires a value " + match[2].str();
  return what;
}

} // namespace

Command_line::Command_line(std::string command)
    : command_(std::move(command)),
      app_(std::string(command_summary(command_)), "tspline " + command_) {
  app_.set_help_flag(); // --help is handled before parsing: it wins over bad arguments
  app_.allow_extras();  // unknown options are reported by parse(), in our words
  // As before CLI11: an option given twice takes the last value.
  app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

Command_line& Command_line::describe(std::string paragraph) {
  paragraphs_.push_back(std::move(paragraph));
  return *this;
}

void Command_line::input(std::string& target, const std::string& value_name,
                         const std::string& help, bool positional) {
  input_ = &target;
  input_option_ = add("input", target, value_name, help, "");
  if (positional)
    positional_input_ =
        app_.add_option(value_name, positional_value_, help + " (the same as --input)");
}

void Command_line::output(std::string& target, const std::string& name,
                          const std::string& value_name, const std::string& help, Output_rule rule,
                          const std::vector<std::string>& old_names) {
  Output output{add(name, target, value_name, help, target), {}, &target, std::move(rule)};
  for (const std::string& old_name : old_names)
    output.old_spellings.push_back(
        add(old_name, target, value_name, "the old spelling of --" + name, "")
            ->group(deprecated_group));
  outputs_.push_back(std::move(output));
}

void Command_line::report(std::string& target, const std::string& help) {
  output(target, "report", "FILE.json", help + " ('-': stdout)", Output_rule{{}, true, false});
}

void Command_line::text(std::string& target, const std::string& name, const std::string& value_name,
                        const std::string& help) {
  add(name, target, value_name, help, target);
}

void Command_line::number(double& target, const std::string& name, const std::string& value_name,
                          const std::string& help, bool show_default) {
  std::ostringstream default_text;
  if (show_default)
    default_text << target;
  add(name, target, value_name, help, default_text.str())
      ->check(CLI::Validator(
          [name](std::string& text) {
            errno = 0;
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
                !std::isfinite(value))
              throw Usage_error("option '--" + name + "' expects a finite number, got '" + text +
                                "'");
            return std::string();
          },
          ""));
}

void Command_line::flag(bool& target, const std::string& name, const std::string& help) {
  app_.add_flag("--" + name, target, help);
}

CLI::Validator Command_line::integer_check(const std::string& name, long long low, long long high,
                                           const std::string& note) {
  // Thrown from inside CLI11 so that the message stays ours ("--levels must be ..."); the
  // text is checked before CLI11 converts it, so no value is ever cast out of range.
  return CLI::Validator(
      [=](std::string& text) {
        const std::size_t sign = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
        if (text.size() == sign || text.find_first_not_of("0123456789", sign) != std::string::npos)
          throw Usage_error("option '--" + name + "' expects an integer, got '" + text + "'");
        errno = 0;
        const long long value = std::strtoll(text.c_str(), nullptr, 10);
        if (errno == ERANGE || value < low || value > high)
          throw Usage_error("--" + name + " must be between " + std::to_string(low) + " and " +
                            std::to_string(high) + note + ", not " + text);
        text = std::to_string(value); // CLI11 reads integers in base 0: 010 would be octal
        return std::string();
      },
      "");
}

bool Command_line::given(const std::string& name) const {
  const CLI::Option* option = app_.get_option_no_throw("--" + name);
  if (option == nullptr)
    return false;
  if (option->count() > 0)
    return true;
  for (const Output& output : outputs_)
    if (output.option == option)
      for (const CLI::Option* old : output.old_spellings)
        if (old->count() > 0)
          return true;
  return option == input_option_ && positional_input_ != nullptr && positional_input_->count() > 0;
}

bool Command_line::help_requested(const std::vector<std::string>& args) {
  for (const std::string& arg : args) {
    if (arg == "--")
      break;
    if (arg == "--help" || arg == "-h")
      return true;
  }
  return false;
}

bool Command_line::parse(const std::vector<std::string>& args) {
  if (help_requested(args)) {
    std::cout << help();
    return false;
  }
  std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11's order
  try {
    app_.parse(reversed);
  } catch (const CLI::ParseError& error) {
    throw Usage_error(usage_message(error));
  }
  const std::vector<std::string> extras = app_.remaining();
  if (!extras.empty()) {
    const std::string& first = extras.front();
    if (first.size() > 1 && first[0] == '-')
      throw Usage_error("unknown option '" + first.substr(0, first.find('=')) + "'");
    throw Usage_error("unexpected argument '" + first + "'");
  }

  if (positional_input_ != nullptr && positional_input_->count() > 0) {
    if (input_option_->count() > 0)
      throw Usage_error("give the input once: --input " + positional_input_->get_name() + " or " +
                        positional_input_->get_name());
    *input_ = positional_value_;
  }

  int to_stdout = 0;
  for (const Output& output : outputs_) {
    const CLI::Option* used = output.option->count() > 0 ? output.option : nullptr;
    for (const CLI::Option* old : output.old_spellings) {
      if (old->count() == 0)
        continue;
      if (used != nullptr)
        throw Usage_error("give one of " + used->get_name() + " and " + old->get_name() +
                          " (the same option)");
      used = old;
      std::cerr << "tspline " << command_ << ": warning: " << old->get_name()
                << " is deprecated, use " << output.option->get_name() << "\n";
    }
    if (used == nullptr)
      continue;
    check_output_path(*output.target, used->get_name(), output.rule);
    to_stdout += *output.target == "-";
  }
  if (to_stdout > 1)
    throw Usage_error("only one output can go to stdout ('-')");
  stdout_taken_ = to_stdout > 0;
  return true;
}

std::ostream& Command_line::summary_stream() const {
  return stdout_taken_ ? std::cerr : std::cout;
}

std::string Command_line::help() const {
  std::ostringstream out;
  out << "usage: tspline " << command_ << " [options]";
  for (const CLI::Option* option : app_.get_options())
    if (option->get_positional())
      out << " [" << option->get_name() << "]";
  out << "\n\n" << app_.get_description() << "\n";
  for (const std::string& paragraph : paragraphs_)
    out << "\n" << paragraph << "\n";

  // Left column: "NAME" for positionals, "--name VALUE" for options.
  using Rows = std::vector<std::pair<std::string, std::string>>;
  Rows arguments, options, deprecated;
  for (const CLI::Option* option : app_.get_options()) {
    std::string left = option->get_name();
    std::string right = option->get_description();
    if (option->get_positional()) {
      arguments.emplace_back(left, right);
      continue;
    }
    if (option->get_type_size() > 0)
      left += " " + option->get_type_name();
    if (!option->get_default_str().empty())
      right += " (default: " + option->get_default_str() + ")";
    (option->get_group() == deprecated_group ? deprecated : options).emplace_back(left, right);
  }
  options.emplace_back("-h, --help", "show this help and exit");

  std::size_t width = 0;
  for (const Rows* rows : {&arguments, &options, &deprecated})
    for (const auto& row : *rows)
      width = std::max(width, row.first.size());
  for (const auto& [title, rows] :
       {std::pair<const char*, const Rows*>{"arguments", &arguments},
        {"options", &options},
        {"deprecated spellings (still accepted, removed in the next version)", &deprecated}}) {
    if (rows->empty())
      continue;
    out << "\n" << title << ":\n";
    for (const auto& row : *rows)
      out << "  " << row.first << std::string(width - row.first.size() + 2, ' ') << row.second
          << "\n";
  }
  return out.str();
}

} // namespace tspline

#include "cli.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <utility>

namespace tspline {

// ---------------------------------------------------------------------------
// Parsed_arguments

bool Parsed_arguments::has(const std::string& name) const {
  return values_.count(name) != 0;
}

const std::string& Parsed_arguments::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end())
    throw Usage_error("option '--" + name + "' is required");
  return it->second;
}

double Parsed_arguments::number(const std::string& name) const {
  const std::string& text = value(name);
  errno = 0;
  char* end = nullptr;
  const double result = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
      !std::isfinite(result))
    throw Usage_error("option '--" + name + "' expects a finite number, got '" + text + "'");
  return result;
}

long long Parsed_arguments::integer(const std::string& name) const {
  const std::string& text = value(name);
  errno = 0;
  char* end = nullptr;
  const long long result = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
    throw Usage_error("option '--" + name + "' expects an integer, got '" + text + "'");
  return result;
}

int Parsed_arguments::integer_in(const std::string& name, int low, int high,
                                 const std::string& note) const {
  const long long result = integer(name);
  if (result < low || result > high)
    throw Usage_error("--" + name + " must be between " + std::to_string(low) + " and " +
                      std::to_string(high) + note + ", not " + std::to_string(result));
  return static_cast<int>(result);
}

// ---------------------------------------------------------------------------
// Argument_parser

Argument_parser::Argument_parser(std::string command, std::string summary)
    : command_(std::move(command)), summary_(std::move(summary)) {}

Argument_parser& Argument_parser::describe(std::string paragraph) {
  paragraphs_.push_back(std::move(paragraph));
  return *this;
}

Argument_parser& Argument_parser::add_option(std::string name, std::string value_name,
                                             std::string help,
                                             std::optional<std::string> default_value) {
  if (value_name.empty())
    value_name = "VALUE";
  options_.push_back(
      {std::move(name), std::move(value_name), std::move(help), std::move(default_value)});
  return *this;
}

Argument_parser& Argument_parser::add_switch(std::string name, std::string help) {
  options_.push_back({std::move(name), std::string(), std::move(help), std::nullopt});
  return *this;
}

Argument_parser& Argument_parser::add_positional(std::string name, std::string help,
                                                 bool required) {
  positionals_.push_back({std::move(name), std::move(help), required});
  return *this;
}

const Argument_parser::Option* Argument_parser::find_option(const std::string& name) const {
  for (const Option& option : options_)
    if (option.name == name)
      return &option;
  return nullptr;
}

Parsed_arguments Argument_parser::parse(const std::vector<std::string>& args) const {
  Parsed_arguments result;
  for (const Option& option : options_)
    if (option.default_value)
      result.values_[option.name] = *option.default_value;

  // `--help` wins wherever it appears before `--`, even after a bad option.
  for (const std::string& arg : args) {
    if (arg == "--")
      break;
    if (arg == "--help" || arg == "-h") {
      result.help_requested_ = true;
      return result;
    }
  }

  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool looks_like_option = !options_ended && arg.size() > 1 && arg[0] == '-';
    if (!looks_like_option) {
      result.positionals_.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    if (arg.compare(0, 2, "--") != 0)
      throw Usage_error("unknown option '" + arg + "'");

    const std::size_t equal = arg.find('=');
    const std::string name =
        arg.substr(2, equal == std::string::npos ? std::string::npos : equal - 2);
    const Option* option = find_option(name);
    if (option == nullptr)
      throw Usage_error("unknown option '--" + name + "'");

    if (option->value_name.empty()) { // a switch
      if (equal != std::string::npos)
        throw Usage_error("option '--" + name + "' takes no value");
      result.switches_.insert(name);
    } else if (equal != std::string::npos) {
      result.values_[name] = arg.substr(equal + 1);
    } else {
      if (i + 1 == args.size())
        throw Usage_error("option '--" + name + "' requires a value " + option->value_name);
      result.values_[name] = args[++i];
    }
  }

  const std::size_t given = result.positionals_.size();
  if (given > positionals_.size())
    throw Usage_error("unexpected argument '" + result.positionals_[positionals_.size()] + "'");
  for (std::size_t i = given; i < positionals_.size(); ++i)
    if (positionals_[i].required)
      throw Usage_error("missing argument " + positionals_[i].name);
  return result;
}

std::string Argument_parser::help() const {
  std::ostringstream out;
  out << "usage: tspline " << command_ << " [options]";
  for (const Positional& positional : positionals_)
    out << (positional.required ? " " + positional.name : " [" + positional.name + "]");
  out << "\n\n" << summary_ << "\n";
  for (const std::string& paragraph : paragraphs_)
    out << "\n" << paragraph << "\n";

  // Left column: "NAME" for positionals, "--name VALUE" for options.
  std::vector<std::pair<std::string, std::string>> rows;
  for (const Positional& positional : positionals_)
    rows.emplace_back(positional.name, positional.help);
  const std::size_t first_option = rows.size();
  for (const Option& option : options_) {
    std::string left = "--" + option.name;
    if (!option.value_name.empty())
      left += " " + option.value_name;
    std::string right = option.help;
    if (option.default_value)
      right += " (default: " + *option.default_value + ")";
    rows.emplace_back(left, right);
  }
  rows.emplace_back("-h, --help", "show this help and exit");

  std::size_t width = 0;
  for (const auto& row : rows)
    width = std::max(width, row.first.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i == 0 && first_option > 0)
      out << "\narguments:\n";
    if (i == first_option)
      out << "\noptions:\n";
    out << "  " << rows[i].first << std::string(width - rows[i].first.size() + 2, ' ')
        << rows[i].second << "\n";
  }
  return out.str();
}

// ---------------------------------------------------------------------------
// Json

Json::Json(bool value) : kind_(Kind::Bool), text_(value ? "true" : "false") {}

Json::Json(double value) {
  if (!std::isfinite(value))
    return; // stays null
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  kind_ = Kind::Number;
  text_ = buffer;
}

Json::Json(const char* value) : kind_(Kind::String), text_(value == nullptr ? "" : value) {}

Json::Json(std::string value) : kind_(Kind::String), text_(std::move(value)) {}

Json Json::array() {
  Json result;
  result.kind_ = Kind::Array;
  return result;
}

Json Json::object() {
  Json result;
  result.kind_ = Kind::Object;
  return result;
}

Json& Json::push_back(Json value) {
  if (kind_ == Kind::Null)
    kind_ = Kind::Array;
  if (kind_ != Kind::Array)
    throw std::logic_error("Json::push_back on a value that is not an array");
  items_.push_back(std::move(value));
  return *this;
}

Json& Json::set(const std::string& key, Json value) {
  if (kind_ == Kind::Null)
    kind_ = Kind::Object;
  if (kind_ != Kind::Object)
    throw std::logic_error("Json::set on a value that is not an object");
  const auto it = std::find(keys_.begin(), keys_.end(), key);
  if (it != keys_.end()) {
    items_[static_cast<std::size_t>(it - keys_.begin())] = std::move(value);
  } else {
    keys_.push_back(key);
    items_.push_back(std::move(value));
  }
  return *this;
}

void write_json_string(std::ostream& out, const std::string& text) {
  out << '"';
  for (const char c : text) {
    switch (c) {
    case '"':
      out << "\\\"";
      break;
    case '\\':
      out << "\\\\";
      break;
    case '\b':
      out << "\\b";
      break;
    case '\f':
      out << "\\f";
      break;
    case '\n':
      out << "\\n";
      break;
    case '\r':
      out << "\\r";
      break;
    case '\t':
      out << "\\t";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
        out << buffer;
      } else {
        out << c; // UTF-8 bytes pass through unchanged
      }
    }
  }
  out << '"';
}

void Json::write(std::ostream& out, int indent) const {
  write(out, indent, 0);
  if (indent > 0)
    out << '\n';
}

std::string Json::dump(int indent) const {
  std::ostringstream out;
  write(out, indent);
  return out.str();
}

void Json::write(std::ostream& out, int indent, int level) const {
  const auto new_line = [&](int depth) {
    if (indent > 0)
      out << '\n' << std::string(static_cast<std::size_t>(indent * depth), ' ');
  };
  switch (kind_) {
  case Kind::Null:
    out << "null";
    return;
  case Kind::Bool:
  case Kind::Number:
    out << text_;
    return;
  case Kind::String:
    write_json_string(out, text_);
    return;
  case Kind::Array:
  case Kind::Object:
    break;
  }

  const bool is_object = kind_ == Kind::Object;
  out << (is_object ? '{' : '[');
  for (std::size_t i = 0; i < items_.size(); ++i) {
    if (i > 0)
      out << ',';
    new_line(level + 1);
    if (is_object) {
      write_json_string(out, keys_[i]);
      out << (indent > 0 ? ": " : ":");
    }
    items_[i].write(out, indent, level + 1);
  }
  if (!items_.empty())
    new_line(level);
  out << (is_object ? '}' : ']');
}

} // namespace tspline

// Command-line helpers shared by the subcommands of `tspline`: a small argument
// parser and a minimal JSON value with a writer. C++17 standard library only.

#ifndef TSPLINE_CLI_H
#define TSPLINE_CLI_H

#include <cstddef>
#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace tspline {

// Bad command-line usage (unknown option, missing value, wrong number of
// arguments). `main` prints it on one line and exits with status 2.
class Usage_error : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

// The result of `Argument_parser::parse`.
class Parsed_arguments {
public:
  // `--help` or `-h` was given; the other arguments were not checked.
  bool help_requested() const { return help_requested_; }

  // The option has a value (given on the command line or by default).
  bool has(const std::string& name) const;
  // The value of an option; throws `Usage_error` if it has none.
  const std::string& value(const std::string& name) const;
  // The value converted to a finite number / an integer; throws `Usage_error`
  // naming the option if the text is not one.
  double number(const std::string& name) const;
  long long integer(const std::string& name) const;
  // The integer value, which must lie in [low, high]; otherwise `Usage_error`
  // "--NAME must be between LOW and HIGH<note>, not VALUE".
  int integer_in(const std::string& name, int low, int high, const std::string& note = "") const;

  // The boolean switch was given.
  bool is_set(const std::string& name) const { return switches_.count(name) != 0; }

  const std::vector<std::string>& positionals() const { return positionals_; }

private:
  friend class Argument_parser;
  bool help_requested_ = false;
  std::map<std::string, std::string> values_;
  std::set<std::string> switches_;
  std::vector<std::string> positionals_;
};

// Parses `--name value`, `--name=value`, boolean switches `--name`, and
// positional arguments; `--` ends the options. Option names are given without
// the leading dashes. `--help`/`-h` is always accepted.
class Argument_parser {
public:
  Argument_parser(std::string command, std::string summary);

  // A paragraph printed in the help after the summary.
  Argument_parser& describe(std::string paragraph);
  // An option taking a value, e.g. add_option("output-dir", "DIR", "where to write", "out").
  Argument_parser& add_option(std::string name, std::string value_name, std::string help,
                              std::optional<std::string> default_value = std::nullopt);
  // A boolean switch, e.g. add_switch("exact", "use exact rational arithmetic").
  Argument_parser& add_switch(std::string name, std::string help);
  // Positional arguments, in order; optional ones must come last.
  Argument_parser& add_positional(std::string name, std::string help, bool required = true);

  // Throws `Usage_error` for an unknown option, a missing or unexpected value,
  // or a wrong number of positional arguments.
  Parsed_arguments parse(const std::vector<std::string>& args) const;

  // The text printed for `tspline <command> --help`.
  std::string help() const;

private:
  struct Option {
    std::string name;
    std::string value_name; // empty for a switch
    std::string help;
    std::optional<std::string> default_value;
  };
  struct Positional {
    std::string name;
    std::string help;
    bool required;
  };

  const Option* find_option(const std::string& name) const;

  std::string command_;
  std::string summary_;
  std::vector<std::string> paragraphs_;
  std::vector<Option> options_;
  std::vector<Positional> positionals_;
};

// A JSON value: null, bool, number, string, array or object (keys keep their
// insertion order). Doubles are written with 17 significant digits so that
// they read back exactly; non-finite doubles are written as null.
class Json {
public:
  enum class Kind { Null, Bool, Number, String, Array, Object };

  Json() = default;
  Json(std::nullptr_t) {}
  Json(bool value);
  Json(double value);
  template <
      class Integer,
      std::enable_if_t<std::is_integral_v<Integer> && !std::is_same_v<Integer, bool>, int> = 0>
  Json(Integer value) : kind_(Kind::Number), text_(std::to_string(value)) {}
  Json(const char* value);
  Json(std::string value);

  static Json array();
  static Json object();

  Kind kind() const { return kind_; }
  // Number of elements of an array or members of an object, 0 otherwise.
  std::size_t size() const { return kind_ == Kind::Object ? keys_.size() : items_.size(); }

  // Appends to an array (a null value becomes an empty array first).
  Json& push_back(Json value);
  // Sets a member of an object, replacing an existing one with the same key
  // (a null value becomes an empty object first).
  Json& set(const std::string& key, Json value);

  // Writes the value; indent > 0 pretty-prints with that many spaces per level,
  // indent == 0 writes everything on one line.
  void write(std::ostream& out, int indent = 2) const;
  std::string dump(int indent = 2) const;

private:
  void write(std::ostream& out, int indent, int level) const;

  Kind kind_ = Kind::Null;
  std::string text_;              // Bool/Number: the literal; String: the raw string
  std::vector<std::string> keys_; // Object
  std::vector<Json> items_;       // Array elements or Object values
};

// Writes `text` as a quoted JSON string with the required escapes.
void write_json_string(std::ostream& out, const std::string& text);

} // namespace tspline

#endif // TSPLINE_CLI_H

#pragma once
/// \file args.hpp
/// A small command-line parser: `--name value`, `--name v1 v2` and `--flag` options, declared per
/// command, so that every command lists and checks its own options.

#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace pagor::cli {

/// Wrong command-line usage; the message says what and how to fix it.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One option of a command.
struct Option {
  std::string name;  ///< without the leading dashes
  int values = 1;    ///< number of values it takes (0 for a flag)
  std::string meta;  ///< value placeholder for the help, e.g. "FILE"
  std::string help;  ///< one line
};

/// A command's options: `first`, then each group of `more` in order (shared groups and the
/// command's own).
std::vector<Option> joined(std::vector<Option> first,
                           std::initializer_list<std::vector<Option>> more);

/// Parsed options of one command.
class Args {
 public:
  /// Parses `argv` against `options`. Throws UsageError for unknown options, missing values and
  /// repeated options.
  Args(const std::vector<std::string>& argv, const std::vector<Option>& options);

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  /// The single value of an option, or `fallback` when absent.
  std::string get(const std::string& name, const std::string& fallback = {}) const;
  /// All values of an option (empty when absent).
  const std::vector<std::string>& all(const std::string& name) const;
  /// An integer value; throws UsageError naming the option when it is not one.
  int get_int(const std::string& name, int fallback) const;

 private:
  std::map<std::string, std::vector<std::string>> values_;
};

/// Formats the option list for `--help`.
std::string format_options(const std::vector<Option>& options);

/// Parses an integer, throwing UsageError naming `what` on failure.
int parse_int(const std::string& text, const std::string& what);

}  // namespace pagor::cli

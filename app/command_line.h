// A small command-line reader for the headless subcommands: "--name value" options, repeatable
// options, list options ("--measured a.csv b.csv", values up to the next "--" option) and flags,
// with messages that say which option is wrong.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace pat::app {

class CommandLine {
 public:
  /// `value_options` take a value, `flags` do not; a value option also in `list_options` takes
  /// every following argument up to the next one that starts with "--" (at least one). Anything
  /// else is an error.
  CommandLine(std::vector<std::string> args, const std::set<std::string>& value_options,
              const std::set<std::string>& flags, const std::set<std::string>& list_options = {});

  bool has(const std::string& option) const;
  /// The value of an option given once; throws InputError when a required one is missing or
  /// when it is given more than once (repeatable options are read with values()).
  std::string value(const std::string& option) const;
  std::string value_or(const std::string& option, const std::string& fallback) const;
  std::vector<std::string> values(const std::string& option) const;
  /// A positive number (seconds, hertz...); names the option in the error.
  double positive_number(const std::string& option) const;
  double positive_number_or(const std::string& option, double fallback) const;
  /// The path of an output option ("" when absent), checked before any work: not empty, in a
  /// folder that exists, not a folder, and not a file another output option of the same command
  /// already names (one would overwrite the other; the error names both options).
  /// `required`: absent is an error too.
  std::string output_path(const std::string& option, bool required = false) const;

 private:
  std::map<std::string, std::vector<std::string>> values_;
  std::set<std::string> flags_;
  /// Output files named so far (absolute, normalized) and the option that named each.
  mutable std::map<std::string, std::string> outputs_;
};

/// Parses a finite number; throws InputError naming `what`.
double parse_number(const std::string& text, const std::string& what);

}  // namespace pat::app

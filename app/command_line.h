// A small command-line reader for the headless subcommands: "--name value" options, repeatable
// options, list options ("--measured a.csv b.csv", values up to the next "--" option) and flags,
// with messages that say which option is wrong.
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
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
  /// The arguments as given (after the subcommand), joined by spaces, an argument with a space
  /// in single quotes: what an output records of how it was made.
  std::string arguments_text() const;
  /// The value of an option given once; throws InputError when a required one is missing or
  /// when it is given more than once (repeatable options are read with values()).
  std::string value(const std::string& option) const;
  std::string value_or(const std::string& option, const std::string& fallback) const;
  std::vector<std::string> values(const std::string& option) const;
  /// A positive number (seconds, hertz...); names the option in the error.
  double positive_number(const std::string& option) const;
  double positive_number_or(const std::string& option, double fallback) const;
  /// A whole number from 1 to `most` (seeds, threads, passes): a fraction or a number beyond
  /// `most` is refused naming the option (a cast had run 1.5 as 1 and 3e9 as none).
  int whole_number_or(const std::string& option, int most, int fallback) const;
  /// The path of an output option ("" when absent), checked before any work: not empty, in a
  /// folder that exists, not a folder, not a file another output option of the same command
  /// already names (one would overwrite the other; the error names both options), and not a file
  /// the command reads (input_files()). `required`: absent is an error too.
  std::string output_path(const std::string& option, bool required = false) const;

  /// A file the command reads that is not an option's value (a positional argument), with the
  /// words that name it in a message ("the raw trace").
  void add_input_file(const std::string& what, const std::string& path);
  /// The existing files the command reads, each with the words that name it: --action's preset
  /// (the shipped one for grand and upright), --input's CSV, --measured, --calibration and
  /// --exercise files, and those added with add_input_file.
  std::vector<std::pair<std::string, std::string>> input_files() const;
  /// Every file the command reads or has named as an output, except the output `option`'s own,
  /// each with the words that name it ("--out", "the file given to --input"): what a file the
  /// output writes beside its own (a plot's second CSV) must not replace.
  std::vector<std::pair<std::string, std::string>> files_other_than(
      const std::string& option) const;

 private:
  std::vector<std::string> arguments_;
  std::map<std::string, std::vector<std::string>> values_;
  std::set<std::string> flags_;
  /// Output files named so far, each with the option that named it.
  mutable std::vector<std::pair<std::string, std::string>> outputs_;
  std::vector<std::pair<std::string, std::string>> extra_inputs_;  ///< (words, path)
};

/// Whether two paths name the same file: the same file on disk when both exist, else the same
/// absolute, normalized path.
bool same_file(const std::string& a, const std::string& b);

/// Parses a finite number; throws InputError naming `what`.
double parse_number(const std::string& text, const std::string& what);

}  // namespace pat::app

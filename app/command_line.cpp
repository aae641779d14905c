#include "command_line.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "io/csv.h"
#include "model/preset_loader.h"

namespace pat::app {

namespace {

std::string normalized_path(const std::string& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return (error ? std::filesystem::path(path) : absolute).lexically_normal().string();
}

bool is_regular_file(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (std::filesystem::exists(a, error) && std::filesystem::exists(b, error)) {
    const bool same = std::filesystem::equivalent(a, b, error);
    if (!error) return same;
  }
  return normalized_path(a) == normalized_path(b);
}

CommandLine::CommandLine(std::vector<std::string> args, const std::set<std::string>& value_options,
                         const std::set<std::string>& flags,
                         const std::set<std::string>& list_options)
    : arguments_(args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (flags.count(arg)) {
      flags_.insert(arg);
    } else if (value_options.count(arg)) {
      if (i + 1 >= args.size()) throw InputError("option " + arg + " needs a value");
      // the next word is one of this command's own options: the value was left out (it had been
      // taken as the value: "--measured --threads 1" said "--threads: cannot read the file")
      const std::string& next = args[i + 1];
      if (value_options.count(next) || flags.count(next))
        throw InputError("option " + arg + " needs a value (found the option " + next + ")");
      values_[arg].push_back(args[++i]);
      if (list_options.count(arg))
        while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0)
          values_[arg].push_back(args[++i]);
    } else if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos &&
               value_options.count(arg.substr(0, arg.find('=')))) {
      values_[arg.substr(0, arg.find('='))].push_back(arg.substr(arg.find('=') + 1));
    } else {
      throw InputError("unknown option '" + arg + "' (see pianoaction --help)");
    }
  }
}

bool CommandLine::has(const std::string& option) const {
  return flags_.count(option) || values_.count(option);
}

std::string CommandLine::value(const std::string& option) const {
  const auto it = values_.find(option);
  if (it == values_.end()) throw InputError("missing option " + option);
  // an option read as one value given twice: which one was meant is not ours to guess (the
  // last one would win without a word)
  if (it->second.size() > 1)
    throw InputError(option + " is given " + std::to_string(it->second.size()) + " times ('" +
                     it->second.front() + "' and '" + it->second.back() + "'): give it once");
  return it->second.back();
}

std::string CommandLine::value_or(const std::string& option, const std::string& fallback) const {
  return has(option) ? value(option) : fallback;
}

std::vector<std::string> CommandLine::values(const std::string& option) const {
  const auto it = values_.find(option);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

double parse_number(const std::string& text, const std::string& what) {
  double x = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
    throw InputError(what + ": '" + text + "' is not a number");
  return x;
}

double CommandLine::positive_number(const std::string& option) const {
  const double x = parse_number(value(option), option);
  if (x <= 0.0) throw InputError(option + ": must be positive (got " + value(option) + ")");
  return x;
}

double CommandLine::positive_number_or(const std::string& option, double fallback) const {
  return has(option) ? positive_number(option) : fallback;
}

int CommandLine::whole_number_or(const std::string& option, int most, int fallback) const {
  if (!has(option)) return fallback;
  const double x = parse_number(value(option), option);
  if (!(x >= 1.0 && x <= most && x == std::floor(x)))
    throw InputError(option + ": must be a whole number from 1 to " + std::to_string(most) +
                     " (got " + value(option) + ")");
  return static_cast<int>(x);
}

std::string CommandLine::output_path(const std::string& option, bool required) const {
  if (!has(option) && !required) return "";
  const std::string path = value(option);  // throws for a missing required option
  try {
    check_output_path(path);
  } catch (const InputError& e) {
    throw InputError(option + ": " + e.what());
  }
  for (const auto& [what, input] : input_files()) {
    if (same_file(path, input))
      throw InputError(option + ": " + path + " is " + what +
                       ", which this command reads; writing there would destroy it, so give the "
                       "output its own file");
  }
  for (const auto& [named, named_by] : outputs_) {
    if (named_by != option && same_file(path, named))
      throw InputError(option + ": " + path + " is also the " + named_by +
                       " file; the second output would overwrite the first, so give each its own "
                       "file");
  }
  outputs_.emplace_back(path, option);
  return path;
}

void CommandLine::add_input_file(const std::string& what, const std::string& path) {
  extra_inputs_.emplace_back(what, path);
}

std::vector<std::pair<std::string, std::string>> CommandLine::input_files() const {
  std::vector<std::pair<std::string, std::string>> files;
  const auto add = [&files](const std::string& what, const std::string& path) {
    if (is_regular_file(path)) files.emplace_back(what, path);
  };
  // the options that name files the commands read, as the commands read them
  for (const std::string& action : values("--action")) {
    // an action's name reads the shipped preset (load_action)
    if (action == "grand" || action == "upright")
      add("the shipped preset of --action " + action, preset_directory() + "/" + action + ".json");
    else
      add("the file given to --action", action);
  }
  for (const std::string& input : values("--input"))
    if (input.rfind("csv:", 0) == 0) add("the file given to --input", input.substr(4));
  for (const char* option : {"--measured", "--calibration", "--exercise"})
    for (const std::string& path : values(option))
      add(std::string("the file given to ") + option, path);
  for (const auto& [what, path] : extra_inputs_) add(what, path);
  return files;
}

std::vector<std::pair<std::string, std::string>> CommandLine::files_other_than(
    const std::string& option) const {
  std::vector<std::pair<std::string, std::string>> files = input_files();
  for (const auto& [path, named_by] : outputs_)
    if (named_by != option) files.emplace_back("the " + named_by + " file", path);
  return files;
}

std::string CommandLine::arguments_text() const {
  std::string text;
  for (const std::string& arg : arguments_) {
    if (!text.empty()) text += ' ';
    text += arg.find(' ') == std::string::npos ? arg : "'" + arg + "'";
  }
  return text;
}

}  // namespace pat::app

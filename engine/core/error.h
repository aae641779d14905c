// Errors reported to the user: every message names where the problem is (file, field, line)
// and what is wrong, so the command line and the window can show it as it is.
#pragma once

#include <stdexcept>
#include <string>

namespace pat {

/// A problem with user input (preset, CSV, command-line value, input SPEC).
/// what() is a complete sentence such as
///   "presets/grand.json: bodies[2].mass_g: must be positive (got -3)".
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// Builds "source: location: problem", leaving out empty parts.
std::string located_message(const std::string& source, const std::string& location,
                            const std::string& problem);

}  // namespace pat

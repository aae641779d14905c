// Builds the model a subcommand runs: --action, then every --set and --without, in order.
#pragma once

#include "command_line.h"
#include "model/action_model.h"

namespace pat::app {

/// Refuses a NAME given twice among an option's NAME=VALUE assignments: one of the two values
/// would be dropped without a word (the edits' own parsers name any other problem).
void refuse_repeated_names(const std::string& option, const std::vector<std::string>& assignments);

/// Loads --action (grand, upright or a preset file) and applies --set NAME=MM and
/// --without PART, then every --effect NAME=VALUE (model/effects.h). Throws InputError naming the
/// option or the file. `needs_rest`: a --without part the whole action cannot rest without is
/// refused (false for the commands that take one body alone: swing, keyfall).
ActionModel load_configured_action(const CommandLine& cl, bool needs_rest = true);

}  // namespace pat::app

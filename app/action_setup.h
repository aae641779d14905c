// Builds the model a subcommand runs: --action, then every --set and --without, in order.
#pragma once

#include "command_line.h"
#include "model/action_model.h"

namespace pat::app {

/// Loads --action (grand, upright or a preset file) and applies --set NAME=MM and
/// --without PART, then every --effect NAME=VALUE (model/effects.h). Throws InputError naming the
/// option or the file.
ActionModel load_configured_action(const CommandLine& cl);

}  // namespace pat::app

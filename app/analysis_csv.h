// --out CSV for the analysis subcommands (swing, keyfall, touchweight, study double-blow): the
// analysis' table, with the action and what was run in its metadata lines.
#pragma once

#include <string>

#include "command_line.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat::app {

/// Writes `table` to the --out path, when given, with `# action:` (the model's name) and
/// `# analysis:` metadata. Throws InputError naming the file when it cannot be written.
void write_analysis_csv(const CommandLine& cl, CsvTable table, const ActionModel& model,
                        const std::string& analysis);

}  // namespace pat::app

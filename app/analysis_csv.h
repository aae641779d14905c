// --out CSV for the analysis subcommands (swing, keyfall, touchweight, study double-blow): the
// analysis' table, with the action and what was run in its metadata lines.
#pragma once

#include <string>

#include "io/csv.h"
#include "model/action_model.h"

namespace pat::app {

/// Writes `table` to `path` (the --out path, checked before the work by
/// CommandLine::output_path; "" writes nothing) with `# action:` (grand or upright) and
/// `# analysis:` metadata. Throws InputError naming the file when it cannot be written.
void write_analysis_csv(const std::string& path, CsvTable table, const ActionModel& model,
                        const std::string& analysis);

}  // namespace pat::app

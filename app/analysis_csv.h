// --out CSV for the analysis subcommands (swing, keyfall, touchweight, sweep, the studies): the
// analysis' table, with the action and how it was run in its metadata lines.
#pragma once

#include <string>

#include "command_line.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat::app {

/// Records how a table was made in its `#` lines, as `simulate --out` does: `action` (grand or
/// upright), `preset` (the file read), `settings` (the adjusters turned, or "regulated"),
/// `without` (parts left out, when any) and `options` (the subcommand's arguments as given:
/// the analysis' own, such as a sweep's band or a touchweight's spring factors).
void add_run_metadata(CsvTable& table, const ActionModel& model, const CommandLine& cl);

/// Writes `table` to `path` (the --out path, checked before the work by
/// CommandLine::output_path; "" writes nothing) with add_run_metadata's lines and `# analysis:`.
/// Throws InputError naming the file when it cannot be written.
void write_analysis_csv(const std::string& path, CsvTable table, const ActionModel& model,
                        const std::string& analysis, const CommandLine& cl);

}  // namespace pat::app

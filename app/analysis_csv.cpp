#include "analysis_csv.h"

#include <utility>

#include "model/model_edits.h"

namespace pat::app {

void add_run_metadata(CsvTable& table, const ActionModel& model, const CommandLine& cl) {
  table.metadata["action"] = model.kind;  // as in every CSV: grand or upright
  table.metadata["preset"] = model.source_file;
  table.metadata["settings"] = adjuster_settings_text(model);
  std::string removed;
  for (const std::string& part : model.removed_parts)
    removed += (removed.empty() ? "" : " ") + part;
  if (!removed.empty()) table.metadata["without"] = removed;
  table.metadata["options"] = cl.arguments_text();
}

void write_analysis_csv(const std::string& path, CsvTable table, const ActionModel& model,
                        const std::string& analysis, const CommandLine& cl) {
  if (path.empty()) return;
  add_run_metadata(table, model, cl);
  table.metadata["analysis"] = analysis;
  write_csv(path, table);
}

}  // namespace pat::app

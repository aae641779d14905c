#include "analysis_csv.h"

#include <utility>

#include "model/model_edits.h"

namespace pat::app {

void add_run_metadata(CsvTable& table, const ActionModel& model, const CommandLine& cl) {
  for (auto& [key, value] : model_metadata(model)) table.metadata[key] = value;  // as simulate
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

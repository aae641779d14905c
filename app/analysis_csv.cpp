#include "analysis_csv.h"

#include <utility>

namespace pat::app {

void write_analysis_csv(const CommandLine& cl, CsvTable table, const ActionModel& model,
                        const std::string& analysis) {
  const std::string path = cl.value_or("--out", "");
  if (path.empty()) return;
  table.metadata["action"] = model.name;
  table.metadata["analysis"] = analysis;
  write_csv(path, table);
}

}  // namespace pat::app

#include "analysis_csv.h"

#include <utility>

namespace pat::app {

void write_analysis_csv(const std::string& path, CsvTable table, const ActionModel& model,
                        const std::string& analysis) {
  if (path.empty()) return;
  table.metadata["action"] = model.kind;  // as in every CSV: grand or upright
  table.metadata["analysis"] = analysis;
  write_csv(path, table);
}

}  // namespace pat::app

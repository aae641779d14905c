#include "run_trace_export.h"

#include <cstdio>

#include "core/error.h"
#include "sim/simulation.h"

namespace pat::ui {

CsvTable run_trace_table(const FrameHistory& history, std::map<std::string, std::string> metadata) {
  if (history.empty() || !history.at(0).model)
    throw InputError("the run has no frames to export yet");
  const ActionModel& model = *history.at(0).model;
  CsvTable table;
  table.columns = trace_columns(model);
  char frames[160];
  std::snprintf(frames, sizeof frames,
                "%zu kept by the window, t = %.6g to %.6g s, spaced as they were played "
                "(not a fixed sample rate)",
                history.size(), history.first_time(), history.last_time());
  metadata["frames"] = frames;
  table.metadata = std::move(metadata);
  table.rows.reserve(history.size());
  // the same bodies, contacts and straps in every frame (an adjuster moves geometry only)
  const auto padded = [](const std::vector<double>& values, std::size_t count,
                         std::vector<double>& row) {
    for (std::size_t i = 0; i < count; ++i) row.push_back(i < values.size() ? values[i] : 0.0);
  };
  for (std::size_t i = 0; i < history.size(); ++i) {
    const Frame& f = history.at(i);
    std::vector<double> row;
    row.reserve(table.columns.size());
    row.push_back(f.t);
    padded(f.angle_deg, model.bodies.size(), row);
    row.push_back(f.hammer_string_gap_mm);
    row.push_back(f.finger_force_n);
    padded(f.contact_force_n, model.contacts.size(), row);
    padded(f.strap_tension_n, model.straps.size(), row);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace pat::ui

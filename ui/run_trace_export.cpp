#include "run_trace_export.h"

#include <cstdio>

#include "core/error.h"
#include "sim/simulation.h"

namespace pat::ui {
namespace {

constexpr const char* kHiddenSettings = "hidden (practice exercise)";

// The adjusters whose position differs between the frames (a replayed demo turning its screw,
// a slider moved during the run), in the model's order.
std::vector<std::size_t> changing_adjusters(const FrameHistory& history) {
  const ActionModel& first = *history.at(0).model;
  std::vector<std::size_t> changing;
  for (std::size_t a = 0; a < first.adjusters.size(); ++a)
    for (std::size_t i = 1; i < history.size(); ++i) {
      const ActionModel& m = *history.at(i).model;
      if (a < m.adjusters.size() && m.adjusters[a].value != first.adjusters[a].value) {
        changing.push_back(a);
        break;
      }
    }
  return changing;
}

}  // namespace

CsvTable run_trace_table(const FrameHistory& history, std::map<std::string, std::string> metadata) {
  if (history.empty() || !history.at(0).model)
    throw InputError("the run has no frames to export yet");
  const ActionModel& model = *history.at(0).model;
  CsvTable table;
  table.columns = trace_columns(model);
  // settings that changed during the run go in columns of their own (not in an exercise, where
  // they are what the student looks for); the metadata line then says so
  const bool hidden = metadata.count("settings") && metadata["settings"] == kHiddenSettings;
  const std::vector<std::size_t> changing =
      hidden ? std::vector<std::size_t>{} : changing_adjusters(history);
  for (std::size_t a : changing) table.columns.push_back(model.adjusters[a].name + "_mm");
  if (!changing.empty())
    metadata["settings"] =
        "changed during the run (the _mm columns: each adjuster from its "
        "regulated position, mm)";
  char frames[160];
  std::snprintf(frames, sizeof frames,
                "%zu kept by the window, t = %.6g to %.6g s, spaced as they were played "
                "(not a fixed sample rate)",
                history.size(), history.first_time(), history.last_time());
  metadata["frames"] = frames;
  table.metadata = std::move(metadata);
  table.rows.reserve(history.size());
  for (std::size_t i = 0; i < history.size(); ++i) {
    const Frame& f = history.at(i);
    // every frame of a run has the model's bodies, contacts and straps (an adjuster moves
    // geometry only); one that has not is refused rather than filled with made-up zeros
    if (f.angle_deg.size() != model.bodies.size() ||
        f.contact_force_n.size() != model.contacts.size() ||
        f.strap_tension_n.size() != model.straps.size())
      throw InputError("the frame at t = " + std::to_string(f.t) +
                       " s does not have the action's bodies, contacts and straps");
    std::vector<double> row;
    row.reserve(table.columns.size());
    row.push_back(f.t);
    row.insert(row.end(), f.angle_deg.begin(), f.angle_deg.end());
    row.push_back(f.hammer_string_gap_mm);
    row.push_back(f.finger_force_n);
    row.insert(row.end(), f.contact_force_n.begin(), f.contact_force_n.end());
    row.insert(row.end(), f.strap_tension_n.begin(), f.strap_tension_n.end());
    for (std::size_t a : changing) row.push_back(f.model->adjusters[a].value * 1e3);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace pat::ui

// Upright vs grand (pianoaction study compare): the same key input on both actions, their key
// and hammer motion on one time grid, the first impact of each (time, hammer velocity), and the
// repetition limits of each (repetition_sweep.h, full and half stroke). The six runs (two traces,
// four sweeps) are independent and run in parallel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "analysis/repetition_sweep.h"
#include "io/csv.h"
#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

struct ComparisonOptions {
  std::string input = "force:pulse:10:100";  ///< a mezzo-forte blow (DESIGN.md SPEC)
  double duration_s = 0.3;
  double sample_interval_s = 1e-4;  ///< overlay grid (s)
  bool repetition_limits = true;    ///< also run the four sweeps
  SweepOptions sweep;               ///< stroke and f_max are set per sweep
  double f_max_full_hz = 20.0;
  double f_max_half_hz = 25.0;
};

struct ActionComparison {
  std::string action;    ///< the model's kind (grand, upright)
  SimulationResult run;  ///< under the common input (trace on the common grid)
  std::optional<SimEvent> first_impact;
  std::optional<SweepResult> full_stroke, half_stroke;  ///< when repetition_limits
};

struct ComparisonResult {
  std::vector<ActionComparison> actions;  ///< in the order given
  /// time_s, then for each action ACTION_key_angle_deg, ACTION_hammer_angle_deg,
  /// ACTION_hammer_string_gap_mm, ACTION_finger_force_n; rows up to the shorter run.
  CsvTable overlay;
  double wall_s = 0.0;
};

/// Runs the comparison on `models` (normally the grand and the upright; their kinds must
/// differ). Progress counts the runs; a cancel throws Cancelled.
ComparisonResult compare_actions(const std::vector<const ActionModel*>& models,
                                 const ComparisonOptions& options,
                                 const ProgressCallback& progress = nullptr);

}  // namespace pat

// Automatic regulation (paper section 5.3): settings taken in the technician's order, each
// adjuster found by a bracketing search on its measurement (bisection safeguarded false
// position), passes repeated until every measurement is within tolerance.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/action_model.h"
#include "regulation/measurements.h"

namespace pat {

/// One adjustment made by the regulation.
struct RegulationStep {
  int pass = 0;
  std::string setting;
  double adjuster_mm = 0.0;  ///< position chosen
  double measured = 0.0;     ///< the setting's measurement there (its unit)
  double target = 0.0;
  int evaluations = 0;  ///< measurements taken to find it
  std::string note;     ///< why the setting was left for the next pass, if it was
};

struct RegulationOptions {
  int max_passes = 6;
  /// Called after each setting is adjusted; return false to cancel.
  std::function<bool(const RegulationStep&)> on_step;
};

struct RegulationResult {
  bool converged = false;
  ActionModel model;  ///< the regulated model (adjuster values found)
  std::vector<SettingReading> settings;
  std::vector<RegulationStep> steps;
  int passes = 0;
  double wall_time_s = 0.0;
  std::string message;  ///< why it did not converge, naming the setting
};

/// Regulates `model` from its current adjuster positions. A setting that cannot be measured or
/// reached in one pass (settings interact) is retried in the next. Never throws for an
/// unreachable target: converged = false and message names the setting and what was measured.
RegulationResult regulate(const ActionModel& model, const RegulationOptions& options = {});

/// Writes `model` as a preset: the preset it was read from, with every adjuster's current
/// offset baked into its geometry (the written preset's adjusters read 0 = regulated). The file
/// is written to a temporary name and renamed, so a failure leaves an existing file untouched.
void write_preset(const ActionModel& model, const std::string& path);

}  // namespace pat

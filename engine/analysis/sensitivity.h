// Sensitivity of the action to its regulation (issue 4): each of the seven settings' adjusters
// moved by −step and +step from the current model, and the change of what a player and a
// technician notice — impact velocity for a fixed key force, the time of let-off (escapement)
// under that force, and any further metric groups the caller adds (touchweight, repetition
// limit). The table a teacher shows: which screw matters most, and in which direction.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

/// Metrics computed together from one model (e.g. one simulation gives several numbers).
/// evaluate returns one value per name; NaN when the metric does not exist for that model
/// (no strike, no escapement).
struct SensitivityMetricGroup {
  std::vector<std::string> names;  ///< e.g. impact_velocity_mps (unit in the name)
  std::function<std::vector<double>(const ActionModel&, const RestState&)> evaluate;
};

/// impact_velocity_mps and let_off_time_ms under a constant key force (N), w2. Let-off time: the
/// jack's toe meeting the let-off button, where the trip begins (NaN when it never does before
/// the strike).
SensitivityMetricGroup blow_metrics(double key_force_n = 20.0);

/// The metric groups of the sensitivity table: the blow metrics at this key force, and the
/// static touchweight and repetition limit where available.
std::vector<SensitivityMetricGroup> sensitivity_metric_groups(double key_force_n = 20.0);

/// downweight_g and upweight_g (static touchweight, analysis/touchweight.h).
SensitivityMetricGroup touchweight_metrics();

/// max_repetition_hz: the repetition limit of a chirp (analysis/repetition_sweep.h), halfway
/// stroke on the grand, full stroke on the upright.
SensitivityMetricGroup repetition_metrics();

/// A metric's key in words and its unit, as a table or plot names it: impact_velocity_mps →
/// {"impact velocity", "m/s"}, max_repetition_hz → {"repetition limit", "Hz"} (the keys stay in
/// the CSV and JSON).
struct MetricWords {
  std::string words, unit;
};
MetricWords metric_words(const std::string& key);

struct SensitivityOptions {
  double step_mm = 0.5;  ///< each adjuster at −step and +step
  std::vector<SensitivityMetricGroup> groups = sensitivity_metric_groups();
};

struct SensitivityRow {
  std::string setting;
  std::string unit;  ///< of the setting's measurement
  /// The setting measured at −step, 0, +step (NaN when it cannot be measured there), read as a
  /// technician reads it (read_setting, regulation/measurements.h).
  double measured[3] = {0.0, 0.0, 0.0};
  /// How a reading was taken when not as the variant stands ("drop +1.00 mm"), else empty.
  std::string measured_note[3];
  /// Why a reading is NaN, else empty.
  std::string measured_problem[3];
  /// Metric values at −step and +step, in the order of SensitivityResult::metrics.
  std::vector<double> minus, plus;
  /// The change of metric m per mm of the setting's *measured* value (central difference:
  /// (plus − minus) / (measured[2] − measured[0])); NaN when undefined.
  std::vector<double> per_unit_of_setting;
};

struct SensitivityResult {
  std::vector<std::string> metrics;
  std::vector<double> baseline;  ///< metric values of the model as given
  std::vector<SensitivityRow> rows;
};

/// One setting's effect on one metric: |plus − minus|, the metric's change across the adjuster's
/// −step … +step (the same screw turn for every setting: what a technician compares).
struct SensitivityRank {
  std::string setting;
  double change = 0.0;  ///< in the metric's unit
};

/// "Which screw matters most" for metric `metric` (an index into r.metrics): the settings by
/// |plus − minus|, largest first. Left out: a setting where the metric is NaN on either side,
/// and one whose change is at rounding level (at most 1e-6 of the largest, or none at all).
std::vector<SensitivityRank> rank_by_change(const SensitivityResult& r, std::size_t metric);

/// A variant whose metric lies more than a threshold from the baseline: for a metric that is no
/// smooth function of the screws (the repetition limit jumps between regimes), which screws tip
/// it, instead of a slope.
struct MetricJump {
  std::string setting;
  int side = 0;  ///< −1: the adjuster at −step, +1: at +step
  double value = 0.0;
};
/// A change of the repetition limit taken as a jump between regimes: several hertz (about forty
/// chirp cycles' spacing at 13 Hz and 1 Hz/s), where the screws' smooth effects move it by
/// tenths.
inline constexpr double kRepetitionJumpHz = 3.0;
/// Every such variant of metric `metric`, in the rows' order (− before +); NaN values left out.
std::vector<MetricJump> jumps_beyond(const SensitivityResult& r, std::size_t metric,
                                     double threshold);

/// Runs every (setting × {−, 0, +}) × group case in parallel on the available cores. Settings
/// are those of the model's regulation list. Cancels through `progress` (throws Cancelled).
SensitivityResult sensitivity(const ActionModel& model, const SensitivityOptions& options,
                              const ProgressCallback& progress = {});

}  // namespace pat

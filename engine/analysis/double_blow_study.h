// The upright's bridle strap and butt spring (paper section 7.3, Figs. 25–26; fact F6): the same
// force blows on the upright with both parts, without the bridle strap, without the butt spring
// and without either, and how fast the hammer comes back after the first blow.
//
// Every run starts from the complete upright at rest (the part is unhooked on the resting
// action, so that all four start alike; an upright drawn with its hammer's centre of mass on the
// string side of the centre pin has no rest of its own without the butt spring). Each variant
// runs twice (all runs in parallel, run_parallel):
//  - one pulse (force:pulse:N:MS) for the return: "returned to rest" is the first instant after
//    the first impact at which the strike point is back within `rest_band_mm` of the complete
//    action's rest position (hammer–string gap ≥ rest gap − band); hammer_return_s = that instant −
//    impact time. The band (1 mm, about 2 % of the 45 mm blow) is what a technician's eye calls
//    "back on the rest rail"; null (never) when it does not happen within the run.
//  - two pulses (force:double:N:MS:GAP_MS): the second impact's strike-point speed toward the
//    string, 0 when the second blow does not reach the string.
#pragma once

#include <string>
#include <vector>

#include "analysis/progress.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

struct DoubleBlowOptions {
  double force_n = 15.0;  ///< a forte blow (F2: 2–50 N)
  /// held long enough for the backcheck to catch the hammer (impact ≈ 22 ms, check ≈ 26 ms), so
  /// that the return after the key's release is the work of the strap, the spring and gravity
  double pulse_ms = 60.0;
  double gap_ms = 120.0;
  double duration_s = 0.6;
  double rest_band_mm = 1.0;
};

struct DoubleBlowVariant {
  std::string name;  ///< both, no_bridle, no_butt_spring, neither
  double first_impact_t_s = -1.0;
  double first_impact_velocity_mps = 0.0;
  double hammer_return_s = -1.0;  ///< −1: not back within the run
  /// The second blow's strike: the first impact after the second pulse starts, counted only
  /// when the first blow struck before that (−1: none).
  double second_impact_t_s = -1.0;
  double second_impact_velocity_mps = 0.0;
  /// The double blow struck only after its second pulse had begun: the two pulses drove one
  /// stroke (a gap too short for the first blow to reach the string), so there is no second
  /// blow to time.
  bool one_stroke = false;
  std::string stop_cause;  ///< non-empty when a run stopped early
};

struct DoubleBlowStudy {
  std::vector<DoubleBlowVariant> variants;
  /// time_s, then hammer_angle_deg of the double-blow run of each variant (<name>_hammer_angle_deg)
  CsvTable trace;
};

/// Runs the study on an upright action (one with a "bridle" strap and a "butt_spring").
/// Throws InputError when the action lacks them; `progress` counts the 8 runs and can cancel.
DoubleBlowStudy double_blow_study(const ActionModel& upright, const DoubleBlowOptions& options = {},
                                  const ProgressCallback& progress = {});

}  // namespace pat

// The hidden-effect experiment of DESIGN.md section 4 (issue 6, "must show" 1 and 2): an effect
// with a seeded random value inside its physical range is hidden in three synthetic trials
// (a 1 kg mass, a double blow, a 4 Hz sine), with 0.3° noise at 2000 fps, a time offset within
// ±5 ms and an angle offset within ±0.5°; the diagnosis must name it, estimate its value within
// 25 % and gain at least 50 % on held-out trials. With nothing hidden it must name no cause.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "measured/diagnosis.h"
#include "measured/measured_data.h"
#include "model/effects.h"

namespace pat {

/// One family's test range: values drawn log-uniformly (linear for mm) in [lo, hi], a part of
/// the physical range where the effect changes the hammer's motion visibly.
struct HiddenEffectRange {
  std::string effect;
  double lo = 0.0, hi = 0.0;
};

/// The families of the candidate library with their test ranges for this action.
std::vector<HiddenEffectRange> hidden_effect_ranges(const ActionModel& model);

/// The three inputs of the experiment.
const std::vector<std::string>& hidden_effect_inputs();

/// The value for a range and a seed.
double hidden_value(const HiddenEffectRange& range, unsigned long long seed);

/// The three synthetic trials (0.5 s each) with `hidden` (or nothing) in them; offsets and
/// noise from `seed`.
std::vector<MeasuredTrial> hidden_effect_trials(const ActionModel& model,
                                                const std::optional<Effect>& hidden,
                                                unsigned long long seed);

struct HiddenEffectOutcome {
  std::optional<Effect> hidden;
  Diagnosis diagnosis;
  bool named_right = false;  ///< the cause's family is the hidden one's (null when none hidden)
  double value_error = 0.0;  ///< |estimate − hidden| / hidden (mm effects: / max(|hidden|, 0.5))
  bool passed = false;       ///< named right, value within 25 %, gain ≥ 50 % (or null: no cause)
};

/// Runs one case: synthesizes the trials and diagnoses them with `candidates` (empty: the whole
/// library) on `threads` threads (0: every core).
HiddenEffectOutcome run_hidden_effect_case(const ActionModel& model,
                                           const std::optional<Effect>& hidden,
                                           unsigned long long seed,
                                           const std::vector<std::string>& candidates = {},
                                           unsigned threads = 0);

}  // namespace pat

// The maximum repetition frequencies the reference paper reports (Table 2; DESIGN.md fact F4),
// and a sweep's maximum set beside them in words, so that a result that disagrees says so
// instead of only quoting the fact.
#pragma once

#include <optional>
#include <string>

#include "analysis/repetition_sweep.h"

namespace pat {

/// The paper's model and experiment, Hz. The grand's half-stroke experiment reads "≥ 20": the
/// actuator could not go faster (`experiment_at_least`).
struct PaperRepetitionLimits {
  double model_hz = 0.0;
  double experiment_hz = 0.0;
  bool experiment_at_least = false;
};

/// For an action kind ("grand", "upright") and stroke; empty where the paper gives none (the
/// upright's half stroke, another kind).
std::optional<PaperRepetitionLimits> paper_repetition_limits(const std::string& kind,
                                                             Stroke stroke);

/// A sweep's maximum beside the paper's: "The paper (Table 2): model 13 Hz, experiment 14 Hz;
/// this sweep's 17.5 Hz is above both, a known limit of this model (README, Limits)." Within
/// kPaperAgreementHz of the span of the two it "agrees"; above an "at least" experiment it
/// agrees with that bound; a sweep that found no limit in its band is compared by its last judged
/// cycle's frequency (its max_frequency_hz, a lower bound). `settings`: the action's adjusters
/// turned from regulation (regulation_state: "regulated", or empty, when every setting reads within
/// tolerance): a deregulated action's difference is put down to them, not to the model. Empty when
/// the paper gives no figure or the sweep has no maximum, but for the upright's halfway stroke
/// without one, which says why (no repetition lever).
std::string compare_with_paper(const SweepResult& result, const std::string& kind,
                               const std::string& settings = "regulated");

/// How far outside the paper's model–experiment span a maximum still counts as agreeing, Hz:
/// the facts say "about" (DESIGN.md F4); the sweep itself moves by up to 0.5 Hz between chirp
/// rates (fact F4's stability) and steps 0.5 Hz apart, so 1 Hz is the two together.
inline constexpr double kPaperAgreementHz = 1.0;

}  // namespace pat

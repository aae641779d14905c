// What the model gets wrong on one measured trial (DESIGN.md section 4, item 1): the residual
// of the aligned model by phase of the stroke and by feature, in numbers and in words.
#pragma once

#include <string>
#include <vector>

#include "measured/alignment.h"
#include "measured/measured_data.h"
#include "measured/model_trace.h"

namespace pat {

/// The phases of a stroke, in order.
inline const std::vector<std::string>& phase_names() {
  static const std::vector<std::string> names{
      "rest", "acceleration", "free_flight", "impact", "rebound_and_check", "release", "return"};
  return names;
}

struct PhaseResidual {
  std::string phase;
  int samples = 0;
  double rms_deg = 0.0;   ///< root mean square of the residual in the phase
  double mean_deg = 0.0;  ///< its mean (measured − model): > 0 the hammer is higher than modelled
  /// The measurement's noise within the phase (estimate_noise over the second differences whose
  /// three samples all lie in it): a position sensor's scatter depends on where it reads, e.g.
  /// ten times larger near rest than near the string on the real Kawai files. The whole trial's
  /// noise when the phase has fewer than kMinPhaseNoiseSamples such differences, or when its
  /// own estimate is 0.
  double noise_deg = 0.0;
  /// The same samples under the model with the named cause (add_extended_phases): what it
  /// mends and what it makes worse, phase by phase.
  bool has_extended = false;
  double extended_rms_deg = 0.0;
  double extended_mean_deg = 0.0;
};

/// Second differences a phase needs for its own noise estimate (a median of fewer scatters by
/// more than a quarter of itself).
inline constexpr int kMinPhaseNoiseSamples = 20;

struct FeatureDiscrepancy {
  std::string feature;  ///< impact_time, impact_velocity, let_off_time, check_angle, ...
  std::string unit;
  double measured = 0.0;
  double model = 0.0;
  double difference = 0.0;  ///< measured − model
  bool measured_known = true;
  std::string text;         ///< in words
  bool model_known = true;  ///< false for a property of the residual alone (its oscillation)
};

struct TrialDiscrepancies {
  std::vector<std::string> phase_of_sample;  ///< one per measured sample
  std::vector<PhaseResidual> phases;         ///< every phase that has samples, in order
  std::vector<FeatureDiscrepancy> features;
  /// Dominant frequency of the residual over the longest stretch of rebound and check, and its
  /// amplitude; 0 when there is no peak inside the range searched.
  double residual_oscillation_hz = 0.0;
  double residual_oscillation_deg = 0.0;
};

/// Phases come from the measurement and the key, not from the model judged: rest before the
/// stroke, acceleration from the rise (the last sample near the lowest level since the last
/// impact), free flight from the model's escapement (let-off is not visible in a hammer trace)
/// to 1 ms before the measured impact, impact (−1 ms … +2 ms around the measured impact), rebound
/// and check until the key starts to rise (the file's key, else the input's), release while the
/// hammer falls back from there, return once it is within 0.3 deg of its rest level.
/// Features compare the measured events (detect_events) with the model's, read from the aligned
/// model trace at the file's samples by the same detect_events (the same rule on both sides).
TrialDiscrepancies find_discrepancies(const MeasuredTrial& trial, const ModelTrace& model,
                                      const Alignment& alignment,
                                      const std::vector<MeasuredEvent>& measured_events,
                                      double noise_deg);

/// Adds the residual of the extended model (aligned like the baseline) to each phase.
void add_extended_phases(TrialDiscrepancies& discrepancies, const Alignment& extended);

}  // namespace pat

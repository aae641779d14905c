// Live deregulation (paper section 7.2): an adjuster moves while the action runs with a
// sinusoidal key motion; the setting's measurement is tracked over time, and the run ends when
// a contact penetration becomes unphysical (the cause names the contact and its two parts).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

struct DeregulationOptions {
  std::string setting = "hammer_blow";
  double rate_mm_per_s = 1.0;  ///< adjuster speed (the paper: 0.5 mm every 0.5 s)
  double frequency_hz = 3.0;   ///< key motion: motion:sine:HZ:full
  double duration_s = 10.0;
  /// The adjuster moves in steps of rate × interval every interval (the paper screws the key
  /// pilot 0.5 mm every 0.5 s); 0 moves it continuously (every step).
  double step_interval_s = 0.5;
  /// Called with the simulated time; return false to cancel.
  std::function<bool(double t)> on_progress;
};

struct DeregulationSample {
  double t = 0.0;               ///< s
  double adjuster_mm = 0.0;     ///< adjuster position at t
  double measured = 0.0;        ///< the setting measured (its unit) on the action at that position
  std::string measure_problem;  ///< why it could not be measured there (measured NaN), or empty
  /// How it was read when not as the action stands (read_setting: the let-off with the drop
  /// screw out of the way), or empty.
  std::string measure_note;
  /// hammer–string distance at rest (mm) at that position: the blow, whatever the setting (on
  /// the upright the key pilot is the lost-motion capstan, which shrinks the blow once the jack
  /// lifts the butt)
  double blow_mm = 0.0;
  double hammer_string_gap_mm = 0.0;  ///< dynamic: gap at the top of the key cycle
  double whippen_angle_deg = 0.0;     ///< dynamic: whippen angle at the top of the key cycle
};

struct DeregulationResult {
  std::string status;   ///< "stopped" (unphysical contact, cancel) or "ok" (duration reached)
  double stop_t = 0.0;  ///< s
  std::string stop_cause;
  std::vector<DeregulationSample> samples;  ///< one per key cycle
  CsvTable trace;                           ///< simulate's trace columns plus adjuster_mm
};

DeregulationResult deregulate(const ActionModel& model, const DeregulationOptions& options);

/// A run's stop cause in a technician's words, for a class watching a demo fail: "the jack
/// jammed in the repetition lever's window (it cannot get back under the knuckle)" for the
/// simulator's "unphysical penetration in contact 'jack–repetition lever window' (jack into
/// lever): …"; "the A was driven into the B: the action jams there" for another contact; "the
/// parts left the action's working geometry" for a diverged run; else the cause as it is.
std::string stop_in_trade_words(const std::string& stop_cause);

/// How fast the setting itself should change in a demo a class can follow: 2 mm per second for
/// a setting in mm (a millimetre per 0.5 s screw turn), 0.1 per second for a fraction (the
/// upright's damper lift).
inline constexpr double kDemoSettingRatePerS_mm = 2.0;
inline constexpr double kDemoSettingRatePerS_fraction = 0.1;

/// The adjuster travel (mm) of demo_adjuster_rate's probe.
inline constexpr double kDemoProbe_mm = 0.25;

/// The adjuster speed (mm/s, positive: the adjuster's own + direction) at which setting
/// `setting` of `model` changes by about the rate above: that rate over |Δm / Δa|, the change of
/// the measured setting for a probe of kDemoProbe_mm of its adjuster from where it stands (+,
/// or − where + cannot be read or changes nothing), within [0.05, 2] mm/s and rounded to
/// 0.05 mm/s. The adjuster-to-setting ratios differ widely: about 1 for key dip, 6 for the
/// grand's let-off (mm of hammer per mm of button), 12 for its hammer blow (capstan). 1 mm/s
/// when the setting cannot be measured on this action. Throws InputError for an unknown setting.
double demo_adjuster_rate(const ActionModel& model, const std::string& setting);

/// The adjuster's position over time as the run turned it, from the trace's time_s and
/// adjuster_mm: a staircase (two points at the time of each turn, the old and the new position,
/// and the last position held to the trace's end), for a plot. Empty without those columns.
struct AdjusterSteps {
  std::vector<double> t_s, mm;
};
AdjusterSteps adjuster_steps(const CsvTable& trace);

}  // namespace pat

// The technician's measurements of the seven regulation settings (DESIGN.md section 3), taken
// on the simulated action the way they are taken on a real one:
//   rest geometry        key dip (key-front travel to the punching), hammer blow (hammer–string
//                        distance at rest), lever height (knuckle–jack gap at rest; with the
//                        knuckle down on the jack, minus the lever top's gap below it), jack
//                        position (jack edge vs knuckle core), lost motion (jack–butt gap),
//                        bridle (strap slack at rest);
//   slow key press       let-off (hammer–string distance at escapement), drop (distance after
//                        the hammer drops onto the repetition lever), damper lift (fraction of
//                        the hammer travel at which the damper starts to lift);
//   forte blow           checking (hammer–string distance when the backcheck catches it).
// Values are in the setting's unit (mm, or a fraction).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

/// One measured setting, with its target and adjuster position.
struct SettingReading {
  std::string name;
  std::string unit;
  double target = 0.0;
  double tolerance = 0.0;
  double measured = 0.0;
  double adjuster_mm = 0.0;  ///< adjuster offset from the preset's regulated position
  /// Why the setting could not be read there (measured is then NaN); empty when it was read.
  std::string problem;
  /// How it was read when not as the action stands (read_setting): e.g. the grand's let-off
  /// with the drop screw out of the way; empty when read as it stands.
  std::string note;
  bool within_tolerance() const;  ///< false when not read
};

/// Whether `measured` (the setting's unit) lies within the setting's tolerance of its target.
bool within_tolerance(const RegulationSetting& setting, double measured);

/// Measures setting `name` of `model` (its unit). `rest` may pass the model's rest state.
/// Throws InputError for an unknown setting, std::runtime_error when the measurement cannot be
/// taken (e.g. the action never escapes in the slow press) with the reason.
double measure_setting(const ActionModel& model, const std::string& name,
                       const RestState* rest = nullptr);

/// The aftertouch (mm): key-front travel left to the front-rail punching at let-off in a slow
/// press. Not one of the seven settings but their result (key dip, blow and let-off; domain
/// notes: about .045 in, 1.1 mm). Throws std::runtime_error with the reason when the slow press
/// shows no escapement.
double measure_aftertouch(const ActionModel& model, const RestState* rest = nullptr);

/// The aftertouch technicians set: .035–.045 in, 0.89–1.14 mm on a grand's front rail
/// (domain.md, table row 8: Yamaha about .035, Steinway .045).
inline constexpr double kAftertouchGaugeLowMm = 0.035 * 25.4;
inline constexpr double kAftertouchGaugeHighMm = 0.045 * 25.4;
/// Where an aftertouch lies against that gauge.
enum class AgainstGauge { less, within, more };
inline AgainstGauge aftertouch_against_gauge(double aftertouch_mm) {
  return aftertouch_mm < kAftertouchGaugeLowMm    ? AgainstGauge::less
         : aftertouch_mm > kAftertouchGaugeHighMm ? AgainstGauge::more
                                                  : AgainstGauge::within;
}

/// Setting `setting` of `model` as a technician reads it (its problem when it cannot be read).
/// Where a slow press shows the hammer carried by another part (HammerCarriedElsewhere: the
/// grand's repetition lever, stopped by a drop screw that is too high for a let-off button
/// screwed down) and the setting names the adjuster that is moved out of the way first
/// (RegulationSetting::clear_adjuster, the drop screw), it is read again with that adjuster at
/// its clear position, as technicians set let-off with the drop screw out of the way; `note` then
/// says so. `rest` may pass the model's rest state.
SettingReading read_setting(const ActionModel& model, const RegulationSetting& setting,
                            const RestState* rest = nullptr);

/// Every setting of the model's regulation list, in the technician's order, from one rest state
/// (read_setting).
/// A setting that cannot be read there gets measured = NaN and its `problem`; the others are
/// still read. The settings are read in parallel on `threads` threads (0: one per core); each
/// read one counts as an item of `progress`, which can cancel (throws Cancelled).
std::vector<SettingReading> read_settings(const ActionModel& model,
                                          const ProgressCallback& progress = {},
                                          unsigned threads = 0);

/// The same on one thread, throwing the first setting's problem (std::runtime_error) instead.
std::vector<SettingReading> measure_settings(const ActionModel& model);

/// "regulated" when the adjusters are at their regulated positions or every setting reads within
/// its tolerance (automatic regulation leaves offsets of micrometres: still regulated); else the
/// adjusters' offsets (adjuster_settings_text), to which a result's difference is put down.
std::string regulation_state(const ActionModel& model);

}  // namespace pat

// A raw hammer-shank sensor trace (raw_trace.h) turned into the measured-data format
// (measured_data.h; DESIGN.md section 5): time_s, hammer_angle_deg (degrees from rest, toward the
// string positive) and the normalized sensor reading it came from (sensor_reading, fraction of
// the ADC's full scale).
//
// Sample i of the window [from, to] is at time_s = (i − i_from) / rate (s from the window start).
//
// The angle is θ = θ_c · s, where θ_c is the model's hammer rotation from rest to string contact
// (hammer_contact_angle_deg, from the preset) and s the hammer's travel as a fraction of its
// rest-to-string travel, from one of two calibrations:
//
// * estimated (no calibration points): the sensor is taken to be linear in the hammer angle
//   between two levels found in the trace,
//       s = (r − r_rest) / (r_peak − r_rest),
//   r_rest = the median reading of the window's first 50 ms (the hammer at rest; at least 5 and
//   at most a quarter of the samples), r_peak = the reading farthest from it (the hammer against
//   the string: the strike's peak). Monotone whichever way the sensor runs: a reversed sensor
//   (readings that fall as the hammer rises) has r_peak < r_rest and the same formula. Exact at
//   rest and at the string; in between, a curved sensor (the CNY-70 is strongly nonlinear in
//   distance) is off by its departure from the straight line through those two levels.
// * the author's points (sensor_calibration.h): position p(r) at the sensor spot by monotone
//   cubic interpolation, with the first point at rest and the last at the string (true of
//   calibration.csv: 0 in at reading 0, and 0.148 in ≈ the 5/32 in travel of the sensor spot at
//   reading 1, which the strikes of hammer_damper_2K_17b.txt reach),
//       s = (p(r) − p_first) / (p_last − p_first).
//   A point at radius ρ on the shank moves ρ sin θ toward the sensor, so s ∝ sin θ rather than θ;
//   at θ_c ≈ 20° the two differ by < 2 % (sin x / x = 0.98), below the calibration's resolution
//   (its points are 1/64 in, about 10 % of the travel, apart), and s is used as linear in θ.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "io/csv.h"
#include "measured/key_sensor.h"
#include "measured/raw_trace.h"
#include "measured/sensor_calibration.h"
#include "model/action_model.h"

namespace pat {

/// The hammer's rotation (deg, trace sign: toward the string positive) from the model's rest
/// state to string contact, turning the hammer joint alone (its ancestors held at rest) until the
/// strike point reaches the string plane (ActionDynamics::hammer_string_gap = 0). Throws
/// InputError naming the preset when the hammer never reaches the string within 90°.
double hammer_contact_angle_deg(const ActionModel& model);

/// The strike seen in a raw trace: rest level, noise and peak (see the file comment).
struct RawStrike {
  double rest_reading = 0.0;   ///< median of the first 50 ms
  double noise = 0.0;          ///< 1.4826 MAD of those samples (reading units)
  std::size_t peak_index = 0;  ///< in the window
  double peak_reading = 0.0;
  bool reversed = false;  ///< readings fall as the hammer rises
};

/// Finds the strike in a window of readings sampled at `rate_hz`: the reading farthest from the
/// rest level, more than 20 times the rest noise (at least 2e-5 of full scale) from it, after
/// the rest samples, and followed within 20 ms by a rebound (a return by 10 % of the excursion,
/// as the hammer leaves the string; a hammer pushed slowly to the string and held is no strike).
/// Returns nothing and says why in `why_not` when there is none.
std::optional<RawStrike> find_raw_strike(const std::vector<double>& reading, double rate_hz,
                                         std::string& why_not);

struct RawImportOptions {
  double rate_hz = 0.0;  ///< samples per second of the file
  double from_s = 0.0;   ///< window start, s of the file's time (sample i at i / rate)
  double to_s = std::numeric_limits<double>::infinity();
  /// the author's points; without them the calibration is estimated from rest and peak
  std::optional<SensorCalibration> calibration;
  double contact_angle_deg = 0.0;  ///< θ_c (hammer_contact_angle_deg of the action)
  std::string action;              ///< for the "# action:" line
  /// The key's own sensor, another column of the same file (key_sensor.h), with its calibration
  /// points and the key front's arm (key_front_arm_m); without it the file has no key angle.
  std::optional<RawTrace> key_trace;
  std::optional<SensorCalibration> key_calibration;
  double key_front_arm_m = 0.0;
};

struct RawImport {
  CsvTable table;                   ///< the measured-data file, ready for write_csv
  std::size_t first_sample = 0;     ///< index in the file of the window's first sample
  std::optional<RawStrike> strike;  ///< always found without calibration points
  double peak_t_s = 0.0;            ///< strike peak, s from the window start (when found)
  double peak_angle_deg = 0.0;      ///< the angle it maps to
  std::optional<KeyAngles> key;     ///< the key angles, when a key sensor was given
};

/// Converts the window of a raw trace; with a key sensor the file also gets key_angle_deg (and
/// the key's reading, key_sensor_reading), which diagnose then uses as the model's input. Throws
/// InputError naming the file or option: rate ≤ 0 or too slow to resolve the impact
/// (kMaxSampleIntervalS), an empty or reversed window, fewer than kMinMeasuredSamples samples in
/// it, no strike found when there are no calibration points, a key sensor without its points or
/// with another length than the hammer's column.
RawImport import_raw(const RawTrace& trace, const RawImportOptions& options);

}  // namespace pat

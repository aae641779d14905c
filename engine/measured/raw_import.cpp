#include "measured/raw_import.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>

#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "measured/measured_data.h"
#include "measured/rest_level.h"
#include "sim/simulation.h"

namespace pat {

double hammer_contact_angle_deg(const ActionModel& model) {
  const RestState rest = find_rest_state(model);
  ActionDynamics dynamics(model, nullptr);
  const int hammer = model.landmarks.hammer;
  const double sign = model.bodies[static_cast<std::size_t>(hammer)].trace_sign;
  // gap (m) with the hammer turned by `angle` (rad, toward the string) from rest
  auto gap = [&](double angle) {
    DofVector q = rest.q;
    q[hammer] += sign * angle;
    return dynamics.hammer_string_gap(q);
  };
  const double step = 5.0 * kPi / 180.0, limit = 0.5 * kPi;
  double low = 0.0, high = step;
  if (!(gap(0.0) > 0.0))
    throw InputError(
        located_message(model.source_file, "landmarks", "the hammer touches the string at rest"));
  while (gap(high) > 0.0) {
    low = high;
    high += step;
    if (high > limit)
      throw InputError(located_message(
          model.source_file, "landmarks",
          "the hammer does not reach the string within 90 degrees of rotation from rest"));
  }
  // bisection to 1e-12 rad: the gap is monotone over one 5° step of a ~20° blow
  while (high - low > 1e-12) {
    const double mid = 0.5 * (low + high);
    (gap(mid) > 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high) * 180.0 / kPi;
}

namespace {

std::string number_text(double x, int precision = 6) {
  std::ostringstream out;
  out.precision(precision);
  out << x;
  return out.str();
}

/// The key angles of the window [first, first + count) into `result`, and the table's key
/// columns and metadata.
void add_key_columns(const RawImportOptions& o, const RawTrace& hammer, std::size_t first,
                     std::size_t count, RawImport& result, CsvTable& table) {
  const RawTrace& key = *o.key_trace;
  if (!o.key_calibration)
    throw InputError("the key's sensor (column " + std::to_string(key.column) +
                     ") needs its calibration points: without them its curved reading cannot be "
                     "turned into a key-front dip");
  if (key.reading.size() != hammer.reading.size())
    throw InputError(located_message(
        hammer.path, "",
        "the key's column " + std::to_string(key.column) + " has " +
            std::to_string(key.reading.size()) + " samples and the hammer's column " +
            std::to_string(hammer.column) + " " + std::to_string(hammer.reading.size()) +
            ": both must come from the same recording"));
  const std::vector<double> window(
      key.reading.begin() + static_cast<std::ptrdiff_t>(first),
      key.reading.begin() + static_cast<std::ptrdiff_t>(first + count));
  const SensorCalibration& c = *o.key_calibration;
  result.key = key_angles_from_sensor(window, o.rate_hz, c, o.key_front_arm_m);
  std::ostringstream note;
  note << "calibration points of " << std::filesystem::path(c.path).filename().string()
       << (c.sensor.empty() ? "" : " (" + c.sensor + ")") << " for column " << key.column
       << ", normalized = (reading - " << c.offset << ") / " << c.gain
       << ", key-front position by monotone cubic interpolation, minus its rest "
       << number_text(result.key->rest_position_in) << " in (median of the first 50 ms); key "
       << "angle = asin(dip / " << number_text(1e3 * o.key_front_arm_m, 4)
       << " mm, the model's key front arm); smoothed by a Gaussian of sigma "
       << number_text(1e3 * kKeySmoothingSigmaS, 3) << " ms (engine/measured/key_sensor.h)";
  table.metadata["key_calibration"] = note.str();
  table.columns.push_back("key_angle_deg");
  table.columns.push_back("key_sensor_reading");
}

}  // namespace

std::optional<RawStrike> find_raw_strike(const std::vector<double>& r, double rate_hz,
                                         std::string& why_not) {
  const std::size_t n = r.size();
  // rest: the first 50 ms, at least 5 samples and at most a quarter of the window
  const std::size_t rest_count = rest_sample_count(n, rate_hz);
  if (n < 2 * rest_count) {
    why_not = "the window is too short to hold a rest level and a strike";
    return std::nullopt;
  }
  RawStrike strike;
  const std::vector<double> rest(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(rest_count));
  strike.rest_reading = median(rest);
  std::vector<double> deviation(rest_count);
  for (std::size_t i = 0; i < rest_count; ++i)
    deviation[i] = std::abs(rest[i] - strike.rest_reading);
  strike.noise = 1.4826 * median(deviation);

  std::size_t peak = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(r[i] - strike.rest_reading) > std::abs(r[peak] - strike.rest_reading)) peak = i;
  const double excursion = r[peak] - strike.rest_reading;
  // 20 noise sigmas: a strike spans the whole stroke, hundreds of sigmas on the real files;
  // the floor keeps a noise-free synthetic trace's rounding from counting as a strike
  const double threshold = 20.0 * std::max(strike.noise, 1e-6);
  const double duration_ms = 1e3 * static_cast<double>(rest_count) / rate_hz;
  std::ostringstream reason;
  if (std::abs(excursion) <= threshold) {
    reason << "the reading never leaves its rest level " << number_text(strike.rest_reading)
           << " (median of the first " << number_text(duration_ms, 3) << " ms, noise "
           << number_text(strike.noise, 3) << ") by more than 20 times its noise";
    why_not = reason.str();
    return std::nullopt;
  }
  if (peak < rest_count) {
    reason << "the reading is farthest from rest within the first " << number_text(duration_ms, 3)
           << " ms, which must be the hammer at rest (start the window before the strike)";
    why_not = reason.str();
    return std::nullopt;
  }
  // the rebound: within 20 ms the reading returns toward rest by 10 % of the excursion
  const std::size_t rebound_end =
      std::min(n, peak + 1 + static_cast<std::size_t>(std::ceil(0.02 * rate_hz)));
  bool rebounds = false;
  for (std::size_t i = peak + 1; i < rebound_end && !rebounds; ++i)
    rebounds = std::abs(r[i] - strike.rest_reading) < 0.9 * std::abs(excursion);
  if (!rebounds) {
    reason << "the largest excursion from rest (reading " << number_text(r[peak]) << " at "
           << number_text(static_cast<double>(peak) / rate_hz) << " s into the window, rest "
           << number_text(strike.rest_reading)
           << ") is not followed within 20 ms by a rebound from the string (a return by 10 % of "
              "the excursion): a hammer pushed slowly to the string is not a strike";
    why_not = reason.str();
    return std::nullopt;
  }
  strike.peak_index = peak;
  strike.peak_reading = r[peak];
  strike.reversed = excursion < 0.0;
  return strike;
}

RawImport import_raw(const RawTrace& trace, const RawImportOptions& o) {
  const std::string& path = trace.path;
  std::ostringstream problem;
  if (!(o.rate_hz > 0.0) || !std::isfinite(o.rate_hz)) {
    problem << "--rate must be a positive sample rate in samples/s (got " << o.rate_hz << ")";
    throw InputError(problem.str());
  }
  if (1.0 / o.rate_hz > kMaxSampleIntervalS) {
    problem << "--rate " << o.rate_hz
            << " samples/s is too slow to resolve the hammer-string impact, which lasts 1-4 ms "
               "(at least "
            << 1.0 / kMaxSampleIntervalS << " samples/s are needed)";
    throw InputError(problem.str());
  }
  if (!(o.from_s >= 0.0) || !std::isfinite(o.from_s)) {
    problem << "--from " << o.from_s << " s: the window must start at 0 s or later";
    throw InputError(problem.str());
  }
  if (!(o.to_s > o.from_s)) {  // an --to not given is +inf
    problem << "--from " << o.from_s << " s and --to " << o.to_s
            << " s: the window must end after it starts";
    throw InputError(problem.str());
  }
  const std::size_t total = trace.reading.size();
  const double file_duration = static_cast<double>(total - 1) / o.rate_hz;
  const auto first = static_cast<std::size_t>(std::ceil(o.from_s * o.rate_hz - 1e-9));
  // bounded in floating point before the cast (an --to of 1e17 s overflowed the index)
  const std::size_t last = static_cast<std::size_t>(
      std::min(static_cast<double>(total - 1), std::floor(o.to_s * o.rate_hz + 1e-9)));
  const std::size_t count = first <= last && first < total ? last - first + 1 : 0;
  if (o.from_s > file_duration) {  // the window lies beyond the recording's end
    problem << "--from " << o.from_s << " s is beyond the end of the recording: column "
            << trace.column << " holds " << total << " samples, " << file_duration << " s at "
            << o.rate_hz << " samples/s";
    throw InputError(located_message(path, "", problem.str()));
  }
  if (count < kMinMeasuredSamples) {
    problem << "only " << count << " sample" << (count == 1 ? "" : "s") << " in the window "
            << o.from_s << " s to " << std::min(o.to_s, file_duration) << " s of column "
            << trace.column << " (" << total << " samples, " << file_duration << " s at "
            << o.rate_hz << " samples/s in the file; at least " << kMinMeasuredSamples
            << " are needed)";
    throw InputError(located_message(path, "", problem.str()));
  }
  const std::vector<double> r(trace.reading.begin() + static_cast<std::ptrdiff_t>(first),
                              trace.reading.begin() + static_cast<std::ptrdiff_t>(first + count));

  RawImport result;
  result.first_sample = first;
  std::string why_not;
  result.strike = find_raw_strike(r, o.rate_hz, why_not);
  if (!result.strike && !o.calibration) {
    problem << "no strike found in column " << trace.column << " between "
            << static_cast<double>(first) / o.rate_hz << " s and "
            << static_cast<double>(first + count - 1) / o.rate_hz << " s: " << why_not
            << "; without calibration points (--calibration) the rest level and the strike's "
               "peak are needed to calibrate the sensor";
    throw InputError(located_message(path, "", problem.str()));
  }

  // s(r): the fraction of the rest-to-string travel (raw_import.h)
  std::function<double(double)> travel;
  std::ostringstream calibration_note;
  if (o.calibration) {
    const SensorCalibration& c = *o.calibration;
    const double p_first = c.position.front(), p_last = c.position.back();
    travel = [&c, p_first, p_last](double reading) {
      return (c.position_at(reading) - p_first) / (p_last - p_first);
    };
    calibration_note << "calibration points of "
                     << std::filesystem::path(c.path).filename().string()
                     << (c.sensor.empty() ? "" : " (" + c.sensor + ")")
                     << ", normalized = (reading - " << c.offset << ") / " << c.gain
                     << ", position by monotone cubic interpolation; position " << p_first
                     << " in (rest) = 0 deg, " << p_last
                     << " in (string) = " << number_text(o.contact_angle_deg, 5)
                     << " deg (the model's hammer rotation from rest to string contact), linear "
                        "between";
  } else {
    const RawStrike& s = *result.strike;
    const double rest = s.rest_reading, span = s.peak_reading - s.rest_reading;
    travel = [rest, span](double reading) { return (reading - rest) / span; };
    calibration_note << "estimated, sensor taken as linear in the hammer angle: reading "
                     << number_text(rest) << " (rest, median of the first 50 ms) = 0 deg, "
                     << number_text(s.peak_reading) << " (string-contact peak at "
                     << number_text(static_cast<double>(s.peak_index) / o.rate_hz)
                     << " s) = " << number_text(o.contact_angle_deg, 5)
                     << " deg (the model's hammer rotation from rest to string contact)"
                     << (s.reversed ? "; reversed sensor (readings fall as the hammer rises)" : "");
  }

  CsvTable& table = result.table;
  table.metadata["action"] = o.action;
  std::ostringstream source;
  source << std::filesystem::path(path).filename().string() << " column " << trace.column
         << (o.key_trace ? " (hammer) and column " + std::to_string(o.key_trace->column) + " (key)"
                         : std::string())
         << ", samples " << first << " to " << first + count - 1 << " ("
         << static_cast<double>(first) / o.rate_hz << " to "
         << static_cast<double>(first + count - 1) / o.rate_hz << " s at " << o.rate_hz
         << " samples/s), "
         << (trace.counts ? "ADC counts out of 2^" + std::to_string(trace.bits)
                          : std::string("normalized readings"));
  table.metadata["source"] = source.str();
  table.metadata["calibration"] = calibration_note.str();
  table.columns = {"time_s", "hammer_angle_deg", "sensor_reading"};
  if (o.key_trace) add_key_columns(o, trace, first, count, result, table);
  table.rows.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // 1e-4 deg: far below the sensor's noise (about 0.05 deg at rest on the real files)
    const double angle = std::round(o.contact_angle_deg * travel(r[i]) * 1e4) / 1e4;
    table.rows.push_back({static_cast<double>(i) / o.rate_hz, angle, r[i]});
    if (result.key) {
      // 1e-5 deg of key: 0.04 µm at the key front
      table.rows.back().push_back(std::round(result.key->angle_deg[i] * 1e5) / 1e5);
      table.rows.back().push_back(o.key_trace->reading[first + i]);
    }
  }
  if (result.strike) {
    result.peak_t_s = static_cast<double>(result.strike->peak_index) / o.rate_hz;
    result.peak_angle_deg = table.rows[result.strike->peak_index][1];
  }
  // the file must pass the measured-data checks that diagnose applies
  measured_from_table(table, path, o.action);
  return result;
}

}  // namespace pat

#include "measured/measured_data.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "io/csv.h"
#include "measured/rest_level.h"

namespace pat {

double MeasuredTrial::sample_interval_s() const {
  if (t.size() < 2) return 0.0;
  return (t.back() - t.front()) / static_cast<double>(t.size() - 1);
}

MeasuredTrial read_measured(const std::string& path, const std::string& expected_action) {
  // read_csv names the file and line for NaN, text and short rows
  return measured_from_table(read_csv(path), path, expected_action);
}

MeasuredTrial measured_from_table(const CsvTable& table, const std::string& path,
                                  const std::string& expected_action) {
  MeasuredTrial trial;
  trial.path = path;
  for (const char* needed : {"time_s", "hammer_angle_deg"})
    if (table.column_index(needed) < 0) {
      std::string have;
      for (const std::string& c : table.columns) have += (have.empty() ? "" : ", ") + c;
      throw InputError(path + ": missing column '" + needed + "' (measured data needs time_s " +
                       "and hammer_angle_deg; the file has: " + have + ")");
    }
  auto meta = [&](const char* key) {
    const auto it = table.metadata.find(key);
    return it == table.metadata.end() ? std::string() : it->second;
  };
  trial.action = meta("action");
  trial.input_spec = meta("input");
  if (!expected_action.empty() && !trial.action.empty() && trial.action != expected_action)
    throw InputError(path + ": the data were measured on the " + trial.action +
                     " action ('# action: " + trial.action + "') but the " + expected_action +
                     " action was requested");
  trial.t = table.column("time_s");
  trial.hammer_deg = table.column("hammer_angle_deg");
  if (table.column_index("key_angle_deg") >= 0) trial.key_deg = table.column("key_angle_deg");
  trial.key_force_measured = table.column_index("key_force_n") >= 0;
  if (trial.t.size() < kMinMeasuredSamples)
    throw InputError(path + ": only " + std::to_string(trial.t.size()) + " samples (at least " +
                     std::to_string(kMinMeasuredSamples) + " are needed)");
  for (std::size_t i = 1; i < trial.t.size(); ++i)
    if (!(trial.t[i] > trial.t[i - 1])) {
      std::ostringstream out;
      // the file's line where it was read from a file, as every other message names it
      if (table.row_lines.size() == trial.t.size())
        out << path << ": line " << table.row_lines[i] << ": time_s is not increasing ("
            << trial.t[i - 1] << " s on line " << table.row_lines[i - 1] << ", then " << trial.t[i]
            << " s)";
      else
        out << path << ": time_s is not increasing at data row " << i + 1 << " (" << trial.t[i - 1]
            << " s, then " << trial.t[i] << " s)";
      throw InputError(out.str());
    }
  const double dt = trial.sample_interval_s();
  if (dt > kMaxSampleIntervalS) {
    std::ostringstream out;
    out << path << ": sampled every " << dt * 1e3 << " ms (" << 1.0 / dt
        << " samples/s), too slow to resolve the hammer-string impact, which lasts 1-4 ms "
           "(at least "
        << 1.0 / kMaxSampleIntervalS << " samples/s are needed)";
    throw InputError(out.str());
  }
  return trial;
}

double estimate_noise(const std::vector<double>& v) {
  if (v.size() < 5) return 0.0;
  std::vector<double> d2;
  d2.reserve(v.size());
  for (std::size_t i = 1; i + 1 < v.size(); ++i) d2.push_back(v[i + 1] - 2 * v[i] + v[i - 1]);
  return noise_from_second_differences(std::move(d2));
}

double noise_from_second_differences(std::vector<double> d2) {
  if (d2.size() < 3) return 0.0;
  const double m = median(d2);
  for (double& x : d2) x = std::abs(x - m);
  return 1.4826 * median(d2) / std::sqrt(6.0);
}

std::vector<double> moving_average5(const std::vector<double>& values) {
  const std::size_t n = values.size();
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i < 2 ? 0 : i - 2, b = std::min(n - 1, i + 2);
    double sum = 0.0;
    for (std::size_t j = a; j <= b; ++j) sum += values[j];
    out[i] = sum / static_cast<double>(b - a + 1);
  }
  return out;
}

std::vector<MeasuredEvent> detect_events(const std::vector<double>& t, const std::vector<double>& h,
                                         double noise_deg) {
  std::vector<MeasuredEvent> events;
  const std::size_t n = h.size();
  if (n < 5) return events;
  // light smoothing against the noise for the check search
  const std::vector<double> s = moving_average5(h);
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  const double range = *hi - *lo;
  if (range < 10.0 * noise_deg || range <= 0) return events;
  const double top = *hi - 0.25 * range;
  const double dt = (t.back() - t.front()) / static_cast<double>(n - 1);
  const std::size_t window = std::max<std::size_t>(2, static_cast<std::size_t>(2e-3 / dt));
  // a new impact needs a new stroke: the hammer must have fallen halfway back since the last one
  // (otherwise the second maximum is the same strike's bounce or the shank's vibration)
  bool armed = true;
  std::size_t i = 1;
  while (i + 1 < n) {
    if (!armed && s[i] < *lo + 0.5 * range) armed = true;
    // a local maximum of the raw trace over ±2 ms, above `top`
    if (armed && h[i] >= top && h[i] >= h[i - 1] && h[i] >= h[i + 1]) {
      const std::size_t a = i > window ? i - window : 0, b = std::min(n - 1, i + window);
      bool is_max = true;
      for (std::size_t j = a; j <= b && is_max; ++j) is_max = h[j] <= h[i];
      // followed by a rebound: within 20 ms the angle falls by 10 % of the range
      bool rebounds = false;
      for (std::size_t j = i; j < n && t[j] < t[i] + 20e-3 && !rebounds; ++j)
        rebounds = h[j] < h[i] - 0.1 * range;
      if (is_max && rebounds) {
        const double y0 = h[i - 1], y1 = h[i], y2 = h[i + 1];
        const double denom = y0 - 2 * y1 + y2;
        const double shift = denom < 0 ? 0.5 * (y0 - y2) / denom : 0.0;
        events.push_back({"impact", t[i] + std::clamp(shift, -0.5, 0.5) * dt, y1});
        armed = false;
        // the check: the smoothed angle stops falling (stays within a band for 5 ms)
        const std::size_t hold = std::max<std::size_t>(3, static_cast<std::size_t>(5e-3 / dt));
        const double band = std::max(3.0 * noise_deg, 0.02 * range);
        for (std::size_t j = i + window; j + hold < n && t[j] < t[i] + 0.2; ++j) {
          if (s[j] > h[i] - 0.1 * range) continue;  // still near the string
          bool still = true;
          for (std::size_t k = j; k <= j + hold && still; ++k) still = std::abs(s[k] - s[j]) < band;
          if (still) {
            if (s[j] - *lo > range / 3.0) events.push_back({"check", t[j], s[j]});
            break;
          }
        }
        i = b + 1;
        continue;
      }
    }
    ++i;
  }
  return events;
}

}  // namespace pat

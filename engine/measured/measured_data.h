// Measured hammer traces (DESIGN.md sections 4 and 5): reading and checking a measured-data
// file, and finding the impacts and checks visible in it.
//
// File: '#' metadata lines `# action: grand|upright` and `# input: SPEC` (optional), a header
// with time_s and hammer_angle_deg (degrees from rest, toward the string positive), optionally
// key_angle_deg and key_force_n.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pat {

struct MeasuredTrial {
  std::string path;
  std::string action;      ///< from "# action:", empty when absent
  std::string input_spec;  ///< from "# input:", empty when absent
  std::vector<double> t;   ///< s, strictly increasing
  std::vector<double> hammer_deg;
  std::vector<double> key_deg;      ///< empty when not measured
  bool key_force_measured = false;  ///< the file has key_force_n (the finger's force, N)
  double sample_interval_s() const;
  double duration_s() const { return t.empty() ? 0.0 : t.back() - t.front(); }
};

/// The hammer–string contact lasts 1–4 ms (paper section 6; Askenfelt & Jansson): a trace must
/// be sampled at least every 1 ms to see the impact at all.
inline constexpr double kMaxSampleIntervalS = 1e-3;
/// Fewest samples a measured trace may have.
inline constexpr std::size_t kMinMeasuredSamples = 20;

/// Reads and checks a measured file. `expected_action` ("grand"/"upright"; empty: any) must
/// match its "# action:" line when it has one. Throws InputError naming the file and the
/// problem: missing column, non-monotone time (with the line), non-finite value, action
/// mismatch, fewer than kMinMeasuredSamples samples, or a sample interval too long to resolve the
/// impact.
MeasuredTrial read_measured(const std::string& path, const std::string& expected_action);

struct CsvTable;
/// The same checks on a table already read (e.g. synthesized in memory); `path` names it.
MeasuredTrial measured_from_table(const CsvTable& table, const std::string& path,
                                  const std::string& expected_action);

/// An event seen in a hammer trace.
struct MeasuredEvent {
  std::string type;  ///< "impact" or "check"
  double t = 0.0;    ///< s, in the file's time
  double angle_deg = 0.0;
};

/// Impacts: local maxima of the hammer angle within 25 % of the trace's range from its top,
/// followed by a fall (the rebound), and only after the hammer has fallen halfway back since
/// the previous impact (a new stroke, not a bounce); the time is refined by a parabola through the
/// three samples around the peak. Checks: after an impact, the first time the hammer's fall stops
/// (the smoothed angle stays within `noise_deg`·3 for 5 ms) above a third of the peak angle.
std::vector<MeasuredEvent> detect_events(const std::vector<double>& t,
                                         const std::vector<double>& hammer_deg, double noise_deg);

/// The 5-sample centred moving average of `values` (2 before, 2 after; fewer at the ends): white
/// noise shrinks by √5, and a change shows in it two samples before it happens.
std::vector<double> moving_average5(const std::vector<double>& values);

/// Noise level of a sampled signal (deg): 1.4826·MAD of the second differences / √6, which a
/// smooth signal barely affects (white noise σ gives second differences of variance 6σ²).
double estimate_noise(const std::vector<double>& values);

/// The same estimate from second differences already taken (v[i+1] − 2v[i] + v[i−1]), e.g.
/// only those of one phase of a stroke; 0 for fewer than 3.
double noise_from_second_differences(std::vector<double> second_differences);

}  // namespace pat

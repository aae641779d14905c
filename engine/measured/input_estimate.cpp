#include "measured/input_estimate.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/format.h"
#include "measured/model_trace.h"

namespace pat {
namespace {

constexpr double kOnsetFraction = 0.05;  // motion onset: 5 % of the way from rest to the peak
constexpr double kKeptS = 0.5;           // of the trial, kept from the model's motion onset (s)

std::string pulse_spec(double force, double ms) {
  std::ostringstream out;
  out << "force:pulse:" << force << ":" << ms;
  return out.str();
}

struct ModelRise {
  bool ok = false;
  double onset = 0.0, impact = 0.0;
};

ModelRise model_rise(const ActionModel& model, const std::string& spec) {
  ModelRise r;
  const ModelTrace trace = simulate_trace(model, spec, 0.4, 1e-4);
  if (trace.impact_t.empty()) return r;
  r.impact = trace.impact_t.front();
  const double peak = trace.hammer_at(r.impact);
  for (std::size_t i = 0; i < trace.hammer_deg.size(); ++i)
    if (trace.hammer_deg[i] > kOnsetFraction * peak) {
      r.onset = static_cast<double>(i) * trace.dt;
      break;
    }
  r.ok = r.impact > r.onset;
  return r;
}

}  // namespace

EstimatedInput estimate_key_input(const ActionModel& model, const MeasuredTrial& trial) {
  const double noise = estimate_noise(trial.hammer_deg);
  const auto events = detect_events(trial.t, trial.hammer_deg, noise);
  const auto impact = std::find_if(events.begin(), events.end(),
                                   [](const MeasuredEvent& e) { return e.type == "impact"; });
  if (impact == events.end())
    throw InputError(trial.path +
                     ": no key input is known (no '# input:' line and no key_angle_deg column) "
                     "and no strike is visible in the hammer trace to estimate one from");
  // rest level: the median of the 50 ms before the strike's rise
  std::size_t i_peak = static_cast<std::size_t>(
      std::lower_bound(trial.t.begin(), trial.t.end(), impact->t) - trial.t.begin());
  i_peak = std::min(i_peak, trial.t.size() - 1);
  const double peak = trial.hammer_deg[i_peak];
  std::size_t i_on = i_peak;
  std::vector<double> before(trial.hammer_deg.begin(),
                             trial.hammer_deg.begin() + static_cast<long>(i_peak));
  std::sort(before.begin(), before.end());
  const double rest = before.empty() ? 0.0 : before[before.size() / 10];  // low decile
  while (i_on > 0 && trial.hammer_deg[i_on] > rest + kOnsetFraction * (peak - rest)) --i_on;
  EstimatedInput out;
  out.measured_rise_s = impact->t - trial.t[i_on];
  // hold: until the hammer has fallen back below 20 % of its travel
  std::size_t i_fall = i_peak;
  while (i_fall + 1 < trial.t.size() && (trial.hammer_deg[i_fall] > rest + 0.2 * (peak - rest) ||
                                         trial.t[i_fall] < impact->t + 20e-3))
    ++i_fall;
  // held until the hammer falls back, or past the kept window when it falls back only after it
  // (or never): a release inside the window would then be the model's alone
  const double held_ms = (trial.t[i_fall] - trial.t[i_on]) * 1e3 - 20.0;
  const bool falls_back = trial.hammer_deg[i_fall] <= rest + 0.2 * (peak - rest);
  out.pulse_ms =
      falls_back && held_ms <= 1e3 * kKeptS ? std::max(held_ms, 30.0) : 1e3 * kKeptS + 100.0;
  out.pulse_ms = std::round(out.pulse_ms);

  // force whose rise time matches: scan, then interpolate log(rise) against log(force)
  const double forces[] = {3, 4.5, 7, 10, 15, 22, 33, 50};
  double prev_f = 0, prev_rise = 0;
  bool have_prev = false;
  out.force_n = 0;
  // a strike the force pulses cannot make: slower than the softest one by half again (a slow
  // press, a hammer pushed by hand) or faster than the hardest by as much. Refused rather than
  // fitted with the nearest pulse, whose rise would differ from the data's by that much.
  auto out_of_reach = [&](double model_rise_s, double force, const char* which) {
    std::ostringstream problem;
    problem << trial.path << ": no key input is known (no '# input:' line and no key_angle_deg "
            << "column) and a force pulse cannot make this strike: the hammer rises in "
            << format_fixed(1e3 * out.measured_rise_s, 1) << " ms from its first motion to the "
            << "string, the " << which << " pulse (" << format_fixed(force, 0) << " N) in "
            << format_fixed(1e3 * model_rise_s, 1)
            << " ms; give the input ('# input:'), or record the key (import-raw --key-column)";
    throw InputError(problem.str());
  };
  for (double f : forces) {
    const ModelRise r = model_rise(model, pulse_spec(f, out.pulse_ms));
    if (!r.ok) continue;
    const double rise = r.impact - r.onset;
    if (rise <= out.measured_rise_s) {
      if (!have_prev) {
        if (out.measured_rise_s > 1.5 * rise) out_of_reach(rise, f, "softest");
        out.force_n = f;
      } else {
        const double x = std::log(out.measured_rise_s / prev_rise) / std::log(rise / prev_rise);
        out.force_n = std::exp(std::log(prev_f) + x * std::log(f / prev_f));
      }
      break;
    }
    prev_f = f, prev_rise = rise, have_prev = true;
  }
  if (out.force_n == 0 && have_prev && out.measured_rise_s < prev_rise / 1.5)
    out_of_reach(prev_rise, prev_f, "hardest");
  if (out.force_n == 0) out.force_n = have_prev ? prev_f : forces[0];
  out.force_n = std::round(out.force_n * 100.0) / 100.0;
  out.spec = pulse_spec(out.force_n, out.pulse_ms);
  const ModelRise r = model_rise(model, out.spec);
  out.model_rise_s = r.ok ? r.impact - r.onset : 0.0;

  // the strike on the model's clock: onsets coincide, kKeptS kept
  const double shift = trial.t[i_on] - (r.ok ? r.onset : 0.0);
  out.file_shift_s = shift;
  out.trial = trial;
  out.trial.t.clear();
  out.trial.hammer_deg.clear();
  out.trial.key_deg.clear();
  for (std::size_t i = 0; i < trial.t.size(); ++i) {
    const double t = trial.t[i] - shift;
    if (t < 0.0 || t > kKeptS) continue;
    out.trial.t.push_back(t);
    out.trial.hammer_deg.push_back(trial.hammer_deg[i]);
  }
  out.trial.input_spec = out.spec;
  return out;
}

}  // namespace pat

#include "measured/discrepancies.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/format.h"
#include "core/types.h"

namespace pat {
namespace {

std::string label(const ModelTrace& m, double t) {
  constexpr double kNearRestDeg = 0.3;
  const double angle = m.hammer_at(t);
  const double rate = (m.hammer_at(t + 5e-4) - m.hammer_at(t - 5e-4)) / 1e-3;  // deg/s
  double last_impact = -1.0, last_check = -1.0, next_escapement = 1e9, next_impact = 1e9;
  for (double x : m.impact_t) {
    if (x <= t + 1e-3) last_impact = std::max(last_impact, x);
    if (x > t + 1e-3) next_impact = std::min(next_impact, x);
  }
  for (double x : m.check_t)
    if (x <= t) last_check = std::max(last_check, x);
  for (double x : m.escapement_t)
    if (x > t) next_escapement = std::min(next_escapement, x);
  if (last_impact >= 0 && t >= last_impact - 1e-3 && t <= last_impact + 2e-3) return "impact";
  if (last_impact >= 0 && t > last_impact) {
    const bool caught_after = last_check > last_impact;
    if ((caught_after && t <= last_check + 10e-3) || (!caught_after && t <= last_impact + 60e-3))
      return "rebound_and_check";
  }
  // before any strike a hammer near rest is at rest, or starting its rise
  if (angle < kNearRestDeg && last_impact < 0) return rate < 10.0 ? "rest" : "acceleration";
  if (angle < kNearRestDeg) return "return";
  // after a check the hammer is held (a creep of a few deg/s included) until the key lets it go:
  // then it falls, or is thrown up by a repetition lever first, both at tens of deg/s or more
  // (a rise into another strike within 50 ms is that strike's acceleration, below)
  constexpr double kHeldRateDegPerS = 50.0;
  const bool rising_to_strike = rate > 0.0 && next_impact - t < 50e-3;
  if (last_impact >= 0 && last_check > last_impact && !rising_to_strike)
    return std::abs(rate) < kHeldRateDegPerS ? "rebound_and_check" : "release";
  if (rate > 5.0) {
    double prev_escapement = -1.0;
    for (double x : m.escapement_t)
      if (x <= t) prev_escapement = std::max(prev_escapement, x);
    return prev_escapement > last_impact && next_escapement > t ? "free_flight" : "acceleration";
  }
  if (rate < -5.0) return "release";
  return last_check > last_impact && last_impact >= 0 ? "rebound_and_check" : "acceleration";
}

/// Hammer angular rate just before the peak at tp: slope over [tp − 2.5 ms, tp − 0.5 ms].
template <typename F>
double approach_rate(F angle_at, double tp) {
  return (angle_at(tp - 0.5e-3) - angle_at(tp - 2.5e-3)) / 2e-3;
}

double measured_at(const MeasuredTrial& trial, double t) {
  const auto it = std::lower_bound(trial.t.begin(), trial.t.end(), t);
  if (it == trial.t.begin()) return trial.hammer_deg.front();
  if (it == trial.t.end()) return trial.hammer_deg.back();
  const std::size_t i = static_cast<std::size_t>(it - trial.t.begin());
  const double f = (t - trial.t[i - 1]) / (trial.t[i] - trial.t[i - 1]);
  return trial.hammer_deg[i - 1] + f * (trial.hammer_deg[i] - trial.hammer_deg[i - 1]);
}

}  // namespace

TrialDiscrepancies find_discrepancies(const MeasuredTrial& trial, const ModelTrace& model,
                                      const Alignment& al, const std::vector<MeasuredEvent>& events,
                                      double noise_deg) {
  TrialDiscrepancies out;
  const double dt_shift = al.time_offset_s;
  std::map<std::string, std::pair<double, double>> sums;  // Σr, Σr²
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < trial.t.size(); ++i) {
    const std::string p = label(model, trial.t[i] - dt_shift);
    out.phase_of_sample.push_back(p);
    sums[p].first += al.residual[i];
    sums[p].second += al.residual[i] * al.residual[i];
    ++counts[p];
  }
  // each phase's own noise: second differences of the measured angle within one phase only
  std::map<std::string, std::vector<double>> second_differences;
  for (std::size_t i = 1; i + 1 < trial.t.size(); ++i) {
    const std::string& p = out.phase_of_sample[i];
    if (out.phase_of_sample[i - 1] == p && out.phase_of_sample[i + 1] == p)
      second_differences[p].push_back(trial.hammer_deg[i + 1] - 2.0 * trial.hammer_deg[i] +
                                      trial.hammer_deg[i - 1]);
  }
  for (const std::string& p : phase_names()) {
    if (!counts.count(p)) continue;
    PhaseResidual r;
    r.phase = p;
    r.samples = counts[p];
    r.rms_deg = std::sqrt(sums[p].second / r.samples);
    r.mean_deg = sums[p].first / r.samples;
    std::vector<double>& d2 = second_differences[p];
    r.noise_deg = d2.size() >= static_cast<std::size_t>(kMinPhaseNoiseSamples)
                      ? noise_from_second_differences(std::move(d2))
                      : noise_deg;
    // a held phase of a quantised signal can have a median scatter of 0: no residual is "within"
    // that, so the whole trial's estimate is used instead
    if (!(r.noise_deg > 0.0)) r.noise_deg = noise_deg;
    out.phases.push_back(r);
  }

  auto model_at = [&](double t) { return model.hammer_at(t - dt_shift) + al.angle_offset_deg; };
  auto add = [&](std::string feature, std::string unit, double measured, double modelled,
                 std::string what) {
    FeatureDiscrepancy f{feature, unit, measured, modelled, measured - modelled, true, ""};
    std::ostringstream text;
    text << what << ": measured " << format_fixed(measured) << " " << unit << ", model "
         << format_fixed(modelled) << " " << unit << " (difference "
         << format_fixed(measured - modelled) << " " << unit << ")";
    f.text = text.str();
    out.features.push_back(f);
  };
  // the model's impact and check are read from its aligned trace, sampled where the file is, by
  // the rule that reads them in the file (detect_events): its own events time the impact at first
  // touch, the file's at the felt's deepest point, about 1 ms later (a perfect model would show a
  // difference)
  MeasuredTrial model_sampled;  // the model as the file would have recorded it
  model_sampled.t = trial.t;
  model_sampled.hammer_deg.resize(trial.t.size());
  for (std::size_t i = 0; i < trial.t.size(); ++i)
    model_sampled.hammer_deg[i] = model_at(trial.t[i]);
  const std::vector<MeasuredEvent> model_events =
      detect_events(model_sampled.t, model_sampled.hammer_deg, noise_deg);
  auto first_of = [](const std::vector<MeasuredEvent>& list, const std::string& type) {
    const auto it = std::find_if(list.begin(), list.end(),
                                 [&](const MeasuredEvent& e) { return e.type == type; });
    return it == list.end() ? nullptr : &*it;
  };
  const MeasuredEvent* impact = first_of(events, "impact");
  const MeasuredEvent* check = first_of(events, "check");
  // a peak of the model's trace is its strike only when the model did touch the string (a hammer
  // that rises and falls back short of it has a peak too), and its check only when it was caught
  const bool model_strikes = !model.impact_t.empty();
  const MeasuredEvent* model_impact = model_strikes ? first_of(model_events, "impact") : nullptr;
  const MeasuredEvent* model_check =
      model.check_t.empty() ? nullptr : first_of(model_events, "check");
  if (impact && model_impact) {
    add("impact_time", "ms", impact->t * 1e3, model_impact->t * 1e3, "first impact time");
    add("impact_velocity", "deg/s",
        approach_rate([&](double t) { return measured_at(trial, t); }, impact->t),
        approach_rate([&](double t) { return measured_at(model_sampled, t); }, model_impact->t),
        "hammer rate just before the first impact");
  } else if (impact && !model_strikes) {
    out.features.push_back({"impact_time", "ms", impact->t * 1e3, 0.0, 0.0, true,
                            "the measured hammer strikes the string at " +
                                format_fixed(impact->t * 1e3) + " ms but the model never does"});
  } else if (impact) {
    out.features.push_back(
        {"impact_time", "ms", impact->t * 1e3, (model.impact_t.front() + dt_shift) * 1e3, 0.0, true,
         "the model touches the string at " +
             format_fixed((model.impact_t.front() + dt_shift) * 1e3) +
             " ms, too lightly for its trace to show a strike the way the file's does"});
  } else if (model_strikes) {
    const double t = model_impact ? model_impact->t : model.impact_t.front() + dt_shift;
    out.features.push_back({"impact_time", "ms", 0.0, t * 1e3, 0.0, false,
                            "the model strikes the string but no impact is seen in the data"});
  }
  if (!model.escapement_t.empty()) {
    FeatureDiscrepancy f{
        "let_off_time", "ms", 0.0, (model.escapement_t.front() + dt_shift) * 1e3, 0.0, false, ""};
    f.text = "model let-off (escapement) at " + format_fixed(f.model) +
             " ms; a hammer trace does not show let-off directly";
    out.features.push_back(f);
  }
  if (check && model_check) {
    add("check_angle", "deg", check->angle_deg, model_check->angle_deg,
        "hammer angle when caught by the backcheck");
  } else if (check && !model.check_t.empty()) {
    // caught in both, but the model's hammer is not held still long enough for the file's rule
    out.features.push_back({"check_angle", "deg", check->angle_deg,
                            model_at(model.check_t.front() + dt_shift), 0.0, true,
                            "the model's backcheck catches the hammer at " +
                                format_fixed((model.check_t.front() + dt_shift) * 1e3) +
                                " ms but does not hold it still as the file's does (measured " +
                                format_fixed(check->angle_deg) + " deg when held)"});
  } else if (check) {
    out.features.push_back({"check_angle", "deg", check->angle_deg, 0.0, 0.0, true,
                            "the file's backcheck holds the hammer at " +
                                format_fixed(check->angle_deg) +
                                " deg but the model's never catches it"});
  }
  // settling level: the last 20 ms
  {
    double sm = 0, sn = 0;
    int n = 0;
    for (std::size_t i = 0; i < trial.t.size(); ++i)
      if (trial.t[i] >= trial.t.back() - 20e-3) {
        sm += trial.hammer_deg[i];
        sn += model_at(trial.t[i]);
        ++n;
      }
    if (n > 0) add("settling_level", "deg", sm / n, sn / n, "hammer level over the last 20 ms");
  }
  // oscillation in the residual after the impacts (rebound and check phases): a DFT scan
  {
    std::vector<double> t, r;
    for (std::size_t i = 0; i < trial.t.size(); ++i)
      if (out.phase_of_sample[i] == "rebound_and_check" || out.phase_of_sample[i] == "impact") {
        t.push_back(trial.t[i]);
        r.push_back(al.residual[i]);
      }
    if (t.size() > 20) {
      double best = 0, best_f = 0;
      for (double f = 10.0; f <= 500.0; f += 2.0) {
        double c = 0, s = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
          c += r[i] * std::cos(2 * kPi * f * t[i]);
          s += r[i] * std::sin(2 * kPi * f * t[i]);
        }
        const double amp = 2.0 * std::hypot(c, s) / static_cast<double>(t.size());
        if (amp > best) best = amp, best_f = f;
      }
      out.residual_oscillation_hz = best_f;
      out.residual_oscillation_deg = best;
      FeatureDiscrepancy f{"residual_oscillation", "Hz", best_f, 0.0, best_f, true, ""};
      f.text =
          "strongest oscillation in the residual after the impact: " + format_fixed(best_f, 0) +
          " Hz, amplitude " + format_fixed(best) + " deg" +
          (best > 3.0 * noise_deg ? " (above the noise)" : " (within the noise)");
      out.features.push_back(f);
    }
  }
  return out;
}

}  // namespace pat

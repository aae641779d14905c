#include "measured/discrepancies.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "core/format.h"
#include "core/types.h"

namespace pat {
namespace {

/// The phase of every measured sample, read from the measurement and the key, not from the
/// model being judged (DESIGN.md section 4): its impacts (detect_events), the measured hammer
/// (lightly smoothed, referred to rest by the alignment's angle offset) and the key (the file's
/// own key column, else the key of the input the model was driven with). Only let-off, which a
/// hammer trace does not show, is taken from the model: its escapement splits the rise into
/// acceleration and free flight. After an impact the hammer is in rebound and check until the
/// key is let up (release), and back once it is within kNearRestDeg of rest (return). The key
/// (lightly smoothed; its angle grows as it goes down) is let up once it has come back up
/// kKeyReleaseFraction of its stroke (from where it stood before the stroke to its deepest point
/// since the impact): a held key's felt overshoot, its bounce on the punching and the sensor's
/// scatter stay below that, a half-stroke repetition's release does not. The release is dated
/// back to where the key left the level it was held at (the median since the impact, within a
/// band of kHeldBandFraction of the key's travel or three times the smoothed key's noise), and on
/// while the sample before was deeper still. A later stroke starts where its rise leaves the
/// lowest level since the last impact.
std::vector<std::string> measured_phases(const MeasuredTrial& trial, const ModelTrace& model,
                                         const Alignment& al,
                                         const std::vector<MeasuredEvent>& events,
                                         double noise_deg) {
  constexpr double kNearRestDeg = 0.3;
  // a quarter of the stroke: beyond the punching's overshoot under a 1 kg blow (10 %, 3.0° at the
  // impact, held at 2.7°) and the bounce of a forte key
  constexpr double kKeyReleaseFraction = 0.25;
  // the band of a held key: 5 % of its travel (0.5 mm at the key front for a 10 mm dip), above
  // the key sensor's ±0.1 mm scatter near rest
  constexpr double kHeldBandFraction = 0.05;
  const std::size_t n = trial.t.size();
  std::vector<std::string> phase(n, "rest");
  if (n == 0) return phase;
  // the hammer: a 5-sample moving average (the noise / √5), in degrees from rest
  std::vector<double> h = moving_average5(trial.hammer_deg);
  for (double& x : h) x -= al.angle_offset_deg;
  const double near = std::max(kNearRestDeg, 3.0 * noise_deg / std::sqrt(5.0));
  // the key: the file's own column (a 5-sample moving average, as the hammer), else the key of
  // the input the model was driven with
  const bool measured_key = trial.key_deg.size() == n;
  std::vector<double> key = measured_key ? moving_average5(trial.key_deg) : std::vector<double>(n);
  if (!measured_key)
    for (std::size_t i = 0; i < n; ++i) key[i] = model.key_at(trial.t[i] - al.time_offset_s);
  const auto [key_lo, key_hi] = std::minmax_element(key.begin(), key.end());
  const double key_travel = *key_hi - *key_lo;
  const double key_band =
      std::max(kHeldBandFraction * key_travel,
               measured_key ? 3.0 * estimate_noise(trial.key_deg) / std::sqrt(5.0) : 0.0);
  auto index_at = [&](double t) {
    return static_cast<std::size_t>(std::lower_bound(trial.t.begin(), trial.t.end(), t) -
                                    trial.t.begin());
  };
  std::vector<double> impacts;
  for (const MeasuredEvent& e : events)
    if (e.type == "impact") impacts.push_back(e.t);
  std::sort(impacts.begin(), impacts.end());
  auto set_range = [&](std::size_t from, std::size_t to, const char* name) {
    for (std::size_t i = from; i < std::min(to, n); ++i) phase[i] = name;
  };
  if (impacts.empty()) {  // no strike: rest, the rise to the highest point, the fall back
    std::size_t rise = 0;
    while (rise < n && h[rise] <= near) ++rise;
    const std::size_t top =
        static_cast<std::size_t>(std::max_element(h.begin(), h.end()) - h.begin());
    set_range(rise, top + 1, "acceleration");
    for (std::size_t i = top + 1; i < n; ++i) phase[i] = h[i] <= near ? "return" : "release";
    return phase;
  }
  std::size_t segment_start = 0;  // after the previous impact phase
  double rest_level = 0.0;        // the hammer's level before the first rise, when seen
  for (std::size_t k = 0; k < impacts.size(); ++k) {
    const std::size_t impact_from = index_at(impacts[k] - 1e-3);
    const std::size_t impact_to = std::min(n, index_at(impacts[k] + 2e-3 + 1e-9));
    // the rise: after the last sample near the lowest level since the segment's start
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = segment_start; i < impact_from; ++i) lowest = std::min(lowest, h[i]);
    std::size_t rise = segment_start;
    for (std::size_t i = segment_start; i < impact_from; ++i)
      if (h[i] <= lowest + near) rise = i + 1;
    if (k == 0 && rise >= 10) {  // a median of the rest before the stroke
      std::vector<double> before(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(rise));
      std::nth_element(before.begin(), before.begin() + before.size() / 2, before.end());
      rest_level = before[before.size() / 2];
    }
    std::size_t flight = impact_from;
    for (double e : model.escapement_t) {
      const std::size_t i = index_at(e + al.time_offset_s);
      if (i >= rise && i < impact_from) {
        flight = i;
        break;
      }
    }
    // (a later stroke's rise relabels the end of the previous stroke's release or return)
    set_range(rise, flight, "acceleration");
    set_range(flight, impact_from, "free_flight");
    set_range(impact_from, impact_to, "impact");
    // after it, up to the next stroke's impact phase: rebound and check, release, return
    const std::size_t end = k + 1 < impacts.size() ? index_at(impacts[k + 1] - 1e-3) : n;
    std::size_t release = end;
    if (key_travel > 0.0) {
      // where the key stood before this stroke (rest, or a half release before a repetition)
      double before_stroke = key[std::min(segment_start, n - 1)];
      for (std::size_t i = segment_start; i < impact_from; ++i)
        before_stroke = std::min(before_stroke, key[i]);
      // the deepest point since the impact, then the first sample a quarter of the stroke up
      std::size_t deepest = std::min(index_at(impacts[k]), n - 1);
      std::size_t let_up = end;
      for (std::size_t i = deepest; i < end; ++i) {
        if (key[i] >= key[deepest]) deepest = i;
        const double stroke = key[deepest] - before_stroke;
        if (key[i] < key[deepest] - kKeyReleaseFraction * (stroke > 0.0 ? stroke : key_travel)) {
          let_up = i;
          break;
        }
      }
      if (let_up < end) {
        // dated back to where the key left the level it was held at
        std::vector<double> held(
            key.begin() + static_cast<std::ptrdiff_t>(impact_to),
            key.begin() + static_cast<std::ptrdiff_t>(std::max(let_up, impact_to)));
        double held_level = key[deepest];
        if (!held.empty()) {
          std::nth_element(held.begin(), held.begin() + held.size() / 2, held.end());
          held_level = held[held.size() / 2];
        }
        // back through the band above the held level (angles below it), and on while the sample
        // before was deeper still (a clean sensor's key is dated to where it began to move)
        std::size_t start = let_up;
        while (start > impact_to &&
               (key[start - 1] < held_level - key_band || key[start - 1] > key[start]))
          --start;
        // the moving average starts to come up two samples before the key does (not when the
        // walk stopped at the impact: the key rose straight after it)
        if (measured_key && start > impact_to) start = std::min(start + 2, let_up);
        release = std::max(start, impact_to);
      }
    }
    std::size_t back = end;
    for (std::size_t i = release; i < end; ++i)
      if (h[i] <= rest_level + near) {
        back = i;
        break;
      }
    set_range(impact_to, release, "rebound_and_check");
    set_range(release, back, "release");
    set_range(back, end, "return");
    segment_start = impact_to;
  }
  return phase;
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
  out.phase_of_sample = measured_phases(trial, model, al, events, noise_deg);
  for (std::size_t i = 0; i < trial.t.size(); ++i) {
    const std::string& p = out.phase_of_sample[i];
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
  // oscillation in the residual after the impact: a DFT over the longest contiguous stretch of
  // rebound and check (a transform over samples gathered from several stretches has peaks of
  // their gaps), detrended (a drift is not an oscillation) and Hann-windowed. Searched from four
  // periods in the stretch (or 10 Hz) to 500 Hz or a quarter of the sampling rate; a strongest
  // amplitude at either end of that range is no peak (it rises beyond the range) and is not
  // reported.
  {
    std::size_t best_from = 0, best_length = 0;
    for (std::size_t i = 0; i < trial.t.size();) {
      if (out.phase_of_sample[i] != "rebound_and_check") {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < trial.t.size() && out.phase_of_sample[j] == "rebound_and_check") ++j;
      if (j - i > best_length) best_from = i, best_length = j - i;
      i = j;
    }
    if (best_length > 20) {
      std::vector<double> t(trial.t.begin() + static_cast<std::ptrdiff_t>(best_from),
                            trial.t.begin() + static_cast<std::ptrdiff_t>(best_from + best_length));
      std::vector<double> r(
          al.residual.begin() + static_cast<std::ptrdiff_t>(best_from),
          al.residual.begin() + static_cast<std::ptrdiff_t>(best_from + best_length));
      // remove the least-squares line
      const double m = static_cast<double>(t.size());
      double st = 0, sr = 0, stt = 0, str = 0;
      for (std::size_t i = 0; i < t.size(); ++i)
        st += t[i], sr += r[i], stt += t[i] * t[i], str += t[i] * r[i];
      const double denominator = m * stt - st * st;
      const double slope = denominator > 0 ? (m * str - st * sr) / denominator : 0.0;
      const double intercept = (sr - slope * st) / m;
      for (std::size_t i = 0; i < t.size(); ++i) r[i] -= intercept + slope * t[i];
      const double span = t.back() - t.front();
      const double interval = span / (m - 1.0);
      // at least four periods in the stretch: a residual's slow curve after the detrend (a
      // drift that is not a line) has its largest components at one to three periods
      const double f_lo = std::max(10.0, 4.0 / span);
      const double f_hi = std::min(500.0, 0.25 / interval);
      const double f_step = std::min(2.0, 0.25 / span);  // a quarter of the resolution 1/span
      // a Hann window: without it, the stretch's ends leak a slow curve into sidelobes that
      // look like peaks at (k + 1/2) periods; amplitudes are divided by the window's sum
      std::vector<double> window(t.size());
      double window_sum = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        window[i] = 0.5 - 0.5 * std::cos(2 * kPi * (t[i] - t.front()) / span);
        window_sum += window[i];
      }
      double best = 0, best_f = 0;
      for (double f = f_lo; f <= f_hi; f += f_step) {
        double c = 0, s = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
          c += window[i] * r[i] * std::cos(2 * kPi * f * t[i]);
          s += window[i] * r[i] * std::sin(2 * kPi * f * t[i]);
        }
        const double amp = 2.0 * std::hypot(c, s) / window_sum;
        if (amp > best) best = amp, best_f = f;
      }
      const std::string range = format_fixed(f_lo, 0) + "–" + format_fixed(f_hi, 0) + " Hz";
      const std::string stretch = "the residual over " + format_fixed(1e3 * span, 0) +
                                  " ms of rebound and check from " +
                                  format_fixed(1e3 * t.front(), 1) + " ms";
      FeatureDiscrepancy f{"residual_oscillation", "Hz", 0.0, 0.0, 0.0, false, ""};
      f.model_known = false;  // a property of the residual alone: nothing measured or modelled
      const bool inside = f_hi > f_lo && best_f > f_lo + 0.5 * f_step && best_f < f_hi - f_step;
      if (inside && best > 3.0 * noise_deg) {
        out.residual_oscillation_hz = best_f;
        out.residual_oscillation_deg = best;
        f.text = "strongest oscillation in " + stretch + ": " + format_fixed(best_f, 0) +
                 " Hz, amplitude " + format_fixed(best) + " deg (above the noise)";
      } else if (inside) {
        f.text = "no oscillation above the noise in " + stretch + " within " + range +
                 " (strongest " + format_fixed(best_f, 0) + " Hz, " + format_fixed(best, 3) +
                 " deg)";
      } else {
        f.text = "no oscillation peak in " + stretch + " within " + range +
                 " (the strongest component lies at the edge of that range)";
      }
      out.features.push_back(f);
    }
  }
  return out;
}

void add_extended_phases(TrialDiscrepancies& d, const Alignment& extended) {
  for (PhaseResidual& p : d.phases) {
    double sum = 0.0, sum2 = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < d.phase_of_sample.size() && i < extended.residual.size(); ++i)
      if (d.phase_of_sample[i] == p.phase) {
        sum += extended.residual[i];
        sum2 += extended.residual[i] * extended.residual[i];
        ++count;
      }
    if (count == 0) continue;
    p.has_extended = true;
    p.extended_rms_deg = std::sqrt(sum2 / count);
    p.extended_mean_deg = sum / count;
  }
}

}  // namespace pat

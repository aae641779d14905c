#include "measured/diagnosis.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <tuple>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "measured/alignment.h"
#include "measured/input_estimate.h"
#include "measured/model_trace.h"
#include "measured/raw_import.h"
#include "sim/key_travel.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

constexpr double kMaxShiftS = 10e-3;  // nuisance time offset searched within ±10 ms

struct PreparedTrial {
  MeasuredTrial data;
  std::string spec;
  bool estimated = false;
  double model_duration_s = 0.0;
  /// the time offset searched: none when the trial's own key column drives the model (the key
  /// and the hammer were sampled on one clock, so the model's time is the file's)
  double max_shift_s = kMaxShiftS;
  /// time in the file = time compared + file_shift_s (an estimated input's strike is moved onto
  /// the model's clock)
  double file_shift_s = 0.0;
};

struct Evaluation {
  bool ok = false;
  double rss = 0.0;
  std::vector<double> residual;
};

/// The rest state of a candidate model, or nothing when it cannot rest (a value that breaks
/// the action). With the same joints as the model as it is, Newton continuation from that
/// model's rest state (`baseline`), which falls back to the dynamic settle when it does not
/// converge nearby: the settle (0.7 s simulated) costs about half a trial's run, and a candidate
/// changes the rest little (the hammer felt ×0.3 moves it by 1e-16 rad). Added bodies (shank
/// flex, backcheck compliance) settle.
std::optional<RestState> try_rest(const ActionModel& model, const RestState* baseline) {
  try {
    if (baseline && baseline->q.size() == model.dofs()) return rest_state_near(model, *baseline);
    return find_rest_state(model);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// One candidate's parameter s and its value.
struct Parameter {
  EffectInfo info;
  double lo = 0.0, hi = 0.0;  // range of s
  double value(double s) const { return info.log_scale ? std::exp(s) : s; }
  double s_of(double v) const { return info.log_scale ? std::log(v) : v; }
};

Parameter parameter_for(const EffectInfo& info) {
  Parameter p;
  p.info = info;
  p.lo = p.s_of(info.min);
  p.hi = p.s_of(info.max);
  return p;
}

class Evaluator {
 public:
  explicit Evaluator(const std::vector<PreparedTrial>& trials) : trials_(trials) {}

  /// Runs trial j; `rest` is the model's rest state (null: the model cannot rest).
  Evaluation run(const ActionModel& model, const RestState* rest, std::size_t j) {
    ++simulations;
    Evaluation e;
    if (!rest) return e;
    ModelTrace trace;
    try {
      trace = simulate_trace(model, trials_[j].spec, trials_[j].model_duration_s, 1e-4, rest);
    } catch (const std::exception&) {
      return e;  // the model cannot rest or run with this value: a failed evaluation
    }
    if (!trace.completed) return e;
    Alignment al = align(trials_[j].data, trace, trials_[j].max_shift_s);
    e.ok = true;
    e.rss = al.rss;
    e.residual = std::move(al.residual);
    return e;
  }

  /// The remembered evaluation of trial j at parameter s of `effect` ("" for the model as it
  /// is), if any. The fits come back to values already run (a fold's start is the fit on every
  /// trial, every candidate's neutral value is the baseline).
  std::optional<Evaluation> recalled(const std::string& effect, double s, std::size_t j) {
    const std::lock_guard<std::mutex> lock(memo_mutex_);
    const auto it = memo_.find({effect, s, j});
    if (it == memo_.end()) return std::nullopt;
    return it->second;
  }
  void remember(const std::string& effect, double s, std::size_t j, const Evaluation& e) {
    const std::lock_guard<std::mutex> lock(memo_mutex_);
    memo_.emplace(std::make_tuple(effect, s, j), e);
  }

  /// The rest state of the model as it is, the start of every candidate's rest (try_rest).
  void set_baseline_rest(const RestState& rest) { baseline_rest_ = rest; }
  const RestState* baseline_rest() const { return baseline_rest_ ? &*baseline_rest_ : nullptr; }

  std::atomic<int> simulations{0};

 private:
  const std::vector<PreparedTrial>& trials_;
  std::optional<RestState> baseline_rest_;
  std::mutex memo_mutex_;
  std::map<std::tuple<std::string, double, std::size_t>, Evaluation> memo_;
};

/// Trial evaluations of parameter s, one per trial of `set`; with `stop_at_failure` a failed one
/// (ok = false) ends the list early (the set's cost is then infinite anyway). Remembered
/// evaluations are reused; the model and its rest state are built only when some trial must
/// run. The neutral value of an effect is the model as it is.
std::vector<Evaluation> evaluate_trials(Evaluator& ev, const ActionModel& base, const Parameter& p,
                                        double s, const std::vector<std::size_t>& set,
                                        bool stop_at_failure) {
  const double value = p.value(s);
  const bool neutral = p.info.has_neutral &&
                       std::abs(value - p.info.neutral) <= 1e-9 * std::max(1.0, std::abs(value));
  const std::string key = neutral ? std::string() : p.info.name;
  const double key_s = neutral ? 0.0 : s;
  std::vector<Evaluation> out;
  std::optional<ActionModel> model;
  std::optional<RestState> rest;
  for (std::size_t j : set) {
    std::optional<Evaluation> e = ev.recalled(key, key_s, j);
    if (!e) {
      if (!model) {
        try {
          model = neutral ? base : with_effect(base, {p.info.name, value});
        } catch (const InputError&) {
          out.resize(set.size());  // no model at this value: every trial fails
          return out;
        }
        rest = try_rest(*model, ev.baseline_rest());
      }
      e = ev.run(*model, rest ? &*rest : nullptr, j);
      ev.remember(key, key_s, j, *e);
    }
    out.push_back(std::move(*e));
    if (stop_at_failure && !out.back().ok) return out;
  }
  return out;
}

struct SetResult {
  bool ok = false;
  double cost = std::numeric_limits<double>::infinity();
  std::vector<double> residual;  // concatenated over the set
};

SetResult evaluate_set(Evaluator& ev, const ActionModel& base, const Parameter& p, double s,
                       const std::vector<std::size_t>& set) {
  SetResult out;
  out.cost = 0.0;
  for (const Evaluation& e : evaluate_trials(ev, base, p, s, set, true)) {
    if (!e.ok) {
      out.cost = std::numeric_limits<double>::infinity();
      return out;
    }
    out.cost += e.rss;
    out.residual.insert(out.residual.end(), e.residual.begin(), e.residual.end());
  }
  out.ok = true;
  return out;
}

/// Levenberg–Marquardt on one parameter with a forward-difference Jacobian of the residual
/// vector (a small LM of our own: for p = 1 the normal equations are scalars).
/// `blocked` (when given) tells whether a step was refused because the model stopped there.
double levenberg_marquardt(Evaluator& ev, const ActionModel& base, const Parameter& p, double s0,
                           const std::vector<std::size_t>& set, double& cost_out,
                           int max_iterations, bool* blocked = nullptr) {
  const double range = p.hi - p.lo;
  const double spacing = range / (kScanPoints - 1);  // the scan found the basin to this
  double s = s0;
  SetResult at = evaluate_set(ev, base, p, s, set);
  if (!at.ok) {
    cost_out = at.cost;
    return s;
  }
  double lambda = 1e-2;
  double h = 0.05 * spacing;
  for (int it = 0; it < max_iterations; ++it) {
    const double hs = s + h <= p.hi ? h : -h;
    const SetResult shifted = evaluate_set(ev, base, p, s + hs, set);
    if (!shifted.ok) break;
    double g = 0.0, hess = 0.0;
    for (std::size_t i = 0; i < at.residual.size(); ++i) {
      const double jac = (shifted.residual[i] - at.residual[i]) / hs;
      g += jac * at.residual[i];
      hess += jac * jac;
    }
    if (hess <= 0.0) break;
    bool improved = false;
    double step = 0.0;
    for (int tries = 0; tries < 3 && !improved; ++tries) {
      step = -g / (hess * (1.0 + lambda));
      step = std::clamp(step, -spacing, spacing);  // a trust region: the scan's spacing
      const double s_new = std::clamp(s + step, p.lo, p.hi);
      SetResult trial = evaluate_set(ev, base, p, s_new, set);
      if (!trial.ok && blocked) *blocked = true;
      if (trial.ok && trial.cost < at.cost) {
        s = s_new;
        at = std::move(trial);
        lambda = std::max(lambda / 10.0, 1e-6);
        improved = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved || std::abs(step) < 1e-3 * range) break;
    h = std::clamp(0.5 * std::abs(step), 0.01 * spacing, 0.05 * spacing);
  }
  cost_out = at.cost;
  return s;
}

struct CandidateWork {
  Parameter param;
  CandidateFit fit;
  std::vector<double> held_out_rss;           // per trial
  std::vector<std::vector<double>> scan_rss;  // [scan point][trial], inf when failed
  std::vector<double> scan_s;
  double all_s = 0.0;                     // fitted on every trial
  double all_rss = 0.0;                   // its cost over every trial (one trial: the criterion)
  std::vector<double> fold_s;             // fitted leaving out trial f
  std::vector<double> fold_training_rss;  // its cost on the trials it was fitted on
  double scan_best_rss = 0.0;             // lowest scan cost over every trial
  bool refined = false;
};

/// Start of the local fit: the vertex of the parabola through the best scan point and its two
/// neighbours (costs summed over `set`), kept within the neighbours; the best point itself at
/// the ends of the range or when a neighbour failed.
double parabola_start(const CandidateWork& w, const std::vector<std::size_t>& set, int k) {
  if (k <= 0 || k + 1 >= static_cast<int>(w.scan_s.size())) return w.scan_s[k];
  double c[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (std::size_t j : set) c[i] += w.scan_rss[k - 1 + i][j];
  if (!std::isfinite(c[0]) || !std::isfinite(c[2])) return w.scan_s[k];
  const double h = w.scan_s[k + 1] - w.scan_s[k];
  const double curvature = c[0] - 2.0 * c[1] + c[2];
  if (curvature <= 0.0) return w.scan_s[k];
  const double offset = 0.5 * h * (c[0] - c[2]) / curvature;
  return w.scan_s[k] + std::clamp(offset, -h, h);
}

/// Start of the local fit on every trial: the best of a finer scan (kFineScanPoints between each
/// pair of scan points) across the best scan point's two intervals, or the parabola's vertex when
/// that is better. A contact-switching simulation's cost can be jagged on the scale of the scan's
/// spacing (a spring factor that decides whether the backcheck holds the hammer between two
/// blows: a minimum a tenth of a spacing wide), where a local fit from the vertex ends in a side
/// dip.
double fine_scan_start(Evaluator& ev, const ActionModel& base, const CandidateWork& w,
                       const std::vector<std::size_t>& set, int k) {
  const Parameter& p = w.param;
  double best_s = parabola_start(w, set, k);
  double best = evaluate_set(ev, base, p, best_s, set).cost;
  if (best_s != w.scan_s[k]) {
    double at_k = 0.0;
    for (std::size_t j : set) at_k += w.scan_rss[k][j];
    if (at_k < best) best = at_k, best_s = w.scan_s[k];
  }
  for (int side : {-1, 1}) {
    const int nb = k + side;
    if (nb < 0 || nb >= static_cast<int>(w.scan_s.size())) continue;
    for (int i = 1; i <= kFineScanPoints; ++i) {
      const double s = w.scan_s[k] + (w.scan_s[nb] - w.scan_s[k]) * i / (kFineScanPoints + 1);
      const double cost = evaluate_set(ev, base, p, s, set).cost;
      if (cost < best) best = cost, best_s = s;
    }
  }
  return best_s;
}

/// The aligned cost of every trial at parameter s (inf where the model fails).
std::vector<double> scan_point(Evaluator& ev, const ActionModel& base, const Parameter& p, double s,
                               std::size_t trial_count) {
  std::vector<double> rss(trial_count, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> every(trial_count);
  for (std::size_t j = 0; j < trial_count; ++j) every[j] = j;
  const std::vector<Evaluation> evaluations = evaluate_trials(ev, base, p, s, every, false);
  for (std::size_t j = 0; j < evaluations.size(); ++j)
    if (evaluations[j].ok) rss[j] = evaluations[j].rss;
  return rss;
}

double summed(const std::vector<double>& rss) {
  double c = 0.0;
  for (double r : rss) c += r;
  return c;
}

/// The scan of a candidate over its physical range (every trial at every scan point).
void scan_candidate(Evaluator& ev, const ActionModel& base, const std::vector<std::size_t>& samples,
                    CandidateWork& w) {
  const Parameter& p = w.param;
  for (int k = 0; k < kScanPoints; ++k) {
    const double s = p.lo + (p.hi - p.lo) * k / (kScanPoints - 1);
    w.scan_s.push_back(s);
    w.scan_rss.push_back(scan_point(ev, base, p, s, samples.size()));
  }
  w.scan_best_rss = std::numeric_limits<double>::infinity();
  for (const auto& rss : w.scan_rss) w.scan_best_rss = std::min(w.scan_best_rss, summed(rss));
}

/// Halves a screened-in candidate's scan spacing (the midpoints of every interval). A
/// contact-switching simulation's cost can have basins narrower than the screening scan's
/// spacing: a soft backcheck (0.5 N/mm) that throws the hammer back at the string gives a 1 kg
/// blow's cost a minimum only about ±15 % wide in the stiffness (a third of the spacing), with
/// another one at a third of the value.
void densify_scan(Evaluator& ev, const ActionModel& base, const std::vector<std::size_t>& samples,
                  CandidateWork& w) {
  std::vector<double> s;
  std::vector<std::vector<double>> rss;
  for (std::size_t k = 0; k < w.scan_s.size(); ++k) {
    s.push_back(w.scan_s[k]);
    rss.push_back(w.scan_rss[k]);
    if (k + 1 == w.scan_s.size()) break;
    const double mid = 0.5 * (w.scan_s[k] + w.scan_s[k + 1]);
    s.push_back(mid);
    rss.push_back(scan_point(ev, base, w.param, mid, samples.size()));
    w.scan_best_rss = std::min(w.scan_best_rss, summed(rss.back()));
  }
  w.scan_s = std::move(s);
  w.scan_rss = std::move(rss);
}

/// Further starts for the fit on the trials of `set` (the fit so far `s` at cost `cost`): each
/// trial's own minimum. The cost of one trial can be jagged on a scale finer than any scan: in a
/// double blow, whether the backcheck holds the hammer or lets it bounce back to the string
/// changes within a few percent of the hammer felt's stiffness or the backcheck's, and there the
/// summed cost's minimum is a narrow dip at the true value, missed by the scan, while a smoother
/// trial (a sine, a 1 kg blow) has its own minimum within a few percent of it. Each trial's best
/// scan point (parabola vertex) is refined on that trial alone (one Levenberg–Marquardt
/// iteration); the sum is evaluated there, and the best of these starts, when better than the
/// fit so far, is refined on the set (kTrialMinimumLmIterations).
void fit_from_trial_minima(Evaluator& ev, const ActionModel& base, const CandidateWork& w,
                           const std::vector<std::size_t>& set, double& s, double& cost) {
  const Parameter& p = w.param;
  double best_start = s;
  double best_start_cost = cost;
  for (std::size_t j : set) {
    int k_j = -1;
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < w.scan_s.size(); ++k)
      if (w.scan_rss[k][j] < lowest) lowest = w.scan_rss[k][j], k_j = static_cast<int>(k);
    if (k_j < 0) continue;
    double trial_cost = 0.0;
    const double s_j =
        levenberg_marquardt(ev, base, p, parabola_start(w, {j}, k_j), {j}, trial_cost, 1);
    // a trial whose own minimum is the fit so far (within the local fit's resolution) adds no
    // start
    if (!std::isfinite(trial_cost) || std::abs(s_j - s) < 1e-3 * (p.hi - p.lo)) continue;
    const double joint = evaluate_set(ev, base, p, s_j, set).cost;
    if (joint < best_start_cost) best_start_cost = joint, best_start = s_j;
  }
  if (!(best_start_cost < cost)) return;
  // the local fit only accepts steps that lower the cost: it ends at or below best_start_cost
  s = levenberg_marquardt(ev, base, p, best_start, set, cost, kTrialMinimumLmIterations);
}

/// The best scan point of a candidate on the trials of `set` (its index, -1 when every point
/// failed) and its cost.
int best_scan_point(const CandidateWork& w, const std::vector<std::size_t>& set, double& cost) {
  int best_k = -1;
  cost = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(w.scan_s.size()); ++k) {
    double c = 0.0;
    for (std::size_t j : set) c += w.scan_rss[k][j];
    if (c < cost) cost = c, best_k = k;
  }
  return best_k;
}

/// Fits a scanned candidate on the trials of `set` alone, from scratch: the scan's costs summed
/// over those trials find the basin (the scan itself does not depend on the data of other
/// trials), then the finer scan, the local fits and the further starts. Returns the parameter s,
/// and its cost over the set in `cost` (inf: the model fails over the whole range).
double fit_on_trials(Evaluator& ev, const ActionModel& base, const CandidateWork& w,
                     const std::vector<std::size_t>& set, double& cost) {
  const Parameter& p = w.param;
  const double inf = std::numeric_limits<double>::infinity();
  cost = inf;
  double best = inf;
  const int best_k = best_scan_point(w, set, best);
  if (best_k < 0) return w.scan_s.front();
  // A second basin of the scan (a point not next to the best one whose cost is within
  // kSecondBasinRatio of it) gets its own local fit: the cost of a contact-switching simulation
  // has local minima.
  const double fine_start = fine_scan_start(ev, base, w, set, best_k);
  bool blocked = false;
  double s = levenberg_marquardt(ev, base, p, fine_start, set, cost, kMaxLmIterations, &blocked);
  // the model may stop (a contact turns unphysical) between the finer scan's best point and the
  // minimum, which the local fit cannot cross: then the best scan point gets its own local fit
  if (blocked && fine_start != w.scan_s[best_k]) {
    double scan_start_cost = inf;
    const double from_scan =
        levenberg_marquardt(ev, base, p, w.scan_s[best_k], set, scan_start_cost, kMaxLmIterations);
    if (scan_start_cost < cost) s = from_scan, cost = scan_start_cost;
  }
  const int points = static_cast<int>(w.scan_s.size());
  auto summed_over_set = [&](int k) {
    double c = 0.0;
    for (std::size_t j : set) c += w.scan_rss[k][j];
    return c;
  };
  int second_k = -1;
  double second = inf;
  for (int k = 0; k < points; ++k) {
    if (std::abs(k - best_k) < 2) continue;
    bool local_min = true;
    const double c = summed_over_set(k);
    for (int nb : {k - 1, k + 1}) {
      if (nb < 0 || nb >= points) continue;
      local_min = local_min && c <= summed_over_set(nb);
    }
    if (local_min && c < second) second = c, second_k = k;
  }
  if (second_k >= 0 && second < kSecondBasinRatio * best) {
    double other_cost = inf;
    const double other = levenberg_marquardt(ev, base, p, parabola_start(w, set, second_k), set,
                                             other_cost, kMaxLmIterations);
    if (other_cost < cost) s = other, cost = other_cost;
  }
  if (set.size() > 1) fit_from_trial_minima(ev, base, w, set, s, cost);
  return s;
}

/// The trials but `left_out` (every trial when left_out is out of range).
std::vector<std::size_t> trials_but(std::size_t trial_count, std::size_t left_out) {
  std::vector<std::size_t> set;
  for (std::size_t j = 0; j < trial_count; ++j)
    if (j != left_out) set.push_back(j);
  return set;
}

/// The local fits and the leave-one-out validation of a scanned candidate: the fit on every
/// trial (the value named), then for each trial a fit from scratch on the others alone (its own
/// scan sums, finer scan and local fits, as above) evaluated on the trial left out.
void refine_candidate(Evaluator& ev, const ActionModel& base,
                      const std::vector<std::size_t>& samples, CandidateWork& w) {
  const std::size_t trial_count = samples.size();
  const Parameter& p = w.param;
  const double inf = std::numeric_limits<double>::infinity();
  const bool held_out = trial_count > 1;
  w.held_out_rss.assign(trial_count, inf);
  w.fold_training_rss.assign(trial_count, inf);
  w.fold_s.assign(trial_count, 0.0);
  densify_scan(ev, base, samples, w);
  double all_cost = inf;
  w.all_s = fit_on_trials(ev, base, w, trials_but(trial_count, trial_count), all_cost);
  if (!std::isfinite(all_cost)) {
    w.fit.completed = false;
    w.fit.note = "the model fails to run over the whole range of this effect";
    return;
  }
  w.all_rss = all_cost;
  w.fit.value = p.value(w.all_s);
  std::size_t all_samples = 0;
  for (std::size_t n : samples) all_samples += n;
  w.fit.training_rms_deg = std::sqrt(all_cost / static_cast<double>(all_samples));
  if (!held_out) return;
  for (std::size_t f = 0; f < trial_count; ++f) {
    // leave trial f out: a fit that never sees it
    double cost = inf;
    const double s = fit_on_trials(ev, base, w, trials_but(trial_count, f), cost);
    w.fold_s[f] = s;
    w.fold_training_rss[f] = cost;
    w.fit.fold_values.push_back(p.value(s));
    const SetResult validation = evaluate_set(ev, base, p, s, {f});
    w.held_out_rss[f] = validation.ok ? validation.cost : inf;
  }
}

/// "FILE: hammer_angle_deg runs from LOW to HIGH deg, " : the start of a units message.
std::string angle_span_text(const MeasuredTrial& trial, double low, double high) {
  return trial.path + ": hammer_angle_deg runs from " + format_fixed(low, 3) + " to " +
         format_fixed(high, 3) + " deg, ";
}

/// Refuses a hammer trace that cannot be in degrees from rest toward the string (DESIGN.md
/// section 5) for an action whose hammer turns `contact_deg` from rest to the string: one that
/// goes half of that below rest (the sign reversed) or half of it beyond the string. The real
/// strike overshoots its rest by 2.5 deg on its return and peaks 0.1 deg past contact (felt
/// compression).
void check_angle_sign_and_scale(const MeasuredTrial& trial, double contact_deg) {
  if (trial.hammer_deg.empty()) return;  // read_measured refuses such a file first
  const auto [low, high] = std::minmax_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  const std::string stroke = format_fixed(contact_deg, 1);
  if (*low < -0.5 * contact_deg)
    throw InputError(angle_span_text(trial, *low, *high) + "more than half the hammer's " + stroke +
                     " deg stroke below rest: angles are positive toward the string (is the "
                     "sign reversed?)");
  if (*high > 1.5 * contact_deg)
    throw InputError(angle_span_text(trial, *low, *high) + "more than half the hammer's " + stroke +
                     " deg stroke beyond the string: are the angles in degrees from rest?");
}

/// Refuses a hammer trace that moves less than a tenth of the hammer's `contact_deg` (radians,
/// or a hammer that never rises).
void check_angle_range(const MeasuredTrial& trial, double contact_deg) {
  if (trial.hammer_deg.empty()) return;
  const auto [low, high] = std::minmax_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  if (*high - *low < 0.1 * contact_deg)
    throw InputError(angle_span_text(trial, *low, *high) + "less than a tenth of the " +
                     format_fixed(contact_deg, 1) +
                     " deg the hammer turns from rest to the string: are the angles in radians, "
                     "or does the hammer never rise?");
}

/// Refuses a key trace that moves less than a tenth of the key's `key_dip_deg` while the hammer
/// reaches at least half its `contact_deg` (angles in radians: a key column of 0.045 had driven
/// a key that never went down, and the hammer's strike read as the model's error).
void check_key_range(const MeasuredTrial& trial, double contact_deg, double key_dip_deg) {
  if (trial.key_deg.empty() || trial.hammer_deg.empty()) return;
  const auto [key_low, key_high] = std::minmax_element(trial.key_deg.begin(), trial.key_deg.end());
  const double hammer_high = *std::max_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  if (*key_high - *key_low < 0.1 * key_dip_deg && hammer_high > 0.5 * contact_deg)
    throw InputError(trial.path + ": key_angle_deg moves only " +
                     format_fixed(*key_high - *key_low, 3) + " deg, less than a tenth of the " +
                     format_fixed(key_dip_deg, 2) +
                     " deg of the key's full dip, while the hammer rises " +
                     format_fixed(hammer_high, 1) + " deg: are the key angles in radians?");
}

PreparedTrial prepare(const ActionModel& model, const MeasuredTrial& trial) {
  PreparedTrial p;
  p.data = trial;
  if (!trial.input_spec.empty()) {
    p.spec = trial.input_spec;
  } else if (!trial.key_deg.empty() || trial.key_force_measured) {
    // the measured key motion (or else the finger's measured force) drives the model, on the
    // file's clock; a force column had been left unread and a pulse estimated instead, whose
    // misfit was then blamed on a candidate (shank_flex "explained" a synthetic trace without it)
    p.spec = "csv:" + trial.path;
    p.max_shift_s = 0.0;
  } else {
    const EstimatedInput est = estimate_key_input(model, trial);
    p.data = est.trial;
    p.spec = est.spec;
    p.estimated = true;
    p.file_shift_s = est.file_shift_s;
  }
  p.model_duration_s = p.data.t.back() + kMaxShiftS + 2e-3;
  return p;
}

/// The decision in one sentence (Diagnosis::verdict). best: the first fitted candidate of the
/// ranking, if any; best_rms_deg its error in the ranking's measure.
std::string diagnosis_verdict(const Diagnosis& d, const CandidateFit* best, bool at_limit,
                              double best_rms_deg) {
  const std::string measure = d.held_out ? "held-out" : "training";
  if (d.cause) {  // (the gain's error is each trial under its own fold's choice: it may differ)
    std::string text = d.cause->name + " = " + format_number(d.cause->value, 4) + " " +
                       d.cause_unit + " explains the discrepancy best: the " + measure +
                       " error is " + format_fixed(d.extended_rms_deg, 3) + " deg with it, " +
                       format_fixed(d.baseline_rms_deg, 3) + " deg without (noise " +
                       format_fixed(d.noise_deg, 3) + " deg)";
    // what "best" rests on, where it is less than it reads: one candidate has no rival, and an
    // input estimated from the hammer has a misfit of its own that a candidate may take up
    if (d.ranking.size() == 1) text += "; it was the only candidate compared";
    bool estimated = false;
    for (const TrialReport& r : d.trials) estimated = estimated || r.input_estimated;
    if (estimated)
      text +=
          "; the input was estimated from the hammer (no '# input:' line, key angle or "
          "key force), so part of the error may be the estimate's";
    return text;
  }
  if (d.ambiguous) return "the ranking is ambiguous (" + d.ranking.front().note + ")";
  // a residual whose power is within 2.25 times the noise's (rms within 1.5 times) is the noise
  if (d.baseline_rms_deg <= kWithinNoiseRatio * d.noise_deg)
    return "the model is within the noise (error " + format_fixed(d.baseline_rms_deg, 3) +
           " deg, noise " + format_fixed(d.noise_deg, 3) + " deg)";
  std::string text = "no candidate explains the discrepancy (error " +
                     format_fixed(d.baseline_rms_deg, 3) + " deg against noise " +
                     format_fixed(d.noise_deg, 3) + " deg";
  if (!best) return text + "; no candidate could be fitted)";
  text += "; the best, " + best->effect + ", leaves " + format_fixed(best_rms_deg, 3) + " deg " +
          measure;
  if (at_limit) return text + " at a limit of its range, so it is not identified)";
  return text + ", not enough to name it)";
}

}  // namespace

Diagnosis diagnose(const ActionModel& model, const std::vector<MeasuredTrial>& trials,
                   const DiagnoseOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (trials.empty()) throw InputError("diagnose needs at least one measured file");
  // a copy of a file under another name would validate the fit on the data it was fitted to
  // (two copies had passed as two trials: "held out", the validated error the training one)
  for (std::size_t j = 1; j < trials.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (trials[j].t == trials[i].t && trials[j].hammer_deg == trials[i].hammer_deg)
        throw InputError(trials[j].path + ": the same measurement as " + trials[i].path +
                         " (every time and hammer angle equal); each trial must be another "
                         "measurement, since the others validate the fit on it");
  Diagnosis d;
  d.action = model.kind;
  std::vector<PreparedTrial> prepared;
  const double contact_deg = hammer_contact_angle_deg(model);
  const RestState base_rest = find_rest_state(model);
  const double key_dip_deg = key_full_dip_angle(model, base_rest) * 180.0 / kPi;
  for (const MeasuredTrial& t : trials) {
    // a reversed sign or a trace beyond the string first (an estimated input would be fitted to
    // it), a trace too small after (a flat one without an input is told that first)
    check_angle_sign_and_scale(t, contact_deg);
    check_key_range(t, contact_deg, key_dip_deg);
    prepared.push_back(prepare(model, t));
    check_angle_range(t, contact_deg);
  }
  const std::size_t n_trials = prepared.size();
  d.held_out = n_trials > 1;
  Evaluator ev(prepared);

  // baseline: the model as it is
  std::size_t total_samples = 0;
  double base_rss = 0.0, noise2 = 0.0;
  std::vector<double> base_trial_rss(n_trials);
  ev.set_baseline_rest(base_rest);
  for (std::size_t j = 0; j < n_trials; ++j) {
    TrialReport r;
    r.path = prepared[j].data.path;
    r.data = prepared[j].data;
    r.input_spec = prepared[j].spec;
    r.input_estimated = prepared[j].estimated;
    r.file_time_shift_s = prepared[j].file_shift_s;
    try {  // a bad '# input:' line: the file that carries it
      parse_input_spec(prepared[j].spec, input_context(model, base_rest));
    } catch (const InputError& e) {
      throw InputError(r.path + ": '# input: " + r.input_spec + "': " + e.what());
    }
    r.baseline =
        simulate_trace(model, prepared[j].spec, prepared[j].model_duration_s, 1e-4, &base_rest);
    if (!r.baseline.completed)
      throw InputError(r.path + ": the model stops under the input '" + r.input_spec +
                       "': " + r.baseline.stop_cause);
    // the least-squares alignment is what the fits compare against; what is shown (the phases,
    // the features, the traces) takes the angle offset at rest, where only the calibration can
    // be wrong
    const Alignment fitted = align(prepared[j].data, r.baseline, prepared[j].max_shift_s);
    // half a step of align()'s grid from the searched edge (its refinement may pass it by a
    // step: 10.2 ms for a file 30 ms late had been taken as the offset without a word)
    r.time_offset_at_limit = prepared[j].max_shift_s > 0.0 &&
                             std::abs(fitted.time_offset_s) > prepared[j].max_shift_s - 1e-4;
    r.noise_deg = estimate_noise(prepared[j].data.hammer_deg);
    r.measured_events = detect_events(prepared[j].data.t, prepared[j].data.hammer_deg, r.noise_deg);
    r.discrepancies =
        find_discrepancies(prepared[j].data, r.baseline, fitted, r.measured_events, r.noise_deg);
    r.at_rest.resize(r.discrepancies.phase_of_sample.size());
    for (std::size_t i = 0; i < r.at_rest.size(); ++i)
      r.at_rest[i] = r.discrepancies.phase_of_sample[i] == "rest";
    r.baseline_alignment = referenced_to_rest(fitted, r.at_rest);
    r.baseline_fitted_rss = fitted.rss;
    if (r.baseline_alignment.angle_offset_deg != fitted.angle_offset_deg)
      r.discrepancies = find_discrepancies(prepared[j].data, r.baseline, r.baseline_alignment,
                                           r.measured_events, r.noise_deg);
    if (prepared[j].file_shift_s != 0.0) {  // times on the model's clock: say where in the file
      for (FeatureDiscrepancy& f : r.discrepancies.features)
        if (f.feature == "impact_time" && f.measured_known)
          f.text += " (the strike was moved onto the model's clock: measured " +
                    format_fixed(f.measured + 1e3 * prepared[j].file_shift_s) +
                    " ms in the file's time)";
    }
    Evaluation baseline_evaluation;
    baseline_evaluation.ok = true;
    baseline_evaluation.rss = fitted.rss;
    baseline_evaluation.residual = fitted.residual;
    ev.remember("", 0.0, j, baseline_evaluation);
    base_trial_rss[j] = fitted.rss;
    base_rss += fitted.rss;
    total_samples += prepared[j].data.t.size();
    noise2 += r.noise_deg * r.noise_deg;
    d.trials.push_back(std::move(r));
  }
  d.noise_deg = std::sqrt(noise2 / static_cast<double>(n_trials));
  const double n = static_cast<double>(total_samples);
  d.baseline_rms_deg = std::sqrt(base_rss / n);

  // candidates, fitted in parallel
  std::vector<CandidateWork> work;
  auto add_candidate = [&work](const EffectInfo& info) {
    work.emplace_back();
    work.back().param = parameter_for(info);
  };
  if (options.candidates.empty()) {
    for (const EffectInfo& info : candidate_effects(model)) add_candidate(info);
  } else {
    for (const std::string& name : options.candidates) add_candidate(describe_effect(model, name));
  }
  std::vector<std::size_t> samples;
  for (const PreparedTrial& p : prepared) samples.push_back(p.data.t.size());
  // screening: every candidate is scanned. A fit refines only the kRefinedCandidates with the
  // lowest scan cost on its own trials (the others cannot win there: their best scan point is
  // already worse than the refined ones' starting points): the fit on every trial, and each
  // leave-one-out fit, whose shortlist is chosen on its training trials alone.
  run_parallel(
      work.size(), [&](std::size_t c) { scan_candidate(ev, model, samples, work[c]); },
      options.progress, options.threads);
  auto shortlist = [&work](const std::vector<std::size_t>& set) {
    std::vector<double> cost(work.size());
    std::vector<std::size_t> order(work.size());
    for (std::size_t c = 0; c < work.size(); ++c) {
      order[c] = c;
      best_scan_point(work[c], set, cost[c]);
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
    order.resize(std::min<std::size_t>(kRefinedCandidates, work.size()));
    return order;
  };
  std::vector<bool> to_refine(work.size(), false);
  for (std::size_t c : shortlist(trials_but(n_trials, n_trials))) to_refine[c] = true;
  std::vector<std::vector<std::size_t>> fold_shortlists;
  if (d.held_out)
    for (std::size_t f = 0; f < n_trials; ++f) {
      fold_shortlists.push_back(shortlist(trials_but(n_trials, f)));
      for (std::size_t c : fold_shortlists.back()) to_refine[c] = true;
    }
  std::vector<std::size_t> refined;
  for (std::size_t c = 0; c < work.size(); ++c)
    if (to_refine[c]) refined.push_back(c);
  run_parallel(
      refined.size(),
      [&](std::size_t i) {
        CandidateWork& w = work[refined[i]];
        w.refined = true;
        refine_candidate(ev, model, samples, w);
      },
      options.progress, options.threads);
  if (options.progress)  // the progress counted every candidate as refinable
    for (std::size_t i = refined.size(); i < work.size(); ++i)
      options.progress->item_done("screened out");

  // The gain, honestly held out: each trial's error under the candidate chosen (lowest training
  // cost among its fold's shortlist) and fitted on the other trials alone.
  struct FoldChoice {
    std::string effect, unit;
    double value = 0.0;
  };
  std::vector<double> held_out_rss(n_trials, std::numeric_limits<double>::infinity());
  std::vector<std::optional<FoldChoice>> fold_choice(n_trials);
  for (std::size_t f = 0; f < fold_shortlists.size(); ++f) {
    const CandidateWork* chosen = nullptr;
    for (std::size_t c : fold_shortlists[f]) {
      const CandidateWork& w = work[c];
      if (!w.fit.completed || !std::isfinite(w.fold_training_rss[f])) continue;
      if (!chosen || w.fold_training_rss[f] < chosen->fold_training_rss[f]) chosen = &w;
    }
    if (!chosen) continue;
    held_out_rss[f] = chosen->held_out_rss[f];
    fold_choice[f] = FoldChoice{chosen->param.info.name, chosen->param.info.unit,
                                chosen->param.value(chosen->fold_s[f])};
  }

  // each candidate: its fit on every trial (the selection's criterion) and its held-out error
  double sample_interval = 0.0;
  for (const PreparedTrial& p : prepared) sample_interval += p.data.sample_interval_s();
  sample_interval /= static_cast<double>(n_trials);
  const double n_eff = std::max(2.0, n * sample_interval / kCorrelationTimeS);
  const double base_ms = base_rss / n;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (CandidateWork& w : work) {
    CandidateFit& f = w.fit;
    f.effect = w.param.info.name;
    f.unit = w.param.info.unit;
    f.validated_rms_deg = nan;
    f.delta_bic = nan;
    if (!w.refined) {
      f.completed = std::isfinite(w.scan_best_rss);
      f.training_rms_deg = std::sqrt(w.scan_best_rss / n);
      f.note = "screened out: its best scan point (rms " + format_fixed(f.training_rms_deg) +
               " deg) is worse than the " + std::to_string(kRefinedCandidates) +
               " candidates fitted";
      int k = 0;
      for (std::size_t i = 0; i < w.scan_rss.size(); ++i)
        if (summed(w.scan_rss[i]) <= w.scan_best_rss) k = static_cast<int>(i);
      f.value = w.param.value(w.scan_s[k]);
      continue;
    }
    if (!f.completed) continue;
    // a value pinned at a limit of the physical range is not identified: the family may point
    // the right way, but the effect as modelled does not explain the data (1 % of the range: the
    // local fit's clamped steps end exactly there)
    const double margin = 0.01 * (w.param.hi - w.param.lo);
    if (w.all_s <= w.param.lo + margin || w.all_s >= w.param.hi - margin)
      f.note = "its fitted value is at a limit of the physical range: not identified";
    double criterion_ms = w.all_rss / n;  // one trial: nothing is held out
    if (d.held_out) {
      double held = 0.0;
      for (double r : w.held_out_rss) held += r;
      if (!std::isfinite(held)) {
        f.completed = false;
        f.note = "the model failed on a held-out trial at the value fitted without it";
        continue;
      }
      criterion_ms = held / n;
      f.validated_rms_deg = std::sqrt(criterion_ms);
    }
    f.delta_bic = n_eff * std::log(base_ms / criterion_ms) - std::log(n_eff);
  }
  // Ranked by the criterion: with two trials or more the held-out error (each trial judged by
  // the fit made without it), which tells apart two candidates that fit the same trials equally
  // well but predict the others differently; with one trial the fit itself. Candidates screened
  // out come after, by their best scan point.
  auto criterion = [&d](const CandidateWork& w) {
    return d.held_out ? w.fit.validated_rms_deg : w.fit.training_rms_deg;
  };
  std::sort(work.begin(), work.end(), [&](const CandidateWork& a, const CandidateWork& b) {
    if (a.refined != b.refined) return a.refined;
    if (a.fit.completed != b.fit.completed) return a.fit.completed;
    if (a.refined) return a.fit.completed ? criterion(a) < criterion(b) : a.all_rss < b.all_rss;
    return a.scan_best_rss < b.scan_best_rss;
  });
  for (const CandidateWork& w : work) d.ranking.push_back(w.fit);

  d.extended_rms_deg = d.baseline_rms_deg;
  const CandidateWork& best = work.front();
  const bool at_limit = best.fit.note.rfind("its fitted value is at a limit", 0) == 0;
  const double best_ms =
      d.held_out ? best.fit.validated_rms_deg * best.fit.validated_rms_deg : best.all_rss / n;
  // the runner-up of another effect, fitted: a cause is named only with a margin over it
  const CandidateWork* runner_up = nullptr;
  for (std::size_t i = 1; i < work.size() && !runner_up; ++i)
    if (work[i].refined && work[i].fit.completed) runner_up = &work[i];
  // mean squares compared: the rms ratio squared
  const bool decisive =
      !runner_up || std::pow(criterion(*runner_up), 2) > kMinRunnerUpRatio * best_ms;
  const bool explains = best.refined && best.fit.completed && !at_limit &&
                        best_ms < kMaxExplainedRatio * base_ms && best.fit.delta_bic > kMinBicGain;
  if (explains && !decisive) {
    d.ambiguous = true;
    d.ranking.front().note =
        "fits best, but " + runner_up->fit.effect + " fits within " +
        format_fixed(100.0 * (std::sqrt(kMinRunnerUpRatio) - 1.0), 0) + " % of its " +
        (d.held_out ? "held-out " : "") + "rms error (" + format_fixed(criterion(*runner_up), 3) +
        " against " + format_fixed(criterion(best), 3) + " deg): the trials do not tell them apart";
  }
  if (explains && decisive) {
    const double s = best.all_s;
    d.cause = Effect{best.param.info.name, best.param.value(s)};
    d.cause_unit = best.param.info.unit;
    d.ranking.front().value = d.cause->value;
    if (d.held_out) {
      double held = 0.0;
      for (double r : held_out_rss) held += r;
      d.extended_rms_deg = std::sqrt(held / n);
    } else {
      d.extended_rms_deg = best.fit.training_rms_deg;
    }
    const ActionModel extended = with_effect(model, *d.cause);
    const RestState extended_rest = find_rest_state(extended);
    for (std::size_t j = 0; j < n_trials; ++j) {
      TrialReport& r = d.trials[j];
      r.extended = simulate_trace(extended, prepared[j].spec, prepared[j].model_duration_s, 1e-4,
                                  &extended_rest);
      r.extended_alignment = referenced_to_rest(
          align(prepared[j].data, r.extended, prepared[j].max_shift_s), r.at_rest);
      add_extended_phases(r.discrepancies, r.extended_alignment);
      if (d.held_out && fold_choice[j]) {
        r.held_out_effect = fold_choice[j]->effect;
        r.held_out_value = fold_choice[j]->value;
        r.held_out_unit = fold_choice[j]->unit;
        r.held_out_rms_deg = std::sqrt(held_out_rss[j] / static_cast<double>(samples[j]));
      }
    }
  }
  d.gain = d.baseline_rms_deg > 0 ? 1.0 - d.extended_rms_deg / d.baseline_rms_deg : 0.0;
  d.verdict = diagnosis_verdict(d, best.refined && best.fit.completed ? &best.fit : nullptr,
                                at_limit, std::sqrt(best_ms));
  const std::string searched = "±" + format_number(kMaxShiftS * 1e3) + " ms searched";
  for (const TrialReport& r : d.trials)
    if (r.time_offset_at_limit) {
      d.verdict = "Not to be trusted: " + r.path + "'s clock differs from the model's by more " +
                  "than the " + searched + ". " + d.verdict;
      break;
    }
  d.gain_basis =
      !d.cause ? std::string("no cause named: the extended model is the baseline") +
                     (d.held_out ? "" : " (one trial: no trial can be held out)")
      : d.held_out
          ? "held-out trials: each trial's error under the candidate chosen (lowest training "
            "cost) and fitted on the other trials alone, never on it"
          : "the fitted trial itself: with one trial no trial can be held out (leave-one-out "
            "needs two or more), so this is a training gain";

  // in words: the worst phases first, then the features
  struct Line {
    double weight;
    std::string text;
  };
  std::vector<Line> lines;
  for (const TrialReport& r : d.trials) {
    if (r.time_offset_at_limit)  // first: every figure of this trial depends on it
      lines.push_back(
          {std::numeric_limits<double>::infinity(),
           r.path + ": the clock offset found, " +
               format_fixed(r.baseline_alignment.time_offset_s * 1e3) +
               " ms, is at the edge of the " + searched +
               ": the file's time and the model's differ by more (is time_s counted from the "
               "start of the input its '# input:' line gives?), so its comparison is not to be "
               "trusted"});
    for (const PhaseResidual& p : r.discrepancies.phases) {
      std::string text = r.path + ": " + p.phase + ": residual rms " + format_fixed(p.rms_deg) +
                         " deg over " + std::to_string(p.samples) + " samples (noise " +
                         format_fixed(p.noise_deg) + " deg in this phase)";
      // an offset only where the mean carries the residual: a residual swinging about zero had
      // read "higher than the model by 0.00 deg" (the real strike's rest, 0.22 deg rms)
      if (p.rms_deg > 2.0 * p.noise_deg && std::abs(p.mean_deg) >= 0.5 * p.rms_deg)
        text += std::string(", the measured hammer is on average ") +
                (p.mean_deg > 0 ? "higher" : "lower") + " than the model by " +
                format_fixed(std::abs(p.mean_deg)) + " deg";
      else if (p.rms_deg > 2.0 * p.noise_deg)
        text += ", swinging about zero with no steady offset (mean " + format_fixed(p.mean_deg) +
                " deg)";
      else
        text += ", within the noise";
      if (p.has_extended)
        text += "; with " + d.cause->name + " " + format_fixed(p.extended_rms_deg) + " deg rms";
      lines.push_back({p.rms_deg, text});
    }
    for (const FeatureDiscrepancy& f : r.discrepancies.features)
      lines.push_back({0.0, r.path + ": " + f.text});
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const Line& a, const Line& b) { return a.weight > b.weight; });
  for (const Line& l : lines) d.discrepancies.push_back(l.text);
  d.simulations = ev.simulations.load() + static_cast<int>(n_trials);
  d.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

}  // namespace pat

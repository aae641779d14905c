#include "analysis/sensitivity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "analysis/parallel_runs.h"
#include "analysis/repetition_sweep.h"
#include "analysis/touchweight.h"
#include "core/error.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "model/model_edits.h"
#include "regulation/measurements.h"
#include "sim/key_travel.h"
#include "sim/simulator.h"

namespace pat {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The adjuster that regulates `setting` (regulation settings and adjusters share names).
const Adjuster& adjuster_of(const ActionModel& model, const std::string& setting) {
  for (const Adjuster& a : model.adjusters)
    if (a.name == setting) return a;
  throw InputError("sensitivity: setting '" + setting + "' has no adjuster in " + model.name);
}

}  // namespace

SensitivityMetricGroup blow_metrics(double key_force_n) {
  SensitivityMetricGroup group;
  group.names = {"impact_velocity_mps", "let_off_time_ms"};
  group.evaluate = [key_force_n](const ActionModel& model, const RestState& rest) {
    std::shared_ptr<const KeyInput> input = parse_input_spec(
        "force:const:" + format_number(key_force_n, 6), input_context(model, rest));
    SimulationOptions options;
    options.duration_s = 0.4;  // a 20 N blow strikes in about 30 ms; softer ones well within
    options.sample_interval_s = 0.0;
    Simulator sim(borrow(model), input, options, &rest);
    // let-off: the jack's toe meeting its button, where the trip begins (the escapement event,
    // the jack leaving the knuckle or butt, comes later: in a loud blow on the grand after the
    // strike, README "Escapement in loud blows is a slide")
    const int button = model.landmarks.letoff_contact;
    double velocity = kNaN, let_off = kNaN;
    bool running = true;
    while (running && sim.time() < options.duration_s && std::isnan(velocity)) {
      running = sim.step(options.duration_s);
      // read the step's events and contacts even when it ended the run (as simulate() does)
      if (std::isnan(let_off) && button >= 0 && sim.contact_closed(button))
        let_off = sim.time() * 1e3;
      const auto& events = sim.events();
      for (auto e = events.end() - sim.new_event_count(); e != events.end(); ++e)
        if (e->type == "impact") {
          velocity = e->hammer_velocity;
          break;
        }
    }
    return std::vector<double>{velocity, let_off};
  };
  return group;
}

SensitivityMetricGroup touchweight_metrics() {
  SensitivityMetricGroup group;
  group.names = {"downweight_g", "upweight_g"};
  group.evaluate = [](const ActionModel& model, const RestState&) {
    const TouchweightResult t = measure_touchweight(model);
    return std::vector<double>{t.downweight_g, t.upweight_g};
  };
  return group;
}

SensitivityMetricGroup repetition_metrics() {
  SensitivityMetricGroup group;
  group.names = {"max_repetition_hz"};
  group.evaluate = [](const ActionModel& model, const RestState&) {
    SweepOptions options;
    // the grand's halfway stroke exercises its repetition lever (drop, lever height); the
    // upright has only the full stroke
    options.stroke = model.kind == "grand" ? Stroke::half : Stroke::full;
    options.mode = SweepMode::chirp;
    options.f_start_hz = 6.0;  // below every limit of F4, above the slow-key misfires
    options.f_max_hz = 24.0;
    options.chirp_rate_hz_per_s = 1.0;
    options.threads = 1;  // the sensitivity cases are already spread over the cores
    options.chirp_segments = 1;
    const SweepResult r = run_repetition_sweep(model, options);
    return std::vector<double>{r.max_frequency_hz ? *r.max_frequency_hz : kNaN};
  };
  return group;
}

std::vector<SensitivityMetricGroup> sensitivity_metric_groups(double key_force_n) {
  return {blow_metrics(key_force_n), touchweight_metrics(), repetition_metrics()};
}

std::vector<MetricJump> jumps_beyond(const SensitivityResult& r, std::size_t metric,
                                     double threshold) {
  std::vector<MetricJump> jumps;
  const double base = r.baseline.at(metric);
  for (const SensitivityRow& row : r.rows)
    for (const auto& [value, side] :
         {std::pair{row.minus.at(metric), -1}, std::pair{row.plus.at(metric), +1}})
      if (std::abs(value - base) > threshold) jumps.push_back({row.setting, side, value});
  return jumps;
}

SensitivityResult sensitivity(const ActionModel& model, const SensitivityOptions& options,
                              const ProgressCallback& progress) {
  if (!(options.step_mm > 0.0)) throw InputError("sensitivity: step_mm must be positive");
  SensitivityResult result;
  std::vector<std::size_t> group_offset;
  for (const SensitivityMetricGroup& g : options.groups) {
    group_offset.push_back(result.metrics.size());
    result.metrics.insert(result.metrics.end(), g.names.begin(), g.names.end());
  }
  const std::size_t n_settings = model.regulation.size();
  const std::size_t n_metrics = result.metrics.size();

  // the model variants: index 0 the model as given, then (−, +) per setting
  std::vector<std::shared_ptr<const ActionModel>> variants{std::make_shared<ActionModel>(model)};
  for (const RegulationSetting& s : model.regulation) {
    const Adjuster& a = adjuster_of(model, s.name);
    for (const double sign : {-1.0, 1.0}) {
      try {
        variants.push_back(std::make_shared<ActionModel>(
            with_adjuster(model, s.name, a.value + sign * options.step_mm * 1e-3)));
      } catch (const InputError& e) {
        // the step is the table's, the same for every setting: named as such when a screw
        // cannot turn that far (the adjuster's message alone had seemed to blame the setting)
        throw InputError("sensitivity step (--step) " + format_number(options.step_mm) +
                         " mm: " + e.what() + "; give a smaller step");
      }
    }
  }
  std::vector<RestState> rests(variants.size());
  std::vector<char> failed(variants.size(), 0);            // a variant without a rest state
  std::vector<std::string> rest_problem(variants.size());  // why it has none
  std::vector<std::vector<double>> metrics(variants.size(), std::vector<double>(n_metrics, kNaN));
  // readings[s][p]: setting s read on its own variant at −step, 0, +step
  std::vector<std::array<SettingReading, 3>> readings(n_settings);
  auto variant_of = [](std::size_t setting, int position) -> std::size_t {
    return position == 1 ? 0 : 1 + 2 * setting + (position == 2 ? 1 : 0);
  };

  // first every variant's rest state, then the measurement and metric jobs, all in parallel
  const std::size_t n_groups = options.groups.size();
  const std::size_t metric_jobs = variants.size() * n_groups;
  const std::size_t measure_jobs = 3 * n_settings;
  ProgressReporter reporter(progress, variants.size() + metric_jobs + measure_jobs);
  run_parallel(
      variants.size(),
      [&](std::size_t v) {
        try {
          rests[v] = find_rest_state(*variants[v]);
        } catch (const std::exception& e) {
          if (v == 0) throw;  // the model as given must rest; a variant may not (NaN below)
          failed[v] = 1;
          rest_problem[v] = std::string("the action does not come to rest there: ") + e.what();
        }
      },
      &reporter);
  run_parallel(
      metric_jobs + measure_jobs,
      [&](std::size_t job) {
        if (job < metric_jobs) {
          const std::size_t v = job / n_groups, g = job % n_groups;
          if (failed[v]) return;
          const SensitivityMetricGroup& group = options.groups[g];
          std::vector<double> values;
          try {
            values = group.evaluate(*variants[v], rests[v]);
          } catch (const Cancelled&) {
            throw;
          } catch (const std::exception&) {
            return;  // the metric does not exist for this variant (e.g. the key cannot move)
          }
          for (std::size_t i = 0; i < group.names.size() && i < values.size(); ++i)
            metrics[v][group_offset[g] + i] = values[i];
          return;
        }
        const std::size_t k = job - metric_jobs, setting = k / 3;
        const int position = static_cast<int>(k % 3);
        const std::size_t v = variant_of(setting, position);
        SettingReading& reading = readings[setting][position];
        if (failed[v]) {  // not read: said why
          reading.measured = kNaN;
          reading.problem = rest_problem[v];
          return;
        }
        // read as a technician reads it (read_setting: e.g. the let-off with the drop screw out
        // of the way); one that cannot be read there is NaN with its reason
        reading = read_setting(*variants[v], model.regulation[setting], &rests[v]);
      },
      &reporter);

  result.baseline = metrics[0];
  for (std::size_t s = 0; s < n_settings; ++s) {
    SensitivityRow row;
    row.setting = model.regulation[s].name;
    row.unit = model.regulation[s].unit;
    for (int p = 0; p < 3; ++p) {
      row.measured[p] = readings[s][p].measured;
      row.measured_problem[p] = readings[s][p].problem;
      row.measured_note[p] = readings[s][p].note;
    }
    row.minus = metrics[variant_of(s, 0)];
    row.plus = metrics[variant_of(s, 2)];
    const double d_setting = row.measured[2] - row.measured[0];
    for (std::size_t m = 0; m < n_metrics; ++m)
      row.per_unit_of_setting.push_back(
          std::abs(d_setting) > 1e-9 ? (row.plus[m] - row.minus[m]) / d_setting : kNaN);
    result.rows.push_back(std::move(row));
  }
  return result;
}

MetricWords metric_words(const std::string& key) {
  static const std::pair<const char*, const char*> kUnits[] = {
      {"_mps", "m/s"}, {"_ms", "ms"}, {"_mm", "mm"}, {"_hz", "Hz"}, {"_g", "g"}, {"_n", "N"}};
  MetricWords out{key, ""};
  for (const auto& [suffix, symbol] : kUnits) {
    const std::string tail = suffix;
    if (out.words.size() > tail.size() &&
        out.words.compare(out.words.size() - tail.size(), tail.size(), tail) == 0) {
      out.words.resize(out.words.size() - tail.size());
      out.unit = symbol;
      break;
    }
  }
  if (out.words == "max_repetition") out.words = "repetition limit";
  std::replace(out.words.begin(), out.words.end(), '_', ' ');
  if (const auto at = out.words.find("let off"); at != std::string::npos)
    out.words.replace(at, 7, "let-off");  // the technicians' spelling
  return out;
}

std::vector<SensitivityRank> rank_by_change(const SensitivityResult& r, std::size_t metric) {
  std::vector<SensitivityRank> ranks;
  for (const SensitivityRow& row : r.rows) {
    if (metric >= row.minus.size() || metric >= row.plus.size()) continue;
    const double change = std::abs(row.plus[metric] - row.minus[metric]);
    if (std::isfinite(change)) ranks.push_back({row.setting, change});
  }
  std::stable_sort(
      ranks.begin(), ranks.end(),
      [](const SensitivityRank& a, const SensitivityRank& b) { return a.change > b.change; });
  // a setting that leaves the metric alone (e.g. 1e-11 g of downweight from the hammer blow,
  // the rounding of two static solutions) is no rank
  const double noise = ranks.empty() ? 0.0 : 1e-6 * ranks.front().change;
  while (!ranks.empty() && !(ranks.back().change > noise)) ranks.pop_back();
  return ranks;
}

}  // namespace pat

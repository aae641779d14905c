#include "regulation/deregulation.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.h"
#include "core/format.h"
#include "model/model_edits.h"
#include "regulation/measurements.h"
#include "sim/key_travel.h"
#include "sim/simulator.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

/// The setting measured at `rest`, or NaN where it cannot be (e.g. the jack never escapes).
double measured_or_nan(const ActionModel& model, const std::string& setting,
                       const RestState* rest) {
  try {
    return measure_setting(model, setting, rest);
  } catch (const std::exception&) {
    return std::nan("");
  }
}

}  // namespace

double demo_adjuster_rate(const ActionModel& model, const std::string& setting) {
  const int setting_index = model.setting_index(setting);
  if (setting_index < 0) measure_setting(model, setting);             // throws, naming the settings
  constexpr double kFallback = 1.0, kSlowest = 0.05, kFastest = 2.0;  // mm/s
  constexpr double kSteps = 20.0;  // rounded to 1/20 mm/s (divided, so 0.35 is the double 0.35)
  const RegulationSetting& target = model.regulation[static_cast<std::size_t>(setting_index)];
  const double wanted =
      target.unit == "mm" ? kDemoSettingRatePerS_mm : kDemoSettingRatePerS_fraction;
  const Adjuster& adjuster = model.adjusters[model.adjuster_index(setting)];
  const double here = measured_or_nan(model, setting, nullptr);
  if (!std::isfinite(here)) return kFallback;
  for (const double probe_mm : {kDemoProbe_mm, -kDemoProbe_mm}) {
    const double moved = adjuster.value + probe_mm * 1e-3;
    if (moved < adjuster.min || moved > adjuster.max) continue;
    const double there = measured_or_nan(with_adjuster(model, setting, moved), setting, nullptr);
    const double ratio = std::abs(there - here) / kDemoProbe_mm;  // setting unit per mm
    if (!std::isfinite(ratio) || ratio < 1e-6) continue;
    // clamped, then rounded: the bounds are whole twentieths, so rounding stays within them
    return std::round(std::clamp(wanted / ratio, kSlowest, kFastest) * kSteps) / kSteps;
  }
  return kFallback;
}

DeregulationResult deregulate(const ActionModel& model, const DeregulationOptions& options) {
  const int setting_index = model.setting_index(options.setting);
  if (setting_index < 0) measure_setting(model, options.setting);  // throws, naming the settings
  if (!(options.frequency_hz > 0.0) || !(options.duration_s > 0.0))
    throw InputError("deregulate: frequency and duration must be positive numbers");
  if (!std::isfinite(options.rate_mm_per_s) || options.rate_mm_per_s == 0.0)
    throw InputError(
        "deregulate: the rate must be a number of mm/s other than 0, its sign the "
        "direction the adjuster turns (got " +
        format_number(options.rate_mm_per_s) + ")");
  const Adjuster& adjuster = model.adjusters[model.adjuster_index(options.setting)];
  const double start_value = adjuster.value;
  const double rate = options.rate_mm_per_s * 1e-3;  // m/s

  RestState rest = find_rest_state(model);
  std::shared_ptr<const KeyInput> input;
  try {
    input = parse_input_spec("motion:sine:" + format_number(options.frequency_hz, 10) + ":full",
                             input_context(model, rest));
  } catch (const InputError& e) {  // the spec is ours: name the option it came from
    const std::string why = e.what();
    const auto colon = why.find("': ");
    throw InputError("deregulate: the key's frequency " + format_number(options.frequency_hz) +
                     " Hz: " + (colon == std::string::npos ? why : why.substr(colon + 3)));
  }
  SimulationOptions sim_options;
  sim_options.sample_interval_s = 0.0;
  Simulator sim(std::make_shared<const ActionModel>(model), input, sim_options, &rest);

  DeregulationResult result;
  result.trace.columns = trace_columns(model);
  result.trace.columns.push_back("adjuster_mm");
  result.trace.metadata["action"] = model.kind;
  result.trace.metadata["input"] = input->spec();
  result.trace.metadata["deregulation"] =
      options.setting + " at " + format_number(options.rate_mm_per_s, 10) + " mm/s";
  const int whippen = model.body_index("whippen");
  // the adjuster moves in steps (the paper's screw turns) or, continuously, every 10 ms
  const double interval = options.step_interval_s > 0.0 ? options.step_interval_s : 0.01;
  double value = start_value;
  // the blow at rest goes with every sample; it is the measurement itself when that is the setting
  const bool setting_is_blow = options.setting == "hammer_blow";
  const RegulationSetting& target = model.regulation[static_cast<std::size_t>(setting_index)];
  const SettingReading first_reading = read_setting(model, target, &rest);
  double measured = first_reading.measured;
  std::string measure_problem = first_reading.problem;  // why `measured` is NaN, when it is
  std::string measure_note = first_reading.note;  // how it was read when not as the action stands
  double blow_mm = setting_is_blow ? measured : measure_setting(model, "hammer_blow", &rest);
  const double period = 1.0 / options.frequency_hz;
  int next_cycle = 1;
  double next_row = 0.0;
  const double row_interval = 1e-3;
  auto record_row = [&]() {
    // the simulator's angles count from its starting rest, which set_model keeps
    std::vector<double> row = sim.trace_row(sim.time(), sim.q(), sim.v());
    row.push_back(value * 1e3);
    result.trace.rows.push_back(std::move(row));
  };
  record_row();
  next_row = row_interval;
  while (sim.time() < options.duration_s - 1e-12) {
    const double t_stop = std::min({options.duration_s, next_cycle * period, next_row});
    if (!sim.advance_to(t_stop)) break;
    const double t = sim.time();
    if (t >= next_row - 1e-12) {
      record_row();
      next_row += row_interval;
    }
    // the screw turns at every interval boundary
    const double wanted = start_value + rate * interval * std::floor((t + 1e-9) / interval);
    if (std::abs(wanted - value) > 1e-12) {
      if (wanted < adjuster.min || wanted > adjuster.max) {
        // the turn that would leave the range is not made: the stop names the range and where
        // the screw stands
        sim.stop("the adjuster '" + options.setting + "' reached the end of its range [" +
                 format_number(adjuster.min * 1e3) + ", " + format_number(adjuster.max * 1e3) +
                 "] mm at " + format_number(value * 1e3) + " mm (the next turn would take it to " +
                 format_number(wanted * 1e3) + " mm)");
        break;
      }
      value = wanted;
      auto moved =
          std::make_shared<const ActionModel>(with_adjuster(model, options.setting, value));
      sim.set_model(moved);
      try {
        rest = rest_state_near(*moved, rest);
        // read as a technician reads it (e.g. the let-off with the drop screw out of the way)
        const SettingReading reading = read_setting(*moved, target, &rest);
        measured = reading.measured;  // NaN where it cannot be read (the jack never escapes)
        measure_problem = reading.problem;
        measure_note = reading.note;
      } catch (const std::exception& e) {
        measured = std::nan("");  // no rest state near the last one
        measure_problem = e.what();
        measure_note.clear();
      }
      blow_mm = setting_is_blow ? measured : measured_or_nan(*moved, "hammer_blow", &rest);
    }
    // one sample per key cycle, at its top (key back at rest)
    if (t >= next_cycle * period - 1e-12) {
      DeregulationSample sample;
      sample.t = t;
      sample.adjuster_mm = value * 1e3;
      sample.measured = measured;
      sample.measure_problem = measure_problem;
      sample.measure_note = measure_note;
      sample.blow_mm = blow_mm;
      sample.hammer_string_gap_mm = sim.hammer_string_gap(sim.q()) * 1e3;
      sample.whippen_angle_deg = whippen >= 0 ? model.bodies[whippen].trace_sign *
                                                    deg(sim.q()[whippen] - sim.rest().q[whippen])
                                              : 0.0;
      result.samples.push_back(sample);
      ++next_cycle;
    }
    if (options.on_progress && !options.on_progress(t)) {
      sim.stop("cancelled");
      break;
    }
  }
  result.status = sim.stopped() ? "stopped" : "ok";
  result.stop_cause = sim.stop_cause();
  result.stop_t = sim.time();
  return result;
}

AdjusterSteps adjuster_steps(const CsvTable& trace) {
  AdjusterSteps steps;
  const int time_column = trace.column_index("time_s");
  const int adjuster_column = trace.column_index("adjuster_mm");
  if (time_column < 0 || adjuster_column < 0 || trace.rows.empty()) return steps;
  for (const std::vector<double>& row : trace.rows) {
    const double t = row[time_column], mm = row[adjuster_column];
    if (!steps.mm.empty() && mm == steps.mm.back()) continue;
    if (!steps.mm.empty()) {  // a turn: the old position up to now, then the new one
      steps.t_s.push_back(t);
      steps.mm.push_back(steps.mm.back());
    }
    steps.t_s.push_back(t);
    steps.mm.push_back(mm);
  }
  steps.t_s.push_back(trace.rows.back()[time_column]);  // held to the end of the run
  steps.mm.push_back(steps.mm.back());
  return steps;
}

std::string stop_in_trade_words(const std::string& stop_cause) {
  const std::string marker = "unphysical penetration in contact '";
  const std::size_t at = stop_cause.find(marker);
  if (at == std::string::npos) {
    if (stop_cause.find("diverged") != std::string::npos ||
        stop_cause.find("integrator failed") != std::string::npos)
      return "the parts left the action's working geometry (the model cannot follow it further)";
    return stop_cause;
  }
  const std::size_t name_from = at + marker.size();
  const std::size_t name_to = stop_cause.find('\'', name_from);
  const std::string contact = stop_cause.substr(name_from, name_to - name_from);
  if (contact.find("repetition lever window") != std::string::npos)
    return "the jack jammed in the repetition lever's window (it cannot get back under the "
           "knuckle)";
  if (contact.find("backcheck") != std::string::npos)  // (on the key: "into the key" misleads)
    return "the hammer was driven into the backcheck (" + contact + "): the action jams there";
  if (contact.find("string") != std::string::npos && contact.find("hammer") != std::string::npos)
    return "the hammer blocks against the string (it is driven into it, without let-off)";
  // "(A into B)" after the name
  const std::size_t open = stop_cause.find('(', name_to);
  const std::size_t into = stop_cause.find(" into ", open);
  const std::size_t close = stop_cause.find(')', into);
  if (open == std::string::npos || into == std::string::npos || close == std::string::npos)
    return "the action jams at the " + contact;
  const std::string a = stop_cause.substr(open + 1, into - open - 1);
  const std::string b = stop_cause.substr(into + 6, close - into - 6);
  return "the " + a + " was driven into the " + b + " (" + contact + "): the action jams there";
}

}  // namespace pat

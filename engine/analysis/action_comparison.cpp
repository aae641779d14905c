#include "analysis/action_comparison.h"

#include <algorithm>
#include <chrono>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "sim/key_travel.h"

namespace pat {
namespace {

constexpr const char* kOverlaid[] = {"key_angle_deg", "hammer_angle_deg", "hammer_string_gap_mm",
                                     "finger_force_n"};

CsvTable overlay_of(const std::vector<ActionComparison>& actions, const ComparisonOptions& o) {
  CsvTable table;
  table.metadata["input"] = o.input;
  table.columns.push_back("time_s");
  std::size_t rows = actions.empty() ? 0 : actions.front().run.trace.rows.size();
  std::vector<std::vector<int>> source(actions.size());
  for (std::size_t a = 0; a < actions.size(); ++a) {
    const CsvTable& trace = actions[a].run.trace;
    rows = std::min(rows, trace.rows.size());
    for (const char* column : kOverlaid) {
      const int index = trace.column_index(column);
      if (index < 0) continue;
      table.columns.push_back(actions[a].action + "_" + column);
      source[a].push_back(index);
    }
  }
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<double> row{actions.front().run.trace.rows[r][0]};
    for (std::size_t a = 0; a < actions.size(); ++a)
      for (int index : source[a]) row.push_back(actions[a].run.trace.rows[r][index]);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace

ComparisonResult compare_actions(const std::vector<const ActionModel*>& models,
                                 const ComparisonOptions& o, const ProgressCallback& progress) {
  if (models.empty()) throw InputError("study compare: no action to compare");
  const auto start = std::chrono::steady_clock::now();
  ComparisonResult result;
  result.actions.resize(models.size());
  for (std::size_t a = 0; a < models.size(); ++a) {
    result.actions[a].action = models[a]->kind;
    for (std::size_t b = 0; b < a; ++b)
      if (models[b]->kind == models[a]->kind)
        throw InputError("study compare: two actions of the same kind '" + models[a]->kind + "'");
  }
  // the SPEC is checked on every model before any run starts
  std::vector<RestState> rests;
  for (const ActionModel* model : models) {
    rests.push_back(find_rest_state(*model));
    parse_input_spec(o.input, input_context(*model, rests.back()));
  }

  const std::size_t per_action = o.repetition_limits ? 3 : 1;
  ProgressReporter reporter(progress, models.size() * per_action);
  const ProgressCallback keep_going = [&](double, const std::string&) {
    return reporter.still_wanted();
  };
  run_parallel(
      models.size() * per_action,
      [&](std::size_t job) {
        const std::size_t a = job / per_action, kind = job % per_action;
        ActionComparison& out = result.actions[a];
        const ActionModel& model = *models[a];
        if (kind == 0) {
          const auto input = parse_input_spec(o.input, input_context(model, rests[a]));
          SimulationOptions options;
          options.integrator = o.sweep.integrator;
          options.integrator_options.fixed_step_s = o.sweep.step_s;
          options.duration_s = o.duration_s;
          options.sample_interval_s = o.sample_interval_s;
          options.on_step = [&](double) { return reporter.still_wanted(); };
          out.run = simulate(model, input.get(), options, &rests[a]);
          for (const SimEvent& e : out.run.events) {
            if (e.type != "impact") continue;
            out.first_impact = e;
            break;
          }
          return;  // run_parallel counts the finished runs
        }
        SweepOptions sweep = o.sweep;
        sweep.stroke = kind == 1 ? Stroke::full : Stroke::half;
        sweep.mode = SweepMode::chirp;
        sweep.f_max_hz = kind == 1 ? o.f_max_full_hz : o.f_max_half_hz;
        SweepResult limit = run_repetition_sweep(model, sweep, keep_going);
        (kind == 1 ? out.full_stroke : out.half_stroke) = std::move(limit);
      },
      &reporter);
  reporter.throw_if_cancelled();
  result.overlay = overlay_of(result.actions, o);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace pat

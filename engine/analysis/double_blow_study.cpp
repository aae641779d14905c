#include "analysis/double_blow_study.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "model/model_edits.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat {
namespace {

struct VariantModels {
  std::string name;
  ActionModel model;
};

std::string milliseconds(double ms) {
  return format_number(ms, 9);
}

}  // namespace

DoubleBlowStudy double_blow_study(const ActionModel& upright, const DoubleBlowOptions& options,
                                  const ProgressCallback& progress) {
  if (upright.strap_index("bridle") < 0 || upright.spring_index("butt_spring") < 0)
    throw InputError(upright.source_file +
                     ": the double-blow study needs an upright action with a 'bridle' strap and "
                     "a 'butt_spring' (this is a " +
                     upright.kind + " action)");
  if (!(options.force_n > 0.0) || !(options.pulse_ms > 0.0) || !(options.gap_ms >= 0.0) ||
      !(options.duration_s > 0.0) || !(options.rest_band_mm > 0.0))
    throw InputError(
        "double-blow study: force, pulse, duration and band must be positive and "
        "the gap not negative");
  std::vector<VariantModels> variants;
  variants.push_back({"both", upright});
  variants.push_back({"no_bridle", without_part(upright, "bridle")});
  variants.push_back({"no_butt_spring", without_part(upright, "butt_spring")});
  variants.push_back({"neither", without_part(without_part(upright, "bridle"), "butt_spring")});

  const std::string force = format_number(options.force_n, 9);
  const std::string single = "force:pulse:" + force + ":" + milliseconds(options.pulse_ms);
  const std::string twice = "force:double:" + force + ":" + milliseconds(options.pulse_ms) + ":" +
                            milliseconds(options.gap_ms);

  // every variant starts from the complete upright at rest: the strap or spring is unhooked on
  // the resting action, so that all four start alike (an upright whose hammer's centre of mass
  // lies on the string side of its centre pin has no rest of its own without the spring)
  const RestState rest = find_rest_state(upright);

  DoubleBlowStudy study;
  study.variants.resize(variants.size());
  for (std::size_t v = 0; v < variants.size(); ++v) study.variants[v].name = variants[v].name;
  std::vector<SimulationResult> doubles(variants.size());
  // each job's stop, joined in one order after the runs (the two runs of a variant run at once)
  std::vector<std::string> single_stops(variants.size()), double_stops(variants.size());
  ProgressReporter reporter(progress, 2 * variants.size());
  run_parallel(
      2 * variants.size(),
      [&](std::size_t job) {
        const std::size_t v = job / 2;
        const bool second_run = job % 2 == 1;
        const ActionModel& model = variants[v].model;
        const auto input =
            parse_input_spec(second_run ? twice : single, input_context(model, rest));
        SimulationOptions sim;
        sim.duration_s = options.duration_s;
        sim.on_step = [&reporter](double) { return reporter.still_wanted(); };
        SimulationResult run = simulate(model, input.get(), sim, &rest);
        if (reporter.cancelled()) return;
        // the two jobs of a variant fill different members of it
        DoubleBlowVariant& out = study.variants[v];
        if (run.status != "ok") (second_run ? double_stops : single_stops)[v] = run.stop_cause;
        std::vector<const SimEvent*> impacts;
        for (const SimEvent& e : run.events)
          if (e.type == "impact") impacts.push_back(&e);
        if (!second_run) {
          if (!impacts.empty()) {
            out.first_impact_t_s = impacts[0]->t;
            out.first_impact_velocity_mps = impacts[0]->hammer_velocity;
            const int gap_column = run.trace.column_index("hammer_string_gap_mm");
            const double rest_gap_mm = rest.hammer_string_gap * 1e3;
            for (const std::vector<double>& row : run.trace.rows) {
              if (row[0] <= impacts[0]->t) continue;
              if (row[gap_column] >= rest_gap_mm - options.rest_band_mm) {
                out.hammer_return_s = row[0] - impacts[0]->t;
                break;
              }
            }
          }
        } else {
          // the second impact: the first one after the second pulse starts, when the first blow
          // had struck before it; a first strike that comes only after the second pulse began
          // is both pulses' one stroke (a short gap), with no second blow
          const double second_start =
              options.pulse_ms * 1e-3 + 2e-3 + options.gap_ms * 1e-3;  // 1 ms ramps
          if (!impacts.empty() && impacts.front()->t < second_start) {
            for (const SimEvent* e : impacts) {
              if (e->t >= second_start) {
                out.second_impact_t_s = e->t;
                out.second_impact_velocity_mps = e->hammer_velocity;
                break;
              }
            }
          } else if (!impacts.empty()) {
            out.one_stroke = true;
          }
          doubles[v] = std::move(run);
        }
        reporter.item_done(variants[v].name + (second_run ? " double blow" : " single blow"));
      },
      &reporter);
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::string& cause = study.variants[v].stop_cause;
    if (!single_stops[v].empty()) cause = "single blow: " + single_stops[v];
    if (!double_stops[v].empty())
      cause += (cause.empty() ? "" : "; ") + std::string("double blow: ") + double_stops[v];
  }

  study.trace.columns = {"time_s"};
  for (const VariantModels& v : variants)
    study.trace.columns.push_back(v.name + "_hammer_angle_deg");
  // every run samples the same instants; a run that stopped early shortens the table
  std::size_t rows = doubles[0].trace.rows.size();
  for (const SimulationResult& run : doubles) rows = std::min(rows, run.trace.rows.size());
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<double> row{doubles[0].trace.rows[r][0]};
    for (const SimulationResult& run : doubles)
      row.push_back(run.trace.rows[r][run.trace.column_index("hammer_angle_deg")]);
    study.trace.rows.push_back(row);
  }
  return study;
}

}  // namespace pat

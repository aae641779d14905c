// pianoaction sweep: the maximum repetition frequency (DESIGN.md section 5, fact F4; the
// definitions are in engine/analysis/repetition_sweep.h).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "analysis/paper_repetition.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "io/csv.h"
#include "plot_output.h"
#include "regulation/measurements.h"
#include "sweep_report.h"

namespace pat::app {

int run_sweep(const std::vector<std::string>& args) {
  const CommandLine cl(args,
                       {"--action", "--set", "--without", "--stroke", "--mode", "--fmax",
                        "--fstart", "--rate", "--step-hz", "--window", "--out", "--plot"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl);
  SweepOptions options;
  options.stroke = parse_stroke(cl.value("--stroke"), "--stroke");
  options.mode = parse_sweep_mode(cl.value_or("--mode", "chirp"), "--mode");
  options.f_start_hz = cl.positive_number_or("--fstart", options.f_start_hz);
  options.f_max_hz = cl.positive_number_or("--fmax", options.stroke == Stroke::half ? 25.0 : 20.0);
  // each mode's own pace: one of the other mode would be ignored without a word
  if (options.mode == SweepMode::chirp && cl.has("--step-hz"))
    throw InputError(
        "--step-hz sets the steps mode's frequency increment; a chirp's pace is --rate");
  if (options.mode == SweepMode::steps && cl.has("--rate"))
    throw InputError("--rate sets the chirp's pace; the steps mode's increment is --step-hz");
  options.chirp_rate_hz_per_s = cl.positive_number_or("--rate", options.chirp_rate_hz_per_s);
  options.step_hz = cl.positive_number_or("--step-hz", options.step_hz);
  if (cl.has("--window")) {
    const double window = cl.positive_number("--window");
    if (window != static_cast<int>(window))
      throw InputError("--window: expected a whole number of cycles (got " + cl.value("--window") +
                       ")");
    options.window_cycles = static_cast<int>(window);
  }
  const std::string out_path = cl.output_path("--out");
  const PlotOption plot(cl);
  // the chirp run is traced for its plot: a sample every 0.5 ms, ten or more per cycle
  if (plot.given() && options.mode == SweepMode::chirp) options.trace_interval_s = 5e-4;

  const SweepResult result = run_repetition_sweep(model, options);
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(sweep_plots(result));
  if (!out_path.empty()) {
    CsvTable table = sweep_cycles_table(result, model);
    add_run_metadata(table, model, cl);  // the band, the rate, the settings it ran with
    write_csv(out_path, table);
  }

  if (cl.has("--json")) {
    nlohmann::json out = sweep_json(result);
    out["action"] = model.kind;
    std::cout << out.dump(1) << "\n";
  } else {
    std::cout << model.name << ", " << stroke_name(result.stroke) << " stroke, "
              << sweep_mode_name(result.mode) << ": " << sweep_summary(result) << "\n";
    const std::string paper = compare_with_paper(result, model.kind, regulation_state(model));
    if (!paper.empty()) std::cout << "  " << paper << "\n";
    std::cout << "  " << result.simulated_s << " s simulated in " << result.wall_s << " s\n";
    if (!out_path.empty()) std::cout << "  cycles written to " << out_path << "\n";
    if (plot.given()) std::cout << "  plot written to " << plot.path() << "\n";
  }
  return 0;
}

}  // namespace pat::app

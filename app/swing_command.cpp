// pianoaction swing: the hammer swing test on its flange (DESIGN.md fact F5, section 5).
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "analysis/swing_test.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "plot_output.h"

namespace pat::app {

int run_swing(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--out", "--release-deg", "--plot"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl, false);  // one body alone: no rest needed
  SwingOptions options;
  if (cl.has("--release-deg")) {
    const double degrees = cl.positive_number("--release-deg");
    if (degrees > 179.0) throw InputError("--release-deg: at most 179 degrees from hanging");
    options.release_angle_rad = degrees * M_PI / 180.0;
  }
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const SwingResult result = swing_test(model, options);
  plot.write(
      {table_plot(result.trace, "Hammer swing", "angle from hanging (deg)",
                  {{"swing_angle_deg", "angle"}}),
       table_plot(result.trace, "Swing rate", "rate (deg/s)", {{"swing_rate_deg_per_s", "rate"}})},
      !cl.has("--json"));
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  write_analysis_csv(out_path, result.trace, model,
                     "swing test: hammer alone on its flange, released from " +
                         format_number(options.release_angle_rad * 180.0 / M_PI) +
                         " deg from hanging",
                     cl);
  if (cl.has("--json")) {
    nlohmann::json out{{"round_trips", result.round_trips},
                       {"half_swings", result.half_swings},
                       {"stopped", result.stopped},
                       {"stop_time_s", result.stop_time_s},
                       {"stick_angle_deg", result.stick_angle_deg},
                       {"first_half_period_s", result.first_half_period_s},
                       {"turning_amplitudes_deg", result.turning_amplitudes_deg},
                       {"action", model.kind}};
    std::cout << out.dump(1) << "\n";
  } else if (result.stopped && result.half_swings == 0 && result.stop_time_s == 0.0) {
    std::cout << model.name << ": hammer swing test\n  released within the stick angle ("
              << result.stick_angle_deg
              << " deg from hanging): the flange's friction holds it, no swing\n";
  } else if (result.stopped && result.half_swings == 0) {
    // just outside the stick zone: it creeps down into it, too slowly to turn
    std::cout << model.name << ": hammer swing test\n  released just outside the stick angle ("
              << result.stick_angle_deg
              << " deg from hanging): it sinks into it without a swing and stays there from "
              << result.stop_time_s << " s\n";
  } else {
    std::cout << model.name << ": hammer swing test\n  " << result.round_trips << " round trips ("
              << result.half_swings << " half swings), "
              << (result.stopped ? "stopped" : "still swinging") << " at " << result.stop_time_s
              << " s; sticks within " << result.stick_angle_deg
              << " deg of hanging\n  turning points (deg from hanging):";
    for (double a : result.turning_amplitudes_deg) std::cout << " " << a;
    std::cout << "\n";
  }
  return 0;
}

}  // namespace pat::app

// pianoaction keyfall: the key alone released onto the front-rail punching (paper section 4.3).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "analysis/key_fall.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "plot_output.h"

namespace pat::app {

int run_keyfall(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--out", "--duration", "--plot"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl, false);  // one body alone: no rest needed
  KeyFallOptions options;
  options.duration_s = cl.positive_number_or("--duration", options.duration_s);
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const KeyFallResult result = key_fall(model, options);
  plot.write({table_plot(result.trace, "Key front falling", "dip (mm)",
                         {{"key_front_dip_mm", "key front dip"}}),
              table_plot(result.trace, "Front-rail punching", "force (N)",
                         {{"punching_force_n", "punching force"}})},
             !cl.has("--json"));
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  write_analysis_csv(out_path, result.trace, model,
                     "key fall: key alone released from its rest position", cl);
  const bool touched = result.fall_time_s >= 0.0;
  if (cl.has("--json")) {
    nlohmann::json out{
        {"fall_time_s", touched ? nlohmann::json(result.fall_time_s) : nlohmann::json(nullptr)},
        {"fall_distance_mm", result.fall_distance_mm},
        {"impact_velocity_mps",
         touched ? nlohmann::json(result.impact_velocity_mps) : nlohmann::json(nullptr)},
        {"bounces", result.bounces},
        {"first_rebound_mm",
         touched ? nlohmann::json(result.first_rebound_mm) : nlohmann::json(nullptr)},
        {"final_dip_mm", result.final_dip_mm},
        {"action", model.kind}};
    std::cout << out.dump(1) << "\n";
  } else if (touched) {
    std::cout << model.name << ": key fall\n  meets the front-rail punching after "
              << result.fall_time_s * 1e3 << " ms, " << result.fall_distance_mm << " mm down at "
              << result.impact_velocity_mps << " m/s; " << result.bounces
              << " bounce(s), first rebound " << result.first_rebound_mm << " mm; resting at "
              << result.final_dip_mm << " mm\n";
  } else {
    std::cout << model.name << ": key fall\n  the key did not reach the front-rail punching in "
              << options.duration_s << " s\n";
  }
  return 0;
}

}  // namespace pat::app

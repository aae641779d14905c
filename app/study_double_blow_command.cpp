// pianoaction study double-blow: the upright's bridle strap and butt spring (fact F6).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "analysis/double_blow_study.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "plot_output.h"

namespace pat::app {

int run_study_double_blow(const std::vector<std::string>& args) {
  const CommandLine cl(
      args,
      {"--action", "--set", "--out", "--force", "--pulse-ms", "--gap-ms", "--duration", "--plot"},
      {"--json"});
  const ActionModel model = load_configured_action(cl);
  DoubleBlowOptions options;
  options.force_n = cl.positive_number_or("--force", options.force_n);
  options.pulse_ms = cl.positive_number_or("--pulse-ms", options.pulse_ms);
  if (cl.has("--gap-ms")) {
    options.gap_ms = parse_number(cl.value("--gap-ms"), "--gap-ms");
    if (options.gap_ms < 0.0) throw InputError("--gap-ms must not be negative");
  }
  options.duration_s = cl.positive_number_or("--duration", options.duration_s);
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const DoubleBlowStudy study = double_blow_study(model, options);
  plot.write({table_plot(study.trace, "Hammer under a double blow", "hammer angle (deg)",
                         {{"both_hammer_angle_deg", "bridle and butt spring"},
                          {"no_bridle_hammer_angle_deg", "no bridle"},
                          {"no_butt_spring_hammer_angle_deg", "no butt spring"},
                          {"neither_hammer_angle_deg", "neither"}})},
             !cl.has("--json"));
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  write_analysis_csv(out_path, study.trace, model,
                     "double blow with and without bridle strap and butt spring", cl);
  auto or_null = [](bool known, double value) {
    return known ? nlohmann::json(value) : nlohmann::json(nullptr);
  };
  if (cl.has("--json")) {
    nlohmann::json variants = nlohmann::json::array();
    for (const DoubleBlowVariant& v : study.variants) {
      nlohmann::json item{
          {"name", v.name},
          {"hammer_return_s", or_null(v.hammer_return_s >= 0.0, v.hammer_return_s)},
          {"second_impact_velocity_mps",
           or_null(v.second_impact_t_s >= 0.0, v.second_impact_velocity_mps)},
          {"first_impact_t_s", or_null(v.first_impact_t_s >= 0.0, v.first_impact_t_s)},
          {"first_impact_velocity_mps",
           or_null(v.first_impact_t_s >= 0.0, v.first_impact_velocity_mps)},
          {"second_impact_t_s", or_null(v.second_impact_t_s >= 0.0, v.second_impact_t_s)},
          {"one_stroke", v.one_stroke}};
      if (!v.stop_cause.empty()) item["stop_cause"] = v.stop_cause;
      variants.push_back(item);
    }
    nlohmann::json out{
        {"variants", variants}, {"rest_band_mm", options.rest_band_mm}, {"action", model.kind}};
    std::cout << out.dump(1) << "\n";
  } else {
    // two runs per variant: the return is timed after a single blow (in the double blow the
    // second one may come before the hammer is back), the second impact in the double blow
    std::cout << model.name << ": " << options.force_n << " N blows held " << options.pulse_ms
              << " ms. Return: after a single blow, from its impact until the hammer is within "
              << options.rest_band_mm << " mm of rest. Second blow: a second pulse "
              << options.gap_ms << " ms after the first ends\n";
    for (const DoubleBlowVariant& v : study.variants) {
      std::cout << "  " << v.name << ": back to rest ";
      if (v.hammer_return_s >= 0.0)
        std::cout << format_number(v.hammer_return_s * 1e3) << " ms after a single blow's impact";
      else
        std::cout << "not within the run after a single blow";
      if (v.second_impact_t_s >= 0.0)
        std::cout << "; the second blow strikes at " << format_number(v.second_impact_velocity_mps)
                  << " m/s (t = " << format_number(v.second_impact_t_s * 1e3) << " ms)";
      else if (v.one_stroke)
        std::cout << "; no second blow: the second pulse began before the first blow reached the "
                     "string, and both drove one stroke (lengthen --gap-ms)";
      else
        std::cout << "; the second blow does not strike within the run";
      if (!v.stop_cause.empty()) std::cout << "  [" << v.stop_cause << "]";
      std::cout << "\n";
    }
  }
  // a run that stopped leaves its variant's figures short: said on stderr, and the exit code
  // is simulate's for a stopped run (README), after everything computed was written
  bool stopped = false;
  for (const DoubleBlowVariant& v : study.variants)
    if (!v.stop_cause.empty()) {
      std::cerr << "pianoaction study double-blow: " << v.name << " stopped: " << v.stop_cause
                << "\n";
      stopped = true;
    }
  return stopped ? kExitRunStopped : 0;
}

}  // namespace pat::app

// pianoaction deregulate: an adjuster moves while the key plays a sine (DESIGN.md section 5;
// the paper's section 7.2).
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"
#include "json_output.h"
#include "plot_output.h"
#include "regulation/deregulation.h"
#include "settings_output.h"

namespace pat::app {
namespace {

/// The setting measured at each adjuster step (the demo's point: what the technician would read
/// as the screw turns), the adjuster, then the motion it causes.
std::vector<PlotSpec> deregulation_plots(const ActionModel& model, const std::string& setting,
                                         const DeregulationResult& result) {
  const int index = model.setting_index(setting);
  const std::string unit = index >= 0 ? model.regulation[index].unit : "mm";
  PlotSpec measured = time_plot("Measured " + setting, setting + " (" + unit + ")");
  measured.curves.push_back(point_curve(setting, "measured"));
  PlotSpec adjuster = time_plot("Adjuster " + setting, "adjuster offset (mm)");
  adjuster.curves.push_back(point_curve("adjuster", "adjuster_mm"));
  for (const DeregulationSample& s : result.samples) {
    adjuster.curves[0].add(s.t, s.adjuster_mm);
    if (!std::isfinite(s.measured)) continue;  // not measurable at this step
    measured.curves[0].add(s.t, s.measured);
  }
  std::vector<PlotSpec> plots;
  add_plot(plots, std::move(measured));
  add_plot(plots, std::move(adjuster));
  add_plot(plots, table_plot(result.trace, "Hammer–string gap", "gap (mm)",
                             {{"hammer_string_gap_mm", "hammer–string gap"}}));
  add_plot(plots, table_plot(result.trace, "Key, whippen and hammer", "angle (deg)",
                             {{"key_angle_deg", "key"},
                              {"whippen_angle_deg", "whippen"},
                              {"hammer_angle_deg", "hammer"}}));
  return plots;
}

}  // namespace

int run_deregulate(const std::vector<std::string>& args) {
  const CommandLine cl(args,
                       {"--action", "--set", "--without", "--setting", "--rate", "--frequency",
                        "--duration", "--step-interval", "--out", "--plot"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl);
  DeregulationOptions options;
  options.setting = cl.value("--setting");
  options.rate_mm_per_s = parse_number(cl.value("--rate"), "--rate");
  options.frequency_hz = cl.positive_number_or("--frequency", 3.0);
  options.duration_s = cl.positive_number_or("--duration", 10.0);
  options.step_interval_s = cl.has("--step-interval")
                                ? parse_number(cl.value("--step-interval"), "--step-interval")
                                : 0.5;
  if (options.step_interval_s < 0.0)
    throw InputError("--step-interval: must not be negative (0 moves the adjuster continuously)");
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const DeregulationResult result = deregulate(model, options);
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(deregulation_plots(model, options.setting, result));
  if (!out_path.empty()) write_csv(out_path, result.trace);

  if (cl.has("--json")) {
    nlohmann::json samples = nlohmann::json::array();
    for (const DeregulationSample& s : result.samples)
      samples.push_back(
          {{"t_s", s.t},
           {"adjuster_mm", s.adjuster_mm},
           {"measured", std::isfinite(s.measured) ? nlohmann::json(s.measured) : nullptr},
           {"measure_problem", text_or_null(s.measure_problem)},
           {"measure_note", text_or_null(s.measure_note)},
           {"blow_mm", std::isfinite(s.blow_mm) ? nlohmann::json(s.blow_mm) : nullptr},
           {"hammer_string_gap_mm", s.hammer_string_gap_mm},
           {"whippen_angle_deg", s.whippen_angle_deg}});
    nlohmann::json out{{"status", result.status},
                       {"setting", options.setting},
                       {"stop_t_s", result.stop_t},
                       {"stop_cause", result.status == "ok" ? nlohmann::json(nullptr)
                                                            : nlohmann::json(result.stop_cause)},
                       {"samples", samples}};
    std::cout << out.dump(1) << "\n";
  } else {
    std::cout << "deregulating " << options.setting << " at " << options.rate_mm_per_s
              << " mm/s, key at " << options.frequency_hz << " Hz\n";
    const int setting = model.setting_index(options.setting);
    const std::string unit = setting >= 0 ? model.regulation[setting].unit : "";
    int last_kind = 0;  // 0 read as the action stands, 1 read another way, 2 not read
    for (const DeregulationSample& s : result.samples) {
      std::cout << "  t " << format_fixed(s.t, 3) << " s  adjuster "
                << number_in(s.adjuster_mm, "mm", 3) << " mm  " << options.setting << " "
                << (std::isfinite(s.measured) ? number_in(s.measured, unit) + " " + unit
                                              : std::string("cannot be read"))
                << "  blow "
                << (std::isfinite(s.blow_mm) ? number_in(s.blow_mm, "mm") + " mm" : "-")
                << "  whippen " << format_fixed(s.whippen_angle_deg, 2) << " deg";
      // why a setting cannot be read, or how it was read, is written where it first appears,
      // not at each following sample (the JSON has every sample's)
      const int kind = !s.measure_problem.empty() ? 2 : !s.measure_note.empty() ? 1 : 0;
      if (kind != last_kind && kind > 0)
        std::cout << "  (" << (kind == 2 ? s.measure_problem : s.measure_note) << ")";
      last_kind = kind;
      std::cout << "\n";
    }
    const std::string words = stop_in_trade_words(result.stop_cause);
    std::cout << result.status << " at t = " << result.stop_t << " s"
              << (result.stop_cause.empty() ? ""
                  : words == result.stop_cause
                      ? ": " + result.stop_cause
                      : ": " + words + " (in the model's terms: " + result.stop_cause + ")")
              << "\n";
    if (plot.given()) std::cout << "plot written to " << plot.path() << "\n";
  }
  return 0;
}

}  // namespace pat::app

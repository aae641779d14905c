// pianoaction regulate: automatic regulation in the technician's order (DESIGN.md sections 3, 5).
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "json_output.h"
#include "plot_output.h"
#include "regulation/regulation.h"
#include "settings_output.h"

namespace pat::app {
namespace {

/// The steps in the technician's order (each setting's distance from its target, in
/// tolerances, and the adjuster chosen; a marker where each pass begins), then every setting
/// as left.
std::vector<PlotSpec> regulation_plots(const ActionModel& model, const RegulationResult& r) {
  PlotSpec off = category_plot("Regulation steps: distance from the target",
                               "measured − target (tolerances)", "step", "step_index");
  PlotSpec adjusters = category_plot("Regulation steps: adjuster chosen", "adjuster offset (mm)",
                                     "step", "step_index");
  PlotCurve distance = point_curve("measured − target", "off_target_tolerances");
  PlotCurve adjuster = point_curve("adjuster", "adjuster_mm");
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const RegulationStep& s = r.steps[i];
    off.x_categories.push_back(s.setting);
    if (i == 0 || r.steps[i - 1].pass != s.pass)
      off.markers.push_back({double(i) - 0.5, "pass " + std::to_string(s.pass)});
    adjuster.add(double(i), s.adjuster_mm);
    if (!std::isfinite(s.measured)) continue;  // not measurable in that position
    distance.add(double(i), (s.measured - s.target) /
                                model.regulation[model.setting_index(s.setting)].tolerance);
  }
  adjusters.x_categories = off.x_categories;
  adjusters.markers = off.markers;
  off.curves.push_back(std::move(distance));
  adjusters.curves.push_back(std::move(adjuster));

  PlotSpec settings = settings_plot(
      r.converged ? "Settings after regulation" : "Settings where regulation stopped", r.settings);
  std::vector<PlotSpec> plots;
  add_plot(plots, std::move(off));
  add_plot(plots, std::move(adjusters));
  add_plot(plots, std::move(settings));
  return plots;
}

}  // namespace

int run_regulate(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--out", "--max-passes", "--plot"},
                       {"--json", "--quiet"});
  const ActionModel model = load_configured_action(cl);
  if (model.regulation.empty())
    throw InputError(model.source_file + ": the preset lists no regulation settings");
  RegulationOptions options;
  options.max_passes = cl.whole_number_or("--max-passes", 100, 6);
  const bool text = !cl.has("--json");
  if (text && !cl.has("--quiet")) {
    options.on_step = [&model](const RegulationStep& s) {
      const int i = model.setting_index(s.setting);
      const std::string unit = i >= 0 ? model.regulation[i].unit : "";
      // the adjuster to the micrometre: the search moves it by less than the table's 0.01 mm
      std::cout << "pass " << s.pass << "  " << s.setting << ": adjuster "
                << number_in(s.adjuster_mm, "mm", 3) << " mm, reads "
                << (std::isfinite(s.measured) ? number_in(s.measured, unit) + " " + unit
                                              : std::string("nothing"))
                << " (target " << number_in(s.target, unit) << " " << unit << "; " << s.evaluations
                << (s.evaluations == 1 ? " measurement)" : " measurements)");
      if (!s.note.empty()) std::cout << "  [" << s.note << "]";
      std::cout << "\n";
      return true;
    };
  }
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");  // checked before the regulation
  const RegulationResult result = regulate(model, options);
  // a regulation that failed is plotted too: its steps show where it got stuck
  plot.write(regulation_plots(model, result), text);
  // a regulation that did not converge writes nothing: the previous file stays as it was
  if (result.converged && !out_path.empty()) write_preset(result.model, out_path);

  if (!text) {
    nlohmann::json settings = nlohmann::json::array();
    for (const SettingReading& r : result.settings) settings.push_back(setting_json(r));
    nlohmann::json steps = nlohmann::json::array();
    for (const RegulationStep& s : result.steps) {
      nlohmann::json step{{"pass", s.pass},
                          {"setting", s.setting},
                          {"adjuster_mm", s.adjuster_mm},
                          {"measured", number_or_null(s.measured)},
                          {"target", s.target},
                          {"evaluations", s.evaluations}};
      if (!s.note.empty()) step["note"] = s.note;
      steps.push_back(step);
    }
    nlohmann::json out{
        {"converged", result.converged},
        {"action", model.kind},
        {"settings", settings},
        {"steps", steps},
        {"passes", result.passes},
        {"wall_time_s", result.wall_time_s},
        {"message", result.converged ? nlohmann::json(nullptr) : nlohmann::json(result.message)}};
    if (result.converged && !out_path.empty()) out["written"] = out_path;
    std::cout << out.dump(1) << "\n";
  } else {
    print_settings_table(std::cout, result.model, result.settings,
                         "adjusters off the preset's positions after the regulation");
    std::cout << (result.converged ? "regulated" : "not regulated") << " in " << result.passes
              << (result.passes == 1 ? " pass, " : " passes, ") << format_number(result.wall_time_s)
              << " s\n";
    if (result.converged && !out_path.empty())
      std::cout << "regulated preset written to " << out_path << "\n";
  }
  if (!result.converged) {
    std::cerr << "pianoaction regulate: the " << model.kind
              << " action could not be regulated: " << result.message
              << (out_path.empty() ? "" : " (no preset written to " + out_path + ")") << "\n";
    return 1;
  }
  return 0;
}

}  // namespace pat::app

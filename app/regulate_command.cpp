// pianoaction regulate: automatic regulation in the technician's order (DESIGN.md sections 3, 5).
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "core/error.h"
#include "commands.h"
#include "regulation/regulation.h"

namespace pat::app {
namespace {

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

}  // namespace

int run_regulate(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--out", "--max-passes"},
                       {"--json", "--quiet"});
  const ActionModel model = load_configured_action(cl);
  if (model.regulation.empty())
    throw InputError(model.source_file + ": the preset lists no regulation settings");
  RegulationOptions options;
  options.max_passes = static_cast<int>(cl.positive_number_or("--max-passes", 6));
  const bool text = !cl.has("--json");
  if (text && !cl.has("--quiet")) {
    options.on_step = [](const RegulationStep& s) {
      std::cout << "pass " << s.pass << "  " << s.setting << ": adjuster " << s.adjuster_mm
                << " mm -> " << s.measured << " (target " << s.target << ", "
                << s.evaluations << " measurements)";
      if (!s.note.empty()) std::cout << "  [" << s.note << "]";
      std::cout << "\n";
      return true;
    };
  }
  const RegulationResult result = regulate(model, options);
  const std::string out_path = cl.value_or("--out", "");
  // a regulation that did not converge writes nothing: the previous file stays as it was
  if (result.converged && !out_path.empty()) write_preset(result.model, out_path);

  if (!text) {
    nlohmann::json settings = nlohmann::json::array();
    for (const SettingReading& r : result.settings)
      settings.push_back({{"name", r.name},
                          {"unit", r.unit},
                          {"target", r.target},
                          {"tolerance", r.tolerance},
                          {"measured", number_or_null(r.measured)},
                          {"adjuster_mm", r.adjuster_mm},
                          {"within_tolerance", r.within_tolerance()}});
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
    nlohmann::json out{{"converged", result.converged},
                       {"action", model.kind},
                       {"settings", settings},
                       {"steps", steps},
                       {"passes", result.passes},
                       {"wall_time_s", result.wall_time_s},
                       {"message", result.converged ? nlohmann::json(nullptr)
                                                    : nlohmann::json(result.message)}};
    if (result.converged && !out_path.empty()) out["written"] = out_path;
    std::cout << out.dump(1) << "\n";
  } else {
    for (const SettingReading& r : result.settings)
      std::cout << "  " << r.name << ": " << r.measured << " " << r.unit << " (target "
                << r.target << " ± " << r.tolerance << ", adjuster " << r.adjuster_mm
                << " mm)" << (r.within_tolerance() ? "" : "  OUT OF TOLERANCE") << "\n";
    std::cout << (result.converged ? "regulated" : "not regulated") << " in " << result.passes
              << " passes, " << result.wall_time_s << " s\n";
    if (result.converged && !out_path.empty())
      std::cout << "regulated preset written to " << out_path << "\n";
  }
  if (!result.converged) {
    std::cerr << "pianoaction regulate: the " << model.kind
              << " action could not be regulated: " << result.message
              << (out_path.empty() ? "" : " (nothing written)") << "\n";
    return 1;
  }
  return 0;
}

}  // namespace pat::app

// pianoaction measure: the seven regulation settings read the way a technician reads them
// (regulation/measurements.h) on the action as given, with --set/--without/--effect applied,
// against their targets; nothing is adjusted. A setting that cannot be read there is reported
// with the reason, and the others are still read.
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "json_output.h"
#include "plot_output.h"
#include "regulation/measurements.h"
#include "settings_output.h"

namespace pat::app {
int run_measure(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--effect", "--plot"}, {"--json"});
  const ActionModel model = load_configured_action(cl);
  if (model.regulation.empty())
    throw InputError(model.source_file + ": the preset lists no regulation settings");
  const PlotOption plot(cl.output_path("--plot"));
  const std::vector<SettingReading> readings = read_settings(model);
  bool all_within = true;
  for (const SettingReading& r : readings) all_within = all_within && r.within_tolerance();

  plot.write({settings_plot("Settings as read: distance from the target", readings)},
             !cl.has("--json"));

  if (cl.has("--json")) {
    nlohmann::json settings = nlohmann::json::array();
    for (std::size_t i = 0; i < readings.size(); ++i) {
      nlohmann::json setting = setting_json(readings[i]);
      setting["measurement"] = model.regulation[i].measurement;
      setting["problem"] = text_or_null(readings[i].problem);
      settings.push_back(setting);
    }
    std::cout << nlohmann::json{{"action", model.kind},
                                {"settings", settings},
                                {"within_tolerance", all_within}}
                     .dump(1)
              << "\n";
    return 0;
  }
  std::cout << model.name << ": the regulation settings as a technician reads them\n";
  print_settings_table(std::cout, model, readings);
  std::cout << (all_within ? "every setting within its tolerance\n"
                           : "not every setting is within its tolerance (regulate adjusts them)\n");
  return 0;
}

}  // namespace pat::app

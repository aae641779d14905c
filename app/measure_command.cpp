// pianoaction measure: the seven regulation settings read the way a technician reads them
// (regulation/measurements.h) on the action as given, with --set/--without/--effect applied,
// against their targets; nothing is adjusted. A setting that cannot be read there is reported
// with the reason, and the others are still read.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

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
  const PlotOption plot(cl);
  const std::vector<SettingReading> readings = read_settings(model);
  // the seven settings' result, read as a technician does with a gauge on the front rail
  double aftertouch_mm = NAN;
  std::string aftertouch_problem;
  try {
    aftertouch_mm = measure_aftertouch(model);
  } catch (const std::runtime_error& e) {
    aftertouch_problem = e.what();
  }
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
      setting["note"] = text_or_null(readings[i].note);
      settings.push_back(setting);
    }
    std::cout << nlohmann::json{{"action", model.kind},
                                {"settings", settings},
                                {"within_tolerance", all_within},
                                {"aftertouch_mm", number_or_null(aftertouch_mm)},
                                {"aftertouch_problem", text_or_null(aftertouch_problem)}}
                     .dump(1)
              << "\n";
    return 0;
  }
  std::cout << model.name << ": the regulation settings as a technician reads them\n";
  print_settings_table(std::cout, model, readings, "adjusters turned from the preset's positions");
  std::cout << "aftertouch (key travel left at let-off; the settings' result, technicians set "
               ".035-.045 in, 0.89-1.14 mm): ";
  if (!aftertouch_problem.empty())
    std::cout << "cannot be read: " << aftertouch_problem << "\n";
  else {
    const AgainstGauge against = aftertouch_against_gauge(aftertouch_mm);
    std::cout << number_in(aftertouch_mm, "mm") << " mm, "
              << (against == AgainstGauge::within ? "within that"
                  : against == AgainstGauge::less ? "less than that"
                                                  : "more than that")
              << "\n";
  }
  std::cout << (all_within ? "every setting within its tolerance\n"
                           : "not every setting is within its tolerance (regulate adjusts them)\n");
  return 0;
}

}  // namespace pat::app

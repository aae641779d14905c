// pianoaction measure: the seven regulation settings read the way a technician reads them
// (regulation/measurements.h) on the action as given, with --set/--without/--effect applied,
// against their targets; nothing is adjusted. A setting that cannot be read there is reported
// with the reason, and the others are still read.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "json_output.h"
#include "plot_output.h"
#include "regulation/measurements.h"
#include "settings_output.h"

namespace pat::app {
namespace {

/// A value in a setting's unit as a technician writes it: mm to 0.01, a fraction to 0.001
/// (a value that rounds to zero is written without a minus sign).
std::string number_in(double value, const std::string& unit) {
  const int decimals = unit == "mm" ? 2 : 3;
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

/// `text` padded with spaces to `width` characters (UTF-8: "±" is one character, two bytes).
std::string padded(const std::string& text, std::size_t width) {
  std::size_t characters = 0;
  for (const unsigned char c : text)
    if ((c & 0xC0) != 0x80) ++characters;
  return text + std::string(characters < width ? width - characters : 1, ' ');
}

}  // namespace

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
  std::cout << padded("setting", 16) << padded("measured", 16) << padded("target", 24)
            << padded("adjuster", 11) << "\n";
  for (const SettingReading& s : readings) {
    std::ostringstream adjuster;  // signed: which way the adjuster was turned
    adjuster << (s.adjuster_mm < 0.0 ? "" : "+") << number_in(s.adjuster_mm, "mm") << " mm";
    std::cout << padded(s.name, 16)
              << padded(s.problem.empty() ? number_in(s.measured, s.unit) + " " + s.unit : "-", 16)
              << padded(number_in(s.target, s.unit) + " ± " + number_in(s.tolerance, s.unit) + " " +
                            s.unit,
                        24)
              << padded(adjuster.str(), 11);
    if (!s.problem.empty())
      std::cout << "cannot be read: " << s.problem;
    else if (!s.within_tolerance())
      std::cout << "OUT OF TOLERANCE";
    std::cout << "\n";
  }
  std::cout << (all_within ? "every setting within its tolerance\n"
                           : "not every setting is within its tolerance (regulate adjusts them)\n");
  return 0;
}

}  // namespace pat::app

// pianoaction measure: the seven regulation settings read the way a technician reads them
// (regulation/measurements.h) on the action as given, with --set/--without/--effect applied,
// against their targets; nothing is adjusted. A setting that cannot be read there is reported
// with the reason, and the others are still read.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "json_output.h"
#include "plot_output.h"
#include "regulation/measurements.h"

namespace pat::app {
namespace {

struct Reading {
  SettingReading setting;
  std::string problem;  ///< why it could not be read (empty: read)
};

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

/// Each setting's distance from its target in tolerances (within ±1: regulated); a setting
/// that cannot be read has no point.
std::vector<PlotSpec> measure_plots(const std::vector<Reading>& readings) {
  PlotSpec plot = category_plot("Settings as read: distance from the target",
                                "measured − target (tolerances)", "setting", "setting_index");
  PlotCurve distance = point_curve("measured − target", "off_target_tolerances");
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const SettingReading& s = readings[i].setting;
    plot.x_categories.push_back(s.name);
    if (readings[i].problem.empty()) distance.add(double(i), (s.measured - s.target) / s.tolerance);
  }
  plot.curves.push_back(std::move(distance));
  std::vector<PlotSpec> plots;
  add_plot(plots, std::move(plot));
  return plots;
}

}  // namespace

int run_measure(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--set", "--without", "--effect", "--plot"}, {"--json"});
  const ActionModel model = load_configured_action(cl);
  if (model.regulation.empty())
    throw InputError(model.source_file + ": the preset lists no regulation settings");
  const PlotOption plot(cl.value_or("--plot", ""));
  const RestState rest = find_rest_state(model);
  std::vector<Reading> readings;
  bool all_within = true;
  for (const RegulationSetting& s : model.regulation) {
    Reading r;
    r.setting.name = s.name;
    r.setting.unit = s.unit;
    r.setting.target = s.target;
    r.setting.tolerance = s.tolerance;
    r.setting.adjuster_mm = model.adjusters[model.adjuster_index(s.name)].value * 1e3;
    try {
      r.setting.measured = measure_setting(model, s.name, &rest);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      r.setting.measured = NAN;
      r.problem = e.what();
    }
    all_within = all_within && r.problem.empty() && r.setting.within_tolerance();
    readings.push_back(r);
  }

  plot.write(measure_plots(readings), !cl.has("--json"));

  if (cl.has("--json")) {
    nlohmann::json settings = nlohmann::json::array();
    for (std::size_t i = 0; i < readings.size(); ++i) {
      const SettingReading& s = readings[i].setting;
      settings.push_back({{"name", s.name},
                          {"measurement", model.regulation[i].measurement},
                          {"unit", s.unit},
                          {"target", s.target},
                          {"tolerance", s.tolerance},
                          {"measured", number_or_null(s.measured)},
                          {"adjuster_mm", s.adjuster_mm},
                          {"within_tolerance", readings[i].problem.empty() && s.within_tolerance()},
                          {"problem", text_or_null(readings[i].problem)}});
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
  for (const Reading& r : readings) {
    const SettingReading& s = r.setting;
    std::ostringstream adjuster;  // signed: which way the adjuster was turned
    adjuster << (s.adjuster_mm < 0.0 ? "" : "+") << number_in(s.adjuster_mm, "mm") << " mm";
    std::cout << padded(s.name, 16)
              << padded(r.problem.empty() ? number_in(s.measured, s.unit) + " " + s.unit : "-", 16)
              << padded(number_in(s.target, s.unit) + " ± " + number_in(s.tolerance, s.unit) + " " +
                            s.unit,
                        24)
              << padded(adjuster.str(), 11);
    if (!r.problem.empty())
      std::cout << "cannot be read: " << r.problem;
    else if (!s.within_tolerance())
      std::cout << "OUT OF TOLERANCE";
    std::cout << "\n";
  }
  std::cout << (all_within ? "every setting within its tolerance\n"
                           : "not every setting is within its tolerance (regulate adjusts them)\n");
  return 0;
}

}  // namespace pat::app

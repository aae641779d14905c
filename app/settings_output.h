// The regulation settings as read (regulation/measurements.h) in the output of `regulate` and
// `measure`: one plot and one JSON object per setting.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "plot_spec.h"
#include "regulation/measurements.h"

namespace pat::app {

/// Each setting's distance from its target in tolerances (within ±1: regulated); a setting that
/// was not read has no point.
PlotSpec settings_plot(const std::string& title, const std::vector<SettingReading>& readings);

/// name, unit, target, tolerance, measured (null when not read), adjuster_mm, within_tolerance.
nlohmann::json setting_json(const SettingReading& reading);

/// A value in a setting's unit as a technician writes it: mm to 0.01, a fraction to 0.001, or
/// with `decimals` when given (a value that rounds to zero is written without a minus sign).
std::string number_in(double value, const std::string& unit, int decimals = -1);

/// The settings as a table (setting, measured, target ± tolerance, adjuster offset from the
/// preset's position to the micrometre, and what is wrong), then, under `turned_heading`, what +
/// means for each adjuster that is turned (its description in `model`).
void print_settings_table(std::ostream& out, const ActionModel& model,
                          const std::vector<SettingReading>& readings,
                          const std::string& turned_heading);

}  // namespace pat::app

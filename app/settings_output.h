// The regulation settings as read (regulation/measurements.h) in the output of `regulate` and
// `measure`: one plot and one JSON object per setting.
#pragma once

#include <nlohmann/json.hpp>
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

}  // namespace pat::app

#include "settings_output.h"

#include <cmath>
#include <utility>

#include "json_output.h"

namespace pat::app {

PlotSpec settings_plot(const std::string& title, const std::vector<SettingReading>& readings) {
  PlotSpec plot =
      category_plot(title, "measured − target (tolerances)", "setting", "setting_index");
  PlotCurve distance = point_curve("measured − target", "off_target_tolerances");
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const SettingReading& s = readings[i];
    plot.x_categories.push_back(s.name);
    if (std::isfinite(s.measured)) distance.add(double(i), (s.measured - s.target) / s.tolerance);
  }
  plot.curves.push_back(std::move(distance));
  return plot;
}

nlohmann::json setting_json(const SettingReading& r) {
  return {{"name", r.name},
          {"unit", r.unit},
          {"target", r.target},
          {"tolerance", r.tolerance},
          {"measured", number_or_null(r.measured)},
          {"adjuster_mm", r.adjuster_mm},
          {"within_tolerance", r.within_tolerance()}};
}

}  // namespace pat::app

#include "settings_output.h"

#include <cmath>
#include <utility>

#include "core/format.h"
#include "json_output.h"

namespace pat::app {

PlotSpec settings_plot(const std::string& title, const std::vector<SettingReading>& readings) {
  PlotSpec plot =
      category_plot(title, "measured − target (tolerances)", "setting", "setting_index");
  PlotCurve distance = point_curve("measured − target", "off_target_tolerances");
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const SettingReading& s = readings[i];
    // in the technician's words; a setting that cannot be read says so where its point would be
    plot.x_categories.push_back(setting_words(s.name) +
                                (std::isfinite(s.measured) ? "" : " (no reading)"));
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

std::string number_in(double value, const std::string& unit, int decimals) {
  return format_fixed(value, decimals >= 0 ? decimals : unit == "mm" ? 2 : 3);
}

namespace {

/// `text` padded with spaces to `width` characters (UTF-8: "±" is one character, two bytes).
std::string padded(const std::string& text, std::size_t width) {
  std::size_t characters = 0;
  for (const unsigned char c : text)
    if ((c & 0xC0) != 0x80) ++characters;
  return text + std::string(characters < width ? width - characters : 1, ' ');
}

/// A signed adjuster offset to the micrometre, the regulation's resolution: which way it was
/// turned ("+0.300 mm", "-0.004 mm", "0.000 mm").
std::string signed_mm(double value_mm) {
  const std::string number = number_in(value_mm, "mm", 3);
  return (number[0] == '-' || number == "0.000" ? "" : "+") + number + " mm";
}

}  // namespace

void print_settings_table(std::ostream& out, const ActionModel& model,
                          const std::vector<SettingReading>& readings,
                          const std::string& turned_heading) {
  out << padded("setting", 16) << padded("measured", 16) << padded("target", 24)
      << padded("adjuster", 12) << "\n";
  std::vector<std::string> turned;  // what + means, for the adjusters that are not at 0
  for (const SettingReading& s : readings) {
    out << padded(s.name, 16)
        << padded(s.problem.empty() ? number_in(s.measured, s.unit) + " " + s.unit : "-", 16)
        << padded(
               number_in(s.target, s.unit) + " ± " + number_in(s.tolerance, s.unit) + " " + s.unit,
               24)
        << padded(signed_mm(s.adjuster_mm), 12);
    if (!s.problem.empty())
      out << "cannot be read: " << s.problem;
    else if (!s.within_tolerance())
      out << "OUT OF TOLERANCE";
    if (!s.note.empty()) out << (s.problem.empty() && s.within_tolerance() ? "" : "; ") << s.note;
    out << "\n";
    const int a = model.adjuster_index(s.name);
    if (a >= 0 && signed_mm(s.adjuster_mm) != "0.000 mm" && !model.adjusters[a].description.empty())
      turned.push_back(s.name + " " + signed_mm(s.adjuster_mm) + ": " +
                       model.adjusters[a].description);
  }
  if (!turned.empty()) {
    out << turned_heading << " (+ as described):\n";
    for (const std::string& line : turned) out << "  " << line << "\n";
  }
}

}  // namespace pat::app

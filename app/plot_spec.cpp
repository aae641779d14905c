#include "plot_spec.h"

#include <utility>

namespace pat::app {

PlotSpec time_plot(const std::string& title, const std::string& y_title) {
  PlotSpec plot;
  plot.title = title;
  plot.y_title = y_title;
  return plot;
}

PlotSpec category_plot(const std::string& title, const std::string& y_title,
                       const std::string& x_title, const std::string& x_column) {
  PlotSpec plot = time_plot(title, y_title);
  plot.x_title = x_title;
  plot.x_column = x_column;
  plot.x_unit.clear();
  return plot;
}

PlotCurve point_curve(const std::string& label, const std::string& column) {
  PlotCurve curve = line_curve(label, column);
  curve.points = true;
  return curve;
}

PlotCurve line_curve(const std::string& label, const std::string& column) {
  PlotCurve curve;
  curve.label = label;
  curve.column = column;
  return curve;
}

PlotSpec table_plot(const CsvTable& table, const std::string& title, const std::string& y_title,
                    std::initializer_list<ColumnCurve> curves, const std::string& x_column,
                    const std::string& x_title, const std::string& x_unit) {
  PlotSpec plot = time_plot(title, y_title);
  plot.x_column = x_column;
  plot.x_title = x_title;
  plot.x_unit = x_unit;
  if (table.column_index(x_column) < 0) return plot;
  const std::vector<double> x = table.column(x_column);
  for (const ColumnCurve& c : curves) {
    if (table.column_index(c.column) < 0) continue;
    PlotCurve curve = line_curve(c.label, c.column);
    curve.x = x;
    curve.y = table.column(c.column);
    plot.curves.push_back(std::move(curve));
  }
  return plot;
}

PlotSpec table_plot(const CsvTable& table, const std::string& title, const std::string& y_title,
                    std::initializer_list<ColumnCurve> curves) {
  return table_plot(table, title, y_title, curves, "time_s", "time (s)", "s");
}

void add_plot(std::vector<PlotSpec>& plots, PlotSpec plot) {
  for (const PlotCurve& c : plot.curves)
    if (!c.y.empty()) {
      plots.push_back(std::move(plot));
      return;
    }
}

std::vector<PlotSpec> trace_plots(const CsvTable& trace) {
  std::vector<PlotSpec> plots;
  add_plot(plots, table_plot(trace, "Key and hammer", "angle (deg)",
                             {{"key_angle_deg", "key"}, {"hammer_angle_deg", "hammer"}}));
  add_plot(plots, table_plot(trace, "Hammer–string gap", "gap (mm)",
                             {{"hammer_string_gap_mm", "hammer–string gap"}}));
  add_plot(plots, table_plot(trace, "Finger force (the touch)", "force (N)",
                             {{"finger_force_n", "finger force"}}));
  return plots;
}

}  // namespace pat::app

// What `--plot FILE` draws, as plain data: plots of named series over any x axis (time,
// frequency, key dip, setting), built by each subcommand from the results it computed. In the
// window build plot_output.cpp hands them to the window's plot and export code (ui/
// analysis_plots.h); this header stays free of Qt so that the engine-only build compiles.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "io/csv.h"

namespace pat::app {

struct PlotCurve {
  std::string label;         ///< in the legend
  std::string column;        ///< CSV column with its unit, e.g. hammer_angle_deg
  std::vector<double> x, y;  ///< x ascending
  bool points = false;       ///< markers only (one result per cycle or case), else a line
  int colour = -1;           ///< palette index; -1: the curve's place in its plot

  void add(double x_value, double y_value) {
    x.push_back(x_value);
    y.push_back(y_value);
  }
};

struct PlotMarker {
  double x = 0.0;
  std::string label;
};

struct PlotSpec {
  std::string title;
  std::string y_title;  ///< with the unit, e.g. "angle (deg)"
  std::string x_title = "time (s)", x_column = "time_s", x_unit = "s";
  std::vector<PlotCurve> curves;
  std::vector<std::string> x_categories;  ///< names of x = 0, 1, … (empty: numeric x)
  std::vector<PlotMarker> markers;
};

/// A plot over time (s), curves to be added.
PlotSpec time_plot(const std::string& title, const std::string& y_title);
/// A plot over named positions x = 0, 1, … (settings, cases), categories to be added.
PlotSpec category_plot(const std::string& title, const std::string& y_title,
                       const std::string& x_title, const std::string& x_column);
/// An empty curve drawn as markers (one result per case or cycle).
PlotCurve point_curve(const std::string& label, const std::string& column);
/// An empty curve drawn as a line.
PlotCurve line_curve(const std::string& label, const std::string& column);

/// A column of a table and its legend label.
struct ColumnCurve {
  const char* column;
  const char* label;
};

/// A plot of table columns over the table's x column (default time_s). Columns the table lacks
/// are left out (a trace without a finger force has no finger-force curve).
PlotSpec table_plot(const CsvTable& table, const std::string& title, const std::string& y_title,
                    std::initializer_list<ColumnCurve> curves);
PlotSpec table_plot(const CsvTable& table, const std::string& title, const std::string& y_title,
                    std::initializer_list<ColumnCurve> curves, const std::string& x_column,
                    const std::string& x_title, const std::string& x_unit);

/// Appends `plot` when it has a curve with data.
void add_plot(std::vector<PlotSpec>& plots, PlotSpec plot);

/// The plots of a simulation trace (DESIGN.md section 5 columns): key and hammer angles,
/// hammer–string gap, finger force; the trace plots of the window.
std::vector<PlotSpec> trace_plots(const CsvTable& trace);

}  // namespace pat::app

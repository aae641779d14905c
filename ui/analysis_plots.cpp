#include "analysis_plots.h"

#include <QApplication>
#include <algorithm>
#include <memory>

#include "gui_application.h"
#include "plot_export.h"
#include "plot_panel.h"
#include "plot_styles.h"

namespace pat::ui {

PlotPanel* make_analysis_plot_panel(const AnalysisPlot& p, QWidget* parent) {
  auto* panel = new PlotPanel(p.title, p.y_title, parent);
  panel->set_x_axis(p.x_title, p.x_column, "x", p.x_unit, 1.0);
  for (std::size_t s = 0; s < p.series.size(); ++s) {
    const AnalysisSeries& series = p.series[s];
    const int id = panel->add_series(series.label, series.column,
                                     series_colour(series.colour >= 0 ? series.colour : int(s)));
    panel->set_data(id, series.x, series.y);
    if (series.points) panel->set_points_only(id);
  }
  if (!p.x_categories.empty()) panel->set_x_categories(p.x_categories);
  for (const AnalysisMarker& m : p.markers) panel->add_marker(m.x, m.label);
  panel->fit_all();
  return panel;
}

QSize stacked_plot_size(std::size_t count) {
  return QSize(1000, 300 * static_cast<int>(std::max<std::size_t>(count, 1)));
}

QStringList write_analysis_plots(const std::vector<AnalysisPlot>& plots, const QString& path,
                                 QSize size, const ApproveFiles& approve) {
  export_format(path);  // a wrong extension is reported before any work
  if (!QApplication::instance() && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");  // the command line needs no display
  const std::unique_ptr<QApplication> app = application_if_none();
  if (!size.isValid()) size = stacked_plot_size(plots.size());
  std::vector<std::unique_ptr<PlotPanel>> panels;
  std::vector<PlotPanel*> raw;
  for (const AnalysisPlot& p : plots) {
    panels.emplace_back(make_analysis_plot_panel(p));
    panels.back()->resize(size.width(),
                          size.height() / int(std::max<std::size_t>(plots.size(), 1)));
    raw.push_back(panels.back().get());
  }
  return export_plots(raw, path, size, {}, approve);
}

}  // namespace pat::ui

#include "trace_plots.h"

#include <QApplication>
#include <memory>

#include "plot_export.h"
#include "plot_styles.h"

namespace pat::ui {
namespace {

struct SeriesSpec {
  const char* column;
  const char* label;
};

std::unique_ptr<PlotPanel> make_plot(const CsvTable& trace, const char* title, const char* axis,
                                     std::initializer_list<SeriesSpec> series) {
  std::unique_ptr<PlotPanel> plot;
  const std::vector<double> time = trace.column("time_s");
  int n = 0;
  for (const SeriesSpec& s : series) {
    if (trace.column_index(s.column) < 0) continue;
    if (!plot) plot = std::make_unique<PlotPanel>(QObject::tr(title), QObject::tr(axis));
    const int id = plot->add_series(QObject::tr(s.label), s.column, series_colour(n++));
    plot->set_data(id, time, trace.column(s.column));
  }
  if (plot) {
    plot->resize(1000, 300);
    plot->fit_all();
  }
  return plot;
}

}  // namespace

std::vector<std::unique_ptr<PlotPanel>> make_trace_plots(const CsvTable& trace) {
  using namespace plot_titles;
  std::vector<std::unique_ptr<PlotPanel>> plots;
  auto add = [&](std::unique_ptr<PlotPanel> plot) {
    if (plot) plots.push_back(std::move(plot));
  };
  add(make_plot(trace, kAngles, kAnglesAxis,
                {{"key_angle_deg", "key"}, {"hammer_angle_deg", "hammer"}}));
  add(make_plot(trace, kGap, kGapAxis, {{"hammer_string_gap_mm", "hammer–string gap"}}));
  add(make_plot(trace, kFinger, kFingerAxis, {{"finger_force_n", "finger force"}}));
  return plots;
}

void write_trace_plot(const CsvTable& trace, const QString& path, QSize size) {
  export_format(path);  // a wrong extension is reported before any work
  std::unique_ptr<QApplication> app;
  if (!QApplication::instance()) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "pianoaction";
    static char* argv[] = {name, nullptr};
    app = std::make_unique<QApplication>(argc, argv);
  }
  const auto plots = make_trace_plots(trace);
  std::vector<PlotPanel*> raw;
  for (const auto& p : plots) raw.push_back(p.get());
  export_plots(raw, path, size);
}

}  // namespace pat::ui

#include "plot_output.h"

#include <iostream>
#include <utility>

#include "core/error.h"
#ifdef PAT_HAVE_UI
#include <QString>

#include "analysis_plots.h"
#include "analysis_result.h"
#include "plot_export.h"
#endif

namespace pat::app {
namespace {

#ifdef PAT_HAVE_UI
QString text(const std::string& s) {
  return QString::fromStdString(s);
}

ui::AnalysisPlot to_analysis_plot(const PlotSpec& spec) {
  ui::AnalysisPlot plot;
  plot.title = text(spec.title);
  plot.x_title = text(spec.x_title);
  plot.x_column = text(spec.x_column);
  plot.x_unit = text(spec.x_unit);
  plot.y_title = text(spec.y_title);
  for (const PlotCurve& c : spec.curves)
    plot.series.push_back({text(c.label), text(c.column), c.x, c.y, c.points, c.colour});
  for (const std::string& name : spec.x_categories) plot.x_categories.push_back(text(name));
  for (const PlotMarker& m : spec.markers) plot.markers.push_back({m.x, text(m.label)});
  return plot;
}
#endif

}  // namespace

bool plotting_available() {
#ifdef PAT_HAVE_UI
  return true;
#else
  return false;
#endif
}

#ifdef PAT_HAVE_UI
void check_plot_path(const std::string& path) {
  ui::export_format(text(path));
}

bool is_csv_plot_path(const std::string& path) {
  return ui::export_format(text(path)) == ui::ExportFormat::Csv;
}

void write_plots(const std::string& path, const std::vector<PlotSpec>& plots,
                 const std::vector<KeptFile>& keep) {
  if (plots.empty()) throw InputError("--plot " + path + ": the run gave nothing to plot");
  std::vector<ui::AnalysisPlot> converted;
  for (const PlotSpec& spec : plots) converted.push_back(to_analysis_plot(spec));
  // a CSV holds one table: plots whose rows differ (another x axis, other x values) go to further
  // files beside PATH (said on stderr, which --json leaves to notes); those names are known only
  // from the plots, so they are checked against the files kept before anything is written
  const auto approve = [&](const QStringList& files) {
    for (int f = 1; f < files.size(); ++f)
      for (const auto& [what, kept] : keep)
        if (same_file(files[f].toStdString(), kept))
          throw InputError("--plot " + path + ": some of its plots go to " +
                           files[f].toStdString() + ", which is " + what +
                           "; nothing was plotted, so give --plot another name");
    return true;
  };
  const QStringList written = ui::write_analysis_plots(converted, text(path), {}, approve);
  for (int f = 1; f < written.size(); ++f)
    std::cerr << "note: plots went to " << written[f].toStdString()
              << " too (a CSV holds one table: plots whose rows differ have their own)\n";
}
#else
void check_plot_path(const std::string& path) {
  throw InputError("--plot " + path +
                   ": plots need the window build; this build has no plotting (configured with "
                   "PAT_ENGINE_ONLY)");
}

void write_plots(const std::string& path, const std::vector<PlotSpec>&,
                 const std::vector<KeptFile>&) {
  check_plot_path(path);
}

bool is_csv_plot_path(const std::string& path) {
  check_plot_path(path);
  return false;
}
#endif

PlotOption::PlotOption(const CommandLine& command_line)
    : command_line_(command_line), path_(command_line.output_path("--plot")) {
  if (given()) check_plot_path(path_);  // a wrong extension fails before any work
}

bool PlotOption::write(const std::vector<PlotSpec>& plots) const {
  if (!given()) return false;
  write_plots(path_, plots, command_line_.files_other_than("--plot"));
  return true;
}

void PlotOption::write(const std::vector<PlotSpec>& plots, bool announce) const {
  if (write(plots) && announce) std::cout << "plot written to " << path_ << "\n";
}

}  // namespace pat::app

#include "plot_output.h"

#include <algorithm>
#include <filesystem>
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
  auto write_group = [](const std::string& file, const std::vector<const PlotSpec*>& group) {
    std::vector<ui::AnalysisPlot> converted;
    for (const PlotSpec* spec : group) converted.push_back(to_analysis_plot(*spec));
    ui::write_analysis_plots(converted, text(file));
  };
  std::vector<const PlotSpec*> all;
  for (const PlotSpec& spec : plots) all.push_back(&spec);
  if (!is_csv_plot_path(path)) {  // a picture stacks every plot
    write_group(path, all);
    return;
  }
  // a CSV holds one x axis: the plots over the first plot's x go to PATH, those over each other
  // x to STEM_<x column>.csv beside it (said on stderr, which --json leaves to notes)
  std::vector<std::string> x_columns;  // in the order the plots first use them
  for (const PlotSpec& spec : plots)
    if (std::find(x_columns.begin(), x_columns.end(), spec.x_column) == x_columns.end())
      x_columns.push_back(spec.x_column);
  const std::filesystem::path file(path);
  std::vector<std::string> group_paths;
  for (std::size_t g = 0; g < x_columns.size(); ++g) {
    group_paths.push_back(
        g == 0
            ? path
            : (file.parent_path() / (file.stem().string() + "_" + x_columns[g] + ".csv")).string());
    for (const auto& [what, kept] : keep) {
      if (g > 0 && same_file(group_paths[g], kept))
        throw InputError("--plot " + path + ": its plots over " + x_columns[g] + " go to " +
                         group_paths[g] + ", which is " + what +
                         "; nothing was plotted, so give --plot another name");
    }
  }
  for (std::size_t g = 0; g < x_columns.size(); ++g) {
    std::vector<const PlotSpec*> group;
    for (const PlotSpec* spec : all)
      if (spec->x_column == x_columns[g]) group.push_back(spec);
    const std::string& group_path = group_paths[g];
    write_group(group_path, group);
    if (g > 0)
      std::cerr << "note: the plots over " << x_columns[g] << " went to " << group_path
                << " (a CSV holds one x axis)\n";
  }
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

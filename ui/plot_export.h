// Export of one plot or several (stacked top to bottom on one page or image): PNG at a chosen
// pixel size, PDF and SVG as vector graphics of that size, CSV of the time range shown. The
// format comes from the file extension. Used by the window and by `--plot` on the command line.
#pragma once

#include <QSize>
#include <QString>
#include <QStringList>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pat::ui {

class PlotPanel;

enum class ExportFormat { Png, Pdf, Svg, Csv };

/// The width (px) a large export is laid out at before it is drawn larger, text included: the
/// plots here, the action view's pictures (animation_export.h).
inline constexpr double kExportLayoutWidth = 800.0;

/// The format of a file name's extension (.png .pdf .svg .csv, any case). Throws InputError
/// naming the file for any other extension.
ExportFormat export_format(const QString& path);

/// What decides which CSV file a plot's rows go to: its x column, its title, the x value of each
/// row it writes (in order; a value may repeat, as a frequency held for several cycles) and the
/// names of the x values when the plot names them (a category plot's "0 key_dip; 1 let_off").
struct PlotCsvShape {
  QString x_column;
  QString title;
  std::vector<double> x;
  std::string x_names;
};

/// One CSV file of a plot export: its path and the plots (indices) whose columns it holds.
struct PlotCsvFile {
  QString path;
  std::vector<std::size_t> plots;
};

/// How a CSV export of plots is split. A CSV is one table: plots share a file when they have the
/// same x column, the same x values row by row and the same names for them, so that a row holds
/// one sample of each. The first plot's file is `path`; each further file is STEM_<x column>.csv
/// beside it, or STEM_<plot title>.csv when a file has that x column already (numbered when two
/// plots of one title need one each).
std::vector<PlotCsvFile> plot_csv_files(const std::vector<PlotCsvShape>& plots,
                                        const QString& path);

/// Called with the files a CSV export will write (`path` first) before anything is written;
/// false writes nothing. May throw InputError (e.g. a further file would replace an input).
using ApproveFiles = std::function<bool(const QStringList& files)>;

/// Writes `plots` to `path` (format from the extension) and returns the files written (a CSV
/// export may write several: plot_csv_files; none when `approve` declined). `size` is the whole
/// export in pixels (points for PDF); the plots share its height. `metadata` (e.g. action, input,
/// settings) goes into a CSV's '#' lines. Throws InputError naming the file when it cannot be
/// written.
QStringList export_plots(const std::vector<PlotPanel*>& plots, const QString& path, QSize size,
                         const std::map<std::string, std::string>& metadata = {},
                         const ApproveFiles& approve = {});

}  // namespace pat::ui

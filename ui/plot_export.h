// Export of one plot or several (stacked top to bottom on one page or image): PNG at a chosen
// pixel size, PDF and SVG as vector graphics of that size, CSV of the time range shown. The
// format comes from the file extension. Used by the window and by `--plot` on the command line.
#pragma once

#include <QSize>
#include <QString>
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

/// Writes `plots` to `path` (format from the extension). `size` is the whole export in pixels
/// (points for PDF); the plots share its height. `metadata` (e.g. action, input, settings) goes
/// into a CSV's '#' lines. Throws InputError naming the file when it cannot be written.
void export_plots(const std::vector<PlotPanel*>& plots, const QString& path, QSize size,
                  const std::map<std::string, std::string>& metadata = {});

}  // namespace pat::ui

// Plots of series over any x axis (AnalysisPlot: time, frequency, key dip, setting) as
// PlotPanels: the Analyses dock shows them, and the command line's --plot writes them to a
// file without a window.
#pragma once

#include <QSize>
#include <QString>
#include <vector>

#include "analysis_result.h"
#include "plot_export.h"

class QWidget;

namespace pat::ui {

class PlotPanel;

/// A panel showing `plot` fitted to all its data (series in the shared colours, markers,
/// named categories).
PlotPanel* make_analysis_plot_panel(const AnalysisPlot& plot, QWidget* parent = nullptr);

/// The export size for `count` stacked plots: 1000 px wide, 300 px per plot.
QSize stacked_plot_size(std::size_t count);

/// Exports the plots stacked top to bottom to `path` (format from the extension; size default:
/// stacked_plot_size; a CSV may be several files: plot_csv_files), creating an offscreen Qt
/// application when none runs (the command line needs no display). Returns the files written.
/// Throws InputError naming the file.
QStringList write_analysis_plots(const std::vector<AnalysisPlot>& plots, const QString& path,
                                 QSize size = {}, const ApproveFiles& approve = {});

}  // namespace pat::ui

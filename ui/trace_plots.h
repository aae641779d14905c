// Plots of a recorded trace (a CSV table with the columns of DESIGN.md section 5): key and
// hammer angles, hammer–string gap, finger force. The command line's --plot uses them.
#pragma once

#include <QSize>
#include <QString>
#include <memory>
#include <vector>

#include "io/csv.h"
#include "plot_panel.h"

namespace pat::ui {

/// One plot per quantity the trace has, fitted to all its data.
std::vector<std::unique_ptr<PlotPanel>> make_trace_plots(const CsvTable& trace);

/// Exports the trace plots to `path` (format from the extension), creating an offscreen Qt
/// application when none runs (the command line needs no display). Throws InputError.
void write_trace_plot(const CsvTable& trace, const QString& path, QSize size = QSize(1000, 900));

}  // namespace pat::ui

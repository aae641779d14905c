// What an analysis run from the window hands back: a summary line, a table of named values and
// plots of series over any x axis (frequency, time, setting). Plain data, built in the worker
// thread and shown by the AnalysesPanel.
#pragma once

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

#include "analysis/progress.h"

namespace pat::ui {

struct AnalysisTableRow {
  QString quantity;
  QString value;
  QString unit;
};

struct AnalysisSeries {
  QString label;
  QString column;            ///< CSV column with its unit, e.g. strikes_per_cycle
  std::vector<double> x, y;  ///< x ascending
  bool points = false;       ///< markers only (per-cycle results), else a line
  int colour = -1;           ///< palette index (series_colour); -1: the series' place in its plot
};

/// A vertical line across a plot at x, labelled (e.g. the maximum repetition frequency).
struct AnalysisMarker {
  double x = 0.0;
  QString label;
};

struct AnalysisPlot {
  QString title;
  QString x_title, x_column;  ///< e.g. "frequency (Hz)", frequency_hz
  QString x_unit;             ///< for the cursor readout, e.g. Hz
  QString y_title;            ///< with the unit, e.g. "impact velocity (m/s)"
  std::vector<AnalysisSeries> series;
  std::vector<QString> x_categories;  ///< names of x = 0, 1, … (empty: numeric x)
  std::vector<AnalysisMarker> markers;
  QString tab;  ///< short name on its tab (empty: the title); the dock is narrow
};

/// A table with its own columns (a ranking, the cycles of a sweep), shown in a tab of its own.
struct AnalysisGrid {
  QString title;
  QStringList columns;  ///< with units, e.g. "validated rms (deg)"
  std::vector<QStringList> rows;
};

struct AnalysisResult {
  QString summary;  ///< one sentence a teacher can read out
  std::vector<AnalysisTableRow> table;
  std::vector<AnalysisPlot> plots;
  std::vector<AnalysisGrid> grids;
  /// When set, the panel offers "Export report…": writes the analysis's own report into a
  /// folder (throws InputError naming what cannot be written). Runs on the window's thread.
  std::function<void(const QString& folder)> write_report;
};

/// The work of one analysis, run in a worker thread. It calls the callback with its progress;
/// when the callback returns false it stops by throwing pat::Cancelled.
using AnalysisTask = std::function<AnalysisResult(const ProgressCallback& progress)>;

}  // namespace pat::ui

Q_DECLARE_METATYPE(pat::ui::AnalysisResult)

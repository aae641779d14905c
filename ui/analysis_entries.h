// The analyses of the catalogue that live in files of their own, and the helpers they share
// with it (analysis_catalogue.cpp).
#pragma once

#include <QString>

#include "analysis_catalogue.h"
#include "io/csv.h"

namespace pat::ui {

/// The repetition-frequency sweep (fact F4): stroke, mode, frequency band (sweep_analysis.cpp).
AnalysisEntry repetition_sweep_entry();
/// Upright vs grand under one input, with their repetition limits (comparison_analysis.cpp).
AnalysisEntry action_comparison_entry();
/// Diagnosis of measured files against candidate extensions (diagnosis_analysis.cpp).
AnalysisEntry diagnosis_entry();

/// A number as the command line prints it (core/format.h), `precision` significant digits; for
/// a class, "—" where there is none (NaN) and 0 below 0.0005 (no "4.62e-05").
QString number(double value, int precision = 3);
/// A plot over time (s) of these series.
AnalysisPlot time_plot(const QString& title, const QString& y_title,
                       std::vector<AnalysisSeries> series);
/// A trace column as a plotted series (x: its time_s column; empty when a column is missing).
AnalysisSeries trace_series(const CsvTable& trace, const std::string& column, const QString& label,
                            bool points = false);

}  // namespace pat::ui

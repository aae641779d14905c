// The practice session report for a teacher: a PDF (QPdfWriter drawing a QTextDocument) and
// the CSV of the engine (write_session_csv). The hidden fault is named only once the session
// is scored.
#pragma once

#include <QString>

#include "practice/session.h"

namespace pat::ui {

/// The report as HTML (what the PDF shows).
QString session_report_html(const PracticeSession& session);

/// Writes the PDF report. Throws InputError when the file cannot be written.
void write_session_pdf(const QString& path, const PracticeSession& session);

/// The report's two files from the name chosen in the save dialog: NAME.pdf and NAME.csv side by
/// side, whether the name was typed with ".pdf", with ".csv" (either case) or without an
/// extension ("session" → session.pdf, session.csv; "rep.csv" → rep.pdf, rep.csv).
struct ReportPaths {
  QString pdf, csv;
};
ReportPaths report_paths(const QString& chosen);

}  // namespace pat::ui

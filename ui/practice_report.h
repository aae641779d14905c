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

}  // namespace pat::ui

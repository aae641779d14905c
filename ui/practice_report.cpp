#include "practice_report.h"

#include <QFile>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>

#include "core/error.h"

namespace pat::ui {
namespace {

QString cell(const std::string& text) {
  return QString::fromStdString(text).toHtmlEscaped();
}

/// A reading with its unit ("0.15 mm"), or why there is none.
QString reading(const std::optional<double>& v, const std::string& unit) {
  return v ? QString::fromStdString(reading_text(*v, unit)) : QObject::tr("not measurable");
}

}  // namespace

QString session_report_html(const PracticeSession& session) {
  const Exercise& e = session.exercise();
  QString html = "<h2>" + QObject::tr("Practice session report") + "</h2>";
  html += "<p>";
  if (!session.trainee().empty())
    html += QObject::tr("Trainee: %1").arg("<b>" + cell(session.trainee()) + "</b>") + "<br>";
  html += "<b>" + cell(e.title) + "</b><br>" + QObject::tr("Action: %1").arg(cell(e.kind));
  if (e.seed)
    html += "<br>" + QObject::tr("Exercise number %1, level %2").arg(*e.seed).arg(e.level);
  if (!e.source_file.empty())
    html += "<br>" + QObject::tr("Exercise file: %1").arg(cell(e.source_file));
  if (!e.notes.empty()) html += "<br>" + cell(e.notes);
  html += "</p>";
  const auto& score = session.final_score();
  if (score) {
    html += "<h3>" + QObject::tr("Score: %1 / 100").arg(score->total, 0, 'f', 1) + "</h3><ul>";
    for (const std::string& note : score->notes) html += "<li>" + cell(note) + "</li>";
    html += "</ul><p>" + QObject::tr("Hidden:") + " ";
    QStringList hidden;
    for (const FaultAnswer& a : exercise_answers(e))
      hidden << cell(setting_words(a.setting)) + " (" +
                    QObject::tr("%1 than its target").arg(cell(a.direction)) + ")";
    html += hidden.join(", ");
    html += "</p><table border='1' cellspacing='0' cellpadding='3'><tr><th>" +
            QObject::tr("setting") + "</th><th>" + QObject::tr("regulated") + "</th><th>" +
            QObject::tr("deregulated") + "</th><th>" + QObject::tr("after correction") +
            "</th></tr>";
    const ActionModel& regulated = session.regulated();
    for (const CorrectionReading& r : score->readings) {
      if (!r.scored) continue;  // named in the notes above when out of tolerance
      const int index = regulated.setting_index(r.setting);
      const std::string unit = index >= 0 ? regulated.regulation[index].unit : std::string();
      html += "<tr><td>" + cell(setting_words(r.setting)) + "</td><td>" +
              reading(r.regulated, unit) + "</td><td>" + reading(r.hidden, unit) + "</td><td>" +
              reading(r.corrected, unit) + "</td></tr>";
    }
    html += "</table>";
  } else {
    html += "<p>" + QObject::tr("Not scored yet.") + "</p>";
  }
  html += "<h3>" + QObject::tr("History") +
          "</h3><table border='1' cellspacing='0' "
          "cellpadding='3'><tr><th>t (s)</th><th>" +
          QObject::tr("what") + "</th><th>" + QObject::tr("detail") + "</th></tr>";
  // a test's line, then the sentences the trainee read (in grey)
  for (const SessionEvent& ev : session.history())
    html += "<tr><td>" + QString::number(ev.t_s, 'f', 1) + "</td><td>" + cell(ev.kind) +
            "</td><td>" + cell(ev.detail) +
            (ev.words.empty() ? QString()
                              : "<br><span style='color:#555'>" + cell(ev.words) + "</span>") +
            "</td></tr>";
  html += "</table>";
  return html;
}

void write_session_pdf(const QString& path, const PracticeSession& session) {
  // written beside and renamed, so an existing report is never left half-written
  const QString temporary = path + ".tmp";
  {
    QPdfWriter pdf(temporary);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setResolution(150);
    pdf.setTitle(QObject::tr("Practice session report"));
    QTextDocument doc;
    doc.setHtml(session_report_html(session));
    doc.print(&pdf);
  }
  QFile written(temporary);
  if (!written.exists() || written.size() == 0)
    throw InputError(path.toStdString() + ": cannot write the PDF report");
  QFile::remove(path);
  if (!written.rename(path)) {
    written.remove();
    throw InputError(path.toStdString() + ": cannot write the PDF report (rename failed)");
  }
}

ReportPaths report_paths(const QString& chosen) {
  QString stem = chosen;
  while (stem.endsWith(".pdf", Qt::CaseInsensitive) || stem.endsWith(".csv", Qt::CaseInsensitive))
    stem.chop(4);
  return {stem + ".pdf", stem + ".csv"};
}

}  // namespace pat::ui

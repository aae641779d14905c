// The save dialogs' paths: the suffix of the format chosen in the dialog when the name typed has
// none ("lesson1" with "PDF (*.pdf)" chosen is lesson1.pdf), and one question before files the
// dialog did not confirm are replaced (a report's companion CSV, a table's further tables, the
// files of a report folder).
#pragma once

#include <QString>
#include <QStringList>

class QWidget;

namespace pat::ui {

/// `path` with the first suffix of `selected_filter` ("PDF (*.pdf)" → ".pdf") appended when its
/// file name has none of the suffixes `filters` offers (all the dialog's, ";;"-separated; "plots
/// v2.1" has none, "plots.svg" keeps its own when SVG is offered); otherwise `path` unchanged.
QString with_filter_suffix(const QString& path, const QString& selected_filter,
                           const QString& filters);

/// QFileDialog::getSaveFileName, then with_filter_suffix; a suffix added that names an existing
/// file (which the dialog did not ask about) is confirmed. Empty when cancelled.
QString ask_save_path(QWidget* parent, const QString& title, const QString& start,
                      const QString& filter);

/// A title as part of a file name: lower case, every run of other characters than letters and
/// digits one '_' ("Hammer speed at the strike" → "hammer_speed_at_the_strike").
QString file_stem(const QString& title);

/// The files among `paths` that exist.
QStringList existing_files(const QStringList& paths);

/// True when none of `paths` exists, or the user agrees to replace those that do (one question
/// listing them).
bool confirm_replacing(QWidget* parent, const QStringList& paths);

/// True when `folder` is empty or missing, or the user agrees to write into it (files of the same
/// names are replaced).
bool confirm_writing_into(QWidget* parent, const QString& folder);

}  // namespace pat::ui

#include "save_paths.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QRegularExpression>

namespace pat::ui {

QString with_filter_suffix(const QString& path, const QString& selected_filter,
                           const QString& filters) {
  if (path.isEmpty()) return path;
  static const QRegularExpression pattern(R"(\*\.([A-Za-z0-9]+))");
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (!suffix.isEmpty()) {
    for (auto it = pattern.globalMatch(filters); it.hasNext();)
      if (it.next().captured(1).toLower() == suffix) return path;  // a format offered
  }
  const QRegularExpressionMatch match = pattern.match(selected_filter);
  if (!match.hasMatch()) return path;  // "All files (*)": the name as typed
  return path + "." + match.captured(1);
}

QString ask_save_path(QWidget* parent, const QString& title, const QString& start,
                      const QString& filter) {
  QString selected;
  const QString chosen = QFileDialog::getSaveFileName(parent, title, start, filter, &selected);
  if (chosen.isEmpty()) return {};
  const QString path = with_filter_suffix(chosen, selected.isEmpty() ? filter : selected, filter);
  if (path != chosen && !confirm_replacing(parent, {path})) return {};
  return path;
}

QString file_stem(const QString& title) {
  QString stem;
  for (const QChar c : title.toLower()) stem += c.isLetterOrNumber() ? c : QChar('_');
  while (stem.contains("__")) stem.replace("__", "_");
  while (stem.startsWith('_')) stem.remove(0, 1);
  while (stem.endsWith('_')) stem.chop(1);
  return stem;
}

QStringList existing_files(const QStringList& paths) {
  QStringList existing;
  for (const QString& p : paths)
    if (QFileInfo::exists(p)) existing << p;
  return existing;
}

bool confirm_replacing(QWidget* parent, const QStringList& paths) {
  const QStringList existing = existing_files(paths);
  if (existing.isEmpty()) return true;
  QStringList names;
  for (const QString& p : existing) names << QFileInfo(p).fileName();
  const QString question = names.size() == 1
                               ? QObject::tr("%1 already exists. Replace it?").arg(names.front())
                               : QObject::tr("These %1 files already exist:\n%2\n\nReplace them?")
                                     .arg(names.size())
                                     .arg(names.join("\n"));
  return QMessageBox::question(parent, QObject::tr("Replace files?"), question) == QMessageBox::Yes;
}

bool confirm_writing_into(QWidget* parent, const QString& folder) {
  const QDir dir(folder);
  if (!dir.exists() || dir.isEmpty()) return true;
  return QMessageBox::question(
             parent, QObject::tr("Write into this folder?"),
             QObject::tr("%1 already holds files; those with the report's names "
                         "(the JSON, the CSVs and the plots) will be replaced.\n\n"
                         "Write the report there?")
                 .arg(folder)) == QMessageBox::Yes;
}

}  // namespace pat::ui

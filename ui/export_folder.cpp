#include "export_folder.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace pat::ui {

QString export_folder() {
  const QString remembered = QSettings().value("export_folder").toString();
  if (!remembered.isEmpty() && QFileInfo(remembered).isDir()) return remembered;
  const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  if (!documents.isEmpty() && QFileInfo(documents).isDir()) return documents;
  return QDir::homePath();
}

QString export_path(const QString& file) {
  return file.isEmpty() ? export_folder() : QDir(export_folder()).filePath(file);
}

void remember_export_folder(const QString& exported_path) {
  const QFileInfo info(exported_path);
  QSettings().setValue("export_folder",
                       info.isDir() ? info.absoluteFilePath() : info.absolutePath());
}

}  // namespace pat::ui

// Where the window's export dialogs open: the folder last exported to (remembered in the
// settings), else the user's documents folder, else home; never the program's working directory
// (started from a build tree, that put a class's reports among the sources).
#pragma once

#include <QString>

namespace pat::ui {

/// The folder to open an export dialog in.
QString export_folder();
/// `file` in export_folder() (a suggested name; an empty name gives the folder alone).
QString export_path(const QString& file);
/// Remembers the folder of `exported_path`, a file just written (or the folder itself, for a
/// report written into a folder).
void remember_export_folder(const QString& exported_path);

}  // namespace pat::ui

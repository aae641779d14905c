#include "gui_application.h"

#include <unistd.h>

#include <QApplication>
#include <QDir>
#include <QFile>

namespace pat::ui {

std::unique_ptr<QApplication> application_if_none() {
  if (QApplication::instance()) return nullptr;
  // a command run outside a desktop session (ssh, cron, CI) has no XDG_RUNTIME_DIR, and Qt
  // warns about it on every --plot; the folder it would fall back to, made private as Qt wants
  // it, is set instead
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    const QString runtime = QDir::tempPath() + "/runtime-" + QString::number(::getuid());
    if (QDir().mkpath(runtime) &&
        QFile::setPermissions(
            runtime, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner))
      qputenv("XDG_RUNTIME_DIR", runtime.toLocal8Bit());
  }
  // QApplication keeps argc and argv by reference: they must outlive it
  static int argc = 1;
  static char name[] = "pianoaction";
  static char* argv[] = {name, nullptr};
  return std::make_unique<QApplication>(argc, argv);
}

}  // namespace pat::ui

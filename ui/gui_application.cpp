#include "gui_application.h"

#include <QApplication>

namespace pat::ui {

std::unique_ptr<QApplication> application_if_none() {
  if (QApplication::instance()) return nullptr;
  // QApplication keeps argc and argv by reference: they must outlive it
  static int argc = 1;
  static char name[] = "pianoaction";
  static char* argv[] = {name, nullptr};
  return std::make_unique<QApplication>(argc, argv);
}

}  // namespace pat::ui

// A QApplication for the code paths that run without the window's main() (the command line's
// --plot exports, bench --window).
#pragma once

#include <memory>

class QApplication;

namespace pat::ui {

/// A new QApplication when none runs (the caller keeps it for as long as it needs Qt), else
/// null. Set QT_QPA_PLATFORM before the call to choose the platform.
std::unique_ptr<QApplication> application_if_none();

}  // namespace pat::ui

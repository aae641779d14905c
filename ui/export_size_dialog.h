// Asks for the export size (pixels; points for PDF) of plot exports.
#pragma once

#include <QSize>

class QWidget;

namespace pat::ui {

/// Shows a small modal dialog (from a menu, never from a timer); returns `current` if cancelled.
QSize ask_export_size(QWidget* parent, QSize current);

}  // namespace pat::ui

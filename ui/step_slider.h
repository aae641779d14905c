// A slider for adjuster moves: it keeps the arrow, page and Home/End keys when it has the focus
// (the window's Left/Right shortcuts step the simulation otherwise, so a focused slider could
// not be moved 0.01 mm from the keyboard), and ignores the mouse wheel unless it has the focus
// (FocusWheel), so that scrolling a panel past it does not move an adjuster.
#pragma once

#include <QKeyEvent>
#include <QSlider>

#include "focus_wheel.h"

namespace pat::ui {

class StepSlider : public FocusWheel<QSlider> {
 public:
  explicit StepSlider(Qt::Orientation orientation, QWidget* parent = nullptr)
      : FocusWheel<QSlider>(parent) {
    setOrientation(orientation);
  }

 protected:
  bool event(QEvent* e) override {
    if (e->type() == QEvent::ShortcutOverride) {
      switch (static_cast<QKeyEvent*>(e)->key()) {
        case Qt::Key_Left:
        case Qt::Key_Right:
        case Qt::Key_Up:
        case Qt::Key_Down:
        case Qt::Key_PageUp:
        case Qt::Key_PageDown:
        case Qt::Key_Home:
        case Qt::Key_End:
          e->accept();  // the key press then comes to this slider, not to a shortcut
          return true;
        default:
          break;
      }
    }
    return QSlider::event(e);
  }
};

}  // namespace pat::ui

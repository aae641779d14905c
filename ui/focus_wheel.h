// A widget that takes the mouse wheel only when it has the focus (clicked or tabbed to): a wheel
// turned to scroll a panel past a combo box or spin box leaves its choice alone and scrolls the
// panel instead (a practice answer changed under a passing wheel).
#pragma once

#include <QWheelEvent>

namespace pat::ui {

template <class Widget>
class FocusWheel : public Widget {
 public:
  explicit FocusWheel(QWidget* parent = nullptr) : Widget(parent) {
    this->setFocusPolicy(Qt::StrongFocus);  // a wheel alone does not give the focus
  }

 protected:
  void wheelEvent(QWheelEvent* e) override {
    if (this->hasFocus())
      Widget::wheelEvent(e);
    else
      e->ignore();  // to the scroll area around it
  }
};

}  // namespace pat::ui

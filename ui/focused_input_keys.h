// Keys a focused input needs are not taken by the window's single-key shortcuts (Space strikes,
// 1–5 strike pp to ff, P plays, Left/Right step, Home rewinds): a combo box opens on Space and
// finds its items by typed letters and digits, a spin box or text field takes what is typed and
// moves its cursor, a list, table, tab bar, slider or text view moves with the arrows and Home.
// Buttons keep the shortcuts (a teacher clicks Strike, then strikes on with the space bar).
// One filter on the application sees every ShortcutOverride before the shortcut map does.
#pragma once

#include <QObject>

class QKeyEvent;
class QWidget;

namespace pat::ui {

class FocusedInputKeys : public QObject {
 public:
  explicit FocusedInputKeys(QObject* parent = nullptr) : QObject(parent) {}

  /// True if `focused` uses `key` itself (a key of the window's shortcuts, no Ctrl or Alt).
  static bool keeps(const QWidget* focused, const QKeyEvent& key);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace pat::ui

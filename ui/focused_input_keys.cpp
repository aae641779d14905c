#include "focused_input_keys.h"

#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QTextEdit>

namespace pat::ui {

bool FocusedInputKeys::keeps(const QWidget* focused, const QKeyEvent& key) {
  if (!focused || (key.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)))
    return false;
  const int k = key.key();
  const bool arrow_or_home = k == Qt::Key_Left || k == Qt::Key_Right || k == Qt::Key_Home;
  const bool typed = k == Qt::Key_Space || k == Qt::Key_P || (k >= Qt::Key_0 && k <= Qt::Key_9);
  if (!arrow_or_home && !typed) return false;  // not a key of the window's shortcuts
  // text is typed and edited there
  if (qobject_cast<const QLineEdit*>(focused) || qobject_cast<const QAbstractSpinBox*>(focused))
    return true;
  // Space opens the list, letters and digits find an item (arrows move through it without them)
  if (qobject_cast<const QComboBox*>(focused)) return typed || k == Qt::Key_Home;
  // lists and tables: arrows, Home, Space (a check box in a row), keyboard search
  if (qobject_cast<const QAbstractItemView*>(focused)) return true;
  // moved with the arrows and Home
  if (qobject_cast<const QAbstractSlider*>(focused) || qobject_cast<const QTabBar*>(focused) ||
      qobject_cast<const QPlainTextEdit*>(focused) || qobject_cast<const QTextEdit*>(focused))
    return arrow_or_home;
  return false;
}

bool FocusedInputKeys::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride && watched->isWidgetType() &&
      keeps(static_cast<QWidget*>(watched), *static_cast<QKeyEvent*>(event))) {
    event->accept();  // the key press then goes to the focused widget, not to a shortcut
    return true;
  }
  return QObject::eventFilter(watched, event);
}

}  // namespace pat::ui

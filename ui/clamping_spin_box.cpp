#include "clamping_spin_box.h"

#include <algorithm>

namespace pat::ui {

ClampingSpinBox::ClampingSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
  setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
}

bool ClampingSpinBox::read_number(const QString& text, double& value) const {
  QString number = text;
  if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
  if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
  bool ok = false;
  value = locale().toDouble(number.trimmed(), &ok);
  return ok;
}

QValidator::State ClampingSpinBox::validate(QString& text, int& position) const {
  const QValidator::State state = QDoubleSpinBox::validate(text, position);
  if (state != QValidator::Invalid) return state;
  double value = 0.0;
  // a number beyond the range: kept while typed, brought within it when entered
  return read_number(text, value) ? QValidator::Intermediate : QValidator::Invalid;
}

void ClampingSpinBox::fixup(QString& text) const {
  double value = 0.0;
  if (read_number(text, value)) {
    text = textFromValue(std::clamp(value, minimum(), maximum()));
    return;
  }
  QDoubleSpinBox::fixup(text);
}

double ClampingSpinBox::valueFromText(const QString& text) const {
  double value = 0.0;
  if (read_number(text, value)) return std::clamp(value, minimum(), maximum());
  return QDoubleSpinBox::valueFromText(text);
}

}  // namespace pat::ui

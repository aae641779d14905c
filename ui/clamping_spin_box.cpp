#include "clamping_spin_box.h"

#include <QRegularExpression>
#include <algorithm>
#include <cmath>

namespace pat::ui {

ClampingSpinBox::ClampingSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {}

bool ClampingSpinBox::read_number(const QString& text, double& value) const {
  QString number = text;
  if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
  if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
  number = number.trimmed();
  // a plain number as the field writes them: a sign, digits, the locale's decimal point and at
  // most the field's decimals (no exponent, no group separators: "1e3" or "3,5" read as 1000 or
  // 35 would throw the adjuster to the end of its travel)
  const QRegularExpression plain(QStringLiteral("^[+\\-]?\\d+(%1\\d{0,%2})?$")
                                     .arg(QRegularExpression::escape(locale().decimalPoint()))
                                     .arg(decimals()));
  if (!plain.match(number).hasMatch()) return false;
  bool ok = false;
  value = locale().toDouble(number, &ok);
  return ok && std::isfinite(value);
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
  // a number beyond the range goes to its nearest end; anything else (an emptied field, a lone
  // sign) back to the value the field had, as QDoubleSpinBox does
  text = textFromValue(read_number(text, value) ? std::clamp(value, minimum(), maximum())
                                                : this->value());
}

}  // namespace pat::ui

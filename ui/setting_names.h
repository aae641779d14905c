// Names of the regulation settings and their adjusters as a class reads them: "let-off", not
// the preset's identifier "let_off"; the part an adjuster turns ("let-off button"), the head of
// its description before the ':' that says which way is positive.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <cmath>
#include <string>

#include "model/action_model.h"

namespace pat::ui {

/// "key_dip" → "key dip", "let_off" → "let-off" (the technicians' spelling).
inline QString setting_title(const std::string& name) {
  return QString::fromStdString(setting_words(name));
}

/// A setting's reading with its unit, as the regulation panel shows it: millimetres to 0.01 mm,
/// a fraction (the upright's damper lift: of the hammer's travel) as a percentage to 0.1 %, a
/// value that rounds to zero without a sign, and "no reading" where there is none (NaN).
inline QString setting_value_text(double value, const std::string& unit) {
  if (!std::isfinite(value)) return QObject::tr("no reading");
  const bool fraction = unit == "fraction";
  if (fraction) value *= 100.0;
  const int decimals = fraction ? 1 : 2;
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
  const QString number = QString::number(value, 'f', decimals);
  return number + " " + (fraction ? QStringLiteral("%") : QString::fromStdString(unit));
}

/// An adjuster's offset (mm) to `decimals` places, one that rounds to zero without a sign;
/// `plus`: a positive one with its "+".
inline QString adjuster_mm_text(double mm, int decimals, bool plus = false) {
  if (std::abs(mm) < 0.5 * std::pow(10.0, -decimals)) mm = 0.0;
  return (plus && mm > 0.0 ? QStringLiteral("+") : QString()) + QString::number(mm, 'f', decimals);
}

/// The part the adjuster turns, from its description ("let-off button: + screws it down …" →
/// "let-off button"); empty when the description has no such head.
inline QString adjuster_part(const Adjuster& adjuster) {
  return QString::fromStdString(adjuster_part_words(adjuster.description));
}

/// The adjusters turned from regulation as a class reads them, "hammer blow +1.25 mm, let-off
/// -0.50 mm" (to 0.01 mm; a turn that rounds to zero, such as automatic regulation's few
/// micrometres, left out), or "as regulated".
inline QString adjuster_settings_words(const ActionModel& model) {
  QStringList turned;
  for (const Adjuster& a : model.adjusters)
    if (const QString mm = adjuster_mm_text(a.value * 1e3, 2, true); mm != QStringLiteral("0.00"))
      turned << setting_title(a.name) + " " + mm + " mm";
  return turned.isEmpty() ? QObject::tr("as regulated") : turned.join(", ");
}

}  // namespace pat::ui

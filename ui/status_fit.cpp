#include "status_fit.h"

#include <QObject>

namespace pat::ui {

QString fit_status(const QStringList& wordings, const QFontMetricsF& metrics, double width_px) {
  if (wordings.isEmpty()) return {};
  for (const QString& wording : wordings)
    if (metrics.horizontalAdvance(wording) <= width_px) return wording;
  return metrics.elidedText(wordings.back(), Qt::ElideRight, width_px);
}

QStringList run_status_wordings(const QString& state, const QString& action, const QString& input,
                                const QString& hint) {
  const auto with_hint = [&](const QString& text) {
    return hint.isEmpty() ? text : QObject::tr("%1: %2").arg(text, hint);
  };
  // a hint follows a colon, so the action and input go in parentheses; without one they read on
  // ("Running Upright action with a 20 N blow held 40 ms")
  if (hint.isEmpty())
    return {QObject::tr("%1 %2 with %3").arg(state, action, input),
            QObject::tr("%1 with %2").arg(state, input), state};
  return {with_hint(QObject::tr("%1 (%2 with %3)").arg(state, action, input)),
          with_hint(QObject::tr("%1 (with %2)").arg(state, input)), with_hint(state), state};
}

}  // namespace pat::ui

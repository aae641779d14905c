// A status-line message fitted to the width it has: of the same message worded at decreasing
// lengths (the full one first), the first that fits, else the shortest elided at its end. With
// the class's larger text a run's status ("Paused at t = … (Grand action (double escapement)
// with a 20 N blow held 40 ms): Play or P goes on, …") was cut in the middle of a word.
#pragma once

#include <QFontMetricsF>
#include <QString>
#include <QStringList>

namespace pat::ui {

/// The first of `wordings` whose width in `metrics` is at most `width_px`; when none is, the last
/// one elided on the right to `width_px`. Empty `wordings`: an empty string.
QString fit_status(const QStringList& wordings, const QFontMetricsF& metrics, double width_px);

/// The wordings of a run's status: "STATE (ACTION with INPUT): HINT", then without the action's
/// name, then the state and the hint alone, then the state alone. Without a hint: "STATE ACTION
/// with INPUT", "STATE with INPUT", then the state alone.
QStringList run_status_wordings(const QString& state, const QString& action, const QString& input,
                                const QString& hint);

}  // namespace pat::ui

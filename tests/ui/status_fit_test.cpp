// A run's status line worded to fit its width (ui/status_fit.h): the full wording where it
// fits, then shorter ones in order, and the shortest elided only when nothing else fits.
#include "status_fit.h"

#include <QFont>
#include <QTest>

using pat::ui::fit_status;
using pat::ui::run_status_wordings;

class StatusFitTest : public QObject {
  Q_OBJECT
 private slots:
  void wordings_drop_the_action_then_the_input_then_the_hint() {
    const QStringList wordings =
        run_status_wordings("Paused at t = 18.02 ms", "Grand action (double escapement)",
                            "a 20 N blow held 40 ms", "Play or P goes on");
    QCOMPARE(wordings,
             (QStringList{"Paused at t = 18.02 ms (Grand action (double escapement) with a 20 N "
                          "blow held 40 ms): Play or P goes on",
                          "Paused at t = 18.02 ms (with a 20 N blow held 40 ms): Play or P goes on",
                          "Paused at t = 18.02 ms: Play or P goes on", "Paused at t = 18.02 ms"}));
    // no hint: no colon, and no parentheses
    QCOMPARE(run_status_wordings("Running", "Upright action", "an 8 N blow held 80 ms", ""),
             (QStringList{"Running Upright action with an 8 N blow held 80 ms",
                          "Running with an 8 N blow held 80 ms", "Running"}));
  }

  void the_longest_wording_that_fits_is_shown() {
    const QFontMetricsF metrics{QFont()};
    const QStringList wordings = run_status_wordings(
        "Paused at t = 18.02 ms", "Grand action (double escapement)", "a 20 N blow held 40 ms",
        "Play or P goes on, Step and Step back move one frame, ten with Shift");
    for (int i = 0; i < wordings.size(); ++i) {
      const double width = metrics.horizontalAdvance(wordings[i]);
      // exactly its own width: that wording; a pixel less: the next one
      QCOMPARE(fit_status(wordings, metrics, width), wordings[i]);
      if (i + 1 < wordings.size())
        QCOMPARE(fit_status(wordings, metrics, width - 1.0), wordings[i + 1]);
    }
    // narrower than the shortest: the shortest, elided within the width
    const double narrow = 0.5 * metrics.horizontalAdvance(wordings.back());
    const QString elided = fit_status(wordings, metrics, narrow);
    QVERIFY2(elided.endsWith(QChar(0x2026)) && elided.startsWith("Paused"), qPrintable(elided));
    QVERIFY(metrics.horizontalAdvance(elided) <= narrow);
    QCOMPARE(fit_status({}, metrics, 100.0), QString());
  }
};

QTEST_MAIN(StatusFitTest)
#include "status_fit_test.moc"

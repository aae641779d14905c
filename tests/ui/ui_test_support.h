// Shared helpers of the window tests: waiting on the event loop for a condition.
#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTest>
#include <functional>

namespace pat::ui::test {

/// Runs the event loop until `done` holds or `timeout_ms` passes; returns whether it held.
inline bool wait_until(const std::function<bool()>& done, int timeout_ms = 20000) {
  QElapsedTimer timer;
  timer.start();
  while (!done()) {
    if (timer.elapsed() > timeout_ms) return false;
    QTest::qWait(5);
  }
  return true;
}

}  // namespace pat::ui::test

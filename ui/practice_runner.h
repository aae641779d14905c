// The practice mode's background work: a technician's test run on the hidden action and on the
// regulated one (for the comparison), and the measurements the final score needs — both in a
// worker thread (QtConcurrent), with progress and cancel, so the window never freezes.
#pragma once

#include <QFuture>
#include <QMetaObject>
#include <QObject>
#include <QString>
#include <atomic>
#include <exception>
#include <map>
#include <memory>
#include <vector>

#include "practice/observations.h"
#include "practice/session.h"

namespace pat::ui {

class PracticeRunner : public QObject {
  Q_OBJECT
 public:
  explicit PracticeRunner(QObject* parent = nullptr);
  ~PracticeRunner() override;

  /// Runs `test` on `hidden` and (once per exercise, then cached) on `regulated`.
  void observe(std::shared_ptr<const ActionModel> hidden,
               std::shared_ptr<const ActionModel> regulated, PracticeTest test);
  /// Measures the settings the score needs (measure_corrections) on a copy of `session`.
  void measure(const PracticeSession& session);
  /// Forgets the regulated action's cached observations (a new exercise), and the results of any
  /// run started before: one already finished but not yet delivered (its signal queued for the
  /// window's thread) is dropped, so that it cannot reach the new exercise. Call after cancel()
  /// and wait().
  void reset_cache();
  void cancel() { cancelled_.store(true); }
  bool running() const { return running_; }
  void wait() { future_.waitForFinished(); }

 signals:
  void progress(double fraction, const QString& stage);
  void observed(int test, const std::vector<pat::Observation>& seen,
                const std::vector<pat::Observation>& regulated);
  void measured(const std::vector<pat::CorrectionReading>& readings);
  /// A failure or a cancel: the reason.
  void failed(const QString& reason);

 private:
  /// From a worker: `result` (which emits the run's signal) runs in the window's thread, always
  /// queued, with the run marked over, unless the run's exercise (`generation`) was left behind.
  template <class Result>
  void deliver(int generation, Result result) {
    QMetaObject::invokeMethod(
        this,
        [this, generation, result] {
          if (generation != generation_) return;  // an exercise left behind: dropped
          running_ = false;
          result();
        },
        Qt::QueuedConnection);
  }
  /// deliver()s failed(error's message).
  void report_failure(int generation, const std::exception& error);

  std::atomic<bool> cancelled_{false};
  bool running_ = false;
  int generation_ = 0;  ///< of the exercise the runs are for (reset_cache() starts a new one)
  QFuture<void> future_;
  std::map<int, std::vector<Observation>> regulated_cache_;  ///< used in the window thread only
};

}  // namespace pat::ui

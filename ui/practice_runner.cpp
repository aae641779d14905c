#include "practice_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "background_pool.h"

namespace pat::ui {

PracticeRunner::PracticeRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<std::vector<pat::Observation>>();
  qRegisterMetaType<std::vector<pat::CorrectionReading>>();
}

PracticeRunner::~PracticeRunner() {
  cancelled_.store(true);
  future_.waitForFinished();
}

void PracticeRunner::reset_cache() {
  ++generation_;
  regulated_cache_.clear();
  if (future_.isFinished()) running_ = false;  // a queued delivery would have said so
}

void PracticeRunner::observe(std::shared_ptr<const ActionModel> hidden,
                             std::shared_ptr<const ActionModel> regulated, PracticeTest test) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  const int key = static_cast<int>(test);
  const int generation = generation_;
  const auto cached = regulated_cache_.find(key);
  const bool have_regulated = cached != regulated_cache_.end();
  std::vector<Observation> regulated_seen =
      have_regulated ? cached->second : std::vector<Observation>{};
  // its results come back through the window's event queue (queued even when the wait() of a
  // new exercise runs a task not yet started in the window's own thread): never inside a call
  future_ = QtConcurrent::run(background_pool(), [this, hidden, regulated, test, key, generation,
                                                  have_regulated, regulated_seen]() mutable {
    const QString stage = QString::fromStdString(test_name(test));
    const int runs = have_regulated ? 1 : 2;
    int run_index = 0;
    double last_sent = -1.0;
    // the engine reports every step (tens of thousands in a forte blow): the window hears of
    // each whole percent only, so its event queue never floods
    ProgressReporter reporter(
        [this, stage, &run_index, &last_sent, runs, generation](double f, const std::string&) {
          const double overall = (run_index + f) / runs;
          if (overall - last_sent >= 0.01) {
            last_sent = overall;
            QMetaObject::invokeMethod(
                this,
                [this, overall, stage, generation] {
                  // an exercise left behind: its stage is not the new one's
                  if (generation == generation_) emit progress(overall, stage);
                },
                Qt::QueuedConnection);
          }
          return !cancelled_.load();
        },
        1);
    try {
      std::vector<Observation> seen = run_test(*hidden, find_rest_state(*hidden), test, &reporter);
      if (!have_regulated) {
        run_index = 1;
        regulated_seen = run_test(*regulated, find_rest_state(*regulated), test, &reporter);
      }
      if (cancelled_.load()) throw Cancelled();
      deliver(generation, [this, key, seen, regulated_seen] {
        regulated_cache_[key] = regulated_seen;
        emit observed(key, seen, regulated_seen);
      });
    } catch (const std::exception& e) {
      report_failure(generation, e);
    }
  });
}

void PracticeRunner::report_failure(int generation, const std::exception& error) {
  const QString reason = QString::fromStdString(error.what());
  deliver(generation, [this, reason] { emit failed(reason); });
}

void PracticeRunner::measure(const PracticeSession& session) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  auto copy = std::make_shared<PracticeSession>(session);
  const int generation = generation_;
  future_ = QtConcurrent::run(background_pool(), [this, copy, generation] {
    try {
      QMetaObject::invokeMethod(
          this,
          [this, generation] {
            if (generation == generation_) emit progress(0.0, tr("measuring"));
          },
          Qt::QueuedConnection);
      std::vector<CorrectionReading> readings = measure_corrections(*copy);
      if (cancelled_.load()) throw Cancelled();
      deliver(generation, [this, readings] { emit measured(readings); });
    } catch (const std::exception& e) {
      report_failure(generation, e);
    }
  });
}

}  // namespace pat::ui

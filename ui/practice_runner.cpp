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
  regulated_cache_.clear();
}

void PracticeRunner::observe(std::shared_ptr<const ActionModel> hidden,
                             std::shared_ptr<const ActionModel> regulated, PracticeTest test) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  const int key = static_cast<int>(test);
  const auto cached = regulated_cache_.find(key);
  const bool have_regulated = cached != regulated_cache_.end();
  std::vector<Observation> regulated_seen =
      have_regulated ? cached->second : std::vector<Observation>{};
  future_ = QtConcurrent::run(background_pool(), [this, hidden, regulated, test, key,
                                                  have_regulated, regulated_seen]() mutable {
    const QString stage = QString::fromStdString(test_name(test));
    const int runs = have_regulated ? 1 : 2;
    int run_index = 0;
    double last_sent = -1.0;
    // the engine reports every step (tens of thousands in a forte blow): the window hears of
    // each whole percent only, so its event queue never floods
    ProgressReporter reporter(
        [this, stage, &run_index, &last_sent, runs](double f, const std::string&) {
          const double overall = (run_index + f) / runs;
          if (overall - last_sent >= 0.01) {
            last_sent = overall;
            QMetaObject::invokeMethod(this,
                                      [this, overall, stage] { emit progress(overall, stage); });
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
      QMetaObject::invokeMethod(this, [this, key, seen, regulated_seen] {
        running_ = false;
        regulated_cache_[key] = regulated_seen;
        emit observed(key, seen, regulated_seen);
      });
    } catch (const std::exception& e) {
      const QString reason = QString::fromStdString(e.what());
      QMetaObject::invokeMethod(this, [this, reason] {
        running_ = false;
        emit failed(reason);
      });
    }
  });
}

void PracticeRunner::measure(const PracticeSession& session) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  auto copy = std::make_shared<PracticeSession>(session);
  future_ = QtConcurrent::run(background_pool(), [this, copy] {
    try {
      QMetaObject::invokeMethod(this, [this] { emit progress(0.0, tr("measuring")); });
      std::vector<CorrectionReading> readings = measure_corrections(*copy);
      if (cancelled_.load()) throw Cancelled();
      QMetaObject::invokeMethod(this, [this, readings] {
        running_ = false;
        emit measured(readings);
      });
    } catch (const std::exception& e) {
      const QString reason = QString::fromStdString(e.what());
      QMetaObject::invokeMethod(this, [this, reason] {
        running_ = false;
        emit failed(reason);
      });
    }
  });
}

}  // namespace pat::ui

#include "analysis_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>
#include <memory>
#include <mutex>

#include "background_pool.h"

namespace pat::ui {

AnalysisRunner::AnalysisRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<pat::ui::AnalysisResult>();
}

AnalysisRunner::~AnalysisRunner() {
  cancel_requested_.store(true);
  future_.waitForFinished();
}

void AnalysisRunner::start(const QString& title, AnalysisTask task) {
  if (running_) return;
  running_ = true;
  cancel_requested_.store(false);
  // its deliveries are queued even when the task runs on this thread (one not yet started runs
  // inside waitForFinished, the destructor's): called directly, they reached a window being
  // taken down
  future_ = QtConcurrent::run(background_pool(), [this, title, task = std::move(task)] {
    // the task may report from several threads (parallel runs): throttle under a lock
    auto throttle = std::make_shared<std::pair<std::mutex, QElapsedTimer>>();
    throttle->second.start();
    const ProgressCallback report = [this, throttle](double fraction, const std::string& stage) {
      // cancelled: no more progress (queued after the panel's "cancelling…", it had said "5 of
      // 15" again, as if the cancel had not been heard)
      if (cancel_requested_.load()) return false;
      {
        std::lock_guard<std::mutex> lock(throttle->first);
        if (throttle->second.elapsed() >= 30 || fraction >= 1.0) {
          throttle->second.restart();
          const QString text = QString::fromStdString(stage);
          QMetaObject::invokeMethod(
              this,
              [this, fraction, text] {
                if (!cancel_requested_.load()) emit progress(fraction, text);
              },
              Qt::QueuedConnection);
        }
      }
      return !cancel_requested_.load();
    };
    try {
      AnalysisResult result = task(report);
      QMetaObject::invokeMethod(
          this,
          [this, title, result = std::move(result)] {
            running_ = false;
            emit finished(title, result);
          },
          Qt::QueuedConnection);
    } catch (const Cancelled&) {
      QMetaObject::invokeMethod(
          this,
          [this, title] {
            running_ = false;
            emit cancelled(title);
          },
          Qt::QueuedConnection);
    } catch (const std::exception& e) {
      const QString message = QString::fromStdString(e.what());
      QMetaObject::invokeMethod(
          this,
          [this, title, message] {
            running_ = false;
            emit failed(title, message);
          },
          Qt::QueuedConnection);
    }
  });
}

}  // namespace pat::ui

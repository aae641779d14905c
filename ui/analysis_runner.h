// Runs one analysis at a time off the window's thread (QtConcurrent). Progress reaches the
// window through queued calls, at most a few dozen times a second; cancel() makes the task's
// progress callback return false, and the task stops at its next report.
#pragma once

#include <QElapsedTimer>
#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>

#include "analysis_result.h"

namespace pat::ui {

class AnalysisRunner : public QObject {
  Q_OBJECT
 public:
  explicit AnalysisRunner(QObject* parent = nullptr);
  /// Cancels a running task and waits for it (the task must not outlive the window).
  ~AnalysisRunner() override;

  /// Starts `task`; ignored while another one runs (the panel disables Run meanwhile).
  void start(const QString& title, AnalysisTask task);
  void cancel() { cancel_requested_.store(true); }
  bool running() const { return running_; }
  /// True once the task's thread has returned (running() turns false a moment earlier, when
  /// the result reaches the window's thread).
  bool task_finished() const { return future_.isFinished(); }
  void wait() { future_.waitForFinished(); }

 signals:
  void progress(double fraction, const QString& stage);
  void finished(const QString& title, const pat::ui::AnalysisResult& result);
  void cancelled(const QString& title);
  void failed(const QString& title, const QString& message);

 private:
  std::atomic<bool> cancel_requested_{false};
  bool running_ = false;
  QFuture<void> future_;
};

}  // namespace pat::ui

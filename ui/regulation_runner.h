// "Regulate automatically" from the window: regulate() in a background thread, each step
// reported as it is made (for the panel's log), cancellable, the regulated model handed back.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>

#include "regulation/regulation.h"

namespace pat::ui {

class RegulationRunner : public QObject {
  Q_OBJECT
 public:
  explicit RegulationRunner(QObject* parent = nullptr);
  ~RegulationRunner() override;

  void start(std::shared_ptr<const ActionModel> model);
  /// Stops after the step in progress; finished() follows.
  void cancel() { cancelled_.store(true); }
  bool running() const { return running_; }
  /// Waits for the background work (tests).
  void wait() { future_.waitForFinished(); }

 signals:
  /// One adjustment made: a line for the log.
  void stepDone(const QString& line);
  /// The result (the model with the adjusters found, even when it did not converge).
  void finished(std::shared_ptr<const pat::ActionModel> model, bool converged,
                const QString& message);

 private:
  std::atomic<bool> cancelled_{false};
  bool running_ = false;
  QFuture<void> future_;
};

}  // namespace pat::ui

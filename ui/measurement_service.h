// Live measured values for the regulation panel: every setting of a model measured the way a
// technician measures it (measure_setting, tens of milliseconds each for the slow press and
// the forte blow), in a background thread. A newer request supersedes the one running: its
// remaining settings are skipped and the newer model is measured next.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <memory>
#include <mutex>

#include "model/action_model.h"

namespace pat::ui {

class MeasurementService : public QObject {
  Q_OBJECT
 public:
  explicit MeasurementService(QObject* parent = nullptr);
  ~MeasurementService() override;

  /// Measures every setting of `model` (after the running request stops).
  void request(std::shared_ptr<const ActionModel> model);
  bool busy() const;

 signals:
  /// A setting measured on the latest requested model (its unit); `note`: how it was read when
  /// not as the action stands (SettingReading::note), else empty.
  void measured(const QString& setting, double value, const QString& note);
  /// A setting that could not be measured; the reason from the engine.
  void failed(const QString& setting, const QString& reason);
  /// Every setting of the latest model measured.
  void finished();

 private:
  void start_next();
  void run(std::shared_ptr<const ActionModel> model, int generation);

  std::atomic<int> generation_{0};
  std::mutex mutex_;
  std::shared_ptr<const ActionModel> pending_;
  bool running_ = false;
  /// One thread of its own, run at a lower priority (nice 10) than the window and the simulation
  /// worker; a pool of its own so that the shared pool's threads keep their priority.
  QThreadPool pool_;
  QFuture<void> future_;
};

}  // namespace pat::ui

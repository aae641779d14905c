#include "measurement_service.h"

#include <QMetaObject>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "regulation/measurements.h"

namespace pat::ui {

MeasurementService::MeasurementService(QObject* parent) : QObject(parent) {
  pool_.setMaxThreadCount(1);
}

MeasurementService::~MeasurementService() {
  generation_.store(-1000000);  // the running job stops after its current measurement
  future_.waitForFinished();
}

bool MeasurementService::busy() const {
  return running_;
}

void MeasurementService::request(std::shared_ptr<const ActionModel> model) {
  ++generation_;
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(model);
  }
  if (!running_) start_next();
}

void MeasurementService::start_next() {
  std::shared_ptr<const ActionModel> model;
  {
    std::lock_guard lock(mutex_);
    model.swap(pending_);
  }
  if (!model) {
    running_ = false;
    emit finished();
    return;
  }
  running_ = true;
  const int generation = generation_.load();
  future_ = QtConcurrent::run(&pool_, [this, model, generation] {
    // the live readings yield the cores to the window and the simulation worker (Qt runs an
    // idle-priority thread under SCHED_IDLE on Linux): on two cores they would otherwise delay
    // the event loop by up to 0.2 s. The thread is this service's own: QThread::setPriority
    // cannot bring a thread back from SCHED_IDLE (it keeps the thread's policy), and a shared
    // pool thread left there delayed the window's painting by up to 0.25 s (bench --window)
    QThread::currentThread()->setPriority(QThread::IdlePriority);
    run(model, generation);
  });
}

void MeasurementService::run(std::shared_ptr<const ActionModel> model, int generation) {
  auto current = [&] { return generation_.load() == generation; };
  try {
    const RestState rest = find_rest_state(*model);
    for (const RegulationSetting& setting : model->regulation) {
      if (!current()) break;
      const QString name = QString::fromStdString(setting.name);
      try {
        const double value = measure_setting(*model, setting.name, &rest);
        QMetaObject::invokeMethod(this, [this, name, value, generation] {
          if (generation_.load() == generation) emit measured(name, value);
        });
      } catch (const std::exception& e) {
        const QString reason = QString::fromStdString(e.what());
        QMetaObject::invokeMethod(this, [this, name, reason, generation] {
          if (generation_.load() == generation) emit failed(name, reason);
        });
      }
    }
  } catch (const std::exception& e) {
    const QString reason = QString::fromStdString(e.what());
    QMetaObject::invokeMethod(this, [this, reason, generation] {
      if (generation_.load() == generation) emit failed(QString(), reason);
    });
  }
  // the next request, in the window's thread
  QMetaObject::invokeMethod(this, [this] { start_next(); });
}

}  // namespace pat::ui

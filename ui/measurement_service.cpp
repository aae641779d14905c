#include "measurement_service.h"

#include <QMetaObject>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>
#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "regulation/measurements.h"

namespace pat::ui {
namespace {

// The live readings yield the cores to the window and the simulation worker: on two cores they
// would otherwise delay the event loop by up to 0.2 s. Nice 10 (scheduler weight 110 against
// 1024) rather than SCHED_IDLE: an idle-class thread can wait seconds for a core on a busy
// machine, and if it waits while holding a lock the window needs (Qt's event queue, when it
// posts a reading), the window freezes that long. Raising one's own nice needs no privilege.
void lower_this_threads_priority() {
#ifdef __linux__
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#else
  QThread::currentThread()->setPriority(QThread::LowPriority);
#endif
}

}  // namespace

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
    lower_this_threads_priority();  // a new pool thread after an idle spell starts at nice 0
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
      // as a technician reads it (with the drop screw out of the way where the lever would hide
      // the let-off, which the note says)
      const SettingReading reading = read_setting(*model, setting, &rest);
      if (reading.problem.empty()) {
        const double value = reading.measured;
        const QString note = QString::fromStdString(reading.note);
        QMetaObject::invokeMethod(
            this,
            [this, name, value, note, generation] {
              if (generation_.load() == generation) emit measured(name, value, note);
            },
            Qt::QueuedConnection);
      } else {
        const QString reason = QString::fromStdString(reading.problem);
        QMetaObject::invokeMethod(
            this,
            [this, name, reason, generation] {
              if (generation_.load() == generation) emit failed(name, reason);
            },
            Qt::QueuedConnection);
      }
    }
  } catch (const std::exception& e) {
    const QString reason = QString::fromStdString(e.what());
    QMetaObject::invokeMethod(
        this,
        [this, reason, generation] {
          if (generation_.load() == generation) emit failed(QString(), reason);
        },
        Qt::QueuedConnection);
  }
  // the next request, in the window's thread, always queued: a task the pool had not begun when
  // the window closed runs inside the destructor's waitForFinished, on the window's thread, where
  // a direct call would start another task on the object being destroyed
  QMetaObject::invokeMethod(
      this, [this] { start_next(); }, Qt::QueuedConnection);
}

}  // namespace pat::ui

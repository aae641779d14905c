#include "regulation_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "background_pool.h"
#include "setting_names.h"

namespace pat::ui {

RegulationRunner::RegulationRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<std::shared_ptr<const pat::ActionModel>>();
}

RegulationRunner::~RegulationRunner() {
  cancelled_.store(true);
  future_.waitForFinished();
}

void RegulationRunner::start(std::shared_ptr<const ActionModel> model) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  // its deliveries are queued even when the task runs on this thread (one not yet started runs
  // inside waitForFinished, the destructor's): called directly, they reached a window being
  // taken down
  future_ = QtConcurrent::run(background_pool(), [this, model] {
    RegulationOptions options;
    options.on_step = [this, model](const RegulationStep& s) {
      // as the panel reads: the setting in words, its reading as the panel shows it, the
      // adjuster signed
      std::string unit = "mm";
      for (const RegulationSetting& r : model->regulation)
        if (r.name == s.setting) unit = r.unit;
      const QString line =
          tr("pass %1  %2: adjuster %3 mm → reads %4 (target %5)%6")
              .arg(s.pass)
              .arg(setting_title(s.setting))
              .arg(adjuster_mm_text(s.adjuster_mm, 3, true))
              .arg(setting_value_text(s.measured, unit))
              .arg(setting_value_text(s.target, unit))
              .arg(s.note.empty() ? QString() : " — " + QString::fromStdString(s.note));
      QMetaObject::invokeMethod(
          this, [this, line] { emit stepDone(line); }, Qt::QueuedConnection);
      return !cancelled_.load();
    };
    std::shared_ptr<const ActionModel> result_model = model;
    bool converged = false;
    QString message;
    try {
      RegulationResult result = regulate(*model, options);
      result_model = std::make_shared<const ActionModel>(std::move(result.model));
      converged = result.converged;
      message = cancelled_.load() ? tr("cancelled") : QString::fromStdString(result.message);
      if (converged)
        message = tr("converged in %1 passes (%2 s)")
                      .arg(result.passes)
                      .arg(result.wall_time_s, 0, 'f', 1);
    } catch (const std::exception& e) {
      message = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(
        this,
        [this, result_model, converged, message] {
          running_ = false;
          emit finished(result_model, converged, message);
        },
        Qt::QueuedConnection);
  });
}

}  // namespace pat::ui

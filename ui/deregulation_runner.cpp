#include "deregulation_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>
#include <exception>
#include <map>

#include "background_pool.h"
#include "model/model_edits.h"
#include "sim/simulation.h"

namespace pat::ui {

DeregulationRunner::DeregulationRunner(QObject* parent) : QObject(parent) {}

DeregulationRunner::~DeregulationRunner() {
  cancelled_.store(true);
  future_.waitForFinished();
}

void DeregulationRunner::start(std::shared_ptr<const ActionModel> model,
                               DeregulationOptions options) {
  if (running_) return;
  running_ = true;
  cancelled_.store(false);
  // its deliveries are queued even when the task runs on this thread (one not yet started runs
  // inside waitForFinished, the destructor's): called directly, they reached a window being
  // taken down
  future_ = QtConcurrent::run(background_pool(), [this, model, options]() mutable {
    const double duration = options.duration_s;
    double last_reported = -1.0;
    options.on_progress = [this, duration, &last_reported](double t) {
      if (t - last_reported >= 0.01 * duration) {
        last_reported = t;
        const double fraction = t / duration;
        QMetaObject::invokeMethod(
            this, [this, fraction] { emit progress(fraction); }, Qt::QueuedConnection);
      }
      return !cancelled_.load();
    };
    DeregulationResult result;
    std::vector<Frame> frames;
    try {
      result = deregulate(*model, options);
      frames = frames_from_trace(*model, options.setting, result.trace);
    } catch (const std::exception& e) {
      result.status = "stopped";
      result.stop_cause = e.what();
    }
    if (cancelled_.load()) result.stop_cause = "cancelled";
    QMetaObject::invokeMethod(
        this,
        [this, frames = std::move(frames), result] {
          running_ = false;
          emit finished(frames, result);
        },
        Qt::QueuedConnection);
  });
}

std::vector<Frame> frames_from_trace(const ActionModel& model, const std::string& adjuster,
                                     const CsvTable& trace) {
  std::vector<Frame> frames;
  if (trace.rows.empty()) return frames;
  const RestState rest = find_rest_state(model);
  const int n = model.dofs();
  const int t_col = trace.column_index("time_s");
  const int gap_col = trace.column_index("hammer_string_gap_mm");
  const int finger_col = trace.column_index("finger_force_n");
  const int adjuster_col = trace.column_index("adjuster_mm");
  std::vector<int> angle_cols, contact_cols, strap_cols;
  for (const Body& b : model.bodies)
    angle_cols.push_back(trace.column_index(column_name(b.name) + "_angle_deg"));
  for (const Contact& c : model.contacts)
    contact_cols.push_back(trace.column_index(column_name(c.name) + "_force_n"));
  for (const Strap& s : model.straps)
    strap_cols.push_back(trace.column_index(column_name(s.name) + "_tension_n"));
  std::map<double, std::shared_ptr<const ActionModel>> models;  // by adjuster position, mm
  for (const auto& row : trace.rows) {
    Frame f;
    f.t = row[t_col];
    f.q = rest.q;
    f.v = DofVector::Zero(n);
    for (int k = 0; k < n; ++k) {
      if (angle_cols[k] < 0) continue;
      f.angle_deg.push_back(row[angle_cols[k]]);
      f.q[k] = rest.q[k] + row[angle_cols[k]] * M_PI / 180.0 / model.bodies[k].trace_sign;
    }
    f.hammer_string_gap_mm = gap_col >= 0 ? row[gap_col] : 0.0;
    f.finger_force_n = finger_col >= 0 ? row[finger_col] : 0.0;
    for (int c : contact_cols) f.contact_force_n.push_back(c >= 0 ? row[c] : 0.0);
    for (int c : strap_cols) f.strap_tension_n.push_back(c >= 0 ? row[c] : 0.0);
    const double mm = adjuster_col >= 0 ? row[adjuster_col] : 0.0;
    auto& m = models[mm];
    if (!m) m = std::make_shared<const ActionModel>(with_adjuster(model, adjuster, mm * 1e-3));
    f.model = m;
    frames.push_back(std::move(f));
  }
  return frames;
}

}  // namespace pat::ui

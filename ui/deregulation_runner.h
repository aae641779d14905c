// The deregulation demo from the window (paper section 7.2): deregulate() in a background
// thread with progress and Cancel; the result is replayed as an animation (frames rebuilt
// from its trace) with the measured value of the setting over time.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <vector>

#include "frame.h"
#include "regulation/deregulation.h"

namespace pat::ui {

class DeregulationRunner : public QObject {
  Q_OBJECT
 public:
  explicit DeregulationRunner(QObject* parent = nullptr);
  ~DeregulationRunner() override;

  void start(std::shared_ptr<const ActionModel> model, DeregulationOptions options);
  void cancel() { cancelled_.store(true); }
  bool running() const { return running_; }
  void wait() { future_.waitForFinished(); }

 signals:
  /// Simulated time reached, as a fraction of the duration.
  void progress(double fraction);
  /// Done (or stopped, or cancelled): the frames to replay and the result.
  void finished(const std::vector<pat::ui::Frame>& frames, const pat::DeregulationResult& result);

 private:
  std::atomic<bool> cancelled_{false};
  bool running_ = false;
  QFuture<void> future_;
};

/// Frames of a recorded trace (simulate's columns plus adjuster_mm): joint coordinates from the
/// trace angles and the rest state; one model per adjuster position.
std::vector<Frame> frames_from_trace(const ActionModel& model, const std::string& adjuster,
                                     const CsvTable& trace);

}  // namespace pat::ui

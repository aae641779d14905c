// The engine's side of the window: a Simulator run in its own thread, stepped in short chunks up
// to a target time the window sets. Changes from the window (model, input, the mouse-played
// key) are queued and applied at the next step boundary; frames are recorded at a sample
// interval into a mutex-guarded buffer, and framesAvailable() is emitted only when that buffer
// goes from empty to non-empty (the window drains it from its redraw timer).
#pragma once

#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "frame.h"
#include "inputs/key_input.h"
#include "sim/simulator.h"

namespace pat::ui {

class LiveKeyInput;

/// What a run starts from: the model and the input SPEC ("" = no finger on the key).
struct RunSetup {
  std::shared_ptr<const ActionModel> model;
  std::string input_spec;
  int run_id = 0;  ///< tags the run's frames, so that frames of a replaced run are dropped
};

class SimulationWorker : public QObject {
  Q_OBJECT
 public:
  SimulationWorker();
  ~SimulationWorker() override;

  // thread-safe requests (any thread); applied by the worker at its next step boundary
  void set_target_time(double t);
  void set_sample_interval(double seconds);
  void request_model(std::shared_ptr<const ActionModel> model);
  /// A blow struck now: `spec` (a force SPEC) starting at the current simulated time.
  /// Returns the request's serial number: the first frame recorded after the worker applies it
  /// carries it with the simulated time it took effect (Frame::inputs_applied_through).
  int request_blow(const std::string& spec);
  /// The key follows `angle_rad` (from rest, positive down) from now on (mouse play), kept
  /// between rest and the run's full dip; the transition to each new target lasts
  /// `transition_s` of simulated time. Returns the request's serial number, as request_blow.
  int request_key_angle(double angle_rad, double transition_s);

  /// A new run wanted (any thread): the worker builds the latest one asked for when it gets to
  /// it, so that a slider dragged at rest (a restart at every move, each finding its rest state)
  /// does not leave a queue of runs to build. Requests made before it are dropped (they were the
  /// old run's); those made after it wait for the new run.
  void request_run(const RunSetup& setup);

  /// Takes the recorded frames (oldest first).
  std::vector<Frame> take_frames();

 public slots:
  /// Builds a new run (rest state, input) and records its first frame.
  void start_run(const pat::ui::RunSetup& setup);
  /// Steps toward the target time for a few milliseconds, then yields to the event loop.
  void compute();

 signals:
  void framesAvailable();
  /// The run started; `notes`: what the user should know of its input (input_notes; empty:
  /// nothing).
  void runStarted(int run_id, const QString& notes);
  /// The run could not start (bad SPEC, a model that does not settle): the message says why.
  void runFailed(int run_id, const QString& message);
  /// The run stopped by itself (unphysical contact, divergence): the simulator's cause.
  void runStopped(int run_id, const QString& cause);

 protected:
  /// Called by request_run (in the asking thread) once the run is stored, before its start is
  /// queued: where a loaded machine can pause the asking thread while the worker goes on. A test
  /// waits there to make that pause happen every time.
  virtual void after_run_stored() {}

 private:
  void schedule_compute();
  void start_requested_run();
  /// Applies what was asked for at this step boundary; false (nothing taken) when a new run is
  /// asked for: what is pending then waits for it.
  bool apply_pending();
  /// An input (a blow, a grab of the key) took effect now: the next frame says so.
  void stamp_input(int serial);
  void record_frame();
  /// The run is a frame spacing (at the current playback speed) past its last frame.
  bool frame_due() const;

  std::unique_ptr<Simulator> sim_;
  int run_id_ = 0;
  double full_dip_rad_ = 0.0;
  double last_frame_t_ = 0.0;  ///< simulated time of the last frame recorded (s)
  std::vector<std::string> unreported_events_;
  std::shared_ptr<LiveKeyInput> live_key_;
  DynamicsReading reading_;

  std::atomic<double> target_time_{0.0};
  std::atomic<double> sample_interval_{2e-4};
  std::atomic<bool> compute_scheduled_{false};
  std::atomic<bool> has_pending_{false};

  std::mutex pending_mutex_;
  std::optional<RunSetup> pending_run_;  // the latest run asked for, not yet built
  std::atomic<bool> run_requested_{false};
  std::shared_ptr<const ActionModel> pending_model_;
  std::string pending_blow_;
  bool pending_key_ = false;
  double pending_key_angle_ = 0.0, pending_key_transition_ = 0.0;
  int last_input_serial_ = 0;     // of the latest blow or key request (under pending_mutex_)
  int pending_input_serial_ = 0;  // of the latest one pending (under pending_mutex_)
  // worker thread: the latest input applied since the last frame, for the next frame
  int applied_input_serial_ = 0;
  double applied_input_t_ = 0.0;

  std::mutex frames_mutex_;
  std::vector<Frame> frames_;
};

}  // namespace pat::ui

Q_DECLARE_METATYPE(pat::ui::RunSetup)

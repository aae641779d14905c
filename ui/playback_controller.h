// Playback of a simulation run in the window: owns the worker thread, keeps the history of
// frames, and moves the displayed time with the wall clock times the playback speed (real time
// down to 1/1000). The worker is asked to compute a little ahead of the displayed time; when it
// cannot keep up, the display waits and the achieved real-time factor says so. A redraw timer
// drains the worker's frames at most 60 times a second.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QThread>
#include <QTimer>
#include <memory>
#include <utility>
#include <vector>

#include "frame_history.h"
#include "simulation_worker.h"

namespace pat::ui {

class PlaybackController : public QObject {
  Q_OBJECT
 public:
  explicit PlaybackController(QObject* parent = nullptr);
  ~PlaybackController() override;

  /// Starts a new run of `model` under `input_spec` ("" = no finger) from rest at t = 0.
  void restart(std::shared_ptr<const ActionModel> model, const std::string& input_spec);
  /// The input SPEC the current run was started with.
  const std::string& run_spec() const { return run_spec_; }
  /// Nothing of the current run computed past its start yet (restarted, or held at rest).
  bool at_start() const { return history_.empty() || history_.last_time() <= 0.0; }
  /// Plays recorded frames (an analysis result such as the deregulation demo) instead of a
  /// live run; playback stops at the last frame.
  void replay(std::vector<Frame> frames);
  bool replaying() const { return replay_; }
  /// Replaces the running model at the next step boundary (a slider moved).
  void change_model(std::shared_ptr<const ActionModel> model);
  /// A blow (force SPEC) struck now; starts playing.
  void strike(const std::string& force_spec);
  /// The key played with the mouse: key angle (rad from rest, positive down), kept between
  /// rest and the run's full dip by the worker; starts playing.
  void play_key(double angle_rad);
  /// The mouse lets the key go: from now the key is free (no finger force), as a finger lifted
  /// off it; it had been led back to rest and held there, pulling it up (−0.5 N) as the
  /// hammer came down.
  void release_key();

  void play();
  void pause();
  /// Paused: `frames` frames forward (computed if needed) or back. A frame is the recording
  /// interval, from 0.01 ms at 1/1000 to 0.2 ms at 1/10 and faster (sample_interval()).
  void step_forward(int frames = 1);
  void step_back(int frames = 1);
  /// The larger step (Shift with the step keys or buttons): enough to cross a blow's escapement,
  /// drop and check (about 7 ms on the grand) in a few presses at 1/10.
  static constexpr int kLargeStepFrames = 10;
  /// Paused, just before the last blow struck or key played before the frame shown (2 ms
  /// before it); again, the one before; at last the oldest frame kept.
  void rewind();
  /// Displayed time (within the history), paused.
  void seek(double t);
  /// Playback speed, simulated seconds per wall second (1 = real time, 0.001 = 1/1000).
  void set_speed(double speed);

  bool playing() const { return playing_; }
  double speed() const { return speed_; }
  double display_time() const { return display_time_; }
  double achieved_realtime_factor() const { return achieved_factor_; }
  const FrameHistory& history() const { return history_; }
  std::shared_ptr<const ActionModel> model() const { return model_; }
  /// The frame shown now (interpolated between recorded frames in slow motion).
  const Frame& current_frame() const { return current_; }
  bool has_frame() const { return has_frame_; }
  bool run_stopped() const { return stopped_; }
  /// What drove the key at simulated time `t` of this run, in inputChanged's words: the run's
  /// input, or a blow struck or the mouse's play from the time it began.
  QString input_at(double t) const;
  /// Every input of this run in order, by the SPECs that run them again (the words where there is
  /// none: the key played with the mouse): "force:pulse:20:40; from t = 1.2345 s
  /// force:pulse:12:40"; a run of one input gives its SPEC alone, which `diagnose` reads back
  /// from an exported trace. `in_words`: "a 20 N blow held 40 ms; from t = 1.2345 s a 12 N blow
  /// held 40 ms, struck".
  QString inputs_text(bool in_words = false) const;
  /// Redraw timer ticks that showed a new frame, and their count per wall second (measured).
  double redraw_rate_hz() const { return redraw_rate_hz_; }

 signals:
  /// A new frame is shown (at most once per redraw tick).
  void frameShown(const pat::ui::Frame& frame);
  /// New frames reached the display (in time order): the plots append them.
  void framesPassed(const std::vector<pat::ui::Frame>& frames);
  void playingChanged(bool playing);
  /// What drives the key now, in words: the run's input, a blow struck, the key played with the
  /// mouse, or a recorded replay.
  void inputChanged(const QString& what);
  void runRestarted();
  /// The run stopped by itself (a diverging step); the message says why.
  void runStopped(const QString& message);
  /// The run could not start (its input or model refused); the message says why.
  void runRefused(const QString& message);
  void realtimeFactorChanged(double factor);
  /// The user moved through the run while paused (a step, a step back, a rewind or a seek), not
  /// the one frame computed to show a changed setting.
  void navigated();

 private slots:
  void tick();
  void on_run_started(int run_id, const QString& notes);
  void on_run_failed(int run_id, const QString& message);
  void on_run_stopped(int run_id, const QString& cause);

 private:
  /// Starts the achieved-speed measurement afresh and reports "nothing achieved" (paused, or
  /// the speed changed).
  void restart_factor_window();
  void drain();
  /// Paused: `frames` frames forward, computed if needed (step_forward without its navigated()).
  void advance(int frames);
  /// Paused: has the worker compute the frame after the last one recorded, for drain() to show.
  void ask_next_frame();
  /// Records what drives the key from simulated time `from_t` on (in words, and the SPEC where
  /// there is one), and says so (inputChanged). `request`: the worker's serial number of the
  /// request behind it, whose frames give the time it took effect (0: none; from_t is exact).
  void note_input(double from_t, const QString& what, const std::string& spec = {},
                  int request = 0);
  /// Inputs asked for up to serial `through` took effect at simulated time `t`.
  void time_inputs(int through, double t);
  void show_time(double t);
  double sample_interval() const;

  QThread thread_;
  SimulationWorker* worker_;  // lives in thread_, deleted when it finishes
  QTimer timer_;
  QElapsedTimer wall_;
  qint64 last_tick_ns_ = 0;

  FrameHistory history_;
  std::shared_ptr<const ActionModel> model_;
  std::string run_spec_;
  int run_id_ = 0;
  bool playing_ = false;
  bool stopped_ = false;
  bool replay_ = false;      // frames from an analysis: no worker behind them
  bool key_played_ = false;  // the mouse drives the key since the last run start or blow
  int frames_to_step_ = 0;   // frames of a step still to compute after the one awaited
  struct InputRecord {
    double from_t;  // simulated time, s
    QString words;
    std::string spec;  // "" where there is none (the mouse's play, a replay)
    // the worker's request behind it, until its frames say when it took effect (0: timed): till
    // then from_t is the time last drawn, up to a redraw's worth of run earlier
    int request = 0;
  };
  std::vector<InputRecord> inputs_;  // in order
  double speed_ = 0.1;
  double display_time_ = 0.0;
  double passed_time_ = -1.0;  // frames up to here went to framesPassed
  Frame current_;
  bool has_frame_ = false;
  // achieved real-time factor and redraw rate, averaged over about half a second
  double factor_window_sim_ = 0.0, factor_window_wall_ = 0.0;
  double achieved_factor_ = 0.0;  ///< 0 while paused and until a window at the speed is measured
  int redraws_in_window_ = 0;
  double redraw_rate_hz_ = 0.0;
};

}  // namespace pat::ui

#include "playback_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "input_words.h"

namespace pat::ui {
namespace {

constexpr int kRedrawIntervalMs = 16;  // at most about 60 redraws a second
constexpr double kLeadWallS = 0.04;    // the worker computes this far ahead (wall seconds)

}  // namespace

PlaybackController::PlaybackController(QObject* parent)
    : QObject(parent), worker_(new SimulationWorker) {
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &SimulationWorker::framesAvailable, this, &PlaybackController::drain,
          Qt::QueuedConnection);
  connect(worker_, &SimulationWorker::runStarted, this, &PlaybackController::on_run_started,
          Qt::QueuedConnection);
  connect(worker_, &SimulationWorker::runFailed, this, &PlaybackController::on_run_failed,
          Qt::QueuedConnection);
  connect(worker_, &SimulationWorker::runStopped, this, &PlaybackController::on_run_stopped,
          Qt::QueuedConnection);
  thread_.setObjectName("simulation");
  thread_.start();
  timer_.setInterval(kRedrawIntervalMs);
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, &PlaybackController::tick);
  wall_.start();
  timer_.start();
}

PlaybackController::~PlaybackController() {
  timer_.stop();
  thread_.quit();
  thread_.wait();
}

void PlaybackController::restart(std::shared_ptr<const ActionModel> model,
                                 const std::string& input_spec) {
  model_ = std::move(model);
  run_spec_ = input_spec;
  ++run_id_;
  history_.clear();
  frames_to_step_ = 0;
  stopped_ = false;
  replay_ = false;
  has_frame_ = false;
  display_time_ = 0.0;
  passed_time_ = -1.0;
  worker_->take_frames();
  worker_->set_sample_interval(sample_interval());
  key_played_ = false;
  inputs_.clear();
  note_input(0.0, input_in_words(input_spec), input_spec);
  worker_->request_run(RunSetup{model_, input_spec, run_id_});
  emit runRestarted();
}

void PlaybackController::replay(std::vector<Frame> frames) {
  pause();
  ++run_id_;  // frames still coming from the worker's run are dropped
  history_.clear();
  for (Frame& f : frames) {
    f.run = run_id_;
    history_.append(std::move(f));
  }
  stopped_ = false;
  replay_ = true;
  passed_time_ = -1.0;
  has_frame_ = false;
  emit runRestarted();
  key_played_ = false;
  inputs_.clear();
  note_input(-std::numeric_limits<double>::infinity(), tr("a recorded replay"));
  if (history_.empty()) return;
  model_ = history_.at(0).model;
  show_time(history_.first_time());
  play();
}

void PlaybackController::note_input(double from_t, const QString& what, const std::string& spec,
                                    int request) {
  inputs_.push_back({from_t, what, spec, request});
  emit inputChanged(what);
}

void PlaybackController::time_inputs(int through, double t) {
  for (InputRecord& input : inputs_)
    if (input.request > 0 && input.request <= through) {
      input.from_t = t;
      input.request = 0;
    }
}

QString PlaybackController::input_at(double t) const {
  // the last input that had started by t (the first, if t lies before every one)
  QString what = inputs_.empty() ? QString() : inputs_.front().words;
  for (const InputRecord& input : inputs_)
    if (input.from_t <= t) what = input.words;
  return what;
}

QString PlaybackController::inputs_text(bool in_words) const {
  QStringList parts;
  for (const InputRecord& input : inputs_) {
    // the SPEC where there is one (what runs it again), else the words (the mouse's play)
    const QString text =
        in_words || input.spec.empty() ? input.words : QString::fromStdString(input.spec);
    parts << (parts.isEmpty() ? text
                              : tr("from t = %1 s %2").arg(input.from_t, 0, 'f', 4).arg(text));
  }
  return parts.join("; ");
}

void PlaybackController::change_model(std::shared_ptr<const ActionModel> model) {
  if (replay_) return;  // a recorded analysis cannot change
  model_ = model;
  // the run takes it from its next step: a paused run stays at the time shown (a screw turned
  // with the arrow keys must not step the run too; the window's status line says the change acts
  // as the run goes on), but its frame is drawn again with the screw where it now is (the parts
  // respond as the run goes on)
  worker_->request_model(model);
  if (!playing_ && has_frame_) {
    current_.model = std::move(model);
    emit frameShown(current_);
  }
}

void PlaybackController::strike(const std::string& force_spec) {
  if (stopped_ || replay_) return;
  seek(history_.last_time());
  const int request = worker_->request_blow(force_spec);
  key_played_ = false;
  note_input(history_.last_time(), tr("%1, struck").arg(input_in_words(force_spec)), force_spec,
             request);
  play();
}

void PlaybackController::play_key(double angle_rad) {
  if (stopped_ || replay_) return;
  // a grab plays the key from the run's end, as a blow does (playing behind it, after a rewind,
  // the run would not reach the grab until the display had caught up)
  if (!key_played_ || !playing_) seek(history_.last_time());
  // the key follows the mouse within 30 ms of wall time (shorter in simulated time when slowed);
  // the run keeps the angle within its own full dip (known to the worker as it builds the run,
  // here only once its start is reported: a key grabbed on the first frame drawn came before it)
  const double transition = std::clamp(0.03 * speed_, 2e-3, 0.03);
  const int request = worker_->request_key_angle(std::max(angle_rad, 0.0), transition);
  if (!key_played_)
    note_input(history_.last_time(), tr("the key played with the mouse"), {}, request);
  key_played_ = true;
  play();
}

void PlaybackController::release_key() {
  if (stopped_ || replay_ || !key_played_) return;
  seek(history_.last_time());
  const int request = worker_->request_blow("force:const:0");
  key_played_ = false;
  note_input(history_.last_time(), input_in_words("force:const:0"), "force:const:0", request);
  play();
}

void PlaybackController::play() {
  if (stopped_ || playing_) return;
  frames_to_step_ = 0;
  playing_ = true;
  last_tick_ns_ = wall_.nsecsElapsed();
  emit playingChanged(true);
}

void PlaybackController::pause() {
  if (!playing_) return;
  playing_ = false;
  if (!replay_) worker_->set_target_time(display_time_);
  restart_factor_window();  // nothing is achieved while paused ("achieved —", not the last)
  emit playingChanged(false);
}

void PlaybackController::restart_factor_window() {
  factor_window_sim_ = factor_window_wall_ = 0.0;
  redraws_in_window_ = 0;
  if (achieved_factor_ == 0.0) return;
  achieved_factor_ = 0.0;
  emit realtimeFactorChanged(0.0);
}

void PlaybackController::step_forward(int frames) {
  advance(frames);
  if (!history_.empty()) emit navigated();
}

void PlaybackController::advance(int frames) {
  pause();
  if (history_.empty() || frames < 1) return;
  if (display_time_ > history_.last_time() + 1e-12 && !stopped_ && !replay_) {
    // a step still being computed: this one goes on from where that one will be
    frames_to_step_ += frames;
    return;
  }
  const std::size_t i = history_.index_at(display_time_);
  const std::size_t wanted = i + static_cast<std::size_t>(frames);
  if (wanted < history_.size()) {
    show_time(history_.at(wanted).t);
  } else if (!stopped_ && !replay_) {
    // the frames still missing are computed one at a time (the worker lands exactly on a time it
    // is asked for and records a frame there; asked for several frames' time at once, it could
    // stop a fraction of a step short of the last one's place on its own grid); drain() asks for
    // each next one, and shows the last
    frames_to_step_ = static_cast<int>(wanted - (history_.size() - 1)) - 1;
    ask_next_frame();
  } else {
    show_time(history_.last_time());  // a stopped run or a replay: as far as it goes
  }
}

void PlaybackController::ask_next_frame() {
  display_time_ = history_.last_time() + sample_interval();
  worker_->set_target_time(display_time_);
}

void PlaybackController::step_back(int frames) {
  pause();
  if (history_.empty() || frames < 1) return;
  const std::size_t i = history_.index_at(display_time_);
  const std::size_t back = static_cast<std::size_t>(frames);
  show_time(history_.at(i > back ? i - back : 0).t);
  emit navigated();
}

void PlaybackController::rewind() {
  pause();
  if (history_.empty()) return;
  // back to just before the latest blow struck (or key played) before the time shown, so that a
  // class sees it again without stepping back through the whole run; pressed again, to the one
  // before it, and at last to the run's start
  constexpr double kLeadS = 2e-3;  // shown from slightly before the blow: the key still at rest
  const double first = history_.first_time();
  const double now = has_frame_ ? current_.t : display_time();
  double target = first;
  for (const InputRecord& input : inputs_) {
    const double before = input.from_t - kLeadS;
    if (input.from_t > first && before > first && before < now - 1e-9)
      target = std::max(target, before);
  }
  show_time(target);
  emit navigated();
}

void PlaybackController::seek(double t) {
  if (history_.empty()) return;
  show_time(std::clamp(t, history_.first_time(), history_.last_time()));
  emit navigated();
}

void PlaybackController::set_speed(double speed) {
  const double before = speed_;
  speed_ = std::clamp(speed, 1e-3, 1.0);
  worker_->set_sample_interval(sample_interval());
  // what was achieved at the speed before says nothing of this one: measured afresh
  if (speed_ != before) restart_factor_window();
}

double PlaybackController::sample_interval() const {
  // about four frames per redraw, from 1e-5 s (two of the window's integrator steps) up to 0.2 ms
  return std::clamp(speed_ / 240.0, 1e-5, 2e-4);
}

void PlaybackController::drain() {
  std::vector<Frame> frames = worker_->take_frames();
  for (Frame& f : frames) {
    if (f.run != run_id_) continue;
    if (f.inputs_applied_through > 0) time_inputs(f.inputs_applied_through, f.inputs_applied_t);
    history_.append(std::move(f));
  }
  // a run's first frame is shown as it comes, paused or playing: shown later (when the run's
  // start was reported, or at the next redraw), it undid a step asked for in between
  if (!has_frame_ && !history_.empty() && !replay_) show_time(history_.first_time());
  // a step waiting for its frame: shown, or with more frames to step, the next one asked for
  if (!playing_ && !history_.empty() && display_time_ > current_.t &&
      history_.last_time() >= display_time_ - 1e-12) {
    if (frames_to_step_ > 0 && !stopped_) {
      --frames_to_step_;
      ask_next_frame();
    } else {
      frames_to_step_ = 0;
      show_time(display_time_);
    }
  }
}

void PlaybackController::tick() {
  drain();
  const qint64 now = wall_.nsecsElapsed();
  const double wall_dt = (now - last_tick_ns_) * 1e-9;
  last_tick_ns_ = now;
  if (!playing_ || history_.empty()) return;

  const double before = display_time_;
  const double wanted = display_time_ + wall_dt * speed_;
  if (!replay_) worker_->set_target_time(wanted + kLeadWallS * speed_);
  show_time(std::min(wanted, history_.last_time()));
  if (replay_ && display_time_ >= history_.last_time()) pause();

  factor_window_sim_ += display_time_ - before;
  factor_window_wall_ += wall_dt;
  ++redraws_in_window_;
  if (factor_window_wall_ >= 0.5) {
    achieved_factor_ = factor_window_sim_ / factor_window_wall_;
    redraw_rate_hz_ = redraws_in_window_ / factor_window_wall_;
    factor_window_sim_ = factor_window_wall_ = 0.0;
    redraws_in_window_ = 0;
    emit realtimeFactorChanged(achieved_factor_);
  }
}

void PlaybackController::show_time(double t) {
  display_time_ = t;
  current_ = history_.interpolated(t);
  has_frame_ = true;
  // frames between the last shown time and now go to the plots, in order
  if (t > passed_time_) {
    std::vector<Frame> passed;
    for (std::size_t i = passed_time_ < 0.0 ? 0 : history_.index_at(passed_time_) + 1;
         i < history_.size() && history_.at(i).t <= t; ++i)
      passed.push_back(history_.at(i));
    if (!passed.empty()) {
      passed_time_ = passed.back().t;
      emit framesPassed(passed);
    }
  }
  emit frameShown(current_);
}

void PlaybackController::on_run_started(int run_id, const QString& notes) {
  if (run_id != run_id_) return;
  // what the input's reading means (a CSV's ignored column, its held end) goes with its name,
  // also when a blow or the mouse took over before this report came (said when it still drives)
  if (!notes.isEmpty() && !inputs_.empty()) {
    inputs_.front().words += tr(" (%1)").arg(notes);
    if (inputs_.size() == 1) emit inputChanged(inputs_.front().words);
  }
  drain();
}

void PlaybackController::on_run_failed(int run_id, const QString& message) {
  if (run_id != run_id_) return;
  stopped_ = true;
  pause();
  emit runRefused(message);
}

void PlaybackController::on_run_stopped(int run_id, const QString& cause) {
  if (run_id != run_id_) return;
  drain();
  stopped_ = true;
  pause();
  if (!history_.empty()) show_time(history_.last_time());
  emit runStopped(cause);
}

}  // namespace pat::ui

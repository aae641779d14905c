#include "simulation_worker.h"

#include <QElapsedTimer>
#include <QMetaObject>
#include <exception>
#include <limits>

#include "integrators/integrator_factory.h"
#include "live_key_input.h"
#include "shifted_key_input.h"
#include "sim/key_travel.h"

namespace pat::ui {

namespace {

// wall time spent stepping before the worker yields to its event loop
constexpr qint64 kChunkNs = 4'000'000;

}  // namespace

SimulationWorker::SimulationWorker() {
  qRegisterMetaType<pat::ui::RunSetup>();
}

SimulationWorker::~SimulationWorker() = default;

void SimulationWorker::set_target_time(double t) {
  target_time_.store(t);
  schedule_compute();
}

void SimulationWorker::set_sample_interval(double seconds) {
  sample_interval_.store(seconds);
}

void SimulationWorker::request_model(std::shared_ptr<const ActionModel> model) {
  std::lock_guard lock(pending_mutex_);
  pending_model_ = std::move(model);
  has_pending_.store(true);
}

int SimulationWorker::request_blow(const std::string& spec) {
  int serial = 0;
  {
    std::lock_guard lock(pending_mutex_);
    pending_blow_ = spec;
    pending_key_ = false;  // a blow (or the key let go) comes after the mouse's last move
    serial = pending_input_serial_ = ++last_input_serial_;
    has_pending_.store(true);
  }
  schedule_compute();
  return serial;
}

int SimulationWorker::request_key_angle(double angle_rad, double transition_s) {
  int serial = 0;
  {
    std::lock_guard lock(pending_mutex_);
    pending_key_ = true;
    pending_key_angle_ = angle_rad;
    pending_key_transition_ = transition_s;
    serial = pending_input_serial_ = ++last_input_serial_;
    has_pending_.store(true);
  }
  schedule_compute();
  return serial;
}

std::vector<Frame> SimulationWorker::take_frames() {
  std::lock_guard lock(frames_mutex_);
  std::vector<Frame> out;
  out.swap(frames_);
  return out;
}

void SimulationWorker::schedule_compute() {
  if (compute_scheduled_.exchange(true)) return;
  QMetaObject::invokeMethod(this, &SimulationWorker::compute, Qt::QueuedConnection);
}

void SimulationWorker::request_run(const RunSetup& setup) {
  bool start_queued = false;
  {
    // the run and its flag change together, under the lock: raised after the lock was let go,
    // the flag could go up after the worker had already taken this run, and stay up with nothing
    // to take (every later run then waited for a start that never came)
    std::lock_guard lock(pending_mutex_);
    pending_run_ = setup;
    // a blow, key move or model asked for before belonged to the run being replaced
    pending_model_.reset();
    pending_blow_.clear();
    pending_key_ = false;
    has_pending_.store(false);
    start_queued = run_requested_.exchange(true);
  }
  after_run_stored();
  if (!start_queued)
    QMetaObject::invokeMethod(
        this, [this] { start_requested_run(); }, Qt::QueuedConnection);
}

void SimulationWorker::start_requested_run() {
  RunSetup setup;
  {
    std::lock_guard lock(pending_mutex_);
    run_requested_.store(false);
    if (!pending_run_) return;
    setup = std::move(*pending_run_);
    pending_run_.reset();
  }
  start_run(setup);
  // what was asked for since (a blow struck as the run started) acts on it
  if (has_pending_.load()) schedule_compute();
}

void SimulationWorker::start_run(const RunSetup& setup) {
  run_id_ = setup.run_id;
  sim_.reset();
  live_key_.reset();
  unreported_events_.clear();
  applied_input_serial_ = 0;
  QString notes;
  try {
    SimulationOptions options;
    options.integrator = "w2";
    // half the command line's default: the window spends most of its time on a key held after
    // a blow, where the default chatters (integrator_factory.h); still about four times faster
    // than real time, above every playback speed
    options.integrator_options.fixed_step_s = kW2HeldKeyStepS;
    const RestState rest = find_rest_state(*setup.model);
    const InputContext context = input_context(*setup.model, rest);
    full_dip_rad_ = context.full_dip_angle_rad;
    std::shared_ptr<const KeyInput> input;
    if (!setup.input_spec.empty()) input = parse_input_spec(setup.input_spec, context);
    // the window's run has no end: a recording's last value is held after it
    if (input)
      notes = QString::fromStdString(input_notes(*input, std::numeric_limits<double>::infinity()));
    sim_ = std::make_unique<Simulator>(setup.model, input, options, &rest);
  } catch (const std::exception& e) {
    emit runFailed(run_id_, QString::fromStdString(e.what()));
    return;
  }
  target_time_.store(0.0);
  record_frame();  // the first frame, at rest; it sets last_frame_t_
  emit runStarted(run_id_, notes);
}

void SimulationWorker::compute() {
  compute_scheduled_.store(false);
  // a new run is on its way: what is pending is for it, not for the run it replaces
  if (run_requested_.load()) return;
  if (!sim_ || sim_->stopped()) return;
  // a state computed past the last frame with no frame for it yet (the run went ahead at a
  // faster speed's wider frame spacing): recorded now, or a slower playback, asking for less than
  // the run already has, would wait for it for ever
  if (frame_due()) record_frame();
  QElapsedTimer wall;
  wall.start();
  while (sim_->time() < target_time_.load() - 1e-12 && wall.nsecsElapsed() < kChunkNs) {
    // a new run asked for meanwhile: what is pending is for it (start_requested_run applies it)
    if (has_pending_.load() && !apply_pending()) return;
    if (!sim_->step(target_time_.load())) break;
    for (int k = sim_->new_event_count(); k > 0; --k)
      unreported_events_.push_back(sim_->events()[sim_->events().size() - k].type);
    if (frame_due()) record_frame();
  }
  if (sim_->stopped()) {
    record_frame();
    emit runStopped(run_id_, QString::fromStdString(sim_->stop_cause()));
    return;
  }
  if (sim_->time() < target_time_.load() - 1e-12) schedule_compute();
}

bool SimulationWorker::frame_due() const {
  // the interval read at every call: a slower playback speed chosen between two frames shortens
  // the wait for the next one (stored at the last frame, the old 0.2 ms could lie beyond every
  // target the slow playback asked for, and the run froze)
  return sim_->time() >= last_frame_t_ + sample_interval_.load() - 1e-12;
}

bool SimulationWorker::apply_pending() {
  std::shared_ptr<const ActionModel> model;
  std::string blow;
  bool key = false;
  double key_angle = 0.0, key_transition = 0.0;
  int serial = 0;
  {
    std::lock_guard lock(pending_mutex_);
    // asked for after a new run was (request_run clears what came before): for that run, not
    // for this one, which it replaces. Checked under the lock the request took, so that a
    // request made as the run is asked for cannot slip in between
    if (run_requested_.load()) return false;
    serial = pending_input_serial_;
    model.swap(pending_model_);
    blow.swap(pending_blow_);
    key = pending_key_;
    key_angle = pending_key_angle_;
    key_transition = pending_key_transition_;
    pending_key_ = false;
    has_pending_.store(false);
  }
  try {
    if (model) sim_->set_model(model);
    const double t = sim_->time();
    if (!blow.empty()) {
      live_key_.reset();
      const InputContext context{full_dip_rad_};
      sim_->set_input(std::make_shared<ShiftedKeyInput>(parse_input_spec(blow, context), t));
      stamp_input(serial);
    }
    if (key) {
      const int key_body = sim_->model().landmarks.key;
      if (!live_key_) {
        const double angle = sim_->q()[key_body] - sim_->rest().q[key_body];
        const double rate = sim_->v()[key_body];
        live_key_ = std::make_shared<LiveKeyInput>(t, angle, rate, full_dip_rad_);
        live_key_->set_target(key_angle);
        live_key_->update(t, key_transition);
        sim_->set_input(live_key_);
        stamp_input(serial);
      } else {
        live_key_->set_target(key_angle);
        if (live_key_->update(t, key_transition)) sim_->set_input(live_key_);
      }
    }
  } catch (const std::exception& e) {
    sim_->stop(e.what());
  }
  return true;
}

void SimulationWorker::stamp_input(int serial) {
  applied_input_serial_ = serial;
  applied_input_t_ = sim_->time();
}

void SimulationWorker::record_frame() {
  Frame frame;
  frame.t = sim_->time();
  frame.q = sim_->q();
  frame.v = sim_->v();
  frame.model = sim_->model_ptr();
  const ActionModel& model = *frame.model;
  const DofVector& rest = sim_->rest().q;
  frame.angle_deg.resize(model.bodies.size());
  for (std::size_t k = 0; k < model.bodies.size(); ++k)
    frame.angle_deg[k] = model.bodies[k].trace_sign * (frame.q[k] - rest[k]) * 180.0 / M_PI;
  frame.hammer_string_gap_mm = sim_->hammer_string_gap(frame.q) * 1e3;
  sim_->evaluate(frame.t, frame.q, frame.v, reading_);
  frame.finger_force_n = reading_.finger_force;
  frame.contact_force_n.reserve(reading_.contacts.size());
  for (const ContactReading& c : reading_.contacts) frame.contact_force_n.push_back(c.normal_force);
  frame.strap_tension_n = reading_.strap_tension;
  frame.events.swap(unreported_events_);
  frame.run = run_id_;
  frame.inputs_applied_through = applied_input_serial_;
  frame.inputs_applied_t = applied_input_t_;
  applied_input_serial_ = 0;
  last_frame_t_ = frame.t;

  bool was_empty = false;
  {
    std::lock_guard lock(frames_mutex_);
    was_empty = frames_.empty();
    frames_.push_back(std::move(frame));
  }
  if (was_empty) emit framesAvailable();
}

}  // namespace pat::ui

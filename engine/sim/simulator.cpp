#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/format.h"

namespace pat {
namespace {

constexpr double kMaxTurnFromRest = M_PI;  // rad
// a jack-knuckle (butt) opening within this time (s) of the let-off button's touch is the
// escapement; the jack under the knuckle with its toe off the button this long has reset
constexpr double kEscapementWindow = 2e-3;

std::string part_name(const ActionModel& model, int body) {
  return body < 0 ? std::string("frame") : model.bodies[body].name;
}

/// Beyond this turn from rest (rad) a part has left the travel of any working action (the
/// largest, the hammer's, is about 25°).
constexpr double kBeyondTravel = 35.0 * M_PI / 180.0;

/// A key this close to its front-rail punching (m) has reached the bottom (key_bottom).
constexpr double kKeyBottomReach = 1e-6;

/// A clue to a failed or diverged run: the part farthest beyond a working action's travel at q
/// (the state before the step that failed), as "; just before, the jack stood 55° from rest …",
/// or nothing when every part was within it (a plain numerical failure).
std::string beyond_travel_note(const ActionModel& model, const DofVector& rest,
                               const DofVector& q) {
  int farthest = -1;
  double turn = kBeyondTravel;
  for (int i = 0; i < q.size(); ++i) {
    const double t = std::abs(q[i] - rest[i]);
    if (std::isfinite(t) && t > turn) {
      turn = t;
      farthest = i;
    }
  }
  if (farthest < 0) return "";
  // a setting far off can throw a part out of the geometry, and so can a step too long for the
  // blow; with every setting at its regulated place only the second is left to suspect
  bool regulated = true;
  for (const Adjuster& adjuster : model.adjusters)
    if (std::abs(adjuster.value) > 1e-9) regulated = false;  // m: a micrometre's thousandth
  return "; just before, the " + part_name(model, farthest) + " stood " +
         format_number(turn * 180.0 / M_PI) +
         "° from rest, beyond the travel of a working action (the parts have left the geometry "
         "the model describes: " +
         (regulated ? std::string("every setting is regulated, so a shorter step may help)")
                    : std::string("look for a setting far off, or try a shorter step)"));
}

}  // namespace

Simulator::Simulator(std::shared_ptr<const ActionModel> model,
                     std::shared_ptr<const KeyInput> input, const SimulationOptions& options,
                     const RestState* rest)
    : model_(std::move(model)), input_(std::move(input)), options_(options) {
  rest_ = rest ? *rest : find_rest_state(*model_);
  const int n = model_->dofs();
  q1_ = rest_.q;
  v1_ = DofVector::Zero(n);
  make_integrator(options_.integrator, options_.integrator_options);  // validates the name
  restart_integrator();
  q0_ = q1_;
  v0_ = v1_;
  dynamics_->contact_penetrations(q1_, penetration_);
  penetration_exact_ = true;
  key_was_at_bottom_ = key_at_bottom(penetration_);
}

void Simulator::restart_integrator() {
  if (integrator_) {
    steps_done_before_ += integrator_->stats().steps;
    rhs_done_before_ += integrator_->stats().rhs_evaluations;
  }
  dynamics_ = std::make_unique<ActionDynamics>(*model_, input_.get());
  penetration_limit_.clear();
  closed_end_contacts_.clear();
  for (std::size_t c = 0; c < model_->contacts.size(); ++c) {
    const Contact& contact = model_->contacts[c];
    penetration_limit_.push_back(contact.max_penetration);
    if (contact.closed_start || contact.closed_end) closed_end_contacts_.push_back(c);
  }
  dynamics_->set_key_rest_angle(rest_.q[model_->landmarks.key]);
  integrator_ = make_integrator(options_.integrator, options_.integrator_options);
  integrator_->initialize(*dynamics_, t1_, dynamics_->compress(q1_, v1_));
  // a prescribed key takes its angle from the input
  dynamics_->expand(t1_, integrator_->state(), q1_, v1_);
}

void Simulator::set_model(std::shared_ptr<const ActionModel> model) {
  if (model->dofs() != model_->dofs())
    throw std::invalid_argument("Simulator::set_model: the new model has other joints");
  model_ = std::move(model);
  restart_integrator();
  dynamics_->contact_penetrations(q1_, penetration_);
  penetration_exact_ = true;
  key_was_at_bottom_ = key_at_bottom(penetration_);
}

void Simulator::set_input(std::shared_ptr<const KeyInput> input) {
  input_ = std::move(input);
  restart_integrator();
}

void Simulator::stop(const std::string& cause) {
  if (stopped_) return;
  stopped_ = true;
  stop_cause_ = cause;
}

void Simulator::evaluate(double t, const DofVector& q, const DofVector& v, DynamicsReading& out) {
  dynamics_->evaluate(t, q, v, out);
}

std::vector<double> Simulator::trace_row(double t, const DofVector& q, const DofVector& v) {
  dynamics_->evaluate(t, q, v, reading_);
  const ActionModel& model = *model_;
  std::vector<double> row;
  row.reserve(1 + model.dofs() + 2 + reading_.contacts.size() + reading_.strap_tension.size());
  row.push_back(t);
  for (int k = 0; k < model.dofs(); ++k)
    row.push_back(model.bodies[k].trace_sign * deg(q[k] - rest_.q[k]));
  row.push_back(dynamics_->hammer_string_gap(q) * 1e3);
  row.push_back(reading_.finger_force);
  for (const ContactReading& c : reading_.contacts) row.push_back(c.normal_force);
  for (double tension : reading_.strap_tension) row.push_back(tension);
  for (double& x : row) x += 0.0;  // −0 (a sign flip of an exact 0) is +0: no "-0" in a CSV
  return row;
}

bool Simulator::step(double t_max) {
  new_events_ = 0;
  if (stopped_) return false;
  t0_ = t1_;
  q0_ = q1_;
  v0_ = v1_;
  if (integrator_->step(t_max) != StepStatus::Ok) {
    stop("the integrator failed: " + integrator_->failure_reason() +
         beyond_travel_note(*model_, rest_.q, q0_));
    return false;
  }
  t1_ = integrator_->time();
  dynamics_->expand(t1_, integrator_->state(), q1_, v1_);
  steps_ = steps_done_before_ + integrator_->stats().steps;
  rhs_evaluations_ = rhs_done_before_ + integrator_->stats().rhs_evaluations;
  for (int i = 0; i < q1_.size(); ++i) {
    if (!std::isfinite(q1_[i]) || !std::isfinite(v1_[i])) {
      stop("the simulation diverged (non-finite state)" +
           beyond_travel_note(*model_, rest_.q, q0_));
      return false;
    }
    // no part of an action turns half a turn from rest (the largest, the hammer, about 25°; the
    // contacts stop every part long before): past that, the integration has blown up (a step
    // far too long, say) even while the numbers are still finite
    if (std::abs(q1_[i] - rest_.q[i]) > kMaxTurnFromRest) {
      const std::string note = beyond_travel_note(*model_, rest_.q, q0_);
      stop("the simulation diverged: the " + part_name(*model_, i) + " turned " +
           format_number(std::abs(q1_[i] - rest_.q[i]) * 180.0 / M_PI) +
           "° from rest (more than half a turn" +
           (note.empty() ? std::string("; a shorter step may help)") : ")" + note));
      return false;
    }
  }
  dynamics_->contact_penetration_bounds(q1_, next_penetration_);
  check_penetrations();
  detect_events();
  std::swap(penetration_, next_penetration_);
  penetration_exact_ = false;
  return !stopped_;
}

const std::vector<double>& Simulator::contact_penetrations() {
  if (!penetration_exact_) {
    dynamics_->contact_penetrations(q1_, penetration_);
    penetration_exact_ = true;
  }
  return penetration_;
}

bool Simulator::advance_to(double t) {
  while (!stopped_ && t1_ < t - 1e-12) step(t);
  return !stopped_;
}

void Simulator::check_penetrations() {
  const ActionModel& model = *model_;
  for (std::size_t c = 0; c < penetration_limit_.size(); ++c) {
    if (next_penetration_[c] > penetration_limit_[c]) {
      const Contact& contact = model.contacts[c];
      stop("unphysical penetration in contact '" + contact.name + "' (" +
           part_name(model, contact.body_a) + " into " + part_name(model, contact.body_b) +
           "): " + format_number(next_penetration_[c] * 1e3) + " mm, limit " +
           format_number(contact.max_penetration * 1e3) + " mm");
      return;
    }
  }
  // pressed into a face (or its corner) at the step's start, behind the face's line past a
  // closed end at the step's end: A went round the end of B's face into B (action_dynamics.h)
  for (std::size_t c : closed_end_contacts_) {
    if (penetration_[c] > 0.0 && dynamics_->behind_face_end(c, q1_)) {
      const Contact& contact = model.contacts[c];
      const std::string a = part_name(model, contact.body_a);
      const std::string b = part_name(model, contact.body_b);
      stop("unphysical penetration in contact '" + contact.name + "' (" + a + " into " + b +
           "): the " + a + ", pressed into the " + b + "'s face, went past its end and passes " +
           "through the " + b);
      return;
    }
  }
}

void Simulator::detect_events() {
  const ActionLandmarks& marks = model_->landmarks;
  const std::vector<double>& previous = penetration_;
  const std::vector<double>& current = next_penetration_;
  const std::size_t before = events_.size();
  // events wait in held_events_ while a check is being confirmed (below), so that a check
  // dated back to its contact's closing still lands in time order and among the step's new
  // events
  auto report = [&](SimEvent e) { held_events_.push_back(std::move(e)); };
  auto became_active = [&](int c) { return c >= 0 && current[c] > 0.0 && previous[c] <= 0.0; };
  // the hammer–string gap goes with each event (rare: computed only then)
  double gap = 0.0;
  bool have_gap = false;
  auto gap_now = [&] {
    if (!have_gap) {
      gap = dynamics_->hammer_string_gap(q1_);
      have_gap = true;
    }
    return gap;
  };

  if (marks.letoff_contact >= 0 && current[marks.letoff_contact] > 0.0) last_letoff_active_ = t1_;
  // reset: the jack under the knuckle (butt) with its toe off the button for 2 ms, the window in
  // which an opening counts as escapement (its bounce as it springs back is none)
  if (marks.escapement_contact >= 0 && current[marks.escapement_contact] > 0.0 &&
      (last_letoff_active_ < 0.0 || t1_ - last_letoff_active_ >= kEscapementWindow))
    jack_reset_ = true;
  // escapement: the jack leaves the knuckle (butt) within 2 ms of touching the let-off button,
  // once per stroke
  if (jack_reset_ && marks.escapement_contact >= 0 && previous[marks.escapement_contact] > 0.0 &&
      current[marks.escapement_contact] <= 0.0 && last_letoff_active_ >= 0.0 &&
      t1_ - last_letoff_active_ < kEscapementWindow) {
    report({"escapement", reported_time(t1_), 0.0, gap_now()});
    jack_reset_ = false;
  }
  if (became_active(marks.string_contact)) {
    // strike-point speed toward the string just before contact
    const Vec2 vel = dynamics_->point_velocity(marks.hammer, marks.strike_point, q0_, v0_);
    report({"impact", reported_time(t1_), -marks.string_normal.dot(vel), gap_now()});
    impact_since_check_ = true;
  }
  // check: the backcheck catches the returning hammer. A contact is a catch once it has taken a
  // fifth of the hammer's speed away from the string; one that opens before is a brush (on the
  // upright the whippen, flung up as a forte key bottoms, carries the backcheck against the
  // hammer just after the strike and lets it go on at over 90 % of its speed). The event keeps
  // the time and gap where the catching contact closed.
  if (marks.check_contact >= 0) {
    auto speed_away = [&](const DofVector& q, const DofVector& v) {
      return marks.string_normal.dot(
          dynamics_->point_velocity(marks.hammer, marks.strike_point, q, v));
    };
    if (became_active(marks.check_contact) && impact_since_check_)
      pending_check_ = PendingCheck{reported_time(t1_), gap_now(), speed_away(q0_, v0_)};
    if (pending_check_) {
      if (!(current[marks.check_contact] > 0.0)) {
        pending_check_.reset();  // a brush: the hammer goes on
      } else if (speed_away(q1_, v1_) <=
                 kCaughtSpeedFraction * std::max(pending_check_->speed, 0.0)) {
        confirm_pending_check();
      }
    }
  }
  // key_bottom: the key within a micrometre of its punching. A key moved to full dip (a
  // full-stroke motion) touches it exactly, where a penetration of ±1e-16 m decided the event
  // by rounding: the W-method reported it and the adaptive integrators did not. A key pressed
  // down crosses the micrometre within one step (5 µs at 0.2 m/s).
  const bool at_bottom = key_at_bottom(current);
  if (at_bottom) {
    if (!key_was_at_bottom_ && (last_key_bottom_ < 0.0 || t1_ - last_key_bottom_ > 5e-3))
      report({"key_bottom", reported_time(t1_), 0.0, gap_now()});
    last_key_bottom_ = t1_;
  }
  key_was_at_bottom_ = at_bottom;
  if (!pending_check_) release_held_events();
  new_events_ = static_cast<int>(events_.size() - before);
}

bool Simulator::key_at_bottom(const std::vector<double>& penetration) {
  const int c = model_->landmarks.key_bottom_contact;
  // a contact certainly apart has a bound (contact_cull.h) that may lie anywhere below zero,
  // also within the reach: its distance is read then
  return c >= 0 && penetration[c] > -kKeyBottomReach &&
         dynamics_->contact_penetration(c, q1_) > -kKeyBottomReach;
}

void Simulator::confirm_pending_check() {
  const SimEvent check{"check", pending_check_->t, 0.0, pending_check_->gap};
  // in time order among the events held since its contact closed
  auto at = held_events_.end();
  while (at != held_events_.begin() && (at - 1)->t > check.t) --at;
  held_events_.insert(at, check);
  impact_since_check_ = false;
  pending_check_.reset();
}

void Simulator::release_held_events() {
  events_.insert(events_.end(), held_events_.begin(), held_events_.end());
  held_events_.clear();
}

void Simulator::finish_events() {
  // the run ends with the catching contact still closed: a catch (it holds the hammer)
  if (pending_check_ && marks_check_closed()) confirm_pending_check();
  pending_check_.reset();
  const std::size_t before = events_.size();
  release_held_events();
  new_events_ = static_cast<int>(events_.size() - before);
}

bool Simulator::marks_check_closed() const {
  const int c = model_->landmarks.check_contact;
  return c >= 0 && static_cast<std::size_t>(c) < penetration_.size() && penetration_[c] > 0.0;
}

}  // namespace pat

// A running simulation, stepped one integrator step at a time: the immutable ActionModel plus the
// mutable state (t, q, q̇, integrator memory, event memory). The model and the input can be
// replaced between steps (live deregulation, the window's sliders and mouse key); the state is
// carried over and the integrator restarts from it.
//
// Each step is checked: a non-finite state or a contact penetration beyond the contact's limit
// stops the run with a cause naming the contact and its two parts. Events (escapement, impact,
// check, key_bottom) are detected from contact penetrations at step ends.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/action_dynamics.h"
#include "sim/simulation.h"

namespace pat {

/// An event's time as reported (s): the step's end to the nanosecond. A fixed-step integrator's
/// time is a running sum of its steps (2863 steps of 1e-5 s end at 0.028629999999999003 s); a
/// nanosecond is a ten-thousandth of the default step, far below what an event's time can tell,
/// and the integration keeps its own time.
inline double reported_time(double t) {
  return std::round(t * 1e9) / 1e9;  // 1e9 is exact: the double nearest the nanosecond count
}

/// A backcheck contact is a catch once the returning hammer has lost this much of its speed away
/// from the string; one that opens before is a brush. Shared by the simulator's check event and
/// the regulation's checking reading (regulation/technician_tests.h: BackcheckCatch).
inline constexpr double kCaughtSpeedFraction = 0.8;

/// A non-owning pointer to something the caller keeps alive for the Simulator's whole life
/// (simulate() and the technician's tests run a Simulator over a model they were handed).
template <typename T>
std::shared_ptr<const T> borrow(const T& object) {
  return std::shared_ptr<const T>(&object, [](const T*) {});
}

class Simulator {
 public:
  /// Starts at t = 0 from the rest state (computed, or `rest` when given). `input` may be null
  /// (no finger). Throws std::runtime_error when the action does not settle at rest.
  Simulator(std::shared_ptr<const ActionModel> model, std::shared_ptr<const KeyInput> input,
            const SimulationOptions& options, const RestState* rest = nullptr);

  /// One integrator step, never past `t_max`. Returns false (and does nothing) once stopped.
  bool step(double t_max);
  /// Steps until time() reaches `t` or the run stops. Returns !stopped().
  bool advance_to(double t);

  /// Replaces the model at the current step boundary; (t, q, q̇) are kept. Joints must match.
  void set_model(std::shared_ptr<const ActionModel> model);
  /// Replaces the key input at the current step boundary (a prescribed key keeps its angle
  /// only if the new input agrees; the caller makes it continuous).
  void set_input(std::shared_ptr<const KeyInput> input);
  /// Stops the run with a cause (e.g. "cancelled").
  void stop(const std::string& cause);

  double time() const { return t1_; }
  const DofVector& q() const { return q1_; }  ///< joint coordinates, rad
  const DofVector& v() const { return v1_; }  ///< joint rates, rad/s
  /// The previous step end (for interpolation between steps).
  double previous_time() const { return t0_; }
  const DofVector& previous_q() const { return q0_; }
  const DofVector& previous_v() const { return v0_; }

  bool stopped() const { return stopped_; }
  const std::string& stop_cause() const { return stop_cause_; }
  /// Signed contact penetrations at time() (m; < 0: the gap still open), by contact index.
  /// Computed on the first call after a step: the steps themselves only need their signs.
  const std::vector<double>& contact_penetrations();
  /// Whether contact `c` is closed at time(): the sign the steps keep, without the exact
  /// penetrations contact_penetrations() computes (cheap enough to ask after every step).
  bool contact_closed(int c) const { return penetration_[c] > 0.0; }
  /// Events found so far, in time order.
  const std::vector<SimEvent>& events() const { return events_; }
  /// Events reported by the latest step() (or finish_events()) call: the last ones of
  /// events(). A step that closes the backcheck contact holds its events back until the contact
  /// proves a catch (then the check, dated to the closing, comes with them in time order) or a
  /// brush, a few steps later.
  int new_event_count() const { return new_events_; }
  /// At the end of a run: a catch still being confirmed whose contact is closed is reported, and
  /// every held event released (simulate() calls it).
  void finish_events();

  const ActionModel& model() const { return *model_; }
  std::shared_ptr<const ActionModel> model_ptr() const { return model_; }
  const KeyInput* input() const { return input_.get(); }
  const RestState& rest() const { return rest_; }
  ActionDynamics& dynamics() { return *dynamics_; }
  const Integrator& integrator() const { return *integrator_; }

  /// Accelerations, contact forces and the finger force at (t, q, q̇) given.
  void evaluate(double t, const DofVector& q, const DofVector& v, DynamicsReading& out);
  /// One row of the trace (trace_columns() order) at (t, q, q̇): body angles in degrees from
  /// rest(), the hammer–string gap, the finger force, contact forces and strap tensions.
  std::vector<double> trace_row(double t, const DofVector& q, const DofVector& v);
  /// Hammer–string gap (m) at q.
  double hammer_string_gap(const DofVector& q) { return dynamics_->hammer_string_gap(q); }

  long steps() const { return steps_; }
  long rhs_evaluations() const { return rhs_evaluations_; }

 private:
  void restart_integrator();
  void detect_events();
  void check_penetrations();

  std::shared_ptr<const ActionModel> model_;
  std::shared_ptr<const KeyInput> input_;
  SimulationOptions options_;
  RestState rest_;
  std::unique_ptr<ActionDynamics> dynamics_;
  std::unique_ptr<Integrator> integrator_;
  // counters of integrators replaced by set_model/set_input
  long steps_done_before_ = 0, rhs_done_before_ = 0;
  long steps_ = 0, rhs_evaluations_ = 0;

  double t0_ = 0.0, t1_ = 0.0;
  DofVector q0_, v0_, q1_, v1_;
  // at t1_: exact where a contact may touch, a negative bound where it is surely apart (enough
  // for the events and the limit check; contact_penetrations() makes them exact on demand)
  std::vector<double> penetration_;
  bool penetration_exact_ = false;
  std::vector<double> next_penetration_;          // scratch: at the end of the step being taken
  std::vector<double> penetration_limit_;         // each contact's max_penetration, m
  std::vector<std::size_t> closed_end_contacts_;  // contacts with a closed face end
  bool stopped_ = false;
  std::string stop_cause_;
  std::vector<SimEvent> events_;
  DynamicsReading reading_;  // scratch for trace_row
  int new_events_ = 0;
  bool impact_since_check_ = false;
  // a check contact that has not yet shown itself a catch: where and when it closed, and the
  // hammer's speed away from the string just before (m/s)
  struct PendingCheck {
    double t = 0.0, gap = 0.0, speed = 0.0;
  };
  std::optional<PendingCheck> pending_check_;
  std::vector<SimEvent> held_events_;  // found while a check is pending, not yet in events_
  void confirm_pending_check();
  void release_held_events();
  bool marks_check_closed() const;
  double last_key_bottom_ = -1.0;
  bool key_was_at_bottom_ = false;  // within kKeyBottomReach of the punching at the last step
  bool key_at_bottom(const std::vector<double>& penetration);
  double last_letoff_active_ = -1.0;
  // the jack has stood under the knuckle (butt) with its toe off the let-off button since the
  // last escapement: one escapement per stroke, not one each time the checked hammer's knuckle
  // touches and leaves the side of the tripped jack
  bool jack_reset_ = true;
};

}  // namespace pat

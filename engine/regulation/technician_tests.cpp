#include "regulation/technician_tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/format.h"
#include "dynamics/action_dynamics.h"
#include "inputs/key_input.h"
#include "sim/key_travel.h"
#include "sim/simulator.h"

namespace pat {
namespace {

/// The value of a quantity (before → after over a step) where a gap (gap_before → gap_after)
/// closed or opened: linear in the step.
double at_crossing(double before, double after, double gap_before, double gap_after) {
  const double span = gap_before - gap_after;
  const double s = span != 0.0 ? gap_before / span : 1.0;
  return before + s * (after - before);
}

/// How far below its closest carried approach to the string the hammer must rest at the end of
/// the slow press, the let-off button having touched the jack toe, to count as escaped (m): four
/// times the 0.05 mm regulation tolerance, and well inside the 1.5 mm the hammer falls from
/// let-off to drop.
constexpr double kFallBack = 0.2e-3;
/// How far the hammer must have fallen from its closest carried approach for a let-off-only
/// press to stop early (m): two thirds of the 1.5 mm fall from let-off to drop, five times the
/// knuckle's bounce as the jack takes over from a repetition lever stopped by its drop screw
/// (0.2 mm, measured on the shipped grand).
constexpr double kClearFall = 1.0e-3;

}  // namespace

std::string slow_press_spec() {
  return "motion:press:" + format_number(kSlowPressSeconds, 12);
}

std::string forte_blow_spec() {
  return "force:const:" + format_number(kForteBlowNewtons, 12);
}

double contact_gap(const ActionModel& model, int contact_index, const DofVector& q) {
  ActionDynamics dynamics(model, nullptr);
  std::vector<double> penetration;
  dynamics.contact_penetrations(q, penetration);
  return -penetration[contact_index];
}

SlowPressReading slow_press(const ActionModel& model, const RestState& rest, int damper_contact,
                            bool until_escapement) {
  const ActionLandmarks& marks = model.landmarks;
  const double depth = key_full_dip_angle(model, rest);
  SimulationOptions options;
  // CVODE's adaptive steps grow long in the quasi-static press; its tolerance keeps the hammer
  // position to ~1 µm, far inside the 0.05 mm regulation tolerance
  options.integrator = "cvode";
  options.integrator_options.relative_tolerance = 1e-6;
  options.integrator_options.absolute_tolerance = 1e-9;
  options.integrator_options.max_step_s = 2e-3;
  options.sample_interval_s = 0.0;
  std::shared_ptr<const KeyInput> input = parse_input_spec(slow_press_spec(), {depth});
  Simulator sim(borrow(model), input, options, &rest);
  auto gap_of = [&sim](int contact) { return -sim.contact_penetrations()[contact]; };

  SlowPressReading reading;
  // the key-front travel left to the punching (the press's depth is its first touch) from a key
  // angle (rad from rest)
  auto aftertouch_after = [&](double key_angle) {
    return key_front_travel(model, rest, depth) - key_front_travel(model, rest, key_angle);
  };
  bool damper_lifted = damper_contact < 0;
  bool letoff_touched = false, jack_carried = false;
  double key_at_let_off = 0.0;  // rad from rest, where the closest carried approach was
  // closest approach of the hammer to the string while the jack still touches the knuckle: the
  // point where the hammer stops rising and falls back (what the technician sees as let-off;
  // the contact itself opens a little later, once the knuckle has slid off the jack's corner)
  double closest_carried_gap = std::numeric_limits<double>::infinity();
  // and by whatever carries it (the jack or, too high, the repetition lever), for the message
  double closest_gap = std::numeric_limits<double>::infinity();
  double previous_gap = sim.hammer_string_gap(sim.q());
  double previous_damper = damper_contact >= 0 ? gap_of(damper_contact) : 0.0;
  if (!damper_lifted && previous_damper <= 0.0)
    throw std::runtime_error("the damper already rests on its lifter at rest");
  const double end = kSlowPressSeconds + kSlowPressHoldSeconds;
  while (sim.time() < end - 1e-12) {
    if (!sim.step(end))
      throw std::runtime_error("the slow key press stopped at t = " + std::to_string(sim.time()) +
                               " s: " + sim.stop_cause());
    const double gap = sim.hammer_string_gap(sim.q());
    const double escapement = gap_of(marks.escapement_contact);
    closest_gap = std::min(closest_gap, gap);
    if (gap_of(marks.letoff_contact) <= 0.0) letoff_touched = true;
    if (!letoff_touched && marks.check_contact >= 0 && gap_of(marks.check_contact) <= 0.0)
      throw BackcheckStopsTheRisingHammer(
          "in a slow key press the hammer's tail meets the backcheck on its way up, " +
          format_number((rest.hammer_string_gap - gap) * 1e3) +
          " mm above rest, before let-off (the backcheck is too close)");
    if (escapement <= 0.0) {
      jack_carried = true;
      if (gap < closest_carried_gap) {
        closest_carried_gap = gap;
        key_at_let_off = sim.q()[marks.key] - rest.q[marks.key];
      }
    }
    if (!damper_lifted) {
      const double damper = gap_of(damper_contact);
      if (damper <= 0.0) {
        // the hammer's travel tells the lift only while the key drives the hammer: a damper
        // lifting after let-off, with the hammer falling back from its closest carried
        // approach, would read an ever earlier fraction the later it lifts
        if (jack_carried && gap > closest_carried_gap + kFallBack)
          throw std::runtime_error(
              "in a slow key press the damper starts to lift only after the jack has escaped");
        const double at_lift = at_crossing(previous_gap, gap, previous_damper, damper);
        reading.damper_lift_fraction = (rest.hammer_string_gap - at_lift) / rest.hammer_string_gap;
        damper_lifted = true;
      }
      previous_damper = damper;
    }
    previous_gap = gap;
    // the hammer has fallen well away from the jack top that carried it: the jack has escaped
    // and a press for the let-off alone may end here
    if (until_escapement && damper_lifted && letoff_touched && jack_carried &&
        gap > closest_carried_gap + kClearFall) {
      reading.let_off_gap = closest_carried_gap;
      reading.aftertouch = aftertouch_after(key_at_let_off);
      return reading;
    }
  }
  // Escapement, as the technician sees it: the hammer, held at the bottom of the press, rests
  // clearly below its closest carried approach to the string (it fell onto the repetition lever
  // or the backcheck). The jack-knuckle (butt) contact opening during the press is no criterion:
  // it opens for an instant when the knuckle bounces as the jack takes over from a repetition
  // lever stopped by its drop screw, and it may stay closed after escapement with the knuckle
  // resting against the side of the tipped jack (as on a real grand with the key held down).
  // The one escape without a fall: a let-off button turned so far down that the jack trips before
  // the repetition lever meets its drop screw; the lever then carries the hammer on up to the
  // screw and holds it no lower than where the jack left it. At the end of that press the jack,
  // held tipped on its button, stands clear of the knuckle.
  const double held_gap = sim.hammer_string_gap(sim.q());
  // (only with a repetition lever stopped by a drop screw, and the hammer held off the string:
  // an upright's hammer pushed up to the string by its backcheck, say, has not escaped so)
  const bool lever_holds_it = model.setting_index("drop") >= 0 && held_gap > 0.0;
  const bool tripped_clear = lever_holds_it && gap_of(marks.letoff_contact) <= 0.0 &&
                             gap_of(marks.escapement_contact) > 0.0;
  const bool escaped = letoff_touched && jack_carried &&
                       (held_gap > closest_carried_gap + kFallBack || tripped_clear);
  if (escaped) {
    reading.let_off_gap = closest_carried_gap;
    reading.aftertouch = aftertouch_after(key_at_let_off);
  }
  if (!escaped && !jack_carried) {
    // what the technician sees, with its distance first: the hammer rising to a point and
    // staying there, with no let-off to read
    char seen[160];
    std::snprintf(seen, sizeof seen, "up to %.1f mm from the string and holds it at %.1f mm",
                  closest_gap * 1e3, held_gap * 1e3);
    throw HammerCarriedElsewhere(
        model.setting_index("drop") >= 0
            ? std::string("in a slow key press the jack never lifts the hammer: the repetition "
                          "lever carries it ") +
                  seen +
                  ", so neither let-off nor drop is seen in this press (the drop screw stops "
                  "the lever only after the "
                  "let-off button has tripped the jack: the drop screw is too high or the "
                  "let-off button too low; let-off is set with the drop screw out of the way: "
                  "screw the drop screw down (drop +) to see this let-off, or the button back "
                  "up (let-off −))"
            : std::string("in a slow key press the jack never lifts the hammer: another part "
                          "carries it ") +
                  seen + ", so no let-off is seen",
        held_gap);
  }
  if (!escaped)
    throw JackNeverEscapes(
        "in a slow key press the jack never escapes (the jack toe does not trip on the let-off "
        "button before the key bottoms)",
        held_gap,
        damper_contact >= 0 && damper_lifted ? reading.damper_lift_fraction
                                             : std::numeric_limits<double>::quiet_NaN());
  if (!damper_lifted) throw std::runtime_error("in a slow key press the damper never lifts");
  reading.drop_gap = held_gap;
  reading.checked_at_end = gap_of(marks.check_contact) <= 0.0;
  return reading;
}

bool BackcheckCatch::update(double t, double gap, double check_gap, bool struck,
                            const std::function<double()>& backcheck_share) {
  const double dt = t - t_;
  const double speed = dt > 0.0 ? (gap - gap_) / dt : 0.0;  // m/s, + away from the string
  const bool closed = struck && check_gap_ > 0.0 && check_gap <= 0.0;
  const double closed_at = closed ? at_crossing(gap_, gap, check_gap_, check_gap) : 0.0;
  const double before = free_speed_;  // the step that closes it may already brake
  t_ = t;
  gap_ = gap;
  check_gap_ = check_gap;
  free_speed_ = speed;
  if (closed && backcheck_share() <= 0.5) {  // the hammer ran into the backcheck
    caught_gap_ = closed_at;
    return true;
  }
  if (closed && !touching_) {  // the backcheck ran into the hammer: a catch if it holds it back
    touching_ = true;
    touch_gap_ = closed_at;
    touch_speed_ = std::max(before, 0.0);
  }
  if (!touching_) return false;
  if (speed <= kCaughtSpeedFraction * touch_speed_) {
    caught_gap_ = touch_gap_;
    return true;
  }
  if (check_gap > 0.0) touching_ = false;  // a brush: the backcheck let the hammer go on
  return false;
}

namespace {

/// The part (0–1) of a contact gap's closing from `before` to `after` that is due to the motion
/// of its body B (the backcheck's side) and B's ancestors: the gap with them held at `before`,
/// against the gap's whole change. 0 when the gap did not close.
double closing_share_of_body_b(ActionDynamics& dynamics, const ActionModel& model, int contact,
                               const DofVector& before, const DofVector& after) {
  std::vector<double> penetration;
  dynamics.contact_penetrations(before, penetration);
  const double gap_before = -penetration[contact];
  dynamics.contact_penetrations(after, penetration);
  const double gap_after = -penetration[contact];
  if (gap_after >= gap_before) return 0.0;
  DofVector held = after;  // body B and its ancestors where they were
  for (int b = model.contacts[contact].body_b; b >= 0; b = model.bodies[b].parent)
    held[b] = before[b];
  dynamics.contact_penetrations(held, penetration);
  const double gap_held = -penetration[contact];
  return std::clamp((gap_held - gap_after) / (gap_before - gap_after), 0.0, 1.0);
}

}  // namespace

SimulatedBackcheckCatch::SimulatedBackcheckCatch(const ActionModel& model, Simulator& sim)
    : model_(model),
      dynamics_(std::make_unique<ActionDynamics>(model, nullptr)),
      watch_(sim.time(), sim.hammer_string_gap(sim.q()),
             -sim.contact_penetrations()[model.landmarks.check_contact]) {}

SimulatedBackcheckCatch::~SimulatedBackcheckCatch() = default;

bool SimulatedBackcheckCatch::update(Simulator& sim, bool struck) {
  const int check = model_.landmarks.check_contact;
  const auto share = [&] {
    return closing_share_of_body_b(*dynamics_, model_, check, sim.previous_q(), sim.q());
  };
  return watch_.update(sim.time(), sim.hammer_string_gap(sim.q()),
                       -sim.contact_penetrations()[check], struck, share);
}

SimulationOptions forte_blow_options() {
  SimulationOptions options;
  // the error-controlled CVODE rather than the fixed-step W-method: at 1e-5 s the W-method's
  // hammer position wanders by a few hundredths of a millimetre with the moment its frozen
  // Jacobian is refreshed (F8: 0.02 deg at the strike radius is 0.05 mm), as much as the
  // checking tolerance; at rtol 1e-7 the reading repeats to about a micrometre
  options.integrator = "cvode";
  options.integrator_options.relative_tolerance = 1e-7;
  options.integrator_options.absolute_tolerance = 1e-10;
  options.integrator_options.max_step_s = 1e-3;
  options.sample_interval_s = 0.0;
  return options;
}

ForteBlowReading forte_blow(const ActionModel& model, const RestState& rest) {
  const SimulationOptions options = forte_blow_options();
  const InputContext context = input_context(model, rest);
  std::shared_ptr<const KeyInput> input = parse_input_spec(forte_blow_spec(), context);
  Simulator sim(borrow(model), input, options, &rest);
  ForteBlowReading reading;
  bool struck = false;
  SimulatedBackcheckCatch catch_watch(model, sim);
  while (sim.time() < kForteHoldSeconds) {
    if (!sim.step(kForteHoldSeconds))
      throw std::runtime_error("the forte blow stopped at t = " + std::to_string(sim.time()) +
                               " s: " + sim.stop_cause());
    if (!struck && sim.new_event_count() > 0) {
      for (auto e = sim.events().end() - sim.new_event_count(); e != sim.events().end(); ++e)
        if (e->type == "impact") {
          struck = true;
          reading.impact_velocity = e->hammer_velocity;
        }
    }
    // caught: the hammer's tail (catcher) meets the backcheck on its way back from the string
    // (not brushed by it)
    if (catch_watch.update(sim, struck)) {
      reading.checked_gap = catch_watch.caught_gap();
      return reading;
    }
  }
  if (!struck) throw std::runtime_error("in a forte blow the hammer never reaches the string");
  throw std::runtime_error("after a forte blow the backcheck never catches the hammer");
}

}  // namespace pat

#include "regulation/technician_tests.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "dynamics/action_dynamics.h"
#include "inputs/key_input.h"
#include "sim/key_travel.h"
#include "sim/simulator.h"

namespace pat {
namespace {

/// The key pressed from rest to `depth` (rad) along a half cosine in `duration`, then held.
class SlowPressMotion final : public KeyInput {
 public:
  SlowPressMotion(double depth, double duration)
      : depth_(depth), duration_(duration), spec_("slow press") {}
  bool is_motion() const override { return true; }
  double force_n(double) const override { return 0.0; }
  KeyMotionSample motion(double t) const override {
    if (t >= duration_) return {depth_, 0.0, 0.0};
    const double w = M_PI / duration_;
    return {0.5 * depth_ * (1.0 - std::cos(w * t)), 0.5 * depth_ * w * std::sin(w * t),
            0.5 * depth_ * w * w * std::cos(w * t)};
  }
  const std::string& spec() const override { return spec_; }

 private:
  double depth_, duration_;
  std::string spec_;
};

/// Where a quantity crossed zero between two steps: the fraction of the step (linear).
double crossing_fraction(double before, double after) {
  const double span = before - after;
  return span != 0.0 ? before / span : 1.0;
}

}  // namespace

double contact_gap(const ActionModel& model, int contact_index, const DofVector& q) {
  ActionDynamics dynamics(model, nullptr);
  return contact_gap(dynamics, contact_index, q);
}

double contact_gap(ActionDynamics& dynamics, int contact_index, const DofVector& q) {
  const Contact& c = dynamics.model().contacts[contact_index];
  const Vec2 center = dynamics.point_position(c.body_a, c.center_a, q);
  if (c.shape == ContactShape::CircleCircle) {
    const Vec2 other = dynamics.point_position(c.body_b, c.center_b, q);
    return (center - other).norm() - (c.radius_a + c.radius_b);
  }
  const Vec2 s0 = dynamics.point_position(c.body_b, c.segment_start, q);
  const Vec2 s1 = dynamics.point_position(c.body_b, c.segment_end, q);
  const Vec2 normal = dynamics.point_position(c.body_b, c.segment_start + c.segment_normal, q) - s0;
  const Vec2 u = s1 - s0;
  const double t = (center - s0).dot(u) / u.squaredNorm();
  const bool beside = c.radius_b > 0.0 && normal.dot(center - s0) < 0.0;
  if (t >= 0.0 && t <= 1.0 && !beside) return normal.dot(center - s0) - c.radius_a;
  const Vec2 corner = (t < 0.5 ? s0 : s1) - c.radius_b * normal;
  return (center - corner).norm() - (c.radius_a + c.radius_b);
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
  auto input = std::make_shared<SlowPressMotion>(depth, kSlowPressSeconds);
  Simulator sim(std::shared_ptr<const ActionModel>(&model, [](const ActionModel*) {}), input,
                options, &rest);

  ActionDynamics gauge(model, nullptr);
  SlowPressReading reading;
  bool escaped = false, damper_lifted = damper_contact < 0;
  bool letoff_touched = false, jack_carried = false;
  double previous_gap = sim.hammer_string_gap(sim.q());
  double previous_escapement = contact_gap(gauge, marks.escapement_contact, sim.q());
  double previous_damper = damper_contact >= 0 ? contact_gap(gauge, damper_contact, sim.q()) : 0.0;
  if (!damper_lifted && previous_damper <= 0.0)
    throw std::runtime_error("the damper already rests on its lifter at rest");
  const double end = kSlowPressSeconds + kSlowPressHoldSeconds;
  while (sim.time() < end - 1e-12) {
    if (!sim.step(end))
      throw std::runtime_error("the slow key press stopped at t = " + std::to_string(sim.time()) +
                               " s: " + sim.stop_cause());
    const double gap = sim.hammer_string_gap(sim.q());
    const double escapement = contact_gap(gauge, marks.escapement_contact, sim.q());
    if (contact_gap(gauge, marks.letoff_contact, sim.q()) <= 0.0) letoff_touched = true;
    if (escapement <= 0.0) jack_carried = true;
    // escapement: the jack leaves the knuckle (butt) once the let-off button has tipped it
    if (!escaped && letoff_touched && previous_escapement <= 0.0 && escapement > 0.0) {
      const double s = crossing_fraction(previous_escapement, escapement);
      reading.let_off_gap = previous_gap + s * (gap - previous_gap);
      escaped = true;
    }
    if (!damper_lifted) {
      const double damper = contact_gap(gauge, damper_contact, sim.q());
      if (damper <= 0.0) {
        const double s = crossing_fraction(previous_damper, damper);
        const double at_lift = previous_gap + s * (gap - previous_gap);
        reading.damper_lift_fraction =
            (rest.hammer_string_gap - at_lift) / rest.hammer_string_gap;
        damper_lifted = true;
      }
      previous_damper = damper;
    }
    previous_gap = gap;
    previous_escapement = escapement;
    if (escaped && damper_lifted && until_escapement) return reading;
  }
  if (!escaped && !jack_carried)
    throw std::runtime_error(
        "in a slow key press the jack never lifts the hammer (it is carried by another part, "
        "e.g. the repetition lever when the drop screw is too high)");
  if (!escaped)
    throw std::runtime_error(
        "in a slow key press the jack never escapes (the jack toe does not trip on the let-off "
        "button before the key bottoms)");
  if (!damper_lifted)
    throw std::runtime_error("in a slow key press the damper never lifts");
  reading.drop_gap = sim.hammer_string_gap(sim.q());
  reading.checked_at_end = contact_gap(gauge, marks.check_contact, sim.q()) <= 0.0;
  return reading;
}

ForteBlowReading forte_blow(const ActionModel& model, const RestState& rest) {
  const ActionLandmarks& marks = model.landmarks;
  SimulationOptions options;
  options.integrator = "w2";
  options.sample_interval_s = 0.0;
  const InputContext context = input_context(model, rest);
  std::shared_ptr<const KeyInput> input =
      parse_input_spec("force:const:" + std::to_string(kForteBlowNewtons), context);
  Simulator sim(std::shared_ptr<const ActionModel>(&model, [](const ActionModel*) {}), input,
                options, &rest);
  ActionDynamics gauge(model, nullptr);
  ForteBlowReading reading;
  bool struck = false;
  double previous_gap = sim.hammer_string_gap(sim.q());
  double previous_check = contact_gap(gauge, marks.check_contact, sim.q());
  const double limit = 0.3;
  while (sim.time() < limit) {
    if (!sim.step(limit))
      throw std::runtime_error("the forte blow stopped at t = " + std::to_string(sim.time()) +
                               " s: " + sim.stop_cause());
    const double gap = sim.hammer_string_gap(sim.q());
    const double check = contact_gap(gauge, marks.check_contact, sim.q());
    if (!struck && sim.new_event_count() > 0) {
      for (auto e = sim.events().end() - sim.new_event_count(); e != sim.events().end(); ++e)
        if (e->type == "impact") {
          struck = true;
          reading.impact_velocity = e->hammer_velocity;
        }
    }
    // caught: the hammer's tail (catcher) meets the backcheck on its way back from the string
    if (struck && previous_check > 0.0 && check <= 0.0) {
      const double s = crossing_fraction(previous_check, check);
      reading.checked_gap = previous_gap + s * (gap - previous_gap);
      return reading;
    }
    previous_gap = gap;
    previous_check = check;
  }
  if (!struck) throw std::runtime_error("in a forte blow the hammer never reaches the string");
  throw std::runtime_error("after a forte blow the backcheck never catches the hammer");
}

}  // namespace pat

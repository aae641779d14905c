#include "sim/key_travel.h"

#include <stdexcept>

#include "dynamics/action_dynamics.h"
#include "model/model_edits.h"

namespace pat {
namespace {

/// Signed penetration of the key-bottom contact with the key turned to `angle` (absolute joint
/// value); negative: the gap still open.
double bottom_penetration(const ActionModel& model, ActionDynamics& dynamics, DofVector q,
                          double angle) {
  q[model.landmarks.key] = angle;
  std::vector<double> penetration;
  dynamics.contact_penetrations(q, penetration);
  return penetration[model.landmarks.key_bottom_contact];
}

}  // namespace

double key_full_dip_angle(const ActionModel& model, const RestState& rest) {
  ActionDynamics dynamics(model, nullptr);
  const double start = rest.q[model.landmarks.key];
  // scan outward in steps of kProbeStep (about 2 mm at the front of a 220 mm key arm) for the
  // first angle where the key presses into its punching: one long jump could carry the key's
  // front past the punching's far end, where the contact no longer sees it
  constexpr double kProbeStep = 0.01;  // rad
  constexpr double kProbeReach = 0.3;  // rad: some 60 mm at the key front, six times a key dip
  double lo = start, hi = start;
  bool reached = false;
  for (double turn = kProbeStep; turn <= kProbeReach + 1e-12 && !reached; turn += kProbeStep) {
    lo = hi;
    hi = start + turn;
    reached = bottom_penetration(model, dynamics, rest.q, hi) > 0.0;
  }
  if (!reached)
    throw std::runtime_error(model_origin(model) +
                             ": the key never reaches its front-rail punching");
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bottom_penetration(model, dynamics, rest.q, mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi) - start;
}

double key_front_travel(const ActionModel& model, const RestState& rest, double key_angle) {
  ActionDynamics dynamics(model, nullptr);
  DofVector q = rest.q;
  const Vec2 at_rest = dynamics.point_position(model.landmarks.key, model.landmarks.key_front, q);
  q[model.landmarks.key] += key_angle;
  const Vec2 moved = dynamics.point_position(model.landmarks.key, model.landmarks.key_front, q);
  return at_rest.y() - moved.y();
}

InputContext input_context(const ActionModel& model, const RestState& rest) {
  InputContext context;
  context.full_dip_angle_rad = key_full_dip_angle(model, rest);
  return context;
}

}  // namespace pat

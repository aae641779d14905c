#include "live_key_input.h"

#include <algorithm>
#include <cmath>

namespace pat::ui {

LiveKeyInput::LiveKeyInput(double t0, double angle_rad, double rate_rad_s, double max_angle_rad)
    : target_(std::clamp(angle_rad, 0.0, max_angle_rad)),
      max_angle_(max_angle_rad),
      t0_(t0),
      angle0_(angle_rad),
      rate0_(rate_rad_s),
      angle1_(target_.load()) {}

void LiveKeyInput::set_target(double angle_rad) {
  target_.store(std::clamp(angle_rad, 0.0, max_angle_));
}

KeyMotionSample LiveKeyInput::motion(double t) const {
  const double s = (t - t0_) / duration_;
  if (s >= 1.0) return {angle1_, 0.0, 0.0};
  if (s <= 0.0) return {angle0_, rate0_, 0.0};
  // cubic Hermite: angle0, rate0 at s = 0; angle1, rate 0 at s = 1
  const double h = duration_;
  const double d = angle1_ - angle0_;
  const double m0 = rate0_ * h;
  const double c3 = -2.0 * d + m0;
  const double c2 = 3.0 * d - 2.0 * m0;
  KeyMotionSample out;
  out.angle = angle0_ + m0 * s + c2 * s * s + c3 * s * s * s;
  out.rate = (m0 + 2.0 * c2 * s + 3.0 * c3 * s * s) / h;
  out.acceleration = (2.0 * c2 + 6.0 * c3 * s) / (h * h);
  return out;
}

bool LiveKeyInput::update(double t, double transition_s) {
  const double goal = target_.load();
  if (goal == angle1_) return false;
  const KeyMotionSample now = motion(t);
  t0_ = t;
  angle0_ = now.angle;
  rate0_ = now.rate;
  angle1_ = goal;
  // no faster than a fortissimo finger: full dip in kFastestDipSeconds
  const double slowest_allowed = std::abs(goal - now.angle) / max_angle_ * kFastestDipSeconds;
  duration_ = std::max({transition_s, slowest_allowed, 1e-4});
  return true;
}

}  // namespace pat::ui

// The key played with the mouse: a prescribed key motion whose target angle the window sets
// while the simulation runs. The worker moves toward each new target along a cubic that starts
// from the current angle and rate and ends at rest on the target after `transition_s`, so the
// key rate and acceleration stay finite however the mouse jumps, and the key never moves
// faster than a fortissimo finger.
#pragma once

#include <atomic>
#include <string>

#include "inputs/key_input.h"

namespace pat::ui {

class LiveKeyInput : public KeyInput {
 public:
  /// The fastest key descent from rest to full dip (s), about a fortissimo blow: a jump of the
  /// mouse never moves the key faster.
  static constexpr double kFastestDipSeconds = 0.02;

  /// Starts at `angle_rad` (from rest, positive down) moving at `rate_rad_s` at time `t0`;
  /// targets are kept within [0, max_angle_rad].
  LiveKeyInput(double t0, double angle_rad, double rate_rad_s, double max_angle_rad);

  bool is_motion() const override { return true; }
  double force_n(double) const override { return 0.0; }
  KeyMotionSample motion(double t) const override;
  const std::string& spec() const override { return spec_; }

  /// Any thread: the angle the key should go to (rad from rest).
  void set_target(double angle_rad);
  double target() const { return target_.load(); }
  double max_angle() const { return max_angle_; }

  /// Worker thread, at a step boundary: starts a transition to the latest target if it moved.
  /// Returns true when the motion changed (the integrator must restart).
  bool update(double t, double transition_s);

 private:
  std::atomic<double> target_;
  double max_angle_;
  // current transition: from (angle0, rate0) at t0 to (angle1, 0) at t0 + duration
  double t0_, angle0_, rate0_ = 0.0, angle1_, duration_ = 1e-3;
  std::string spec_ = "live:mouse";
};

}  // namespace pat::ui

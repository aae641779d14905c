// The technician's tests on the simulated action, as building blocks of the measurements:
// contact gaps at rest, the slow key press (let-off, drop, damper lift) and the forte blow
// (checking).
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>

#include "model/action_model.h"
#include "sim/simulation.h"
#include "sim/simulator.h"

namespace pat {

class ActionDynamics;
class Simulator;

/// Signed gap of contact `contact` at q (m): > 0 apart (the distance still to close), < 0 when
/// the parts overlap (minus the penetration). Same geometry as the dynamics (contact_geometry.h).
double contact_gap(const ActionModel& model, int contact, const DofVector& q);

/// A slow press in which the jack never lifts the hammer: another part carries it (the grand's
/// repetition lever when the drop screw is too high). The regulation tells it from other
/// failures: the way out is to move that part out of the way, not to search further.
class HammerCarriedElsewhere : public std::runtime_error {
 public:
  /// `held_gap`: the hammer–string distance (m) at which the other part holds it.
  HammerCarriedElsewhere(const std::string& what, double held_gap)
      : std::runtime_error(what), held_gap_(held_gap) {}
  double held_gap() const { return held_gap_; }

 private:
  double held_gap_;
};

/// A slow press in which the hammer's tail meets the backcheck on its way up, before the jack
/// trips on the let-off button: the backcheck is bent so close that it stops the rising hammer,
/// and what the press would read is where the backcheck holds it. The regulation bends the
/// backcheck back first.
class BackcheckStopsTheRisingHammer : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A slow press in which the jack never lets the hammer go: with the key held down the hammer
/// still rests within 0.2 mm of its closest approach to the string, and (on a grand) the jack
/// does not stand tipped clear of the knuckle with the repetition lever holding the hammer off
/// the string (slow_press in technician_tests.cpp). What a technician still
/// sees: `held_gap()`, the hammer–string distance with the key held down (m), and
/// `damper_lift_fraction()`, as in SlowPressReading (NaN when the damper did not lift or was not
/// watched).
class JackNeverEscapes : public std::runtime_error {
 public:
  JackNeverEscapes(const std::string& what, double held_gap, double damper_lift_fraction)
      : std::runtime_error(what),
        held_gap_(held_gap),
        damper_lift_fraction_(damper_lift_fraction) {}
  double held_gap() const { return held_gap_; }
  double damper_lift_fraction() const { return damper_lift_fraction_; }

 private:
  double held_gap_, damper_lift_fraction_;
};

struct SlowPressReading {
  double let_off_gap = 0.0;           ///< m, hammer–string distance at let-off: the closest
                                      ///< approach while the jack carries the hammer
  double drop_gap = 0.0;              ///< m, hammer–string distance at the end, key held down
  double damper_lift_fraction = 0.0;  ///< hammer travel fraction when the damper contact starts
  bool checked_at_end = false;        ///< the backcheck holds the hammer at the end
  /// m, key-front travel left to the front-rail punching at let-off (the technician's
  /// aftertouch, gauged with the jack just tripping on its button); NaN without an escapement
  double aftertouch = std::numeric_limits<double>::quiet_NaN();
};

/// Duration of the slow press: the key goes from rest to full dip along a half cosine in
/// this time, then is held while the hammer settles.
inline constexpr double kSlowPressSeconds = 1.0;
inline constexpr double kSlowPressHoldSeconds = 0.4;
/// The slow press as an input SPEC (motion:press:SECONDS, inputs/key_input.h).
std::string slow_press_spec();

/// Presses the key slowly (quasi-static: the hammer's speed stays below ~0.05 m/s) to full dip
/// and holds it. `damper_contact` (-1: none) is the contact whose first touch marks the damper
/// lift. Throws std::runtime_error naming what did not happen (no escapement, a stopped run, a
/// damper that lifts only after the jack has escaped), HammerCarriedElsewhere or
/// BackcheckStopsTheRisingHammer.
/// With `until_escapement`, the press ends once the jack escapes (let-off only: drop_gap and
/// checked_at_end are then not read).
SlowPressReading slow_press(const ActionModel& model, const RestState& rest, int damper_contact,
                            bool until_escapement = false);

struct ForteBlowReading {
  double impact_velocity = 0.0;  ///< m/s
  double checked_gap = 0.0;      ///< m, hammer–string distance when the backcheck catches it
};

/// Force of the forte blow (N at the key front, held so that the key stays down).
inline constexpr double kForteBlowNewtons = 40.0;
/// The forte blow as an input SPEC (force:const:N).
std::string forte_blow_spec();
/// How long the forte blow is followed, key held (s): strike, rebound and check settle in it.
inline constexpr double kForteHoldSeconds = 0.3;

/// Reads the backcheck's catch on a forte blow's rebound, step by step: the hammer–string gap
/// where the catcher meets the backcheck on its way back from the string. A contact closed
/// mostly by the backcheck's own motion (more than half of the gap's closing over the step)
/// that opens again before it has taken a fifth of the returning hammer's speed is a brush,
/// not a catch: on the upright the whippen, flung off the capstan as a forte key bottoms,
/// carries the backcheck against the hammer just after the strike (3.6 mm from the string)
/// and lets it go on at 94 % of its speed. Any other contact is the catch, read where the gap
/// closed (the grand's backcheck stands on the resting key: its tail runs into it).
class BackcheckCatch {
 public:
  /// `gap`: hammer–string distance (m); `check_gap`: catcher–backcheck gap (m, ≤ 0 touching).
  BackcheckCatch(double t, double gap, double check_gap)
      : t_(t), gap_(gap), check_gap_(check_gap) {}

  /// After each step; `struck`: the hammer has reached the string; `backcheck_share()`: the
  /// part of the step's closing of the check gap due to the backcheck's own motion (0–1; asked
  /// only on the step that closes it). True once caught.
  bool update(double t, double gap, double check_gap, bool struck,
              const std::function<double()>& backcheck_share);
  /// m, valid once update() returned true.
  double caught_gap() const { return caught_gap_; }

 private:
  double t_, gap_, check_gap_;
  double free_speed_ = 0.0;                     ///< m/s away from the string over the previous step
  bool touching_ = false;                       ///< in a contact that may still prove a brush
  double touch_gap_ = 0.0, touch_speed_ = 0.0;  ///< m, m/s away from the string
  double caught_gap_ = 0.0;
};

/// BackcheckCatch fed by a running simulation: after each step it reads the hammer–string and
/// check gaps and, on the step that closes the check contact, the backcheck's share of that
/// closing (from the step's start, Simulator::previous_q(), to its end). Used by every procedure
/// that reads the forte blow's catch, so that they read the same one.
class SimulatedBackcheckCatch {
 public:
  SimulatedBackcheckCatch(const ActionModel& model, Simulator& sim);
  ~SimulatedBackcheckCatch();
  /// After each step; `struck`: the hammer has reached the string. True once caught.
  bool update(Simulator& sim, bool struck);
  /// m, valid once update() returned true.
  double caught_gap() const { return watch_.caught_gap(); }

 private:
  const ActionModel& model_;
  std::unique_ptr<ActionDynamics> dynamics_;  ///< for the backcheck's share of a closing
  BackcheckCatch watch_;
};

/// The simulation options of the forte blow (also for other procedures that must read the same
/// catch, e.g. the practice mode's observations).
SimulationOptions forte_blow_options();

/// A forte blow with the key held down: the hammer strikes, falls back and is caught by the
/// backcheck; the distance is read where the catcher meets the backcheck and is held back by
/// it (BackcheckCatch: a brush of the backcheck is not a catch). Throws
/// std::runtime_error when the hammer does not strike or is not caught.
ForteBlowReading forte_blow(const ActionModel& model, const RestState& rest);

}  // namespace pat

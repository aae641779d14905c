// The technician's swing test of the hammer flange (paper section 6, Fig. 16; domain.md
// section 6): the hammer alone on its centre pin, held with the line from the pin to its centre
// of mass horizontal and released; it swings under gravity against the joint friction
// (paper eq. 4) and the technician counts the round trips until it stops.
//
// Angle φ: of the pin → centre-of-mass line from straight down (rad, released at φ0 = π/2).
// A half swing runs from one turning point (φ̇ = 0) to the next; a round trip is two.
// "Stopped": at a turning point where gravity can no longer overcome the joint's Coulomb level A
// (the saturation of eq. 4; its B1 term vanishes at rest):  m g d sin|φ| ≤ A, i.e.
// |φ| ≤ φ_stick = asin(A / (m g d)), d = |centre of mass − pin|. A real flange sticks there; the
// regularized law would only creep on. More generally the hammer has stopped once its energy
// above hanging, ½ I_p φ̇² + m g d (1 − cos φ), is below m g d (1 − cos φ_stick): it can no
// longer reach a turning point outside the stick zone (this also ends a swing that dies out
// without turning). The half swing under way then does not count.
#pragma once

#include <vector>

#include "analysis/progress.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

struct SwingOptions {
  double release_angle_rad = 1.5707963267948966;  ///< φ0 (π/2: horizontal)
  double max_duration_s = 30.0;                   ///< gives up (stopped = false) after this
  double relative_tolerance = 1e-8;               ///< of the adaptive Rosenbrock integrator
  double sample_interval_s = 1e-3;                ///< trace row spacing
};

struct SwingResult {
  double round_trips = 0.0;  ///< half swings / 2
  int half_swings = 0;
  bool stopped = false;          ///< false: still swinging at max_duration_s
  double stop_time_s = 0.0;      ///< time of the stop (or max_duration_s)
  double stick_angle_deg = 0.0;  ///< φ_stick
  std::vector<double> turning_times_s;
  std::vector<double> turning_amplitudes_deg;  ///< |φ| at each turning point
  double first_half_period_s = 0.0;            ///< release to the first turning point
  double pin_to_com_m = 0.0;                   ///< d
  double inertia_about_pin_kgm2 = 0.0;         ///< I_com + m d²
  CsvTable trace;  ///< time_s, swing_angle_deg (φ), swing_rate_deg_per_s
};

/// Runs the swing test on the hammer of `action` (taken out alone, isolated_body_model).
/// `progress` (may be empty) sees the fraction of max_duration_s; returning false throws
/// Cancelled.
SwingResult swing_test(const ActionModel& action, const SwingOptions& options = {},
                       const ProgressCallback& progress = {});

}  // namespace pat

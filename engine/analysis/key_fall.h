// The paper's key characterisation (section 4.3, Fig. 6a): the key alone on its balance pin,
// released from rest at its position in the resting action, falls front-down under gravity (its
// front is heavier without the action on its back) against the balance-pin friction (eq. 4)
// until its front meets the front-rail punching, where it bounces and settles.
//
// Before contact the key is a rigid lever on a pin:  I_p θ̈ = m g·(arm) − T_friction, so without
// friction ½ I_p θ̇² = m g Δh_com (energy) and, for the 2–3° of a key dip, θ(t) ≈ ½ α0 t².
#pragma once

#include <optional>

#include "analysis/progress.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

struct KeyFallOptions {
  double duration_s = 0.3;
  double relative_tolerance = 1e-7;  ///< of the adaptive Rosenbrock integrator
  double sample_interval_s = 1e-4;   ///< trace row spacing
  /// Key joint coordinate at release (rad); empty: the key's angle in the action's rest state.
  std::optional<double> start_angle_rad;
};

struct KeyFallResult {
  double start_angle_rad = 0.0;      ///< key joint coordinate at release (the action's rest)
  double fall_time_s = -1.0;         ///< release to first punching contact (−1: none)
  double fall_distance_mm = 0.0;     ///< key-front drop at first contact
  double fall_angle_rad = 0.0;       ///< key rotation at first contact
  double impact_velocity_mps = 0.0;  ///< key-front speed at first contact
  int bounces = 0;                   ///< times the key front leaves the punching again
  double first_rebound_mm = 0.0;     ///< highest key-front rise after the first contact
  double final_dip_mm = 0.0;         ///< key-front drop at the end (resting on the punching)
  CsvTable trace;                    ///< time_s, key_angle_deg, key_front_dip_mm, punching_force_n
};

/// Releases the key of `action` alone (isolated_body_model with its frame contacts) from the
/// key angle of the action's rest state (or options.start_angle_rad). `progress` (may be empty)
/// sees the fraction of the duration; returning false throws Cancelled.
KeyFallResult key_fall(const ActionModel& action, const KeyFallOptions& options = {},
                       const ProgressCallback& progress = {});

}  // namespace pat

// The model's hammer and key angles on a uniform time grid, for comparison with measured data.
#pragma once

#include <string>
#include <vector>

#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

struct ModelTrace {
  double dt = 1e-4;                 ///< grid spacing, s (t_i = i dt from the start of the input)
  std::vector<double> hammer_deg;   ///< hammer angle from rest, deg (DESIGN.md section 5 sign)
  std::vector<double> key_deg;      ///< key angle from rest, deg
  std::vector<double> key_force_n;  ///< force at the key front (force inputs), else empty
  bool completed = true;            ///< false: the run stopped early (unphysical, diverged)
  std::string stop_cause;
  std::vector<double> impact_t, escapement_t, check_t;  ///< events, s

  /// Linear interpolation of the hammer angle at time t (s); the rest value before 0 and the
  /// last value after the end.
  double hammer_at(double t) const;
  double key_at(double t) const;
};

/// Simulates `model` under input SPEC (DESIGN.md section 5) for `duration_s` with the W-method
/// at its default step, sampled every `dt` s. A run that stops early is returned with
/// completed = false and its samples so far (the rest held at the last value). `rest`: the
/// model's rest state when already known (it is computed otherwise).
ModelTrace simulate_trace(const ActionModel& model, const std::string& input_spec,
                          double duration_s, double dt = 1e-4, const RestState* rest = nullptr);

}  // namespace pat

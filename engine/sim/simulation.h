// Runs a simulation of an action under a key input: finds the rest state, integrates, detects
// events (escapement, impact, check, key bottom), stops a run whose contacts become unphysical,
// and records a trace.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "inputs/key_input.h"
#include "integrators/integrator_factory.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

/// The action at rest under gravity, springs and contacts (no finger).
struct RestState {
  DofVector q;                     ///< joint coordinates, rad
  double hammer_string_gap = 0.0;  ///< m
};

/// Finds the static equilibrium by integrating the unloaded action with extra joint damping until
/// it is still. Throws std::runtime_error naming the problem if it does not settle.
RestState find_rest_state(const ActionModel& model);

struct SimulationOptions {
  std::string integrator = "w2";
  IntegratorOptions integrator_options;
  double duration_s = 0.5;
  double sample_interval_s = 1e-4;  ///< trace row spacing (0: no trace)
  /// The trace also ends with the state the run ended in, when that falls between samples (a
  /// run stopped between two rows, a duration that is no multiple of the spacing): one row off
  /// the grid, so only for traces read row by row (simulate --out), not resampled ones.
  bool trace_final_state = false;
  /// Called after every accepted step with the time; return false to cancel the run.
  std::function<bool(double t)> on_step;
};

struct SimEvent {
  std::string type;                ///< escapement, impact, check, key_bottom
  double t = 0.0;                  ///< s
  double hammer_velocity = 0.0;    ///< impacts: strike-point speed toward the string, m/s
  double hammer_string_gap = 0.0;  ///< m, at the event
};

struct SimulationResult {
  std::string status = "ok";  ///< "ok", or "stopped" (unphysical state, failure, cancel)
  std::string stop_cause;     ///< names the contact and the two parts, or the failure
  double end_time = 0.0;      ///< s
  std::vector<SimEvent> events;
  CsvTable trace;  ///< DESIGN.md section 5 columns
  RestState rest;
  long steps = 0;
  long rhs_evaluations = 0;
  double wall_time_s = 0.0;      ///< integration only (rest state excluded)
  double realtime_factor = 0.0;  ///< simulated time / wall time
};

/// Throws InputError when sampling every `sample_interval_s` for `duration_s` would make more than
/// 5 million trace rows (over a gigabyte): refused before any work.
void check_trace_rows(double duration_s, double sample_interval_s);

/// Simulates `model` driven by `input` (may be null: no finger) for options.duration_s.
/// The rest state is computed first (or passed in to save the time).
SimulationResult simulate(const ActionModel& model, const KeyInput* input,
                          const SimulationOptions& options, const RestState* rest = nullptr);

/// Trace column names for a model: time_s, <body>_angle_deg..., hammer_string_gap_mm,
/// finger_force_n, <contact>_force_n..., <strap>_tension_n...
std::vector<std::string> trace_columns(const ActionModel& model);

/// A contact's name as a column prefix: lower case, runs of other characters become '_'.
std::string column_name(const std::string& name);

}  // namespace pat

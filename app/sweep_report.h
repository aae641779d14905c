// JSON, CSV and one-line summaries of a repetition sweep, shared by `sweep` and `study compare`.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/repetition_sweep.h"
#include "plot_spec.h"

namespace pat::app {

/// DESIGN.md section 5 keys (max_frequency_hz, stroke, mode) plus limit_found, first_failure
/// (t_s, frequency_hz, kind, strikes), run status, timing (simulated_s, wall_s) and the cycles
/// (chirp) or frequencies (steps).
nlohmann::json sweep_json(const SweepResult& result);

/// "ok", or the status of the sweep's run that stopped (chirp: its run; steps: the first
/// frequency's run that stopped), and that run's cause (empty when none stopped).
std::string sweep_run_status(const SweepResult& result);
std::string sweep_stop_cause(const SweepResult& result);

/// One cycle: t_s, frequency_hz, strikes, success, kind, judged, strike_velocity_mps.
nlohmann::json cycle_json(const CycleResult& cycle);

/// One row per cycle: t_s (cycle start), frequency_hz, strikes, success (1/0), judged (1/0),
/// strike_velocity_mps, and the run's frequency for the steps mode (step_frequency_hz).
/// Metadata: action, stroke, mode.
CsvTable sweep_cycles_table(const SweepResult& result, const ActionModel& model);

/// The plots of `--plot`: strikes per judged cycle and the hammer speed at each strike over
/// the frequency, the maximum marked; the chirp run's key and hammer motion when traced.
std::vector<PlotSpec> sweep_plots(const SweepResult& result);

/// "maximum 13.2 Hz (first failure: missed strike at 13.4 Hz, t = 11.4 s)" and the like.
std::string sweep_summary(const SweepResult& result);

}  // namespace pat::app

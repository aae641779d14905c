// The diagnosis as data for others: its JSON (DESIGN.md section 5 keys: baseline_rms_deg, cause,
// extended_rms_deg, gain, ranking, discrepancies, measured_events, plus per-trial details) and
// the report folder written by `pianoaction diagnose --report DIR` and by the window's "Export
// report" (one writer for both).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "measured/diagnosis.h"

namespace pat {

nlohmann::json diagnosis_json(const Diagnosis& diagnosis);

/// One trial's measured, baseline and extended-model hammer angles aligned on the measured
/// samples: time_s, measured_deg, baseline_deg, residual_baseline_deg, phase_index (metadata
/// "phases" names them), then extended_deg and residual_extended_deg when a cause was found.
CsvTable trial_traces_table(const TrialReport& trial);

/// Writes into `dir` (created when missing): diagnosis.json (diagnosis_json), ranking.csv,
/// phases.csv and one <file>_traces.csv per trial (measured, baseline and extended model
/// aligned, their residuals, the phase index of each sample). Throws InputError naming the
/// folder or file that cannot be written; diagnosis.json is replaced only once fully written.
void write_diagnosis_report(const std::string& dir, const Diagnosis& diagnosis);

}  // namespace pat

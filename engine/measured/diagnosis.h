// Diagnosis of measured data (DESIGN.md section 4; reference/numerics.md section 7): drive the
// model with each trial's input, align the nuisance offsets, report what the model gets wrong,
// fit each candidate extension, compare them on held-out trials and name the cause only when it
// beats the baseline beyond the noise.
//
// Fitting: each candidate has one parameter s (log of the value for factors, frequencies and
// stiffnesses; mm for regulation offsets). The cost of a set of trials is Σ over trials of the
// aligned residual Σ r² (the offsets re-estimated at every s: variable projection). A scan of
// kScanPoints values over the physical range finds the basin, a finer scan (kFineScanPoints
// between the best point and each neighbour) narrows it, then Levenberg–Marquardt
// (forward-difference Jacobian of the residual vector) refines it from the best point found.
// Each trial's own minimum (its best scan point refined on it alone) is a further start when the
// sum over the trials is lower there: in a double blow, whether the backcheck holds the hammer or
// lets it bounce back to the string changes within a few percent of a felt's or the backcheck's
// stiffness, so the summed cost has a dip at the true value narrower than any scan, next to the
// minimum of a smoother trial (a sine, a 1 kg blow).
//
// Screening: every candidate is scanned; only the kRefinedCandidates with the lowest scan cost
// are fitted locally and validated (the others are listed with their best scan point). The scan
// of each of those is first made twice as dense (the midpoints): a contact-switching
// simulation's cost can have basins narrower than the screening spacing.
//
// Validation: leave one trial out (refit on the others, starting from the fit on every trial,
// and evaluate the held-out one) for every trial; the validated error is the RMS of the held-out
// residuals. With one trial there is no held-out data and the training error is used (said so in
// the result).
//
// Selection: the best candidate by validated error is named the cause only if
//   (1) its validated mean square is below kMaxExplainedRatio × the baseline's, and
//   (2) ΔBIC = N_eff ln(MS_base / MS_cand) − ln N_eff > kMinBicGain, with N_eff the samples
//       divided by the residual correlation length (kCorrelationTimeS): residuals of sampled
//       trajectories are autocorrelated, which makes the raw N too optimistic, and
//   (3) its fitted value is not at a limit of its physical range (then it is not identified).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "measured/discrepancies.h"
#include "measured/measured_data.h"
#include "model/effects.h"

namespace pat {

inline constexpr int kScanPoints = 9;
inline constexpr int kFineScanPoints = 3;  // between the dense scan points, beside the best one
inline constexpr std::size_t kRefinedCandidates = 4;  // fitted and validated after the scan
inline constexpr int kMaxLmIterations = 4;            // the fit on every trial
inline constexpr int kFoldLmIterations = 2;           // each leave-one-out refit, from that fit
inline constexpr double kSecondBasinRatio = 2.0;  // a second scan minimum this close is fitted too
inline constexpr double kMaxExplainedRatio = 0.7;
inline constexpr double kMinBicGain = 10.0;  // "very strong" evidence (Kass & Raftery)
inline constexpr double kCorrelationTimeS = 5e-3;

struct DiagnoseOptions {
  std::vector<std::string> candidates;  ///< effect names; empty: candidate_effects(model)
  unsigned threads = 0;                 ///< 0: every core
  /// One item per candidate scanned, then one per candidate refined: construct it with
  /// diagnosis_progress_items(candidates). A cancel throws Cancelled after the running items.
  ProgressReporter* progress = nullptr;
};

struct CandidateFit {
  std::string effect;
  std::string unit;
  double value = 0.0;               ///< fitted on every trial
  std::vector<double> fold_values;  ///< fitted leaving out trial k
  double training_rms_deg = 0.0;    ///< at the fold fits, on their training trials
  double validated_rms_deg = 0.0;   ///< held-out residual RMS
  double delta_bic = 0.0;           ///< vs the baseline on held-out residuals (> 0: better)
  bool completed = true;            ///< false: every fit made the run fail
  std::string note;
};

struct TrialReport {
  std::string path;
  MeasuredTrial data;      ///< as compared (an estimated input's strike on the model's clock)
  std::string input_spec;  ///< the input the model was driven with (estimated if unknown)
  bool input_estimated = false;
  double noise_deg = 0.0;
  /// The baseline aligned with its angle offset taken at rest (referenced_to_rest; the fits and
  /// the gain use align()'s least-squares offset): residual, offset and Σ r² as shown.
  Alignment baseline_alignment;
  std::vector<bool> at_rest;         ///< the samples of the baseline's rest phase
  double baseline_fitted_rss = 0.0;  ///< Σ r² with align()'s least-squares offset (the fits')
  ModelTrace baseline;
  std::vector<MeasuredEvent> measured_events;
  TrialDiscrepancies discrepancies;
  ModelTrace extended;  ///< with the cause (empty without one)
  Alignment extended_alignment;
};

struct Diagnosis {
  std::string action;
  double noise_deg = 0.0;         ///< estimated from the data
  double baseline_rms_deg = 0.0;  ///< on the held-out trials (all trials, each held out once)
  double extended_rms_deg = 0.0;  ///< with the cause, held out; = baseline without a cause
  double gain = 0.0;              ///< 1 − extended/baseline
  bool held_out = true;           ///< false with a single trial (training errors)
  std::optional<Effect> cause;
  std::string cause_unit;
  std::vector<CandidateFit> ranking;  ///< best validated first
  std::vector<TrialReport> trials;
  std::vector<std::string> discrepancies;  ///< in words, largest first
  double wall_time_s = 0.0;
  int simulations = 0;
};

/// The items a diagnosis of `candidates` candidates reports (scans, then refinements).
inline std::size_t diagnosis_progress_items(std::size_t candidates) {
  return candidates + std::min(kRefinedCandidates, candidates);
}

/// Runs the diagnosis. Throws InputError when a trial has no usable input, or when the model
/// cannot run under a trial's input.
Diagnosis diagnose(const ActionModel& model, const std::vector<MeasuredTrial>& trials,
                   const DiagnoseOptions& options = {});

}  // namespace pat

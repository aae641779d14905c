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
// Screening: every candidate is scanned; a fit refines only the kRefinedCandidates with the
// lowest scan cost on its own training trials (the others are listed with their best scan
// point). The scan of each refined one is first made twice as dense (the midpoints): a
// contact-switching simulation's cost can have basins narrower than the screening spacing.
//
// Validation: leave one trial out. For every trial, each candidate is fitted from scratch on the
// other trials alone (the scan's costs summed over them, its own finer scan and local fits: the
// held-out trial's data takes no part in it) and evaluated on the trial left out; a candidate's
// validated error is the RMS of those held-out residuals. The gain is measured the same way for
// the whole procedure: for each trial, the candidate with the lowest training cost among the
// shortlist of the other trials, fitted on them, is evaluated on it. With one trial nothing can
// be held out: the result says so, no held-out error is given, and the gain is a training gain.
//
// Selection: candidates are ranked by their validated (held-out) error, or with one trial by
// their cost fitted on it (all have one parameter, so the error compares them like an
// information criterion would; a candidate that fits the trials it saw as well as another but
// predicts the one it did not see worse ranks below it). The best is named the cause only if
//   (1) its validated mean square (training with one trial) is below kMaxExplainedRatio × the
//       baseline's, and
//   (2) ΔBIC = N_eff ln(MS_base / MS_cand) − ln N_eff > kMinBicGain, with N_eff the samples
//       divided by the residual correlation length (kCorrelationTimeS): residuals of sampled
//       trajectories are autocorrelated, which makes the raw N too optimistic, and
//   (3) its fitted value is not at a limit of its physical range (then it is not identified;
//       every such fit in the ranking says so), and
//   (4) the runner-up (the next fitted candidate) leaves at least kMinRunnerUpRatio times its
//       mean square, in the same measure (validated, else training): otherwise the ranking is
//       ambiguous and no cause is named.
#pragma once

#include <algorithm>
#include <limits>
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
inline constexpr int kMaxLmIterations = 4;           // each local fit (on every trial, or a fold's)
inline constexpr int kTrialMinimumLmIterations = 2;  // from the best trial's own minimum
inline constexpr double kSecondBasinRatio = 2.0;  // a second scan minimum this close is fitted too
inline constexpr double kMaxExplainedRatio = 0.7;
inline constexpr double kMinBicGain = 10.0;  // "very strong" evidence (Kass & Raftery)
inline constexpr double kCorrelationTimeS = 5e-3;
/// Criterion (4): a runner-up within 1.5 times the best's mean square (22 % in rms) explains the
/// data about as well. On real strikes the residual is mostly the model's structure, not noise,
/// so the BIC over N_eff (which a 10 % rms difference on 100 effective samples passes) is no
/// measure of which of two fits is right; a third of the residual power is.
inline constexpr double kMinRunnerUpRatio = 1.5;
/// A baseline error within 1.5 times the noise (residual power within 2.25 times the noise's) is
/// called the noise: the verdict says the model needs no cause, not that none was found.
inline constexpr double kWithinNoiseRatio = 1.5;

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
  std::vector<double> fold_values;  ///< fitted from scratch leaving out trial k
  double training_rms_deg = 0.0;    ///< fitted on every trial, over every trial (the ranking's)
  double validated_rms_deg = 0.0;   ///< held-out residual RMS; NaN with one trial
  double delta_bic = 0.0;           ///< vs the baseline on held-out residuals (> 0: better)
  bool completed = true;            ///< false: every fit made the run fail
  std::string note;
};

struct TrialReport {
  std::string path;
  MeasuredTrial data;      ///< as compared (an estimated input's strike on the model's clock)
  std::string input_spec;  ///< the input the model was driven with (estimated if unknown)
  bool input_estimated = false;
  /// Time in the file = time here (data, events, traces) + file_time_shift_s: nonzero when an
  /// estimated input's strike was moved onto the model's clock (the samples before it dropped).
  double file_time_shift_s = 0.0;
  /// The baseline's clock offset ended at the ±10 ms searched: the file's time and the model's
  /// differ by more (its time_s not counted from the input's start?), and the comparison of this
  /// trial is not to be trusted (said first in the discrepancies and in the verdict).
  bool time_offset_at_limit = false;
  double noise_deg = 0.0;
  /// The baseline aligned with its angle offset taken at rest (referenced_to_rest; the fits and
  /// the gain use align()'s least-squares offset): residual, offset and Σ r² as shown.
  Alignment baseline_alignment;
  std::vector<bool> at_rest;         ///< the samples of the baseline's rest phase
  double baseline_fitted_rss = 0.0;  ///< Σ r² with align()'s least-squares offset (the fits')
  ModelTrace baseline;
  std::vector<MeasuredEvent> measured_events;
  TrialDiscrepancies discrepancies;
  ModelTrace extended;  ///< with the cause fitted on every trial (empty without one)
  Alignment extended_alignment;
  /// Held out (two or more trials, a cause named): the candidate chosen and fitted on the other
  /// trials alone, and this trial's error under it.
  std::string held_out_effect;
  double held_out_value = 0.0;
  std::string held_out_unit;
  double held_out_rms_deg = std::numeric_limits<double>::quiet_NaN();
};

struct Diagnosis {
  std::string action;
  double noise_deg = 0.0;         ///< estimated from the data
  double baseline_rms_deg = 0.0;  ///< on the held-out trials (all trials, each held out once)
  /// With a cause: each trial under the candidate chosen and fitted without it (a training
  /// error with one trial); = baseline without a cause.
  double extended_rms_deg = 0.0;
  double gain = 0.0;       ///< 1 − extended/baseline
  std::string gain_basis;  ///< what the gain is measured on, in words
  bool held_out = true;    ///< false with a single trial (training errors)
  bool ambiguous = false;  ///< the best fit explains the data, but the runner-up about as well
  /// The decision in one sentence: the cause and the error it removes; or why none is named
  /// (an ambiguous ranking, a model within the noise, or no candidate that explains it).
  std::string verdict;
  std::optional<Effect> cause;
  std::string cause_unit;
  std::vector<CandidateFit> ranking;  ///< best validated first
  std::vector<TrialReport> trials;
  std::vector<std::string> discrepancies;  ///< in words, largest first
  double wall_time_s = 0.0;
  int simulations = 0;
};

/// The items a diagnosis of `candidates` candidates reports (scans, then refinements).
/// Every candidate may be refined: each leave-one-out fit has its own shortlist.
inline std::size_t diagnosis_progress_items(std::size_t candidates) {
  return 2 * candidates;
}

/// Runs the diagnosis. Throws InputError when a trial has no usable input, or when the model
/// cannot run under a trial's input.
Diagnosis diagnose(const ActionModel& model, const std::vector<MeasuredTrial>& trials,
                   const DiagnoseOptions& options = {});

}  // namespace pat

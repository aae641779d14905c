// Maximum repetition frequency (DESIGN.md fact F4; paper section 7.1, Fig. 19 and Table 2).
//
// The key is driven by a prescribed sinusoidal motion (inputs/key_input.h):
//   full stroke:  key angle θ(t) = A/2 (1 − cos φ(t)),               A = full-dip angle
//   half stroke:  a first descent at f_start to full dip, then
//                 θ(t) = A − A/4 (1 − cos φ(t − t0)),  t0 = 1/(2 f_start)
//                 i.e. between full dip and half release, where the grand's repetition lever
//                 lets the jack re-engage under the knuckle without a full key return.
// Chirp mode: a run with the phase φ(τ) = 2π (f_start τ + r τ²/2), r the chirp rate in Hz/s;
// with r = 1 Hz/s the frequency (Hz) equals the time (s) plus f_start, as in the paper's Fig. 19.
// To use the cores, the band [f_start, f_max] is cut into equal segments run in parallel, each
// its own chirp at the same rate from rest; every segment after the first starts 1 s of chirp
// below its band and drops the cycles before it, so that its start from rest is forgotten (the
// cycles are then put end to end in the times of one continuous chirp). The number of segments
// is fixed (chirp_segments, 2 by default), not the machine's core count: where the action has
// two responses at one frequency (the grand's full stroke from 14.5 to 18 Hz), a segment started
// from rest inside that range may take the other one, so the cut changes the result, and a
// result must not depend on the machine. A trace (for a plot) is put together the same way.
// Steps mode: one run per frequency f_i = f_start, f_start + Δf, …, ≤ f_max, each a constant
// sine held for settle + window cycles; the frequencies run in parallel on the cores.
//
// Definitions (the contract the tests check):
//   - A CYCLE is the key motion between two successive upper turning points of the key: φ = 2πk
//     for the full stroke (the key at rest), φ = π + 2πk for the half stroke (the key at half
//     release); the half stroke's cycle 0 runs from t = 0 (rest) through the first descent to the
//     first half release. A cycle's frequency is 1 / its duration (Hz).
//   - A STRIKE is an `impact` event of the Simulator (the hammer–string contact becoming active)
//     at a hammer speed of at least `min_strike_speed_mps` (0.1 m/s, a tenth of the softest blow
//     of fact F2, about 1 m/s under 2 N): a slower touch sounds no note (in a slow halfway
//     stroke the grand's hammer drifts onto the string at 3-4 cm/s after let-off, 0.007 m/s in
//     the steps at 3 Hz) and is not counted. Impacts closer than `strike_merge_s` to the previous
//     one are the same strike (the felt chattering on the string within one blow), not a new one.
//   - A cycle SUCCEEDS when exactly one strike falls in [start, end). Otherwise it fails with the
//     kind `missed` (no strike: the jack did not reset under the knuckle, or the hammer was
//     blocked) or `double` (two or more strikes: the hammer bounced back to the string); a run
//     that stops on an unphysical state fails the cycle it stopped in with the kind `stopped`.
//   - The first `settle_cycles` cycles of every run are the start-up transient from rest and are
//     reported but not judged.
//   - A STEADY WINDOW is `window_cycles` consecutive judged cycles: in the chirp, any such run of
//     cycles; in the steps mode, the judged cycles of one frequency's run.
//   - The REPEATING RANGE of a chirp is its longest run of consecutive successful judged cycles
//     (the first of equally long runs), and it must be at least one steady window long; the
//     maximum frequency is the frequency of its last cycle. Steps: a frequency passes when every
//     cycle of its steady window succeeds; the repeating range is the longest run of consecutive
//     passing frequencies and the maximum is its highest frequency.
//     Why the longest run and not the first failure or the highest success: a key moved too
//     slowly throws the hammer too gently to reach the string after let-off (the upright below
//     about 6 Hz, with sporadic misses and double strikes up to about 10 Hz), or lets it be thrown
//     twice before let-off (a sine decelerates the key before let-off, so the grand's hammer
//     leaves the jack, bounces off the string and is thrown again, below about 10 Hz); and above
//     the limit the jack may still reset in a lucky run of a few cycles. Neither is the range in
//     which the action repeats, which is the long unbroken run between them.
//   - ALTERNATING BLOWS (a period doubling): a steady window of judged cycles that all strike,
//     whose first-strike speeds alternate strong and weak: each speed differs from the next one
//     by at least kAlternationRatio times, and the differences change sign from cycle to cycle.
//     The sweep reports the frequency where the first such window starts (chirp: the window's
//     first cycle; steps: the lowest frequency whose steady window alternates). On the grand's
//     full stroke a steady sine started from rest alternates at 10 and 11 Hz (1.6-1.8 times;
//     1.2-1.4 at 10.5 and 11.5 Hz) and plainly at 20 Hz (5.1-5.4 against 1.9-2.0 m/s), while a
//     chirp from below keeps even blows to about 19.6 Hz (from 2, 8 or 11 Hz at 1 Hz/s): a
//     frequency reported here tells that the limit may depend on how the key got there.
//   - The first failure reported is the failing cycle (frequency) right after the repeating range;
//     `limit_found` says that there is one below f_max. When no run is a steady window long
//     there is no maximum (`max_frequency_hz` empty) and the first failure is the first failing
//     judged cycle (frequency).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "io/csv.h"
#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

enum class Stroke { full, half };
enum class SweepMode { chirp, steps };

/// "full"/"half" and "chirp"/"steps"; parse_* throw InputError naming `what` for other words.
std::string stroke_name(Stroke stroke);
std::string sweep_mode_name(SweepMode mode);
Stroke parse_stroke(const std::string& word, const std::string& what);
SweepMode parse_sweep_mode(const std::string& word, const std::string& what);

struct SweepOptions {
  Stroke stroke = Stroke::full;
  SweepMode mode = SweepMode::chirp;
  double f_start_hz = 2.0;           ///< first frequency (chirp start, first step)
  double f_max_hz = 20.0;            ///< last frequency
  double chirp_rate_hz_per_s = 1.0;  ///< dF/dt of the chirp (paper: 1 Hz/s)
  double step_hz = 0.5;              ///< steps: frequency increment
  int settle_cycles = 3;             ///< cycles of each run not judged (start from rest)
  int window_cycles = 8;         ///< cycles of a steady window (steps: judged cycles per frequency)
  double strike_merge_s = 3e-3;  ///< impacts closer than this are one strike (s)
  double min_strike_speed_mps = 0.1;  ///< slower impacts are touches, not strikes (m/s)
  double trace_interval_s = 0.0;      ///< chirp: > 0 keeps a trace sampled at this interval (s)
  std::string integrator = "w2";
  double step_s = 1e-5;  ///< fixed integrator step (s)
  unsigned threads = 0;  ///< worker threads (0: one per core)
  /// chirp: segments, run in parallel on up to `threads` (at least 1)
  unsigned chirp_segments = 2;
};

enum class CycleOutcome { struck_once, missed, double_strike, stopped };
/// "ok", "missed", "double", "stopped".
std::string outcome_name(CycleOutcome outcome);

struct CycleResult {
  double t_start_s = 0.0, t_end_s = 0.0;  ///< in the run's time (s)
  double frequency_hz = 0.0;              ///< 1 / (t_end − t_start)
  int strikes = 0;
  double strike_velocity_mps = 0.0;  ///< hammer speed at the cycle's first strike (0: none)
  bool judged = true;                ///< false for the settling cycles
  CycleOutcome outcome = CycleOutcome::struck_once;
  bool success() const { return outcome == CycleOutcome::struck_once; }
};

/// One frequency of the steps mode.
struct FrequencyResult {
  double frequency_hz = 0.0;
  bool passed = false;
  int failed_cycles = 0;          ///< in the steady window
  std::string run_status = "ok";  ///< "ok" or "stopped"
  std::string stop_cause;
  std::vector<CycleResult> cycles;  ///< every cycle of the run, settling ones first
};

struct SweepResult {
  Stroke stroke = Stroke::full;
  SweepMode mode = SweepMode::chirp;
  std::optional<double> max_frequency_hz;  ///< empty: the first judged cycle already fails
  bool limit_found = false;                ///< a failure was found at or below f_max
  /// The failure that ends the maximum (see the definitions); absent when none.
  std::optional<CycleResult> first_failure;
  /// Where strong and weak blows start to alternate (see the definitions); empty when they never
  /// do in the band.
  std::optional<double> alternating_from_hz;
  std::vector<CycleResult> cycles;           ///< chirp: every cycle
  std::vector<FrequencyResult> frequencies;  ///< steps: every frequency in order
  std::string run_status = "ok";             ///< chirp: "ok" or "stopped"
  std::string stop_cause;
  CsvTable trace;            ///< chirp with trace_interval_s > 0
  double simulated_s = 0.0;  ///< total simulated time of all runs (s)
  double wall_s = 0.0;       ///< wall time of the whole sweep (s)
};

/// A judged cycle as a point over frequency, for plots: the cycle's own frequency (chirp) or its
/// run's (steps). In the order judged_cycle_points gives them the frequencies rise (a chirp's
/// cycles shorten with time; the steps come in increasing order).
struct CyclePoint {
  double frequency_hz = 0.0;
  int strikes = 0;
  double strike_velocity_mps = 0.0;  ///< hammer speed at the first strike (0: none)
};
/// Every judged cycle of a sweep (settling cycles left out).
std::vector<CyclePoint> judged_cycle_points(const SweepResult& result);

/// The judged cycles below the repeating range (a key moved too slowly: see the definitions),
/// which a summary of the range must not hide.
struct FailuresBelowRange {
  double range_from_hz = 0.0;  ///< the repeating range's first judged cycle (its frequency)
  int judged = 0;              ///< judged cycles below it
  int doubles = 0;             ///< of them, failed with two or more strikes
  int missed = 0;              ///< of them, failed with none (or stopped)
};
/// Empty when the sweep has no repeating range.
std::optional<FailuresBelowRange> failures_below_range(const SweepResult& result);

/// A strike candidate: impact time and hammer velocity (from the Simulator's events).
struct Impact {
  double t_s = 0.0;
  double velocity_mps = 0.0;
};

/// Start times of the cycles of a stroke whose phase follows φ(τ) = 2π (f0 τ + r τ²/2)
/// (r = 0: a sine), up to t_end (s): each cycle is [boundaries[k], boundaries[k+1]).
std::vector<double> cycle_boundaries(Stroke stroke, double f0_hz, double rate_hz_per_s,
                                     double t_end_s);

/// Counts strikes per cycle and classifies the cycles (definitions above). `run_end_s` is where
/// the run ended; when `stopped`, the cycle containing run_end_s fails as `stopped` and later
/// cycles are dropped. The first `settle_cycles` are marked not judged.
/// Impacts slower than `min_strike_speed_mps` (after merging chatter into the impact that starts
/// it) are touches, not strikes.
std::vector<CycleResult> classify_cycles(const std::vector<double>& boundaries,
                                         const std::vector<Impact>& impacts, double merge_s,
                                         int settle_cycles, double run_end_s, bool stopped,
                                         double min_strike_speed_mps = 0.0);

/// Strike speeds of neighbouring alternating blows differ by at least this factor. Measured on
/// the grand's full stroke in steps: one blow per cycle mostly keeps its neighbours' speeds
/// within a factor 1.3 (1.46 at most, 13.5 Hz: 2.6 and 3.8 m/s, not in turn), the period
/// doubling at 20 Hz differs 2.6-2.8 times (5.3 and 1.9 m/s); 1.5 lies between. A milder
/// alternation at 10-11.5 Hz (1.2-1.8 times) straddles it and is reported from 10 Hz.
inline constexpr double kAlternationRatio = 1.5;

/// Index (into `cycles`) of the first cycle of the first window of `window_cycles` consecutive
/// judged cycles that alternate (definitions above); cycles not judged are skipped. Empty when
/// there is none or window_cycles < 3 (an alternation needs two differences of opposite sign).
std::optional<std::size_t> first_alternating_window(const std::vector<CycleResult>& cycles,
                                                    int window_cycles);

/// The chirp rule over cycles in time order; a run must be at least `window_cycles` long.
/// Sets max_frequency_hz, limit_found, first_failure and alternating_from_hz of `result`.
void chirp_maximum(const std::vector<CycleResult>& cycles, int window_cycles, SweepResult& result);

/// The steps rule over frequencies in increasing order; sets the same fields (a frequency
/// alternates when its judged cycles, at least 3 of them, make one alternating window).
void steps_maximum(const std::vector<FrequencyResult>& frequencies, SweepResult& result);

/// The input SPEC of a chirp run (motion:chirp:F0:F1:SECONDS:stroke).
std::string chirp_spec(const SweepOptions& options);

/// Runs the sweep. Progress: chirp by simulated time, steps by frequencies done; a cancel throws
/// Cancelled. Throws InputError for inconsistent options (naming the option).
SweepResult run_repetition_sweep(const ActionModel& model, const SweepOptions& options,
                                 const ProgressCallback& progress = nullptr);

}  // namespace pat

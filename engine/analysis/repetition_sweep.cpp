#include "analysis/repetition_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "core/types.h"
#include "inputs/key_input.h"
#include "sim/key_travel.h"

namespace pat {

std::string stroke_name(Stroke stroke) {
  return stroke == Stroke::full ? "full" : "half";
}

std::string sweep_mode_name(SweepMode mode) {
  return mode == SweepMode::chirp ? "chirp" : "steps";
}

Stroke parse_stroke(const std::string& word, const std::string& what) {
  if (word == "full") return Stroke::full;
  if (word == "half") return Stroke::half;
  throw InputError(what + ": unknown stroke '" + word + "' (expected full or half)");
}

SweepMode parse_sweep_mode(const std::string& word, const std::string& what) {
  if (word == "chirp") return SweepMode::chirp;
  if (word == "steps") return SweepMode::steps;
  throw InputError(what + ": unknown mode '" + word + "' (expected chirp or steps)");
}

std::string outcome_name(CycleOutcome outcome) {
  switch (outcome) {
    case CycleOutcome::struck_once:
      return "ok";
    case CycleOutcome::missed:
      return "missed";
    case CycleOutcome::double_strike:
      return "double";
    case CycleOutcome::stopped:
      return "stopped";
  }
  return "?";
}

std::vector<CyclePoint> judged_cycle_points(const SweepResult& result) {
  std::vector<CyclePoint> points;
  auto add = [&points](const std::vector<CycleResult>& cycles, double run_frequency_hz) {
    for (const CycleResult& c : cycles)
      if (c.judged)
        points.push_back({run_frequency_hz > 0.0 ? run_frequency_hz : c.frequency_hz, c.strikes,
                          c.strike_velocity_mps});
  };
  if (result.mode == SweepMode::chirp)
    add(result.cycles, 0.0);
  else
    for (const FrequencyResult& f : result.frequencies) add(f.cycles, f.frequency_hz);
  return points;
}

std::optional<FailuresBelowRange> failures_below_range(const SweepResult& result) {
  if (!result.max_frequency_hz) return std::nullopt;
  const double top = *result.max_frequency_hz + 1e-9;
  FailuresBelowRange below;
  const auto count = [&below](const CycleResult& c) {
    if (!c.judged) return;
    ++below.judged;
    if (!c.success()) ++(c.outcome == CycleOutcome::double_strike ? below.doubles : below.missed);
  };
  if (result.mode == SweepMode::steps) {
    // the range: the passing frequencies run up to the maximum
    std::size_t end = result.frequencies.size();
    for (std::size_t i = 0; i < result.frequencies.size(); ++i)
      if (result.frequencies[i].passed && result.frequencies[i].frequency_hz <= top) end = i;
    if (end == result.frequencies.size()) return std::nullopt;
    std::size_t start = end;
    while (start > 0 && result.frequencies[start - 1].passed) --start;
    below.range_from_hz = result.frequencies[start].frequency_hz;
    for (std::size_t i = 0; i < start; ++i)
      for (const CycleResult& c : result.frequencies[i].cycles) count(c);
    return below;
  }
  // chirp: the range's last cycle is the last success at the maximum (frequencies rise)
  std::vector<const CycleResult*> judged;
  for (const CycleResult& c : result.cycles)
    if (c.judged) judged.push_back(&c);
  std::size_t end = judged.size();
  for (std::size_t i = 0; i < judged.size(); ++i)
    if (judged[i]->success() && judged[i]->frequency_hz <= top) end = i;
  if (end == judged.size()) return std::nullopt;
  std::size_t start = end;
  while (start > 0 && judged[start - 1]->success()) --start;
  below.range_from_hz = judged[start]->frequency_hz;
  for (std::size_t i = 0; i < start; ++i) count(*judged[i]);
  return below;
}

std::vector<double> cycle_boundaries(Stroke stroke, double f0_hz, double rate_hz_per_s,
                                     double t_end_s) {
  // τ at which the phase reaches φ: π r τ² + 2π f0 τ − φ = 0
  auto time_of_phase = [&](double phi) {
    const double turns = phi / (2.0 * kPi);
    if (rate_hz_per_s == 0.0) return turns / f0_hz;
    return (-f0_hz + std::sqrt(f0_hz * f0_hz + 2.0 * rate_hz_per_s * turns)) / rate_hz_per_s;
  };
  std::vector<double> boundaries{0.0};
  const double origin = stroke == Stroke::half ? 0.5 / f0_hz : 0.0;  // the first descent
  const double first_phase = stroke == Stroke::half ? kPi : 2.0 * kPi;
  for (int k = 0;; ++k) {
    const double t = origin + time_of_phase(first_phase + 2.0 * kPi * k);
    if (t > t_end_s + 1e-12) break;
    boundaries.push_back(t);
  }
  return boundaries;
}

std::vector<CycleResult> classify_cycles(const std::vector<double>& boundaries,
                                         const std::vector<Impact>& impacts, double merge_s,
                                         int settle_cycles, double run_end_s, bool stopped,
                                         double min_strike_speed_mps) {
  std::vector<CycleResult> cycles;
  std::size_t next_impact = 0;
  double last_strike = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < boundaries.size(); ++k) {
    CycleResult cycle;
    cycle.t_start_s = boundaries[k];
    cycle.t_end_s = boundaries[k + 1];
    cycle.frequency_hz = 1.0 / (cycle.t_end_s - cycle.t_start_s);
    cycle.judged = static_cast<int>(k) >= settle_cycles;
    if (stopped && cycle.t_start_s > run_end_s) break;
    while (next_impact < impacts.size() && impacts[next_impact].t_s < cycle.t_end_s) {
      const Impact& impact = impacts[next_impact++];
      const bool new_strike = impact.t_s - last_strike >= merge_s;
      last_strike = impact.t_s;  // a chatter chain extends from its latest contact
      if (!new_strike || impact.t_s < cycle.t_start_s) continue;
      // a touch too slow to sound (its chatter merged into it above) is no strike
      if (impact.velocity_mps < min_strike_speed_mps) continue;
      if (cycle.strikes++ == 0) cycle.strike_velocity_mps = impact.velocity_mps;
    }
    if (stopped && run_end_s < cycle.t_end_s) {
      cycle.outcome = CycleOutcome::stopped;
      cycles.push_back(cycle);
      break;
    }
    cycle.outcome = cycle.strikes == 1   ? CycleOutcome::struck_once
                    : cycle.strikes == 0 ? CycleOutcome::missed
                                         : CycleOutcome::double_strike;
    cycles.push_back(cycle);
  }
  return cycles;
}

namespace {

// The longest run of consecutive items that pass (the first of equally long ones): returns the
// index one past its last item and sets its length (0 when nothing passes). Items where
// `counted` is false are skipped: they neither extend nor break a run.
std::size_t longest_run_end(const std::vector<bool>& pass, const std::vector<bool>& counted,
                            std::size_t& best_length) {
  std::size_t best_end = 0, length = 0;
  best_length = 0;
  for (std::size_t i = 0; i < pass.size(); ++i) {
    if (!counted[i]) continue;
    length = pass[i] ? length + 1 : 0;
    if (length > best_length) {
      best_length = length;
      best_end = i + 1;
    }
  }
  return best_end;
}

}  // namespace

std::optional<std::size_t> first_alternating_window(const std::vector<CycleResult>& cycles,
                                                    int window_cycles) {
  if (window_cycles < 3) return std::nullopt;
  std::vector<std::size_t> judged;
  for (std::size_t i = 0; i < cycles.size(); ++i)
    if (cycles[i].judged) judged.push_back(i);
  const auto window = static_cast<std::size_t>(window_cycles);
  // `run` counts the judged cycles ending at k that alternate with all their predecessors in it
  std::size_t run = 0;
  for (std::size_t k = 0; k < judged.size(); ++k) {
    const CycleResult& c = cycles[judged[k]];
    if (c.strikes < 1 || c.strike_velocity_mps <= 0.0) {
      run = 0;
      continue;
    }
    if (run == 0) {
      run = 1;
    } else {
      const double previous = cycles[judged[k - 1]].strike_velocity_mps;
      const double speed = c.strike_velocity_mps;
      const bool far_apart =
          std::max(previous, speed) >= kAlternationRatio * std::min(previous, speed);
      // the sign of this change must differ from the previous change's
      const bool turns =
          run < 2 ||
          (speed - previous) * (previous - cycles[judged[k - 2]].strike_velocity_mps) < 0.0;
      if (!far_apart)
        run = 1;
      else if (!turns)
        run = 2;  // the last two cycles still make a start
      else
        ++run;
    }
    if (run >= window) return judged[k + 1 - window];
  }
  return std::nullopt;
}

void chirp_maximum(const std::vector<CycleResult>& cycles, int window_cycles, SweepResult& result) {
  result.max_frequency_hz.reset();
  result.first_failure.reset();
  result.limit_found = false;
  std::vector<bool> pass, counted;
  for (const CycleResult& c : cycles) {
    pass.push_back(c.success());
    counted.push_back(c.judged);
  }
  result.alternating_from_hz.reset();
  if (const auto start = first_alternating_window(cycles, window_cycles))
    result.alternating_from_hz = cycles[*start].frequency_hz;
  std::size_t length = 0;
  const std::size_t end = longest_run_end(pass, counted, length);
  std::size_t from = 0;
  if (length >= static_cast<std::size_t>(window_cycles)) {
    result.max_frequency_hz = cycles[end - 1].frequency_hz;
    from = end;
  }
  for (std::size_t k = from; k < cycles.size(); ++k) {
    if (!cycles[k].judged || cycles[k].success()) continue;
    result.first_failure = cycles[k];
    result.limit_found = true;
    return;
  }
}

namespace {

// The cycle that made a frequency fail: its first judged cycle that failed, not a settling one
// before it (which does not count, and was reported as the failure); else the cycle where its
// run stopped while settling.
std::optional<CycleResult> failing_cycle(const FrequencyResult& f) {
  for (const CycleResult& cycle : f.cycles)
    if (cycle.judged && !cycle.success()) return cycle;
  for (const CycleResult& cycle : f.cycles)
    if (cycle.outcome == CycleOutcome::stopped) return cycle;
  for (const CycleResult& cycle : f.cycles)
    if (!cycle.success()) return cycle;
  return std::nullopt;
}

}  // namespace

void steps_maximum(const std::vector<FrequencyResult>& frequencies, SweepResult& result) {
  result.max_frequency_hz.reset();
  result.first_failure.reset();
  result.limit_found = false;
  result.alternating_from_hz.reset();
  std::vector<bool> pass;
  for (const FrequencyResult& f : frequencies) {
    pass.push_back(f.passed);
    const auto judged = std::count_if(f.cycles.begin(), f.cycles.end(),
                                      [](const CycleResult& c) { return c.judged; });
    if (!result.alternating_from_hz && first_alternating_window(f.cycles, static_cast<int>(judged)))
      result.alternating_from_hz = f.frequency_hz;
  }
  std::size_t length = 0;
  const std::size_t end = longest_run_end(pass, std::vector<bool>(pass.size(), true), length);
  std::size_t from = 0;
  if (length > 0) {  // a passing frequency is a whole steady window already
    result.max_frequency_hz = frequencies[end - 1].frequency_hz;
    from = end;
  }
  for (std::size_t i = from; i < frequencies.size(); ++i) {
    if (frequencies[i].passed) continue;
    result.limit_found = true;
    result.first_failure = failing_cycle(frequencies[i]);
    return;
  }
}

std::string chirp_spec(const SweepOptions& options) {
  const double seconds = (options.f_max_hz - options.f_start_hz) / options.chirp_rate_hz_per_s;
  // 12 digits: the run's phase must be the one cycle_boundaries assumes
  return "motion:chirp:" + format_number(options.f_start_hz, 12) + ":" +
         format_number(options.f_max_hz, 12) + ":" + format_number(seconds, 12) + ":" +
         stroke_name(options.stroke);
}

namespace {

void check_options(const SweepOptions& o) {
  auto positive = [](double value, const std::string& what) {
    if (!(value > 0.0) || !std::isfinite(value))
      throw InputError(what + " must be a positive number (got " + format_number(value) + ")");
  };
  positive(o.f_start_hz, "sweep start frequency");
  positive(o.f_max_hz, "sweep maximum frequency (--fmax)");
  positive(o.chirp_rate_hz_per_s, "chirp rate");
  positive(o.step_hz, "frequency step");
  positive(o.step_s, "integrator step");
  if (!(o.f_max_hz > o.f_start_hz))
    throw InputError("sweep maximum frequency (--fmax) must be above the start frequency " +
                     format_number(o.f_start_hz) + " Hz (got " + format_number(o.f_max_hz) +
                     " Hz)");
  if (o.f_max_hz > kMaxKeyMotionHz)
    throw InputError("sweep maximum frequency (--fmax) must be at most " +
                     format_number(kMaxKeyMotionHz) + " Hz (got " + format_number(o.f_max_hz) +
                     " Hz)");
  // a chirp faster than this changes its frequency by more than itself within a cycle of the
  // lowest band (2 Hz): no cycle there is a cycle at one frequency; and its tail after the band
  // (a millisecond) would hold billions of cycles to judge
  constexpr double kMaxChirpRateHzPerS = 1000.0;
  if (o.mode == SweepMode::chirp && o.chirp_rate_hz_per_s > kMaxChirpRateHzPerS)
    throw InputError("chirp rate (--rate) must be at most " +
                     format_number(kMaxChirpRateHzPerS, 6) + " Hz per second (got " +
                     format_number(o.chirp_rate_hz_per_s) +
                     "): faster, the frequency changes within a cycle");
  // each step is a run of its own: more than this is a slip in the increment
  constexpr double kMaxSteps = 10000.0;
  const double steps = (o.f_max_hz - o.f_start_hz) / o.step_hz + 1.0;
  if (o.mode == SweepMode::steps && steps > kMaxSteps)
    throw InputError("frequency step (--step-hz) " + format_number(o.step_hz) + " Hz makes " +
                     format_number(steps, 3) + " steps from " + format_number(o.f_start_hz) +
                     " to " + format_number(o.f_max_hz) + " Hz: at most " +
                     format_number(kMaxSteps, 6) + " (a larger step)");
  if (o.settle_cycles < 0) throw InputError("settling cycles must not be negative");
  if (!(o.min_strike_speed_mps >= 0.0) || !std::isfinite(o.min_strike_speed_mps))
    throw InputError("the slowest strike speed must be 0 or more m/s (got " +
                     format_number(o.min_strike_speed_mps) + ")");
  if (o.window_cycles < 1) throw InputError("steady window must have at least one cycle");
}

SimulationOptions simulation_options(const SweepOptions& o, double duration) {
  SimulationOptions options;
  options.integrator = o.integrator;
  options.integrator_options.fixed_step_s = o.step_s;
  options.duration_s = duration;
  options.sample_interval_s = 0.0;
  return options;
}

std::vector<Impact> impacts_of(const SimulationResult& run) {
  std::vector<Impact> impacts;
  for (const SimEvent& e : run.events)
    if (e.type == "impact") impacts.push_back({e.t, e.hammer_velocity});
  return impacts;
}

// Keep the simulated time of a run a whole number of cycles plus a little, so that the last
// boundary falls inside the run.
constexpr double kTailS = 1e-3;

// Chirp time (s) a later segment runs before its own band, from rest: about 10 cycles or more
// in the bands of interest (≥ 10 Hz), after which the start from rest is forgotten (the upright's
// limit moves from 12.45 to 14.1 Hz when a segment starts from rest at 12.5 Hz without it).
constexpr double kOverlapS = 1.0;

// One chirp run over [f_a, f_b] (a segment of the sweep), classified. `done_s` accumulates the
// simulated time of all segments for the progress report.
struct ChirpSegment {
  double f_a = 0.0, f_b = 0.0;
  double t_offset_s = 0.0;   // where f_a falls in one continuous chirp from f_start
  double keep_from_s = 0.0;  // cycles starting earlier in the run belong to the segment before
  SimulationResult run;
  std::vector<CycleResult> cycles;
};

void run_chirp(const ActionModel& model, const RestState& rest, const SweepOptions& o,
               const ProgressCallback& progress, SweepResult& result) {
  // the fixed number of segments (the cut is part of the result, repetition_sweep.h), on the
  // threads there are; a trace (for a plot) is stitched from theirs like the cycles
  const unsigned threads = o.threads == 0 ? default_thread_count() : o.threads;
  const std::size_t count = std::max<std::size_t>(1, o.chirp_segments);
  std::vector<ChirpSegment> segments(count);
  double total_s = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    ChirpSegment& seg = segments[i];
    const double f_a = o.f_start_hz + (o.f_max_hz - o.f_start_hz) * static_cast<double>(i) / count;
    seg.f_b = o.f_start_hz + (o.f_max_hz - o.f_start_hz) * static_cast<double>(i + 1) / count;
    // a later segment starts kOverlapS of chirp earlier, from rest, and its cycles before f_a
    // are dropped: the action forgets its start from rest before it reaches its own band
    seg.f_a = std::max(o.f_start_hz, f_a - o.chirp_rate_hz_per_s * kOverlapS);
    // a half stroke's chirp starts after its first descent (half a period at its own start
    // frequency): the segment's phase origin and the continuous chirp's differ by that much
    const double origin = o.stroke == Stroke::half ? 0.5 / seg.f_a : 0.0;
    const double global_origin = o.stroke == Stroke::half ? 0.5 / o.f_start_hz : 0.0;
    seg.keep_from_s = origin + (f_a - seg.f_a) / o.chirp_rate_hz_per_s;
    seg.t_offset_s = global_origin - origin + (seg.f_a - o.f_start_hz) / o.chirp_rate_hz_per_s;
    total_s += (seg.f_b - seg.f_a) / o.chirp_rate_hz_per_s;
  }
  const InputContext context = input_context(model, rest);
  ProgressReporter reporter(progress, 1);
  std::mutex progress_mutex;  // keeps the reported fractions in order across segments
  double done_s = 0.0;        // simulated time of all segments so far
  const auto run_segment = [&](std::size_t i) {
    ChirpSegment& seg = segments[i];
    SweepOptions segment_options = o;
    segment_options.f_start_hz = seg.f_a;
    segment_options.f_max_hz = seg.f_b;
    const auto input = parse_input_spec(chirp_spec(segment_options), context);
    const double origin = o.stroke == Stroke::half ? 0.5 / seg.f_a : 0.0;
    const double duration = origin + (seg.f_b - seg.f_a) / o.chirp_rate_hz_per_s + kTailS;
    SimulationOptions options = simulation_options(o, duration);
    options.sample_interval_s = o.trace_interval_s;
    double last_report = 0.0;
    options.on_step = [&](double t) {
      if (t < last_report + 0.01) return true;  // every 10 ms of simulated time
      const double f = seg.f_a + o.chirp_rate_hz_per_s * std::max(0.0, t - origin);
      std::lock_guard<std::mutex> lock(progress_mutex);
      done_s += t - last_report;
      last_report = t;
      reporter.partial(done_s / total_s, format_number(std::round(f * 10.0) / 10.0) + " Hz of " +
                                             format_number(o.f_max_hz));
      return !reporter.cancelled();
    };
    seg.run = simulate(model, input.get(), options, &rest);
    seg.cycles =
        classify_cycles(cycle_boundaries(o.stroke, seg.f_a, o.chirp_rate_hz_per_s, duration),
                        impacts_of(seg.run), o.strike_merge_s, o.settle_cycles, seg.run.end_time,
                        seg.run.status != "ok", o.min_strike_speed_mps);
  };
  run_parallel(count, run_segment, nullptr, threads);
  reporter.throw_if_cancelled();
  for (const ChirpSegment& seg : segments) {
    // a segment's cycles are kept from where the kept ones of the segment before end (the cycle
    // across the cut did not finish in that run, so cutting at the band's edge left it out of
    // both): from the first cycle whose middle lies past that seam, and never one wholly before
    // the segment's band (its run-in from rest)
    const double seam_s = result.cycles.empty() ? -std::numeric_limits<double>::infinity()
                                                : result.cycles.back().t_end_s;
    for (CycleResult c : seg.cycles) {             // times as in one continuous chirp from f_start
      if (c.t_end_s <= seg.keep_from_s) continue;  // wholly before its band: the run-in
      c.t_start_s += seg.t_offset_s;
      c.t_end_s += seg.t_offset_s;
      if (0.5 * (c.t_start_s + c.t_end_s) < seam_s) continue;
      result.cycles.push_back(c);
    }
    result.simulated_s += seg.run.end_time;
    if (seg.run.status != "ok" && result.run_status == "ok") {
      result.run_status = seg.run.status;
      result.stop_cause = seg.run.stop_cause;
    }
  }
  result.trace.columns = segments.front().run.trace.columns;
  result.trace.metadata = segments.front().run.trace.metadata;
  for (const ChirpSegment& seg : segments) {
    for (const std::vector<double>& row : seg.run.trace.rows) {
      if (row.empty() || row.front() < seg.keep_from_s - 1e-12) continue;
      std::vector<double> shifted = row;
      shifted.front() += seg.t_offset_s;
      // a segment's last millisecond (its tail) lies under the next one's first rows
      if (!result.trace.rows.empty() && shifted.front() <= result.trace.rows.back().front())
        continue;
      result.trace.rows.push_back(std::move(shifted));
    }
  }
  chirp_maximum(result.cycles, o.window_cycles, result);
  reporter.item_done("done");
}

void run_steps(const ActionModel& model, const RestState& rest, const SweepOptions& o,
               const ProgressCallback& progress, SweepResult& result) {
  std::vector<double> frequencies;
  for (int i = 0;; ++i) {
    const double f = o.f_start_hz + i * o.step_hz;
    if (f > o.f_max_hz + 1e-9) break;
    frequencies.push_back(f);
  }
  const InputContext context = input_context(model, rest);
  std::vector<FrequencyResult> results(frequencies.size());
  std::vector<double> simulated(frequencies.size(), 0.0);
  ProgressReporter reporter(progress, frequencies.size());
  run_parallel(
      frequencies.size(),
      [&](std::size_t i) {
        const double f = frequencies[i];
        const auto input = parse_input_spec(
            "motion:sine:" + format_number(f, 12) + ":" + stroke_name(o.stroke), context);
        const int cycles = o.settle_cycles + o.window_cycles;
        const double origin = o.stroke == Stroke::half ? 0.5 / f : 0.0;
        const double duration = origin + cycles / f + kTailS;
        SimulationOptions options = simulation_options(o, duration);
        options.on_step = [&](double) { return reporter.still_wanted(); };
        const SimulationResult run = simulate(model, input.get(), options, &rest);
        FrequencyResult& out = results[i];
        out.frequency_hz = f;
        out.run_status = run.status;
        out.stop_cause = run.stop_cause;
        out.cycles = classify_cycles(cycle_boundaries(o.stroke, f, 0.0, duration), impacts_of(run),
                                     o.strike_merge_s, o.settle_cycles, run.end_time,
                                     run.status != "ok", o.min_strike_speed_mps);
        int judged = 0;
        for (const CycleResult& c : out.cycles) {
          if (!c.judged) continue;
          ++judged;
          if (!c.success()) ++out.failed_cycles;
        }
        out.passed = out.failed_cycles == 0 && judged == o.window_cycles;
        simulated[i] = run.end_time;  // run_parallel counts the finished frequency
      },
      &reporter, o.threads);
  reporter.throw_if_cancelled();
  result.frequencies = std::move(results);
  for (double s : simulated) result.simulated_s += s;
  steps_maximum(result.frequencies, result);
}

}  // namespace

SweepResult run_repetition_sweep(const ActionModel& model, const SweepOptions& options,
                                 const ProgressCallback& progress) {
  check_options(options);
  const auto start = std::chrono::steady_clock::now();
  const RestState rest = find_rest_state(model);
  SweepResult result;
  result.stroke = options.stroke;
  result.mode = options.mode;
  if (options.mode == SweepMode::chirp)
    run_chirp(model, rest, options, progress, result);
  else
    run_steps(model, rest, options, progress, result);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace pat

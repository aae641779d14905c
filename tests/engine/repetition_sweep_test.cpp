// The repetition sweep's definitions (analysis/repetition_sweep.h): cycle boundaries against the
// key motion they cut, the cycle classifier and both maximum rules on synthetic impact lists.
// The physics (fact F4) is in repetition_facts_test.cpp.
#include "analysis/repetition_sweep.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "inputs/key_input.h"
#include "test_support.h"

namespace pat {
namespace {

constexpr double kDip = 0.04;  // rad, a full-dip angle for the motion inputs

// Each boundary after the first must be an upper turning point of the key: rate zero and the
// angle at the stroke's top (0 for full, A/2 for half). Tolerances: the boundaries are closed
// forms of the same phase law, so only round-off separates them (1e-9 rad, 1e-6 rad/s at rates
// of order A·2πf ≈ 5 rad/s).
void expect_turning_points(const std::string& spec, Stroke stroke, double f0, double rate,
                           double t_end) {
  const auto input = parse_input_spec(spec, InputContext{kDip});
  const std::vector<double> b = cycle_boundaries(stroke, f0, rate, t_end);
  ASSERT_GT(b.size(), 5u);
  EXPECT_EQ(b.front(), 0.0);
  const double top = stroke == Stroke::full ? 0.0 : 0.5 * kDip;
  for (std::size_t k = 1; k < b.size(); ++k) {
    const KeyMotionSample m = input->motion(b[k]);
    EXPECT_NEAR(m.angle, top, 1e-9) << spec << " boundary " << k;
    EXPECT_NEAR(m.rate, 0.0, 1e-6) << spec << " boundary " << k;
    // the key's highest point is the angle's minimum (angles are positive down)
    EXPECT_GT(m.acceleration, 0.0) << "a top, not a bottom: " << spec << " boundary " << k;
    EXPECT_GT(b[k], b[k - 1]);
    EXPECT_LE(b[k], t_end);
  }
  // no turning point is skipped: the key reaches full dip once inside every cycle
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    double deepest = 0.0;
    for (int i = 1; i < 200; ++i)
      deepest = std::max(deepest, input->motion(b[k] + (b[k + 1] - b[k]) * i / 200.0).angle);
    EXPECT_NEAR(deepest, kDip, 1e-3 * kDip) << spec << " cycle " << k;  // 200 samples per cycle
  }
}

TEST(RepetitionCycles, SineBoundariesAreTheKeyTopsAtWholePeriods) {
  expect_turning_points("motion:sine:8:full", Stroke::full, 8.0, 0.0, 1.0);
  const std::vector<double> b = cycle_boundaries(Stroke::full, 8.0, 0.0, 1.0);
  ASSERT_EQ(b.size(), 9u);  // 0, 1/8, …, 8/8
  EXPECT_NEAR(b[3], 3.0 / 8.0, 1e-12);
}

TEST(RepetitionCycles, HalfStrokeBoundariesAreTheHalfReleases) {
  expect_turning_points("motion:sine:10:half", Stroke::half, 10.0, 0.0, 1.0);
  // cycle 0 holds the first descent and the first rise to half release: 0.05 s + 0.05 s
  EXPECT_NEAR(cycle_boundaries(Stroke::half, 10.0, 0.0, 1.0)[1], 0.1, 1e-12);
}

TEST(RepetitionCycles, ChirpBoundariesFollowTheRisingFrequency) {
  expect_turning_points("motion:chirp:2:12:10:full", Stroke::full, 2.0, 1.0, 10.0);
  expect_turning_points("motion:chirp:4:14:5:half", Stroke::half, 4.0, 2.0, 5.0);
  // the cycle frequency 1/duration tracks f0 + r t at the cycle's middle within the chirp's
  // curvature: over one cycle the period changes by r/f² ≈ 1 %, so 1 % of f
  const std::vector<double> b = cycle_boundaries(Stroke::full, 2.0, 1.0, 10.0);
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    const double mid = 0.5 * (b[k] + b[k + 1]);
    EXPECT_NEAR(1.0 / (b[k + 1] - b[k]), 2.0 + mid, 0.01 * (2.0 + mid));
  }
}

TEST(RepetitionCycles, ClassifierCountsStrikesMergesChatterAndFlagsSettling) {
  const std::vector<double> b{0, 1, 2, 3, 4, 5, 6};
  const std::vector<Impact> impacts{
      {0.5, 2.0},  // cycle 0: one strike
                   // cycle 1: none
      {2.2, 1.5},
      {2.6, 0.8},  // cycle 2: two strikes 0.4 s apart
      {3.5, 1.1},
      {3.501, 0.1},  // cycle 3: a strike and its chatter 1 ms later
      {3.999, 1.0},
      {4.001, 0.2},  // cycle 3 again; its chatter crosses into cycle 4
      {5.5, 1.3}};   // cycle 5
  const auto cycles = classify_cycles(b, impacts, 3e-3, 1, 6.0, false);
  ASSERT_EQ(cycles.size(), 6u);
  EXPECT_FALSE(cycles[0].judged);
  EXPECT_TRUE(cycles[1].judged);
  EXPECT_EQ(cycles[0].outcome, CycleOutcome::struck_once);
  EXPECT_DOUBLE_EQ(cycles[0].strike_velocity_mps, 2.0);
  EXPECT_EQ(cycles[1].outcome, CycleOutcome::missed);
  EXPECT_EQ(cycles[2].strikes, 2);
  EXPECT_EQ(cycles[2].outcome, CycleOutcome::double_strike);
  EXPECT_DOUBLE_EQ(cycles[2].strike_velocity_mps, 1.5);
  EXPECT_EQ(cycles[3].strikes, 2);  // 3.5 and 3.999 are separate blows
  EXPECT_EQ(cycles[4].strikes, 0);  // 4.001 belongs to the blow at 3.999
  EXPECT_EQ(cycles[4].outcome, CycleOutcome::missed);
  EXPECT_EQ(cycles[5].outcome, CycleOutcome::struck_once);
  EXPECT_DOUBLE_EQ(cycles[5].frequency_hz, 1.0);
}

// The points plotted against frequency: judged cycles only, at the cycle's own frequency in a
// chirp and at the run's frequency in steps, in the order given.
TEST(RepetitionCycles, JudgedCyclePointsLeaveOutSettlingAndUseTheRunFrequencyInSteps) {
  CycleResult settling;
  settling.judged = false;
  settling.frequency_hz = 4.9;
  CycleResult once;
  once.frequency_hz = 5.1;
  once.strikes = 1;
  once.strike_velocity_mps = 2.5;
  CycleResult missed;
  missed.frequency_hz = 5.2;
  missed.outcome = CycleOutcome::missed;

  SweepResult chirp;
  chirp.cycles = {settling, once, missed};
  const std::vector<CyclePoint> chirp_points = judged_cycle_points(chirp);
  ASSERT_EQ(chirp_points.size(), 2u);
  EXPECT_EQ(chirp_points[0].frequency_hz, 5.1);
  EXPECT_EQ(chirp_points[0].strikes, 1);
  EXPECT_EQ(chirp_points[0].strike_velocity_mps, 2.5);
  EXPECT_EQ(chirp_points[1].frequency_hz, 5.2);
  EXPECT_EQ(chirp_points[1].strikes, 0);

  SweepResult steps;
  steps.mode = SweepMode::steps;
  FrequencyResult at_5{5.0, true, 0, "ok", "", {settling, once}};
  FrequencyResult at_6{6.0, false, 1, "ok", "", {settling, missed}};
  steps.frequencies = {at_5, at_6};
  const std::vector<CyclePoint> step_points = judged_cycle_points(steps);
  ASSERT_EQ(step_points.size(), 2u);
  EXPECT_EQ(step_points[0].frequency_hz, 5.0);
  EXPECT_EQ(step_points[1].frequency_hz, 6.0);
  EXPECT_EQ(step_points[1].strikes, 0);
}

TEST(RepetitionCycles, AStoppedRunFailsTheCycleItStoppedIn) {
  const std::vector<double> b{0, 1, 2, 3, 4};
  const auto cycles = classify_cycles(b, {{0.5, 1.0}, {1.5, 1.0}, {2.2, 1.0}}, 3e-3, 0, 2.5, true);
  ASSERT_EQ(cycles.size(), 3u);
  EXPECT_TRUE(cycles[1].success());
  EXPECT_EQ(cycles[2].outcome, CycleOutcome::stopped);  // struck once, but did not finish
}

std::vector<CycleResult> cycles_from(const std::vector<std::pair<double, CycleOutcome>>& list,
                                     int settle) {
  std::vector<CycleResult> cycles;
  for (const auto& [f, outcome] : list) {
    CycleResult c;
    c.frequency_hz = f;
    c.outcome = outcome;
    c.judged = static_cast<int>(cycles.size()) >= settle;
    cycles.push_back(c);
  }
  return cycles;
}

TEST(RepetitionMaximum, ChirpTakesTheTopOfTheLongestRunOfSuccesses) {
  using O = CycleOutcome;
  const O ok = O::struck_once;
  SweepResult r;
  // a settling miss; too slow: a miss, a lucky pair, a double strike; the repeating range
  // 7–10 Hz; a miss; a lucky pair above the limit
  r.cycles = cycles_from({{2, O::missed},
                          {3, O::missed},
                          {4, ok},
                          {5, ok},
                          {6, O::double_strike},
                          {7, ok},
                          {8, ok},
                          {9, ok},
                          {10, ok},
                          {11, O::missed},
                          {12, ok},
                          {13, ok},
                          {14, O::missed}},
                         1);
  chirp_maximum(r.cycles, 3, r);
  ASSERT_TRUE(r.max_frequency_hz.has_value());
  EXPECT_EQ(*r.max_frequency_hz, 10.0);
  // the failures under the range are counted, not hidden by it: of the judged 3–6 Hz, a miss
  // and a double strike (the settling miss at 2 Hz is not judged)
  const auto below = failures_below_range(r);
  ASSERT_TRUE(below.has_value());
  EXPECT_EQ(below->range_from_hz, 7.0);
  EXPECT_EQ(below->judged, 4);
  EXPECT_EQ(below->doubles, 1);
  EXPECT_EQ(below->missed, 1);
  EXPECT_TRUE(r.limit_found);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_EQ(r.first_failure->outcome, O::missed);
  EXPECT_EQ(r.first_failure->frequency_hz, 11.0);

  r.cycles = cycles_from({{2, ok}, {3, ok}, {4, ok}}, 0);
  chirp_maximum(r.cycles, 2, r);
  EXPECT_EQ(*r.max_frequency_hz, 4.0);
  EXPECT_FALSE(r.limit_found);  // no failure up to the last frequency
  EXPECT_FALSE(r.first_failure.has_value());
  EXPECT_EQ(failures_below_range(r)->judged, 0);  // the range starts at the first cycle

  chirp_maximum(cycles_from({{2, ok}, {3, O::missed}, {4, ok}, {5, O::missed}}, 0), 2, r);
  EXPECT_FALSE(r.max_frequency_hz.has_value());  // no run of two successes
  EXPECT_EQ(r.first_failure->frequency_hz, 3.0);
  // a settling cycle does not count toward a run
  chirp_maximum(cycles_from({{2, ok}, {3, ok}, {4, O::missed}}, 1), 2, r);
  EXPECT_FALSE(r.max_frequency_hz.has_value());
  // of two equally long runs the first one counts
  chirp_maximum(cycles_from({{2, ok}, {3, ok}, {4, O::missed}, {5, ok}, {6, ok}}, 0), 2, r);
  EXPECT_EQ(*r.max_frequency_hz, 3.0);
  EXPECT_EQ(r.first_failure->frequency_hz, 4.0);
}

TEST(RepetitionMaximum, StepsTakesTheTopOfTheLongestRunOfPassingFrequencies) {
  auto frequency = [](double f, bool passed) {
    FrequencyResult r;
    r.frequency_hz = f;
    r.passed = passed;
    CycleResult c;
    c.frequency_hz = f;
    c.outcome = passed ? CycleOutcome::struck_once : CycleOutcome::missed;
    r.cycles = {c};
    return r;
  };
  SweepResult r;
  steps_maximum({frequency(4, false), frequency(10, true), frequency(11, true),
                 frequency(12, false), frequency(13, false)},
                r);
  EXPECT_EQ(*r.max_frequency_hz, 11.0);  // the too-slow failure at 4 Hz is below the limit
  EXPECT_TRUE(r.limit_found);
  EXPECT_EQ(r.first_failure->frequency_hz, 12.0);
  steps_maximum({frequency(10, false)}, r);
  EXPECT_FALSE(r.max_frequency_hz.has_value());
  EXPECT_TRUE(r.limit_found);
  steps_maximum({frequency(10, true)}, r);
  EXPECT_FALSE(r.limit_found);
  steps_maximum({frequency(10, true), frequency(11, false), frequency(12, true),
                 frequency(13, true), frequency(14, false)},
                r);
  EXPECT_EQ(*r.max_frequency_hz, 13.0);  // the longer run 12–13 Hz, not the lone 10 Hz
  EXPECT_EQ(r.first_failure->frequency_hz, 14.0);
  // below the range 12–13 Hz: the cycles of 10 and 11 Hz, the one of 11 Hz missed
  r.mode = SweepMode::steps;
  r.frequencies = {frequency(10, true), frequency(11, false), frequency(12, true),
                   frequency(13, true), frequency(14, false)};
  const auto below = failures_below_range(r);
  ASSERT_TRUE(below.has_value());
  EXPECT_EQ(below->range_from_hz, 12.0);
  EXPECT_EQ(below->judged, 2);
  EXPECT_EQ(below->missed, 1);
  EXPECT_EQ(below->doubles, 0);
}

// A failing frequency's failure is its first judged cycle that fails, not a settling cycle
// before it (a settling miss at 13 Hz was reported as the first failure, "judged": false).
TEST(RepetitionMaximum, StepsReportTheFirstJudgedFailureNotASettlingOne) {
  FrequencyResult f;
  f.frequency_hz = 13.0;
  f.passed = false;
  f.cycles = cycles_from({{13, CycleOutcome::missed},
                          {13, CycleOutcome::struck_once},
                          {13, CycleOutcome::double_strike},
                          {13, CycleOutcome::missed}},
                         2);
  for (std::size_t k = 0; k < f.cycles.size(); ++k) f.cycles[k].t_start_s = 0.1 * double(k);
  SweepResult r;
  steps_maximum({f}, r);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_TRUE(r.first_failure->judged);
  EXPECT_EQ(r.first_failure->outcome, CycleOutcome::double_strike);
  EXPECT_DOUBLE_EQ(r.first_failure->t_start_s, 0.2);
}

// Cycles that each strike once, with the given first-strike speeds (m/s); the first `settle`
// are not judged.
std::vector<CycleResult> struck_cycles(const std::vector<double>& speeds, int settle = 0) {
  std::vector<CycleResult> cycles;
  for (double v : speeds) {
    CycleResult c;
    c.frequency_hz = 10.0 + static_cast<double>(cycles.size());
    c.strikes = v > 0.0 ? 1 : 0;
    c.outcome = v > 0.0 ? CycleOutcome::struck_once : CycleOutcome::missed;
    c.strike_velocity_mps = v;
    c.judged = static_cast<int>(cycles.size()) >= settle;
    cycles.push_back(c);
  }
  return cycles;
}

TEST(RepetitionMaximum, AlternatingBlowsAreFoundWhereStrongAndWeakAlternate) {
  // one blow per cycle with a mild alternation (factor 1.27), then strong and weak blows (4.4
  // and 1.4 m/s) from index 6
  const std::vector<CycleResult> grand =
      struck_cycles({3.3, 2.6, 3.2, 2.6, 3.3, 2.6, 4.4, 1.4, 3.8, 1.3, 3.9, 1.2, 3.8, 1.4});
  ASSERT_TRUE(first_alternating_window(grand, 8).has_value());
  EXPECT_EQ(*first_alternating_window(grand, 8), 5u);  // 2.6 → 4.4 already differs 1.7 times
  EXPECT_FALSE(first_alternating_window(grand, 10).has_value());  // only 9 alternate
  // far apart but not alternating: a rising ramp has no change of sign
  EXPECT_FALSE(first_alternating_window(struck_cycles({0.5, 1, 2, 4, 8, 16}), 3).has_value());
  // a pair of equal speeds restarts the window; a missed cycle breaks it
  EXPECT_FALSE(first_alternating_window(struck_cycles({4, 1, 4, 4, 1, 4, 0, 1, 4}), 4).has_value());
  EXPECT_EQ(*first_alternating_window(struck_cycles({4, 1, 4, 4, 1, 4, 1}), 4), 3u);
  // a ramp's last step can start an alternation
  EXPECT_EQ(*first_alternating_window(struck_cycles({1, 2, 4, 1, 4}), 3), 1u);
  // cycles not judged do not count (the start-up from rest)
  EXPECT_EQ(*first_alternating_window(struck_cycles({4, 1, 4, 3, 1, 3, 1}, 3), 4), 3u);
  EXPECT_FALSE(first_alternating_window(struck_cycles({4, 1, 4, 1}, 1), 4).has_value());
  // an alternation needs at least two changes of sign
  EXPECT_FALSE(first_alternating_window(struck_cycles({4, 1, 4, 1}), 2).has_value());

  SweepResult r;
  chirp_maximum(grand, 4, r);
  ASSERT_TRUE(r.alternating_from_hz.has_value());
  EXPECT_EQ(*r.alternating_from_hz, 15.0);  // index 5
  chirp_maximum(struck_cycles({3, 3, 3, 3, 3}), 4, r);
  EXPECT_FALSE(r.alternating_from_hz.has_value());  // reset by a sweep without alternation

  FrequencyResult steady, alternating;
  steady.frequency_hz = 14.0;
  steady.passed = true;
  steady.cycles = struck_cycles({2.0, 3.0, 2.9, 3.0, 2.9, 3.0}, 2);
  alternating.frequency_hz = 14.5;
  alternating.cycles = struck_cycles({2.0, 3.0, 4.4, 1.4, 3.8, 1.3}, 2);
  steps_maximum({steady, alternating, alternating}, r);
  ASSERT_TRUE(r.alternating_from_hz.has_value());
  EXPECT_EQ(*r.alternating_from_hz, 14.5);
}

// The grand's full stroke, steady sines started from rest: at 16.5 Hz one even blow per cycle
// (3.1 m/s), at 20 Hz strong and weak blows in turn (5.1-5.4 against 1.9-2.0 m/s, a period
// doubling), which the steps mode reports.
TEST(RepetitionSweep, StepsReportWhereTheGrandsBlowsStartToAlternate) {
  const ActionModel grand = test::shipped("grand");
  SweepOptions o;
  o.mode = SweepMode::steps;
  o.f_start_hz = 16.5;
  o.f_max_hz = 20.0;
  o.step_hz = 3.5;
  const SweepResult r = run_repetition_sweep(grand, o);
  ASSERT_EQ(r.frequencies.size(), 2u);
  EXPECT_TRUE(r.frequencies[0].passed);
  ASSERT_TRUE(r.alternating_from_hz.has_value());
  EXPECT_EQ(*r.alternating_from_hz, 20.0);
}

// A slow halfway stroke (3 Hz: the key front moves at most 2π·3·2.5 mm = 47 mm/s) lets the
// grand's hammer off and drifts it onto the string at under 1 cm/s, which sounds no note: those
// touches are not strikes (min_strike_speed_mps, 0.1 m/s), so the cycles miss. Counting every
// impact, as before, called them successful repetitions.
TEST(RepetitionSweep, ATouchTooSlowToSoundIsNotAStrike) {
  const ActionModel grand = test::shipped("grand");
  SweepOptions o;
  o.mode = SweepMode::steps;
  o.stroke = Stroke::half;
  o.f_start_hz = 3.0;
  o.f_max_hz = 3.5;
  o.step_hz = 1.0;  // 3 Hz only
  const SweepResult counted = run_repetition_sweep(grand, o);
  ASSERT_EQ(counted.frequencies.size(), 1u);
  for (const CycleResult& c : counted.frequencies[0].cycles) {
    if (!c.judged) continue;
    EXPECT_EQ(c.strikes, 0) << "at " << c.t_start_s << " s: " << c.strike_velocity_mps << " m/s";
    EXPECT_EQ(c.outcome, CycleOutcome::missed);
  }
  EXPECT_FALSE(counted.frequencies[0].passed);
  // the same run with every impact a strike: the touches (under 0.1 m/s) pass as repetitions
  o.min_strike_speed_mps = 0.0;
  const SweepResult every_impact = run_repetition_sweep(grand, o);
  int touches = 0;
  for (const CycleResult& c : every_impact.frequencies[0].cycles)
    if (c.judged && c.strikes > 0) {
      ++touches;
      EXPECT_LT(c.strike_velocity_mps, 0.1);
    }
  EXPECT_GT(touches, 0);
}

TEST(RepetitionSweepOptions, InconsistentOptionsAreNamed) {
  SweepOptions o;
  o.f_max_hz = 1.0;  // below the 2 Hz start
  try {
    run_repetition_sweep(ActionModel{}, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--fmax"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_stroke("quarter", "--stroke"), InputError);
  EXPECT_THROW(parse_sweep_mode("random", "--mode"), InputError);
  EXPECT_EQ(chirp_spec(SweepOptions{}), "motion:chirp:2:20:18:full");
}

// Paces that would fill the memory are refused before any run: a chirp of 1e20 Hz/s (its
// millisecond tail past the band held ~1e14 cycles to judge; out of memory at 24 GB) and a
// steps increment of 1e-300 Hz (5e299 runs).
TEST(RepetitionSweepOptions, RunawayPacesAreRefusedBeforeAnyRun) {
  auto message = [](const SweepOptions& o) {
    // an empty model: no run could even start
    return test::error_of([&] { run_repetition_sweep(ActionModel{}, o); });
  };
  SweepOptions chirp;
  chirp.f_max_hz = 2.5;
  chirp.chirp_rate_hz_per_s = 1e20;
  EXPECT_NE(message(chirp).find("--rate"), std::string::npos) << message(chirp);
  SweepOptions steps;
  steps.mode = SweepMode::steps;
  steps.f_max_hz = 2.5;
  steps.step_hz = 1e-300;
  EXPECT_NE(message(steps).find("--step-hz"), std::string::npos) << message(steps);
}

}  // namespace
}  // namespace pat

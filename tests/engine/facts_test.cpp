// Facts of DESIGN.md section 2 that the engine issue must reproduce (F2, F3, F8), static rest,
// and that every contact of both actions takes part in some run.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "integrators/integrator_factory.h"
#include "model/model_edits.h"
#include "test_support.h"

namespace pat {
namespace {

class BothActions : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Presets, BothActions, ::testing::Values("grand", "upright"));

double first_impact_velocity(const SimulationResult& r) {
  const auto impacts = test::events_of(r, "impact");
  return impacts.empty() ? 0.0 : impacts.front()->hammer_velocity;
}

TEST_P(BothActions, F2_SoftToVeryLoudKeyForcesSpanOneToSixMetresPerSecond) {
  const ActionModel model = test::shipped(GetParam());
  const double soft = first_impact_velocity(test::run(model, "force:pulse:2:200", 0.3));
  const double loud = first_impact_velocity(test::run(model, "force:pulse:50:200", 0.1));
  std::printf("%s: 2 N -> %.2f m/s, 50 N -> %.2f m/s\n", GetParam().c_str(), soft, loud);
  // "about 1 to 6 m/s" (Russell & Rossing; Kinoshita): soft within 0.9–1.5, loud within 4.5–7.5.
  // Measured: grand 1.05 and 6.59, upright 1.14 and 7.26 m/s. "About 1" with a 10 % margin below
  // (a 2 N blow a tenth slower than 1 m/s is still a soft blow, one at half of it is not). The
  // upright's loud blow is beyond "about 6" (README, limits: the jack slides out from under the
  // butt in loud blows and drives the hammer up to the string); 7.5 keeps it from growing
  // further unnoticed.
  EXPECT_GT(soft, 0.9);
  EXPECT_LT(soft, 1.5);
  EXPECT_GT(loud, 4.5);
  EXPECT_LT(loud, 7.5);
  // and monotone in between
  double previous = soft;
  for (double force : {5.0, 10.0, 20.0}) {
    const double v = first_impact_velocity(
        test::run(model, "force:pulse:" + std::to_string(force) + ":200", 0.2));
    EXPECT_GT(v, previous) << force << " N";
    previous = v;
  }
  EXPECT_GT(loud, previous);
}

TEST_P(BothActions, F3_OneKilogramOnTheKeyStrikesWithinATenthOfASecondThenIsCaught) {
  const ActionModel model = test::shipped(GetParam());
  const SimulationResult r = test::run(model, "mass:1kg", 0.2);
  ASSERT_EQ(r.status, "ok") << r.stop_cause;
  const auto impacts = test::events_of(r, "impact");
  ASSERT_FALSE(impacts.empty());
  std::printf("%s: 1 kg -> impact at %.1f ms\n", GetParam().c_str(), impacts[0]->t * 1e3);
  EXPECT_GT(impacts[0]->t, 0.03);  // paper section 6: strike within about 0.03-0.1 s
  EXPECT_LT(impacts[0]->t, 0.1);
  const auto checks = test::events_of(r, "check");
  ASSERT_FALSE(checks.empty());
  EXPECT_GT(checks[0]->t, impacts[0]->t);
}

TEST_P(BothActions, RestingActionIsInStaticEquilibrium) {
  const ActionModel model = test::shipped(GetParam());
  const SimulationResult r = test::run(model, "force:const:0", 2.0);
  ASSERT_EQ(r.status, "ok");
  double worst = 0.0;
  for (const auto& row : r.trace.rows)
    for (int k = 0; k < model.dofs(); ++k) worst = std::max(worst, std::abs(row[1 + k]));
  // no drift: every body stays within 0.01° of its rest angle for 2 s
  EXPECT_LT(worst, 0.01);
  EXPECT_TRUE(r.events.empty());
}

TEST_P(BothActions, EveryContactTakesPartInSomeRun) {
  const ActionModel model = test::shipped(GetParam());
  std::set<std::string> touched;
  // force:pulse:50:10, a staccato forte blow: the key let go as it bottoms, before the
  // backcheck can hold the hammer, which falls back onto the grand's hammer rest rail (let go at
  // 20 ms, the hammer is caught first; the damper, sent back by its stop rail, then lands on the
  // rising key and lets the hammer down without reaching the rail within 0.4 s)
  auto collect = [&](const SimulationResult& r) {
    for (std::size_t c = 0; c < r.trace.columns.size(); ++c) {
      const std::string& column = r.trace.columns[c];
      if (column.size() < 8 || column.substr(column.size() - 8) != "_force_n") continue;
      for (const auto& row : r.trace.rows)
        if (row[c] > 0.0) touched.insert(column);
    }
  };
  for (const char* spec :
       {"mass:1kg", "force:pulse:50:200", "force:pulse:50:10", "motion:sine:2", "force:const:0"})
    collect(test::run(model, spec, 0.4));
  // the grand's lever rest holds the lever only when its spring is gone (--without)
  if (model.kind == "grand")
    collect(test::run(without_part(model, "repetition_spring"), "force:const:0", 0.1));
  for (const Contact& contact : model.contacts)
    EXPECT_TRUE(touched.count(column_name(contact.name) + "_force_n")) << contact.name;
}

/// Largest difference in a trace column between two runs sampled alike, and the column's range
/// in the second (the reference), in the column's unit.
struct ColumnError {
  double error = 0.0, range = 0.0;
};
ColumnError column_error(const SimulationResult& run, const SimulationResult& reference,
                         const std::string& column) {
  const auto a = run.trace.column(column);
  const auto b = reference.trace.column(column);
  EXPECT_EQ(a.size(), b.size()) << column;
  double error = 0.0, lo = 0.0, hi = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    error = std::max(error, std::abs(a[i] - b[i]));
    lo = std::min(lo, b[i]);
    hi = std::max(hi, b[i]);
  }
  return {error, hi - lo};
}
ColumnError hammer_error(const SimulationResult& run, const SimulationResult& reference) {
  return column_error(run, reference, "hammer_angle_deg");
}

/// The grand driven by `spec` for `duration` with the W-method at its default step and with the
/// RODAS4 reference at rtol 1e-8; both must run to the end.
struct AgainstReference {
  SimulationResult w2, reference;
};
AgainstReference grand_against_reference(const std::string& spec, double duration) {
  const ActionModel model = test::shipped("grand");
  AgainstReference runs{test::run(model, spec, duration),
                        test::run(model, spec, duration, "rodas", 1e-8)};
  EXPECT_EQ(runs.w2.status, "ok") << spec;
  EXPECT_EQ(runs.reference.status, "ok") << spec;
  return runs;
}

TEST(Integrators, F8_W2AgainstAdaptiveReferenceOnGrandDoubleBlow) {
  const ActionModel model = test::shipped("grand");
  const std::string blow = "force:double:20:40:60";
  const auto [w2, ref] = grand_against_reference(blow, 0.3);
  const ColumnError e = hammer_error(w2, ref);
  std::printf("w2 vs rodas: max hammer angle error %.4f deg = %.3f %% of %.2f deg\n", e.error,
              100 * e.error / e.range, e.range);
  EXPECT_LT(e.error, 0.02 * e.range);  // the paper's 2 % (section 3.2)
  // DESIGN.md's aim is 0.5 %; 0.36 % measured. The error at 1e-5 s is not yet in the asymptotic
  // regime (contacts open and close inside steps; 13 % at 2e-5 s), so a bound at the aim itself
  // would flip with any change of the model: 1 % still catches a twofold regression.
  EXPECT_LT(e.error, 0.01 * e.range);
  // and it converges: half the step, at least three times less error (0.028 % measured)
  SimulationOptions half;
  half.duration_s = 0.3;
  half.integrator_options.fixed_step_s = 5e-6;
  const RestState rest = find_rest_state(model);
  const auto input = parse_input_spec(blow, input_context(model, rest));
  const SimulationResult finer = simulate(model, input.get(), half, &rest);
  ASSERT_EQ(finer.status, "ok");
  const ColumnError f = hammer_error(finer, ref);
  std::printf("w2 at 5e-6 s: %.3f %%\n", 100 * f.error / f.range);
  EXPECT_LT(f.error, e.error / 3.0);
}

// The W-method on a motion-driven run (the sweeps, the deregulation, the practice's repetition
// all prescribe the key): against RODAS4 at rtol 1e-8 on the grand under a 10 Hz full-stroke
// sine, both the hammer angle and the finger force, an output that the key's equation gives
// from the accelerations. Measured: hammer 0.026 % of its range; finger force 0.08 N of its
// 35 N range (0.23 %). The bounds, 0.1 % and 1 %, are four times those.
TEST(Integrators, W2OnAPrescribedKeyMotionAgreesWithTheReference) {
  const std::string motion = "motion:sine:10:full";
  const auto [w2, ref] = grand_against_reference(motion, 0.3);
  const ColumnError hammer = hammer_error(w2, ref);
  const ColumnError finger = column_error(w2, ref, "finger_force_n");
  std::printf("w2 vs rodas on %s: hammer %.4f %% of %.1f deg, finger force %.4f N of %.2f N\n",
              motion.c_str(), 100 * hammer.error / hammer.range, hammer.range, finger.error,
              finger.range);
  EXPECT_LT(hammer.error, 1e-3 * hammer.range);
  EXPECT_LT(finger.error, 1e-2 * finger.range);
}

// A key held after a blow (the window's commonest state): the grand's hammer tail wedged on the
// backcheck is held by the leather's stiff regularized friction. At the window's step
// (kW2HeldKeyStepS) the W-method agrees with RODAS4 at rtol 1e-8 over the held 0.2 s, in the
// hammer angle and in the backcheck force; at the default 1e-5 s it chatters (README, Limits),
// which the last check asserts so that a fix shows up here. Measured: hammer 0.0002 deg, the
// backcheck force 0.48 N of its 42 N range (1.1 %); at the default step 21.7 N (51 %). The
// bounds: 0.01 deg (under a pixel of the drawn hammer at any zoom a class uses) and 10 % of the
// range for the force (the chatter is five times that).
TEST(Integrators, W2AtTheWindowStepHoldsTheCaughtHammerLikeTheReference) {
  const ActionModel model = test::shipped("grand");
  const std::string held = "force:pulse:20:1000";
  constexpr double kDuration = 0.2;  // s: caught at about 30 ms, held from then on
  const SimulationResult reference = test::run(model, held, kDuration, "rodas", 1e-8);
  const RestState rest = find_rest_state(model);
  const auto input = parse_input_spec(held, input_context(model, rest));
  SimulationOptions options;
  options.duration_s = kDuration;
  options.integrator_options.fixed_step_s = kW2HeldKeyStepS;
  const SimulationResult window = simulate(model, input.get(), options, &rest);
  const SimulationResult fallback = test::run(model, held, kDuration);  // the default 1e-5 s
  ASSERT_EQ(window.status, "ok");
  ASSERT_EQ(reference.status, "ok");
  const ColumnError hammer = hammer_error(window, reference);
  const ColumnError check = column_error(window, reference, "hammer_tail_backcheck_force_n");
  const ColumnError coarse = column_error(fallback, reference, "hammer_tail_backcheck_force_n");
  std::printf(
      "held key: hammer %.4f deg of %.1f, backcheck force %.2f N of %.1f (default "
      "step: %.2f N)\n",
      hammer.error, hammer.range, check.error, check.range, coarse.error);
  EXPECT_LT(hammer.error, 0.01);  // deg
  EXPECT_LT(check.error, 0.1 * check.range);
  EXPECT_GT(coarse.error, 0.3 * check.range);  // the default step's chatter (known limit)
}

}  // namespace
}  // namespace pat

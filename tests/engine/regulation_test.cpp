// Regulation: the technician's measurements, the static equilibrium they stand on, automatic
// regulation, writing a regulated preset, live deregulation, and their bad input.
#include "regulation/regulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "model/model_edits.h"
#include "regulation/deregulation.h"
#include "regulation/measurements.h"
#include "regulation/technician_tests.h"
#include "sim/static_equilibrium.h"
#include "test_support.h"

namespace pat {
namespace {

using test::shipped;

double measure_at(const ActionModel& model, const std::string& setting, double mm) {
  const ActionModel moved = with_adjuster(model, setting, mm * 1e-3);
  const RestState rest = find_rest_state(moved);
  return measure_setting(moved, setting, &rest);
}

// Newton's static equilibrium agrees with the damped dynamic settle. Tolerance 1e-4 rad
// (0.014 mm at the strike point): the settle ends with joint speeds below 1e-2 rad/s and the
// felts still creeping.
TEST(Regulation, NewtonRestStateMatchesTheDynamicSettle) {
  for (const char* name : {"grand", "upright"}) {
    const ActionModel model = shipped(name);
    const RestState settled = find_rest_state(model);
    DofVector q;
    ASSERT_TRUE(solve_static_equilibrium(model, settled.q, q)) << name;
    EXPECT_LT((q - settled.q).cwiseAbs().maxCoeff(), 1e-4) << name;
    // from a neighbouring model (an adjuster moved by 0.3 mm) continuation finds that
    // model's own settled rest
    const ActionModel moved = with_adjuster(model, "hammer_blow", 0.3e-3);
    const RestState near = rest_state_near(moved, settled);
    EXPECT_LT((near.q - find_rest_state(moved).q).cwiseAbs().maxCoeff(), 1e-4) << name;
  }
}

// Closed forms: the blow is the strike point's distance to the string plane at rest, and the
// key dip is the key front's drop when the key turns to the punching (geometry).
TEST(Regulation, RestMeasurementsAgreeWithDirectGeometry) {
  for (const char* name : {"grand", "upright"}) {
    const ActionModel model = shipped(name);
    const RestState rest = find_rest_state(model);
    ActionDynamics dynamics(model, nullptr);
    const ActionLandmarks& m = model.landmarks;
    const Vec2 strike = dynamics.point_position(m.hammer, m.strike_point, rest.q);
    const double blow_mm = -m.string_normal.dot(m.string_point - strike) * -1e3;
    EXPECT_NEAR(measure_setting(model, "hammer_blow", &rest), std::abs(blow_mm), 1e-9) << name;
    // key dip: turn the key until the punching contact closes; the key front's drop
    const Contact& bottom = model.contacts[m.key_bottom_contact];
    const Vec2 key_point = bottom.center_a;  // the key's side of the punching contact
    // the contact point closes its gap d over an arc of radius |p|; the key front drops by the
    // same angle times its own arm: dip = d / |p_x| * |front_x| (small angle, to 1 %)
    const double gap = bottom.segment_normal.dot(dynamics.point_position(m.key, key_point, rest.q) -
                                                 bottom.segment_start) -
                       bottom.radius_a;
    const double small_angle_dip = gap / std::abs(key_point.x()) * std::abs(m.key_front.x());
    EXPECT_NEAR(measure_setting(model, "key_dip", &rest), small_angle_dip * 1e3,
                0.01 * small_angle_dip * 1e3)
        << name;
  }
}

struct MonotoneCase {
  const char* action;
  const char* setting;
  double from_mm, to_mm;
  double step_mm = 0.5;
  /// Measured as the preset's regulation measures it when the setting asks another adjuster out
  /// of the way first (its clear_first: the grand's let-off with the drop screw screwed down).
  bool other_cleared = false;
};

class MeasurementResponse : public ::testing::TestWithParam<MonotoneCase> {};

// Each measurement responds monotonically to its own adjuster over the range tested (strictly:
// every step changes it by more than 1 µm, or 0.001 of a fraction, always in the same
// direction). 1 µm is fifty times below the 0.05 mm regulation tolerance, and two orders of
// magnitude above the procedures' repeatability (about 1e-2 µm at rest, 1 µm in a press).
TEST_P(MeasurementResponse, IsMonotoneInItsAdjuster) {
  const MonotoneCase c = GetParam();
  ActionModel model = shipped(c.action);
  if (c.other_cleared) {
    const RegulationSetting& s = model.regulation[model.setting_index(c.setting)];
    ASSERT_FALSE(s.clear_adjuster.empty()) << c.setting << " has no clear_first in the preset";
    model = with_adjuster(model, s.clear_adjuster, s.clear_position);
  }
  std::vector<double> values;
  for (double x = c.from_mm; x <= c.to_mm + 1e-9; x += c.step_mm)
    values.push_back(measure_at(model, c.setting, x));
  std::printf("%s %s from %g mm:", c.action, c.setting, c.from_mm);
  for (double v : values) std::printf(" %.4g", v);
  std::printf("\n");
  const double direction = values.back() > values.front() ? 1.0 : -1.0;
  for (std::size_t i = 1; i < values.size(); ++i)
    EXPECT_GT(direction * (values[i] - values[i - 1]), 1e-3)
        << c.action << " " << c.setting << " at step " << i << " ("
        << c.from_mm + c.step_mm * (i - 1) << " → " << c.from_mm + c.step_mm * i
        << " mm: " << values[i - 1] << " → " << values[i] << ")";
}

// The ranges are those over which each adjuster acts on the shipped presets (adjuster mm from
// the regulated position; readings measured with measure_setting in 0.25 mm steps, finer for
// the damper spoon). Where a range is narrower than the adjuster's physical range, the comment
// names the part that takes over beyond it.
INSTANTIATE_TEST_SUITE_P(
    Settings, MeasurementResponse,
    ::testing::Values(
        MonotoneCase{"grand", "key_dip", -2, 2}, MonotoneCase{"grand", "jack_position", -3, 3},
        // knuckle–jack gap 0.10 mm at 0, 3.70 mm at +2.5; from about −0.05 mm the knuckle sits
        // on the jack and the reading is minus the lever top's gap below it (−3.18 mm at −2.5;
        // as a bare knuckle–jack gap it would stay at −0.07 mm, the felt's compression)
        MonotoneCase{"grand", "lever_height", -2.5, 2.5},
        MonotoneCase{"grand", "hammer_blow", -1, 1},
        // with the drop screw cleared (+1 mm: the lever stops with the hammer 7.5 mm from the
        // string) let-off reads 0.32 mm at −0.25 and 6.8 mm at +1.0. Below −0.25 mm the jack
        // lifts the hammer into the string before its toe trips (blocking: at −0.5 mm the head
        // presses the string and the reading stays at 0.28 mm; no escapement from −0.75);
        // beyond +1.0 mm the toe trips before the jack takes the knuckle over from the lever,
        // so the jack never carries the hammer
        MonotoneCase{"grand", "let_off", -0.25, 1.0, 0.25, true},
        // 1.83 mm at −0.25 to 16.6 mm at +3 (3.0 at 0). At −0.25 mm the lever holds the hammer
        // only 0.17 mm below where the jack let it off (1.66 mm), and from −0.3 mm no lower
        // (1.60 and 1.57 mm; at −0.4 the lever carries it on to 1.13 mm): the drop is read
        // because the tipped jack stands clear of the knuckle. From −0.5 mm the lever carries
        // the knuckle past let-off and the jack never lifts the hammer. Beyond +3 mm the
        // falling knuckle comes to rest against the side of the tipped jack, above the lever
        // (17.14 mm at +3.5, 17.01 at +4, the lever 0.7 mm below the knuckle)
        MonotoneCase{"grand", "drop", -0.25, 3},
        // 19.3 mm at −1.5 to 14.3 mm at +1.0. From −1.75 mm the hammer's tail passes below
        // the lower end of the backcheck's face and is never caught; from +1.25 mm the face
        // (stiff enough to catch a forte rebound on its first pass) stops the rising tail and
        // the hammer never reaches the string
        MonotoneCase{"grand", "checking", -1.5, 1.0}, MonotoneCase{"upright", "key_dip", -2, 2},
        // 47.90 mm at −1 to 42.15 mm at +2 (about 1.9 mm of blow per mm of rail). From about
        // −1.4 mm the butt comes down on the jack (the 0.3 mm of lost motion used up) and the
        // jack, not the rail, holds the hammer (48.53 mm at −1.35, 48.78 mm at −1.5 and at −2):
        // the regulation screws the capstan down first (clear_first)
        MonotoneCase{"upright", "hammer_blow", -1, 2},
        // the jack–butt gap at rest, 2.67 mm at −2 to −0.034 mm at +0.5 (about 1.2 mm per mm of
        // capstan); from about +0.25 mm the jack lifts the butt off its rail and the reading is
        // the felt's compression under the hammer's return torque, which hardly changes as the
        // butt rises (gravity falls off as the spring winds up): −0.0337 mm at +0.5, −0.0339 at
        // +0.75, −0.0341 at +1, steps under the 1 µm this test asks for
        MonotoneCase{"upright", "lost_motion", -2, 0.5},
        // 0.05 mm at −0.5 to 38.3 mm at +4 (about 6 mm per mm near regulation). At −0.5 mm
        // the jack already lifts the hammer into the string before its toe trips (0.05 mm, the
        // same down to −1.25 whatever the button); from −1.5 mm the slow press finds the
        // hammer's catcher meeting the backcheck on its way up and reads no let-off
        MonotoneCase{"upright", "let_off", -0.5, 4, 0.25},
        // 42.3 mm at −3.6 to 14.4 mm at +0.4. Beyond, the reading goes on falling (14.1 mm at
        // +0.5, 13.0 mm at +0.75, 0.7 mm at +1.25), but from about +0.75 mm the backcheck holds
        // the hammer so near the string that the forte blow, key held, strikes twice (a second,
        // weak strike: 0.18 m/s at +0.75)
        MonotoneCase{"upright", "checking", -3.6, 0.4}, MonotoneCase{"upright", "bridle", -2, 2},
        // a fraction of the hammer travel, 0.94 at −0.375 to 0.15 at +0.375 (about 1.1 per mm
        // of spoon; 0.97 at −0.5, 0.06 at +0.5). From about +0.6 mm the spoon already holds the
        // damper at rest; below about −0.55 mm it reaches the damper only after let-off (read as
        // unmeasurable, not as a fraction)
        MonotoneCase{"upright", "damper_lift", -0.375, 0.375, 0.125}),
    [](const auto& info) { return std::string(info.param.action) + "_" + info.param.setting; });

// A damper spoon so far back that the damper lifts only after let-off (upright, −0.75 mm) is not
// read as a fraction of the hammer travel: the hammer is then falling back, and the fraction
// read from its position would shrink the later the damper lifts (0.72 at −0.75 mm, 0.41 at
// −1 mm, against 0.97 at −0.5 mm).
// The aftertouch, the seven settings' result: on the regulated grand the key has about the
// technicians' .035–.045 in (0.9–1.1 mm, domain notes) left at let-off; 0.94 mm measured, the
// band 0.8–1.3 mm. It follows the key dip: the punching moves the key's bottom, not its let-off
// point, so a deeper dip leaves more aftertouch and a shallower one less, by most of the dip's
// change (0.86 of it measured).
// A result's difference from the paper's is put down to the settings only when they are off:
// automatic regulation leaves micrometres in the adjusters, and the action is still regulated.
TEST(Regulation, MicrometresLeftInTheAdjustersAreStillRegulated) {
  const ActionModel grand = test::shipped("grand");
  EXPECT_EQ(regulation_state(grand), "regulated");
  // 1 µm of jack position: every reading within tolerance (the jack's own ±0.05 mm)
  EXPECT_EQ(regulation_state(with_adjuster(grand, "jack_position", 1e-6)), "regulated");
  // 0.2 mm of let-off button: let-off 1.5 → about 2.7 mm, named
  EXPECT_EQ(regulation_state(with_adjuster(grand, "let_off", 0.2e-3)), "let_off=0.2mm");
}

TEST(Regulation, GrandAftertouchIsAboutAMillimetreAndFollowsTheKeyDip) {
  const ActionModel grand = shipped("grand");
  const double aftertouch = measure_aftertouch(grand);
  std::printf("grand aftertouch %.3f mm\n", aftertouch);
  EXPECT_GT(aftertouch, 0.8);
  EXPECT_LT(aftertouch, 1.3);
  for (double offset : {-0.2e-3, 0.2e-3}) {  // + adds punchings: less dip
    const ActionModel changed = with_adjuster(grand, "key_dip", offset);
    const double dip_change =
        measure_setting(changed, "key_dip") - measure_setting(grand, "key_dip");
    const double change = measure_aftertouch(changed) - aftertouch;
    EXPECT_GT(change / dip_change, 0.7) << offset;
    EXPECT_LT(change / dip_change, 1.1) << offset;
  }
}

TEST(Regulation, DamperLiftingAfterLetOffIsNotReadAsAFraction) {
  const ActionModel model = shipped("upright");
  try {
    const double fraction = measure_at(model, "damper_lift", -0.75);
    FAIL() << "read as a fraction: " << fraction;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("only after the jack has escaped"), std::string::npos)
        << e.what();
  }
}

// Reading every setting at once: a setting that cannot be read (the button 0.5 mm down: it trips
// the jack before the jack takes the knuckle over from the repetition lever, so the jack never
// lifts the hammer: no drop) gets its reason and the others are still read, as each reads alone;
// measure_settings throws that reason instead. The let-off is read as a technician reads it
// then, with the drop screw out of the way (its clear_first move), and says so: the textbook
// fault (a button screwed down, an early let-off) reads far out of tolerance instead of giving
// no reading.
TEST(Regulation, ReadingEverySettingReportsTheUnreadableOnesAndReadsTheRest) {
  const ActionModel model = with_adjuster(test::shipped("grand"), "let_off", 0.5e-3);
  const std::vector<SettingReading> readings = read_settings(model);
  ASSERT_EQ(readings.size(), model.regulation.size());
  for (const SettingReading& r : readings) {
    if (r.name == "let_off") {
      // the same as a press with the drop screw turned to its clear position (deterministic)
      const RegulationSetting& s = model.regulation[model.setting_index("let_off")];
      EXPECT_EQ(r.measured,
                measure_setting(with_adjuster(model, s.clear_adjuster, s.clear_position), r.name));
      // an early let-off: the hammer leaves the jack farther from the string than 1.5 mm, and
      // farther than the 3 mm at which the lever holds it
      EXPECT_GT(r.measured, 3.0);
      EXPECT_FALSE(r.within_tolerance());
      EXPECT_TRUE(r.problem.empty()) << r.problem;
      EXPECT_NE(r.note.find("with the drop screw out of the way (drop +1.00 mm)"),
                std::string::npos)
          << r.note;
      EXPECT_NE(r.note.find("held there"), std::string::npos) << r.note;
      continue;
    }
    if (r.name == "drop") {
      EXPECT_TRUE(std::isnan(r.measured)) << r.name;
      EXPECT_NE(r.problem.find("never lifts the hammer"), std::string::npos) << r.problem;
      EXPECT_FALSE(r.within_tolerance()) << r.name;
      continue;
    }
    EXPECT_TRUE(r.note.empty()) << r.name << ": " << r.note;
    EXPECT_TRUE(r.problem.empty()) << r.name << ": " << r.problem;
    EXPECT_EQ(r.measured, measure_setting(model, r.name)) << r.name;  // deterministic runs
  }
  EXPECT_DOUBLE_EQ(readings[model.setting_index("let_off")].adjuster_mm, 0.5);
  EXPECT_THROW(measure_settings(model), std::runtime_error);
}

// A regulated (here: deliberately offset) preset written and read back measures the same, and
// its adjusters read 0 again. Tolerance 1e-3 mm: offsets are written to 0.1 µm.
TEST(Regulation, WrittenPresetReadsBackWithTheSameMeasurements) {
  ActionModel model = shipped("grand");
  model = with_adjuster(model, "hammer_blow", 0.4e-3);
  model = with_adjuster(model, "checking", -0.7e-3);
  model = with_adjuster(model, "key_dip", 0.25e-3);
  const std::string path = ::testing::TempDir() + "/regulated-grand.json";
  write_preset(model, path);
  const ActionModel back = load_action(path);
  for (const Adjuster& a : back.adjusters) EXPECT_EQ(a.value, 0.0) << a.name;
  const RestState rest_a = find_rest_state(model), rest_b = find_rest_state(back);
  for (const char* s : {"key_dip", "jack_position", "lever_height", "hammer_blow", "checking"})
    EXPECT_NEAR(measure_setting(model, s, &rest_a), measure_setting(back, s, &rest_b), 1e-3) << s;
  // every contact's geometry and every fixture came through
  ASSERT_EQ(back.contacts.size(), model.contacts.size());
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    EXPECT_LT((back.contacts[i].center_a - model.contacts[i].center_a).norm(), 1e-9);
    EXPECT_LT((back.contacts[i].segment_start - model.contacts[i].segment_start).norm(), 1e-9);
  }
  ASSERT_EQ(back.fixtures.size(), model.fixtures.size());
  for (std::size_t i = 0; i < model.fixtures.size(); ++i)
    for (std::size_t k = 0; k < model.fixtures[i].outline.size(); ++k)
      EXPECT_LT((back.fixtures[i].outline[k] - model.fixtures[i].outline[k]).norm(), 1e-9);
  EXPECT_EQ(back.regulation.size(), model.regulation.size());
  // written twice, the offsets accumulate on the preset's own (not reset)
  const std::string again = ::testing::TempDir() + "/regulated-grand-2.json";
  write_preset(with_adjuster(back, "hammer_blow", 0.1e-3), again);
  EXPECT_NEAR(measure_setting(load_action(again), "hammer_blow"),
              measure_setting(with_adjuster(model, "hammer_blow", 0.5e-3), "hammer_blow"), 1e-3);
  std::remove(path.c_str());
  std::remove(again.c_str());
}

// Fact F1 (paper 5.3): automatic regulation of the grand, every adjuster first turned 0.2–0.3 mm
// off (the shipped preset is regulated already), converges with every one of the seven settings
// within its tolerance of its target (0.05 mm each, as in the preset). The checking it reaches is
// then confirmed by another path: the simulator's own check event on a forte blow (its catch
// criterion is the same, its code separate), within 0.2 mm (the W-method's hammer differs from
// the measurement's CVODE one by about 0.05 mm, F8, and the event is dated to a step's end:
// 4 m/s × 1e-5 s = 0.04 mm).
TEST(Regulation, F1_GrandRegulatesToEveryTarget) {
  ActionModel start = shipped("grand");
  const std::vector<std::pair<std::string, double>> off = {
      {"key_dip", 0.3e-3},      {"jack_position", -0.2e-3}, {"lever_height", 0.2e-3},
      {"hammer_blow", -0.3e-3}, {"let_off", -0.2e-3},       {"drop", 0.2e-3},
      {"checking", -0.3e-3}};
  for (const auto& [adjuster, offset] : off) start = with_adjuster(start, adjuster, offset);
  int off_target = 0;
  for (const SettingReading& r : read_settings(start)) off_target += !r.within_tolerance();
  EXPECT_GE(off_target, 5);  // a real start: most settings out of tolerance
  const RegulationResult result = regulate(start);
  std::printf("grand regulated in %d passes, %.2f s, from %d settings off\n", result.passes,
              result.wall_time_s, off_target);
  ASSERT_TRUE(result.converged) << result.message;
  ASSERT_EQ(result.settings.size(), 7u);
  for (const SettingReading& r : result.settings)
    EXPECT_LE(std::abs(r.measured - r.target), r.tolerance) << r.name << " " << r.measured;
  const SimulationResult blow =
      test::run(result.model, "force:const:" + std::to_string(kForteBlowNewtons), 0.1);
  const auto checks = test::events_of(blow, "check");
  ASSERT_FALSE(checks.empty());
  EXPECT_NEAR(checks.front()->hammer_string_gap * 1e3, 16.0, 0.2);
}

// When the slow press shows the repetition lever carrying the hammer (drop screw too high), the
// let-off regulation turns the drop screw out of the way at once, as a technician would, instead
// of first trying the let-off button over its whole range (17 slow presses) and calling the
// target out of reach; the regulation then converges.
TEST(Regulation, LetOffClearsTheDropScrewAsSoonAsTheLeverCarriesTheHammer) {
  ActionModel model = shipped("grand");
  for (const auto& [name, mm] : {std::pair{"lever_height", 0.8}, std::pair{"let_off", 0.5},
                                 std::pair{"drop", -0.3}, std::pair{"checking", -0.5}})
    model = with_adjuster(model, name, mm * 1e-3);
  const RegulationResult result = regulate(model);
  ASSERT_TRUE(result.converged) << result.message;
  const auto let_off = std::find_if(result.steps.begin(), result.steps.end(),
                                    [](const RegulationStep& s) { return s.setting == "let_off"; });
  ASSERT_NE(let_off, result.steps.end());
  EXPECT_NE(let_off->note.find("never lifts the hammer"), std::string::npos) << let_off->note;
  EXPECT_NE(let_off->note.find("then with 'drop'"), std::string::npos) << let_off->note;
  EXPECT_EQ(let_off->note.find("out of reach"), std::string::npos) << let_off->note;
}

// A let-off button turned down past the drop (grand, +0.3 mm: the jack trips 3.1 mm from the
// string, before the repetition lever meets its drop screw) is still read: the lever carries the
// escaped hammer on up to the drop screw, so the hammer never falls back below where the jack
// left it, but the jack, held tipped on its button, stands clear of the knuckle. The reading is
// what the technician sees: let-off farther from the string than the drop. A drop screw turned
// up (−0.3 mm) leaves the hammer held where the jack let it off (no drop: the two readings
// within 0.1 mm), and is read too.
TEST(Regulation, LetOffBeyondTheDropAndADropScrewTooHighAreRead) {
  const ActionModel grand = shipped("grand");
  const ActionModel early = with_adjuster(grand, "let_off", 0.3e-3);
  const double let_off = measure_setting(early, "let_off");
  const double drop = measure_setting(early, "drop");
  EXPECT_GT(let_off, drop) << "let-off " << let_off << " mm, drop " << drop << " mm";
  EXPECT_NEAR(drop, 3.0, 0.05);  // the drop screw was not touched
  const ActionModel high_drop = with_adjuster(grand, "drop", -0.3e-3);
  const double held = measure_setting(high_drop, "drop");
  EXPECT_NEAR(held, measure_setting(high_drop, "let_off"), 0.1);
  EXPECT_LT(held, 3.0 - 1.0);  // far closer to the string than the regulated 3 mm
}

// A capstan screwed to the bottom of its range (−4 mm) with the jack screw 3 mm off: the blow
// reads 51.8 mm from −4 to −1 mm (the whippen rests on its own, clear of the capstan) and its
// target lies near the other end of that flat stretch, at about 0 mm. The search for a change
// of sign goes on to the far end of the adjuster's range; it used to stop 4 mm from the start
// and call the target out of reach.
TEST(Regulation, ATargetAtTheFarEndOfAFlatStretchIsFound) {
  ActionModel model = with_adjuster(shipped("grand"), "hammer_blow", -4e-3);
  model = with_adjuster(model, "jack_position", 3e-3);
  const RegulationResult result = regulate(model);
  ASSERT_TRUE(result.converged) << result.message;
  for (const SettingReading& r : result.settings)
    EXPECT_LE(std::abs(r.measured - r.target), r.tolerance) << r.name;
}

// A backcheck bent 2 mm toward the hammer rubs the hammer's tail on its way up: the slow press
// says so (a typed failure, not a let-off of some 14 mm), and the regulation bends the
// backcheck back to the end of its range first, then sets let-off, drop and, last, checking.
TEST(Regulation, LetOffBendsTheBackcheckBackWhenItStopsTheRisingHammer) {
  const ActionModel close = with_adjuster(shipped("grand"), "checking", 2e-3);
  EXPECT_THROW(measure_setting(close, "let_off"), BackcheckStopsTheRisingHammer);
  EXPECT_NO_THROW(measure_setting(shipped("grand"), "let_off"));
  const RegulationResult result = regulate(close);
  ASSERT_TRUE(result.converged) << result.message;
  const auto let_off = std::find_if(result.steps.begin(), result.steps.end(),
                                    [](const RegulationStep& s) { return s.setting == "let_off"; });
  ASSERT_NE(let_off, result.steps.end());
  EXPECT_NE(let_off->note.find("meets the backcheck on its way up"), std::string::npos)
      << let_off->note;
  EXPECT_NE(let_off->note.find("then with 'checking' at -4 mm"), std::string::npos)
      << let_off->note;
  for (const SettingReading& r : result.settings)
    EXPECT_LE(std::abs(r.measured - r.target), r.tolerance) << r.name;
}

// The forte blow's catch (BackcheckCatch) on a made-up rebound: the hammer leaves the string at
// 3 m/s. A backcheck that runs into the catcher and touches it for 1 ms without slowing it (a
// brush, 4 mm from the string) is not the catch; the contact the hammer runs into is, read where
// the gap closed (linear in the step: exact here, the gaps being linear in t).
TEST(Regulation, ABrushOfTheBackcheckIsNotTheCatch) {
  const double v = 3.0, dt = 1e-4;  // m/s away from the string; s per step
  BackcheckCatch watch(0.0, 0.0, 1e-3);
  double t = 0.0, gap = 0.0;
  auto check_gap = [](double t) {  // m, linear in t: touching from 1.35 to 2.35 ms, and from 6.05
    if (t < 3.5e-3) return std::abs(t - 1.85e-3) - 0.5e-3;
    return 6.05e-3 - t;
  };
  bool caught = false;
  for (int step = 1; step <= 100 && !caught; ++step) {
    t = step * dt;
    gap += (step <= 61 ? v : 0.1 * v) * dt;  // the second contact stops the hammer from 6.1 ms
    // the backcheck closes the first contact, the hammer runs into it the second time
    caught = watch.update(t, gap, check_gap(t), true, [t] { return t < 3.5e-3 ? 1.0 : 0.0; });
    EXPECT_FALSE(caught && t < 6e-3) << "caught by the brush at t = " << t;
  }
  ASSERT_TRUE(caught);
  // the contact closed at t = 6.05 ms, when the hammer was 3 m/s × 6.05 ms = 18.15 mm away
  EXPECT_NEAR(watch.caught_gap(), v * 6.05e-3, 1e-9);
}

// On the shipped upright the whippen, flung off the capstan as a forte key bottoms, carries
// the backcheck against the hammer right after the strike; the checking reading is where the
// backcheck then catches the returning hammer, not that brush.
TEST(Regulation, UprightCheckingIsReadWhereTheBackcheckHoldsTheHammer) {
  const ActionModel upright = shipped("upright");
  const RestState rest = find_rest_state(upright);
  const double checking = measure_setting(upright, "checking", &rest);
  const SimulationResult blow =
      test::run(upright, "force:const:" + std::to_string(kForteBlowNewtons), 0.1, "cvode", 1e-7);
  const auto force = blow.trace.column("hammer_catcher_backcheck_force_n");
  const auto gap = blow.trace.column("hammer_string_gap_mm");
  const auto impacts = test::events_of(blow, "impact");
  ASSERT_FALSE(impacts.empty());
  std::vector<double> touches;  // hammer–string distance (mm) where each contact begins
  for (std::size_t i = 1; i < force.size(); ++i)
    if (blow.trace.rows[i][0] > impacts[0]->t && force[i - 1] <= 0.0 && force[i] > 0.0)
      touches.push_back(gap[i]);
  ASSERT_GE(touches.size(), 2u);
  std::printf("contacts begin at %.1f and %.1f mm; checking reads %.2f mm\n", touches[0],
              touches[1], checking);
  EXPECT_LT(touches[0], 8.0);  // the brush, close to the string
  // the catch: the second contact, within the trace's sampling (1e-4 s at ≤ 4 m/s: 0.4 mm)
  EXPECT_NEAR(checking, touches[1], 0.5);
}

// The bracketing search on settings measured at rest: from seeded random deregulated starts
// (each adjuster off by up to ±2 mm) the grand's key dip and hammer blow converge to their
// targets within tolerance.
TEST(Regulation, RestSettingsConvergeFromRandomDeregulatedStarts) {
  ActionModel base = shipped("grand");
  std::vector<RegulationSetting> rest_settings;
  for (const RegulationSetting& s : base.regulation)
    if (s.name == "key_dip" || s.name == "hammer_blow") rest_settings.push_back(s);
  base.regulation = rest_settings;
  std::mt19937 random(20261121);
  std::uniform_real_distribution<double> offset(-2e-3, 2e-3);
  for (int start = 0; start < 5; ++start) {
    ActionModel model = base;
    for (const RegulationSetting& s : rest_settings)
      model = with_adjuster(model, s.name, offset(random));
    const RegulationResult result = regulate(model);
    EXPECT_TRUE(result.converged) << "start " << start << ": " << result.message;
    for (const SettingReading& r : result.settings)
      EXPECT_LE(std::abs(r.measured - r.target), r.tolerance) << "start " << start << " " << r.name;
  }
}

// Issue 3, must-show 2: from 20 seeded random deregulated starts (all seven adjusters off by up
// to ±2 mm each) the grand regulates, every setting within its tolerance. Four quarters of five
// starts (separate tests, so that ctest can spread them), each run over the cores.
/// Regulates `kStarts` seeded random deregulated starts of the shipped `action` (every adjuster
/// off by up to ±2 mm; the quarter picks the seed), both cores, and expects every one to reach
/// every target.
void expect_random_starts_converge(const std::string& action, int quarter) {
  const ActionModel base = shipped(action);
#ifdef PAT_SANITIZED_BUILD
  constexpr int kStarts = 1;  // the sanitizers look for memory errors, not for convergence
#else
  constexpr int kStarts = 5;
#endif
  std::vector<ActionModel> starts;
  std::mt19937 random(20261121 + quarter);
  std::uniform_real_distribution<double> offset(-2e-3, 2e-3);
  for (int start = 0; start < kStarts; ++start) {
    ActionModel model = base;
    for (const RegulationSetting& s : base.regulation)
      model = with_adjuster(model, s.name, offset(random));
    starts.push_back(model);
  }
  std::vector<RegulationResult> results(kStarts);
  run_parallel(kStarts, [&](std::size_t i) { results[i] = regulate(starts[i]); });
  for (int start = 0; start < kStarts; ++start) {
    const RegulationResult& result = results[start];
    std::printf("%s quarter %d start %d: %s in %d passes, %.2f s\n", action.c_str(), quarter, start,
                result.converged ? "converged" : "NOT converged", result.passes,
                result.wall_time_s);
    EXPECT_TRUE(result.converged) << "start " << start << ": " << result.message;
    for (const SettingReading& r : result.settings)
      EXPECT_LE(std::abs(r.measured - r.target), r.tolerance) << "start " << start << " " << r.name;
  }
}

class GrandRandomStarts : public ::testing::TestWithParam<int> {};
TEST_P(GrandRandomStarts, AllSevenSettingsConverge) {
  expect_random_starts_converge("grand", GetParam());
}
INSTANTIATE_TEST_SUITE_P(Quarters, GrandRandomStarts, ::testing::Values(0, 1, 2, 3));

// The same for the upright: its seven settings (blow, dip, lost motion, let-off, checking,
// bridle, damper lift) from 20 seeded random deregulated starts.
class UprightRandomStarts : public ::testing::TestWithParam<int> {};
TEST_P(UprightRandomStarts, AllSevenSettingsConverge) {
  expect_random_starts_converge("upright", GetParam());
}
INSTANTIATE_TEST_SUITE_P(Quarters, UprightRandomStarts, ::testing::Values(0, 1, 2, 3));

// A target out of reach gives converged = false and a message naming the setting; nothing
// throws. Unknown settings and out-of-range adjusters are InputErrors naming them.
TEST(Regulation, ImpossibleAndUnknownSettingsAreReported) {
  ActionModel model = shipped("grand");
  for (RegulationSetting& s : model.regulation)
    if (s.name == "hammer_blow") s.target = 80.0;  // the hammer cannot rest 80 mm away
  std::vector<RegulationSetting> only;
  for (const RegulationSetting& s : model.regulation)
    if (s.name == "hammer_blow") only.push_back(s);
  model.regulation = only;
  RegulationOptions options;
  options.max_passes = 2;
  const RegulationResult result = regulate(model, options);
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.message.find("hammer_blow"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("out of reach"), std::string::npos) << result.message;

  try {
    measure_setting(shipped("grand"), "bridle");
    FAIL() << "the grand has no bridle setting";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bridle"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("let_off"), std::string::npos);  // lists the valid ones
  }
  EXPECT_THROW(with_adjuster(shipped("grand"), "let_off", 9e-3), InputError);
}

// The paper's live deregulation (7.2): `setting`'s adjuster turned 0.5 mm every 0.5 s (1 mm/s)
// while the key plays at 3 Hz, for `duration_s`.
DeregulationResult deregulate_at_1mm_per_s(const std::string& action, const std::string& setting,
                                           double duration_s) {
  DeregulationOptions options;
  options.setting = setting;
  options.rate_mm_per_s = 1.0;
  options.duration_s = duration_s;
  return deregulate(shipped(action), options);
}

// Live deregulation (fact F7, paper 7.2): screwing the key pilot (capstan) up 0.5 mm every 0.5 s
// while the key plays at 3 Hz shrinks the blow and raises the whippen, until the jack, pressed
// against the repetition lever's window, goes past the window's edge: the run stops there with
// that cause. The upright's key pilot is its lost-motion capstan: once the jack lifts the butt,
// screwing it up shrinks the blow and raises the whippen too.
TEST(Regulation, DeregulatingTheKeyPilotShrinksTheBlowAndRaisesTheWhippen) {
  constexpr double kDuration = 4.0;  // s
  const DeregulationResult grand = deregulate_at_1mm_per_s("grand", "hammer_blow", kDuration);
  ASSERT_GE(grand.samples.size(), 3u);
  // 0.5 mm of capstan takes about 6 mm off the grand's blow; 5 mm is over two such turns
  EXPECT_LT(grand.samples.back().measured, grand.samples.front().measured - 5.0);
  EXPECT_NEAR(grand.samples.back().blow_mm, grand.samples.back().measured, 1e-9);
  // 0.5 degree: a millimetre of capstan turns the whippen by about a degree
  EXPECT_GT(grand.samples.back().whippen_angle_deg, grand.samples.front().whippen_angle_deg + 0.5);
  EXPECT_EQ(grand.status, "stopped");
  EXPECT_LT(grand.stop_t, kDuration);  // stopped by the contact, not by the clock
  const std::string& cause = grand.stop_cause;
  EXPECT_NE(cause.find("unphysical penetration"), std::string::npos) << cause;
  EXPECT_NE(cause.find("jack–repetition lever window"), std::string::npos) << cause;
  EXPECT_NE(cause.find("(jack into lever)"), std::string::npos) << cause;
  // and in a technician's words, for the class watching the demo
  EXPECT_EQ(stop_in_trade_words(cause),
            "the jack jammed in the repetition lever's window (it cannot get back under the "
            "knuckle)");

  const DeregulationResult upright = deregulate_at_1mm_per_s("upright", "lost_motion", 2.5);
  ASSERT_GE(upright.samples.size(), 3u);
  EXPECT_EQ(upright.status, "ok") << upright.stop_cause;
  // 2 mm of capstan: the jack takes up the 0.3 mm of lost motion, then lifts the butt (about
  // 10 mm of blow per mm of capstan: 46.0 → 30.3 mm at 2 mm, the whippen up 1.6 degrees);
  // 10 mm and 1 degree leave room for either
  EXPECT_LT(upright.samples.back().blow_mm, upright.samples.front().blow_mm - 10.0);
  EXPECT_GT(upright.samples.back().whippen_angle_deg,
            upright.samples.front().whippen_angle_deg + 1.0);
}

// A key pilot (capstan) screwed 1.5–2 mm down, within its travel: the whippen no longer holds
// the key's back down, so the key's front rests lower (about 1.5 mm less dip at 1.5 mm) and its
// punching is found all the same. Before, one probe 0.3 rad down carried the key's front past
// the punching's far end and every run failed with "the key never reaches its punching".
TEST(Regulation, AKeyPilotScrewedFarDownLeavesAShallowerDip) {
  const ActionModel grand = shipped("grand");
  const double regulated_dip = measure_setting(grand, "key_dip");
  for (double mm : {-1.5, -2.0}) {
    const ActionModel low = with_adjuster(grand, "hammer_blow", mm * 1e-3);
    const double dip = measure_setting(low, "key_dip");
    EXPECT_LT(dip, regulated_dip - 1.0) << mm << " mm";
    EXPECT_GT(dip, 5.0) << mm << " mm";  // the key still travels: a shallower dip, not none
    const SimulationResult run = test::run(low, "mass:1kg", 0.1);
    EXPECT_FALSE(test::events_of(run, "key_bottom").empty()) << mm << " mm";
  }
}

// The upright's blow adjuster is its hammer rest rail: moving it toward the strings shortens the
// blow without lifting the whippen (it opens lost motion instead).
TEST(Regulation, DeregulatingTheUprightHammerRailShrinksTheBlowAlone) {
  const DeregulationResult upright = deregulate_at_1mm_per_s("upright", "hammer_blow", 2.5);
  ASSERT_GE(upright.samples.size(), 3u);
  // 2 mm of rail at about 2 mm of blow per mm at the head (head radius over rail radius:
  // 46.0 → 42.2 mm)
  EXPECT_LT(upright.samples.back().measured, upright.samples.front().measured - 3.0);
  EXPECT_NEAR(upright.samples.back().whippen_angle_deg, upright.samples.front().whippen_angle_deg,
              0.1);  // 0.1 degree: the rail does not touch the whippen's chain
}

// The deregulation demo's adjuster plot: the screw as the run turned it, a staircase with a
// vertical step at each turn (two points at one time), held to the end of the trace.
// The stop causes a demo can meet, in a technician's words; a cause that is no contact's (a
// cancel) stays as it is.
TEST(Deregulation, StopsAreToldInATechniciansWords) {
  EXPECT_EQ(stop_in_trade_words("unphysical penetration in contact 'hammer tail–backcheck' "
                                "(hammer into key): 9.1 mm, limit 4 mm"),
            "the hammer was driven into the backcheck (hammer tail–backcheck): the action jams "
            "there");
  EXPECT_EQ(stop_in_trade_words("unphysical penetration in contact 'capstan–whippen heel' (key "
                                "into whippen): 3 mm, limit 2 mm"),
            "the key was driven into the whippen (capstan–whippen heel): the action jams there");
  EXPECT_EQ(stop_in_trade_words("unphysical penetration in contact 'hammer head–string' (hammer "
                                "into frame): 6 mm, limit 5 mm"),
            "the hammer blocks against the string (it is driven into it, without let-off)");
  EXPECT_NE(stop_in_trade_words("the simulation diverged: the jack turned 190° from rest")
                .find("working geometry"),
            std::string::npos);
  EXPECT_EQ(stop_in_trade_words("cancelled"), "cancelled");
  EXPECT_EQ(stop_in_trade_words(""), "");
}

TEST(DeregulationPlot, AdjusterStepsAreAStaircase) {
  CsvTable trace;
  trace.columns = {"time_s", "key_angle_deg", "adjuster_mm"};
  for (int i = 0; i <= 12; ++i) {
    const double t = 0.1 * i;  // turned 0.5 mm at 0.5 s and at 1.0 s
    trace.rows.push_back({t, 0.0, t < 0.5 - 1e-9 ? 0.0 : (t < 1.0 - 1e-9 ? 0.5 : 1.0)});
  }
  const AdjusterSteps steps = adjuster_steps(trace);
  const std::vector<double> t{0.0, 0.5, 0.5, 1.0, 1.0, 1.2}, mm{0.0, 0.0, 0.5, 0.5, 1.0, 1.0};
  ASSERT_EQ(steps.t_s.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(steps.t_s[i], t[i], 1e-12) << i;
    EXPECT_EQ(steps.mm[i], mm[i]) << i;
  }
  EXPECT_TRUE(adjuster_steps(CsvTable{}).t_s.empty());  // no trace: nothing to draw
}

// The demo's default adjuster speed moves the setting itself about 2 mm per second (0.1 per
// second for a fraction), whatever the adjuster's ratio to it: measured one second of screw
// turns away (rate × 1 s of adjuster), the setting has moved by that much. The tolerance, 35 %,
// covers the rate's rounding to 0.05 mm/s (up to 17 % at the slowest rate, 0.15 mm/s) and
// the response's curvature between the 0.25 mm probe and the second's turn; where the rate is
// held at its 2 mm/s limit, the setting moves less than asked. A setting that runs out of room
// within the second (the upright's lost motion, 0.3 mm, closes to nothing, and then the blow
// shrinks instead) reads the same after half the turns and after all of them: it must have got
// there no faster than asked.
TEST(Regulation, DemoRateMovesEachSettingAboutTwoMillimetresASecond) {
  for (const char* action : {"grand", "upright"}) {
    const ActionModel model = shipped(action);
    for (const RegulationSetting& setting : model.regulation) {
      const double rate = demo_adjuster_rate(model, setting.name);
      const double wanted =
          setting.unit == "mm" ? kDemoSettingRatePerS_mm : kDemoSettingRatePerS_fraction;
      const double before = measure_setting(model, setting.name);
      const double half = measure_at(model, setting.name, rate * 0.5);
      const double after = measure_at(model, setting.name, rate * 1.0);
      const double moved = std::abs(after - before);
      const bool out_of_room = std::abs(after - half) < 0.05 * wanted;
      std::printf("%s %s: %.2f mm/s moves it %.3f %s in 1 s%s\n", action, setting.name.c_str(),
                  rate, moved, setting.unit.c_str(), out_of_room ? " (out of room)" : "");
      EXPECT_GE(rate, 0.05);
      EXPECT_LE(rate, 2.0);
      if (rate < 2.0 && !out_of_room)
        EXPECT_NEAR(moved, wanted, 0.35 * wanted) << action << " " << setting.name;
      else
        EXPECT_LE(moved, 1.35 * wanted) << action << " " << setting.name;
    }
  }
  // the ratios differ as the adjusters do: the grand's let-off button moves the let-off about 6
  // times its own travel, the capstan the blow about 12 times, the punchings the dip once
  const ActionModel grand = shipped("grand");
  EXPECT_LT(demo_adjuster_rate(grand, "let_off"), 0.5);
  EXPECT_LT(demo_adjuster_rate(grand, "hammer_blow"), 0.25);
  EXPECT_GT(demo_adjuster_rate(grand, "key_dip"), 1.5);
  EXPECT_THROW(demo_adjuster_rate(grand, "bridle"), InputError);  // an upright setting
}

}  // namespace
}  // namespace pat

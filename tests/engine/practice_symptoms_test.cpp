// Practice symptoms by simulation (issue 7, must-show 1): every setting of both actions hidden
// in both directions (at the middle of its neglect range) gives observations that differ
// measurably from the regulated action's; the measured value moves the way the answer says
// (the neglect range's sense); and the symptom list carries the domain table's description
// (domain.md section 3) where the table gives one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "analysis/parallel_runs.h"
#include "model/model_edits.h"
#include "practice/exercise.h"
#include "practice/neglect_ranges.h"
#include "practice/observations.h"
#include "practice/symptoms.h"
#include "regulation/measurements.h"
#include "regulation/technician_tests.h"
#include "test_support.h"

namespace pat {
namespace {

/// Symptom ids that carry the domain table's description of a (setting, direction), any one of
/// which must appear. Directions are of the measured value relative to its target.
const std::map<std::string, std::set<std::string>>& domain_table() {
  static const std::map<std::string, std::set<std::string>> table = {
      // "Let-off too close / none: blocking; blubber or double strike on fast ff"
      {"let_off:less", {"blocking", "escapes_close", "double_strike"}},
      // "Let-off too far: misses at ppp, weak dynamic control, lost power"
      {"let_off:more", {"escapes_far", "lost_power"}},
      // "Drop too little (too high): double striking / bobble; hammer re-touches the string"
      {"drop:less", {"held_close", "double_strike"}},
      // "Drop screw too low: no hammer rise when testing the rep spring; spongy feel"
      {"drop:more", {"falls_far"}},
      // "Jack too far forward: early escape, weak power, misfire"; "too deep: friction, poor
      // repetition" (+ of the measurement is toward the strings: deep)
      {"jack_position:less", {"jack_forward"}},
      {"jack_position:more", {"jack_deep"}},
      // "Rep lever too high / gap too big: lost motion"; "too low / no gap: failure to repeat"
      {"lever_height:more", {"excess_gap"}},
      {"lever_height:less", {"no_gap", "small_gap", "failure_to_repeat"}},
      // "Backcheck too far / too low: hammer not checking"; "too close / high: the tail brushes
      // on the way up, lower hammer speed"
      {"checking:more", {"no_checking", "checks_far"}},
      {"checking:less", {"checks_close", "lost_power"}},
      // "Too little aftertouch (dip too shallow / blow too long)"; "too much aftertouch"
      {"key_dip:less", {"shallow_dip"}},
      {"key_dip:more", {"deep_dip"}},
      {"hammer_blow:more", {"long_blow"}},
      // "Too much lost motion (upright): hammer lags key, weak/bobbling"
      {"lost_motion:more", {"excess_gap"}},
      // "Damper spoon early/late: heavier touch if early; dampers not lifting if far off"
      {"damper_lift:less", {"damper_early"}},
      {"damper_lift:more", {"damper_late", "damper_no_lift"}},
  };
  return table;
}

/// (action:setting:direction) cases where the present model does not show the domain table's
/// symptom, with the reason. They must still differ measurably from the regulated action; the
/// test asserts the domain symptom is still absent or the setting's own measurement still does
/// not move, so that a model fix (branch `geometry`) shows up here and the entry is removed.
/// None at present: the upright's lost motion, the last entries, now opens and closes with its
/// capstan.
const std::map<std::string, std::string>& known_model_limits() {
  static const std::map<std::string, std::string> cases = {};
  return cases;
}

struct Case {
  std::string kind, setting;
  double adjuster_mm = 0.0;
  std::string direction;
};

struct CaseResult {
  std::vector<Observation> seen;
  std::optional<double> regulated_measure, hidden_measure;
};

std::optional<double> try_measure(const ActionModel& model, const std::string& setting) {
  try {
    return measure_setting(model, setting);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

/// (action kind, setting): one test per setting keeps each under the time limit.
class PracticeSymptoms : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(PracticeSymptoms, HiddenSettingShowsItsDomainSymptoms) {
  const auto& [kind, setting] = GetParam();
  const ActionModel regulated = test::shipped(kind);
  std::vector<Case> cases;
  {
    const NeglectRange& r = neglect_range(kind, setting);
    for (double sign : {-1.0, 1.0}) {
      if (r.only_sign != 0 && sign != r.only_sign) continue;  // a model limit: one-sided
      Exercise e;
      e.kind = kind;
      e.faults = {{r.setting, sign * 0.5 * (r.min_mm + r.max_mm)}};
      cases.push_back(
          {kind, r.setting, e.faults[0].adjuster_mm, exercise_answers(e).front().direction});
    }
  }
  std::vector<Observation> reference;
  std::vector<CaseResult> results(cases.size());
  // the regulated action and every case are independent runs: both cores
  run_parallel(cases.size() + 1, [&](std::size_t i) {
    if (i == cases.size()) {
      reference = run_all_tests(regulated);
      return;
    }
    Exercise e;
    e.kind = kind;
    e.faults = {{cases[i].setting, cases[i].adjuster_mm}};
    const ActionModel hidden = hidden_model(regulated, e);
    results[i].seen = run_all_tests(hidden);
    results[i].regulated_measure = try_measure(regulated, cases[i].setting);
    results[i].hidden_measure = try_measure(hidden, cases[i].setting);
  });

  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const std::string key = c.setting + ":" + c.direction;
    const std::vector<Symptom> symptoms = describe_symptoms(results[i].seen, reference);
    std::string listed;
    for (const Symptom& s : symptoms) listed += "\n    " + s.id + ": " + s.text;
    const std::string where = kind + " " + c.setting + " " + std::to_string(c.adjuster_mm) +
                              " mm (" + c.direction + ")" + listed;
    std::cout << "[practice] " << where << "\n";
    // what the trainee reads never names a setting by its identifier
    for (const RegulationSetting& r : regulated.regulation) {
      if (r.name.find('_') == std::string::npos) continue;  // drop, checking, bridle: words
      for (const Symptom& sy : symptoms)
        EXPECT_EQ((sy.id + sy.text + sy.observation).find(r.name), std::string::npos) << where;
      for (const Observation& o : results[i].seen)
        EXPECT_EQ((o.id + o.label).find(r.name), std::string::npos) << o.id;
    }
    EXPECT_TRUE(differ_measurably(results[i].seen, reference)) << where;
    EXPECT_FALSE(symptoms.empty()) << where;
    const auto expected = domain_table().find(key);
    auto has_domain_symptom = [&] {
      for (const Symptom& s : symptoms)
        if (expected != domain_table().end() && expected->second.count(s.id)) return true;
      return false;
    };
    // the setting's own measurement moves the way the answer says, by more than its tolerance
    // (the resolution the regulation works to); unmeasurable is a symptom of its own
    const auto& reg = results[i].regulated_measure;
    const auto& hid = results[i].hidden_measure;
    const double tolerance = regulated.regulation[regulated.setting_index(c.setting)].tolerance;
    const bool moved = !reg || !hid || std::abs(*hid - *reg) > tolerance;
    const auto known = known_model_limits().find(kind + ":" + key);
    if (known != known_model_limits().end()) {
      EXPECT_FALSE(moved && (has_domain_symptom() || expected == domain_table().end()))
          << where << "\n  the model now shows it: remove it from known_model_limits ("
          << known->second << ")";
      continue;
    }
    EXPECT_TRUE(moved) << where << "\n  its measurement did not move beyond " << tolerance;
    if (reg && hid)
      EXPECT_EQ(*hid > *reg ? "more" : "less", c.direction)
          << where << "\n  measured " << *hid << " vs regulated " << *reg;
    if (expected == domain_table().end()) continue;
    EXPECT_TRUE(has_domain_symptom())
        << where << "\n  expected one of the domain table's symptoms for " << key;
  }
}

std::vector<std::pair<std::string, std::string>> every_setting() {
  std::vector<std::pair<std::string, std::string>> all;
  for (const std::string kind : {"grand", "upright"})
    for (const NeglectRange& r : neglect_ranges(kind)) all.emplace_back(kind, r.setting);
  return all;
}

INSTANTIATE_TEST_SUITE_P(EverySetting, PracticeSymptoms, ::testing::ValuesIn(every_setting()),
                         [](const auto& info) {
                           return info.param.first + "_" + info.param.second;
                         });

}  // namespace
}  // namespace pat

namespace pat {
namespace {

// The observations repeat the technician's measurements (measurements.h) where they overlap:
// the same procedure on the same model gives the same number. The tolerance 1e-9 mm is round-off
// (the same steps are taken). The repetition counts are whole strikes over three cycles.
TEST(PracticeObservations, AgreeWithTheTechniciansMeasurements) {
  const ActionModel grand = test::shipped("grand");
  const RestState rest = find_rest_state(grand);
  std::vector<Observation> seen;
  for (PracticeTest t : all_tests()) {
    const std::vector<Observation> part = run_test(grand, rest, t);
    seen.insert(seen.end(), part.begin(), part.end());
  }
  auto value = [&](const std::string& id) {
    const Observation* o = find_observation(seen, id);
    EXPECT_TRUE(o && o->value) << id;
    return o && o->value ? *o->value : NAN;
  };
  const std::vector<std::pair<std::string, std::string>> same = {
      {"rest.key_travel_mm", "key_dip"},
      {"rest.hammer_distance_mm", "hammer_blow"},
      {"rest.escapement_gap_mm", "lever_height"},
      {"rest.jack_edge_mm", "jack_position"},
      {"slow_press.escapement_distance_mm", "let_off"},
      {"slow_press.held_distance_mm", "drop"},
      {"forte_blow.caught_distance_mm", "checking"},
  };
  for (const auto& [id, setting] : same)
    EXPECT_NEAR(value(id), measure_setting(grand, setting, &rest), 1e-9) << id;
  EXPECT_GT(value("forte_blow.impact_speed_mps"), 0.0);
  for (double hz : kRepetitionFrequencies) {
    std::ostringstream id;
    id << "repetition." << hz << "hz_strikes_per_cycle";
    const double per_cycle = value(id.str());
    EXPECT_NEAR(per_cycle * 3.0, std::round(per_cycle * 3.0), 1e-12) << id.str();
    EXPECT_GE(per_cycle, 0.0);
  }
  // the regulated action has no symptom compared with itself
  EXPECT_TRUE(describe_symptoms(seen, seen).empty());
  EXPECT_FALSE(differ_measurably(seen, seen));
}

// The window plays each test while its readings are computed (shown_test): what the
// trainee watches must be the test that was read. The slow press and the forte blow played with
// the window's W-method give the readings of the technician's own CVODE runs: 0.05 mm is the
// regulation tolerance (the W-method's hammer wanders by a few hundredths of a millimetre, F8),
// 2 % of the strike speed the W-method's error on a blow (F8 aims at 0.5 % of the range).
TEST(PracticeObservations, TheInputShownForEachTestIsTheTestThatWasRead) {
  EXPECT_EQ(shown_test(PracticeTest::Rest).input, "");
  EXPECT_EQ(shown_test(PracticeTest::SlowPress).input, "motion:press:1");
  EXPECT_EQ(shown_test(PracticeTest::ForteBlow).input, "force:const:40");
  EXPECT_EQ(shown_test(PracticeTest::Repetition).input, "motion:sine:12:full");
  EXPECT_DOUBLE_EQ(shown_test(PracticeTest::Repetition).duration_s, 4.0 / 12.0);  // four cycles
  for (const std::string action : {"grand", "upright"}) {
    SCOPED_TRACE(action);
    const ActionModel model = test::shipped(action);
    const RestState rest = find_rest_state(model);
    std::vector<Observation> seen = run_test(model, rest, PracticeTest::SlowPress);
    const std::vector<Observation> blow = run_test(model, rest, PracticeTest::ForteBlow);
    seen.insert(seen.end(), blow.begin(), blow.end());

    const ShownTest shown_press = shown_test(PracticeTest::SlowPress);
    const SimulationResult press = test::run(model, shown_press.input, shown_press.duration_s);
    ASSERT_EQ(press.status, "ok") << press.stop_cause;
    // let-off is the closest approach while the jack carries the hammer: up to the escapement
    // (the upright's hammer, thrown free at 0.2 m/s, flies on 1 mm nearer)
    const auto escapes = test::events_of(press, "escapement");
    ASSERT_FALSE(escapes.empty());
    const std::vector<double> t_s = press.trace.column("time_s");
    const std::vector<double> gap_mm = press.trace.column("hammer_string_gap_mm");
    double closest_mm = gap_mm.front();
    for (std::size_t i = 0; i < t_s.size() && t_s[i] <= escapes[0]->t; ++i)
      closest_mm = std::min(closest_mm, gap_mm[i]);
    EXPECT_NEAR(closest_mm, *find_observation(seen, "slow_press.escapement_distance_mm")->value,
                0.05);
    if (action == "grand")
      EXPECT_NEAR(gap_mm.back(), *find_observation(seen, "slow_press.held_distance_mm")->value,
                  0.05);

    const ShownTest shown_blow = shown_test(PracticeTest::ForteBlow);
    const SimulationResult forte = test::run(model, shown_blow.input, shown_blow.duration_s);
    ASSERT_EQ(forte.status, "ok") << forte.stop_cause;
    const auto impacts = test::events_of(forte, "impact");
    ASSERT_EQ(impacts.size(), 1u);
    const double read_mps = *find_observation(seen, "forte_blow.impact_speed_mps")->value;
    EXPECT_NEAR(impacts[0]->hammer_velocity, read_mps, 0.02 * read_mps);
  }
}

// A jack that never escapes in a slow press is seen for what it is: the escapement cannot be
// read, but where the hammer stays with the key held down can, and the symptoms name blocking
// only when that is at the string. The punching 1 mm up (a shallow key dip): the key bottoms
// before the jack toe reaches its button, and the hammer is held off the string, not jammed.
TEST(PracticeObservations, AJackThatNeverEscapesIsBlockingOnlyAtTheString) {
  const ActionModel regulated = test::shipped("grand");
  const ActionModel hidden = with_adjuster(regulated, "key_dip", 1.0e-3);
  const std::vector<Observation> seen =
      run_test(hidden, find_rest_state(hidden), PracticeTest::SlowPress);
  const std::vector<Observation> reference =
      run_test(regulated, find_rest_state(regulated), PracticeTest::SlowPress);
  const Observation* escapement = find_observation(seen, "slow_press.escapement_distance_mm");
  ASSERT_TRUE(escapement);
  EXPECT_FALSE(escapement->value.has_value());
  EXPECT_NE(escapement->missing_reason.find("never escapes"), std::string::npos);
  const Observation* held = find_observation(seen, "slow_press.held_distance_mm");
  ASSERT_TRUE(held && held->value);
  EXPECT_GT(*held->value, 1.0);  // mm: well off the string
  EXPECT_LT(*held->value, 4.0);
  std::set<std::string> ids;
  std::string text;
  for (const Symptom& s : describe_symptoms(seen, reference)) {
    ids.insert(s.id);
    text += s.text;
  }
  EXPECT_TRUE(ids.count("no_escapement")) << text;
  EXPECT_FALSE(ids.count("blocking")) << text;
  // where the hammer stays is said with the escapement, not as the drop's "held close"
  EXPECT_FALSE(ids.count("held_close")) << text;
  std::ostringstream held_mm;
  held_mm << std::fixed << std::setprecision(2) << *held->value << " mm from the string";
  EXPECT_NE(text.find(held_mm.str()), std::string::npos) << text;
}

// Repetition counts against a regulated action that itself strikes more than once a cycle (the
// grand at 4 and 8 Hz): more strikes are still double strikes, none a failure to repeat, but
// fewer extra strikes are no symptom. Against one strike a cycle every change is one.
TEST(PracticeSymptoms, RepetitionCountsAreSymptomsAgainstTheRegulatedCount) {
  auto count = [](double per_cycle) {
    return std::vector<Observation>{{"repetition.8hz_strikes_per_cycle",
                                     "strikes per key cycle at 8 Hz", "per cycle", per_cycle, ""}};
  };
  auto ids = [&](double hidden, double regulated) {
    std::set<std::string> out;
    for (const Symptom& s : describe_symptoms(count(hidden), count(regulated))) out.insert(s.id);
    return out;
  };
  EXPECT_EQ(ids(0.0, 2.0), std::set<std::string>{"failure_to_repeat"});
  EXPECT_EQ(ids(3.0, 2.0), std::set<std::string>{"double_strike"});
  EXPECT_TRUE(ids(1.0, 2.0).empty());
  EXPECT_TRUE(ids(1.33, 2.0).empty());
  EXPECT_EQ(ids(2.0, 1.0), std::set<std::string>{"double_strike"});
  EXPECT_EQ(ids(0.33, 1.0), std::set<std::string>{"failure_to_repeat"});
}

// The damper's start is a fraction of the hammer's travel; its symptom reads it as the
// regulation panel does, a percentage (it said "(0.36; regulated action: 0.50)").
TEST(PracticeSymptoms, DamperStartReadsAsAPercentageOfTheHammersTravel) {
  auto start = [](double fraction) {
    return std::vector<Observation>{
        {"slow_press.damper_start_fraction", "damper starts to lift", "fraction", fraction, ""}};
  };
  const std::vector<Symptom> symptoms = describe_symptoms(start(0.36), start(0.5));
  ASSERT_EQ(symptoms.size(), 1u);
  EXPECT_EQ(symptoms[0].id, "damper_early");
  EXPECT_NE(symptoms[0].text.find("(36 % of the hammer's travel; regulated action: 50 %)"),
            std::string::npos)
      << symptoms[0].text;
}

// A regulated action strikes once in a forte blow with the key held: the backcheck holds the
// hammer (the upright struck twice before issue 7 was mended).
TEST(PracticeObservations, RegulatedForteBlowStrikesOnce) {
  for (const char* name : {"grand", "upright"}) {
    const ActionModel model = test::shipped(name);
    const RestState rest = find_rest_state(model);
    const std::vector<Observation> seen = run_test(model, rest, PracticeTest::ForteBlow);
    const Observation* strikes = find_observation(seen, "forte_blow.strikes");
    ASSERT_TRUE(strikes && strikes->value) << name;
    EXPECT_EQ(*strikes->value, 1.0) << name;
  }
}

}  // namespace
}  // namespace pat

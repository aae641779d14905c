// Simulation events (sim/simulator.h): each is reported once, in time order, among the step's new
// events; the check is a catch (the backcheck takes a fifth of the returning hammer's speed), not
// a brush; a catch still being confirmed when the run ends is reported; each stroke escapes once;
// a run that blows up says what to suspect.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "model/model_edits.h"
#include "sim/simulator.h"
#include "test_support.h"

namespace pat {
namespace {

std::vector<SimEvent> stepped_events(const ActionModel& model, const std::string& spec,
                                     double duration, std::vector<SimEvent>& final_events) {
  const RestState rest = find_rest_state(model);
  std::shared_ptr<const KeyInput> input = parse_input_spec(spec, input_context(model, rest));
  SimulationOptions options;
  options.duration_s = duration;
  Simulator sim(std::make_shared<const ActionModel>(model), input, options, &rest);
  std::vector<SimEvent> seen;
  while (sim.time() < duration - 1e-12 && sim.step(duration))
    for (auto e = sim.events().end() - sim.new_event_count(); e != sim.events().end(); ++e)
      seen.push_back(*e);
  sim.finish_events();
  for (auto e = sim.events().end() - sim.new_event_count(); e != sim.events().end(); ++e)
    seen.push_back(*e);
  final_events = sim.events();
  return seen;
}

// On the grand's 20 N blow the escapement after the catch comes while the catch is being
// confirmed: the new events of each step must still add up to the run's events, each once.
TEST(Events, EveryEventIsReportedOnceInTimeOrderAmongTheStepsNewEvents) {
  for (const char* action : {"grand", "upright"}) {
    std::vector<SimEvent> all;
    const std::vector<SimEvent> seen =
        stepped_events(test::shipped(action), "force:const:20", 0.4, all);
    ASSERT_EQ(seen.size(), all.size()) << action;
    for (std::size_t i = 0; i < all.size(); ++i) {
      EXPECT_EQ(seen[i].type, all[i].type) << action << " event " << i;
      EXPECT_EQ(seen[i].t, all[i].t) << action << " event " << i;
      if (i > 0) EXPECT_LE(all[i - 1].t, all[i].t) << action << " event " << i;
    }
    EXPECT_TRUE(std::any_of(all.begin(), all.end(), [](const SimEvent& e) {
      return e.type == "check";
    })) << action;
  }
}

// An event's time is reported to the nanosecond: on w2's fixed 1e-5 s step it is a whole
// number of steps, written as such ("0.02863", not the running sum's 0.028629999999999003).
TEST(Events, TimesAreReportedAsWholeStepsToTheNanosecond) {
  const SimulationResult run = test::run(test::shipped("grand"), "force:const:20", 0.1);
  ASSERT_GE(run.events.size(), 3u);
  for (const SimEvent& e : run.events) {
    const double steps = e.t / 1e-5;
    EXPECT_EQ(e.t, std::round(steps) / 1e5) << e.type << " at " << e.t;
    // the shortest decimal that reads back as the time has at most 5 decimals
    char text[32];
    std::snprintf(text, sizeof(text), "%.5f", e.t);
    EXPECT_EQ(std::strtod(text, nullptr), e.t) << e.type;
  }
  EXPECT_EQ(run.end_time, 0.1);
}

// The upright's whippen, flung up as the key bottoms, brushes the backcheck against the
// rebounding hammer 2 mm from the string; the catch comes later, near the 16 mm of checking.
TEST(Events, TheUprightsCheckIsTheCatchNotTheBrushAfterTheStrike) {
  const SimulationResult r = test::run(test::shipped("upright"), "force:const:20", 0.4);
  const auto check = std::find_if(r.events.begin(), r.events.end(),
                                  [](const SimEvent& e) { return e.type == "check"; });
  ASSERT_NE(check, r.events.end());
  // the regulated checking distance is 16 mm; the brush was at 2.2 mm
  EXPECT_GT(check->hammer_string_gap, 10e-3);
  EXPECT_LT(check->hammer_string_gap, 20e-3);
}

// A run that ends with the catching contact closed but not yet confirmed reports the catch.
TEST(Events, ACatchStillBeingConfirmedWhenTheRunEndsIsReported) {
  const ActionModel grand = test::shipped("grand");
  const SimulationResult full = test::run(grand, "force:const:20", 0.1);
  const auto check = std::find_if(full.events.begin(), full.events.end(),
                                  [](const SimEvent& e) { return e.type == "check"; });
  ASSERT_NE(check, full.events.end());
  // end the run two steps after the contact closed (the confirmation takes longer)
  const SimulationResult cut = test::run(grand, "force:const:20", check->t + 2e-5);
  const auto cut_check = std::find_if(cut.events.begin(), cut.events.end(),
                                      [](const SimEvent& e) { return e.type == "check"; });
  ASSERT_NE(cut_check, cut.events.end());
  EXPECT_EQ(cut_check->t, check->t);
}

// One escapement per stroke: a blow held down, soft to forte, escapes once (the checked hammer's
// knuckle touching and leaving the side of the tripped jack used to count again, two or three
// times a blow, and the jack's bounce as it springs back under the butt once more); a double
// blow escapes twice, a repeated key once a cycle.
TEST(Events, EachStrokeEscapesOnce) {
  auto count = [](const SimulationResult& r, const std::string& type) {
    return std::count_if(r.events.begin(), r.events.end(),
                         [&](const SimEvent& e) { return e.type == type; });
  };
  for (const char* action : {"grand", "upright"}) {
    const ActionModel model = test::shipped(action);
    for (const char* blow : {"force:pulse:5:60", "force:pulse:20:60", "force:pulse:40:60"})
      EXPECT_EQ(count(test::run(model, blow, 0.3), "escapement"), 1) << action << " " << blow;
    EXPECT_EQ(count(test::run(model, "force:double:20:40:60", 0.4), "escapement"), 2) << action;
  }
  // 8 Hz over one second, full stroke: eight strokes (the grand strikes twice in some of them)
  EXPECT_EQ(count(test::run(test::shipped("grand"), "motion:sine:8:full", 1.0), "escapement"), 8);
}

// A full-stroke key motion takes the key exactly to its punching at each trough: every
// integrator reports key_bottom there, once a stroke (the W-method had reported it and the
// adaptive ones had not, as rounding put the key ±1e-16 m into the felt or short of it).
TEST(Events, AFullStrokeMotionBottomsTheKeyInEveryIntegrator) {
  const ActionModel grand = test::shipped("grand");
  for (const char* integrator : {"w2", "rodas", "cvode"}) {
    const SimulationResult r = test::run(grand, "motion:sine:8:full", 0.25, integrator, 1e-6);
    ASSERT_EQ(r.status, "ok") << integrator << ": " << r.stop_cause;
    const auto bottoms = test::events_of(r, "key_bottom");
    ASSERT_EQ(bottoms.size(), 2u) << integrator;
    // the troughs of an 8 Hz sine from rest: 62.5 and 187.5 ms; the key is within the
    // micrometre of its punching from about 0.4 ms before
    EXPECT_NEAR(bottoms[0]->t, 0.0625, 1e-3) << integrator;
    EXPECT_NEAR(bottoms[1]->t, 0.1875, 1e-3) << integrator;
  }
}

// The events of one blow do not depend on the integrator: the W-method at its 1e-5 s step, and
// CVODE at a tight tolerance (1e-8), against RODAS at 1e-8 (within 5e-5 % of the hammer's range
// of a 1e-10 reference), report the impact, escapement and check at the same times and the
// impact at the same speed: the detection does not depend on how an integrator steps. Tolerances:
// events are dated at the end of the step that crosses them, so the W-method's times may be up to
// one 10 µs step late, and its trajectory error at that step (bench: 0.3–0.8 % of the hammer's
// range) moves the upright's events 16 µs earlier: 25 µs; its impact speed is within 0.04 % (0.2 %
// allowed). CVODE's steps near a contact are below 1 µs: measured within 0.6 µs and 3e-5 of the
// speed (2 µs and 1e-4 allowed).
TEST(Events, TheIntegratorsAgreeOnTheTimeAndSpeedOfEachEvent) {
  struct Case {
    const char* integrator;
    double time_tolerance_s, relative_speed_tolerance;
  };
  for (const std::string action : {"grand", "upright"}) {
    const ActionModel model = test::shipped(action);
    const SimulationResult reference = test::run(model, "force:pulse:20:200", 0.1, "rodas", 1e-8);
    ASSERT_EQ(reference.status, "ok") << action << ": " << reference.stop_cause;
    for (const Case c : {Case{"w2", 25e-6, 2e-3}, Case{"cvode", 2e-6, 1e-4}}) {
      const SimulationResult r = test::run(model, "force:pulse:20:200", 0.1, c.integrator, 1e-8);
      ASSERT_EQ(r.status, "ok") << action << " " << c.integrator << ": " << r.stop_cause;
      for (const char* type : {"impact", "escapement", "check"}) {
        const auto expected = test::events_of(reference, type);
        const auto got = test::events_of(r, type);
        ASSERT_FALSE(expected.empty()) << action << " " << type;
        ASSERT_EQ(got.size(), expected.size()) << action << " " << c.integrator << " " << type;
        for (std::size_t i = 0; i < got.size(); ++i) {
          EXPECT_NEAR(got[i]->t, expected[i]->t, c.time_tolerance_s)
              << action << " " << c.integrator << " " << type << " " << i;
          EXPECT_NEAR(got[i]->hammer_velocity, expected[i]->hammer_velocity,
                      c.relative_speed_tolerance * std::abs(expected[i]->hammer_velocity))
              << action << " " << c.integrator << " " << type << " " << i;
        }
      }
    }
  }
}

// A 20 N blow with a 0.2 ms step throws the grand's jack 43° and the whippen round its pivot.
// With every setting regulated the stop says the step may be too long; with a setting turned it
// names both suspects (it had blamed a setting far off on the regulated action).
TEST(Stops, ADivergedRunNamesTheStepWhenEverySettingIsRegulated) {
  auto stop_cause = [](const ActionModel& model) {
    const RestState rest = find_rest_state(model);
    const auto input = parse_input_spec("force:pulse:20:30", input_context(model, rest));
    SimulationOptions options;
    options.duration_s = 0.15;
    options.integrator_options.fixed_step_s = 2e-4;
    const SimulationResult r = simulate(model, input.get(), options, &rest);
    EXPECT_EQ(r.status, "stopped");
    return r.stop_cause;
  };
  const ActionModel grand = test::shipped("grand");
  const std::string regulated = stop_cause(grand);
  EXPECT_NE(regulated.find("every setting is regulated, so a shorter step may help"),
            std::string::npos)
      << regulated;
  const std::string turned = stop_cause(with_adjuster(grand, "let_off", 1e-3));
  EXPECT_NE(turned.find("look for a setting far off, or try a shorter step"), std::string::npos)
      << turned;
}

}  // namespace
}  // namespace pat

#include "practice/observations.h"

#include <cmath>
#include <iterator>
#include <memory>
#include <sstream>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "regulation/measurements.h"
#include "regulation/technician_tests.h"
#include "sim/key_travel.h"
#include "sim/simulator.h"

namespace pat {
namespace {

Observation number(const std::string& id, const std::string& label, const std::string& unit,
                   double value) {
  return {id, label, unit, value, {}};
}

Observation missing(const std::string& id, const std::string& label, const std::string& unit,
                    const std::string& reason) {
  return {id, label, unit, std::nullopt, reason};
}

/// The contact whose first touch marks the damper lift (the damper_lift adjuster's contact).
int damper_contact(const ActionModel& model) {
  const int index = model.adjuster_index("damper_lift");
  if (index < 0) return -1;
  for (const AdjusterEffect& e : model.adjusters[index].effects)
    if (e.target == AdjusterEffect::Target::ContactA ||
        e.target == AdjusterEffect::Target::ContactB)
      return e.index;
  return -1;
}

std::vector<Observation> rest_geometry(const ActionModel& model, const RestState& rest) {
  std::vector<Observation> out;
  out.push_back(number("rest.key_travel_mm", "key travel to the front-rail punching", "mm",
                       key_front_travel(model, rest, key_full_dip_angle(model, rest)) * 1e3));
  out.push_back(number("rest.hammer_distance_mm", "hammer–string distance at rest", "mm",
                       rest.hammer_string_gap * 1e3));
  const bool grand = model.kind == "grand";
  out.push_back(number("rest.escapement_gap_mm",
                       grand ? "gap between knuckle and jack top at rest"
                             : "gap between jack and hammer butt at rest",
                       "mm", contact_gap(model, model.landmarks.escapement_contact, rest.q) * 1e3));
  // rest measurements of the procedure (no simulation); their identifiers stay neutral
  const std::string edge = "jack_position", strap = "bridle";
  if (model.setting_index(edge) >= 0)
    out.push_back(number("rest.jack_edge_mm",
                         "jack top's back edge beyond the knuckle core (+ toward the strings)",
                         "mm", measure_setting(model, edge, &rest)));
  if (model.setting_index(strap) >= 0) {
    try {
      out.push_back(number("rest.strap_slack_mm", "bridle strap slack at rest", "mm",
                           measure_setting(model, strap, &rest)));
    } catch (const std::runtime_error& e) {
      out.push_back(missing("rest.strap_slack_mm", "bridle strap slack at rest", "mm", e.what()));
    }
  }
  return out;
}

/// What a technician sees when the slow press fails, without the engine's guesses at the cause
/// (its messages suggest which screw to look at, which would give the answer away).
std::string seen_in_slow_press(const std::string& engine_message) {
  if (engine_message.find("never escapes") != std::string::npos)
    return "in a slow press the jack never escapes before the key bottoms";
  if (engine_message.find("never lifts") != std::string::npos)
    return "in a slow press the jack never lifts the hammer";
  if (engine_message.find("damper never lifts") != std::string::npos)
    return "in a slow press the damper never lifts";
  if (engine_message.find("already rests") != std::string::npos)
    return "the damper already rests on its lifter at rest";
  return engine_message;
}

std::vector<Observation> slow_press_test(const ActionModel& model, const RestState& rest) {
  const std::string escape_id = "slow_press.escapement_distance_mm",
                    escape_label = "hammer–string distance when the jack escapes (slow press)";
  const std::string fall_id = "slow_press.held_distance_mm",
                    fall_label =
                        "hammer–string distance with the key held down after the "
                        "escapement (slow press)";
  const std::string damper_id = "slow_press.damper_start_fraction",
                    damper_label = "hammer travel fraction when the damper starts to lift";
  const int damper = damper_contact(model);
  std::vector<Observation> out;
  try {
    SlowPressReading press;
    std::string damper_failure;
    try {
      press = slow_press(model, rest, damper);
    } catch (const std::runtime_error& e) {
      // the damper may fail on its own: the escapement is still read without it
      if (damper < 0 || std::string(e.what()).find("damper") == std::string::npos) throw;
      damper_failure = seen_in_slow_press(e.what());
      press = slow_press(model, rest, -1);
    }
    out.push_back(number(escape_id, escape_label, "mm", press.let_off_gap * 1e3));
    out.push_back(number(fall_id, fall_label, "mm", press.drop_gap * 1e3));
    if (damper >= 0) {
      if (damper_failure.empty())
        out.push_back(number(damper_id, damper_label, "fraction", press.damper_lift_fraction));
      else
        out.push_back(missing(damper_id, damper_label, "fraction", damper_failure));
    }
  } catch (const JackNeverEscapes& e) {
    // no escapement to read, but where the hammer stays with the key held down is plain to see
    const std::string seen = seen_in_slow_press(e.what());
    out.push_back(missing(escape_id, escape_label, "mm", seen));
    out.push_back(number(fall_id, "hammer–string distance with the key held down (slow press)",
                         "mm", e.held_gap() * 1e3));
    if (damper >= 0)
      out.push_back(std::isfinite(e.damper_lift_fraction())
                        ? number(damper_id, damper_label, "fraction", e.damper_lift_fraction())
                        : missing(damper_id, damper_label, "fraction", seen));
  } catch (const std::runtime_error& e) {
    const std::string seen = seen_in_slow_press(e.what());
    out.push_back(missing(escape_id, escape_label, "mm", seen));
    out.push_back(missing(fall_id, fall_label, "mm", seen));
    if (damper >= 0) out.push_back(missing(damper_id, damper_label, "fraction", seen));
  }
  return out;
}

std::vector<Observation> forte_blow_test(const ActionModel& model, const RestState& rest,
                                         ProgressReporter* progress) {
  // the technician's forte blow (technician_tests.h): the same steps read the same catch
  const SimulationOptions options = forte_blow_options();
  std::shared_ptr<const KeyInput> input =
      parse_input_spec(forte_blow_spec(), input_context(model, rest));
  Simulator sim(borrow(model), input, options, &rest);
  int strikes = 0;
  double impact_velocity = 0.0, caught_gap = NAN;
  SimulatedBackcheckCatch catch_watch(model, sim);
  std::string stop;
  while (sim.time() < kForteHoldSeconds) {
    if (!sim.step(kForteHoldSeconds)) {
      stop = "the run stopped at t = " + std::to_string(sim.time()) + " s: " + sim.stop_cause();
      break;
    }
    for (auto e = sim.events().end() - sim.new_event_count(); e != sim.events().end(); ++e)
      if (e->type == "impact") {
        if (strikes == 0) impact_velocity = e->hammer_velocity;
        ++strikes;
      }
    if (std::isnan(caught_gap) && catch_watch.update(sim, strikes > 0))
      caught_gap = catch_watch.caught_gap();
    if (progress) {
      progress->partial(sim.time() / kForteHoldSeconds, "forte blow");
      progress->throw_if_cancelled();
    }
  }
  std::vector<Observation> out;
  const std::string never_struck = "the hammer never reached the string";
  if (strikes > 0)
    out.push_back(number("forte_blow.impact_speed_mps", "hammer speed at the string (forte)", "m/s",
                         impact_velocity));
  else
    out.push_back(missing("forte_blow.impact_speed_mps", "hammer speed at the string (forte)",
                          "m/s", stop.empty() ? never_struck : stop));
  out.push_back(number("forte_blow.strikes", "strikes of one forte blow, key held", "", strikes));
  const std::string caught_label = "hammer–string distance where the backcheck catches";
  if (!std::isnan(caught_gap))
    out.push_back(number("forte_blow.caught_distance_mm", caught_label, "mm", caught_gap * 1e3));
  else
    out.push_back(missing("forte_blow.caught_distance_mm", caught_label, "mm",
                          !stop.empty()  ? stop
                          : strikes == 0 ? never_struck
                                         : "the backcheck never catches the hammer"));
  const std::string end_label = "hammer–string distance 0.3 s after a forte blow, key held";
  if (stop.empty())
    out.push_back(number("forte_blow.end_distance_mm", end_label, "mm",
                         sim.hammer_string_gap(sim.q()) * 1e3));
  else
    out.push_back(missing("forte_blow.end_distance_mm", end_label, "mm", stop));
  return out;
}

/// Cycles of the repetition test and how many of them are counted (the first starts at rest).
constexpr int kRepetitionCycles = 4;
constexpr int kCountedCycles = 3;

std::string repetition_id(double hz) {
  std::ostringstream id;
  id << "repetition." << hz << "hz_strikes_per_cycle";
  return id.str();
}

constexpr double kForteBlowShownSeconds = 0.05;

std::string repetition_spec(double hz) {
  return "motion:sine:" + format_number(hz, 12) + ":full";
}

Observation repetition_at(const ActionModel& model, const RestState& rest, double hz) {
  std::ostringstream label;
  label << "strikes per key cycle, repeated notes at " << hz << " Hz";
  const std::unique_ptr<KeyInput> input =
      parse_input_spec(repetition_spec(hz), input_context(model, rest));
  SimulationOptions options;
  options.sample_interval_s = 0.0;
  options.duration_s = kRepetitionCycles / hz;
  const SimulationResult run = simulate(model, input.get(), options, &rest);
  if (run.status != "ok")
    return missing(repetition_id(hz), label.str(), "per cycle",
                   "the run stopped: " + run.stop_cause);
  const double counted_from = (kRepetitionCycles - kCountedCycles) / hz;
  int strikes = 0;
  for (const SimEvent& e : run.events)
    if (e.type == "impact" && e.t >= counted_from) ++strikes;
  return number(repetition_id(hz), label.str(), "per cycle",
                static_cast<double>(strikes) / kCountedCycles);
}

}  // namespace

std::string test_name(PracticeTest test) {
  switch (test) {
    case PracticeTest::Rest:
      return "rest";
    case PracticeTest::SlowPress:
      return "slow_press";
    case PracticeTest::ForteBlow:
      return "forte_blow";
    case PracticeTest::Repetition:
      return "repetition";
  }
  return "rest";
}

PracticeTest parse_test(const std::string& name) {
  for (PracticeTest t : all_tests())
    if (test_name(t) == name) return t;
  throw InputError("unknown test '" + name +
                   "' (expected rest, slow_press, forte_blow or repetition)");
}

ShownTest shown_test(PracticeTest test) {
  switch (test) {
    case PracticeTest::Rest:
      return {};
    case PracticeTest::SlowPress:
      return {slow_press_spec(), kSlowPressSeconds + kSlowPressHoldSeconds};
    case PracticeTest::ForteBlow:
      // what there is to see: the strike (12-20 ms) and the backcheck's catch (25-35 ms on both
      // actions); the hold after it is still
      return {forte_blow_spec(), kForteBlowShownSeconds};
    case PracticeTest::Repetition: {
      const double hz = std::end(kRepetitionFrequencies)[-1];
      return {repetition_spec(hz), kRepetitionCycles / hz};
    }
  }
  return {};
}

std::vector<PracticeTest> all_tests() {
  return {PracticeTest::Rest, PracticeTest::SlowPress, PracticeTest::ForteBlow,
          PracticeTest::Repetition};
}

namespace {

std::vector<Observation> run_test_unguarded(const ActionModel& model, const RestState& rest,
                                            PracticeTest test, ProgressReporter* progress) {
  switch (test) {
    case PracticeTest::Rest:
      return rest_geometry(model, rest);
    case PracticeTest::SlowPress:
      return slow_press_test(model, rest);
    case PracticeTest::ForteBlow:
      return forte_blow_test(model, rest, progress);
    case PracticeTest::Repetition: {
      std::vector<Observation> out;
      for (double hz : kRepetitionFrequencies) {
        out.push_back(repetition_at(model, rest, hz));
        if (progress) {
          progress->partial(static_cast<double>(out.size()) / std::size(kRepetitionFrequencies),
                            "repetition");
          progress->throw_if_cancelled();
        }
      }
      return out;
    }
  }
  return {};
}

}  // namespace

std::string test_label(PracticeTest test) {
  switch (test) {
    case PracticeTest::Rest:
      return "rest geometry";
    case PracticeTest::SlowPress:
      return "slow key press";
    case PracticeTest::ForteBlow:
      return "forte blow";
    case PracticeTest::Repetition:
      return "repeated notes";  // as the form's button says
  }
  return "test";
}

std::vector<Observation> run_test(const ActionModel& model, const RestState& rest,
                                  PracticeTest test, ProgressReporter* progress) {
  try {
    return run_test_unguarded(model, rest, test, progress);
  } catch (const Cancelled&) {
    throw;
  } catch (const std::runtime_error& e) {
    // the action is too far off for the test itself (e.g. the key never reaches its
    // punching): that is what the technician observes
    return {missing(test_name(test) + ".done", test_label(test), "", e.what())};
  }
}

std::vector<Observation> run_all_tests(const ActionModel& model, ProgressReporter* progress) {
  const RestState rest = find_rest_state(model);
  const std::vector<PracticeTest> tests = all_tests();
  std::vector<std::vector<Observation>> parts(tests.size());
  run_parallel(
      tests.size(), [&](std::size_t i) { parts[i] = run_test(model, rest, tests[i]); }, progress);
  std::vector<Observation> all;
  for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

const Observation* find_observation(const std::vector<Observation>& list, const std::string& id) {
  for (const Observation& o : list)
    if (o.id == id) return &o;
  return nullptr;
}

}  // namespace pat

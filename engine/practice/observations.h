// What a trainee may observe on the hidden action (issue 7): the technician's own tests, run by
// simulation on the model (never looked up). Each test gives a few numbers; a number that
// cannot be read (the jack never escapes, the backcheck never catches) is reported as missing
// with the reason, which is itself an observation.
//
//   rest        key travel to the front-rail punching (mm), hammer–string distance (mm), the
//               escapement gap at rest (grand: knuckle–jack top, upright: jack–butt; mm), grand:
//               jack edge vs knuckle core (mm), upright: bridle strap slack (mm) — what a
//               technician sees by eye or with a dip block and a ruler;
//   slow_press  the key pressed slowly to the bottom and held (1 s + 0.4 s): hammer–string
//               distance at escapement and after the hammer falls onto the repetition lever
//               (grand), damper start as a fraction of the hammer travel (upright);
//   forte_blow  40 N held at the key front for 0.3 s: impact speed (m/s), number of strikes,
//               hammer–string distance where the backcheck catches, distance at the end;
//   repetition  the key moved through its full dip sinusoidally at 4, 8 and 12 Hz for four
//               cycles: strikes per cycle over the last three (1 = every note sounds once).
// Observation identifiers name what is measured, never a regulation setting, so that a list of
// them gives nothing of the answer away.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/progress.h"
#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

enum class PracticeTest { Rest, SlowPress, ForteBlow, Repetition };

/// The test's identifier ("rest", "slow_press", "forte_blow", "repetition").
std::string test_name(PracticeTest test);
/// The test in words, as the practice form names it ("rest geometry", "slow key press", "forte
/// blow", "repeated notes").
std::string test_label(PracticeTest test);
/// Parses a test identifier; throws InputError naming the tests.
PracticeTest parse_test(const std::string& name);
/// How the window shows a test on the action while it is read: a run from rest under `input`
/// (an input SPEC, "" = no finger) in which the test takes `duration_s`.
struct ShownTest {
  std::string input;
  double duration_s = 0.0;
};
/// rest: the action at rest; slow_press: its input and duration; forte_blow: its input, for the
/// strike and the catch (0.05 s); repetition: its fastest note (kRepetitionFrequencies' last,
/// where a fault shows first), four cycles.
ShownTest shown_test(PracticeTest test);
/// Every test, in the order a technician runs them.
std::vector<PracticeTest> all_tests();

struct Observation {
  std::string id;     ///< e.g. "slow_press.escapement_distance_mm"
  std::string label;  ///< in words, for the window and the report
  std::string unit;   ///< "mm", "m/s", "", "per cycle", "fraction"
  std::optional<double> value;
  std::string missing_reason;  ///< why it could not be read, when value is empty
};

/// Repetition test frequencies (Hz): a slow, a moderate and a fast repeated note.
inline constexpr double kRepetitionFrequencies[] = {4.0, 8.0, 12.0};

/// Runs one test on `model` (rest: its rest state). `progress` (may be null) gets the
/// fraction within the test and may cancel (throws Cancelled). A failure of the action itself
/// (no escapement, no check) is an observation, not an exception; an unphysical run is an
/// observation too (its cause named).
std::vector<Observation> run_test(const ActionModel& model, const RestState& rest,
                                  PracticeTest test, ProgressReporter* progress = nullptr);

/// Every test on `model`, the independent runs on both cores.
std::vector<Observation> run_all_tests(const ActionModel& model,
                                       ProgressReporter* progress = nullptr);

/// The observation with `id`, or null.
const Observation* find_observation(const std::vector<Observation>& list, const std::string& id);

}  // namespace pat

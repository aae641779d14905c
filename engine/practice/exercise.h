// A practice exercise (issue 7, paper section 8): an action with one setting (level 2: two)
// moved off its regulated position, hidden from the trainee, who must name the setting and the
// direction from what a technician can observe, then correct it.
//
// An exercise comes from a seed (the same seed always gives the same fault, on any machine) or
// from a teacher's JSON file in presets/exercises/:
//   { "schema": "pat-exercise/1", "action": "grand", "title": "...", "notes": "...",
//     "faults": [ { "setting": "let_off", "adjuster_mm": -0.3 } ] }
// The answer (setting and direction) follows from the fault without any simulation.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/action_model.h"

namespace pat {

inline constexpr const char* kExerciseSchema = "pat-exercise/1";

/// One hidden mis-setting: the adjuster moved `adjuster_mm` from its regulated position.
struct HiddenFault {
  std::string setting;
  double adjuster_mm = 0.0;
};

/// The expected diagnosis for one fault: `more` or `less` of the measured value relative to
/// its target.
struct FaultAnswer {
  std::string setting;
  std::string direction;  ///< "more" or "less"
  bool operator==(const FaultAnswer&) const = default;
};

struct Exercise {
  std::string action;  ///< "grand", "upright" or a preset path (as given to load_action)
  std::string kind;    ///< the model's kind ("grand" / "upright")
  int level = 1;       ///< number of hidden faults
  std::optional<std::uint64_t> seed;
  std::string source_file;  ///< the teacher's file, empty for a seeded exercise
  std::string title;
  std::string notes;
  std::vector<HiddenFault> faults;
};

/// The exercise drawn from `seed` for `model` (its kind selects the neglect ranges): `level`
/// distinct settings, each offset by a magnitude in its neglect range with a random sign. Seeds
/// 1..n, n+1..2n, ... (n settings) hide each setting once as their first, in a shuffled order.
/// Throws InputError for a level other than 1 or 2.
Exercise generate_exercise(const ActionModel& model, const std::string& action, std::uint64_t seed,
                           int level);

/// Reads a teacher's exercise file and checks it against `model` when given (or the action the
/// file names). Throws InputError naming the file and the field for a broken file (not JSON,
/// wrong schema, missing or mistyped field) or an impossible one (unknown setting, the same
/// setting twice, an offset outside the adjuster's physical range, no fault, more than two).
Exercise load_exercise(const std::string& path);

/// The answers of an exercise, one per fault, in the exercise's order.
std::vector<FaultAnswer> exercise_answers(const Exercise& exercise);

/// The model the trainee works on: `regulated` with every fault's adjuster moved.
ActionModel hidden_model(const ActionModel& regulated, const Exercise& exercise);

/// Parses "SETTING:DIRECTION" (several joined by commas for level 2). Throws InputError for a
/// malformed answer, an unknown setting or a direction other than more/less.
std::vector<FaultAnswer> parse_answers(const ActionModel& model, const std::string& text);

struct AnswerJudgement {
  bool correct = false;  ///< every fault named with its direction, nothing else
  double score = 0.0;    ///< 0–100: per fault, 100/level for setting and direction, 40/level
                         ///< for the setting with the wrong direction; a wrong extra name costs
                         ///< 100/level
  std::vector<std::string> remarks;  ///< per named setting: right, wrong direction, not faulty
};

/// Judges a diagnosis against the exercise (no simulation).
AnswerJudgement judge_answers(const Exercise& exercise, const std::vector<FaultAnswer>& given);

}  // namespace pat

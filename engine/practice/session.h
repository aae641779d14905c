// A practice session (issue 7): one exercise worked through by a trainee — tests run on the
// hidden action, diagnoses given, hints asked for, adjusters moved (relative moves only: the
// trainee never sees where an adjuster truly is), and the final score. Times are given by the
// caller (seconds since the session started), so a session replays the same in a test.
//
// Score (0–100):
//   diagnosis   50 × the first answer's judgement (judge_answers), − 5 per later wrong answer;
//   regulation  40 × the mean, over the hidden faults, of the fraction of the deviation beyond
//               the tolerance tol removed: 1 − max(0, |corrected − regulated| − tol) /
//               (|hidden − regulated| − tol), in [0, 1] (a fault left as found earns nothing),
//               − 5 per setting that was not faulty but was left moved by more than 0.05 mm;
//   economy     10 − 1 per test run toward the diagnosis beyond the four different tests − 1 per
//               full two minutes beyond the first ten (never below 0); a test run once the
//               diagnosis is right (or the answer shown) checks the correction, as a technician
//               re-tests after turning a screw, and costs nothing;
//   hints       − 5 each.
// After the answer is revealed (reveal()), answers are still judged but no longer scored.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "model/action_model.h"
#include "practice/exercise.h"
#include "practice/observations.h"
#include "practice/symptoms.h"

namespace pat {

struct SessionEvent {
  double t_s = 0.0;
  std::string kind;    ///< "start", "test", "answer", "hint", "move", "score"
  std::string detail;  ///< in words, short (the history list's line)
  /// What the trainee was told in full, where the line shortens it: a test's symptom sentences
  /// (empty for the other kinds).
  std::string words;
};

/// The measured value of a setting on three actions (its unit); empty when not measurable.
struct CorrectionReading {
  std::string setting;
  std::optional<double> regulated, hidden, corrected;
  /// A deregulated or moved setting, which the regulation marks are for. The others are read on
  /// the corrected action only (`corrected`), as the regulation panel reads them, so that the
  /// score can name those a correction left out of tolerance (a lever raised lifts the hammer:
  /// the blow, set after it in the technician's order, then reads short).
  bool scored = true;
};

struct SessionScore {
  double diagnosis = 0.0;   ///< 0–50
  double regulation = 0.0;  ///< 0–40
  double economy = 0.0;     ///< 0–10
  double hint_penalty = 0.0;
  double total = 0.0;  ///< 0–100
  bool diagnosed = false;
  int tests_used = 0;   ///< every test run
  int check_tests = 0;  ///< of them, those after the diagnosis (checks of the correction)
  int hints_used = 0;
  double time_s = 0.0;
  std::vector<CorrectionReading> readings;
  std::vector<std::string> notes;  ///< one line per component, for the report
  /// The settings the correction left out of tolerance, other than the scored ones, in words
  /// with their readings ("hammer blow 44.89 mm (target 45.00 mm ± 0.05)"); empty: none.
  std::string out_of_tolerance;
};

/// A setting's reading with its unit, as the report gives it: "0.15 mm", "4.2 % of the hammer's
/// travel" (unit "fraction").
std::string reading_text(double value, const std::string& unit);

/// Steps of one setting closer together than this (s) are one move in the history.
inline constexpr double kMoveMergeSeconds = 5.0;

class PracticeSession {
 public:
  /// `regulated` is the action the exercise was made for (adjusters at their regulated place).
  PracticeSession(Exercise exercise, ActionModel regulated);

  const Exercise& exercise() const { return exercise_; }
  /// The trainee's name for the report (may be empty), on one line: line breaks and other
  /// control characters become spaces, the ends are trimmed.
  void set_trainee(const std::string& name);
  const std::string& trainee() const { return trainee_; }
  const ActionModel& regulated() const { return regulated_; }
  /// The hidden action with the trainee's moves applied (what the sliders act on).
  ActionModel current_model() const;

  /// Records a test's observations on the current model; returns its symptoms compared with
  /// the regulated action's observations `regulated_observations` of the same test.
  std::vector<Symptom> record_test(PracticeTest test, const std::vector<Observation>& seen,
                                   const std::vector<Observation>& regulated_observations,
                                   double t_s);
  /// Gives a diagnosis; the first one counts for the score.
  AnswerJudgement answer(const std::vector<FaultAnswer>& given, double t_s);
  /// The next hint (each more telling than the last, the fourth names the setting), toward the
  /// first hidden setting neither found in an answer nor named by a hint yet; with two, then
  /// toward the other. The first of a setting's hints quotes the symptom read from its own
  /// measurement when one was seen. Once every hidden setting is found or named, and after
  /// reveal() (which it repeats), a hint says so and costs nothing.
  std::string hint(double t_s);
  /// Gives up: the hidden settings in words (recorded in the history); answers given after it
  /// are judged but do not count for the score.
  std::string reveal(double t_s);
  /// The hidden settings in words: each setting, its direction and its adjuster's offset.
  std::string answer_text() const;
  /// "setting was" or "settings were", as many as are hidden.
  std::string answer_heading() const;
  bool revealed() const { return revealed_; }
  /// Moves an adjuster by `delta_mm` relative to where it is (the trainee's slider). Throws
  /// InputError for an unknown setting or a move beyond the adjuster's physical range.
  void move_adjuster(const std::string& setting, double delta_mm, double t_s);
  /// The trainee's total move of a setting's adjuster (mm).
  double moved_mm(const std::string& setting) const;

  /// The settings whose measurements the score needs: the faults and every setting moved.
  std::vector<std::string> scored_settings() const;
  /// Scores the session from the readings of scored_settings() (see measure_corrections).
  SessionScore score(const std::vector<CorrectionReading>& readings, double t_s);

  const std::vector<SessionEvent>& history() const { return history_; }
  int tests_used() const { return tests_used_; }
  /// Tests run once the diagnosis was right or the answer shown: checks of the correction, not
  /// counted against economy.
  int check_tests() const { return check_tests_; }
  /// Whether a test run now would be such a check.
  bool tests_are_checks() const { return diagnosed_ || revealed_; }
  /// The diagnosis marks so far (0–50): half the first answer's score, 5 off per different
  /// wrong answer after it.
  double diagnosis_marks() const;
  /// Answers given before the answer was revealed (repeats included).
  int answers_given() const { return answers_given_; }
  int hints_used() const { return hints_used_; }
  const std::optional<AnswerJudgement>& first_answer() const { return first_answer_; }
  const std::optional<SessionScore>& final_score() const { return final_score_; }

 private:
  Exercise exercise_;
  ActionModel regulated_;
  std::string trainee_;
  std::map<std::string, double> moves_mm_;
  std::vector<SessionEvent> history_;
  std::vector<PracticeTest> tests_run_;
  int tests_used_ = 0;
  int check_tests_ = 0;
  int hints_used_ = 0;
  int wrong_answers_after_first_ = 0;  ///< different wrong answers after the first
  int answers_given_ = 0;
  std::string last_moved_;               ///< the setting of the history's last move
  double last_move_mm_ = 0.0;            ///< that move's size, steps merged
  std::set<std::string> given_answers_;  ///< every answer given, in words
  bool diagnosed_ = false;
  bool revealed_ = false;
  std::set<std::string> found_;                  ///< hidden settings named right in some answer
  std::map<std::string, int> hints_by_setting_;  ///< hints given toward each hidden setting
  std::optional<AnswerJudgement> first_answer_;
  std::vector<Symptom> symptoms_seen_;
  std::optional<SessionScore> final_score_;
};

/// Measures the scored settings on the regulated, hidden and corrected actions (simulation:
/// slow presses and forte blows; tens of milliseconds to a second each).
std::vector<CorrectionReading> measure_corrections(const PracticeSession& session);

/// Writes the session as CSV (history, then the score): columns t_s,kind,detail. Written to a
/// temporary file and renamed. Throws InputError when the file cannot be written.
void write_session_csv(const std::string& path, const PracticeSession& session);

}  // namespace pat

// Practice exercises without simulation: seeds, the answer check, teacher files and their
// errors, the session's bookkeeping and score.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "core/error.h"
#include "practice/exercise.h"
#include "practice/neglect_ranges.h"
#include "practice/session.h"
#include "test_support.h"

namespace pat {
namespace {

const ActionModel& shipped_model(const std::string& kind) {
  static const ActionModel grand = test::shipped("grand");
  static const ActionModel upright = test::shipped("upright");
  return kind == "grand" ? grand : upright;
}

TEST(PracticeExercise, SeedGivesTheSameExerciseWithinTheNeglectRanges) {
  for (const std::string kind : {"grand", "upright"}) {
    const ActionModel& model = shipped_model(kind);
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      for (int level : {1, 2}) {
        const Exercise a = generate_exercise(model, kind, seed, level);
        const Exercise b = generate_exercise(model, kind, seed, level);
        ASSERT_EQ(a.faults.size(), static_cast<std::size_t>(level));
        std::set<std::string> settings;
        for (std::size_t i = 0; i < a.faults.size(); ++i) {
          EXPECT_EQ(a.faults[i].setting, b.faults[i].setting);
          EXPECT_EQ(a.faults[i].adjuster_mm, b.faults[i].adjuster_mm);
          const NeglectRange& r = neglect_range(kind, a.faults[i].setting);
          // offsets are rounded to 0.01 mm: the range holds to half of that
          EXPECT_GE(std::abs(a.faults[i].adjuster_mm), r.min_mm - 0.005) << seed;
          EXPECT_LE(std::abs(a.faults[i].adjuster_mm), r.max_mm + 0.005) << seed;
          settings.insert(a.faults[i].setting);
        }
        EXPECT_EQ(settings.size(), a.faults.size()) << "level 2 hides two different settings";
      }
    }
  }
}

// A class handed exercises 1 to 7 (the grand's seven settings) gets seven different settings to
// find, and so for every later block of seven; independent draws had repeated one (seeds 1 and
// 3 both hid the lever height 0.21 mm high). The order differs from block to block.
TEST(PracticeExercise, ConsecutiveSeedsHideDifferentSettings) {
  for (const std::string kind : {"grand", "upright"}) {
    const ActionModel& model = shipped_model(kind);
    const std::uint64_t n = model.regulation.size();
    std::set<std::vector<std::string>> orders;
    for (std::uint64_t block = 0; block < 20; ++block) {
      std::vector<std::string> order;
      for (std::uint64_t seed = block * n + 1; seed <= (block + 1) * n; ++seed)
        for (int level : {1, 2})
          if (const Exercise e = generate_exercise(model, kind, seed, level); level == 1)
            order.push_back(e.faults[0].setting);
          else
            EXPECT_EQ(e.faults[0].setting, order.back()) << "level 2 hides it too, and another";
      EXPECT_EQ(std::set<std::string>(order.begin(), order.end()).size(), n)
          << kind << ", seeds " << block * n + 1 << " to " << (block + 1) * n;
      orders.insert(order);
    }
    // shuffled per block: of 5040 (grand) or 720 orders, twenty blocks share few
    EXPECT_GE(orders.size(), 15u) << kind;
  }
}

TEST(PracticeExercise, EverySettingOfBothActionsCanBeHiddenInBothDirections) {
  for (const std::string kind : {"grand", "upright"}) {
    const ActionModel& model = shipped_model(kind);
    std::set<std::string> drawn;
    for (std::uint64_t seed = 0; seed < 200; ++seed)
      for (const FaultAnswer& a : exercise_answers(generate_exercise(model, kind, seed, 1)))
        drawn.insert(a.setting + ":" + a.direction);
    for (const RegulationSetting& s : model.regulation) {
      // a one-sided range (a model limit) gives the one direction its sign makes
      const NeglectRange& r = neglect_range(kind, s.name);
      const int way = r.sense * (r.only_sign == 0 ? 1 : r.only_sign);
      EXPECT_TRUE(drawn.count(s.name + ":more") || (r.only_sign != 0 && way < 0))
          << kind << " " << s.name;
      EXPECT_TRUE(drawn.count(s.name + ":less") || (r.only_sign != 0 && way > 0))
          << kind << " " << s.name;
      EXPECT_EQ(r.only_sign == 0, r.model_limit.empty()) << "a one-sided range says why";
    }
    // every setting has a neglect range whose adjuster offsets fit the adjuster's range
    for (const RegulationSetting& s : model.regulation) {
      const NeglectRange& r = neglect_range(kind, s.name);
      const Adjuster& a = model.adjusters[model.adjuster_index(s.name)];
      EXPECT_LT(0.0, r.min_mm);
      EXPECT_LE(r.min_mm, r.max_mm);
      EXPECT_LE(r.max_mm * 1e-3, std::min(-a.min, a.max) + 1e-12) << s.name;
      EXPECT_FALSE(r.source.empty());
    }
  }
}

TEST(PracticeCheck, JudgesRightAndWrongAnswersForFiftySeeds) {
  for (const std::string kind : {"grand", "upright"}) {
    const ActionModel& model = shipped_model(kind);
    for (std::uint64_t seed = 1000; seed < 1050; ++seed) {
      const Exercise e = generate_exercise(model, kind, seed, 1);
      const FaultAnswer right = exercise_answers(e).front();
      // the direction follows from the adjuster's sense and the sign of its offset
      const int sense = neglect_range(kind, right.setting).sense;
      EXPECT_EQ(right.direction, sense * e.faults[0].adjuster_mm > 0 ? "more" : "less");

      const AnswerJudgement good = judge_answers(e, {right});
      EXPECT_TRUE(good.correct);
      EXPECT_DOUBLE_EQ(good.score, 100.0);

      const FaultAnswer flipped{right.setting, right.direction == "more" ? "less" : "more"};
      const AnswerJudgement half = judge_answers(e, {flipped});
      EXPECT_FALSE(half.correct);
      EXPECT_DOUBLE_EQ(half.score, 40.0);

      for (const RegulationSetting& s : model.regulation) {
        if (s.name == right.setting) continue;
        const AnswerJudgement wrong = judge_answers(e, {{s.name, right.direction}});
        EXPECT_FALSE(wrong.correct);
        EXPECT_DOUBLE_EQ(wrong.score, 0.0);
      }
      // a right answer with an extra wrong name is not correct
      const std::string other = model.regulation[0].name == right.setting
                                    ? model.regulation[1].name
                                    : model.regulation[0].name;
      EXPECT_FALSE(judge_answers(e, {right, {other, "more"}}).correct);
    }
    const Exercise two = generate_exercise(model, kind, 7, 2);
    const std::vector<FaultAnswer> both = exercise_answers(two);
    EXPECT_TRUE(judge_answers(two, both).correct);
    EXPECT_DOUBLE_EQ(judge_answers(two, {both[0]}).score, 50.0);
    EXPECT_FALSE(judge_answers(two, {both[0]}).correct);
  }
}

TEST(PracticeCheck, ParsesAnswersAndRejectsBadOnes) {
  const ActionModel& model = shipped_model("grand");
  const auto parsed = parse_answers(model, "let_off:less,checking:more");
  ASSERT_EQ(parsed.size(), 2u);
  EXPECT_EQ(parsed[1], (FaultAnswer{"checking", "more"}));
  EXPECT_THROW(parse_answers(model, "let_off"), InputError);
  EXPECT_THROW(parse_answers(model, "lost_motion:more"), InputError);  // upright only
  EXPECT_THROW(parse_answers(model, "let_off:closer"), InputError);
}

/// Writes `text` to a temporary exercise file and returns the InputError's message.
std::string load_error(const std::string& name, const std::string& text) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("pat_exercise_" + name + ".json")).string();
  std::ofstream(path) << text;
  try {
    load_exercise(path);
  } catch (const InputError& e) {
    std::filesystem::remove(path);
    return e.what();
  }
  std::filesystem::remove(path);
  ADD_FAILURE() << name << ": no InputError";
  return {};
}

TEST(PracticeExerciseFile, ShippedExercisesLoad) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(PAT_PRESET_DIR) + "/exercises")) {
    const Exercise e = load_exercise(entry.path().string());
    EXPECT_FALSE(e.faults.empty());
    EXPECT_EQ(e.level, static_cast<int>(e.faults.size()));
    EXPECT_EQ(exercise_answers(e).size(), e.faults.size());
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(PracticeExerciseFile, BrokenOrImpossibleFilesNameTheFileAndTheField) {
  const std::string head = R"({"schema": "pat-exercise/1", "action": "grand", )";
  struct Case {
    std::string name, text, must_contain;
  };
  const std::vector<Case> cases = {
      {"not_json", "{ \"schema\": ", "not valid JSON"},
      {"no_schema", R"({"action": "grand", "faults": []})", "schema"},
      {"old_schema", R"({"schema": "pat-exercise/0", "action": "grand", "faults": []})",
       "unsupported version"},
      {"no_faults", head + R"("title": "x"})", "faults"},
      {"empty_faults", head + R"("faults": []})", "one or two faults"},
      {"three_faults",
       head + R"("faults": [{"setting": "drop", "adjuster_mm": 1}, {"setting": "let_off",
                  "adjuster_mm": 0.1}, {"setting": "checking", "adjuster_mm": 1}]})",
       "one or two faults"},
      {"unknown_setting", head + R"("faults": [{"setting": "lost_motion", "adjuster_mm": 1}]})",
       "faults[0].setting: unknown setting 'lost_motion'"},
      {"twice", head + R"("faults": [{"setting": "drop", "adjuster_mm": 1}, {"setting": "drop",
                  "adjuster_mm": -1}]})",
       "faults[1].setting"},
      {"beyond_range", head + R"("faults": [{"setting": "drop", "adjuster_mm": 12}]})",
       "faults[0].adjuster_mm: impossible"},
      {"zero_offset", head + R"("faults": [{"setting": "drop", "adjuster_mm": 0}]})",
       "faults[0].adjuster_mm: must be a non-zero offset"},
      {"text_offset", head + R"("faults": [{"setting": "drop", "adjuster_mm": "1"}]})",
       "faults[0].adjuster_mm"},
      {"unknown_action", R"({"schema": "pat-exercise/1", "action": "harpsichord", "faults": []})",
       "action"},
      {"unknown_field", head + R"("fault": []})", "fault: unknown field"},
  };
  for (const Case& c : cases) {
    const std::string message = load_error(c.name, c.text);
    EXPECT_NE(message.find("pat_exercise_" + c.name + ".json"), std::string::npos)
        << c.name << ": " << message;
    EXPECT_NE(message.find(c.must_contain), std::string::npos) << c.name << ": " << message;
  }
  EXPECT_THROW(load_exercise("/nonexistent/exercise.json"), InputError);
}

/// A grand exercise whose one hidden fault is the backcheck's wire bent 2 mm.
Exercise checking_exercise(const ActionModel& model) {
  Exercise e = generate_exercise(model, "grand", 3, 1);
  e.faults = {{"checking", 2.0}};
  return e;
}

TEST(PracticeSession, ScoresDiagnosisCorrectionEconomyAndHints) {
  const ActionModel& model = shipped_model("grand");
  const Exercise e = checking_exercise(model);
  PracticeSession session(e, model);
  const FaultAnswer right = exercise_answers(e).front();
  EXPECT_FALSE(session.answer({{"drop", "more"}}, 30.0).correct);
  EXPECT_FALSE(session.hint(50.0).empty());
  EXPECT_TRUE(session.answer({right}, 60.0).correct);
  // found: a hint now says so, and costs nothing
  EXPECT_EQ(session.hint(70.0).rfind("Every hidden setting has been found", 0), 0u);
  EXPECT_EQ(session.hints_used(), 1);
  session.move_adjuster("checking", -1.5, 80.0);
  session.move_adjuster("checking", -0.5, 90.0);
  EXPECT_DOUBLE_EQ(session.moved_mm("checking"), -2.0);
  EXPECT_THROW(session.move_adjuster("checking", -50.0, 95.0), InputError);
  EXPECT_DOUBLE_EQ(session.moved_mm("checking"), -2.0) << "a refused move changes nothing";
  // the trainee's moves undo the fault exactly: the current model is the regulated one
  EXPECT_NEAR(session.current_model().adjusters[model.adjuster_index("checking")].value, 0.0,
              1e-15);
  EXPECT_EQ(session.scored_settings(), std::vector<std::string>{"checking"});

  // readings as measure_corrections gives them: fully corrected
  const SessionScore s = session.score({{"checking", 16.0, 19.0, 16.0}}, 120.0);
  EXPECT_DOUBLE_EQ(s.diagnosis, 0.0) << "the first answer named a wrong setting";
  EXPECT_DOUBLE_EQ(s.regulation, 40.0);
  EXPECT_DOUBLE_EQ(s.economy, 10.0);
  EXPECT_DOUBLE_EQ(s.hint_penalty, 5.0);
  EXPECT_DOUBLE_EQ(s.total, 45.0);
  // half the deviation left: 1.45 of the 2.95 mm beyond the 0.05 mm tolerance remain
  const SessionScore half = session.score({{"checking", 16.0, 19.0, 17.5}}, 120.0);
  EXPECT_NEAR(half.regulation, 40.0 * (1.0 - 1.45 / 2.95), 1e-9);
  // the fault left as found earns nothing, however small it is against the tolerance
  EXPECT_DOUBLE_EQ(session.score({{"checking", 16.0, 19.0, 19.0}}, 120.0).regulation, 0.0);
  EXPECT_DOUBLE_EQ(session.score({{"checking", 16.0, 16.3, 16.3}}, 120.0).regulation, 0.0);
  // within the tolerance counts as corrected
  EXPECT_DOUBLE_EQ(session.score({{"checking", 16.0, 19.0, 16.04}}, 120.0).regulation, 40.0);

  const std::string csv =
      (std::filesystem::temp_directory_path() / "pat_practice_session.csv").string();
  session.set_trainee("  Ada\nLovelace ");  // one line in the file's metadata
  EXPECT_EQ(session.trainee(), "Ada Lovelace");
  write_session_csv(csv, session);
  std::ifstream in(csv);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("t_s,kind,detail"), std::string::npos);
  EXPECT_NE(text.find("# trainee: Ada Lovelace\n"), std::string::npos);
  // in a technician's words and units: the answer, the readings, the score's notes
  EXPECT_NE(text.find("t_s,kind,detail,words\n"), std::string::npos);
  EXPECT_NE(text.find("drop: more → not correct"), std::string::npos) << text;
  EXPECT_NE(text.find("checking: regulated 16.00 mm, hidden 19.00 mm, corrected 16.04 mm"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("off by 0.04 mm after, 3.00 mm before"), std::string::npos) << text;
  EXPECT_NE(text.find("answer"), std::string::npos);
  EXPECT_NE(text.find("score"), std::string::npos);
  std::filesystem::remove(csv);
  EXPECT_THROW(write_session_csv("/nonexistent/dir/session.csv", session), InputError);
}

// A lever raised lifts the hammer (about 11 mm of blow per mm of lever at the knuckle): a lever
// height corrected to within its own tolerance can leave the blow, set after it, out of its
// tolerance. The regulation panel shows that; the score must say it too, not full marks alone.
TEST(PracticeSession, TheScoreNamesWhatTheCorrectionLeftOutOfTolerance) {
  const ActionModel& model = shipped_model("grand");
  Exercise e = generate_exercise(model, "grand", 3, 1);
  e.faults = {{"lever_height", 0.3}};
  PracticeSession session(e, model);
  EXPECT_TRUE(session.answer(exercise_answers(e), 10.0).correct);
  session.move_adjuster("lever_height", -0.29, 20.0);  // 0.01 mm high: within its tolerance
  const std::vector<CorrectionReading> readings = measure_corrections(session);
  ASSERT_EQ(readings.size(), model.regulation.size()) << "every setting is read";
  EXPECT_TRUE(readings.front().scored);
  EXPECT_EQ(readings.front().setting, "lever_height");
  const SessionScore s = session.score(readings, 30.0);
  EXPECT_DOUBLE_EQ(s.regulation, 40.0) << "the hidden fault is corrected within its tolerance";
  EXPECT_NE(s.out_of_tolerance.find("hammer blow"), std::string::npos) << s.out_of_tolerance;
  const bool noted = std::any_of(s.notes.begin(), s.notes.end(), [](const std::string& n) {
    return n.find("out of tolerance after the correction") != std::string::npos &&
           n.find("hammer blow") != std::string::npos;
  });
  EXPECT_TRUE(noted);
  // corrected exactly, nothing is left out of tolerance
  session.move_adjuster("lever_height", -0.01, 40.0);
  EXPECT_EQ(session.score(measure_corrections(session), 50.0).out_of_tolerance, "");
}

// Economy judges the tests toward the diagnosis: six of them (four different tests, the two
// repeats beyond four cost 1 each), then, once the diagnosis is right, re-tests that check the
// correction, which cost nothing however many (a technician re-tests after turning a screw).
TEST(PracticeSession, TestsAfterTheDiagnosisAreFreeChecks) {
  const ActionModel& model = shipped_model("grand");
  const Exercise e = checking_exercise(model);
  PracticeSession session(e, model);
  const std::vector<Observation> none;
  const PracticeTest diagnosis_tests[] = {PracticeTest::Rest,      PracticeTest::SlowPress,
                                          PracticeTest::ForteBlow, PracticeTest::Repetition,
                                          PracticeTest::SlowPress, PracticeTest::ForteBlow};
  double t = 10.0;
  for (PracticeTest test : diagnosis_tests) session.record_test(test, none, none, t += 10.0);
  EXPECT_FALSE(session.tests_are_checks());
  EXPECT_TRUE(session.answer({exercise_answers(e).front()}, t += 10.0).correct);
  EXPECT_TRUE(session.tests_are_checks());
  for (int i = 0; i < 5; ++i) session.record_test(PracticeTest::ForteBlow, none, none, t += 10.0);
  EXPECT_EQ(session.tests_used(), 11);
  EXPECT_EQ(session.check_tests(), 5);
  const SessionScore s = session.score({{"checking", 16.0, 19.0, 16.0}}, t);
  EXPECT_DOUBLE_EQ(s.economy, 8.0);  // 6 tests toward the diagnosis: 2 beyond the four
  EXPECT_EQ(s.check_tests, 5);
  // the history says which tests were checks
  int checks = 0;
  for (const SessionEvent& event : session.history())
    if (event.kind == "test" && event.detail.find("(check)") != std::string::npos) ++checks;
  EXPECT_EQ(checks, 5);
  // a test's line in words, the test named as the form names it
  EXPECT_EQ(session.history()[1].detail,
            "rest geometry: nothing differs noticeably from a regulated action");
}

// Answer clicked twice on the same wrong answer is one mistake: the first answer (the right
// setting, the wrong direction: 40 of 100, 20 diagnosis marks) loses 5 for each different later
// wrong answer (two here), not for the same one given again or in another order.
TEST(PracticeSession, AWrongAnswerRepeatedIsOneMistake) {
  const ActionModel& model = shipped_model("grand");
  const Exercise e = checking_exercise(model);
  PracticeSession session(e, model);
  const FaultAnswer right = exercise_answers(e).front();
  const FaultAnswer backwards{right.setting, right.direction == "more" ? "less" : "more"};
  EXPECT_FALSE(session.answer({backwards}, 10.0).correct);
  EXPECT_FALSE(session.answer({{"drop", "more"}}, 20.0).correct);
  EXPECT_FALSE(session.answer({{"drop", "more"}}, 21.0).correct);
  // the same pair named in the other order is the same answer
  EXPECT_FALSE(session.answer({{"drop", "more"}, {"let_off", "less"}}, 22.0).correct);
  EXPECT_FALSE(session.answer({{"let_off", "less"}, {"drop", "more"}}, 23.0).correct);
  EXPECT_DOUBLE_EQ(session.diagnosis_marks(), 10.0);  // two different wrong answers
  EXPECT_TRUE(session.answer({right}, 30.0).correct);
  EXPECT_EQ(session.answers_given(), 6);
  const SessionScore s = session.score({{"checking", 16.0, 19.0, 19.0}}, 60.0);
  EXPECT_DOUBLE_EQ(s.diagnosis, 10.0);
}

// A setting stepped from the keyboard (ten 0.01 mm presses) is one move in the history, as long
// as the steps follow each other within kMoveMergeSeconds; another setting, or a pause, starts a
// new one.
TEST(PracticeSession, OneSettingsStepsOneAfterAnotherAreOneMove) {
  const ActionModel& model = shipped_model("grand");
  PracticeSession session(checking_exercise(model), model);
  auto moves = [&session] {
    std::vector<std::string> details;
    for (const SessionEvent& e : session.history())
      if (e.kind == "move") details.push_back(e.detail);
    return details;
  };
  for (int i = 0; i < 10; ++i) session.move_adjuster("checking", -0.01, 10.0 + 0.2 * i);
  ASSERT_EQ(moves().size(), 1u);
  EXPECT_EQ(moves().back(), "checking -0.1 mm (moved -0.1 mm in all)");
  session.move_adjuster("checking", -0.01, 10.0 + 0.2 * 9 + kMoveMergeSeconds + 1.0);
  ASSERT_EQ(moves().size(), 2u);
  EXPECT_EQ(moves().back(), "checking -0.01 mm (moved -0.11 mm in all)");
  session.move_adjuster("drop", 0.05, 20.0);
  session.move_adjuster("checking", 0.01, 20.5);
  EXPECT_EQ(moves().size(), 4u);
  EXPECT_NEAR(session.moved_mm("checking"), -0.1, 1e-12);
  // steps that undo each other leave no move (not "+3.5e-18 mm")
  session.move_adjuster("drop", 0.01, 40.0);
  session.move_adjuster("drop", -0.01, 40.5);
  EXPECT_EQ(moves().size(), 4u);
  EXPECT_EQ(moves().back(), "checking +0.01 mm (moved -0.1 mm in all)");
}

TEST(PracticeSession, FirstHintQuotesTheHiddenSettingsOwnSymptom) {
  // A grand's lever height also moves the hammer's rest (the lever carries the knuckle at
  // rest), so the rest geometry shows a hammer-blow symptom first; the hint must not send the
  // trainee there when the lever's own reading, the knuckle-jack gap, differs too.
  const ActionModel& model = shipped_model("grand");
  Exercise e = generate_exercise(model, "grand", 0, 1);
  e.faults = {{"lever_height", -0.16}};
  PracticeSession session(e, model);
  auto number = [](const std::string& id, double v) { return Observation{id, id, "mm", v, ""}; };
  const std::vector<Observation> regulated{number("rest.hammer_distance_mm", 45.0),
                                           number("rest.escapement_gap_mm", 0.5)};
  const std::vector<Observation> seen{number("rest.hammer_distance_mm", 46.2),
                                      number("rest.escapement_gap_mm", 0.2)};
  const auto symptoms = session.record_test(PracticeTest::Rest, seen, regulated, 10.0);
  ASSERT_EQ(symptoms.size(), 2u);
  ASSERT_EQ(symptoms.front().observation, "rest.hammer_distance_mm");  // seen first
  const std::string hint = session.hint(20.0);
  EXPECT_NE(hint.find(symptoms.back().text), std::string::npos) << hint;
  EXPECT_EQ(hint.find(symptoms.front().text), std::string::npos) << hint;
}

/// A grand exercise of level 2: the let-off button screwed 1 mm and the backcheck bent 2 mm.
Exercise let_off_and_checking_exercise(const ActionModel& model) {
  Exercise e = generate_exercise(model, "grand", 0, 2);
  e.faults = {{"let_off", 1.0}, {"checking", 2.0}};
  return e;
}

TEST(PracticeSession, HintsLeadToTheHiddenSettingNotYetFound) {
  // Two hidden faults: once the trainee has named one right, the hints are about the other,
  // from their first step, and say "the other"; before it, "one hidden setting".
  const ActionModel& model = shipped_model("grand");
  const Exercise e = let_off_and_checking_exercise(model);
  PracticeSession session(e, model);
  const std::vector<FaultAnswer> hidden = exercise_answers(e);
  session.hint(5.0);  // "run the four tests first" (none seen)
  const std::string before = session.hint(6.0);
  EXPECT_EQ(before.rfind("One hidden setting is measured in", 0), 0u) << before;

  EXPECT_FALSE(session.answer({hidden[0], {"drop", "more"}}, 10.0).correct);
  session.hint(20.0);  // the other setting's first step
  const std::string where = session.hint(21.0);
  EXPECT_EQ(where.rfind("The other hidden setting is measured in", 0), 0u) << where;
  session.hint(22.0);
  const std::string named = session.hint(23.0);
  EXPECT_EQ(named,
            "The other hidden setting is checking (" + hidden[1].direction + " than its target).");
  EXPECT_EQ(session.hints_used(), 6);  // each one counts
  // both found or named: no more hints, none charged
  EXPECT_EQ(session.hint(24.0).rfind("The hints have named every hidden setting: ", 0), 0u);
  EXPECT_EQ(session.hints_used(), 6);
}

// Without an answer, the hints name the first hidden setting, then go on to the other (they had
// repeated the first one's name, each charged).
TEST(PracticeSession, HintsGoOnToTheOtherSettingOnceTheFirstIsNamed) {
  const ActionModel& model = shipped_model("grand");
  const Exercise e = let_off_and_checking_exercise(model);
  PracticeSession session(e, model);
  const std::vector<FaultAnswer> hidden = exercise_answers(e);
  std::vector<std::string> hints;
  for (int i = 0; i < 8; ++i) hints.push_back(session.hint(double(i)));
  EXPECT_EQ(hints[3], "One hidden setting is let-off (" + hidden[0].direction +
                          " than its target), and there is a second one.");
  EXPECT_EQ(hints[5].rfind("The other hidden setting is measured in", 0), 0u) << hints[5];
  EXPECT_EQ(hints[7],
            "The other hidden setting is checking (" + hidden[1].direction + " than its target).");
  EXPECT_EQ(session.hints_used(), 8);
}

TEST(PracticeSession, AnswerRemarksNameTheSettingsInTradeWords) {
  const ActionModel& model = shipped_model("grand");
  Exercise e = generate_exercise(model, "grand", 0, 1);
  e.faults = {{"lever_height", -0.16}};
  const AnswerJudgement j = judge_answers(e, {exercise_answers(e).front(), {"let_off", "more"}});
  ASSERT_EQ(j.remarks.size(), 2u);
  EXPECT_EQ(j.remarks[0], "lever height: right setting, right direction");
  EXPECT_EQ(j.remarks[1].rfind("let-off: its adjuster was not moved", 0), 0u) << j.remarks[1];
}

TEST(PracticeSession, RevealShowsTheAnswerAndLaterAnswersDoNotCount) {
  const ActionModel& model = shipped_model("grand");
  const Exercise e = checking_exercise(model);
  PracticeSession session(e, model);
  const FaultAnswer right = exercise_answers(e).front();
  const std::string shown = session.reveal(30.0);
  EXPECT_NE(shown.find("checking " + right.direction + " than its target"), std::string::npos)
      << shown;
  EXPECT_NE(shown.find("+2.00 mm"), std::string::npos) << shown;
  EXPECT_TRUE(session.answer({right}, 40.0).correct);  // still judged
  EXPECT_FALSE(session.first_answer()) << "an answer after the reveal does not count";
  const SessionScore s = session.score({{"checking", 16.0, 19.0, 19.0}}, 60.0);
  EXPECT_DOUBLE_EQ(s.diagnosis, 0.0);
  EXPECT_EQ(session.history()[1].kind, "reveal");  // after "start"
}

}  // namespace
}  // namespace pat

#include "practice/session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"
#include "model/model_edits.h"
#include "regulation/measurements.h"

namespace pat {
namespace {

/// The observation (observations.h) that measures a setting directly: the symptom read from it
/// points at the setting itself rather than at one it moves along.
std::string own_observation(const std::string& kind, const std::string& setting) {
  if (setting == "key_dip") return "rest.key_travel_mm";
  if (setting == "hammer_blow") return "rest.hammer_distance_mm";
  if (setting == "lever_height" || (setting == "lost_motion" && kind == "upright"))
    return "rest.escapement_gap_mm";
  if (setting == "jack_position") return "rest.jack_edge_mm";
  if (setting == "bridle") return "rest.strap_slack_mm";
  if (setting == "let_off") return "slow_press.escapement_distance_mm";
  if (setting == "drop") return "slow_press.held_distance_mm";
  if (setting == "damper_lift") return "slow_press.damper_start_fraction";
  if (setting == "checking") return "forte_blow.caught_distance_mm";
  return {};
}

/// The technician's test that measures a setting: the one its own observation belongs to.
std::string measuring_test(const std::string& kind, const std::string& setting) {
  const std::string own = own_observation(kind, setting);
  if (own.starts_with("slow_press.")) return "the slow key press";
  if (own.starts_with("forte_blow.")) return "the forte blow";
  return "the rest geometry";
}

std::string answers_text(const std::vector<FaultAnswer>& answers) {
  std::string text;
  for (const FaultAnswer& a : answers)
    text += (text.empty() ? "" : ", ") + setting_words(a.setting) + ": " + a.direction;
  return text;
}

}  // namespace

std::string reading_text(double value, const std::string& unit) {
  // to the hundredth of a millimetre a feeler gauge reads (a tenth of a per cent of the travel)
  char text[64];
  if (unit == "fraction")
    std::snprintf(text, sizeof(text), "%.1f %% of the hammer's travel", 100.0 * value);
  else
    std::snprintf(text, sizeof(text), "%.2f%s%s", value, unit.empty() ? "" : " ", unit.c_str());
  return text;
}

namespace {

/// The setting read as a technician reads it, as the regulation panel does (read_setting: the
/// let-off with the drop screw out of the way); empty when it cannot be read there (no
/// escapement, no check, no rest), which scores as not corrected.
std::optional<double> try_read(const ActionModel& model, const std::string& setting) {
  const int index = model.setting_index(setting);
  if (index < 0) return std::nullopt;
  try {
    const double measured =
        read_setting(model, model.regulation[static_cast<std::size_t>(index)]).measured;
    if (std::isfinite(measured)) return measured;
  } catch (const std::runtime_error&) {  // no rest state
  }
  return std::nullopt;
}

}  // namespace

PracticeSession::PracticeSession(Exercise exercise, ActionModel regulated)
    : exercise_(std::move(exercise)), regulated_(std::move(regulated)) {
  history_.push_back({0.0, "start", exercise_.title});
}

void PracticeSession::set_trainee(const std::string& name) {
  std::string line;
  for (char c : name) line += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c;
  const auto first = line.find_first_not_of(' ');
  const auto last = line.find_last_not_of(' ');
  trainee_ = first == std::string::npos ? std::string() : line.substr(first, last - first + 1);
}

ActionModel PracticeSession::current_model() const {
  ActionModel model = hidden_model(regulated_, exercise_);
  for (const auto& [setting, mm] : moves_mm_) {
    const Adjuster& a = model.adjusters[model.adjuster_index(setting)];
    model = with_adjuster(model, setting, a.value + mm * 1e-3);
  }
  return model;
}

std::vector<Symptom> PracticeSession::record_test(
    PracticeTest test, const std::vector<Observation>& seen,
    const std::vector<Observation>& regulated_observations, double t_s) {
  ++tests_used_;
  const bool check = tests_are_checks();
  if (check)
    ++check_tests_;
  else
    tests_run_.push_back(test);  // toward the diagnosis
  std::vector<Symptom> symptoms = describe_symptoms(seen, regulated_observations);
  // the line names the symptoms by their keywords in words ("no gap, failure to repeat"); the
  // sentences the trainee read go with it
  std::string detail = test_label(test) + (check ? " (check): " : ": ");
  std::string words;
  if (symptoms.empty()) detail += "nothing differs noticeably from a regulated action";
  for (std::size_t i = 0; i < symptoms.size(); ++i) {
    detail += (i ? ", " : "") + setting_words(symptoms[i].id);
    words += (i ? " " : "") + symptoms[i].text;
  }
  history_.push_back({t_s, "test", detail, words});
  symptoms_seen_.insert(symptoms_seen_.end(), symptoms.begin(), symptoms.end());
  return symptoms;
}

AnswerJudgement PracticeSession::answer(const std::vector<FaultAnswer>& given, double t_s) {
  AnswerJudgement judgement = judge_answers(exercise_, given);
  if (revealed_) {  // judged, not scored: the answer was shown
    history_.push_back({t_s, "answer", answers_text(given) + " → after the answer was shown"});
    return judgement;
  }
  ++answers_given_;
  // a wrong answer repeated (Answer clicked twice, or its two faults named in the other order)
  // is one mistake, not two
  std::vector<FaultAnswer> in_order = given;
  std::sort(in_order.begin(), in_order.end(), [](const FaultAnswer& a, const FaultAnswer& b) {
    return std::tie(a.setting, a.direction) < std::tie(b.setting, b.direction);
  });
  const bool repeated = !given_answers_.insert(answers_text(in_order)).second;
  if (!first_answer_)
    first_answer_ = judgement;
  else if (!judgement.correct && !diagnosed_ && !repeated)
    ++wrong_answers_after_first_;
  diagnosed_ = diagnosed_ || judgement.correct;
  const std::vector<FaultAnswer> expected = exercise_answers(exercise_);
  for (const FaultAnswer& a : given)  // a hidden setting named with its direction is found
    if (std::find(expected.begin(), expected.end(), a) != expected.end()) found_.insert(a.setting);
  std::ostringstream detail;
  detail << answers_text(given) << " → " << (judgement.correct ? "correct" : "not correct") << " ("
         << format_number(judgement.score) << ")";
  history_.push_back({t_s, "answer", detail.str()});
  return judgement;
}

double PracticeSession::diagnosis_marks() const {
  const double first = first_answer_ ? first_answer_->score : 0.0;
  return std::max(0.0, 0.5 * first - 5.0 * wrong_answers_after_first_);
}

std::string PracticeSession::hint(double t_s) {
  if (revealed_) return reveal(t_s);  // shown already: no more to hint, nothing to charge
  // the hints lead to the first hidden setting not yet named right, each one's from its start
  // (the symptom), so that with two faults the hints after the first is found are about the
  // second; once a setting's hints have named it, the next ones go on to the other
  const std::vector<FaultAnswer> answers = exercise_answers(exercise_);
  constexpr int kNamingStage = 3;  // the stage whose hint names the setting
  // found (named right in an answer) or named by a hint already
  auto known = [&](const FaultAnswer& a) {
    return found_.count(a.setting) > 0 || hints_by_setting_[a.setting] > kNamingStage;
  };
  const auto target =
      std::find_if(answers.begin(), answers.end(), [&](const FaultAnswer& a) { return !known(a); });
  if (target == answers.end()) {
    // every hidden setting found or named: nothing more to hint, nothing charged
    std::string named;
    for (const FaultAnswer& a : answers)
      named += (named.empty() ? "" : "; ") + setting_words(a.setting) + ", " + a.direction +
               " than its target";
    const std::string text =
        found_.size() == answers.size()
            ? std::string(
                  "Every hidden setting has been found: correct them with the sliders "
                  "and finish.")
            : "The hints have named every hidden setting: " + named + ".";
    history_.push_back({t_s, "hint", text + " (not charged)"});
    return text;
  }
  const FaultAnswer& fault = *target;
  const int stage = hints_by_setting_[fault.setting]++;
  // with two faults: "one hidden setting" until one is found or named, then "the other"
  const bool several = answers.size() > 1;
  const bool other = several && std::any_of(answers.begin(), answers.end(), [&](const auto& a) {
                       return a.setting != fault.setting && known(a);
                     });
  const std::string subject = !several ? "The hidden setting"
                              : other  ? "The other hidden setting"
                                       : "One hidden setting";
  std::string text;
  switch (stage) {
    case 0: {
      // the symptom of the setting's own measurement when it was seen: another symptom may be
      // a consequence that points at a different setting (a grand's lever height also moves
      // the hammer's rest, which reads as a hammer-blow symptom)
      const std::string own = own_observation(regulated_.kind, fault.setting);
      const auto direct = std::find_if(symptoms_seen_.begin(), symptoms_seen_.end(),
                                       [&](const Symptom& s) { return s.observation == own; });
      if (symptoms_seen_.empty())
        text =
            "Run the four tests first: the rest geometry, a slow key press, a forte blow and "
            "repeated notes; compare each number with the regulated action.";
      else if (other && direct == symptoms_seen_.end())
        text =
            "The other hidden setting's symptom is not among those seen yet: run the tests "
            "that measure the settings not yet named.";
      else
        text = std::string(other ? "For the other hidden setting, start" : "Start") +
               " from this symptom and ask which setting makes it: " +
               (direct != symptoms_seen_.end() ? direct : symptoms_seen_.begin())->text;
      break;
    }
    case 1:
      text = subject + " is measured in " + measuring_test(regulated_.kind, fault.setting) + ".";
      break;
    case 2:
      text = subject + "'s measured value is " +
             std::string(fault.direction == "more" ? "larger" : "smaller") + " than its target.";
      break;
    default:
      text = subject + " is " + setting_words(fault.setting) + " (" + fault.direction +
             " than its target)" + (several && !other ? ", and there is a second one." : ".");
  }
  ++hints_used_;
  history_.push_back({t_s, "hint", text});
  return text;
}

std::string PracticeSession::answer_heading() const {
  return exercise_.faults.size() > 1 ? "settings were" : "setting was";
}

std::string PracticeSession::answer_text() const {
  const std::vector<FaultAnswer> answers = exercise_answers(exercise_);
  std::string text;
  for (std::size_t i = 0; i < answers.size() && i < exercise_.faults.size(); ++i) {
    const double mm = exercise_.faults[i].adjuster_mm;
    text += (text.empty() ? "" : "; ") + setting_words(answers[i].setting) + " " +
            answers[i].direction + " than its target (its adjuster moved " + (mm >= 0 ? "+" : "") +
            format_fixed(mm, 2) + " mm)";
  }
  return text;
}

std::string PracticeSession::reveal(double t_s) {
  const std::string text = "The hidden " + answer_heading() + ": " + answer_text() + ".";
  if (!revealed_) history_.push_back({t_s, "reveal", text});
  revealed_ = true;
  return text;
}

void PracticeSession::move_adjuster(const std::string& setting, double delta_mm, double t_s) {
  if (regulated_.setting_index(setting) < 0)
    throw InputError("unknown setting '" + setting + "' for the " + regulated_.kind + " action");
  const double total = moved_mm(setting) + delta_mm;
  std::map<std::string, double> moves = moves_mm_;
  moves[setting] = total;
  // checks the physical range on the hidden action (throws InputError beyond it)
  ActionModel model = hidden_model(regulated_, exercise_);
  const Adjuster& a = model.adjusters[model.adjuster_index(setting)];
  with_adjuster(model, setting, a.value + total * 1e-3);
  moves_mm_ = std::move(moves);
  // one setting's steps one after another (ten 0.01 mm key presses) are one move in the
  // history, while no more than kMoveMergeSeconds pass between them
  double step_mm = delta_mm;
  if (!history_.empty() && history_.back().kind == "move" && last_moved_ == setting &&
      t_s - history_.back().t_s <= kMoveMergeSeconds) {
    step_mm += last_move_mm_;
    history_.pop_back();
  }
  // sums of 0.01 mm steps: to the micrometre (steps that undo each other leave no move)
  step_mm = std::round(step_mm * 1e3) / 1e3;
  if (step_mm == 0.0) {
    last_moved_.clear();  // nothing to continue
    return;
  }
  last_moved_ = setting;
  last_move_mm_ = step_mm;
  history_.push_back({t_s, "move",
                      setting_words(setting) + " " + (step_mm > 0 ? "+" : "") +
                          format_number(step_mm) + " mm (moved " +
                          format_number(std::round(total * 1e3) / 1e3) + " mm in all)"});
}

double PracticeSession::moved_mm(const std::string& setting) const {
  const auto it = moves_mm_.find(setting);
  return it == moves_mm_.end() ? 0.0 : it->second;
}

std::vector<std::string> PracticeSession::scored_settings() const {
  std::vector<std::string> names;
  for (const HiddenFault& f : exercise_.faults) names.push_back(f.setting);
  for (const auto& [setting, mm] : moves_mm_)
    if (std::find(names.begin(), names.end(), setting) == names.end()) names.push_back(setting);
  return names;
}

SessionScore PracticeSession::score(const std::vector<CorrectionReading>& readings, double t_s) {
  SessionScore s;
  s.readings = readings;
  s.tests_used = tests_used_;
  s.hints_used = hints_used_;
  s.time_s = t_s;
  s.diagnosed = diagnosed_;
  const double first = first_answer_ ? first_answer_->score : 0.0;
  s.diagnosis = diagnosis_marks();
  s.notes.push_back("diagnosis " + format_number(s.diagnosis) + "/50: first answer " +
                    format_number(first) + "/100, " + std::to_string(wrong_answers_after_first_) +
                    " wrong answers after it");

  double removed_sum = 0.0;
  for (const HiddenFault& f : exercise_.faults) {
    const auto r = std::find_if(readings.begin(), readings.end(),
                                [&](const CorrectionReading& c) { return c.setting == f.setting; });
    double removed = 0.0;
    std::string how = "not measurable after the correction";
    if (r != readings.end() && r->scored && r->regulated && r->corrected) {
      const double residual = std::abs(*r->corrected - *r->regulated);
      const double initial = r->hidden ? std::abs(*r->hidden - *r->regulated) : NAN;
      // the hidden deviation is the scale; when the hidden action could not be measured (no
      // escapement, no check), the setting's tolerance ×10 stands for it
      const RegulationSetting& setting = regulated_.regulation[regulated_.setting_index(f.setting)];
      const double tolerance = setting.tolerance;
      // the part of the deviation beyond the tolerance is what there was to correct: a setting
      // left as found earns nothing
      const double scale =
          std::isfinite(initial) && initial > tolerance ? initial - tolerance : 10 * tolerance;
      removed = std::clamp(1.0 - std::max(0.0, residual - tolerance) / scale, 0.0, 1.0);
      how = "off by " + reading_text(residual, setting.unit) + " after, " +
            (std::isfinite(initial) ? reading_text(initial, setting.unit)
                                    : std::string("unmeasurable")) +
            " before";
    }
    removed_sum += removed;
    s.notes.push_back(setting_words(f.setting) + ": " + format_number(100 * removed) +
                      " % corrected (" + how + ")");
  }
  s.regulation = 40.0 * removed_sum / static_cast<double>(exercise_.faults.size());
  for (const auto& [setting, mm] : moves_mm_) {
    const bool faulty = std::any_of(exercise_.faults.begin(), exercise_.faults.end(),
                                    [&](const HiddenFault& f) { return f.setting == setting; });
    if (!faulty && std::abs(mm) > 0.05) {
      s.regulation -= 5.0;
      s.notes.push_back(setting_words(setting) + " was not deregulated but was left moved " +
                        format_number(mm) + " mm (−5)");
    }
  }
  s.regulation = std::max(0.0, s.regulation);
  // what the correction left out of tolerance elsewhere: named, no marks taken (the exercise is
  // the hidden fault; a technician sets what follows it next, in the regulation order)
  std::string left_out;
  for (const CorrectionReading& r : readings) {
    if (r.scored) continue;
    const int index = regulated_.setting_index(r.setting);
    if (index < 0) continue;
    const RegulationSetting& setting = regulated_.regulation[static_cast<std::size_t>(index)];
    if (r.corrected && within_tolerance(setting, *r.corrected)) continue;
    left_out +=
        (left_out.empty() ? "" : ", ") + setting_words(r.setting) + " " +
        (r.corrected ? reading_text(*r.corrected, setting.unit) : std::string("cannot be read")) +
        " (target " + reading_text(setting.target, setting.unit) + " ± " +
        format_number(setting.tolerance) + ")";
  }
  if (!left_out.empty()) {
    s.out_of_tolerance = left_out;
    s.notes.push_back(
        "out of tolerance after the correction (no marks taken; set next, in the "
        "regulation order): " +
        left_out);
  }

  s.check_tests = check_tests_;
  const std::set<PracticeTest> distinct(tests_run_.begin(), tests_run_.end());
  const int diagnosis_tests = static_cast<int>(tests_run_.size());
  const int extra_tests = std::max(0, diagnosis_tests - static_cast<int>(all_tests().size()));
  const int slow_periods = std::max(0, static_cast<int>((t_s - 600.0) / 120.0));
  s.economy = std::max(0.0, 10.0 - extra_tests - slow_periods);
  s.notes.push_back("economy " + format_number(s.economy) + "/10: " +
                    std::to_string(diagnosis_tests) + (diagnosis_tests == 1 ? " test" : " tests") +
                    " to the diagnosis (" + std::to_string(distinct.size()) + " different), " +
                    std::to_string(check_tests_) + (check_tests_ == 1 ? " check" : " checks") +
                    " of the correction (free), " + format_number(std::round(t_s)) + " s");
  s.hint_penalty = 5.0 * hints_used_;
  if (hints_used_ > 0)
    s.notes.push_back(std::to_string(hints_used_) + (hints_used_ == 1 ? " hint" : " hints") +
                      " (−" + format_number(s.hint_penalty) + ")");
  s.total = std::clamp(s.diagnosis + s.regulation + s.economy - s.hint_penalty, 0.0, 100.0);
  history_.push_back({t_s, "score", format_number(s.total) + "/100"});
  final_score_ = s;
  return s;
}

std::vector<CorrectionReading> measure_corrections(const PracticeSession& session) {
  const ActionModel hidden = hidden_model(session.regulated(), session.exercise());
  const ActionModel corrected = session.current_model();
  std::vector<CorrectionReading> readings;
  const std::vector<std::string> scored = session.scored_settings();
  for (const std::string& setting : scored)
    readings.push_back({setting, try_read(session.regulated(), setting), try_read(hidden, setting),
                        try_read(corrected, setting)});
  // every other setting on the corrected action alone, as the regulation panel reads it
  for (const RegulationSetting& setting : corrected.regulation) {
    if (std::find(scored.begin(), scored.end(), setting.name) != scored.end()) continue;
    readings.push_back(
        {setting.name, std::nullopt, std::nullopt, try_read(corrected, setting.name), false});
  }
  return readings;
}

void write_session_csv(const std::string& path, const PracticeSession& session) {
  std::ostringstream out;
  const Exercise& e = session.exercise();
  out << "# exercise: " << e.title << "\n# action: " << e.kind << "\n";
  if (!session.trainee().empty()) out << "# trainee: " << session.trainee() << "\n";
  if (e.seed) out << "# seed: " << *e.seed << "\n";
  if (!e.source_file.empty()) out << "# file: " << e.source_file << "\n";
  // words: what the trainee read in full (a test's symptom sentences)
  out << "t_s,kind,detail,words\n";
  for (const SessionEvent& ev : session.history())
    out << format_number(ev.t_s) << "," << ev.kind << "," << csv_quoted(ev.detail) << ","
        << csv_quoted(ev.words) << "\n";
  if (const auto& s = session.final_score()) {
    for (const std::string& note : s->notes)
      out << format_number(s->time_s) << ",score_note," << csv_quoted(note) << ",\n";
    const ActionModel& regulated = session.regulated();
    for (const CorrectionReading& r : s->readings) {
      if (!r.scored) continue;  // named in the score's notes when out of tolerance
      const int index = regulated.setting_index(r.setting);
      const std::string unit = index >= 0 ? regulated.regulation[index].unit : std::string();
      auto value = [&unit](const std::optional<double>& v) {
        return v ? reading_text(*v, unit) : std::string("not measurable");
      };
      out << format_number(s->time_s) << ",reading,"
          << csv_quoted(setting_words(r.setting) + ": regulated " + value(r.regulated) +
                        ", hidden " + value(r.hidden) + ", corrected " + value(r.corrected))
          << ",\n";
    }
  }
  write_file_replacing(path, out.str());
}

}  // namespace pat

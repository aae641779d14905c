#include "practice/exercise.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "practice/neglect_ranges.h"

namespace pat {
namespace {

/// SplitMix64: a fixed, portable generator (std:: distributions differ between libraries,
/// and a seed must give the same exercise everywhere).
class SeedSequence {
 public:
  explicit SeedSequence(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  ///< [0, 1)
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t state_;
};

std::string setting_list(const ActionModel& model) {
  std::string names;
  for (const RegulationSetting& s : model.regulation) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

/// Offsets are quoted to 0.01 mm, so a seed's fault reads the same in JSON and in the window.
double rounded_mm(double mm) {
  return std::round(mm * 100.0) / 100.0;
}

/// Which of `count` settings an exercise numbered `seed` hides (the first, at level 2). Numbers
/// 1-7, 8-14, ... (on the grand's seven settings) hide each setting once, in an order shuffled
/// for each block: a class handed consecutive numbers gets different settings to find, where
/// independent draws had repeated one (seeds 1 and 3 had both hidden the lever height 0.21 mm
/// high).
std::size_t first_hidden_index(std::size_t count, std::uint64_t seed) {
  const std::uint64_t n = count;
  const std::uint64_t position = seed + n - 1;  // seed 1 opens a block
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = i;
  SeedSequence block_order(0x5EEDB10Cull ^ (position / n));
  for (std::uint64_t i = n - 1; i > 0; --i)  // Fisher-Yates, with the portable generator
    std::swap(order[i], order[block_order.index(i + 1)]);
  return order[position % n];
}

}  // namespace

Exercise generate_exercise(const ActionModel& model, const std::string& action, std::uint64_t seed,
                           int level) {
  if (level != 1 && level != 2)
    throw InputError("--level: must be 1 (one hidden setting) or 2 (two), got " +
                     std::to_string(level));
  Exercise exercise;
  exercise.action = action;
  exercise.kind = model.kind;
  exercise.level = level;
  exercise.seed = seed;
  exercise.title =
      model.kind + " action, exercise " + std::to_string(seed) + ", level " + std::to_string(level);
  SeedSequence random(seed);
  std::vector<std::string> candidates;
  for (const RegulationSetting& s : model.regulation) candidates.push_back(s.name);
  for (int i = 0; i < level; ++i) {
    const std::size_t pick =
        i == 0 ? first_hidden_index(candidates.size(), seed) : random.index(candidates.size());
    const NeglectRange& range = neglect_range(model.kind, candidates[pick]);
    const double magnitude = range.min_mm + random.uniform() * (range.max_mm - range.min_mm);
    const double coin = random.uniform();  // drawn always: a seed's later draws stay the same
    const double sign = range.only_sign != 0 ? range.only_sign : coin < 0.5 ? -1.0 : 1.0;
    exercise.faults.push_back({candidates[pick], rounded_mm(sign * magnitude)});
    candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(pick));
  }
  return exercise;
}

Exercise load_exercise(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the exercise file");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // malformed, or a number beyond a double
    throw InputError(path + ": not valid JSON (" + json_error_without_id(e) + ")");
  }
  auto fail = [&path](const std::string& field, const std::string& problem) {
    return InputError(located_message(path, field, problem));
  };
  if (!doc.is_object()) throw fail("", "the exercise must be a JSON object");
  if (!doc.contains("schema") || !doc["schema"].is_string())
    throw fail("schema", std::string("missing; expected \"") + kExerciseSchema + "\"");
  if (doc["schema"] != kExerciseSchema)
    throw fail("schema", "unsupported version '" + doc["schema"].get<std::string>() +
                             "' (this program reads " + kExerciseSchema + ")");
  for (const auto& item : doc.items())
    if (item.key() != "schema" && item.key() != "action" && item.key() != "title" &&
        item.key() != "notes" && item.key() != "faults")
      throw fail(item.key(), "unknown field (expected schema, action, title, notes, faults)");
  if (!doc.contains("action") || !doc["action"].is_string())
    throw fail("action", "missing or not a string (grand, upright or a preset path)");
  Exercise exercise;
  exercise.action = doc["action"].get<std::string>();
  exercise.source_file = path;
  for (const char* text_field : {"title", "notes"})
    if (doc.contains(text_field)) {
      if (!doc[text_field].is_string()) throw fail(text_field, "must be a string");
      (std::string(text_field) == "title" ? exercise.title : exercise.notes) =
          doc[text_field].get<std::string>();
    }
  ActionModel model;
  try {
    model = load_action(exercise.action);
  } catch (const InputError& e) {
    throw fail("action", e.what());
  }
  exercise.kind = model.kind;
  if (!doc.contains("faults") || !doc["faults"].is_array())
    throw fail("faults", "missing or not a list of {\"setting\", \"adjuster_mm\"} objects");
  const auto& faults = doc["faults"];
  if (faults.empty() || faults.size() > 2)
    throw fail("faults", "an exercise hides one or two faults, this one lists " +
                             std::to_string(faults.size()));
  std::set<std::string> seen;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const std::string where = "faults[" + std::to_string(i) + "]";
    const auto& f = faults[i];
    if (!f.is_object()) throw fail(where, "must be an object with setting and adjuster_mm");
    if (!f.contains("setting") || !f["setting"].is_string())
      throw fail(where + ".setting",
                 "missing or not a string (one of: " + setting_list(model) + ")");
    const std::string setting = f["setting"].get<std::string>();
    if (model.setting_index(setting) < 0)
      throw fail(where + ".setting", "unknown setting '" + setting + "' for the " + model.kind +
                                         " action (one of: " + setting_list(model) + ")");
    if (!seen.insert(setting).second)
      throw fail(where + ".setting", "'" + setting + "' is already hidden by an earlier fault");
    if (!f.contains("adjuster_mm") || !f["adjuster_mm"].is_number())
      throw fail(where + ".adjuster_mm",
                 "missing or not a number (mm from the regulated "
                 "position)");
    const double mm = f["adjuster_mm"].get<double>();
    if (!std::isfinite(mm) || mm == 0.0)
      throw fail(where + ".adjuster_mm",
                 "must be a non-zero offset (0 is the regulated position: nothing to find)");
    const Adjuster& adjuster = model.adjusters[model.adjuster_index(setting)];
    if (mm * 1e-3 < adjuster.min - 1e-12 || mm * 1e-3 > adjuster.max + 1e-12) {
      std::ostringstream problem;
      problem << "impossible: " << mm << " mm is outside the " << setting
              << " adjuster's physical range [" << adjuster.min * 1e3 << ", " << adjuster.max * 1e3
              << "] mm";
      throw fail(where + ".adjuster_mm", problem.str());
    }
    exercise.faults.push_back({setting, mm});
  }
  exercise.level = static_cast<int>(exercise.faults.size());
  if (exercise.title.empty()) exercise.title = path;
  return exercise;
}

std::vector<FaultAnswer> exercise_answers(const Exercise& exercise) {
  std::vector<FaultAnswer> answers;
  for (const HiddenFault& f : exercise.faults) {
    const int sense = neglect_range(exercise.kind, f.setting).sense;
    answers.push_back({f.setting, sense * f.adjuster_mm > 0.0 ? "more" : "less"});
  }
  return answers;
}

ActionModel hidden_model(const ActionModel& regulated, const Exercise& exercise) {
  ActionModel model = regulated;
  for (const HiddenFault& f : exercise.faults) {
    const Adjuster& a = model.adjusters[model.adjuster_index(f.setting)];
    model = with_adjuster(model, f.setting, a.value + f.adjuster_mm * 1e-3);
  }
  return model;
}

std::vector<FaultAnswer> parse_answers(const ActionModel& model, const std::string& text) {
  std::vector<FaultAnswer> answers;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos)
      throw InputError("--answer: '" + item + "' must be SETTING:DIRECTION (e.g. let_off:less)");
    FaultAnswer a{item.substr(0, colon), item.substr(colon + 1)};
    if (model.setting_index(a.setting) < 0)
      throw InputError("--answer: unknown setting '" + a.setting + "' for the " + model.kind +
                       " action (one of: " + setting_list(model) + ")");
    if (a.direction != "more" && a.direction != "less")
      throw InputError("--answer: direction '" + a.direction +
                       "' must be 'more' or 'less' (of the measured value relative to its "
                       "target)");
    answers.push_back(a);
  }
  if (answers.empty()) throw InputError("--answer: empty (expected SETTING:DIRECTION)");
  return answers;
}

AnswerJudgement judge_answers(const Exercise& exercise, const std::vector<FaultAnswer>& given) {
  const std::vector<FaultAnswer> expected = exercise_answers(exercise);
  const double per_fault = 100.0 / static_cast<double>(expected.size());
  AnswerJudgement judgement;
  int right = 0;
  std::set<std::string> named;
  for (const FaultAnswer& a : given) {
    if (!named.insert(a.setting).second) {
      judgement.remarks.push_back(setting_words(a.setting) + ": named twice");
      judgement.score -= per_fault;
      continue;
    }
    const auto match = std::find_if(expected.begin(), expected.end(),
                                    [&](const FaultAnswer& e) { return e.setting == a.setting; });
    if (match == expected.end()) {
      // its reading may well be off: another setting's adjuster can move it along
      judgement.remarks.push_back(setting_words(a.setting) +
                                  ": its adjuster was not moved (a reading can be off because "
                                  "another setting moves it)");
      judgement.score -= per_fault;
    } else if (match->direction == a.direction) {
      judgement.remarks.push_back(setting_words(a.setting) + ": right setting, right direction");
      judgement.score += per_fault;
      ++right;
    } else {
      judgement.remarks.push_back(setting_words(a.setting) + ": right setting, wrong direction");
      judgement.score += 0.4 * per_fault;
    }
  }
  judgement.score = std::clamp(judgement.score, 0.0, 100.0);
  judgement.correct = right == static_cast<int>(expected.size()) && given.size() == expected.size();
  return judgement;
}

}  // namespace pat

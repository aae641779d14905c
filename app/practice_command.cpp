// pianoaction practice: virtual deregulation exercises (issue 7).
//   practice new   --action A (--seed N | --exercise FILE) [--level 1|2] [--reveal] [--json]
//   practice check --action A (--seed N | --exercise FILE) [--level 1|2] --answer S:D[,S:D]
//                  [--reveal] [--json]
// `new` simulates the technician's tests on the hidden and the regulated action and prints the
// symptoms; `check` judges a diagnosis from the exercise alone (no simulation).
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "command_line.h"
#include "commands.h"
#include "core/error.h"
#include "model/preset_loader.h"
#include "plot_output.h"
#include "practice/exercise.h"
#include "practice/observations.h"
#include "practice/symptoms.h"

namespace pat::app {
namespace {

/// An exercise file given by path, or by name in presets/exercises/.
std::string exercise_path(const std::string& given) {
  if (std::filesystem::exists(given)) return given;
  const std::string shipped =
      preset_directory() + "/exercises/" + given + (given.ends_with(".json") ? "" : ".json");
  return std::filesystem::exists(shipped) ? shipped : given;
}

std::uint64_t parse_seed(const std::string& text) {
  std::size_t used = 0;
  unsigned long long seed = 0;
  try {
    seed = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || text[0] == '-')
    throw InputError("--seed: '" + text + "' is not a non-negative whole number");
  return seed;
}

struct LoadedExercise {
  ActionModel model;  ///< the regulated action
  Exercise exercise;
};

LoadedExercise exercise_from(const CommandLine& cl) {
  if (cl.has("--seed") == cl.has("--exercise"))
    throw InputError("give either --seed N or --exercise FILE");
  if (cl.has("--exercise")) {
    if (cl.has("--level"))
      throw InputError("--level: an exercise file sets its own level (its number of faults)");
    Exercise exercise = load_exercise(exercise_path(cl.value("--exercise")));
    ActionModel model = load_action(exercise.action);
    if (cl.has("--action") && load_action(cl.value("--action")).kind != model.kind)
      throw InputError("--action: " + cl.value("--action") + " is not the " + model.kind +
                       " action the exercise file " + exercise.source_file + " is made for");
    return {std::move(model), std::move(exercise)};
  }
  const std::string action = cl.value("--action");
  ActionModel model = load_action(action);
  const std::string level_text = cl.value_or("--level", "1");
  if (level_text != "1" && level_text != "2")
    throw InputError("--level: must be 1 or 2, got '" + level_text + "'");
  Exercise exercise =
      generate_exercise(model, action, parse_seed(cl.value("--seed")), std::stoi(level_text));
  return {std::move(model), std::move(exercise)};
}

nlohmann::json value_or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json exercise_header(const Exercise& e) {
  nlohmann::json out{{"action", e.kind}, {"level", e.level}, {"title", e.title}};
  out["seed"] = e.seed ? nlohmann::json(*e.seed) : nlohmann::json(nullptr);
  if (!e.source_file.empty()) out["exercise_file"] = e.source_file;
  if (!e.notes.empty()) out["notes"] = e.notes;
  return out;
}

/// --reveal in text: one "answer: SETTING:DIRECTION" line per hidden fault.
void print_answers(const std::vector<FaultAnswer>& answers) {
  for (const FaultAnswer& a : answers)
    std::cout << "answer: " << a.setting << ":" << a.direction << "\n";
}

nlohmann::json answer_json(const FaultAnswer& a) {
  return {{"setting", a.setting}, {"direction", a.direction}};
}

/// How far each observation of the exercise's action is from the regulated action's, one plot
/// per unit (a teacher's chart of what the tests show); observations named by their short id.
std::vector<PlotSpec> observation_plots(const std::vector<Observation>& seen,
                                        const std::vector<Observation>& regulated_seen) {
  std::map<std::string, PlotSpec> by_unit;
  for (const Observation& o : seen) {
    const Observation* reg = find_observation(regulated_seen, o.id);
    const std::string unit = o.unit.empty() ? "count" : o.unit;
    PlotSpec& plot = by_unit[unit];
    if (plot.curves.empty()) {
      plot = category_plot("Observed minus regulated (" + unit + ")", "difference (" + unit + ")",
                           "observation", "observation_index");
      plot.curves = {point_curve("this action − regulated", "difference")};
    }
    const double x = double(plot.x_categories.size());
    plot.x_categories.push_back(o.id.substr(o.id.find('.') + 1));
    if (!o.value || !reg || !reg->value) continue;  // not observed (the text says why)
    plot.curves[0].add(x, *o.value - *reg->value);
  }
  std::vector<PlotSpec> plots;
  for (auto& [unit, plot] : by_unit) add_plot(plots, std::move(plot));
  return plots;
}

int run_new(const CommandLine& cl) {
  const LoadedExercise loaded = exercise_from(cl);
  const PlotOption plot(cl);
  const ActionModel hidden = hidden_model(loaded.model, loaded.exercise);
  std::vector<Observation> regulated_seen, seen;
  try {
    regulated_seen = run_all_tests(loaded.model);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the regulated " + loaded.model.kind +
                             " action cannot be observed: " + e.what());
  }
  try {
    seen = run_all_tests(hidden);
  } catch (const std::runtime_error& e) {
    // the hidden action does not even come to rest: an impossible exercise
    throw InputError(
        (loaded.exercise.source_file.empty() ? "this seed" : loaded.exercise.source_file) +
        ": impossible exercise, the deregulated action cannot be observed (" + e.what() + ")");
  }
  const std::vector<Symptom> symptoms = describe_symptoms(seen, regulated_seen);
  const std::vector<FaultAnswer> answers = exercise_answers(loaded.exercise);
  plot.write(observation_plots(seen, regulated_seen), !cl.has("--json"));

  if (cl.has("--json")) {
    nlohmann::json out = exercise_header(loaded.exercise);
    nlohmann::json symptom_list = nlohmann::json::array();
    for (const Symptom& s : symptoms)
      symptom_list.push_back({{"id", s.id}, {"text", s.text}, {"observation", s.observation}});
    nlohmann::json observations = nlohmann::json::array();
    for (const Observation& o : seen) {
      const Observation* reg = find_observation(regulated_seen, o.id);
      nlohmann::json item{{"id", o.id},
                          {"label", o.label},
                          {"unit", o.unit},
                          {"value", value_or_null(o.value)},
                          {"regulated_value", reg ? value_or_null(reg->value) : nullptr}};
      if (!o.value) item["missing_reason"] = o.missing_reason;
      observations.push_back(item);
    }
    out["symptoms"] = symptom_list;
    out["observations"] = observations;
    if (cl.has("--reveal")) {
      out["answer"] = answer_json(answers.front());
      nlohmann::json all = nlohmann::json::array(), faults = nlohmann::json::array();
      for (const FaultAnswer& a : answers) all.push_back(answer_json(a));
      for (const HiddenFault& f : loaded.exercise.faults)
        faults.push_back({{"setting", f.setting}, {"adjuster_mm", f.adjuster_mm}});
      out["answers"] = all;
      out["faults"] = faults;
    }
    std::cout << out.dump(1) << "\n";
    return 0;
  }
  std::cout << loaded.exercise.title << "\n";
  if (symptoms.empty()) std::cout << "  no symptom differs from the regulated action\n";
  for (const Symptom& s : symptoms) std::cout << "  - " << s.text << "\n";
  if (cl.has("--reveal")) print_answers(answers);
  return 0;
}

int run_check(const CommandLine& cl) {
  const LoadedExercise loaded = exercise_from(cl);
  const AnswerJudgement judgement =
      judge_answers(loaded.exercise, parse_answers(loaded.model, cl.value("--answer")));
  if (cl.has("--json")) {
    nlohmann::json out = exercise_header(loaded.exercise);
    out["correct"] = judgement.correct;
    out["score"] = judgement.score;
    out["remarks"] = judgement.remarks;
    if (cl.has("--reveal")) {  // for a teacher: the exercise's answer, without any simulation
      nlohmann::json all = nlohmann::json::array();
      for (const FaultAnswer& a : exercise_answers(loaded.exercise)) all.push_back(answer_json(a));
      out["answer"] = all.front();
      out["answers"] = all;
    }
    std::cout << out.dump(1) << "\n";
  } else {
    std::cout << (judgement.correct ? "correct" : "not correct") << ", score " << judgement.score
              << "\n";
    for (const std::string& r : judgement.remarks) std::cout << "  " << r << "\n";
    if (cl.has("--reveal")) print_answers(exercise_answers(loaded.exercise));
  }
  return 0;
}

}  // namespace

int run_practice(const std::vector<std::string>& args) {
  if (args.empty() || (args[0] != "new" && args[0] != "check"))
    throw InputError("practice: expected 'new' or 'check' (practice new --action A --seed N)");
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "new")
    return run_new(CommandLine(rest, {"--action", "--seed", "--level", "--exercise", "--plot"},
                               {"--reveal", "--json"}));
  return run_check(CommandLine(rest, {"--action", "--seed", "--level", "--exercise", "--answer"},
                               {"--reveal", "--json"}));
}

}  // namespace pat::app

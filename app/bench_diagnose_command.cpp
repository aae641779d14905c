// pianoaction bench-diagnose: the full hidden-effect matrix of issue 6 (every family, several
// seeds, the whole candidate library; plus null cases) with the wall time of each diagnosis.
// Too slow for the test suite, which runs a reduced set (tests/engine/diagnosis_test.cpp).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "commands.h"
#include "measured/hidden_effects.h"
#include "model/preset_loader.h"

namespace pat::app {

int run_bench_diagnose(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--action", "--seeds", "--null-seeds", "--family", "--threads"},
                       {"--json"});
  const ActionModel model = load_action(cl.value_or("--action", "grand"));
  const int seeds = static_cast<int>(cl.positive_number_or("--seeds", 3));
  const int null_seeds = static_cast<int>(cl.positive_number_or("--null-seeds", 3));
  const std::vector<std::string> only = cl.values("--family");
  nlohmann::json cases = nlohmann::json::array();
  int passed = 0, total = 0;
  auto record = [&](const HiddenEffectOutcome& o, unsigned long long seed) {
    ++total;
    passed += o.passed ? 1 : 0;
    const Diagnosis& d = o.diagnosis;
    nlohmann::json item{
        {"hidden", o.hidden ? nlohmann::json(o.hidden->name) : nlohmann::json(nullptr)},
        {"hidden_value", o.hidden ? nlohmann::json(o.hidden->value) : nlohmann::json(nullptr)},
        {"seed", seed},
        {"cause", d.cause ? nlohmann::json(d.cause->name) : nlohmann::json(nullptr)},
        {"cause_value", d.cause ? nlohmann::json(d.cause->value) : nlohmann::json(nullptr)},
        {"value_error", o.value_error},
        {"baseline_rms_deg", d.baseline_rms_deg},
        {"extended_rms_deg", d.extended_rms_deg},
        {"gain", d.gain},
        {"runner_up", d.ranking.size() > 1 ? d.ranking[1].effect : ""},
        {"passed", o.passed},
        {"simulations", d.simulations},
        {"wall_time_s", d.wall_time_s}};
    cases.push_back(item);
    if (!cl.has("--json"))
      std::cout << (o.hidden ? o.hidden->name + "=" + std::to_string(o.hidden->value)
                             : std::string("nothing hidden"))
                << " seed " << seed << ": cause "
                << (d.cause ? d.cause->name + "=" + std::to_string(d.cause->value)
                            : std::string("null"))
                << ", gain " << d.gain * 100 << " %, " << (o.passed ? "PASS" : "FAIL") << " ("
                << d.wall_time_s << " s, " << d.simulations << " simulations)" << std::endl;
  };
  for (const HiddenEffectRange& range : hidden_effect_ranges(model)) {
    if (!only.empty() && std::find(only.begin(), only.end(), range.effect) == only.end()) continue;
    for (int s = 1; s <= seeds; ++s) {
      const Effect hidden{range.effect, hidden_value(range, static_cast<unsigned long long>(s))};
      record(run_hidden_effect_case(model, hidden, static_cast<unsigned long long>(s)),
             static_cast<unsigned long long>(s));
    }
  }
  if (only.empty())
    for (int s = 1; s <= null_seeds; ++s)
      record(run_hidden_effect_case(model, std::nullopt, static_cast<unsigned long long>(100 + s)),
             static_cast<unsigned long long>(100 + s));
  if (cl.has("--json"))
    std::cout << nlohmann::json{{"cases", cases}, {"passed", passed}, {"total", total}}.dump(1)
              << "\n";
  else
    std::cout << passed << " of " << total << " cases passed\n";
  return passed == total ? 0 : 1;
}

}  // namespace pat::app

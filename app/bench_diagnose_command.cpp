// pianoaction bench-diagnose: the full hidden-effect matrix of issue 6 (every family, several
// seeds, the whole candidate library; plus null cases) with the wall time of each diagnosis.
// Too slow for the test suite, which runs a reduced set (tests/engine/diagnosis_test.cpp).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "measured/hidden_effects.h"
#include "model/preset_loader.h"
#include "plot_output.h"

namespace pat::app {

int run_bench_diagnose(const std::vector<std::string>& args) {
  const CommandLine cl(
      args, {"--action", "--seeds", "--null-seeds", "--family", "--threads", "--plot"}, {"--json"});
  const ActionModel model = load_action(cl.value_or("--action", "grand"));
  const int seeds = cl.whole_number_or("--seeds", 1000, 3);
  const int null_seeds = cl.whole_number_or("--null-seeds", 1000, 3);
  const std::vector<std::string> only = cl.values("--family");
  if (!only.empty() && cl.has("--null-seeds"))
    throw InputError(
        "--null-seeds with --family: the null cases (nothing hidden) run only with the whole "
        "library, without --family; give one or the other");
  const std::vector<HiddenEffectRange> ranges = hidden_effect_ranges(model);
  for (const std::string& family : only)
    if (std::none_of(ranges.begin(), ranges.end(),
                     [&](const HiddenEffectRange& r) { return r.effect == family; })) {
      std::string known;
      for (const HiddenEffectRange& r : ranges) known += (known.empty() ? "" : ", ") + r.effect;
      throw InputError("--family " + family + ": not a family of the " + model.kind +
                       "'s candidate library (" + known + ")");
    }
  const unsigned threads = static_cast<unsigned>(cl.whole_number_or("--threads", 256, 0));
  const PlotOption plot(cl);
  nlohmann::json cases = nlohmann::json::array();
  // per case: the gain of the found cause (passed and failed cases apart) and the wall time
  PlotSpec gains =
      category_plot("Diagnosis of hidden effects: gain", "gain (%)", "case", "case_index");
  PlotSpec times = category_plot("Diagnosis of hidden effects: wall time", "wall time (s)", "case",
                                 "case_index");
  PlotCurve passed_gain = point_curve("passed", "gain_percent");
  PlotCurve failed_gain = point_curve("failed", "gain_percent");
  PlotCurve wall = point_curve("wall time", "wall_time_s");
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
    const double x = double(gains.x_categories.size());
    gains.x_categories.push_back((o.hidden ? o.hidden->name : std::string("nothing hidden")) +
                                 " #" + std::to_string(seed));
    PlotCurve& gain = o.passed ? passed_gain : failed_gain;
    gain.add(x, 100.0 * d.gain);
    wall.add(x, d.wall_time_s);
    if (!cl.has("--json"))
      std::cout << (o.hidden ? o.hidden->name + "=" + std::to_string(o.hidden->value)
                             : std::string("nothing hidden"))
                << " seed " << seed << ": cause "
                << (d.cause ? d.cause->name + "=" + std::to_string(d.cause->value)
                            : std::string("null"))
                << ", gain " << d.gain * 100 << " %, " << (o.passed ? "PASS" : "FAIL") << " ("
                << d.wall_time_s << " s, " << d.simulations << " simulations)" << std::endl;
  };
  for (const HiddenEffectRange& range : ranges) {
    if (!only.empty() && std::find(only.begin(), only.end(), range.effect) == only.end()) continue;
    for (int s = 1; s <= seeds; ++s) {
      const Effect hidden{range.effect, hidden_value(range, static_cast<unsigned long long>(s))};
      record(run_hidden_effect_case(model, hidden, static_cast<unsigned long long>(s), {}, threads),
             static_cast<unsigned long long>(s));
    }
  }
  if (only.empty())
    for (int s = 1; s <= null_seeds; ++s)
      record(run_hidden_effect_case(model, std::nullopt, static_cast<unsigned long long>(100 + s),
                                    {}, threads),
             static_cast<unsigned long long>(100 + s));
  times.x_categories = gains.x_categories;
  gains.curves = {std::move(passed_gain), std::move(failed_gain)};
  times.curves = {std::move(wall)};
  plot.write({gains, times}, !cl.has("--json"));
  if (cl.has("--json"))
    std::cout << nlohmann::json{{"cases", cases}, {"passed", passed}, {"total", total}}.dump(1)
              << "\n";
  else
    std::cout << passed << " of " << total << " cases passed\n";
  return passed == total ? 0 : 1;
}

}  // namespace pat::app

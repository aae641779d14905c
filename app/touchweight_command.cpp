// pianoaction touchweight: static downweight and upweight at the key front (Stanwood; fact F9).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "analysis/touchweight.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "model/model_variations.h"
#include "plot_output.h"

namespace pat::app {

int run_touchweight(const std::vector<std::string>& args) {
  const CommandLine cl(
      args,
      {"--action", "--set", "--without", "--out", "--spring-factor", "--key-lead-g", "--plot"},
      {"--json"});
  // a spring's factors would multiply (2 and 3 gave what 6 gives): one each
  refuse_repeated_names("--spring-factor", cl.values("--spring-factor"));
  ActionModel model = load_configured_action(cl);
  for (const std::string& assignment : cl.values("--spring-factor")) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--spring-factor " + assignment + ": expected SPRING=FACTOR");
    model = with_spring_factor(
        model, assignment.substr(0, eq),
        parse_number(assignment.substr(eq + 1), "--spring-factor " + assignment));
  }
  if (cl.has("--key-lead-g"))
    model = with_key_front_lead(model, parse_number(cl.value("--key-lead-g"), "--key-lead-g"));
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const TouchweightResult result = measure_touchweight(model);
  plot.write({table_plot(result.table(), "Weights at the key front", "weight (g)",
                         {{"downweight_g", "downweight"},
                          {"upweight_g", "upweight"},
                          {"balance_weight_g", "balance weight"},
                          {"friction_weight_g", "friction weight"}},
                         "dip_mm", "key dip (mm)", "mm")},
             !cl.has("--json"));
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  write_analysis_csv(out_path, result.table(), model,
                     "quasi-static touchweight at the key front (Coulomb friction)", cl);
  if (cl.has("--json")) {
    nlohmann::json out{{"downweight_g", result.downweight_g},
                       {"upweight_g", result.upweight_g},
                       {"balance_weight_g", result.balance_weight_g},
                       {"friction_weight_g", result.friction_weight_g},
                       {"key_ratio", result.key_ratio},
                       {"strike_weight_g", result.strike_weight_g},
                       {"front_weight_g", result.front_weight_g},
                       {"key_sinks_mm", result.key_sinks_mm},
                       {"action", model.kind}};
    std::cout << out.dump(1) << "\n";
  } else {
    // grams to 0.1 g, as a technician's weights read
    auto grams = [](double g) { return format_fixed(g, 1) + " g"; };
    std::cout << model.name << ": static touchweight\n  downweight " << grams(result.downweight_g)
              << ", upweight " << grams(result.upweight_g) << ", balance weight "
              << grams(result.balance_weight_g) << ", friction weight "
              << grams(result.friction_weight_g) << "\n  key ratio "
              << format_fixed(result.key_ratio, 3) << ", strike weight "
              << grams(result.strike_weight_g) << ", front weight " << grams(result.front_weight_g)
              << "\n";
    if (const std::string note = key_rest_note(result); !note.empty())
      std::cout << "  " << note << "\n";
  }
  return 0;
}

}  // namespace pat::app

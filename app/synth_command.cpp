// pianoaction synth: measured-like data from the model with effects hidden in it (DESIGN.md
// sections 4 and 5).
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "io/csv.h"
#include "measured/synth.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "plot_output.h"

namespace pat::app {
namespace {

/// Refuses to write synthetic data over a file whose metadata says it holds real measured data
/// (import-raw writes '# source:'): nothing real is ever replaced by a synthesised trace.
void refuse_real_data(const std::string& out_path) {
  std::ifstream existing(out_path);
  std::string line;
  while (std::getline(existing, line) && !line.empty() && line.front() == '#')
    if (line.rfind("# source:", 0) == 0)
      throw InputError("--out " + out_path + ": the file holds real measured data (" +
                       line.substr(2) + "); synth does not overwrite it: choose another file name");
}

}  // namespace

int run_synth(const std::vector<std::string>& args) {
  const CommandLine cl(
      args,
      {"--action", "--input", "--duration", "--effect", "--noise-deg", "--fps", "--time-offset-ms",
       "--angle-offset-deg", "--seed", "--set", "--out", "--plot"},
      {"--json"});
  const std::string out_path = cl.output_path("--out", true);
  refuse_real_data(out_path);
  refuse_repeated_names("--set", cl.values("--set"));
  refuse_repeated_names("--effect", cl.values("--effect"));
  // --set adjusts the base model; the effects go into SynthOptions so that they are recorded
  ActionModel model = load_action(cl.value("--action"));
  for (const std::string& assignment : cl.values("--set")) model = with_setting(model, assignment);
  SynthOptions o;
  o.duration_s = cl.positive_number("--duration");
  for (const std::string& e : cl.values("--effect")) o.effects.push_back(parse_effect(e));
  o.noise_deg = cl.has("--noise-deg") ? parse_number(cl.value("--noise-deg"), "--noise-deg") : 0;
  o.fps = cl.positive_number_or("--fps", 2000.0);
  o.time_offset_s = cl.has("--time-offset-ms")
                        ? parse_number(cl.value("--time-offset-ms"), "--time-offset-ms") * 1e-3
                        : 0.0;
  o.angle_offset_deg = cl.has("--angle-offset-deg")
                           ? parse_number(cl.value("--angle-offset-deg"), "--angle-offset-deg")
                           : 0.0;
  if (cl.has("--seed")) {
    const double seed = parse_number(cl.value("--seed"), "--seed");
    if (seed < 0 || seed != static_cast<double>(static_cast<unsigned long long>(seed)))
      throw InputError("--seed must be a whole number ≥ 0");
    o.seed = static_cast<unsigned long long>(seed);
  }
  const PlotOption plot(cl);
  const CsvTable table = synthesize(model, cl.value("--input"), o);
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write({table_plot(table, "Synthetic measurement", "angle (deg)",
                         {{"hammer_angle_deg", "hammer"}, {"key_angle_deg", "key"}})},
             !cl.has("--json"));
  write_csv(out_path, table);
  if (cl.has("--json"))
    std::cout << nlohmann::json{{"out", out_path},
                                {"samples", table.rows.size()},
                                {"effects", table.metadata.at("synth_effects")}}
                     .dump(1)
              << "\n";
  else
    std::cout << table.rows.size() << " samples written to " << out_path
              << " (effects: " << table.metadata.at("synth_effects") << ")\n";
  return 0;
}

}  // namespace pat::app

// pianoaction diagnose: what the model gets wrong on measured data, the cause among the
// candidate extensions, and the gain (DESIGN.md sections 4 and 5).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "measured/diagnosis.h"
#include "measured/diagnosis_report.h"

namespace pat::app {

int run_diagnose(const std::vector<std::string>& args) {
  const CommandLine cl(args,
                       {"--action", "--measured", "--report", "--candidate", "--threads", "--set"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl);
  std::vector<MeasuredTrial> trials;
  for (const std::string& path : cl.values("--measured"))
    trials.push_back(read_measured(path, model.kind));
  if (trials.empty())
    throw InputError("missing option --measured (one or more measured CSV files)");
  DiagnoseOptions options;
  options.candidates = cl.values("--candidate");
  if (cl.has("--threads")) options.threads = static_cast<unsigned>(cl.positive_number("--threads"));
  const std::string report = cl.value_or("--report", "");
  const Diagnosis d = diagnose(model, trials, options);
  const nlohmann::json json = diagnosis_json(d);
  if (!report.empty()) {
    try {
      write_diagnosis_report(report, d);
    } catch (const InputError& e) {
      throw InputError(std::string("--report ") + e.what());
    }
  }
  if (cl.has("--json")) {
    std::cout << json.dump(1) << "\n";
    return 0;
  }
  std::cout << "diagnosis of " << trials.size() << " measured file(s) on the " << model.kind
            << " action (noise " << d.noise_deg << " deg)\n";
  std::cout << "what the model gets wrong:\n";
  for (std::size_t i = 0; i < d.discrepancies.size() && i < 12; ++i)
    std::cout << "  " << d.discrepancies[i] << "\n";
  std::cout << "ranking (" << (d.held_out ? "held-out" : "training, a single trial") << " rms):\n";
  for (const CandidateFit& c : d.ranking)
    std::cout << "  " << c.effect << " = " << c.value << " " << c.unit << ": "
              << c.validated_rms_deg << " deg" << (c.completed ? "" : " (" + c.note + ")") << "\n";
  if (d.cause)
    std::cout << "cause: " << d.cause->name << " = " << d.cause->value << " " << d.cause_unit
              << "\n";
  else
    std::cout << "cause: none beyond the noise\n";
  std::cout << "baseline " << d.baseline_rms_deg << " deg, extended " << d.extended_rms_deg
            << " deg, gain " << d.gain * 100 << " %  (" << d.simulations << " simulations, "
            << d.wall_time_s << " s)\n";
  if (!report.empty()) std::cout << "report written to " << report << "\n";
  return 0;
}

}  // namespace pat::app

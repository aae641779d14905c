// pianoaction diagnose: what the model gets wrong on measured data, the cause among the
// candidate extensions, and the gain (DESIGN.md sections 4 and 5).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "measured/diagnosis.h"
#include "measured/diagnosis_report.h"
#include "plot_output.h"

namespace pat::app {
namespace {

/// Per trial: the measured hammer against the baseline and the extended model, and their
/// residuals; then the candidate causes ranked by their held-out error.
std::vector<PlotSpec> diagnosis_plots(const Diagnosis& d) {
  std::vector<PlotSpec> plots;
  const std::string extended = d.cause ? "with " + d.cause->name : "extended model";
  for (const TrialReport& trial : d.trials) {
    const CsvTable traces = trial_traces_table(trial);
    const std::string file = std::filesystem::path(trial.path).filename().string();
    PlotSpec angles =
        table_plot(traces, "Measured and simulated hammer: " + file, "hammer angle (deg)",
                   {{"measured_deg", "measured"}, {"baseline_deg", "baseline model"}});
    PlotSpec residuals = table_plot(traces, "Residuals: " + file, "measured − model (deg)",
                                    {{"residual_baseline_deg", "baseline model"}});
    residuals.curves.front().colour = 1;  // each model in the colour it has above
    if (traces.column_index("extended_deg") >= 0) {
      PlotCurve model = line_curve(extended, "extended_deg");
      model.x = traces.column("time_s");
      model.y = traces.column("extended_deg");
      model.colour = 2;  // as it would be third in the residuals too
      angles.curves.push_back(model);
      model.column = "residual_extended_deg";
      model.y = traces.column("residual_extended_deg");
      residuals.curves.push_back(std::move(model));
    }
    add_plot(plots, std::move(angles));
    add_plot(plots, std::move(residuals));
  }
  // a short y title: the candidates' names below the axis leave it little height
  PlotSpec ranking = category_plot(
      std::string("Candidate causes (") + (d.held_out ? "held-out" : "training") + " error)",
      "rms error (deg)", "candidate", "candidate_index");
  PlotCurve rms =
      point_curve("fitted candidate", d.held_out ? "validated_rms_deg" : "training_rms_deg");
  for (const CandidateFit& c : d.ranking) {
    const double error = d.held_out ? c.validated_rms_deg : c.training_rms_deg;
    if (!c.completed || !std::isfinite(error)) continue;
    rms.add(double(ranking.x_categories.size()), error);
    ranking.x_categories.push_back(c.effect);
  }
  // the baseline error as a flat line across the candidates, for scale
  PlotCurve baseline = line_curve("baseline model", "baseline_rms_deg");
  if (!rms.x.empty()) {
    baseline.x = {-0.5, double(ranking.x_categories.size()) - 0.5};
    baseline.y = {d.baseline_rms_deg, d.baseline_rms_deg};
  }
  ranking.curves = {std::move(rms), std::move(baseline)};
  add_plot(plots, std::move(ranking));
  return plots;
}

/// --report names a folder (made if missing) in a folder that exists; checked before the run.
void check_report_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw InputError("--report: empty folder name");
  std::error_code ec;
  fs::path path(dir);
  if (!path.has_filename()) path = path.parent_path();  // "report/" names the folder "report"
  if (fs::exists(path, ec) && !fs::is_directory(path, ec))
    throw InputError("--report " + dir + ": it is a file, not a folder");
  const fs::path parent = path.parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw InputError("--report " + dir + ": the folder '" + parent.string() + "' does not exist");
}

}  // namespace

int run_diagnose(const std::vector<std::string>& args) {
  const CommandLine cl(
      args, {"--action", "--measured", "--report", "--candidate", "--threads", "--set", "--plot"},
      {"--json"}, {"--measured"});
  const ActionModel model = load_configured_action(cl);
  std::vector<MeasuredTrial> trials;
  std::set<std::filesystem::path> seen;
  for (const std::string& path : cl.values("--measured")) {
    // a file given twice would count as its own held-out validation
    if (!seen.insert(std::filesystem::weakly_canonical(path)).second)
      throw InputError("--measured: " + path +
                       " is given twice (each trial must be another "
                       "measurement: the others validate the fit on it)");
    trials.push_back(read_measured(path, model.kind));
  }
  if (trials.empty())
    throw InputError("missing option --measured (one or more measured CSV files)");
  DiagnoseOptions options;
  options.candidates = cl.values("--candidate");
  refuse_repeated_names("--candidate", options.candidates);  // each candidate is fitted once
  if (cl.has("--threads"))
    options.threads = static_cast<unsigned>(cl.whole_number_or("--threads", 256, 0));
  const std::string report = cl.value_or("--report", "");
  if (cl.has("--report")) check_report_folder(report);
  const PlotOption plot(cl);
  const Diagnosis d = diagnose(model, trials, options);
  const nlohmann::json json = diagnosis_json(d);
  if (!report.empty()) {
    try {
      write_diagnosis_report(report, d);
      // and the plots, as the window's Export report writes them
      if (plotting_available())
        write_plots((std::filesystem::path(report) / "diagnosis.png").string(), diagnosis_plots(d));
    } catch (const InputError& e) {
      throw InputError(std::string("--report ") + e.what());
    }
  }
  plot.write(diagnosis_plots(d));
  if (cl.has("--json")) {
    std::cout << json.dump(1) << "\n";
    return 0;
  }
  std::cout << "diagnosis of " << trials.size() << " measured file(s) on the " << model.kind
            << " action (noise " << d.noise_deg << " deg)\n";
  std::cout << "what the model gets wrong:\n";
  for (std::size_t i = 0; i < d.discrepancies.size() && i < 12; ++i)
    std::cout << "  " << d.discrepancies[i] << "\n";
  std::cout << (d.held_out ? "ranking (by the held-out error, each trial under the fit made "
                             "without it; first the rms fitted on every trial):\n"
                           : "ranking (by the rms fitted on the one trial: nothing can be held "
                             "out):\n");
  for (const CandidateFit& c : d.ranking) {
    std::cout << "  " << c.effect << " = " << c.value << " " << c.unit << ": " << c.training_rms_deg
              << " deg";
    if (std::isfinite(c.validated_rms_deg))
      std::cout << ", held-out " << c.validated_rms_deg << " deg";
    else if (d.held_out)
      std::cout << ", not validated";
    if (!c.note.empty()) std::cout << " (" << c.note << ")";
    std::cout << "\n";
  }
  if (d.cause)
    std::cout << "cause: " << d.cause->name << " = " << d.cause->value << " " << d.cause_unit
              << "\n";
  else
    std::cout << "cause: none, " << d.verdict << "\n";
  std::cout << "baseline " << d.baseline_rms_deg << " deg, extended " << d.extended_rms_deg
            << " deg, gain " << d.gain * 100 << " %, measured on " << d.gain_basis << "  ("
            << d.simulations << " simulations, " << d.wall_time_s << " s)\n";
  for (const TrialReport& r : d.trials)
    if (!r.held_out_effect.empty())
      std::cout << "  held out " << r.path << ": " << r.held_out_rms_deg << " deg under "
                << r.held_out_effect << " = " << r.held_out_value << " " << r.held_out_unit
                << " fitted on the other trials\n";
  if (!report.empty()) std::cout << "report written to " << report << "\n";
  if (plot.given()) std::cout << "plot written to " << plot.path() << "\n";
  return 0;
}

}  // namespace pat::app

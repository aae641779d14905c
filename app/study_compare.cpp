// pianoaction study compare: upright vs grand under the same input (analysis/action_comparison.h).
#include <iostream>
#include <nlohmann/json.hpp>

#include "analysis/action_comparison.h"
#include "analysis/paper_repetition.h"
#include "command_line.h"
#include "commands.h"
#include "core/format.h"
#include "model/preset_loader.h"
#include "plot_output.h"
#include "sweep_report.h"

namespace pat::app {
namespace {

nlohmann::json limit_json(const std::optional<SweepResult>& sweep) {
  if (!sweep) return nullptr;
  return {
      {"max_frequency_hz", sweep->max_frequency_hz ? nlohmann::json(*sweep->max_frequency_hz)
                                                   : nlohmann::json(nullptr)},
      {"limit_found", sweep->limit_found},
      {"first_failure_kind", sweep->first_failure
                                 ? nlohmann::json(outcome_name(sweep->first_failure->outcome))
                                 : nlohmann::json(nullptr)},
      {"first_failure_hz", sweep->first_failure ? nlohmann::json(sweep->first_failure->frequency_hz)
                                                : nlohmann::json(nullptr)},
      // the same object as sweep's, so that one script reads both
      {"first_failure",
       sweep->first_failure ? cycle_json(*sweep->first_failure) : nlohmann::json(nullptr)},
      // and a run that stopped, as sweep gives it (it had been left out: a null maximum with
      // limit_found true then read as a failure at once)
      {"run_status", sweep_run_status(*sweep)},
      {"stop_cause", sweep_run_status(*sweep) == "ok" ? nlohmann::json(nullptr)
                                                      : nlohmann::json(sweep_stop_cause(*sweep))}};
}

/// The overlaid motions, gaps and touch of both actions under the common input, then their
/// repetition limits side by side (when the sweeps ran).
std::vector<PlotSpec> comparison_plots(const ComparisonResult& result) {
  std::vector<PlotSpec> plots;
  add_plot(plots, table_plot(result.overlay, "Key and hammer, grand and upright", "angle (deg)",
                             {{"grand_hammer_angle_deg", "grand hammer"},
                              {"upright_hammer_angle_deg", "upright hammer"},
                              {"grand_key_angle_deg", "grand key"},
                              {"upright_key_angle_deg", "upright key"}}));
  add_plot(plots, table_plot(result.overlay, "Hammer–string gap", "gap (mm)",
                             {{"grand_hammer_string_gap_mm", "grand"},
                              {"upright_hammer_string_gap_mm", "upright"}}));
  add_plot(plots,
           table_plot(result.overlay, "Finger force (the touch)", "force (N)",
                      {{"grand_finger_force_n", "grand"}, {"upright_finger_force_n", "upright"}}));
  PlotSpec limits =
      category_plot("Repetition limits", "maximum frequency (Hz)", "action", "action_index");
  PlotCurve full = point_curve("full stroke", "full_stroke_max_hz");
  PlotCurve half = point_curve("half stroke", "half_stroke_max_hz");
  for (std::size_t a = 0; a < result.actions.size(); ++a) {
    const ActionComparison& c = result.actions[a];
    limits.x_categories.push_back(c.action);
    if (c.full_stroke && c.full_stroke->max_frequency_hz) {
      full.add(double(a), *c.full_stroke->max_frequency_hz);
    }
    if (c.half_stroke && c.half_stroke->max_frequency_hz) {
      half.add(double(a), *c.half_stroke->max_frequency_hz);
    }
  }
  limits.curves = {std::move(full), std::move(half)};
  add_plot(plots, std::move(limits));
  return plots;
}

}  // namespace

int run_study_compare(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--input", "--duration", "--fmax", "--out", "--plot"},
                       {"--json", "--no-limits"});
  ComparisonOptions options;
  options.input = cl.value_or("--input", options.input);
  options.duration_s = cl.positive_number_or("--duration", options.duration_s);
  options.repetition_limits = !cl.has("--no-limits");
  if (cl.has("--fmax"))
    options.f_max_full_hz = options.f_max_half_hz = cl.positive_number("--fmax");
  const ActionModel grand = load_action("grand");
  const ActionModel upright = load_action("upright");
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const ComparisonResult result = compare_actions({&grand, &upright}, options);
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(comparison_plots(result), !cl.has("--json"));
  if (!out_path.empty()) {
    CsvTable overlay = result.overlay;
    overlay.metadata["options"] = cl.arguments_text();  // the input, duration and band it ran
    write_csv(out_path, overlay);
  }

  if (cl.has("--json")) {
    nlohmann::json actions = nlohmann::json::array();
    for (const ActionComparison& a : result.actions) {
      const SimEvent* impact = a.first_impact ? &*a.first_impact : nullptr;
      actions.push_back(
          {{"action", a.action},
           {"status", a.run.status},
           {"stop_cause",
            a.run.status == "ok" ? nlohmann::json(nullptr) : nlohmann::json(a.run.stop_cause)},
           {"impact_t_s", impact ? nlohmann::json(impact->t) : nlohmann::json(nullptr)},
           {"impact_velocity_mps",
            impact ? nlohmann::json(impact->hammer_velocity) : nlohmann::json(nullptr)},
           {"repetition_full", limit_json(a.full_stroke)},
           {"repetition_half", limit_json(a.half_stroke)}});
    }
    std::cout << nlohmann::json{{"input", options.input},
                                {"duration_s", options.duration_s},
                                {"actions", actions},
                                {"wall_s", result.wall_s}}
                     .dump(1)
              << "\n";
  } else {
    std::cout << "upright vs grand, input " << options.input << "\n";
    for (const ActionComparison& a : result.actions) {
      std::cout << "  " << a.action << ": ";
      if (a.first_impact)
        std::cout << "impact at " << format_number(a.first_impact->t * 1e3) << " ms, "
                  << format_number(a.first_impact->hammer_velocity) << " m/s";
      else
        std::cout << "no impact within " << options.duration_s << " s";
      if (a.run.status != "ok") std::cout << " (run stopped: " << a.run.stop_cause << ")";
      std::cout << "\n";
      // each limit beside the paper's figures (said when it disagrees)
      const auto limit = [&](const char* stroke, const SweepResult& sweep) {
        std::cout << "    " << stroke << " stroke: " << sweep_summary(sweep) << "\n";
        const std::string paper = compare_with_paper(sweep, a.action);
        if (!paper.empty()) std::cout << "      " << paper << "\n";
      };
      if (a.full_stroke) limit("full", *a.full_stroke);
      if (a.half_stroke) limit("half", *a.half_stroke);
    }
    if (!out_path.empty()) std::cout << "  overlay written to " << out_path << "\n";
  }
  return 0;
}

}  // namespace pat::app

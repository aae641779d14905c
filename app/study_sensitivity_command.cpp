// pianoaction study sensitivity: every regulation setting moved ±step, and what changes (the
// table a teacher shows: which screw matters most). Issue 4; engine/analysis/sensitivity.h.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "action_setup.h"
#include "analysis/sensitivity.h"
#include "analysis_csv.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"
#include "json_output.h"
#include "plot_output.h"

namespace pat::app {
namespace {

/// One plot per metric: its change from the regulated action with each adjuster moved by
/// −step and +step, settings side by side (the window's sensitivity plots).
std::vector<PlotSpec> sensitivity_plots(const SensitivityResult& r, double step_mm) {
  std::vector<std::string> settings;
  for (const SensitivityRow& row : r.rows) settings.push_back(setting_words(row.setting));
  const std::string step = format_number(step_mm);
  std::vector<PlotSpec> plots;
  for (std::size_t m = 0; m < r.metrics.size(); ++m) {
    const std::string& metric = r.metrics[m];
    // in words, the unit in the y title ("change (m/s)"): the keys were cut off there
    const MetricWords named = metric_words(metric);
    PlotSpec plot =
        category_plot(named.words, named.unit.empty() ? "change" : "change (" + named.unit + ")",
                      "setting", "setting_index");
    plot.x_categories = settings;
    // changes from the regulated action, named so (a column "impact_velocity_mps_minus" of
    // 0.0011 read as a speed of 1 mm/s)
    PlotCurve minus = point_curve("adjuster −" + step + " mm", metric + "_change_minus");
    PlotCurve plus = point_curve("adjuster +" + step + " mm", metric + "_change_plus");
    for (std::size_t s = 0; s < r.rows.size(); ++s) {
      for (auto [curve, value] :
           {std::pair{&minus, r.rows[s].minus[m]}, std::pair{&plus, r.rows[s].plus[m]}}) {
        const double change = value - r.baseline[m];
        if (!std::isfinite(change)) continue;  // not measurable on that side
        curve->add(double(s), change);
      }
    }
    plot.curves = {std::move(minus), std::move(plus)};
    add_plot(plots, std::move(plot));
  }
  return plots;
}

/// How each of a row's readings was taken when not as its variant stands, or why it could not
/// be: {"minus": ..., "as_given": ..., "plus": ...}, only those that have one.
nlohmann::json measured_notes(const SensitivityRow& row) {
  nlohmann::json notes = nlohmann::json::object();
  const char* const sides[3] = {"minus", "as_given", "plus"};
  for (int p = 0; p < 3; ++p) {
    if (!row.measured_problem[p].empty())
      notes[sides[p]] = "not read: " + row.measured_problem[p];
    else if (!row.measured_note[p].empty())
      notes[sides[p]] = row.measured_note[p];
  }
  return notes;
}

}  // namespace

int run_study_sensitivity(const std::vector<std::string>& args) {
  const CommandLine cl(
      args, {"--action", "--set", "--without", "--step", "--force", "--out", "--plot"}, {"--json"});
  const ActionModel model = load_configured_action(cl);
  SensitivityOptions options;
  options.step_mm = cl.positive_number_or("--step", 0.5);
  options.groups = sensitivity_metric_groups(cl.positive_number_or("--force", 20.0));
  const PlotOption plot(cl);
  const std::string out_path = cl.output_path("--out");
  const SensitivityResult result = sensitivity(model, options);

  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(sensitivity_plots(result, options.step_mm), !cl.has("--json"));
  if (!out_path.empty()) {
    // one row per setting and side: the setting's measured value (in its own unit, named in the
    // 'setting_index' metadata: mm, or a fraction for a damper lift) and every metric
    CsvTable table;
    table.columns = {"setting_index", "offset_mm", "measured_in_setting_unit"};
    for (const std::string& m : result.metrics) table.columns.push_back(m);
    for (std::size_t s = 0; s < result.rows.size(); ++s) {
      const SensitivityRow& row = result.rows[s];
      for (int side : {0, 2}) {
        std::vector<double> line{double(s), (side - 1) * options.step_mm, row.measured[side]};
        const std::vector<double>& values = side == 0 ? row.minus : row.plus;
        line.insert(line.end(), values.begin(), values.end());
        table.rows.push_back(line);
      }
    }
    std::string names;
    for (std::size_t s = 0; s < result.rows.size(); ++s) {
      if (s > 0) names += ' ';
      names += std::to_string(s) + "=" + result.rows[s].setting + "(" + result.rows[s].unit + ")";
    }
    add_run_metadata(table, model, cl);  // its 'settings': the adjusters as the run began
    table.metadata["setting_index"] = names;
    write_csv(out_path, table);
  }

  if (cl.has("--json")) {
    nlohmann::json settings = nlohmann::json::array();
    for (const SensitivityRow& row : result.rows) {
      nlohmann::json metrics = nlohmann::json::object();
      for (std::size_t m = 0; m < result.metrics.size(); ++m)
        metrics[result.metrics[m]] = {
            {"minus", number_or_null(row.minus[m])},
            {"plus", number_or_null(row.plus[m])},
            {"per_unit_of_setting", number_or_null(row.per_unit_of_setting[m])}};
      settings.push_back({{"name", row.setting},
                          {"unit", row.unit},
                          {"measured_minus", number_or_null(row.measured[0])},
                          {"measured", number_or_null(row.measured[1])},
                          {"measured_plus", number_or_null(row.measured[2])},
                          {"measured_notes", measured_notes(row)},
                          {"metrics", metrics}});
    }
    nlohmann::json baseline = nlohmann::json::object();
    nlohmann::json ranking = nlohmann::json::object();
    for (std::size_t m = 0; m < result.metrics.size(); ++m) {
      baseline[result.metrics[m]] = number_or_null(result.baseline[m]);
      nlohmann::json ranks = nlohmann::json::array();
      for (const SensitivityRank& rank : rank_by_change(result, m))
        ranks.push_back({{"setting", rank.setting}, {"change", rank.change}});
      ranking[result.metrics[m]] = ranks;
    }
    std::cout << nlohmann::json{{"step_mm", options.step_mm},
                                {"baseline", baseline},
                                {"settings", settings},
                                {"ranking", ranking}}
                     .dump(1)
              << "\n";
    return 0;
  }
  std::cout << "adjusters moved by -" << options.step_mm << " / +" << options.step_mm
            << " mm; each metric at - / +\n";
  std::cout << std::left << std::setw(16) << "setting" << std::setw(26) << "measured - / 0 / +";
  for (const std::string& m : result.metrics) std::cout << std::setw(26) << m;
  std::cout << "\n" << std::setprecision(4);
  // the action as given: what each change is a change from
  std::cout << std::setw(16) << "(as given)" << std::setw(26) << "";
  for (double value : result.baseline) {
    std::ostringstream cell;
    cell << std::setprecision(4) << value;
    std::cout << std::setw(26) << cell.str();
  }
  std::cout << "\n";
  // a reading taken with another screw out of the way is starred, one that cannot be taken is
  // "-": both explained under the table
  std::vector<std::string> footnotes;
  const std::string step_words = format_number(options.step_mm) + " mm";
  for (const SensitivityRow& row : result.rows) {
    std::ostringstream measured;
    measured << std::setprecision(4);
    for (int p = 0; p < 3; ++p) {
      if (p > 0) measured << " / ";
      std::string side = "as given";
      if (p != 1) side = std::string(p == 0 ? "-" : "+") + step_words;
      if (!row.measured_problem[p].empty()) {
        measured << "-";
        footnotes.push_back(row.setting + " " + side + ": not read: " + row.measured_problem[p]);
      } else {
        measured << row.measured[p];
        if (!row.measured_note[p].empty()) {
          measured << "*";
          footnotes.push_back(row.setting + " " + side + ": " + row.measured_note[p]);
        }
      }
    }
    std::cout << std::setw(16) << row.setting << std::setw(26) << measured.str();
    for (std::size_t m = 0; m < result.metrics.size(); ++m) {
      std::ostringstream cell;
      cell << std::setprecision(4) << row.minus[m] << " / " << row.plus[m];
      std::cout << std::setw(26) << cell.str();
    }
    std::cout << "\n";
  }
  for (const std::string& note : footnotes) std::cout << "  " << note << "\n";
  // which screw matters most: the same turn of each adjuster, the largest change first
  std::cout << "\nlargest change over the -" << options.step_mm << " ... +" << options.step_mm
            << " mm turn:\n";
  for (std::size_t m = 0; m < result.metrics.size(); ++m) {
    std::cout << "  " << std::setw(22) << result.metrics[m];
    const std::vector<SensitivityRank> ranks = rank_by_change(result, m);
    for (std::size_t i = 0; i < ranks.size() && i < 3; ++i)
      std::cout << (i ? ", " : "") << ranks[i].setting << " " << std::setprecision(3)
                << ranks[i].change;
    // no reading on the action as given (a blow that never struck: too soft, or so hard that
    // its run stopped) is not "no change"
    const bool of_the_blow =
        result.metrics[m] == "impact_velocity_mps" || result.metrics[m] == "let_off_time_ms";
    const char* none = std::isfinite(result.baseline[m]) ? "(no setting changes it measurably)\n"
                       : of_the_blow
                           ? "(not read on the action as given: its blow did not strike in 0.4 s, "
                             "too soft, or so hard that the run stopped; try another --force)\n"
                           : "(not read on the action as given)\n";
    std::cout << (ranks.empty() ? none : "\n");
  }
  // the repetition limit is no smooth function of a screw: it can jump between two regimes
  // (the grand's halfway stroke repeats to about 13 Hz, or to 22-24 Hz once let-off is closer:
  // README, Limits, F4), and a chirp's limit is the frequency of one of its cycles, so variants
  // can share a value. A change of several hertz is such a jump.
  const auto repetition =
      std::find(result.metrics.begin(), result.metrics.end(), "max_repetition_hz");
  if (repetition != result.metrics.end()) {
    const std::size_t m = static_cast<std::size_t>(repetition - result.metrics.begin());
    std::string jumps;
    for (const MetricJump& jump : jumps_beyond(result, m, kRepetitionJumpHz))
      jumps += (jumps.empty() ? "" : ", ") + jump.setting + (jump.side < 0 ? " -" : " +") + " (" +
               format_number(jump.value) + " Hz)";
    if (!jumps.empty())
      std::cout << "  max_repetition_hz jumps from " << format_number(result.baseline[m])
                << " Hz to another regime with " << jumps
                << ": which screws can tip it, not a slope (README, Limits: grand repetition)\n";
  }
  return 0;
}

}  // namespace pat::app

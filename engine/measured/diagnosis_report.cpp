#include "measured/diagnosis_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"

namespace pat {
namespace {

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

/// The phase names in index order, space separated (the traces' "phases" metadata line).
std::string phase_list() {
  std::string list;
  for (const std::string& p : phase_names()) list += (list.empty() ? "" : " ") + p;
  return list;
}

/// A number to 10 significant digits, or an empty field where it is not finite (a candidate
/// that was not validated has no held-out error).
std::string csv_number(double x) {
  if (!std::isfinite(x)) return {};
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.10g", x);
  return buffer;
}

/// Writes a table of text fields (write_file_replacing).
void write_text_csv(const std::string& path, const std::vector<std::string>& columns,
                    const std::vector<std::vector<std::string>>& rows) {
  std::string text;
  auto add_row = [&text](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i > 0) text += ',';
      text += csv_quoted(fields[i]);
    }
    text += "\n";
  };
  add_row(columns);
  for (const auto& row : rows) add_row(row);
  write_file_replacing(path, text);
}

}  // namespace

nlohmann::json diagnosis_json(const Diagnosis& d) {
  nlohmann::json ranking = nlohmann::json::array();
  for (const CandidateFit& c : d.ranking) {
    ranking.push_back({{"effect", c.effect},
                       {"value", c.completed ? nlohmann::json(c.value) : nlohmann::json(nullptr)},
                       {"unit", c.unit},
                       {"fold_values", c.fold_values},
                       {"validated_rms_deg", finite_or_null(c.validated_rms_deg)},
                       {"training_rms_deg", finite_or_null(c.training_rms_deg)},
                       {"delta_bic", finite_or_null(c.delta_bic)},
                       {"completed", c.completed},
                       {"note", c.note}});
  }
  nlohmann::json events = nlohmann::json::array();
  nlohmann::json trials = nlohmann::json::array();
  for (const TrialReport& r : d.trials) {
    nlohmann::json trial_events = nlohmann::json::array();
    for (const MeasuredEvent& e : r.measured_events) {
      // t_s on the clock compared (the model's), file_t_s in the file's own time
      nlohmann::json item{{"type", e.type},
                          {"t_s", e.t},
                          {"file_t_s", e.t + r.file_time_shift_s},
                          {"angle_deg", e.angle_deg},
                          {"file", r.path}};
      events.push_back(item);
      trial_events.push_back(item);
    }
    nlohmann::json phases = nlohmann::json::array();
    for (const PhaseResidual& p : r.discrepancies.phases) {
      nlohmann::json phase{{"phase", p.phase},
                           {"samples", p.samples},
                           {"rms_deg", p.rms_deg},
                           {"mean_deg", p.mean_deg},
                           {"noise_deg", p.noise_deg}};
      if (p.has_extended) {  // the same samples with the cause
        phase["extended_rms_deg"] = p.extended_rms_deg;
        phase["extended_mean_deg"] = p.extended_mean_deg;
      }
      phases.push_back(phase);
    }
    nlohmann::json features = nlohmann::json::array();
    for (const FeatureDiscrepancy& f : r.discrepancies.features)
      features.push_back(
          {{"feature", f.feature},
           {"unit", f.unit},
           {"measured", f.measured_known ? nlohmann::json(f.measured) : nlohmann::json(nullptr)},
           {"model", f.model_known ? nlohmann::json(f.model) : nlohmann::json(nullptr)},
           {"difference",
            f.measured_known ? nlohmann::json(f.difference) : nlohmann::json(nullptr)},
           {"text", f.text}});
    if (r.discrepancies.residual_oscillation_hz > 0.0)  // the residual's own figures
      for (nlohmann::json& f : features)
        if (f["feature"] == "residual_oscillation") {
          f["frequency_hz"] = r.discrepancies.residual_oscillation_hz;
          f["amplitude_deg"] = r.discrepancies.residual_oscillation_deg;
        }
    trials.push_back(
        {{"file", r.path},
         {"input", r.input_spec},
         {"input_estimated", r.input_estimated},
         {"file_time_shift_s", r.file_time_shift_s},
         {"noise_deg", r.noise_deg},
         {"time_offset_ms", r.baseline_alignment.time_offset_s * 1e3},
         {"time_offset_at_limit", r.time_offset_at_limit},
         {"angle_offset_deg", r.baseline_alignment.angle_offset_deg},
         // as the whole diagnosis's baseline and gain take it: with the least-squares offset
         {"baseline_rms_deg", std::sqrt(r.baseline_fitted_rss /
                                        static_cast<double>(r.baseline_alignment.residual.size()))},
         {"phases", phases},
         {"held_out",
          r.held_out_effect.empty()
              ? nlohmann::json(nullptr)
              : nlohmann::json{{"effect", r.held_out_effect},
                               {"value", r.held_out_value},
                               {"unit", r.held_out_unit},
                               {"extended_rms_deg", finite_or_null(r.held_out_rms_deg)}}},
         {"features", features},
         {"measured_events", trial_events}});
  }
  nlohmann::json cause = nullptr;
  if (d.cause)
    cause = {{"effect", d.cause->name}, {"value", d.cause->value}, {"unit", d.cause_unit}};
  return {{"action", d.action},
          {"baseline_rms_deg", d.baseline_rms_deg},
          {"extended_rms_deg", finite_or_null(d.extended_rms_deg)},
          {"gain", finite_or_null(d.gain)},
          {"gain_measured_on", d.gain_basis},
          {"held_out", d.held_out},
          {"ambiguous", d.ambiguous},
          {"verdict", d.verdict},
          {"noise_deg", d.noise_deg},
          {"cause", cause},
          {"ranking", ranking},
          {"discrepancies", d.discrepancies},
          {"measured_events", events},
          {"trials", trials},
          {"simulations", d.simulations},
          {"wall_time_s", d.wall_time_s}};
}

CsvTable trial_traces_table(const TrialReport& r) {
  const auto& phases = phase_names();
  CsvTable traces;
  traces.metadata["file"] = r.path;
  // the times are those compared: the file's own are these plus the shift
  traces.metadata["file_time_shift_s"] = format_number(r.file_time_shift_s, 9);
  traces.metadata["phases"] = phase_list();
  traces.columns = {"time_s", "measured_deg", "baseline_deg", "residual_baseline_deg",
                    "phase_index"};
  const bool extended = !r.extended.hammer_deg.empty();
  if (extended) {
    traces.columns.push_back("extended_deg");
    traces.columns.push_back("residual_extended_deg");
  }
  const Alignment& base = r.baseline_alignment;
  for (std::size_t i = 0; i < r.data.t.size(); ++i) {
    const double measured = r.data.hammer_deg[i];
    const double index = static_cast<double>(
        std::find(phases.begin(), phases.end(), r.discrepancies.phase_of_sample[i]) -
        phases.begin());
    std::vector<double> row{r.data.t[i], measured, measured - base.residual[i], base.residual[i],
                            index};
    if (extended) {
      row.push_back(measured - r.extended_alignment.residual[i]);
      row.push_back(r.extended_alignment.residual[i]);
    }
    traces.rows.push_back(std::move(row));
  }
  return traces;
}

void write_diagnosis_report(const std::string& dir, const Diagnosis& d) {
  const nlohmann::json json = diagnosis_json(d);
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directory(dir, ec);  // one level: a mistyped parent is an error, not a new tree
  if (ec || !fs::is_directory(dir))
    throw InputError(dir + ": cannot create the folder (" + ec.message() + ")");
  write_file_replacing((fs::path(dir) / "diagnosis.json").string(), json.dump(1) + "\n");
  // the candidates by rank, the model as it is first (rank 0) for scale; an empty number: the
  // candidate was screened out before its held-out fit, or its fit made the model fail (the
  // note says which)
  std::vector<std::vector<std::string>> ranking{{"0", "baseline", "", "",
                                                 csv_number(d.baseline_rms_deg),
                                                 csv_number(d.baseline_rms_deg), "", ""}};
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    const CandidateFit& c = d.ranking[i];
    const auto number = [&c](double x) { return c.completed ? csv_number(x) : std::string(); };
    ranking.push_back({std::to_string(i + 1), c.effect, number(c.value), c.unit,
                       number(c.validated_rms_deg), number(c.training_rms_deg), number(c.delta_bic),
                       c.note});
  }
  write_text_csv((fs::path(dir) / "ranking.csv").string(),
                 {"rank", "effect", "value", "unit", "validated_rms_deg", "training_rms_deg",
                  "delta_bic", "note"},
                 ranking);

  // each trial by its file's name, or, where two folders hold files of one name, by its path as
  // given and a traces file numbered by its place (the second had replaced the first's)
  std::map<std::string, int> name_count;
  for (const TrialReport& r : d.trials) ++name_count[fs::path(r.path).filename().string()];
  std::vector<std::vector<std::string>> phase_rows;
  for (std::size_t j = 0; j < d.trials.size(); ++j) {
    const TrialReport& r = d.trials[j];
    const bool shared_name = name_count[fs::path(r.path).filename().string()] > 1;
    const std::string file = shared_name ? r.path : fs::path(r.path).filename().string();
    const std::string traces_name = fs::path(r.path).stem().string() +
                                    (shared_name ? "_" + std::to_string(j + 1) : std::string()) +
                                    "_traces.csv";
    for (const PhaseResidual& p : r.discrepancies.phases)
      phase_rows.push_back({file, p.phase, std::to_string(p.samples), csv_number(p.rms_deg),
                            csv_number(p.mean_deg), csv_number(p.noise_deg),
                            p.has_extended ? csv_number(p.extended_rms_deg) : std::string(),
                            p.has_extended ? csv_number(p.extended_mean_deg) : std::string()});
    write_csv((fs::path(dir) / traces_name).string(), trial_traces_table(r));
  }
  write_text_csv((fs::path(dir) / "phases.csv").string(),
                 {"file", "phase", "samples", "rms_deg", "mean_deg", "noise_deg",
                  "extended_rms_deg", "extended_mean_deg"},
                 phase_rows);
}

}  // namespace pat

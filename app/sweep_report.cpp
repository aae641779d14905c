#include "sweep_report.h"

#include <utility>

#include "core/format.h"

namespace pat::app {
nlohmann::json cycle_json(const CycleResult& c) {
  return {{"t_s", c.t_start_s},
          {"frequency_hz", c.frequency_hz},
          {"strikes", c.strikes},
          {"success", c.success()},
          {"kind", outcome_name(c.outcome)},
          {"judged", c.judged},
          {"strike_velocity_mps", c.strike_velocity_mps}};
}

namespace {

std::string failure_words(CycleOutcome outcome) {
  switch (outcome) {
    case CycleOutcome::missed:
      return "missed strike";
    case CycleOutcome::double_strike:
      return "double strike";
    case CycleOutcome::stopped:
      return "run stopped";
    case CycleOutcome::struck_once:
      break;
  }
  return "none";
}

void add_cycle_rows(CsvTable& table, const std::vector<CycleResult>& cycles, double step_hz) {
  for (const CycleResult& c : cycles) {
    std::vector<double> row{c.t_start_s,
                            c.frequency_hz,
                            static_cast<double>(c.strikes),
                            c.success() ? 1.0 : 0.0,
                            c.judged ? 1.0 : 0.0,
                            c.strike_velocity_mps};
    if (step_hz > 0.0) row.push_back(step_hz);
    table.rows.push_back(std::move(row));
  }
}

}  // namespace

std::string sweep_run_status(const SweepResult& r) {
  if (r.mode == SweepMode::chirp) return r.run_status;
  for (const FrequencyResult& f : r.frequencies)
    if (f.run_status != "ok") return f.run_status;
  return "ok";
}

std::string sweep_stop_cause(const SweepResult& r) {
  if (r.mode == SweepMode::chirp) return r.stop_cause;
  for (const FrequencyResult& f : r.frequencies)
    if (f.run_status != "ok") return f.stop_cause;
  return {};
}

nlohmann::json sweep_json(const SweepResult& r) {
  nlohmann::json out{
      {"max_frequency_hz",
       r.max_frequency_hz ? nlohmann::json(*r.max_frequency_hz) : nlohmann::json(nullptr)},
      {"stroke", stroke_name(r.stroke)},
      {"mode", sweep_mode_name(r.mode)},
      {"limit_found", r.limit_found},
      {"first_failure", r.first_failure ? cycle_json(*r.first_failure) : nlohmann::json(nullptr)},
      {"alternating_from_hz",
       r.alternating_from_hz ? nlohmann::json(*r.alternating_from_hz) : nlohmann::json(nullptr)},
      {"simulated_s", r.simulated_s},
      {"wall_s", r.wall_s}};
  // the judged cycles under the repeating range (a key moved too slowly), counted
  if (const auto below = failures_below_range(r))
    out["below_range"] = {{"range_from_hz", below->range_from_hz},
                          {"judged", below->judged},
                          {"double", below->doubles},
                          {"missed", below->missed}};
  else
    out["below_range"] = nullptr;
  if (r.mode == SweepMode::chirp) {
    out["run_status"] = r.run_status;
    out["stop_cause"] =
        r.run_status == "ok" ? nlohmann::json(nullptr) : nlohmann::json(r.stop_cause);
    nlohmann::json cycles = nlohmann::json::array();
    for (const CycleResult& c : r.cycles) cycles.push_back(cycle_json(c));
    out["cycles"] = cycles;
  } else {
    nlohmann::json frequencies = nlohmann::json::array();
    for (const FrequencyResult& f : r.frequencies) {
      nlohmann::json cycles = nlohmann::json::array();
      for (const CycleResult& c : f.cycles) cycles.push_back(cycle_json(c));
      frequencies.push_back({{"frequency_hz", f.frequency_hz},
                             {"passed", f.passed},
                             {"failed_cycles", f.failed_cycles},
                             {"run_status", f.run_status},
                             {"stop_cause", f.run_status == "ok" ? nlohmann::json(nullptr)
                                                                 : nlohmann::json(f.stop_cause)},
                             {"cycles", cycles}});
    }
    out["frequencies"] = frequencies;
  }
  return out;
}

CsvTable sweep_cycles_table(const SweepResult& r, const ActionModel& model) {
  CsvTable table;
  table.metadata["action"] = model.kind;
  table.metadata["stroke"] = stroke_name(r.stroke);
  table.metadata["mode"] = sweep_mode_name(r.mode);
  // strikes tells the kind of a failure: 0 missed, 2 or more a double strike
  table.columns = {"t_s", "frequency_hz", "strikes", "success", "judged", "strike_velocity_mps"};
  if (r.mode == SweepMode::chirp) {
    add_cycle_rows(table, r.cycles, 0.0);
  } else {
    table.columns.push_back("step_frequency_hz");
    for (const FrequencyResult& f : r.frequencies) add_cycle_rows(table, f.cycles, f.frequency_hz);
  }
  return table;
}

std::vector<PlotSpec> sweep_plots(const SweepResult& r) {
  PlotCurve strikes = point_curve("strikes per cycle", "strikes");
  PlotCurve velocity = point_curve("hammer speed at the strike", "strike_velocity_mps");
  for (const CyclePoint& p : judged_cycle_points(r)) {
    strikes.add(p.frequency_hz, p.strikes);
    if (p.strikes > 0) velocity.add(p.frequency_hz, p.strike_velocity_mps);
  }
  std::vector<PlotMarker> markers;  // the maximum, and where blows start to alternate
  if (r.max_frequency_hz)
    markers.push_back({*r.max_frequency_hz, (r.limit_found ? "maximum " : "no limit up to ") +
                                                format_number(*r.max_frequency_hz) + " Hz"});
  if (r.alternating_from_hz)
    markers.push_back({*r.alternating_from_hz,
                       "alternating blows from " + format_number(*r.alternating_from_hz) + " Hz"});
  auto frequency_plot = [&](const std::string& title, const std::string& y_title, PlotCurve c) {
    PlotSpec plot = time_plot(title, y_title);
    plot.x_title = "frequency (Hz)";
    plot.x_column = "frequency_hz";
    plot.x_unit = "Hz";
    plot.curves.push_back(std::move(c));
    plot.markers = markers;
    return plot;
  };
  std::vector<PlotSpec> plots;
  add_plot(plots, frequency_plot("Strikes per cycle (" + stroke_name(r.stroke) + " stroke)",
                                 "strikes", std::move(strikes)));
  add_plot(plots, frequency_plot("Hammer speed at the strike", "speed (m/s)", std::move(velocity)));
  if (!r.trace.rows.empty())
    add_plot(plots, table_plot(r.trace, "Key and hammer (the chirp run)", "angle (deg)",
                               {{"key_angle_deg", "key"}, {"hammer_angle_deg", "hammer"}}));
  return plots;
}

std::string sweep_summary(const SweepResult& r) {
  const CycleResult* stopped = nullptr;  // the first cycle of a run that stopped
  std::string cause = r.stop_cause;
  for (const CycleResult& c : r.cycles)
    if (c.outcome == CycleOutcome::stopped && !stopped) stopped = &c;
  for (const FrequencyResult& f : r.frequencies)
    for (const CycleResult& c : f.cycles)
      if (c.outcome == CycleOutcome::stopped && !stopped) {
        stopped = &c;
        cause = f.stop_cause;
      }
  // no maximum: a chirp's stopped run that cut the band short is the reason, not the failures
  // before it (a slowly moved key's double strikes), which say only that no steady window began
  // there (in steps each frequency is a run of its own: a stop there cuts nothing short)
  const bool stop_cut_the_band = stopped && r.mode == SweepMode::chirp;
  std::string text = r.max_frequency_hz ? "maximum " + format_number(*r.max_frequency_hz) + " Hz"
                     : stop_cut_the_band
                         ? "no maximum: a run stopped at " + format_number(stopped->frequency_hz) +
                               " Hz (t = " + format_number(stopped->t_start_s) +
                               " s) before a steady window of cycles striking once (" +
                               "--window) had formed"
                         : std::string("no maximum (the first judged cycle fails)");
  const bool headline_names_stop = !r.max_frequency_hz && stop_cut_the_band && r.limit_found;
  if (!r.limit_found) {
    // the band's top, not a limit: the action repeats at least that fast
    text = r.max_frequency_hz
               ? "no limit in the band: the repeating range reaches its top, " +
                     format_number(*r.max_frequency_hz) + " Hz (the maximum is at least that)"
           // nothing failed, yet no steady window: too few judged cycles in the band
           : judged_cycle_points(r).empty()
               ? "no maximum: the band has no judged cycle (a cycle is judged once the key has "
                 "settled into the motion); widen the band"
               : "no maximum: the band's " + std::to_string(judged_cycle_points(r).size()) +
                     (judged_cycle_points(r).size() == 1 ? " judged cycle strikes once"
                                                         : " judged cycles all strike once") +
                     ", but a maximum needs a steady window of them (--window); widen the band" +
                     (r.mode == SweepMode::chirp ? " or slow the chirp (--rate)" : "");
  } else if (!r.first_failure) {
    text += " (a run stopped while settling)";
  } else {
    const CycleResult& f = *r.first_failure;
    text += " (first failure: " + failure_words(f.outcome) + ", " + std::to_string(f.strikes) +
            " strikes, at " + format_number(f.frequency_hz) +
            " Hz, t = " + format_number(f.t_start_s) + " s)";
  }
  // the cycles below the range that fail (a key moved too slowly) are not hidden by it
  if (const auto below = failures_below_range(r); below && below->doubles + below->missed > 0)
    text += "; below the repeating range (from " + format_number(below->range_from_hz) + " Hz) " +
            std::to_string(below->doubles + below->missed) + " of " +
            std::to_string(below->judged) + " judged cycles fail (" +
            std::to_string(below->doubles) + " struck twice or more, " +
            std::to_string(below->missed) +
            " not at all: a key moved that slowly throws the hammer twice or too gently)";
  // a run that stopped (a contact beyond its travel, a diverging step): said, with its cause,
  // even when an earlier failure already set the maximum; in a chirp whose last cycle is the
  // stopped one, nothing above it was simulated
  if (stopped) {
    const bool is_first_failure =
        r.first_failure && r.first_failure->outcome == CycleOutcome::stopped;
    const bool band_ends_there = !r.cycles.empty() && stopped == &r.cycles.back();
    text += headline_names_stop ? "; the stop: "
            : is_first_failure  ? "; the run stopped there: "
                                : "; a run stopped at " + format_number(stopped->frequency_hz) +
                                     " Hz (t = " + format_number(stopped->t_start_s) + " s): ";
    text += cause.empty() ? std::string("no cause given") : cause;
    if (band_ends_there) text += ", so nothing above was simulated";
  }
  if (r.alternating_from_hz)
    text += "; strong and weak blows alternate from " + format_number(*r.alternating_from_hz) +
            " Hz (period doubling: the limit depends on how the key got there, compare " +
            (r.mode == SweepMode::chirp ? "--mode steps" : "--mode chirp") + ")";
  return text;
}

}  // namespace pat::app

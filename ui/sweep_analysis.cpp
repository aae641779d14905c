// The repetition-frequency sweep from the window (fact F4; engine/analysis/repetition_sweep.h
// holds the definitions of cycle, strike, success and maximum). Chirp: its two segments with
// their trace put end to end, so that the key and hammer can be watched losing the beat; steps:
// one run per frequency on both cores.
#include <QObject>
#include <utility>

#include "analysis/paper_repetition.h"
#include "analysis/repetition_sweep.h"
#include "analysis_entries.h"
#include "core/error.h"
#include "core/format.h"
#include "regulation/measurements.h"

namespace pat::ui {
namespace {

// A trace sample every 0.5 ms: ten or more per cycle up to 200 Hz, 36 000 rows for 18 s.
constexpr double kTraceIntervalS = 5e-4;

QString outcome_words(CycleOutcome outcome) {
  switch (outcome) {
    case CycleOutcome::struck_once:
      return QObject::tr("struck once");
    case CycleOutcome::missed:
      return QObject::tr("missed strike");
    case CycleOutcome::double_strike:  // two or more: a cycle with three is no "double"
      return QObject::tr("struck more than once");
    case CycleOutcome::stopped:
      return QObject::tr("run stopped");
  }
  return {};
}

SweepOptions sweep_options(const AnalysisSettings& settings) {
  SweepOptions o;
  o.stroke = parse_stroke(settings.value("stroke", "full").toString().toStdString(), "stroke");
  o.mode = parse_sweep_mode(settings.value("mode", "chirp").toString().toStdString(), "mode");
  o.f_start_hz = settings.value("f_start_hz", o.f_start_hz).toDouble();
  o.f_max_hz = settings.value("f_max_hz", o.f_max_hz).toDouble();
  if (o.f_max_hz <= o.f_start_hz)
    throw InputError("maximum frequency: must be above the start frequency (" +
                     format_number(o.f_start_hz) + " Hz)");
  if (o.mode == SweepMode::chirp) o.trace_interval_s = kTraceIntervalS;
  return o;
}

AnalysisResult sweep_result(const SweepResult& r, const SweepOptions& o, const std::string& kind,
                            const std::string& settings) {
  AnalysisResult result;
  const QString stroke = QString::fromStdString(stroke_name(r.stroke));
  const QString mode = QString::fromStdString(sweep_mode_name(r.mode));
  std::vector<AnalysisMarker> frequency_marker;
  if (r.max_frequency_hz)
    frequency_marker.push_back(
        {*r.max_frequency_hz,
         (r.limit_found ? QObject::tr("maximum %1 Hz") : QObject::tr("no limit up to %1 Hz"))
             .arg(number(*r.max_frequency_hz))});
  if (r.alternating_from_hz)
    frequency_marker.push_back(
        {*r.alternating_from_hz,
         QObject::tr("alternating blows from %1 Hz").arg(number(*r.alternating_from_hz))});

  // the summary a class can read out
  if (!r.max_frequency_hz)
    result.summary = QObject::tr("no repeating range: the key never made %1 strikes in a row.")
                         .arg(o.window_cycles);
  else if (!r.limit_found)
    result.summary = QObject::tr("repeats up to %1 Hz, the end of the sweep: no limit up to %2 Hz.")
                         .arg(number(*r.max_frequency_hz))
                         .arg(number(o.f_max_hz));
  else
    result.summary = QObject::tr("maximum repetition frequency %1 Hz (%2 stroke); above it: %3.")
                         .arg(number(*r.max_frequency_hz))
                         .arg(stroke)
                         .arg(r.first_failure ? outcome_words(r.first_failure->outcome)
                                              : QObject::tr("a run stopped"));
  // the failing cycles under the range (a key moved too slowly) are not hidden by it
  if (const auto below = failures_below_range(r); below && below->doubles + below->missed > 0)
    result.summary += QObject::tr(
                          " Below the repeating range (from %1 Hz) %2 of %3 judged cycles "
                          "fail (%4 struck twice or more, %5 not at all): a key moved that slowly "
                          "throws the hammer twice or too gently.")
                          .arg(number(below->range_from_hz))
                          .arg(below->doubles + below->missed)
                          .arg(below->judged)
                          .arg(below->doubles)
                          .arg(below->missed);
  if (r.alternating_from_hz)
    result.summary +=
        QObject::tr(
            " From %1 Hz strong and weak blows alternate: the limit depends on how the key "
            "got there (compare the %2 mode).")
            .arg(number(*r.alternating_from_hz))
            .arg(r.mode == SweepMode::chirp ? QObject::tr("steps") : QObject::tr("chirp"));

  // beside the paper's figures, and said when it disagrees (not only quoting the fact)
  const std::string paper = compare_with_paper(r, kind, settings);
  if (!paper.empty()) result.summary += " " + QString::fromStdString(paper);

  result.table = {{QObject::tr("maximum repetition frequency"),
                   r.max_frequency_hz ? number(*r.max_frequency_hz) : QObject::tr("none"), "Hz"},
                  {QObject::tr("alternating blows from"),
                   r.alternating_from_hz ? number(*r.alternating_from_hz) : QObject::tr("none"),
                   r.alternating_from_hz ? "Hz" : ""},
                  {QObject::tr("limit found below the end"),
                   r.limit_found ? QObject::tr("yes") : QObject::tr("no"), ""},
                  {QObject::tr("stroke"), stroke, ""},
                  {QObject::tr("mode"), mode, ""},
                  {QObject::tr("frequency band"),
                   QObject::tr("%1 to %2").arg(number(o.f_start_hz)).arg(number(o.f_max_hz)), "Hz"},
                  {QObject::tr("simulated / wall time"),
                   QObject::tr("%1 / %2").arg(number(r.simulated_s)).arg(number(r.wall_s)), "s"}};
  if (r.first_failure) {
    const CycleResult& f = *r.first_failure;
    result.table.push_back({QObject::tr("first failure"),
                            QObject::tr("%1 (%2 strikes) at %3 Hz")
                                .arg(outcome_words(f.outcome))
                                .arg(f.strikes)
                                .arg(number(f.frequency_hz)),
                            ""});
  }
  if (r.run_status != "ok")
    result.table.push_back({QObject::tr("run stopped"), QString::fromStdString(r.stop_cause), ""});

  AnalysisSeries strikes{QObject::tr("strikes in the cycle"), "strikes", {}, {}, true};
  AnalysisSeries velocity{
      QObject::tr("hammer speed at the strike"), "strike_velocity_mps", {}, {}, true};
  for (const CyclePoint& p : judged_cycle_points(r)) {
    strikes.x.push_back(p.frequency_hz);
    strikes.y.push_back(p.strikes);
    if (p.strikes == 0) continue;
    velocity.x.push_back(p.frequency_hz);
    velocity.y.push_back(p.strike_velocity_mps);
  }
  AnalysisGrid grid;
  if (r.mode == SweepMode::chirp) {
    // the trace in the chirp's time, the maximum where its cycle ends and the alternation where
    // its first cycle starts
    std::vector<AnalysisMarker> time_marker;
    for (const CycleResult& c : r.cycles) {
      if (r.max_frequency_hz && c.frequency_hz == *r.max_frequency_hz)
        time_marker.push_back({c.t_end_s, frequency_marker.front().label});
      if (r.alternating_from_hz && c.frequency_hz == *r.alternating_from_hz)
        time_marker.push_back({c.t_start_s, frequency_marker.back().label});
    }
    // the key's few degrees and the hammer's tens each get their own axis
    const QString chirp_time = QObject::tr("time (s); the key at %1 Hz + %2 Hz/s × t")
                                   .arg(number(o.f_start_hz))
                                   .arg(number(o.chirp_rate_hz_per_s));
    const auto chirp_plot = [&](const QString& title, const QString& tab, const QString& y_title,
                                AnalysisSeries series) {
      AnalysisPlot plot = time_plot(title, y_title, {std::move(series)});
      plot.x_title = chirp_time;
      plot.markers = time_marker;
      plot.tab = tab;
      return plot;
    };
    result.plots = {chirp_plot(QObject::tr("Hammer during the chirp"), QObject::tr("Hammer"),
                               QObject::tr("hammer angle (deg)"),
                               trace_series(r.trace, "hammer_angle_deg", QObject::tr("hammer"))),
                    chirp_plot(QObject::tr("Key during the chirp"), QObject::tr("Key"),
                               QObject::tr("key angle (deg)"),
                               trace_series(r.trace, "key_angle_deg", QObject::tr("key"))),
                    chirp_plot(QObject::tr("Hammer–string gap during the chirp"),
                               QObject::tr("Gap"), QObject::tr("gap (mm)"),
                               trace_series(r.trace, "hammer_string_gap_mm", QObject::tr("gap")))};
    grid.title = QObject::tr("Cycles");
    grid.columns = {QObject::tr("start (s)"), QObject::tr("frequency (Hz)"), QObject::tr("strikes"),
                    QObject::tr("outcome"), QObject::tr("judged")};
    for (const CycleResult& c : r.cycles)
      grid.rows.push_back({number(c.t_start_s, 4), number(c.frequency_hz, 4),
                           QString::number(c.strikes), outcome_words(c.outcome),
                           c.judged ? QObject::tr("yes") : QObject::tr("settling")});
  } else {
    AnalysisSeries failed{
        QObject::tr("failed cycles of the window"), "failed_cycles", {}, {}, true};
    for (const FrequencyResult& f : r.frequencies) {
      failed.x.push_back(f.frequency_hz);
      failed.y.push_back(f.failed_cycles);
    }
    AnalysisPlot failures{QObject::tr("Failed cycles per frequency"),
                          QObject::tr("key frequency (Hz)"),
                          "frequency_hz",
                          "Hz",
                          QObject::tr("failed cycles (of %1)").arg(o.window_cycles),
                          {failed},
                          {},
                          frequency_marker,
                          QObject::tr("Failures")};
    result.plots = {failures};
    grid.title = QObject::tr("Frequencies");
    grid.columns = {QObject::tr("frequency (Hz)"), QObject::tr("passed"),
                    QObject::tr("failed cycles"), QObject::tr("run")};
    for (const FrequencyResult& f : r.frequencies)
      grid.rows.push_back(
          {number(f.frequency_hz, 4), f.passed ? QObject::tr("yes") : QObject::tr("no"),
           QString::number(f.failed_cycles),
           f.run_status == "ok" ? QObject::tr("ok") : QString::fromStdString(f.stop_cause)});
  }
  result.plots.push_back({QObject::tr("Strikes per cycle"),
                          QObject::tr("key frequency (Hz)"),
                          "frequency_hz",
                          "Hz",
                          QObject::tr("strikes (1 = success)"),
                          {strikes},
                          {},
                          frequency_marker,
                          QObject::tr("Strikes")});
  result.plots.push_back({QObject::tr("Hammer speed at each strike"),
                          QObject::tr("key frequency (Hz)"),
                          "frequency_hz",
                          "Hz",
                          QObject::tr("hammer speed (m/s)"),
                          {velocity},
                          {},
                          frequency_marker,
                          QObject::tr("Speed")});
  result.grids.push_back(grid);
  return result;
}

}  // namespace

AnalysisEntry repetition_sweep_entry() {
  AnalysisEntry e;
  e.name = QObject::tr("Repetition-frequency sweep");
  e.description = QObject::tr(
      "The key played faster and faster (a chirp at 1 Hz/s, or steady sines in steps): the "
      "highest frequency at which every cycle still gives exactly one strike (the paper: the "
      "grand repeats faster than the upright, above all with a half stroke; its figures are "
      "set beside the result)");
  const AnalysisParameter stroke = AnalysisParameter::choice(
      "stroke", QObject::tr("Stroke"),
      QObject::tr("full: the key comes back to rest every cycle; half: it comes up only halfway, "
                  "where the grand's repetition lever resets the jack"),
      {"full", "half"});
  const AnalysisParameter mode = AnalysisParameter::choice(
      "mode", QObject::tr("Mode"),
      QObject::tr("chirp: a frequency rising 1 Hz each second (with its key and hammer trace); "
                  "steps: one steady run per frequency, 0.5 Hz apart"),
      {"chirp", "steps"});
  AnalysisParameter f_start;
  f_start.key = "f_start_hz";
  f_start.label = QObject::tr("From");
  f_start.kind = AnalysisParameter::Kind::number;
  f_start.minimum = 1.0;
  f_start.maximum = 39.0;
  f_start.value = 2.0;
  f_start.step = 0.5;
  f_start.unit = "Hz";
  AnalysisParameter f_max = f_start;
  f_max.key = "f_max_hz";
  f_max.label = QObject::tr("Maximum frequency");
  f_max.minimum = 2.0;
  f_max.maximum = 40.0;
  f_max.value = 20.0;
  e.parameters = {stroke, mode, f_start, f_max};
  e.make = [](std::shared_ptr<const ActionModel> model,
              const AnalysisSettings& settings) -> AnalysisTask {
    const SweepOptions options = sweep_options(settings);  // bad settings fail before the run
    return [model, options](const ProgressCallback& progress) {
      // a result's difference from the paper's is put down to the settings only when they are
      // out of tolerance (automatic regulation leaves micrometres)
      return sweep_result(run_repetition_sweep(*model, options, progress), options, model->kind,
                          regulation_state(*model));
    };
  };
  return e;
}

}  // namespace pat::ui

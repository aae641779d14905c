// Diagnosis of measured data from the window (engine/measured/diagnosis.h; `diagnose` on the
// command line): measured files against the window's action, the candidate extensions fitted
// and compared on held-out trials, and the report written by the same code as --report DIR.
#include <QFileInfo>
#include <QObject>
#include <algorithm>
#include <cmath>
#include <memory>

#include "analysis_entries.h"
#include "core/error.h"
#include "measured/diagnosis.h"
#include "measured/diagnosis_report.h"
#include "model/effects.h"

namespace pat::ui {
namespace {

QString file_name(const std::string& path) {
  return QFileInfo(QString::fromStdString(path)).fileName();
}

/// Root mean square of `residual` over the samples of each phase (NaN where a phase is absent),
/// pooled over the trials: what the by-phase plot shows for the baseline and the extended model.
std::vector<double> rms_by_phase(const Diagnosis& d, bool extended) {
  const std::vector<std::string>& phases = phase_names();
  std::vector<double> sum(phases.size(), 0.0), count(phases.size(), 0.0);
  for (const TrialReport& r : d.trials) {
    const std::vector<double>& residual =
        extended ? r.extended_alignment.residual : r.baseline_alignment.residual;
    for (std::size_t i = 0; i < residual.size() && i < r.discrepancies.phase_of_sample.size();
         ++i) {
      const auto p = std::find(phases.begin(), phases.end(), r.discrepancies.phase_of_sample[i]);
      if (p == phases.end()) continue;
      sum[p - phases.begin()] += residual[i] * residual[i];
      count[p - phases.begin()] += 1.0;
    }
  }
  std::vector<double> rms(phases.size(), std::nan(""));
  for (std::size_t k = 0; k < phases.size(); ++k)
    if (count[k] > 0) rms[k] = std::sqrt(sum[k] / count[k]);
  return rms;
}

/// An effect's name for a category axis, on lines of about a dozen characters so that four
/// candidates fit side by side: "joint_friction.hammer" → "friction:\nhammer" (the Ranking
/// table keeps the full names).
QString effect_label(const std::string& effect) {
  QString name = QString::fromStdString(effect);
  const int dot = name.indexOf('.');
  if (dot >= 0) {
    const QString family = name.left(dot);
    const QString short_family = family == "joint_friction"      ? QObject::tr("friction")
                                 : family == "felt_stiffness"    ? QObject::tr("felt")
                                 : family == "regulation_offset" ? QObject::tr("offset")
                                                                 : family;
    name = short_family + ": " + name.mid(dot + 1);
  }
  QStringList lines;
  for (const QString& word : name.replace('_', ' ').split(' ', Qt::SkipEmptyParts)) {
    if (!lines.isEmpty() && lines.back().size() + 1 + word.size() <= 12)
      lines.back() += ' ' + word;
    else
      lines << word;
  }
  return lines.join('\n');
}

/// A phase's name short enough for a category axis (the CSV keeps the engine's names).
QString phase_label(const std::string& phase) {
  if (phase == "acceleration") return QObject::tr("accel.");
  if (phase == "free_flight") return QObject::tr("flight");
  if (phase == "rebound_and_check") return QObject::tr("check");
  return QString::fromStdString(phase);
}

AnalysisSeries phase_series(const QString& label, const QString& column,
                            const std::vector<double>& rms) {
  AnalysisSeries s{label, column, {}, {}, true};
  for (std::size_t k = 0; k < rms.size(); ++k)
    if (std::isfinite(rms[k])) {
      s.x.push_back(double(k));
      s.y.push_back(rms[k]);
    }
  return s;
}

AnalysisResult diagnosis_result(std::shared_ptr<const Diagnosis> dp) {
  const Diagnosis& d = *dp;
  AnalysisResult result;
  const bool has_cause = d.cause.has_value();
  const QString cause = has_cause ? QObject::tr("%1 = %2 %3")
                                        .arg(QString::fromStdString(d.cause->name))
                                        .arg(number(d.cause->value))
                                        .arg(QString::fromStdString(d.cause_unit))
                                  : QObject::tr("none");
  const QString error_kind = d.held_out ? QObject::tr("held-out") : QObject::tr("training");
  result.summary = has_cause
                       ? (d.held_out ? QObject::tr("cause %1; the error on held-out trials "
                                                   "falls from %2 to %3 deg (gain %4 %).")
                                     : QObject::tr("cause %1; the error on the single "
                                                   "trial (no held-out data) falls from %2 "
                                                   "to %3 deg (gain %4 %)."))
                             .arg(cause)
                             .arg(number(d.baseline_rms_deg))
                             .arg(number(d.extended_rms_deg))
                             .arg(number(d.gain * 100.0, 2))
                       : QObject::tr("no cause named: %1.").arg(QString::fromStdString(d.verdict));
  result.table = {
      {QObject::tr("cause"), cause, ""},
      {QObject::tr("baseline error (%1 rms)").arg(error_kind), number(d.baseline_rms_deg), "deg"},
      {QObject::tr("extended error (%1 rms)").arg(error_kind), number(d.extended_rms_deg), "deg"},
      {QObject::tr("gain"), number(d.gain * 100.0), "%"},
      {QObject::tr("noise of the measurement"), number(d.noise_deg), "deg"},
      {QObject::tr("trials"), QString::number(d.trials.size()), ""},
      {QObject::tr("simulations / wall time"),
       QObject::tr("%1 / %2 s").arg(d.simulations).arg(number(d.wall_time_s)), ""}};
  // at the file's own time (an estimated input's strike is moved onto the model's clock, on
  // which the plots are drawn: the fast Kawai strike's impact is at 186 ms in its file, 45 ms
  // there; the row had given 45 ms "in" the file)
  for (const TrialReport& r : d.trials)
    for (const MeasuredEvent& e : r.measured_events) {
      QString when = QObject::tr("t = %1 ms in %2")
                         .arg(number((e.t + r.file_time_shift_s) * 1e3, 4), file_name(r.path));
      if (r.file_time_shift_s != 0.0)
        when += QObject::tr(" (%1 ms on the plots' clock)").arg(number(e.t * 1e3, 4));
      result.table.push_back(
          {QObject::tr("measured %1").arg(QString::fromStdString(e.type)), when, ""});
    }
  for (std::size_t i = 0; i < d.discrepancies.size() && i < 10; ++i)
    result.table.push_back(
        {QObject::tr("model error %1").arg(i + 1), QString::fromStdString(d.discrepancies[i]), ""});

  // measured vs baseline vs extended, one plot per trial, the measured events marked
  AnalysisSeries residuals_base{QObject::tr("baseline"), "residual_baseline_deg", {}, {}, false};
  AnalysisPlot residuals =
      time_plot(QObject::tr("Residuals (measured − model)"), QObject::tr("residual (deg)"), {});
  residuals.tab = QObject::tr("Residuals");
  for (const TrialReport& r : d.trials) {
    const QString name = file_name(r.path);
    AnalysisSeries measured{QObject::tr("measured"), "measured_deg", r.data.t, r.data.hammer_deg,
                            false};
    AnalysisSeries baseline{QObject::tr("baseline model"), "baseline_deg", r.data.t, {}, false};
    AnalysisSeries base_res{name + QObject::tr(" baseline"), "residual_baseline_deg", r.data.t,
                            r.baseline_alignment.residual, false};
    for (std::size_t i = 0; i < r.data.t.size(); ++i)
      baseline.y.push_back(r.data.hammer_deg[i] - r.baseline_alignment.residual[i]);
    AnalysisPlot overlay = time_plot(QObject::tr("%1: measured vs model").arg(name),
                                     QObject::tr("hammer angle (deg)"), {measured, baseline});
    overlay.tab = QFileInfo(name).completeBaseName();
    residuals.series.push_back(base_res);
    if (!r.extended.hammer_deg.empty()) {
      AnalysisSeries extended{QObject::tr("extended model"), "extended_deg", r.data.t, {}, false};
      for (std::size_t i = 0; i < r.data.t.size(); ++i)
        extended.y.push_back(r.data.hammer_deg[i] - r.extended_alignment.residual[i]);
      overlay.series.push_back(extended);
      residuals.series.push_back({name + QObject::tr(" extended"), "residual_extended_deg",
                                  r.data.t, r.extended_alignment.residual, false});
    }
    for (const MeasuredEvent& e : r.measured_events)
      overlay.markers.push_back({e.t, QString::fromStdString(e.type)});
    result.plots.push_back(overlay);
  }
  result.plots.push_back(residuals);

  // residuals by phase, pooled over the trials
  std::vector<QString> phases;
  for (const std::string& p : phase_names()) phases.push_back(phase_label(p));
  AnalysisPlot by_phase{
      QObject::tr("Residual by phase"),
      QObject::tr("phase of the stroke"),
      "phase_index",
      "",
      QObject::tr("residual rms (deg)"),
      {phase_series(QObject::tr("baseline"), "baseline_rms_deg", rms_by_phase(d, false))},
      phases,
      {},
      QObject::tr("By phase")};
  if (has_cause)
    by_phase.series.push_back(
        phase_series(QObject::tr("extended"), "extended_rms_deg", rms_by_phase(d, true)));
  result.plots.push_back(by_phase);

  // the ranking: validated error of each fitted candidate against the baseline
  AnalysisPlot ranking{QObject::tr("Ranking of the candidates"),
                       QObject::tr("candidate (best first)"),
                       "rank_index",
                       "",
                       QObject::tr("%1 rms (deg)").arg(error_kind),
                       {},
                       {},
                       {},
                       QObject::tr("Ranking plot")};
  AnalysisSeries validated{QObject::tr("candidate, fitted"),
                           d.held_out ? "validated_rms_deg" : "training_rms_deg",
                           {},
                           {},
                           true};
  AnalysisSeries base_line{
      QObject::tr("baseline (no extension)"), "baseline_rms_deg", {}, {}, false};
  AnalysisGrid grid{QObject::tr("Ranking"),
                    {QObject::tr("rank"), QObject::tr("effect"), QObject::tr("fitted value"),
                     QObject::tr("unit"), QObject::tr("%1 rms (deg)").arg(error_kind),
                     QObject::tr("training rms (deg)"), QObject::tr("ΔBIC"), QObject::tr("note")},
                    {}};
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    const CandidateFit& c = d.ranking[i];
    grid.rows.push_back(
        {QString::number(i + 1), QString::fromStdString(c.effect),
         c.completed ? number(c.value) : QObject::tr("failed"), QString::fromStdString(c.unit),
         std::isfinite(c.validated_rms_deg) ? number(c.validated_rms_deg) : QObject::tr("—"),
         std::isfinite(c.training_rms_deg) ? number(c.training_rms_deg) : QObject::tr("—"),
         std::isfinite(c.delta_bic) ? number(c.delta_bic) : QObject::tr("—"),
         QString::fromStdString(c.note)});
    // one trial: no held-out error, the training one is plotted (the axis says which)
    const double error = d.held_out ? c.validated_rms_deg : c.training_rms_deg;
    if (!c.completed || !std::isfinite(error)) continue;
    ranking.x_categories.push_back(effect_label(c.effect));
    validated.x.push_back(double(ranking.x_categories.size() - 1));
    validated.y.push_back(error);
  }
  if (!validated.x.empty()) {
    base_line.x = {-0.5, validated.x.back() + 0.5};  // across every category
    base_line.y = {d.baseline_rms_deg, d.baseline_rms_deg};
    ranking.series = {validated, base_line};
    result.plots.push_back(ranking);
  }
  result.grids.push_back(grid);

  result.write_report = [dp](const QString& folder) {
    write_diagnosis_report(folder.toStdString(), *dp);
  };
  return result;
}

}  // namespace

AnalysisEntry diagnosis_entry() {
  AnalysisEntry e;
  e.name = QObject::tr("Diagnosis of measured data");
  e.description = QObject::tr(
      "Measured hammer traces (CSV files with time_s and hammer_angle_deg; `pianoaction "
      "import-raw` converts raw optical-sensor readings with their calibration) against this "
      "action: what the model gets wrong by phase, which candidate extension explains it best "
      "on trials it was not fitted to (with two files or more), and the gain. The same analysis "
      "as `pianoaction diagnose`.");
  AnalysisParameter files;
  files.key = "files";
  files.label = QObject::tr("Measured files");
  files.tooltip = QObject::tr(
      "one or more measured CSV files (time_s, hammer_angle_deg, optionally key_angle_deg; "
      "# action: and # input: lines); with two or more, each is held out once");
  files.kind = AnalysisParameter::Kind::files;
  files.file_filter = QObject::tr("Measured data (*.csv);;All files (*)");
  files.check_files = [](const QStringList& paths, const ActionModel& model) {
    QStringList problems;
    for (const QString& path : paths) {
      try {
        read_measured(path.toStdString(), model.kind);
      } catch (const std::exception& ex) {
        problems << QString::fromStdString(ex.what());
      }
    }
    return problems;
  };
  AnalysisParameter candidates;
  candidates.key = "candidates";
  candidates.label = QObject::tr("Candidates");
  candidates.tooltip = QObject::tr(
      "the model extensions fitted (default: the whole library for this action); fewer run "
      "faster");
  candidates.kind = AnalysisParameter::Kind::checklist;
  candidates.items = [](const ActionModel& model) {
    QStringList names;
    for (const EffectInfo& info : candidate_effects(model))
      names << QString::fromStdString(info.name);
    return names;
  };
  e.parameters = {files, candidates};
  e.make = [](std::shared_ptr<const ActionModel> model,
              const AnalysisSettings& settings) -> AnalysisTask {
    const QStringList paths = settings.value("files").toStringList();
    if (paths.isEmpty()) throw InputError("choose one or more measured files first");
    std::vector<std::string> files;
    for (const QString& p : paths) files.push_back(p.toStdString());
    DiagnoseOptions options;
    for (const QString& c : settings.value("candidates").toStringList())
      options.candidates.push_back(c.toStdString());
    if (settings.contains("candidates") && options.candidates.empty())
      throw InputError("candidates: tick at least one");
    return [model, files, options](const ProgressCallback& progress) mutable {
      std::vector<MeasuredTrial> trials;
      for (const std::string& path : files) trials.push_back(read_measured(path, model->kind));
      const std::size_t n =
          options.candidates.empty() ? candidate_effects(*model).size() : options.candidates.size();
      const std::size_t total = diagnosis_progress_items(n);
      // the stage in words: the scan of every candidate, then the fits of the best ones
      ProgressReporter reporter(
          [progress, n, total](double fraction, const std::string&) {
            const auto done = static_cast<std::size_t>(std::lround(fraction * double(total)));
            const std::string stage =
                done < n ? "scanning candidates (" + std::to_string(done) + " of " +
                               std::to_string(n) + ")"
                         : "fitting and validating the best " + std::to_string(total - n);
            return progress ? progress(fraction, stage) : true;
          },
          total);
      options.progress = &reporter;
      reporter.partial(0.0, "");
      auto d = std::make_shared<const Diagnosis>(diagnose(*model, trials, options));
      reporter.throw_if_cancelled();
      return diagnosis_result(d);
    };
  };
  return e;
}

}  // namespace pat::ui

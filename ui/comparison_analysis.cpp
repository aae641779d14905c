// Upright vs grand from the window (engine/analysis/action_comparison.h; `study compare` on the
// command line): the window's action as it stands (sliders included) against the shipped
// preset of the other kind, under one key input, and optionally their repetition limits.
#include <QObject>

#include "analysis/action_comparison.h"
#include "analysis_entries.h"
#include "core/error.h"
#include "input_words.h"
#include "model/preset_loader.h"

namespace pat::ui {
namespace {

// The blows offered (SPECs): the command line's default (mezzo-forte) first.
const char* const kInputs[] = {"force:pulse:10:100", "force:pulse:4:150", "force:pulse:25:80",
                               "mass:1kg"};

/// The choices as the panel shows them: the blows in words.
QStringList input_choices() {
  QStringList words;
  for (const char* spec : kInputs) words << input_in_words(spec);
  return words;
}

/// The SPEC of a chosen blow (its words, as the panel offers them). Throws InputError for words
/// that name none (the panel shows it).
std::string input_spec_of(const QString& choice) {
  for (const char* spec : kInputs)
    if (choice == input_in_words(spec)) return spec;
  throw InputError("Upright vs grand: '" + choice.toStdString() + "' is none of the blows offered");
}

QString limit_text(const std::optional<SweepResult>& sweep) {
  if (!sweep) return QObject::tr("not run");
  if (!sweep->max_frequency_hz) return QObject::tr("no repeating range");
  return sweep->limit_found
             ? number(*sweep->max_frequency_hz)
             : QObject::tr("≥ %1 (no failure)").arg(number(*sweep->max_frequency_hz));
}

AnalysisResult comparison_result(const ComparisonResult& r, const ComparisonOptions& o) {
  AnalysisResult result;
  const QString input = input_in_words(o.input);
  struct Overlaid {
    const char* column;
    QString title, tab, y_title;
  };
  const Overlaid overlaid[] = {{"key_angle_deg", QObject::tr("Key angle"), QObject::tr("Key"),
                                QObject::tr("key angle (deg)")},
                               {"hammer_angle_deg", QObject::tr("Hammer angle"),
                                QObject::tr("Hammer"), QObject::tr("hammer angle (deg)")},
                               {"hammer_string_gap_mm", QObject::tr("Hammer–string gap"),
                                QObject::tr("Gap"), QObject::tr("gap (mm)")},
                               {"finger_force_n", QObject::tr("Force at the key front"),
                                QObject::tr("Force"), QObject::tr("force (N)")}};
  std::vector<AnalysisMarker> impacts;
  for (const ActionComparison& a : r.actions)
    if (a.first_impact)
      impacts.push_back(
          {a.first_impact->t, QObject::tr("%1 impact").arg(QString::fromStdString(a.action))});
  for (const Overlaid& o_ : overlaid) {
    AnalysisPlot plot = time_plot(o_.title + QObject::tr(" under %1").arg(input), o_.y_title, {});
    for (const ActionComparison& a : r.actions)
      plot.series.push_back(
          trace_series(r.overlay, a.action + "_" + o_.column, QString::fromStdString(a.action)));
    plot.markers = impacts;
    plot.tab = o_.tab;
    result.plots.push_back(plot);
  }

  AnalysisPlot limits{QObject::tr("Repetition limits"),
                      QObject::tr("stroke"),
                      "stroke_index",
                      "",
                      QObject::tr("max. frequency (Hz)"),
                      {},
                      {QObject::tr("full stroke"), QObject::tr("half stroke")},
                      {},
                      QObject::tr("Limits")};
  QStringList impact_words, missing_limits;
  for (const ActionComparison& a : r.actions) {
    const QString name = QString::fromStdString(a.action);
    if (a.first_impact) {
      result.table.push_back(
          {name + QObject::tr(": impact time"), number(a.first_impact->t * 1e3), "ms"});
      result.table.push_back({name + QObject::tr(": hammer velocity at impact"),
                              number(a.first_impact->hammer_velocity), "m/s"});
      impact_words << QObject::tr("the %1 strikes after %2 ms at %3 m/s")
                          .arg(name)
                          .arg(number(a.first_impact->t * 1e3))
                          .arg(number(a.first_impact->hammer_velocity));
    } else {
      result.table.push_back({name + QObject::tr(": impact"),
                              QObject::tr("none within %1 s").arg(number(o.duration_s)), ""});
      impact_words << QObject::tr("the %1 does not strike").arg(name);
    }
    if (a.run.status != "ok")
      result.table.push_back(
          {name + QObject::tr(": run stopped"), QString::fromStdString(a.run.stop_cause), ""});
    if (o.repetition_limits) {
      // the method in the name: a chirp's limit depends on where it starts and how fast it
      // rises, so the sweep analysis with other settings reads another value
      const QString method = QObject::tr("chirp from %1 Hz at %2 Hz/s")
                                 .arg(number(o.sweep.f_start_hz))
                                 .arg(number(o.sweep.chirp_rate_hz_per_s));
      result.table.push_back(
          {name + QObject::tr(": repetition limit, full stroke (%1)").arg(method),
           limit_text(a.full_stroke), "Hz"});
      result.table.push_back(
          {name + QObject::tr(": repetition limit, half stroke (%1)").arg(method),
           limit_text(a.half_stroke), "Hz"});
      // a limit found, and a lower bound (no failure up to the sweep's end) as its own series
      // so that the two do not look alike; a stroke without a repeating range has no point,
      // and the title says so
      const QString stem = QString::fromStdString(a.action);
      AnalysisSeries found{name, stem + "_max_frequency_hz", {}, {}, true};
      AnalysisSeries bound{QObject::tr("%1: at least (no failure in the sweep)").arg(name),
                           stem + "_no_failure_up_to_hz",
                           {},
                           {},
                           true};
      const std::optional<SweepResult>* sweeps[] = {&a.full_stroke, &a.half_stroke};
      const QString stroke_names[] = {QObject::tr("full"), QObject::tr("half")};
      for (int s = 0; s < 2; ++s) {
        if (!*sweeps[s]) continue;
        const SweepResult& sweep = **sweeps[s];
        if (!sweep.max_frequency_hz) {
          missing_limits << QObject::tr("%1 %2 stroke").arg(name, stroke_names[s]);
          continue;
        }
        AnalysisSeries& series = sweep.limit_found ? found : bound;
        series.x.push_back(s);
        series.y.push_back(*sweep.max_frequency_hz);
      }
      for (AnalysisSeries* series : {&found, &bound})
        if (!series->x.empty()) limits.series.push_back(*series);
    }
  }
  if (!missing_limits.isEmpty())
    limits.title += QObject::tr(" (no repeating range: %1)").arg(missing_limits.join(", "));
  if (!limits.series.empty() || !missing_limits.isEmpty()) result.plots.push_back(limits);
  result.summary = QObject::tr("under %1, %2.").arg(input, impact_words.join(QObject::tr("; ")));
  return result;
}

}  // namespace

AnalysisEntry action_comparison_entry() {
  AnalysisEntry e;
  e.name = QObject::tr("Upright vs grand");
  e.on_the_window_action = false;
  e.description = QObject::tr(
      "The same blow on the window's action and on the shipped action of the other kind: key "
      "and hammer motion overlaid, when and how fast each hammer strikes, and how fast each "
      "can repeat (full and half stroke)");
  const AnalysisParameter input = AnalysisParameter::choice(
      "input", QObject::tr("Blow"),
      QObject::tr("A force at the key front held a few milliseconds (a blow), or a 1 kg mass laid "
                  "on the key"),
      input_choices());
  const AnalysisParameter limits = AnalysisParameter::choice(
      "limits", QObject::tr("Repetition limits"),
      QObject::tr("also sweep each action's repetition frequency (a few seconds)"),
      {QObject::tr("with"), QObject::tr("without")});
  AnalysisParameter f_max;
  f_max.key = "f_max_hz";
  f_max.label = QObject::tr("Sweep up to");
  f_max.kind = AnalysisParameter::Kind::number;
  f_max.minimum = 5.0;
  f_max.maximum = 40.0;
  f_max.value = 25.0;
  f_max.step = 1.0;
  f_max.decimals = 0;
  f_max.unit = "Hz";
  e.parameters = {input, limits, f_max};
  e.make = [](std::shared_ptr<const ActionModel> model,
              const AnalysisSettings& settings) -> AnalysisTask {
    ComparisonOptions options;
    options.input = input_spec_of(settings.value("input").toString());
    options.repetition_limits = settings.value("limits").toString() != QObject::tr("without");
    options.f_max_full_hz = options.f_max_half_hz =
        settings.value("f_max_hz", options.f_max_half_hz).toDouble();
    return [model, options](const ProgressCallback& progress) {
      // the other kind as shipped (regulated), loaded in the worker
      const ActionModel other = load_action(model->kind == "grand" ? "upright" : "grand");
      const ActionModel* grand = model->kind == "grand" ? model.get() : &other;
      const ActionModel* upright = model->kind == "grand" ? &other : model.get();
      return comparison_result(compare_actions({grand, upright}, options, progress), options);
    };
  };
  return e;
}

}  // namespace pat::ui

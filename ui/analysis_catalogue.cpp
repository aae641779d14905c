#include "analysis_catalogue.h"

#include <QObject>
#include <algorithm>
#include <cmath>

#include "analysis/double_blow_study.h"
#include "analysis/key_fall.h"
#include "analysis/parallel_runs.h"
#include "analysis/sensitivity.h"
#include "analysis/swing_test.h"
#include "analysis/touchweight.h"
#include "analysis_entries.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "regulation/measurements.h"
#include "setting_names.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat::ui {

QString number(double value, int precision) {
  // for a class: no "nan" (a value the analysis could not find) and no "4.62e-05" or "-0" (a
  // change at rounding level, in units of mm, g, ms or m/s)
  if (!std::isfinite(value)) return QObject::tr("—");
  if (std::abs(value) < 5e-4) return QStringLiteral("0");
  return QString::fromStdString(format_number(value, precision));
}

AnalysisPlot time_plot(const QString& title, const QString& y_title,
                       std::vector<AnalysisSeries> series) {
  return {title, QObject::tr("time (s)"), "time_s", "s", y_title, std::move(series), {}, {}};
}

AnalysisSeries trace_series(const CsvTable& trace, const std::string& column, const QString& label,
                            bool points) {
  AnalysisSeries series{label, QString::fromStdString(column), {}, {}, points};
  const int t = trace.column_index("time_s"), c = trace.column_index(column);
  if (t < 0 || c < 0) return series;
  for (const auto& row : trace.rows) {
    series.x.push_back(row[t]);
    series.y.push_back(row[c]);
  }
  return series;
}

namespace {

// The seven settings measured the technician's way, against their targets.
AnalysisEntry technician_measurements() {
  AnalysisEntry e;
  e.name = QObject::tr("Technician's measurements");
  e.description = QObject::tr(
      "Every regulation setting measured as a technician measures it (rest geometry, slow key "
      "press, forte blow), with its target and tolerance");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const std::vector<SettingReading> readings = read_settings(*model, progress);
      AnalysisResult result;
      int off = 0;
      for (const SettingReading& r : readings) {
        const QString name = setting_title(r.name);
        const QString unit = QString::fromStdString(r.unit);
        if (!r.problem.empty()) {
          result.table.push_back(
              {name, QObject::tr("not measurable: %1").arg(QString::fromStdString(r.problem)),
               unit});
          ++off;
          continue;
        }
        const bool ok = r.within_tolerance();
        off += !ok;
        // millimetres to 0.01 mm as in the regulation panel; a fraction (the upright's damper
        // lift) to 0.001 of the hammer travel
        const int decimals = r.unit == "mm" ? 2 : 3;
        auto fixed = [decimals](double x) {
          return QString::fromStdString(format_fixed(x, decimals));
        };
        result.table.push_back(
            {name,
             QObject::tr("%1 (target %2 ± %3)%4%5")
                 .arg(fixed(r.measured))
                 .arg(fixed(r.target))
                 .arg(fixed(r.tolerance))
                 .arg(ok ? QString() : QObject::tr(", out of tolerance"))
                 .arg(r.note.empty() ? QString() : "; " + QString::fromStdString(r.note)),
             unit});
      }
      // the aftertouch the settings leave (technicians check dip by it), against their gauge
      try {
        const double aftertouch = measure_aftertouch(*model);
        const AgainstGauge against = aftertouch_against_gauge(aftertouch);
        // as short as the settings' values beside it ("0.94 (within 0.89–1.14)"): the dock's
        // value column is narrow
        const QString range = QStringLiteral("%1–%2").arg(
            QString::fromStdString(format_fixed(kAftertouchGaugeLowMm, 2)),
            QString::fromStdString(format_fixed(kAftertouchGaugeHighMm, 2)));
        result.table.push_back(
            {QObject::tr("aftertouch (key travel left at let-off; gauge .035–.045 in)"),
             QObject::tr("%1 (%2 %3)")
                 .arg(QString::fromStdString(format_fixed(aftertouch, 2)))
                 .arg(against == AgainstGauge::within ? QObject::tr("within")
                      : against == AgainstGauge::less ? QObject::tr("less than")
                                                      : QObject::tr("more than"))
                 .arg(range),
             QStringLiteral("mm")});
      } catch (const std::exception& e) {
        result.table.push_back({QObject::tr("aftertouch (key travel left at let-off; gauge "
                                            ".035–.045 in)"),
                                QObject::tr("not measurable: %1").arg(e.what()),
                                QStringLiteral("mm")});
      }
      result.summary = off == 0 ? QObject::tr("Every setting is within its tolerance.")
                                : QObject::tr("%1 of %2 settings are out of tolerance.")
                                      .arg(off)
                                      .arg(readings.size());
      return result;
    };
  };
  return e;
}

// Fact F2: the dynamic range of the action, impact velocity against a constant key force.
AnalysisEntry impact_velocity_range() {
  AnalysisEntry e;
  e.name = QObject::tr("Impact velocity vs key force");
  e.description = QObject::tr(
      "A constant force from 2 N (pianissimo) to 50 N (fortissimo) on the key front: the "
      "hammer's velocity at the string and the time it takes to get there");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      std::vector<double> forces;
      // geometric steps from 2 to 50 N: equal steps in loudness (dynamics are logarithmic)
      for (int i = 0; i <= 14; ++i) forces.push_back(2.0 * std::pow(25.0, i / 14.0));
      const std::size_t n = forces.size();
      std::vector<double> velocity(n, std::nan("")), time_ms(n, std::nan(""));
      const RestState rest = find_rest_state(*model);
      ProgressReporter reporter(progress, n);
      run_parallel(
          n,
          [&](std::size_t i) {
            const auto input = parse_input_spec("force:const:" + format_number(forces[i], 6),
                                                input_context(*model, rest));
            SimulationOptions options;
            options.duration_s = 0.6;  // a 2 N touch reaches the string in about 0.3 s
            options.sample_interval_s = 0.0;
            options.on_step = [&reporter](double) { return reporter.still_wanted(); };
            const SimulationResult r = simulate(*model, input.get(), options, &rest);
            for (const SimEvent& ev : r.events)
              if (ev.type == "impact") {
                velocity[i] = ev.hammer_velocity;
                time_ms[i] = ev.t * 1e3;
                break;
              }
          },
          &reporter);
      AnalysisResult result;
      AnalysisPlot vplot{QObject::tr("Hammer velocity at the string"),
                         QObject::tr("key force (N)"),
                         "key_force_n",
                         "N",
                         QObject::tr("impact velocity (m/s)"),
                         {}};
      AnalysisPlot tplot{QObject::tr("Time from touch to impact"),
                         QObject::tr("key force (N)"),
                         "key_force_n",
                         "N",
                         QObject::tr("time to impact (ms)"),
                         {}};
      AnalysisSeries v{QObject::tr("impact velocity"), "impact_velocity_mps", {}, {}, false};
      AnalysisSeries t{QObject::tr("time to impact"), "time_to_impact_ms", {}, {}, false};
      // the table: the speed under its unit (the time had shared its cell: "4.2 m/s after 31
      // ms" under m/s); both, with the force, in the grid of the blows
      AnalysisGrid blows{QObject::tr("Blows"),
                         {QObject::tr("key force (N)"), QObject::tr("impact velocity (m/s)"),
                          QObject::tr("time to impact (ms)")},
                         {}};
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(velocity[i])) {
          result.table.push_back(
              {QObject::tr("%1 N").arg(number(forces[i])), QObject::tr("no strike"), ""});
          blows.rows.push_back(
              {number(forces[i]), QObject::tr("no strike"), QObject::tr("no strike")});
          continue;
        }
        v.x.push_back(forces[i]);
        v.y.push_back(velocity[i]);
        t.x.push_back(forces[i]);
        t.y.push_back(time_ms[i]);
        lo = std::min(lo, velocity[i]);
        hi = std::max(hi, velocity[i]);
        result.table.push_back(
            {QObject::tr("%1 N").arg(number(forces[i])), number(velocity[i]), "m/s"});
        blows.rows.push_back({number(forces[i]), number(velocity[i]), number(time_ms[i])});
      }
      result.grids.push_back(blows);
      vplot.series.push_back(v);
      tplot.series.push_back(t);
      result.plots = {vplot, tplot};
      result.summary = v.x.empty()
                           ? QObject::tr("The hammer never reached the string.")
                           : QObject::tr(
                                 "from %1 m/s (softest) to %2 m/s (loudest); a piano's hammers "
                                 "reach about 1 m/s (pianissimo) to 6 m/s (fortissimo).")
                                 .arg(number(lo))
                                 .arg(number(hi));
      return result;
    };
  };
  return e;
}

namespace {

/// A sensitivity metric as the window names it: its words and its unit, from the engine's key
/// (impact_velocity_mps → "impact velocity", "m/s"; the keys stay in the CSV and JSON).
struct MetricName {
  QString words, unit;
  QString with_unit() const { return unit.isEmpty() ? words : words + " (" + unit + ")"; }
};

MetricName metric_name(const std::string& key) {
  const MetricWords named = metric_words(key);
  return {QString::fromStdString(named.words), QString::fromStdString(named.unit)};
}

}  // namespace

// Which screw matters most: every setting ±0.5 mm and what changes.
AnalysisEntry regulation_sensitivity() {
  AnalysisEntry e;
  e.name = QObject::tr("Sensitivity to each setting");
  e.description = QObject::tr(
      "Each adjuster moved 0.5 mm each way: the setting's measured value and the change of "
      "impact velocity and let-off time under a 20 N key force (and the other metrics listed)");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const SensitivityResult r = sensitivity(*model, SensitivityOptions{}, progress);
      AnalysisResult result;
      std::vector<QString> settings;
      for (const SensitivityRow& row : r.rows) settings.push_back(setting_title(row.setting));
      for (std::size_t m = 0; m < r.metrics.size(); ++m) {
        const QString metric = QString::fromStdString(r.metrics[m]);  // the CSV column's stem
        const MetricName name = metric_name(r.metrics[m]);
        // changes from the regulated action, named so ("impact_velocity_mps_minus = 0.0011"
        // read as a speed of 1 mm/s)
        AnalysisSeries minus{
            QObject::tr("adjuster −0.5 mm"), metric + "_change_minus", {}, {}, true};
        AnalysisSeries plus{QObject::tr("adjuster +0.5 mm"), metric + "_change_plus", {}, {}, true};
        for (std::size_t s = 0; s < r.rows.size(); ++s) {
          minus.x.push_back(double(s));
          minus.y.push_back(r.rows[s].minus[m] - r.baseline[m]);
          plus.x.push_back(double(s));
          plus.y.push_back(r.rows[s].plus[m] - r.baseline[m]);
        }
        // the plot's title names the metric; the axis keeps to the change and its unit, which
        // fits the dock's short plots ("change of impact velocity (m/s)" was cut off)
        AnalysisPlot plot{
            name.words,
            QObject::tr("setting"),
            "setting_index",
            "",
            name.unit.isEmpty() ? QObject::tr("change") : QObject::tr("change (%1)").arg(name.unit),
            {minus, plus}};
        plot.x_categories = settings;
        result.plots.push_back(plot);
      }
      // one row per setting: how the setting itself moved, then one row per metric
      for (const SensitivityRow& row : r.rows) {
        const QString name = setting_title(row.setting);
        // a reading taken another way is starred, with how it was taken on a row of its own
        QStringList readings;
        QStringList comments;
        for (int p = 0; p < 3; ++p) {
          const bool noted = !row.measured_note[p].empty() || !row.measured_problem[p].empty();
          readings << number(row.measured[p]) + (noted ? QStringLiteral("*") : QString());
          if (noted)
            comments << QObject::tr("* %1: %2")
                            .arg(p == 0   ? QObject::tr("−0.5 mm")
                                 : p == 1 ? QObject::tr("as given")
                                          : QObject::tr("+0.5 mm"))
                            .arg(QString::fromStdString(row.measured_problem[p].empty()
                                                            ? row.measured_note[p]
                                                            : row.measured_problem[p]));
        }
        result.table.push_back({name + QObject::tr(" measured (−0.5 / 0 / +0.5 mm)"),
                                readings.join(QStringLiteral(" / ")),
                                QString::fromStdString(row.unit)});
        for (const QString& comment : comments)
          result.table.push_back({QStringLiteral("   ") + comment, QString(), QString()});
        for (std::size_t m = 0; m < r.metrics.size(); ++m)
          result.table.push_back({QStringLiteral("   ") + metric_name(r.metrics[m]).words,
                                  QObject::tr("%1 / %2 / %3")
                                      .arg(number(row.minus[m]))
                                      .arg(number(r.baseline[m]))
                                      .arg(number(row.plus[m])),
                                  metric_name(r.metrics[m]).unit});
      }
      // which screw matters most: per metric, the settings by the change across the same turn
      // (the tab is short: the dock is narrow)
      AnalysisGrid ranking{QObject::tr("Ranking"),
                           {QObject::tr("metric"), QObject::tr("moves most"), QObject::tr("2nd"),
                            QObject::tr("3rd")},
                           {}};
      for (std::size_t m = 0; m < r.metrics.size(); ++m) {
        QStringList row{metric_name(r.metrics[m]).with_unit()};
        const std::vector<SensitivityRank> by_change = rank_by_change(r, m);
        for (std::size_t i = 0; i < 3; ++i)
          row << (i < by_change.size() ? QObject::tr("%1 (%2)")
                                             .arg(setting_title(by_change[i].setting))
                                             .arg(number(by_change[i].change))
                                       : QObject::tr("—"));
        ranking.rows.push_back(row);
      }
      result.grids.push_back(ranking);
      // the setting that moves impact velocity most for the same turn of its adjuster
      const std::vector<SensitivityRank> ranks = rank_by_change(r, 0);
      result.summary =
          ranks.empty() ? QObject::tr("no setting changed the blow measurably.")
                        : QObject::tr("%1 changes the impact velocity most (%2 m/s over ±0.5 mm).")
                              .arg(setting_title(ranks.front().setting))
                              .arg(number(ranks.front().change));
      // the repetition limit jumps between regimes rather than following a screw (README,
      // Limits): the variants that tip it are named, not read as a slope
      const auto repetition = std::find(r.metrics.begin(), r.metrics.end(), "max_repetition_hz");
      if (repetition != r.metrics.end()) {
        QStringList tipped;
        for (const MetricJump& jump : jumps_beyond(
                 r, static_cast<std::size_t>(repetition - r.metrics.begin()), kRepetitionJumpHz))
          tipped << QObject::tr("%1 %2 (%3 Hz)")
                        .arg(setting_title(jump.setting))
                        .arg(jump.side < 0 ? "−" : "+")
                        .arg(number(jump.value));
        if (!tipped.isEmpty())
          result.summary += QObject::tr(
                                " The repetition limit jumps to another regime with %1: "
                                "which screws can tip it, not a slope.")
                                .arg(tipped.join(", "));
      }
      return result;
    };
  };
  return e;
}

// Fact F5: the hammer alone on its flange, released from horizontal.
AnalysisEntry swing() {
  AnalysisEntry e;
  e.name = QObject::tr("Swing test");
  e.uses_the_settings = false;  // no contact: no adjuster reaches the hammer on its flange
  e.description = QObject::tr(
      "The hammer alone on its flange, released from horizontal: the technician counts the "
      "swings until it stops (about two round trips, 2 to 3.5, for a good centre pin)");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const SwingResult r = swing_test(*model, SwingOptions{}, progress);
      AnalysisResult result;
      result.summary = QObject::tr(
                           "%1 round trips before it stops (technicians expect about 2 to 3.5 "
                           "for a well-fitted centre pin).")
                           .arg(number(r.round_trips));
      result.table = {{QObject::tr("round trips"), number(r.round_trips), ""},
                      {QObject::tr("half swings"), QString::number(r.half_swings), ""},
                      {QObject::tr("stopped after"), number(r.stop_time_s), "s"},
                      {QObject::tr("sticking angle"), number(r.stick_angle_deg), "deg"},
                      {QObject::tr("first half period"), number(r.first_half_period_s * 1e3), "ms"},
                      {QObject::tr("pin to centre of mass"), number(r.pin_to_com_m * 1e3), "mm"}};
      result.plots.push_back(
          time_plot(QObject::tr("Hammer swing"), QObject::tr("angle from hanging (deg)"),
                    {trace_series(r.trace, "swing_angle_deg", QObject::tr("angle"))}));
      return result;
    };
  };
  return e;
}

// The paper's key characterisation: the key alone falls onto its front-rail punching.
AnalysisEntry key_fall_test() {
  AnalysisEntry e;
  e.name = QObject::tr("Key fall");
  e.description = QObject::tr(
      "The key alone released from its rest angle under gravity onto the front-rail punching: "
      "fall time, impact speed and bounces (the paper's key characterisation)");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const KeyFallResult r = key_fall(*model, KeyFallOptions{}, progress);
      AnalysisResult result;
      result.summary =
          r.fall_time_s < 0
              ? QObject::tr("the key never reached the punching.")
              : QObject::tr("reaches the punching after %1 ms at %2 m/s, %3 bounce(s).")
                    .arg(number(r.fall_time_s * 1e3))
                    .arg(number(r.impact_velocity_mps))
                    .arg(r.bounces);
      // a key that never reaches the punching has no fall time nor impact (the engine's -1)
      const bool landed = r.fall_time_s >= 0;
      const QString none = QObject::tr("never reached");
      result.table = {
          {QObject::tr("fall time"), landed ? number(r.fall_time_s * 1e3) : none, "ms"},
          {QObject::tr("fall distance"), number(r.fall_distance_mm), "mm"},
          {QObject::tr("impact velocity"), landed ? number(r.impact_velocity_mps) : none, "m/s"},
          {QObject::tr("bounces"), QString::number(r.bounces), ""},
          {QObject::tr("first rebound"), number(r.first_rebound_mm), "mm"},
          {QObject::tr("final dip"), number(r.final_dip_mm), "mm"}};
      result.plots.push_back(
          time_plot(QObject::tr("Key front"), QObject::tr("key-front dip (mm)"),
                    {trace_series(r.trace, "key_front_dip_mm", QObject::tr("dip"))}));
      result.plots.push_back(time_plot(
          QObject::tr("Punching force"), QObject::tr("force (N)"),
          {trace_series(r.trace, "punching_force_n", QObject::tr("front-rail punching"))}));
      return result;
    };
  };
  return e;
}

// Fact F9: static touchweight, Stanwood's definitions.
AnalysisEntry touchweight() {
  AnalysisEntry e;
  e.name = QObject::tr("Touchweight");
  e.description = QObject::tr(
      "Downweight and upweight at the key front (gram weights, friction included), balance "
      "and friction weight (Stanwood), key ratio and strike weight");
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const TouchweightResult r = measure_touchweight(*model, TouchweightOptions{}, progress);
      AnalysisResult result;
      // the usual range is a grand's (DESIGN.md F9, Stanwood); the references give none for an
      // upright, so it is not quoted as if it were the upright's
      const QString usual =
          model->kind == "grand"
              ? QObject::tr("a regulated grand: about 45–55 g down and 20–30 g up")
              : QObject::tr(
                    "the references give a range for grands only, about 45–55 g down and "
                    "20–30 g up; none for uprights");
      result.summary = QObject::tr("downweight %1 g, upweight %2 g (%3).")
                           .arg(number(r.downweight_g))
                           .arg(number(r.upweight_g))
                           .arg(usual);
      if (QString note = QString::fromStdString(key_rest_note(r)); !note.isEmpty()) {
        note[0] = note[0].toUpper();  // a sentence of its own after the summary's
        result.summary += " " + note + ".";
      }
      result.table = {{QObject::tr("downweight"), number(r.downweight_g), "g"},
                      {QObject::tr("upweight"), number(r.upweight_g), "g"},
                      {QObject::tr("balance weight"), number(r.balance_weight_g), "g"},
                      {QObject::tr("friction weight"), number(r.friction_weight_g), "g"},
                      {QObject::tr("front weight"), number(r.front_weight_g), "g"},
                      {QObject::tr("strike weight"), number(r.strike_weight_g), "g"},
                      {QObject::tr("key ratio"), number(r.key_ratio), ""}};
      const CsvTable t = r.table();
      AnalysisPlot plot{QObject::tr("Weights along the key dip"),
                        QObject::tr("key dip (mm)"),
                        "dip_mm",
                        "mm",
                        QObject::tr("weight (g)"),
                        {}};
      const int dip = t.column_index("dip_mm");
      for (const auto& [column, label] : std::vector<std::pair<std::string, QString>>{
               {"downweight_g", QObject::tr("downweight")},
               {"upweight_g", QObject::tr("upweight")},
               {"balance_weight_g", QObject::tr("balance weight")}}) {
        AnalysisSeries series{label, QString::fromStdString(column), {}, {}, false};
        const int c = t.column_index(column);
        for (const auto& row : t.rows) {
          series.x.push_back(row[dip]);
          series.y.push_back(row[c]);
        }
        plot.series.push_back(series);
      }
      result.plots.push_back(plot);
      return result;
    };
  };
  return e;
}

/// A double-blow variant in words: "both" → "with both parts", "no_bridle" → "without the
/// bridle strap" (the identifiers stay in the CSV and JSON).
QString variant_words(const std::string& variant) {
  if (variant == "both") return QObject::tr("with both parts");
  if (variant == "no_bridle") return QObject::tr("without the bridle strap");
  if (variant == "no_butt_spring") return QObject::tr("without the butt spring");
  if (variant == "neither") return QObject::tr("without either");
  return QString::fromStdString(variant);
}

// Fact F6: the upright's bridle strap and butt spring bring the hammer back.
AnalysisEntry double_blow() {
  AnalysisEntry e;
  e.name = QObject::tr("Double blow: bridle strap and butt spring");
  e.description = QObject::tr(
      "Two blows on the upright with and without its bridle strap and butt spring: how fast "
      "the hammer returns after the first blow, and how hard the second one strikes");
  e.applies = [](const ActionModel& m) { return m.kind == "upright"; };
  e.make = [](std::shared_ptr<const ActionModel> model, const AnalysisSettings&) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const DoubleBlowStudy r = double_blow_study(*model, DoubleBlowOptions{}, progress);
      AnalysisResult result;
      AnalysisPlot plot = time_plot(QObject::tr("Hammer angle, double blow"),
                                    QObject::tr("hammer angle (deg)"), {});
      // the return is timed on a run with a single blow (in the double blow the second blow
      // may come first), the second impact on the double blow the plot shows
      std::vector<std::pair<double, QString>> returns;  // ms, variant in words
      for (const DoubleBlowVariant& v : r.variants) {
        const QString name = QString::fromStdString(v.name);
        const QString words = variant_words(v.name);
        result.table.push_back({words + QObject::tr(": back to rest after a single blow"),
                                v.hammer_return_s < 0 ? QObject::tr("not within the run")
                                                      : number(v.hammer_return_s * 1e3),
                                "ms"});
        result.table.push_back({words + QObject::tr(": second blow's impact velocity"),
                                v.second_impact_t_s >= 0 ? number(v.second_impact_velocity_mps)
                                : v.one_stroke           ? QObject::tr("one stroke (gap too short)")
                                                         : QObject::tr("no second strike"),
                                "m/s"});
        plot.series.push_back(trace_series(r.trace, v.name + "_hammer_angle_deg", words));
        if (v.hammer_return_s >= 0) returns.push_back({v.hammer_return_s * 1e3, words});
      }
      result.plots.push_back(plot);
      std::sort(returns.begin(), returns.end());
      QStringList order;
      for (const auto& [ms, words] : returns)
        order << QObject::tr("%1 %2 ms").arg(words, number(ms));
      // what was measured, in its order (a deregulated action may not follow fact F6)
      const int never = static_cast<int>(r.variants.size() - returns.size());
      result.summary =
          order.isEmpty()
              ? QObject::tr("the hammer does not come back to rest within the run in any variant.")
              : QObject::tr(
                    "after a single blow the hammer is back on its rest first %1%2; the "
                    "plot shows the double blows.")
                    .arg(order.join(QObject::tr(", then ")))
                    .arg(never > 0 ? QObject::tr(" (%1 not within the run)").arg(never)
                                   : QString());
      return result;
    };
  };
  return e;
}

}  // namespace

std::vector<AnalysisEntry> analysis_catalogue() {
  return {technician_measurements(),
          impact_velocity_range(),
          touchweight(),
          swing(),
          key_fall_test(),
          double_blow(),
          repetition_sweep_entry(),
          action_comparison_entry(),
          regulation_sensitivity(),
          diagnosis_entry()};
}

}  // namespace pat::ui

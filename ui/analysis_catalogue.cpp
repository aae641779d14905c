#include "analysis_catalogue.h"

#include <QObject>
#include <algorithm>
#include <cmath>

#include "analysis/parallel_runs.h"
#include "analysis/sensitivity.h"
#include "core/format.h"
#include "inputs/key_input.h"
#include "regulation/measurements.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat::ui {
namespace {

QString number(double value, int precision = 3) {
  return QString::fromStdString(format_number(value, precision));
}

// The seven settings measured the technician's way, against their targets.
AnalysisEntry technician_measurements() {
  AnalysisEntry e;
  e.name = QObject::tr("Technician's measurements");
  e.description = QObject::tr(
      "Every regulation setting measured as a technician measures it (rest geometry, slow key "
      "press, forte blow), with its target and tolerance");
  e.make = [](std::shared_ptr<const ActionModel> model) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const std::size_t n = model->regulation.size();
      ProgressReporter reporter(progress, n);
      std::vector<std::optional<SettingReading>> readings(n);
      std::vector<std::string> errors(n);
      const RestState rest = find_rest_state(*model);
      run_parallel(
          n,
          [&](std::size_t i) {
            const RegulationSetting& s = model->regulation[i];
            SettingReading r;
            r.name = s.name;
            r.unit = s.unit;
            r.target = s.target;
            r.tolerance = s.tolerance;
            try {
              r.measured = measure_setting(*model, s.name, &rest);
              readings[i] = r;
            } catch (const std::exception& ex) {
              errors[i] = ex.what();
            }
          },
          &reporter);
      AnalysisResult result;
      int off = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const RegulationSetting& s = model->regulation[i];
        const QString name = QString::fromStdString(s.name);
        const QString unit = QString::fromStdString(s.unit);
        if (!readings[i]) {
          result.table.push_back(
              {name, QObject::tr("not measurable: %1").arg(QString::fromStdString(errors[i])),
               unit});
          ++off;
          continue;
        }
        const SettingReading& r = *readings[i];
        const bool ok = r.within_tolerance();
        off += !ok;
        result.table.push_back({name,
                                QObject::tr("%1 (target %2 ± %3)%4")
                                    .arg(number(r.measured))
                                    .arg(number(r.target))
                                    .arg(number(r.tolerance))
                                    .arg(ok ? QString() : QObject::tr("  OUT")),
                                unit});
      }
      result.summary = off == 0
                           ? QObject::tr("Every setting is within its tolerance.")
                           : QObject::tr("%1 of %2 settings are out of tolerance.").arg(off).arg(n);
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
  e.make = [](std::shared_ptr<const ActionModel> model) -> AnalysisTask {
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
            options.on_step = [&reporter](double) { return !reporter.cancelled(); };
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
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(velocity[i])) {
          result.table.push_back(
              {QObject::tr("%1 N").arg(number(forces[i])), QObject::tr("no strike"), ""});
          continue;
        }
        v.x.push_back(forces[i]);
        v.y.push_back(velocity[i]);
        t.x.push_back(forces[i]);
        t.y.push_back(time_ms[i]);
        lo = std::min(lo, velocity[i]);
        hi = std::max(hi, velocity[i]);
        result.table.push_back(
            {QObject::tr("%1 N").arg(number(forces[i])),
             QObject::tr("%1 m/s after %2 ms").arg(number(velocity[i])).arg(number(time_ms[i])),
             "m/s"});
      }
      vplot.series.push_back(v);
      tplot.series.push_back(t);
      result.plots = {vplot, tplot};
      result.summary = v.x.empty()
                           ? QObject::tr("The hammer never reached the string.")
                           : QObject::tr(
                                 "from %1 m/s (softest) to %2 m/s (loudest); fact F2: about "
                                 "1 to 6 m/s.")
                                 .arg(number(lo))
                                 .arg(number(hi));
      return result;
    };
  };
  return e;
}

// Which screw matters most: every setting ±0.5 mm and what changes.
AnalysisEntry regulation_sensitivity() {
  AnalysisEntry e;
  e.name = QObject::tr("Sensitivity to each setting");
  e.description = QObject::tr(
      "Each adjuster moved 0.5 mm each way: the setting's measured value and the change of "
      "impact velocity and let-off time under a 20 N key force (and the other metrics listed)");
  e.make = [](std::shared_ptr<const ActionModel> model) -> AnalysisTask {
    return [model](const ProgressCallback& progress) {
      const SensitivityResult r = sensitivity(*model, SensitivityOptions{}, progress);
      AnalysisResult result;
      std::vector<AnalysisPlot> plots;
      for (std::size_t m = 0; m < r.metrics.size(); ++m) {
        const QString metric = QString::fromStdString(r.metrics[m]);
        AnalysisSeries minus{QObject::tr("adjuster −0.5 mm"), metric + "_minus", {}, {}, true};
        AnalysisSeries plus{QObject::tr("adjuster +0.5 mm"), metric + "_plus", {}, {}, true};
        for (std::size_t s = 0; s < r.rows.size(); ++s) {
          minus.x.push_back(double(s));
          minus.y.push_back(r.rows[s].minus[m] - r.baseline[m]);
          plus.x.push_back(double(s));
          plus.y.push_back(r.rows[s].plus[m] - r.baseline[m]);
        }
        plots.push_back({QObject::tr("Change of %1").arg(metric),
                         QObject::tr("setting (index)"),
                         "setting_index",
                         "",
                         QObject::tr("change of %1").arg(metric),
                         {minus, plus}});
      }
      for (std::size_t s = 0; s < r.rows.size(); ++s) {
        const SensitivityRow& row = r.rows[s];
        QString changes;
        for (std::size_t m = 0; m < r.metrics.size(); ++m)
          changes += QObject::tr("%1: %2 → %3; ")
                         .arg(QString::fromStdString(r.metrics[m]))
                         .arg(number(row.minus[m]))
                         .arg(number(row.plus[m]));
        result.table.push_back({QObject::tr("%1. %2 (%3 → %4)")
                                    .arg(s)
                                    .arg(QString::fromStdString(row.setting))
                                    .arg(number(row.measured[0]))
                                    .arg(number(row.measured[2])),
                                changes, QString::fromStdString(row.unit)});
      }
      // the setting that moves impact velocity most, per unit of the measured setting
      int largest = -1;
      double largest_change = 0.0;
      for (std::size_t s = 0; s < r.rows.size(); ++s) {
        const double d = std::abs(r.rows[s].plus[0] - r.rows[s].minus[0]);
        if (std::isfinite(d) && d > largest_change) largest = int(s), largest_change = d;
      }
      result.summary =
          largest < 0 ? QObject::tr("no setting changed the blow measurably.")
                      : QObject::tr("%1 changes the impact velocity most (%2 m/s over ±0.5 mm).")
                            .arg(QString::fromStdString(r.rows[largest].setting))
                            .arg(number(largest_change));
      result.plots = plots;
      return result;
    };
  };
  return e;
}

}  // namespace

std::vector<AnalysisEntry> analysis_catalogue() {
  return {technician_measurements(), impact_velocity_range(), regulation_sensitivity()};
}

}  // namespace pat::ui

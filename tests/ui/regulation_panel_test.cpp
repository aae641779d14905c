// The regulation panel (issue 5): a slider moves the adjuster and the measured value follows;
// spin box and slider agree; Reset to regulated; Regulate automatically shows its steps and
// can be cancelled; the current state saved as a preset loads back with the same geometry; a
// broken preset is refused with a message naming the field.
#include "regulation_panel.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QThreadPool>
#include <atomic>
#include <cmath>

#include "analyses_panel.h"
#include "analysis_runner.h"
#include "background_pool.h"
#include "core/error.h"
#include "deregulation_runner.h"
#include "io/csv.h"
#include "main_window.h"
#include "measurement_service.h"
#include "model/preset_loader.h"
#include "playback_controller.h"
#include "regulation/deregulation.h"
#include "regulation_runner.h"
#include "run_controls.h"
#include "setting_names.h"
#include "ui_test_support.h"

using pat::ui::MainWindow;
using pat::ui::RegulationRow;
using pat::ui::test::wait_until;

class RegulationPanelTest : public QObject {
  Q_OBJECT
 private slots:
  void rows_follow_the_settings_with_their_ranges();
  void slider_moves_the_adjuster_and_the_measured_value();
  void reset_to_regulated();
  void regulate_automatically_shows_steps_and_can_be_cancelled();
  void deregulation_demo_can_be_cancelled_and_replays();
  void a_result_for_the_action_before_is_dropped();
  void deregulation_demo_shows_the_blow_shrinking();
  void deregulation_demo_rate_follows_the_setting();
  void saved_state_loads_back();
  void broken_preset_names_the_field();
  void a_runner_destroyed_before_its_task_began_sends_nothing();
};

namespace {

bool measured_all(MainWindow& window) {
  if (window.measurements()->busy()) return false;
  for (const auto& row : window.regulation()->rows())
    if (!row->measured()) return false;
  return true;
}

}  // namespace

void RegulationPanelTest::rows_follow_the_settings_with_their_ranges() {
  MainWindow window;
  window.open_action("grand");
  const pat::ActionModel& model = *window.model();
  QCOMPARE(window.regulation()->rows().size(), model.adjusters.size());
  for (const pat::Adjuster& a : model.adjusters) {
    RegulationRow* row = window.regulation()->row(a.name);
    QVERIFY(row);
    QCOMPARE(row->spin_box()->minimum(), a.min * 1e3);
    QCOMPARE(row->spin_box()->maximum(), a.max * 1e3);
    QVERIFY(row->spin_box()->toolTip().contains(QString::fromStdString(a.description)));
    // named by the setting it turns, for a screen reader ("let-off adjuster, mm from regulated")
    QVERIFY2(row->spin_box()->accessibleName().contains(pat::ui::setting_title(a.name)),
             qPrintable(row->spin_box()->accessibleName()));
    QVERIFY(row->slider()->accessibleName().contains(pat::ui::setting_title(a.name)));
  }
  // the technician's order of the preset's settings
  for (std::size_t i = 0; i < model.regulation.size(); ++i)
    QCOMPARE(window.regulation()->rows()[i]->name(), model.regulation[i].name);

  // a number typed beyond the adjuster's travel goes to its end, and the field's tooltip says
  // so (typed "99", the field had stayed at 0.00 without a word); last: moving
  // an adjuster makes a new model, which `model` above no longer is
  window.show();
  RegulationRow* checking = window.regulation()->row("checking");
  QDoubleSpinBox* spin = checking->spin_box();
  QVERIFY2(spin->toolTip().contains("Its adjuster turns from "), qPrintable(spin->toolTip()));
  auto type = [&](const QString& text) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
  };
  type("99");
  QCOMPARE(spin->value(), spin->maximum());
  type("-99");
  QCOMPARE(spin->value(), spin->minimum());
  type("0.5");
  QCOMPARE(spin->value(), 0.5);
  // an emptied field or a lone sign goes back to the value it had (it is not a 0)
  QSignalSpy changed(spin, &QDoubleSpinBox::valueChanged);
  spin->setFocus();
  spin->selectAll();
  QTest::keyClick(spin, Qt::Key_Delete);
  QTest::keyClick(spin, Qt::Key_Return);
  QCOMPARE(spin->value(), 0.5);
  type("-");
  QCOMPARE(spin->value(), 0.5);
  QCOMPARE(changed.count(), 0);
  QCOMPARE(window.model()->adjusters[window.model()->adjuster_index("checking")].value, 0.5e-3);
}

void RegulationPanelTest::slider_moves_the_adjuster_and_the_measured_value() {
  MainWindow window;
  window.show();
  window.open_action("grand");
  QVERIFY(wait_until([&] { return measured_all(window); }, 60000));
  RegulationRow* row = window.regulation()->row("hammer_blow");
  const double before = *row->measured();
  // in tolerance or not is in the text too, not in the colour alone
  QVERIFY2(row->measured_label()->text().endsWith("✓"), qPrintable(row->measured_label()->text()));

  row->slider()->setValue(100);  // capstan screwed up 1 mm: a shorter blow
  QCOMPARE(row->spin_box()->value(), 1.0);
  const int a = window.model()->adjuster_index("hammer_blow");
  QCOMPARE(window.model()->adjusters[a].value, 1e-3);
  QVERIFY(wait_until([&] { return measured_all(window); }, 60000));
  const double after = *row->measured();
  qInfo("hammer blow measured %.3f mm, after +1 mm on the capstan %.3f mm", before, after);
  QVERIFY(after < before - 1.0);  // the key ratio multiplies the capstan's millimetre
  // the tolerance colour follows the measurement
  const auto& setting = window.model()->regulation[window.model()->setting_index("hammer_blow")];
  QCOMPARE(row->out_of_tolerance(), std::abs(after - setting.target) > setting.tolerance);
  // a blow 1.5 mm short: below its target, and the reading says which way
  QVERIFY2(row->measured_label()->text().endsWith("▼"), qPrintable(row->measured_label()->text()));
  QVERIFY2(row->measured_label()->accessibleName().contains("below the target"),
           qPrintable(row->measured_label()->accessibleName()));

  // a setting that cannot be read says why in the log, once: the let-off button 0.6 mm down
  // trips the jack only after the repetition lever carries the hammer, so there is no drop to
  // read; the let-off itself is read with the drop screw out of the way, as a technician reads
  // it, far out of tolerance, and the log says how it was read (the capstan back first: 1 mm
  // up, it jams the jack in the lever's window, which no reading gets past)
  window.set_adjuster("hammer_blow", 0.0);
  window.set_adjuster("let_off", 0.6);
  QVERIFY(wait_until([&] { return window.regulation()->log_text().contains("drop: no reading"); },
                     60000));
  QVERIFY2(window.regulation()->log_text().contains("repetition lever"),
           qPrintable(window.regulation()->log_text()));
  RegulationRow* let_off_row = window.regulation()->row("let_off");
  QVERIFY(wait_until([&] { return !window.measurements()->busy(); }, 60000));
  QVERIFY(let_off_row->measured() && *let_off_row->measured() > 3.0);
  QVERIFY(let_off_row->out_of_tolerance());
  QVERIFY2(let_off_row->measured_label()->text().endsWith("▲"),
           qPrintable(let_off_row->measured_label()->text()));
  QVERIFY2(let_off_row->measured_label()->toolTip().contains("drop screw out of the way"),
           qPrintable(let_off_row->measured_label()->toolTip()));
  QVERIFY2(window.regulation()->log_text().contains("drop screw out of the way"),
           qPrintable(window.regulation()->log_text()));
  // measured again (after another adjuster moved), a reason or note already shown is not logged
  // again; a new one is
  RegulationRow* dip = window.regulation()->row("key_dip");
  QVERIFY(wait_until([&] { return !window.measurements()->busy() && dip->measured(); }, 60000));
  const double dip_before = *dip->measured();
  window.set_adjuster("key_dip", 0.5);  // half a millimetre of punching: a new reading
  QVERIFY(wait_until(
      [&] {
        return !window.measurements()->busy() && dip->measured() &&
               std::abs(*dip->measured() - dip_before) > 0.1;
      },
      60000));
  QVERIFY(!window.regulation()->row("drop")->measured());  // still unreadable
  const QStringList lines = window.regulation()->log_text().split('\n');
  for (const QString& start : {QString("drop: no reading"), QString("let-off: ")}) {
    QStringList logged;
    for (const QString& line : lines)
      if (line.startsWith(start)) logged << line;
    QVERIFY2(!logged.isEmpty(), qPrintable(start));
    for (int i = 1; i < logged.size(); ++i)
      QVERIFY2(logged[i] != logged[i - 1], qPrintable(logged[i]));
  }
}

void RegulationPanelTest::reset_to_regulated() {
  MainWindow window;
  window.open_action("upright");
  window.set_adjuster("let_off", 0.7);
  window.set_adjuster("bridle", -0.5);
  window.regulation()->show_adjusters(*window.model());
  QCOMPARE(window.regulation()->row("let_off")->value_mm(), 0.7);
  emit window.regulation()->resetRequested();
  for (const pat::Adjuster& a : window.model()->adjusters) QCOMPARE(a.value, 0.0);
  QCOMPARE(window.regulation()->row("let_off")->value_mm(), 0.0);
  QCOMPARE(window.regulation()->row("bridle")->value_mm(), 0.0);
}

void RegulationPanelTest::regulate_automatically_shows_steps_and_can_be_cancelled() {
  MainWindow window;
  window.open_action("grand");
  window.set_adjuster("hammer_blow", 1.0);
  QSignalSpy steps(window.regulation_runner(), &pat::ui::RegulationRunner::stepDone);
  QSignalSpy finished(window.regulation_runner(), &pat::ui::RegulationRunner::finished);
  window.regulate_automatically();
  QVERIFY(window.regulation_runner()->running());
  QVERIFY(wait_until([&] { return steps.count() >= 1; }, 120000));
  QVERIFY(steps.first().first().toString().contains("pass 1"));
  const auto before = window.model();
  QPushButton* cancel = nullptr;
  for (QPushButton* b : window.regulation()->findChildren<QPushButton*>())
    if (b->text() == "Cancel regulation") cancel = b;
  QVERIFY(cancel);
  cancel->click();
  QVERIFY(wait_until([&] { return finished.count() == 1; }, 120000));
  QVERIFY(!window.regulation_runner()->running());
  // the log shows the steps and the cancel; the adjusters it had half searched are not applied
  const QString log = window.regulation()->findChild<QPlainTextEdit*>()->toPlainText();
  QVERIFY2(log.contains("pass 1"), qPrintable(log));
  QVERIFY2(log.contains("Regulation cancelled"), qPrintable(log));
  QCOMPARE(window.model().get(), before.get());

  // a setting moved while a regulation runs is kept: the regulation's result, made from the
  // positions before, is dropped and the log says so
  window.regulate_automatically();
  QVERIFY(window.regulation_runner()->running());
  window.set_adjuster("let_off", 0.3);
  QVERIFY(wait_until([&] { return finished.count() == 2; }, 120000));
  const auto adjuster_mm = [&](const std::string& name) {
    return 1e3 * window.model()->adjusters[window.model()->adjuster_index(name)].value;
  };
  QCOMPARE(adjuster_mm("let_off"), 0.3);
  QCOMPARE(adjuster_mm("hammer_blow"), 1.0);
  QVERIFY2(window.regulation()->log_text().contains("Regulation dropped"),
           qPrintable(window.regulation()->log_text()));
}

void RegulationPanelTest::deregulation_demo_can_be_cancelled_and_replays() {
  MainWindow window;
  window.show();
  window.open_action("grand");
  pat::ui::DeregulationRunner* runner = window.deregulation_runner();
  QSignalSpy progress(runner, &pat::ui::DeregulationRunner::progress);
  bool done = false;
  std::size_t frame_count = 0;
  connect(runner, &pat::ui::DeregulationRunner::finished, this,
          [&](const std::vector<pat::ui::Frame>& frames, const pat::DeregulationResult& result) {
            done = true;
            frame_count = frames.size();
            QCOMPARE(result.stop_cause, std::string("cancelled"));
          });
  window.set_deregulation_demo("let_off", -1.0);
  QVERIFY_THROWS_EXCEPTION(pat::InputError, window.set_deregulation_demo("no_such_setting", 1.0));
  // watched at 1/1000 before, the replay (seconds of the run) would take half an hour: it
  // comes at 1/10
  window.run_controls()->set_speed_index(static_cast<int>(pat::ui::RunControls::speeds().size()) -
                                         1);
  window.run_deregulation_demo();
  QVERIFY(runner->running());
  // a few key cycles (3 Hz), each giving a reading for the result's table
  QVERIFY(wait_until([&] { return !progress.isEmpty() && progress.last().at(0).toDouble() >= 0.1; },
                     120000));
  runner->cancel();
  QVERIFY(wait_until([&] { return done; }, 60000));
  QVERIFY(!runner->running());
  // what was simulated before the cancel is replayed in the window
  QVERIFY(frame_count > 0);
  QVERIFY(window.controller()->replaying());
  QCOMPARE(window.controller()->history().size(), frame_count);
  QCOMPARE(window.controller()->speed(), 0.1);
  // the measured value over time is shown in the Analyses tab, titled with the chosen setting
  // in words (as the panel names it, not its identifier)
  QVERIFY2(window.analyses()->summary().contains("Deregulation of let-off"),
           qPrintable(window.analyses()->summary()));
  // the selector above does not claim the result as one of its analyses
  QVERIFY2(window.analyses()->description().startsWith("Shown: Deregulation of let-off"),
           qPrintable(window.analyses()->description()));
  // each reading's row: when and where the adjuster was, short enough to be read whole in the
  // dock, the adjuster to the thousandth (its steps are 0.075 mm on some settings)
  const QTableWidget* table = window.analyses()->table();
  QVERIFY(table->rowCount() > 0);
  const QTableWidgetItem* first_row = table->item(0, 0);
  QVERIFY2(QRegularExpression("^t = \\d+\\.\\d\\d s, adjuster [+-]?\\d+\\.\\d{3} mm$")
               .match(first_row->text())
               .hasMatch(),
           qPrintable(first_row->text()));
  QVERIFY2(QFontMetrics(table->font()).horizontalAdvance(first_row->text()) + 12 <=
               table->columnWidth(0),
           qPrintable(QString("%1 px wide in a %2 px column")
                          .arg(QFontMetrics(table->font()).horizontalAdvance(first_row->text()))
                          .arg(table->columnWidth(0))));
  window.start("");  // back to a live run
  QVERIFY(!window.controller()->replaying());
}

// Another action opened while a regulation or a demo runs: the result, when it comes, is the
// action before's and is dropped (the upright's panel had shown the grand's regulated hammer
// blow, 45 mm against its 46 mm target, and the demo replayed the grand's frames under the
// upright's legends).
void RegulationPanelTest::a_result_for_the_action_before_is_dropped() {
  MainWindow window;
  window.show();
  window.open_action("grand");
  window.set_adjuster("hammer_blow", 1.0);
  QSignalSpy regulated(window.regulation_runner(), &pat::ui::RegulationRunner::finished);
  window.regulate_automatically();
  QVERIFY(window.regulation_runner()->running());
  window.open_action("upright");
  QVERIFY(wait_until([&] { return regulated.count() == 1; }, 120000));
  QCOMPARE(window.model()->kind, std::string("upright"));
  QVERIFY2(window.statusBar()->currentMessage().contains("dropped"),
           qPrintable(window.statusBar()->currentMessage()));
  QCOMPARE(window.regulation()->row("hammer_blow")->value_mm(), 0.0);  // the upright's own
  QVERIFY(!window.regulation()->log_text().contains("egulated"));

  QSignalSpy demo_done(window.deregulation_runner(), &pat::ui::DeregulationRunner::finished);
  window.open_action("grand");
  window.run_deregulation_demo();
  QVERIFY(window.deregulation_runner()->running());
  window.open_action("upright");
  QVERIFY(wait_until([&] { return demo_done.count() == 1; }, 120000));
  QCOMPARE(window.model()->kind, std::string("upright"));
  QVERIFY(!window.controller()->replaying());
  QVERIFY2(window.statusBar()->currentMessage().contains("deregulation demo"),
           qPrintable(window.statusBar()->currentMessage()));

  // the same action opened again (its log cleared, its run restarted at rest): the demo and the
  // regulation begun before deliver nothing (the cancelled demo had been replayed over the
  // action just opened, and the regulation's steps had filled its fresh log)
  window.set_adjuster("hammer_blow", 1.0);
  window.regulate_automatically();
  window.run_deregulation_demo();
  QVERIFY(window.regulation_runner()->running() && window.deregulation_runner()->running());
  window.open_action("upright");
  QVERIFY(wait_until([&] { return regulated.count() == 2 && demo_done.count() == 2; }, 120000));
  QTest::qWait(50);  // their last steps' lines, queued before the results, are in
  QVERIFY(!window.controller()->replaying());
  QVERIFY2(!window.regulation()->log_text().contains("→") &&
               !window.regulation()->log_text().contains("Deregulation"),
           qPrintable(window.regulation()->log_text()));
  QCOMPARE(window.regulation()->row("hammer_blow")->value_mm(), 0.0);
}

// Fact F7 in the window: the hammer blow screw turned at 1 mm/s while the key plays; the demo
// runs to its own stop, the measured blow shrinks, and the Analyses tab plots every reading.
void RegulationPanelTest::deregulation_demo_shows_the_blow_shrinking() {
  MainWindow window;
  window.show();
  window.open_action("grand");
  pat::ui::DeregulationRunner* runner = window.deregulation_runner();
  bool done = false;
  pat::DeregulationResult result;
  connect(runner, &pat::ui::DeregulationRunner::finished, this,
          [&](const std::vector<pat::ui::Frame>&, const pat::DeregulationResult& r) {
            done = true;
            result = r;
          });
  window.set_deregulation_demo("hammer_blow", 1.0);
  window.run_deregulation_demo();
  QVERIFY(wait_until([&] { return done; }, 120000));
  QVERIFY2(result.stop_cause != "cancelled", result.stop_cause.c_str());
  std::vector<double> blow;
  for (const pat::DeregulationSample& sample : result.samples)
    if (std::isfinite(sample.measured)) blow.push_back(sample.measured);
  QVERIFY2(blow.size() >= 4, qPrintable(QString::number(blow.size())));
  // 0.5 mm of screw per step moves the blow by millimetres (the CLI reads 45 → 21 mm over 2 mm)
  QVERIFY2(blow.back() < blow.front() - 5.0,
           qPrintable(QString("%1 → %2 mm").arg(blow.front()).arg(blow.back())));
  const auto plots = window.analyses()->plots();
  QVERIFY(!plots.empty());
  QCOMPARE(plots.front()->point_count(0), blow.size());
  // the adjuster plot shows the screw as it was turned (engine test DeregulationPlot): as many
  // points as the run's staircase, not one per reading
  QVERIFY(plots.size() >= 2);
  QCOMPARE(plots[1]->point_count(0), pat::adjuster_steps(result.trace).t_s.size());
  // during the replay the panel turns the screw as the run turned it, cannot be moved (the
  // replay cannot change) and reads "replay" instead of the live action's measured value
  pat::ui::PlaybackController* controller = window.controller();
  QVERIFY(controller->replaying());
  controller->pause();
  const pat::ui::Frame last = controller->history().at(controller->history().size() - 1);
  controller->seek(last.t);
  const pat::ui::RegulationRow* row = window.regulation()->row("hammer_blow");
  const double turned_mm =
      last.model->adjusters[last.model->adjuster_index("hammer_blow")].value * 1e3;
  QVERIFY2(turned_mm > 1.0, qPrintable(QString::number(turned_mm)));  // 1 mm/s for seconds
  QVERIFY2(
      wait_until([&] { return std::abs(row->value_mm() - turned_mm) < 0.01; }),
      qPrintable(QString("%1 mm shown, %2 mm in the replay").arg(row->value_mm()).arg(turned_mm)));
  QVERIFY(!row->slider()->isEnabled() && !row->spin_box()->isEnabled());
  QCOMPARE(row->measured_label()->text(), QString("replay"));
  // the panel's log says why, and the way back to the live action
  QVERIFY2(window.regulation()->log_text().contains("Start from rest returns to the live action"),
           qPrintable(window.regulation()->log_text()));
  // and the status line says where the screw is in the frame shown, as the class reads it
  // (it had said "settings hammer_blow=1.2345mm")
  const QString turned = QString("a recorded replay, hammer blow +%1 mm").arg(turned_mm, 0, 'f', 2);
  // (in full: a narrow window's bar words it shorter, the whole in its tooltip)
  const QString status = window.statusBar()->toolTip().isEmpty()
                             ? window.statusBar()->currentMessage()
                             : window.statusBar()->toolTip();
  QVERIFY2(status.contains(turned), qPrintable(status + " lacks " + turned));
  // PAT_UI_SHOTS=DIR keeps a picture of the replay with its plot for a person to look at
  const QString shots = qEnvironmentVariable("PAT_UI_SHOTS");
  if (!shots.isEmpty()) {
    window.show_analyses();
    window.resize(1280, 800);
    QTest::qWait(1500);
    window.grab().save(shots + "/deregulation_demo.png");
    window.regulation()->grab().save(shots + "/deregulation_replay_panel.png");
  }
  // the replay exported with every column: the screw's position frame by frame, not the live
  // action's "regulated"
  QTemporaryDir trace_dir;
  const QString trace_path = trace_dir.filePath("replay.csv");
  window.export_run_trace(trace_path.toStdString());
  const pat::CsvTable trace = pat::read_csv(trace_path.toStdString());
  const int screw = trace.column_index("hammer_blow_mm");
  QVERIFY2(screw >= 0, "no hammer_blow_mm column");
  QVERIFY(std::abs(trace.rows.back()[screw] - turned_mm) < 1e-6);
  QCOMPARE(trace.rows.front()[screw], 0.0);
  QVERIFY(trace.metadata.at("settings").rfind("changed during the run", 0) == 0);
  // back to the live action: its screw, movable, and its measured value
  window.start("");
  QVERIFY(wait_until([&] {
    return std::abs(row->value_mm()) < 1e-9 && row->slider()->isEnabled() &&
           row->measured_label()->text().contains(" mm");
  }));
}

void RegulationPanelTest::saved_state_loads_back() {
  QTemporaryDir dir;
  MainWindow window;
  window.open_action("grand");
  window.set_adjuster("let_off", 0.6);
  const QString path = dir.filePath("deregulated.json");
  window.save_preset(path.toStdString());
  const pat::ActionModel loaded = pat::load_action(path.toStdString());
  // the offset is baked into the geometry: the let-off button sits where the slider put it
  const pat::ActionModel& current = *window.model();
  const int button = current.contact_index("jack toe–let-off button");
  QVERIFY(button >= 0);
  const auto& a = current.contacts[button];
  const auto& b = loaded.contacts[button];
  QVERIFY((a.segment_start - b.segment_start).norm() < 1e-9 ||
          (a.center_b - b.center_b).norm() < 1e-9);
  for (const pat::Adjuster& adj : loaded.adjusters) QCOMPARE(adj.value, 0.0);
}

void RegulationPanelTest::broken_preset_names_the_field() {
  QTemporaryDir dir;
  QFile source(QString::fromStdString(pat::preset_directory()) + "/grand.json");
  QVERIFY(source.open(QIODevice::ReadOnly));
  QString text = QString::fromUtf8(source.readAll());
  // the first body's mass made negative (whatever its value)
  const QRegularExpression mass("\"mass_g\":\\s*([0-9])");
  const QRegularExpressionMatch found = mass.match(text);
  QVERIFY(found.hasMatch());
  text.replace(found.capturedStart(), found.capturedLength(), "\"mass_g\": -" + found.captured(1));
  const QString path = dir.filePath("broken.json");
  QFile broken(path);
  QVERIFY(broken.open(QIODevice::WriteOnly));
  broken.write(text.toUtf8());
  broken.close();

  MainWindow window;
  window.open_action("grand");
  const auto before = window.model();
  try {
    window.open_action(path.toStdString());
    QFAIL("a broken preset was accepted");
  } catch (const pat::InputError& e) {
    const QString message = e.what();
    QVERIFY2(message.contains("broken.json") && message.contains("mass_g"), e.what());
  }
  QCOMPARE(window.model().get(), before.get());  // the running action is kept
}

// A setting chosen for the demo gets the adjuster speed that moves it about 2 mm a second (the
// engine's demo_adjuster_rate, measured on the window's action): the grand's let-off button
// (about 6 mm of let-off per mm) slower than its punchings (about 1), keeping the sign the
// teacher chose; a rate given with the setting (set_deregulation_demo) is kept.
void RegulationPanelTest::deregulation_demo_rate_follows_the_setting() {
  MainWindow window;
  window.show();
  window.open_action("grand");
  QDoubleSpinBox* rate = window.deregulation_rate();
  QVERIFY(wait_until([&] { return !window.demo_rate_pending(); }));
  QTest::qWait(50);  // the watcher's finished signal is queued
  const pat::ActionModel& model = *window.model();
  const double let_off = pat::demo_adjuster_rate(model, "let_off");
  const double key_dip = pat::demo_adjuster_rate(model, "key_dip");
  QCOMPARE(rate->value(), pat::demo_adjuster_rate(model, "hammer_blow"));
  QComboBox* setting = nullptr;
  for (QComboBox* box : window.findChildren<QComboBox*>())
    if (box->findData("let_off") >= 0 && box->findData("checking") >= 0) setting = box;
  QVERIFY(setting);
  rate->setValue(-rate->value());  // the teacher turns it the other way
  setting->setCurrentIndex(setting->findData("let_off"));
  QVERIFY(wait_until([&] { return std::abs(rate->value() + let_off) < 1e-9; }));
  setting->setCurrentIndex(setting->findData("key_dip"));
  QVERIFY(wait_until([&] { return std::abs(rate->value() + key_dip) < 1e-9; }));
  QVERIFY2(key_dip > 1.5 && let_off < 0.5, qPrintable(QString("%1, %2").arg(key_dip).arg(let_off)));
  // the settings scrolled through: one suggestion computed at a time (each had started its own,
  // taking both of the pool's threads from what was asked for next), the last one's shown
  QVERIFY(wait_until([&] { return !window.demo_rate_pending(); }));
  for (int i = 0; i < setting->count(); ++i) setting->setCurrentIndex(i);
  QVERIFY2(pat::ui::background_pool()->activeThreadCount() <= 1,
           qPrintable(QString::number(pat::ui::background_pool()->activeThreadCount())));
  const std::string last = setting->itemData(setting->count() - 1).toString().toStdString();
  const double last_rate = pat::demo_adjuster_rate(model, last);
  QVERIFY(wait_until([&] { return std::abs(std::abs(rate->value()) - last_rate) < 1e-9; }));
  // a rate given with the setting wins over the suggestion still being computed
  window.set_deregulation_demo("drop", 1.25);
  QVERIFY(wait_until([&] { return !window.demo_rate_pending(); }));
  QTest::qWait(50);
  QCOMPARE(rate->value(), 1.25);
}

// A runner destroyed while its task still waits in the pool (both threads busy, the window
// closed): Qt runs the task in the destructor's waitForFinished, on this thread. Its signals
// had then been delivered directly, into a window half taken down (a crash at exit); queued,
// they go nowhere.
void RegulationPanelTest::a_runner_destroyed_before_its_task_began_sends_nothing() {
  QThreadPool* pool = pat::ui::background_pool();
  std::atomic<bool> release{false};
  std::atomic<int> busy{0};
  for (int i = 0; i < pool->maxThreadCount(); ++i)
    pool->start([&] {
      ++busy;
      while (!release.load()) QThread::msleep(1);
    });
  auto free_pool = qScopeGuard([&] {
    release.store(true);
    pool->waitForDone();
  });
  QVERIFY(wait_until([&] { return busy.load() == pool->maxThreadCount(); }));
  const auto model = std::make_shared<const pat::ActionModel>(pat::load_action("grand"));
  {
    auto* runner = new pat::ui::RegulationRunner;
    QSignalSpy steps(runner, &pat::ui::RegulationRunner::stepDone);
    QSignalSpy finished(runner, &pat::ui::RegulationRunner::finished);
    runner->start(model);
    delete runner;
    QCOMPARE(steps.count() + finished.count(), 0);
  }
  {
    auto* runner = new pat::ui::DeregulationRunner;
    QSignalSpy progress(runner, &pat::ui::DeregulationRunner::progress);
    QSignalSpy finished(runner, &pat::ui::DeregulationRunner::finished);
    runner->start(model, pat::DeregulationOptions{});
    delete runner;
    QCOMPARE(progress.count() + finished.count(), 0);
  }
  {
    auto* runner = new pat::ui::AnalysisRunner;
    QSignalSpy progress(runner, &pat::ui::AnalysisRunner::progress);
    QSignalSpy finished(runner, &pat::ui::AnalysisRunner::finished);
    runner->start("a table", [](const pat::ProgressCallback& report) {
      report(0.5, "half");
      return pat::ui::AnalysisResult{};
    });
    delete runner;
    QCOMPARE(progress.count() + finished.count(), 0);
  }
  QCoreApplication::processEvents();  // what was posted to them is gone with them
}

QTEST_MAIN(RegulationPanelTest)
#include "regulation_panel_test.moc"

#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QResizeEvent>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QShortcut>
#include <QSplitter>
#include <QStatusBar>
#include <QStatusTipEvent>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <exception>

#include "action_view.h"
#include "analyses_panel.h"
#include "animation_export.h"
#include "background_pool.h"
#include "core/error.h"
#include "deregulation_runner.h"
#include "export_folder.h"
#include "export_size_dialog.h"
#include "focused_input_keys.h"
#include "input_spec_form.h"
#include "inputs/key_input.h"
#include "measurement_service.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "playback_controller.h"
#include "plot_export.h"
#include "plot_panel.h"
#include "plot_stack.h"
#include "practice_panel.h"
#include "regulation/deregulation.h"
#include "regulation/regulation.h"
#include "regulation_panel.h"
#include "regulation_runner.h"
#include "run_controls.h"
#include "run_trace_export.h"
#include "save_paths.h"
#include "setting_names.h"
#include "status_fit.h"

namespace pat::ui {
namespace {

// the same action, adjusters and removed parts aside: its kind from the same file (or shipped)
bool same_action(const ActionModel& a, const ActionModel& b) {
  return a.kind == b.kind && a.source_file == b.source_file;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("Piano Action Trainer"));
  controller_ = new PlaybackController(this);

  auto* central = new QWidget(this);
  auto* column = new QVBoxLayout(central);
  column->setContentsMargins(2, 2, 2, 2);
  column->setSpacing(2);
  // the run controls span the whole window width, above the regulation panel too
  run_controls_ = new RunControls(controller_, this);
  QToolBar* bar = addToolBar(tr("Run"));
  bar->setObjectName("run_toolbar");
  bar->setMovable(false);
  bar->addWidget(run_controls_);
  banner_ = new QLabel(central);
  banner_->setWordWrap(true);
  banner_->setStyleSheet(
      "background: #c0392b; color: white; font-weight: bold; padding: 6px; font-size: 11pt;");
  banner_->hide();
  column->addWidget(banner_);
  split_ = new QSplitter(Qt::Vertical, central);
  view_ = new ActionView(split_);
  plots_ = new PlotStack(split_);
  split_->addWidget(view_);
  split_->addWidget(plots_);
  split_->setStretchFactor(0, 1);
  split_->setStretchFactor(1, 1);
  split_->setSizes({330, 370});
  column->addWidget(split_, 1);
  setCentralWidget(central);

  regulation_ = new RegulationPanel;
  regulation_scroll_ = new QScrollArea;
  auto* scroll = regulation_scroll_;
  scroll->setWidget(regulation_);
  scroll->setWidgetResizable(true);
  auto* dock = new QDockWidget(tr("Regulation"), this);
  dock->setObjectName("regulation_dock");
  dock->setWidget(scroll);
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  regulation_dock_ = dock;

  // analyses of the current action (with whatever the sliders have done to it)
  analyses_ = new AnalysesPanel([this] { return model_; });
  auto* analyses_dock = analyses_dock_ = new QDockWidget(tr("Analyses"), this);
  analyses_dock->setObjectName("analyses_dock");
  analyses_dock->setWidget(analyses_);
  analyses_dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  addDockWidget(Qt::RightDockWidgetArea, analyses_dock);
  tabifyDockWidget(dock, analyses_dock);
  dock->raise();
  connect(analyses_, &AnalysesPanel::exportRequested, this,
          [this](const std::vector<PlotPanel*>& plots, const QString& what) {
            const int result = analyses_->result_serial();
            export_from_menu(plots, what, false,
                             [this, result] { return analyses_->result_serial() == result; });
          });

  connect(controller_, &PlaybackController::frameShown, view_, &ActionView::show_frame);
  connect(controller_, &PlaybackController::framesPassed, plots_, &PlotStack::append);
  connect(controller_, &PlaybackController::frameShown, this, [this](const Frame& frame) {
    plots_->mark_time(frame.t);
    // a replay's screw turns in the panel as it turned in the run (not in practice: that would
    // show the hidden setting)
    if (controller_->replaying() && !practising_ && frame.model &&
        frame.model != replay_model_shown_) {
      replay_model_shown_ = frame.model;
      regulation_->set_replay(frame.model.get());
      // and the status line says where the screw is now
      running_input_ = tr("a recorded replay, %1").arg(adjuster_settings_words(*frame.model));
      show_run_status();
    }
    // paused: a step or seek moves its time; playing frames recorded before (after a rewind),
    // the input that drove them, as it changes
    if (!controller_->playing() ||
        (!controller_->replaying() && controller_->input_at(frame.t) != running_input_shown_))
      show_run_status();
    if (practice_test_end_s_ >= 0.0 && frame.t >= practice_test_end_s_) {
      // the test shown has played what it read (four repeated notes, not the 24 the input
      // would go on to in its 8 s): the action stops there, for the class to count; Play
      // lets it run on
      controller_->pause();
      end_practice_test_shown();
    }
  });
  connect(controller_, &PlaybackController::runStopped, this, [this](const QString& cause) {
    end_practice_test_shown();  // what it found is not kept waiting for a run that cannot go on
    show_run_status();
    // what made it diverge may be a moved setting or the input itself (a file's huge force)
    const bool moved = model_ && adjuster_settings_text(*model_) != "regulated";
    show_banner((moved ? tr("Run paused at t = %1 ms: %2. Move a setting back, or choose a "
                            "gentler input, and press \"Start from rest\".")
                       : tr("Run paused at t = %1 ms: %2. Choose a gentler input and press "
                            "\"Start from rest\"."))
                    .arg(controller_->display_time() * 1e3, 0, 'f', 2)
                    .arg(cause));
  });
  connect(controller_, &PlaybackController::runRefused, this, [this](const QString& why) {
    end_practice_test_shown();  // a run that cannot start plays no test
    show_run_status();
    show_banner(tr("Could not start: %1. Choose another input, or fix the setting or the file, "
                   "and press \"Start from rest\".")
                    .arg(why));
  });
  // a blow struck, a key played or the run played on: a refused input's or a stopped run's
  // banner is old news (it stayed red over the next run)
  connect(controller_, &PlaybackController::inputChanged, this, [this](const QString& what) {
    running_input_ = what;
    hide_banner();
    show_run_status();
    // a blow struck or the key played into a practice test on screen: the test is over, and the
    // user's own blow is not paused at the test's end (a test's own input is noted while its run
    // starts, before show_practice_test sets that end; its generated input has no notes that
    // would be noted again later)
    end_practice_test_shown();
  });
  connect(controller_, &PlaybackController::playingChanged, this, [this](bool playing) {
    if (playing) {
      setting_waits_ = false;
      hide_banner();
    }
    show_run_status();
  });
  // moved through the run after a screw turned while paused: the status line names the step
  // keys again (frames computed since act with the new setting; those before never had it)
  connect(controller_, &PlaybackController::navigated, this, [this] {
    if (!setting_waits_) return;
    setting_waits_ = false;
    show_run_status();
  });
  connect(controller_, &PlaybackController::runRestarted, this, [this] {
    setting_waits_ = false;
    end_practice_test_shown();  // another run replaces the test on screen
    hide_banner();
    plots_->clear();
    if (!controller_->replaying()) {
      replay_model_shown_.reset();
      if (regulation_->replaying()) {  // the live action again
        regulation_->set_replay(nullptr);
        if (model_) regulation_->show_adjusters(*model_);
      }
    }
  });
  connect(view_, &ActionView::keyPlayed, controller_, &PlaybackController::play_key);
  connect(view_, &ActionView::keyReleased, controller_, &PlaybackController::release_key);
  connect(run_controls_, &RunControls::startRequested, this, &MainWindow::start);
  connect(regulation_, &RegulationPanel::adjusterChanged, this, &MainWindow::set_adjuster);
  connect(regulation_, &RegulationPanel::resetRequested, this, [this] {
    if (!model_) return;
    if (regulation_->replaying()) {  // the rows show the replay's screws; the live action waits
      statusBar()->showMessage(tr("A replay is on screen: Start from rest first, then reset."));
      return;
    }
    auto regulated = std::make_shared<ActionModel>(*model_);
    for (const Adjuster& a : model_->adjusters) *regulated = with_adjuster(*regulated, a.name, 0.0);
    regulation_->show_adjusters(*regulated);
    regulation_->log(tr("Reset: every adjuster at its regulated position."));
    change_model(regulated);
  });

  // the whole of a run's status shortened to fit the bar is in its tooltip; another message
  // (an export written, a refusal) takes the tooltip away with it (the fitted status sets it
  // again after its message)
  connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& message) {
    if (message != run_status_shown_) statusBar()->setToolTip(QString());
  });

  // live measured values and automatic regulation, both off the window's thread
  measurements_ = new MeasurementService(this);
  connect(measurements_, &MeasurementService::measured, this,
          [this](const QString& name, double value, const QString& note) {
            RegulationRow* row = regulation_->row(name.toStdString());
            // how it was read goes to the log once too, as a failed reading's reason does
            if (row && row->set_measured(value, note) && !note.isEmpty() && !practising_)
              regulation_->log(tr("%1: %2 %3.")
                                   .arg(setting_title(name.toStdString()),
                                        setting_value_text(value, row->unit()), note));
          });
  connect(measurements_, &MeasurementService::failed, this,
          [this](const QString& name, const QString& reason) {
            // the reason also goes to the log once (a tooltip alone is not seen in class)
            if (RegulationRow* row = regulation_->row(name.toStdString())) {
              if (row->set_measurement_failed(reason) && !practising_)
                regulation_->log(tr("%1: no reading. %2")
                                     .arg(setting_title(name.toStdString()),
                                          reason.left(1).toUpper() + reason.mid(1)));
            } else
              regulation_->log(tr("Cannot measure: %1").arg(reason));
          });
  regulation_runner_ = new RegulationRunner(this);
  regulate_button_ = regulation_->add_button(
      tr("Regulate automatically"),
      tr("Each adjuster searched in the technician's order (secant steps, kept bracketed), "
         "repeated until every measurement is within tolerance; the steps are listed below"));
  connect(regulate_button_, &QPushButton::clicked, this, [this] {
    if (regulation_runner_->running()) {
      regulation_cancelled_ = true;  // the adjusters it had half searched are not applied
      regulation_runner_->cancel();
    } else {
      regulate_automatically();
    }
  });
  connect(regulation_runner_, &RegulationRunner::stepDone, this, [this](const QString& line) {
    if (regulation_opened_at_ == actions_opened_)
      regulation_->log(line);  // not into the log of an action opened meanwhile
  });
  connect(regulation_runner_, &RegulationRunner::finished, this,
          [this](std::shared_ptr<const ActionModel> model, bool converged, const QString& msg) {
            regulate_button_->setText(tr("Regulate automatically"));
            if (!model_ || regulation_opened_at_ != actions_opened_) {  // an action opened since
              statusBar()->showMessage(
                  tr("The regulation of the %1 was dropped: an action was opened while it ran.")
                      .arg(QString::fromStdString(model->name)));
              return;
            }
            if (regulation_cancelled_) {
              regulation_->log(tr("Regulation cancelled: the adjusters stay where they were."));
              return;
            }
            // a setting moved (or an exercise begun) while it ran: the result belongs to the
            // action it started from, and applying it would undo that change unseen
            if (model_ != regulation_model_) {
              regulation_->log(
                  tr("Regulation dropped: the action was changed while it ran (Regulate "
                     "automatically starts again from the current positions)."));
              return;
            }
            regulation_->log(converged ? tr("Regulated: %1.").arg(msg)
                                       : tr("Not regulated: %1.").arg(msg));
            regulation_->show_adjusters(*model);
            change_model(model);
          });

  deregulation_runner_ = new DeregulationRunner(this);
  deregulate_button_ = regulation_->add_button(
      tr("Deregulation demo"),
      tr("An adjuster (the capstan for hammer_blow, as in the paper, section 7.2) moved in steps "
         "every 0.5 s while the key plays a 3 Hz sine, until the action fails; then replayed, "
         "with the measured value over time in the Analyses tab"));
  auto* demo_options = new QWidget(regulation_);
  auto* demo_row = new QHBoxLayout(demo_options);
  demo_row->setContentsMargins(0, 0, 0, 0);
  deregulation_setting_ = new QComboBox(demo_options);
  deregulation_setting_->setToolTip(tr("The setting whose adjuster the demo moves"));
  deregulation_rate_ = new QDoubleSpinBox(demo_options);
  deregulation_rate_->setRange(-2.0, 2.0);
  deregulation_rate_->setSingleStep(0.05);
  deregulation_rate_->setValue(1.0);
  deregulation_rate_->setSuffix(tr(" mm/s"));
  deregulation_rate_->setToolTip(
      tr("How fast the adjuster moves (in steps every 0.5 s); the sign is the adjuster's own "
         "direction. A setting chosen gets the speed that moves the setting itself about 2 mm a "
         "second, a millimetre per turn: the adjusters' ratios differ (the grand's let-off "
         "button moves the let-off about 6 mm per mm, its capstan the blow about 12)"));
  demo_rate_watcher_ = new QFutureWatcher<double>(this);
  connect(demo_rate_watcher_, &QFutureWatcherBase::finished, this, [this] {
    if (demo_rate_start_waits_) {  // a newer suggestion waited for this one: it starts now
      demo_rate_start_waits_ = false;
      if (demo_rate_request_running_ == demo_rate_request_) start_demo_rate_suggestion();
      return;
    }
    if (demo_rate_request_running_ != demo_rate_request_) return;  // overridden or superseded
    const double rate = demo_rate_watcher_->result();
    if (!std::isfinite(rate)) return;
    const QSignalBlocker own_change(deregulation_rate_);  // not the teacher's setting (below)
    deregulation_rate_->setValue(std::copysign(rate, deregulation_rate_->value()));
  });
  // a rate the teacher sets while a suggestion is on its way wins over it
  connect(deregulation_rate_, &QDoubleSpinBox::valueChanged, this,
          [this] { ++demo_rate_request_; });
  connect(deregulation_setting_, &QComboBox::currentIndexChanged, this,
          &MainWindow::suggest_demo_rate);
  demo_row->addWidget(new QLabel(tr("Demo moves"), demo_options));
  demo_row->addWidget(deregulation_setting_, 1);
  demo_row->addWidget(new QLabel(tr("at"), demo_options));
  demo_row->addWidget(deregulation_rate_);
  regulation_->add_widget(demo_options);
  progress_ = new QProgressBar(regulation_);
  progress_->setRange(0, 100);
  progress_->hide();
  regulation_->layout()->addWidget(progress_);
  connect(deregulate_button_, &QPushButton::clicked, this, [this] {
    if (deregulation_runner_->running())
      deregulation_runner_->cancel();
    else
      run_deregulation_demo();
  });
  connect(deregulation_runner_, &DeregulationRunner::progress, this,
          [this](double f) { progress_->setValue(int(100 * f)); });
  connect(deregulation_runner_, &DeregulationRunner::finished, this,
          [this](const std::vector<Frame>& frames, const DeregulationResult& result) {
            progress_->hide();
            deregulate_button_->setText(tr("Deregulation demo"));
            // an action opened since (the same one opened again too: its log was cleared, its
            // run restarted at rest)
            if (!model_ || !demo_model_ || demo_opened_at_ != actions_opened_) {
              statusBar()->showMessage(
                  tr("The deregulation demo of the %1 was dropped: an action was opened while it "
                     "ran.")
                      .arg(QString::fromStdString(demo_model_ ? demo_model_->name : "")));
              return;
            }
            if (practising_) {  // an exercise began meanwhile: its action stays on screen
              statusBar()->showMessage(
                  tr("The deregulation demo was dropped: a practice exercise began."));
              return;
            }
            const std::string& id = demo_setting_;  // as the demo ran, whatever is chosen now
            const int index = model_ ? model_->setting_index(id) : -1;
            const std::string unit = index >= 0 ? model_->regulation[index].unit : "mm";
            for (const DeregulationSample& s : result.samples)
              regulation_->log(tr("t = %1 s  adjuster %2 mm  %3 reads %4")
                                   .arg(s.t, 0, 'f', 2)
                                   .arg(adjuster_mm_text(s.adjuster_mm, 2))
                                   .arg(setting_title(id))
                                   .arg(setting_value_text(s.measured, unit)));
            // the failure in a technician's words first, the model's own after it
            const std::string words = stop_in_trade_words(result.stop_cause);
            regulation_->log(
                result.stop_cause.empty() ? tr("Deregulation: the action held to the end.")
                : words == result.stop_cause
                    ? tr("Deregulation stopped at t = %1 s: %2")
                          .arg(result.stop_t, 0, 'f', 2)
                          .arg(QString::fromStdString(result.stop_cause))
                    : tr("Deregulation stopped at t = %1 s: %2. (In the model's terms: %3)")
                          .arg(result.stop_t, 0, 'f', 2)
                          .arg(QString::fromStdString(words),
                               QString::fromStdString(result.stop_cause)));
            show_deregulation_result(result);
            if (!frames.empty()) {
              // the replay spans seconds of the run: at 1/1000 it would take half an hour, so
              // a slower speed than 1/10 becomes 1/10 (the class can slow it down again)
              const auto& speeds = RunControls::speeds();
              const auto tenth = std::find(speeds.begin(), speeds.end(), 0.1);
              if (tenth != speeds.end() && controller_->speed() < 0.1)
                run_controls_->set_speed_index(static_cast<int>(tenth - speeds.begin()));
              controller_->replay(frames);
              statusBar()->showMessage(
                  tr("Replaying the deregulation demo; Start from rest "
                     "returns to the live action."));
            }
          });

  build_practice();
  build_menus();
  build_shortcuts();
  statusBar()->showMessage(
      tr("Drag the key front (blue ring) to play the key; space strikes a "
         "blow."));
  restore_settings();
}

MainWindow::~MainWindow() {
  // the demo rate's measurement holds no pointer into the window, but the engine must not still
  // be working when the program's statics go at exit
  demo_rate_watcher_->waitForFinished();
}

void MainWindow::show_analyses() {
  if (!practising_) show_side_panels(true);  // a result shown in a hidden panel is lost on a class
  analyses_dock_->raise();
}

void MainWindow::show_side_panels(bool on) {
  if (side_panels_action_ && side_panels_action_->isChecked() != on) {
    side_panels_action_->setChecked(on);  // its toggled signal comes back here
    return;
  }
  side_panels_shown_ = on;
  show_side_docks(practising_);
}

void MainWindow::show_side_docks(bool practising) {
  regulation_dock_->setVisible(side_panels_shown_ && !practising);
  analyses_dock_->setVisible(side_panels_shown_ && !practising);
}

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  open_preset_action_ = file->addAction(tr("&Open preset…"), QKeySequence::Open, this,
                                        &MainWindow::open_preset_from_menu);
  save_preset_action_ = file->addAction(tr("&Save current state as preset…"), QKeySequence::Save,
                                        this, &MainWindow::save_preset_from_menu);
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* action = menuBar()->addMenu(tr("&Action"));
  auto* group = new QActionGroup(this);
  grand_action_ = action->addAction(tr("&Grand (double escapement)"));
  upright_action_ = action->addAction(tr("&Upright"));
  for (QAction* a : {grand_action_, upright_action_}) {
    a->setCheckable(true);
    group->addAction(a);
  }
  // another action opens at rest and waits, as the window does at launch
  connect(grand_action_, &QAction::triggered, this, [this] {
    open_action("grand");
    hold_at_rest();
  });
  connect(upright_action_, &QAction::triggered, this, [this] {
    open_action("upright");
    hold_at_rest();
  });

  QMenu* exports = menuBar()->addMenu(tr("&Export"));
  measurement_actions_.push_back(
      exports->addAction(tr("&All plots…"), QKeySequence(tr("Ctrl+E")), this,
                         [this] { export_from_menu(plots_->panels(), tr("all plots"), true); }));
  QMenu* one = exports->addMenu(tr("One &plot"));
  measurement_actions_.push_back(one->menuAction());
  for (PlotPanel* panel : plots_->panels()) {
    const QString title = panel->title();
    one->addAction(title + "…", this, [this, title] {
      for (PlotPanel* p : plots_->panels())
        if (p->title() == title) export_from_menu({p}, title, true);
    });
  }
  measurement_actions_.push_back(
      exports->addAction(tr("Run &trace, every column (CSV)…"), this, [this] {
        export_to_chosen_file(tr("the run trace"), tr("CSV (*.csv)"), true,
                              [this](const QString& path) {
                                export_run_trace(path.toStdString());
                                return QStringList{path};
                              });
      }));
  exports->addAction(tr("Action a&nimation (PNG pictures)…"), this,
                     [this] { export_animation_from_menu(); });
  exports->addAction(tr("Export &size…"), this,
                     [this] { export_size_ = ask_export_size(this, export_size_); });
  exports->addSeparator();
  exports->addAction(tr("&Window screenshot…"), this, [this] {
    export_to_chosen_file(
        tr("the window screenshot"), tr("PNG images (*.png);;JPEG images (*.jpg)"), false,
        [this](const QString& path) {
          // the format from the name's suffix
          if (!grab().save(path))
            throw InputError(path.toStdString() +
                             ": could not write the picture (a .png or .jpg name is needed, in "
                             "a folder that can be written)");
          return QStringList{path};
        });
  });

  QMenu* view = menuBar()->addMenu(tr("&View"));
  large_text_action_ = view->addAction(tr("Larger &text (for a class)"));
  large_text_action_->setCheckable(true);
  large_text_action_->setShortcut(QKeySequence(tr("Ctrl+Shift+L")));
  connect(large_text_action_, &QAction::toggled, this, &MainWindow::set_large_text);
  side_panels_action_ = view->addAction(tr("Side &panels (regulation, analyses)"));
  side_panels_action_->setCheckable(true);
  side_panels_action_->setChecked(true);
  side_panels_action_->setShortcut(QKeySequence(tr("Ctrl+Shift+D")));
  connect(side_panels_action_, &QAction::toggled, this, &MainWindow::show_side_panels);
  QAction* labels = view->addAction(tr("Show &labels"));
  labels->setCheckable(true);
  labels->setChecked(true);
  connect(labels, &QAction::toggled, view_, &ActionView::set_labels_visible);
  QAction* cursors = view->addAction(tr("Plot &cursors (click A, right click B)"));
  cursors->setCheckable(true);
  cursors->setChecked(true);
  connect(cursors, &QAction::toggled, this, [this](bool on) {
    for (PlotPanel* p : plots_->panels()) p->set_cursors_enabled(on);
  });
  QAction* follow = view->addAction(tr("Plots &follow the time"));
  follow->setCheckable(true);
  follow->setChecked(true);
  connect(follow, &QAction::toggled, plots_, &PlotStack::set_following);
  connect(plots_, &PlotStack::followingChanged, follow, &QAction::setChecked);
  // how much time the followed plots span: a blow's strike and catch, or a whole slow press
  QMenu* span = view->addMenu(tr("Plot time &span"));
  measurement_actions_.push_back(span->menuAction());
  auto* spans = new QActionGroup(span);
  const std::vector<double> span_choices{0.05, 0.25, 1.0, 2.0, 5.0};
  // the remembered span, or the listed one nearest it (a hand-edited setting)
  const double remembered = QSettings().value("view/plot_span_s", 0.25).toDouble();
  double chosen = 0.25;
  for (const double seconds : span_choices)
    if (std::abs(std::log(seconds / remembered)) < std::abs(std::log(chosen / remembered)))
      chosen = seconds;
  for (const double seconds : span_choices) {
    QAction* a =
        span->addAction(seconds < 1.0 ? tr("%1 ms").arg(seconds * 1e3) : tr("%1 s").arg(seconds));
    a->setCheckable(true);
    a->setChecked(std::abs(seconds - chosen) < 1e-9);
    spans->addAction(a);
    connect(a, &QAction::triggered, this, [this, seconds] {
      QSettings().setValue("view/plot_span_s", seconds);
      plots_->set_window(seconds);
      plots_->set_following(true);
    });
  }
  plots_->set_window(chosen);
  // ticked while the plots show the whole run (it lasts through new runs): unticked, they follow
  QAction* whole = view->addAction(tr("Plots show the &whole run"));
  whole->setShortcut(QKeySequence(tr("Ctrl+Shift+W")));
  whole->setCheckable(true);
  connect(whole, &QAction::triggered, this, [this](bool on) {
    if (on)
      plots_->show_whole_run();
    else
      plots_->set_following(true);
  });
  connect(plots_, &PlotStack::wholeRunChanged, whole, &QAction::setChecked);
  measurement_actions_.push_back(whole);
  QMenu* practice = menuBar()->addMenu(tr("&Practice"));
  // its own action, not the dock's toggleViewAction: Qt disables that one for a dock without a
  // close button, and this dock has none (below)
  practice_action_ = practice->addAction(tr("&Practice mode (find a hidden deregulation)"));
  practice_action_->setCheckable(true);
  practice_action_->setShortcut(QKeySequence(tr("Ctrl+P")));
  connect(practice_action_, &QAction::toggled, this, &MainWindow::show_practice);
  view->addSeparator();
  view->addAction(tr("Fit the &action"), QKeySequence(tr("Ctrl+1")), this,
                  [this] { view_->set_focus(ViewFocus::whole); });
  view->addAction(tr("Close-up: &escapement (jack, knuckle or butt, let-off button)"),
                  QKeySequence(tr("Ctrl+2")), this,
                  [this] { view_->set_focus(ViewFocus::escapement); });
  view->addAction(tr("Close-up: c&hecking (hammer head and tail, backcheck)"),
                  QKeySequence(tr("Ctrl+3")), this,
                  [this] { view_->set_focus(ViewFocus::checking); });
}

void MainWindow::set_large_text(bool on) {
  if (large_text_action_ && large_text_action_->isChecked() != on) {
    large_text_action_->setChecked(on);  // its toggled signal comes back here
    return;
  }
  if (base_point_size_ <= 0.0) base_point_size_ = QApplication::font().pointSizeF();
  large_text_ = on;
  QFont font = QApplication::font();
  font.setPointSizeF(base_point_size_ * (on ? kClassTextScale : 1.0));
  // the window's width before the text changes: the layouts may widen it before the dock is
  // fitted, and a window already pushed past a 1024-pixel projector must not count as the room
  const int width_before = width();
  QApplication::setFont(font);
  // the dock follows its columns, which grow or shrink with the text once the layouts have taken
  // the new font (their size requests are events of their own)
  QTimer::singleShot(0, this, [this, width_before] {
    fit_regulation_dock(true, width_before);
    refit_run_status();  // the status line's text grew or shrank with the rest
  });
  QSettings().setValue("view/large_text", on);
}

void MainWindow::fit_regulation_dock(bool within_screen, int width_before) {
  if (!regulation_scroll_) return;
  // the whole panel visible without a horizontal scroll bar, at its smallest (sliders at their
  // minimum width) so that the window still fits a 1024-pixel projector
  int wanted = regulation_->minimumSizeHint().width() + 24;
  // when the text grows on a shown window: never so wide that the window must outgrow its screen
  // (the toolbar's Start button and the dock's right edge were cut off in larger text); beyond
  // that the dock scrolls. Not when an action opens: the window may not have its size yet (an
  // offscreen screenshot's 1280 pixels on an 800-pixel virtual screen). 15 pixels are the dock's
  // separator and frame
  int window_room = 0;
  if (within_screen && screen()) {
    window_room =
        std::max(screen()->availableGeometry().width(), width_before > 0 ? width_before : width());
    const int room = window_room - centralWidget()->minimumSizeHint().width() - 15;
    if (room > 200) wanted = std::min(wanted, room);
  }
  regulation_scroll_->setMinimumWidth(wanted);
  // a window the larger text had already pushed past that room comes back onto its screen (at
  // 1024x768 it had grown to 1257 pixels, the dock's edge and the Start button off screen)
  if (window_room > 0 && width() > window_room)
    QTimer::singleShot(0, this, [this, window_room] {
      if (width() > window_room) resize(std::max(window_room, minimumSizeHint().width()), height());
    });
}

void MainWindow::build_shortcuts() {
  // a focused combo box, field, list or slider keeps the keys it uses (focused_input_keys.h)
  qApp->installEventFilter(new FocusedInputKeys(this));
  auto shortcut = [this](const QKeySequence& keys, auto slot) {
    auto* s = new QShortcut(keys, this);
    connect(s, &QShortcut::activated, this, slot);
  };
  shortcut(QKeySequence(Qt::Key_Space),
           [this] { controller_->strike(run_controls_->blow_spec()); });
  for (int level = 1; level <= 5; ++level) {
    shortcut(QKeySequence(Qt::Key_0 + level), [this, level] {
      run_controls_->set_blow_level(level);
      controller_->strike(run_controls_->blow_spec(level));
    });
  }
  shortcut(QKeySequence(Qt::Key_P), [this] {
    if (controller_->playing())
      controller_->pause();
    else
      controller_->play();
  });
  shortcut(QKeySequence(Qt::Key_Right), [this] { controller_->step_forward(); });
  shortcut(QKeySequence(Qt::Key_Left), [this] { controller_->step_back(); });
  shortcut(QKeySequence(Qt::SHIFT | Qt::Key_Right),
           [this] { controller_->step_forward(PlaybackController::kLargeStepFrames); });
  shortcut(QKeySequence(Qt::SHIFT | Qt::Key_Left),
           [this] { controller_->step_back(PlaybackController::kLargeStepFrames); });
  shortcut(QKeySequence(Qt::Key_Home), [this] { controller_->rewind(); });
}

void MainWindow::build_practice() {
  practice_ = new PracticePanel;  // it scrolls its own form, under a status line kept in view
  practice_dock_ = new QDockWidget(tr("Practice"), this);
  practice_dock_->setObjectName("practice_dock");
  practice_dock_->setWidget(practice_);
  addDockWidget(Qt::RightDockWidgetArea, practice_dock_);
  // a tab beside the regulation and the analyses: the whole height of the dock area, not a
  // third of it under them
  tabifyDockWidget(regulation_dock_, practice_dock_);
  practice_dock_->hide();
  regulation_dock_->raise();  // the regulation tab in front, as before the practice tab joined
  connect(practice_, &PracticePanel::modelChanged, this, &MainWindow::practise_on);
  connect(practice_, &PracticePanel::testShown, this, &MainWindow::show_practice_test);
  practice_->set_readings_wait_for_playback(true);  // the window plays each test first
  // the regulation panel shows true adjuster positions and measured values, the analyses
  // measure every setting against its target: both hidden while an exercise runs; closing the
  // practice dock returns to the regulated action
  connect(practice_, &PracticePanel::practiceActive, this, [this](bool active) {
    if (active && !practice_took_over_) {  // the class's own input and speed, given back after
      input_before_practice_ = run_controls_->input_form()->spec();
      speed_before_practice_ = run_controls_->speed_index();
      practice_took_over_ = true;
    }
    practising_ = active;
    set_practice_layout(active);
    // a regulation or demo of the class's action ends: its result would land on the exercise
    if (active) {
      regulation_runner_->cancel();
      deregulation_runner_->cancel();
    }
  });
  // scored: the exercise is over and its answer on show, so the measurements, the other actions
  // and the presets come back (they had stayed locked until practice mode was left, with nothing
  // to say so); the regulation panel shows the hidden settings beside the answer, and the
  // practice tab stays in front with the score
  connect(practice_, &PracticePanel::scored, this, [this] {
    practising_ = false;
    set_practice_layout(false);
    practice_dock_->raise();
    if (!model_) return;
    // the panels shown again belong to the exercise's action: its analyses, its adjusters as
    // the trainee left them (the rows had kept the positions from before the exercise: a lever
    // height left at -0.02 mm read 0.00) and its readings (an exercise on the other kind of
    // action had left the class's in them)
    analyses_->set_model(*model_);
    regulation_->show_adjusters(*model_);
    measure_current_model();
  });
  // the dock is opened and closed from the Practice menu only (no close button): hiding it
  // behind a tab or closing the window must not end an exercise
  practice_dock_->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
}

void MainWindow::set_practice_layout(bool practising) {
  // the regulation panel shows true adjuster positions and measured values, the analyses measure
  // every setting against its target; the readout's gap and force, the arrows' newtons, the plots
  // and their exports (the hammer blow at rest, a jack force that names the lever height) would
  // read the hidden setting off for free: the tests are the measurements. The action stays in
  // view, taller (the view refits as it is resized).
  show_side_docks(practising);
  analyses_->set_settings_hidden(practising);
  view_->set_measurements_visible(!practising);
  plots_->setVisible(!practising);
  for (QAction* a : measurement_actions_) a->setEnabled(!practising);
  // another action or preset would leave the exercise's panel on the wrong action, and a saved
  // preset of the hidden action gives its adjusters away
  for (QAction* a : {open_preset_action_, save_preset_action_, grand_action_, upright_action_})
    a->setEnabled(!practising);
}

void MainWindow::end_practice() {
  if (!practice_took_over_) return;
  practising_ = false;
  end_practice_test_shown();
  set_practice_layout(false);
  give_back_class_input();  // the tests shown took over the run input and the speed
  if (!action_name_.empty()) {
    open_action(action_name_);
    hold_at_rest();  // the regulated action waits at rest for Play, as at launch
  }
}

void MainWindow::give_back_class_input() {
  practice_took_over_ = false;
  run_controls_->input_form()->set_spec(input_before_practice_);
  run_controls_->set_speed_index(speed_before_practice_);
}

void MainWindow::show_practice(bool on) {
  if (practice_action_ && practice_action_->isChecked() != on) {
    practice_action_->setChecked(on);  // its toggled signal comes back here
    return;
  }
  practice_dock_->setVisible(on);
  if (on) {
    practice_dock_->raise();
    if (model_) practice_->offer_action(model_->kind);  // the form starts on the action shown
    practice_->resume();  // an exercise left running goes on: its answer stays hidden
  } else {
    end_practice();
  }
}

void MainWindow::practise_on(std::shared_ptr<const ActionModel> model) {
  if (model_ && same_action(*model_, *model)) {
    change_model(std::move(model));
    return;
  }
  // another action: set the view and plots up for it (the regulation panel stays hidden)
  model_ = model;
  ++actions_opened_;
  regulation_->set_model(*model);
  plots_->set_model(*model);
  fit_split_to_action(*model);
  view_->reset_view();
  start(run_controls_->input_form()->spec());
}

void MainWindow::fit_split_to_action(const ActionModel& model) {
  // once the window is laid out (the first time, the splitter has no height yet)
  const double aspect = ActionView::rest_aspect(model);
  QTimer::singleShot(0, this, [this, aspect] {
    const int total = split_->height();
    if (total <= 0) return;
    // the view drawn at the width it has, within 45-55 % of the height: the plots stay readable
    const double wanted = aspect * view_->width();
    const int view_height = static_cast<int>(std::clamp(wanted, 0.45 * total, 0.55 * total));
    split_->setSizes({view_height, total - view_height});  // the view refits as it is resized
  });
}

void MainWindow::open_action(const std::string& name_or_path) {
  auto model = std::make_shared<const ActionModel>(load_action(name_or_path));
  // an action opened after an exercise was scored: the class's own input and speed come back
  // (the exercise had taken them over), as when practice mode is left
  if (practice_took_over_ && !practising_) give_back_class_input();
  action_name_ = name_or_path;
  model_ = model;
  ++actions_opened_;
  // a regulation or demo of the action before ends (its result is dropped when it comes)
  regulation_runner_->cancel();
  deregulation_runner_->cancel();
  grand_action_->setChecked(model->kind == "grand");
  upright_action_->setChecked(model->kind == "upright");
  regulation_->set_model(*model);
  regulation_->clear_log();
  analyses_->set_model(*model);
  {
    // the settings in words, their identifiers as the items' data
    const QString demo = deregulation_setting_->currentData().toString();
    {
      const QSignalBlocker quiet(deregulation_setting_);  // one rate suggestion, below
      deregulation_setting_->clear();
      for (const RegulationSetting& r : model->regulation)
        deregulation_setting_->addItem(setting_title(r.name), QString::fromStdString(r.name));
      const int keep = deregulation_setting_->findData(demo.isEmpty() ? "hammer_blow" : demo);
      deregulation_setting_->setCurrentIndex(std::max(0, keep));
    }
    suggest_demo_rate();
  }
  fit_regulation_dock(false);
  // and again once the new rows have their fonts and sizes (their size requests are events of
  // their own: fitted now alone, a grand opened after the upright with larger text turned off
  // kept the upright's narrower dock and a clipped target column)
  QTimer::singleShot(0, this, [this] { fit_regulation_dock(isVisible()); });
  plots_->set_model(*model);
  fit_split_to_action(*model);
  view_->reset_view();
  setWindowTitle(tr("Piano Action Trainer — %1").arg(QString::fromStdString(model->name)));
  QSettings().setValue("last_preset", QString::fromStdString(name_or_path));
  start(run_controls_->input_form()->spec());
  measure_current_model();
}

void MainWindow::show_practice_test(const QString& input, double duration_s) {
  // a test watched as a class watches it, in at most 8 s: the slow press's 1.4 s at 1/5 (7 s,
  // a technician's own slow press; 1/10 would drag on for 14 s), a forte blow's strike and catch
  // (0.05 s) at 1/100, four repeated notes at 12 Hz (0.33 s) at 1/20
  constexpr double kShownTestWallSeconds = 8.0;
  if (duration_s > 0.0) {
    const auto& speeds = RunControls::speeds();  // fastest first
    int chosen = 0;
    for (int i = 0; i < static_cast<int>(speeds.size()); ++i)
      if (duration_s / speeds[i] <= kShownTestWallSeconds) chosen = i;
    run_controls_->set_speed_index(chosen);
  }
  // the test shown before is over (its readings were shown when this one was asked for); the
  // restart below must not end the new one
  practice_test_end_s_ = -1.0;
  start(input.toStdString());
  practice_test_end_s_ = duration_s > 0.0 ? duration_s : -1.0;
}

void MainWindow::end_practice_test_shown() {
  if (practice_test_end_s_ < 0.0) return;
  practice_test_end_s_ = -1.0;
  practice_->shown_test_played();
}

void MainWindow::start(const std::string& spec) {
  if (!model_) return;
  // a CSV that cannot drive any run (missing, malformed, times running back) is refused here,
  // before the run on screen is thrown away; the worker still checks what needs the action's
  // geometry (a recorded key angle beyond this key's travel). The form's other inputs are kept
  // within range by their fields.
  try {
    if (spec.rfind("csv:", 0) == 0) parse_input_spec(spec, InputContext{});
  } catch (const std::exception& e) {
    const QString why = QString::fromStdString(e.what());
    if (controller_->model() == model_) {  // the same action: its run goes on
      show_banner(
          tr("Not started: %1. Fix the file or choose another input; the run shown before is "
             "kept as it was.")
              .arg(why));
      return;
    }
    // another action (or an exercise's hidden one) was opened: it starts at rest, untouched
    controller_->restart(model_, "");
    controller_->play();
    show_banner(tr("Not started with that input: %1. The action rests; fix the file or choose "
                   "another input.")
                    .arg(why));
    return;
  }
  run_controls_->input_form()->set_spec(spec);  // the form shows what runs
  controller_->restart(model_, spec);
  controller_->play();
}

bool MainWindow::event(QEvent* event) {
  if (event->type() == QEvent::StatusTip) {
    if (static_cast<QStatusTipEvent*>(event)->tip().isEmpty()) {
      if (statusBar()->currentMessage().isEmpty()) show_run_status();
      return true;
    }
  }
  return QMainWindow::event(event);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  refit_run_status();
}

void MainWindow::refit_run_status() {
  if (!run_status_shown_.isEmpty() && statusBar()->currentMessage() == run_status_shown_)
    show_run_status();
}

void MainWindow::hold_at_rest() {
  controller_->pause();
  show_run_status();
}

void MainWindow::show_run_status() {
  if (!model_) return;
  const QString name = QString::fromStdString(model_->name);
  QString state, input, hint;
  if (controller_->playing()) {
    // what drives the frames shown: after a rewind those recorded before, not the last blow
    const double shown_t =
        controller_->has_frame() ? controller_->current_frame().t : controller_->display_time();
    running_input_shown_ =
        controller_->replaying() ? running_input_ : controller_->input_at(shown_t);
    state = tr("Running");
    input = running_input_shown_;
  } else {
    // paused or stopped: what drove the frame shown (after a rewind, not the last blow struck);
    // a replay's own words carry the settings of the frame shown
    const double t =
        controller_->has_frame() ? controller_->current_frame().t : controller_->display_time();
    input = controller_->replaying() ? running_input_ : controller_->input_at(t);
    const QString paused_at = tr("Paused at t = %1 ms").arg(t * 1e3, 0, 'f', 2);
    if (controller_->run_stopped()) {
      // where the run stopped (its last frame), and the frame shown when stepped back from it
      const double stopped_t =
          controller_->history().empty() ? t : controller_->history().last_time();
      state = tr("Stopped at t = %1 ms").arg(stopped_t * 1e3, 0, 'f', 2);
      if (std::abs(t - stopped_t) > 1e-9)
        state += tr(", showing t = %1 ms").arg(t * 1e3, 0, 'f', 2);
      hint = tr("see the message above the action; Start from rest runs again");
    } else if (t <= 0.0 && !controller_->replaying() && controller_->at_start()) {
      // the first frame of a run not yet played (the window's launch, an action opened)
      state = tr("Ready, at rest");
      hint =
          tr("Play or P runs it, Strike or the space bar strikes a blow, keys 1–5 strike pp "
             "to ff");
    } else if (t <= 0.0 && !controller_->replaying()) {
      // a run played (or stepped) and taken back to its start: Play shows it again from the
      // recorded frames
      state = tr("At the start of the run");
      hint = tr("Play or P plays it again, Step moves one frame, ten with Shift");
    } else if (setting_waits_) {
      // a screw turned while paused in a run: the parts move to it only as time goes on
      state = paused_at;
      hint =
          tr("the setting just changed acts as the run goes on (Play), or from rest (Start "
             "from rest)");
    } else {
      state = paused_at;
      hint = tr("Play or P goes on, Step and Step back move one frame, ten with Shift");
    }
  }
  show_fitted_status(run_status_wordings(state, name, input, hint));
  run_status_shown_ = statusBar()->currentMessage();
}

void MainWindow::show_fitted_status(const QStringList& wordings) {
  // the message's room: the bar less its size grip and margins
  constexpr double kStatusMarginsPx = 32.0;
  const QString shown = fit_status(wordings, QFontMetricsF(statusBar()->font()),
                                   statusBar()->width() - kStatusMarginsPx);
  statusBar()->showMessage(shown);
  // the whole message when a shorter one had to be shown
  statusBar()->setToolTip(wordings.isEmpty() || shown == wordings.front() ? QString()
                                                                          : wordings.front());
}

void MainWindow::set_adjuster(const std::string& name, double mm) {
  if (!model_) return;
  try {
    change_model(std::make_shared<const ActionModel>(with_adjuster(*model_, name, mm * 1e-3)));
  } catch (const std::exception& e) {
    statusBar()->showMessage(QString::fromStdString(e.what()));
  }
}

void MainWindow::change_model(std::shared_ptr<const ActionModel> model) {
  model_ = std::move(model);
  // the analysis shown says when it is no longer the window's settings (not during an exercise,
  // whose hidden setting it would name: set_practice_layout)
  analyses_->compare_with_window();
  // at rest, before anything was played (the window's launch, an action opened, a restart
  // still finding its rest): the action settles with the new setting at once, as a technician
  // sees it after a turn of the screw (a capstan turned up lifts the hammer); in a run played
  // and paused (even rewound to its start), it acts as the run goes on, which the status line
  // says (the drawing and the recorded run stay as they were)
  const bool at_rest = !practising_ && !controller_->playing() && !controller_->replaying() &&
                       !controller_->run_stopped() && controller_->at_start();
  if (at_rest) {
    controller_->restart(model_, controller_->run_spec());  // the run's own input, not the form's
    hold_at_rest();
  } else {
    controller_->change_model(model_);
    setting_waits_ = !controller_->playing() && !controller_->replaying();
    if (setting_waits_) show_run_status();
  }
  measure_current_model();
}

void MainWindow::measure_current_model() {
  for (const auto& row : regulation_->rows()) row->set_measuring();
  measurements_->request(model_);
}

void MainWindow::regulate_automatically() {
  if (!model_ || regulation_runner_->running()) return;
  if (regulation_->replaying()) {
    statusBar()->showMessage(tr("A replay is on screen: Start from rest first, then regulate."));
    return;
  }
  regulation_->log(tr("Regulating %1 from the current adjuster positions…")
                       .arg(QString::fromStdString(model_->name)));
  regulate_button_->setText(tr("Cancel regulation"));
  regulation_model_ = model_;
  regulation_opened_at_ = actions_opened_;
  regulation_cancelled_ = false;
  regulation_runner_->start(model_);
}

void MainWindow::run_deregulation_demo() {
  if (!model_ || deregulation_runner_->running()) return;
  ++demo_rate_request_;  // the demo runs at the rate shown; a suggestion still on its way is
                         // dropped
  DeregulationOptions options;
  options.setting = deregulation_setting_->currentData().toString().toStdString();
  demo_setting_ = options.setting;
  options.rate_mm_per_s = deregulation_rate_->value();
  options.frequency_hz = 3.0;
  // long enough for the suggested rates to reach what they show: the grand's capstan at 0.15
  // mm/s jams the jack in the repetition lever's window after 10.5 s
  options.duration_s = 15.0;
  options.step_interval_s = kDeregulationStepS;
  regulation_->log(tr("Deregulation demo: %1, its adjuster %2 mm/s, key at %3 Hz…")
                       .arg(deregulation_setting_->currentText())
                       .arg(options.rate_mm_per_s, 0, 'f', 2)
                       .arg(options.frequency_hz));
  progress_->setValue(0);
  progress_->show();
  deregulate_button_->setText(tr("Cancel the deregulation demo"));
  demo_model_ = model_;
  demo_opened_at_ = actions_opened_;
  deregulation_runner_->start(model_, options);
}

void MainWindow::set_deregulation_demo(const std::string& setting, double rate_mm_per_s) {
  const int index = deregulation_setting_->findData(QString::fromStdString(setting));
  if (index < 0) throw InputError("deregulation demo: unknown setting '" + setting + "'");
  deregulation_setting_->setCurrentIndex(index);
  ++demo_rate_request_;  // the rate given, not the one suggested for the setting
  deregulation_rate_->setValue(rate_mm_per_s);
}

void MainWindow::suggest_demo_rate() {
  const std::string setting = deregulation_setting_->currentData().toString().toStdString();
  if (!model_ || setting.empty()) return;
  demo_rate_request_running_ = ++demo_rate_request_;
  // one suggestion at a time: a setting chosen while one is computed (the combo box scrolled
  // through) waits for it, the latest only; each had started a run of its own, which kept both
  // of the pool's threads from the demo, the regulation and the analyses asked for next
  if (demo_rate_watcher_->isRunning()) {
    demo_rate_start_waits_ = true;
    return;
  }
  start_demo_rate_suggestion();
}

void MainWindow::start_demo_rate_suggestion() {
  const std::string setting = deregulation_setting_->currentData().toString().toStdString();
  if (!model_ || setting.empty()) return;
  demo_rate_watcher_->setFuture(
      QtConcurrent::run(background_pool(), [model = model_, setting]() -> double {
        try {
          return demo_adjuster_rate(*model, setting);
        } catch (const std::exception&) {
          return std::nan("");  // the rate box keeps what it had
        }
      }));
}

void MainWindow::show_deregulation_result(const DeregulationResult& result) {
  const std::string& id = demo_setting_;
  const QString setting = setting_title(id);  // in words, as the panel names it
  const int index = model()->setting_index(id);
  const QString unit =
      index >= 0 ? QString::fromStdString(model()->regulation[index].unit) : tr("mm");
  AnalysisResult shown;
  shown.summary = result.stop_cause.empty() ? tr("the action held to the end.")
                                            : tr("stopped at t = %1 s: %2")
                                                  .arg(result.stop_t, 0, 'f', 2)
                                                  .arg(QString::fromStdString(result.stop_cause));
  AnalysisSeries measured{tr("%1 measured").arg(setting), "measured", {}, {}, true};
  AnalysisSeries adjuster{tr("adjuster"), "adjuster_mm", {}, {}, false};
  AnalysisSeries gap{tr("gap at the top of the cycle"), "hammer_string_gap_mm", {}, {}, true};
  for (const DeregulationSample& s : result.samples) {
    measured.x.push_back(s.t);
    measured.y.push_back(s.measured);
    gap.x.push_back(s.t);
    gap.y.push_back(s.hammer_string_gap_mm);
    // the setting is in the title: a row says when and where its adjuster was, in the width
    // of the dock ("let-off at t = 0.33 s (adjuster 0.00 …" was cut), to the thousandth that a
    // 0.075 mm step needs
    shown.table.push_back(
        {tr("t = %1 s, adjuster %2 mm")
             .arg(s.t, 0, 'f', 2)
             .arg(adjuster_mm_text(s.adjuster_mm, 3, true)),
         std::isfinite(s.measured) ? QString::number(s.measured, 'f', 3) : tr("no reading"), unit});
  }
  // the adjuster as the run turned it, from its trace: steps of rate × interval (the paper's
  // 0.5 mm every 0.5 s); joined once per key cycle, as the readings are, it looked like a ramp
  const AdjusterSteps steps = adjuster_steps(result.trace);
  adjuster.x = steps.t_s;
  adjuster.y = steps.mm;
  // the setting and its adjuster on their own axes: a 2 mm turn beside a 45 mm reading would
  // look flat
  shown.plots.push_back({tr("%1 measured over time").arg(setting),
                         tr("time (s)"),
                         "time_s",
                         "s",
                         tr("%1 (%2)").arg(setting, unit),
                         {measured},
                         {},
                         {},
                         {}});
  // the step as the run made it (the rate box may have changed since)
  const double step_mm = steps.mm.size() >= 3 ? steps.mm[2] - steps.mm[1] : 0.0;
  shown.plots.push_back(
      {tr("Its adjuster, turned %1 mm every %2 s").arg(step_mm, 0, 'g', 3).arg(kDeregulationStepS),
       tr("time (s)"),
       "time_s",
       "s",
       tr("adjuster (mm)"),
       {adjuster},
       {},
       {},
       {}});
  shown.plots.push_back({tr("Hammer–string gap at the top of each key cycle"),
                         tr("time (s)"),
                         "time_s",
                         "s",
                         tr("gap (mm)"),
                         {gap},
                         {},
                         {},
                         {}});
  analyses_->show_result(tr("Deregulation of %1").arg(setting), shown, QString(), demo_model_);
  show_analyses();
}

void MainWindow::save_preset(const std::string& path) {
  write_preset(*model_, path);
}

void MainWindow::save_preset_from_menu() {
  if (!model_) return;
  const QString path = ask_save_path(this, tr("Save current state as preset"), export_folder(),
                                     tr("Action presets (*.json)"));
  if (path.isEmpty()) return;
  try {
    save_preset(path.toStdString());
    statusBar()->showMessage(tr("Preset written to %1").arg(path));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Cannot save the preset"), QString::fromStdString(e.what()));
  }
}

QString MainWindow::banner_text() const {
  return banner_->isVisible() ? banner_->text() : QString();
}

void MainWindow::show_banner(const QString& text) {
  banner_->setText(text);
  banner_->show();
  statusBar()->showMessage(text);
}

void MainWindow::hide_banner() {
  banner_->hide();
  banner_->clear();
}

void MainWindow::open_preset_from_menu() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open preset"),
                                                    QString::fromStdString(preset_directory()),
                                                    tr("Action presets (*.json);;All files (*)"));
  if (path.isEmpty()) return;
  try {
    open_action(path.toStdString());
    hold_at_rest();
  } catch (const std::exception& e) {
    // from a menu: a dialog is fine; the running action stays as it was
    QMessageBox::warning(this, tr("Cannot open the preset"), QString::fromStdString(e.what()));
  }
}

void MainWindow::export_from_menu(std::vector<PlotPanel*> plots, QString what, bool run_plots,
                                  const std::function<bool()>& still_shown) {
  // copies: the plots and title asked for, not whatever they refer to once the dialog is closed
  export_to_chosen_file(
      what, tr("PNG image (*.png);;PDF (*.pdf);;SVG (*.svg);;CSV of the visible range (*.csv)"),
      run_plots, [&](const QString& path) {
        if (still_shown && !still_shown())
          throw InputError(path.toStdString() + ": not written: another result replaced " +
                           what.toStdString() + " while the file was chosen; export again");
        // a CSV's further files (plots with other x values) were not in the dialog's question
        return export_plots(
            plots, path, export_size_, export_metadata(run_plots),
            [this](const QStringList& files) { return confirm_replacing(this, files.mid(1)); });
      });
}

AnimationOptions MainWindow::animation_options() const {
  AnimationOptions options;
  // what the plots show (the time span followed, or the whole run), at the speed chosen: played
  // at 25 pictures a second, the sequence runs as the window played it
  const auto [from, to] = plots_->panels().front()->x_range();
  options.from_s = from;
  options.to_s = to;
  options.interval_s = std::max(controller_->speed() / kAnimationPicturesPerS, 1e-5);
  options.size = export_size_;
  options.focus = view_->focus();
  options.labels = view_->labels_visible();
  options.measurements = view_->measurements_visible();
  return options;
}

int MainWindow::export_animation(const QString& folder,
                                 const std::function<bool(int, int)>& progress) {
  // the frames of the span drawn, copied: the progress dialog runs the event loop, in which a
  // restart or a replay clears the run's history
  const AnimationOptions options = animation_options();
  const FrameHistory& history = controller_->history();
  FrameHistory span;
  if (!history.empty()) {
    const std::size_t last = std::min(history.index_at(options.to_s) + 1, history.size() - 1);
    for (std::size_t i = history.index_at(options.from_s); i <= last; ++i)
      span.append(history.at(i));
  }
  return export_action_animation(span, options, folder, progress);
}

void MainWindow::export_animation_from_menu() {
  const bool was_playing = controller_->playing();
  if (was_playing) controller_->pause();  // the run as it was when Export was chosen
  const QString folder = QFileDialog::getExistingDirectory(
      this, tr("Export the action's animation into an empty folder"), export_folder());
  if (folder.isEmpty()) {
    if (was_playing) controller_->play();
    return;
  }
  try {
    const AnimationOptions options = animation_options();
    const std::vector<double> times = animation_times(controller_->history(), options);
    const int total = static_cast<int>(times.size());
    QProgressDialog progress(tr("Drawing the action's pictures…"), tr("Stop"), 0, total, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    const int written = export_animation(folder, [&progress](int done, int) {
      progress.setValue(done);  // (processes the window's events: it stays responsive)
      return !progress.wasCanceled();
    });
    progress.setValue(total);
    remember_export_folder(folder);
    const QString stopped = written < total
                                ? tr("Stopped after %1 of %2 pictures. ").arg(written).arg(total)
                                : QString();
    statusBar()->showMessage(
        stopped + tr("Exported %1 pictures of the action (t = %2 to %3 ms, every %4 ms; at 25 a "
                     "second they play at the speed chosen) and frames.csv to %5")
                      .arg(written)
                      .arg(times.front() * 1e3, 0, 'f', 1)
                      .arg(times[std::max(written, 1) - 1] * 1e3, 0, 'f', 1)
                      .arg(options.interval_s * 1e3, 0, 'g', 3)
                      .arg(folder));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Export failed"), QString::fromStdString(e.what()));
  }
  if (was_playing) controller_->play();  // as the other exports do
}

void MainWindow::export_to_chosen_file(const QString& what, const QString& filter, bool pause_run,
                                       const std::function<QStringList(const QString&)>& write) {
  // the run pauses while the file is chosen: what is written is what was on screen when Export
  // was chosen, not where the run had got to when the dialog closed
  const bool was_playing = pause_run && controller_->playing();
  if (was_playing) controller_->pause();
  const QString path = ask_save_path(this, tr("Export %1").arg(what), export_folder(), filter);
  if (was_playing) controller_->play();
  if (path.isEmpty()) return;
  try {
    const QStringList written = write(path);
    if (written.isEmpty()) return;
    remember_export_folder(path);
    statusBar()->showMessage(tr("Exported %1 to %2").arg(what, written.join(", ")));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Export failed"), QString::fromStdString(e.what()));
  }
}

std::map<std::string, std::string> MainWindow::export_metadata(bool run_plots) const {
  std::map<std::string, std::string> metadata;
  // the run's action, or the one the analysis shown ran on, with its settings at Run (the window
  // may have opened another action or moved a slider since); none for Upright vs grand
  const std::shared_ptr<const ActionModel> model = run_plots ? model_ : analyses_->result_model();
  if (!model) return metadata;
  metadata["action"] = model->kind;
  metadata["preset"] = model->source_file;
  // during an exercise the turned adjusters are what the student is looking for
  metadata["settings"] =
      practising_ ? "hidden (practice exercise)" : adjuster_settings_text(*model);
  if (run_plots) {
    // every input of the run the plots hold: a blow struck into it is part of its record. By
    // their SPECs (a run of one input gives one SPEC, which `diagnose` reads back from an
    // exported trace), and in words beside them
    if (controller_->replaying()) {
      metadata["input"] = running_input_.toStdString();
    } else {
      metadata["input"] = controller_->inputs_text().toStdString();
      metadata["input_words"] = controller_->inputs_text(true).toStdString();
    }
  }
  return metadata;
}

void MainWindow::export_run_trace(const std::string& path) const {
  write_csv(path, run_trace_table(controller_->history(), export_metadata(true)));
}

void MainWindow::restore_settings() {
  QSettings settings;
  if (!restoreGeometry(settings.value("window/geometry").toByteArray())) {
    // the first start: the size the window's layout is designed for, within the screen (Qt's
    // default, from the widgets' size hints, leaves the plots and readout unreadable)
    QSize size(1280, 800);
    if (const QScreen* screen = this->screen())
      size = size.boundedTo(screen->availableGeometry().size() * 0.95);
    resize(size);
  }
  restoreState(settings.value("window/state").toByteArray());
  practice_dock_->hide();  // a saved state may show it; an exercise starts from the menu only
  export_size_ = settings.value("export/size", export_size_).toSize();
  run_controls_->set_speed_index(settings.value("run/speed_index", 3).toInt());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  // the saved layout is the regulated action's, with its panels shown (no new run or
  // measurement while the window closes: only the docks)
  practice_dock_->hide();
  regulation_dock_->show();
  analyses_dock_->show();
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  settings.setValue("export/size", export_size_);
  // the class's speed, not one a practice test took over (a forte blow shown at 1/100)
  settings.setValue("run/speed_index",
                    practice_took_over_ ? speed_before_practice_ : run_controls_->speed_index());
  QMainWindow::closeEvent(event);
}

}  // namespace pat::ui

// The trainer window (DESIGN.md section 6): run controls on top, the animated action over the
// live plots, the regulation panel at the side; menus for the action, presets, exports and the
// view. A run that stops (unphysical contact, divergence) pauses and shows its cause in a
// banner over the action, never in a dialog.
#pragma once

#include <QFutureWatcher>
#include <QMainWindow>
#include <QSize>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "animation_export.h"
#include "model/action_model.h"

class QAction;
class QComboBox;
class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSplitter;

namespace pat {
struct DeregulationResult;
}

namespace pat::ui {

class ActionView;
class AnalysesPanel;
class MeasurementService;
class PracticePanel;
class PlaybackController;
class DeregulationRunner;
class RegulationRunner;
class PlotStack;
class RegulationPanel;
class RunControls;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Loads an action ("grand", "upright" or a preset file) and starts it at rest with the
  /// input of the run controls. Throws InputError (the caller shows it).
  void open_action(const std::string& name_or_path);
  /// Sets one adjuster of the running model (mm), as the slider does.
  void set_adjuster(const std::string& name, double mm);
  /// Replaces the running model at the next step boundary (keeps the run going).
  void change_model(std::shared_ptr<const ActionModel> model);
  /// Starts a new run from rest under `spec`.
  void start(const std::string& spec);
  /// Holds the run just started at its first frame, the action at rest, until Play or a strike
  /// (the window's launch: a blow played before anyone looks teaches nothing).
  void hold_at_rest();

  /// Shows or hides the regulation and analyses panels (View › Side panels): hidden, the action
  /// and the plots take the window's whole width (a 1024-pixel projector). An exercise's panel
  /// is not one of them; during an exercise those two stay hidden either way.
  void show_side_panels(bool on);
  bool side_panels_shown() const { return side_panels_shown_; }

  std::shared_ptr<const ActionModel> model() const { return model_; }
  PlaybackController* controller() const { return controller_; }
  ActionView* view() const { return view_; }
  PlotStack* plots() const { return plots_; }
  RegulationPanel* regulation() const { return regulation_; }
  RunControls* run_controls() const { return run_controls_; }
  MeasurementService* measurements() const { return measurements_; }
  AnalysesPanel* analyses() const { return analyses_; }
  /// Brings the Analyses tab of the side dock to the front.
  void show_analyses();
  RegulationRunner* regulation_runner() const { return regulation_runner_; }
  /// Starts "Regulate automatically" (the button does the same).
  void regulate_automatically();
  /// The deregulation demo (paper section 7.2): the chosen setting's adjuster moved at the
  /// chosen rate (default: hammer_blow, the capstan screwed up 0.15 mm/s) while the key plays a
  /// 3 Hz sine, then replayed, with the measured value over time in the Analyses tab.
  void run_deregulation_demo();
  /// Chooses the demo's setting and rate (mm/s), as the controls next to its button do (the rate
  /// given wins over the one suggested for the setting).
  void set_deregulation_demo(const std::string& setting, double rate_mm_per_s);
  /// The demo's rate box: a setting chosen there gets the adjuster speed that moves it about
  /// 2 mm a second (engine demo_adjuster_rate, computed in the background; the sign kept).
  QDoubleSpinBox* deregulation_rate() const { return deregulation_rate_; }
  bool demo_rate_pending() const { return demo_rate_watcher_->isRunning(); }
  DeregulationRunner* deregulation_runner() const { return deregulation_runner_; }
  /// The practice mode (issue 7): its dock, shown from the Practice menu.
  PracticePanel* practice() const { return practice_; }
  /// Shows the practice dock; hiding it ends a running exercise (back to the regulated action
  /// and the regulation panel).
  void show_practice(bool on);
  /// Larger text for a class (View menu): the application's font, and with it every label,
  /// plot and panel, at kClassTextScale of its size; remembered for the next start.
  void set_large_text(bool on);
  bool large_text() const { return large_text_; }
  /// Writes the current model (deregulated or not) as a preset. Throws InputError.
  void save_preset(const std::string& path);
  /// The message shown over the action (empty when hidden).
  QString banner_text() const;
  QSize export_size() const { return export_size_; }
  /// A CSV export's '#' lines: action, preset, settings (hidden during an exercise) and, for the
  /// run's plots, the input.
  std::map<std::string, std::string> export_metadata(bool run_plots) const;
  /// Writes the run's frames with every trace column (run_trace_export.h) to `path`. Throws
  /// InputError (no frames, a path that cannot be written).
  void export_run_trace(const std::string& path) const;
  /// The action's animation (Export menu) into an existing empty folder, without the dialogs:
  /// the time span the plots show, one picture every speed/25 of simulated time (played at 25 a
  /// second they run at the speed chosen), at the export size, framed and labelled as the view.
  /// Throws InputError (animation_export.h). Returns the pictures written.
  int export_animation(const QString& folder,
                       const std::function<bool(int done, int total)>& progress = {});
  static constexpr double kAnimationPicturesPerS = 25.0;

 protected:
  void closeEvent(QCloseEvent* event) override;
  /// A menu entry hovered sends its (empty) status tip, which would clear the run's status line
  /// for good; those are dropped, and the run's status shown again.
  bool event(QEvent* event) override;
  /// The run's status line is worded again for the new width (status_fit.h).
  void resizeEvent(QResizeEvent* event) override;

 private:
  static constexpr double kClassTextScale = 1.35;  // large enough to read from the back of a room
  /// The deregulation demo turns its adjuster in steps this far apart (s), as the paper does
  /// (0.5 mm every 0.5 s).
  static constexpr double kDeregulationStepS = 0.5;
  void build_menus();
  void build_shortcuts();
  void show_banner(const QString& text);
  void hide_banner();
  void open_preset_from_menu();
  /// Asks for a file and exports `plots` to it; `run_plots`: the run's plots (the run pauses
  /// while the file is chosen, and a CSV names the input), not an analysis result's.
  AnimationOptions animation_options() const;
  void export_animation_from_menu();
  /// With `still_shown`, the plots are written only if it still says yes once the file is chosen
  /// (the dialog runs the event loop, in which an analysis may replace, and delete, its plots).
  void export_from_menu(std::vector<class PlotPanel*> plots, QString what, bool run_plots,
                        const std::function<bool()>& still_shown = {});
  /// Asks for a file (filter `filter`; the run paused meanwhile when `pause_run`), writes it
  /// with `write`, which returns the files it wrote (none: the user declined), and says where,
  /// or in a dialog why not; `what` names it in both.
  void export_to_chosen_file(const QString& what, const QString& filter, bool pause_run,
                             const std::function<QStringList(const QString&)>& write);
  void restore_settings();
  /// The regulation and analyses docks shown when the side panels are and no exercise runs.
  void show_side_docks(bool practising);
  /// The regulation dock as wide as its panel's smallest layout (after an action or text size);
  /// `within_screen`: no wider than leaves the window on its screen (or at its `width_before`
  /// a text size change, when that was wider: an offscreen 1280-pixel window), and a window
  /// wider than that shrunk back.
  void fit_regulation_dock(bool within_screen, int width_before = 0);
  void measure_current_model();
  void save_preset_from_menu();
  void show_deregulation_result(const DeregulationResult& result);
  void build_practice();
  void practise_on(std::shared_ptr<const ActionModel> model);
  /// Plays a practice test on the hidden action from rest, at the slowest listed speed that
  /// shows its `duration_s` in at most 8 s of wall time.
  void show_practice_test(const QString& input, double duration_s);
  void end_practice();
  /// The class's own run input and speed again, as they were before the exercise took them.
  void give_back_class_input();
  /// The status bar: what runs now and with which input, or where the run is paused.
  void show_run_status();
  /// Shows the first of `wordings` that fits the status bar (status_fit.h), the full one as the
  /// bar's tooltip when it does not.
  void show_fitted_status(const QStringList& wordings);
  /// The run's status again, if the status line still shows it (a new width or font).
  void refit_run_status();
  /// Shares the height between the action view and the plots by the action's shape: a tall
  /// upright gets more of it than a flat grand.
  void fit_split_to_action(const ActionModel& model);

  PlaybackController* controller_;
  QSplitter* split_;
  ActionView* view_;
  PlotStack* plots_;
  double base_point_size_ = 0.0;  // the application font's size at start, pt
  bool large_text_ = false;
  QString run_status_shown_;  // the run's status as last shown (fitted)
  QAction* large_text_action_ = nullptr;
  QAction* side_panels_action_ = nullptr;
  bool side_panels_shown_ = true;
  RegulationPanel* regulation_;
  AnalysesPanel* analyses_;
  QDockWidget* analyses_dock_;
  RunControls* run_controls_;
  MeasurementService* measurements_;
  RegulationRunner* regulation_runner_;
  DeregulationRunner* deregulation_runner_;
  QPushButton* deregulate_button_;
  QComboBox* deregulation_setting_;
  QDoubleSpinBox* deregulation_rate_;
  /// Suggests the demo's rate for the chosen setting (demo_adjuster_rate), in the background.
  void suggest_demo_rate();
  /// Starts computing the suggested rate for the action and setting shown (none running).
  void start_demo_rate_suggestion();
  QFutureWatcher<double>* demo_rate_watcher_;
  int demo_rate_request_ = 0;           ///< the latest suggestion asked for (or overridden)
  int demo_rate_request_running_ = 0;   ///< the one computed now, or started next
  bool demo_rate_start_waits_ = false;  ///< a suggestion waits for the one computed to end
  QProgressBar* progress_;
  QPushButton* regulate_button_;
  QLabel* banner_;
  QScrollArea* regulation_scroll_ = nullptr;
  class QDockWidget* regulation_dock_ = nullptr;
  class QDockWidget* practice_dock_ = nullptr;
  PracticePanel* practice_ = nullptr;
  bool practising_ = false;
  // the model of the replay frame the regulation panel shows (nullptr: the live action)
  std::shared_ptr<const ActionModel> replay_model_shown_;
  QAction* grand_action_;
  QAction* open_preset_action_ = nullptr;
  QAction* save_preset_action_ = nullptr;
  QAction* practice_action_ = nullptr;
  /// Simulated time (s) at which the practice test on screen has been played (its readings are
  /// then shown, PracticePanel::shown_test_played); negative: no test is being played.
  double practice_test_end_s_ = -1.0;
  /// Tells the practice panel that the test on screen is over (played, stopped or replaced).
  void end_practice_test_shown();
  /// Hides (practising) or shows what would measure a hidden setting: the regulation and
  /// analyses docks, the plots and their exports, the readout's and arrows' numbers.
  void set_practice_layout(bool practising);
  std::vector<QAction*> measurement_actions_;  ///< plot exports and plot span: off in practice
  /// An exercise took over the run input and the speed (given back when practice mode ends, or
  /// an action is opened after the exercise was scored).
  bool practice_took_over_ = false;
  std::string input_before_practice_;  ///< the run input when an exercise began
  int speed_before_practice_ = 3;      ///< and the speed (index into RunControls::speeds)
  QString running_input_;              ///< what drives the key (PlaybackController::inputChanged)
  QString running_input_shown_;        ///< what the status line names for the frames being played
  bool setting_waits_ = false;         ///< a setting changed while paused in a run, not yet played
  std::string demo_setting_;  ///< the setting the running (or last) deregulation demo moves
  std::shared_ptr<const ActionModel> demo_model_;        ///< the action the demo runs on
  std::shared_ptr<const ActionModel> regulation_model_;  ///< the action being regulated
  bool regulation_cancelled_ = false;  ///< Cancel pressed: its result is not applied
  /// Counts the actions opened (the same one opened again counts too: its log is cleared and its
  /// run restarted), so that a regulation or demo begun before delivers nothing after
  int actions_opened_ = 0;
  int regulation_opened_at_ = -1;  ///< actions_opened_ when the regulation began
  int demo_opened_at_ = -1;        ///< actions_opened_ when the demo began
  QAction* upright_action_;
  std::shared_ptr<const ActionModel> model_;
  std::string action_name_;
  QSize export_size_{1600, 1000};
};

}  // namespace pat::ui

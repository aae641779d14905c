// The practice mode (issue 7): a dock in the trainer window where a trainee starts an exercise
// (a seed or a teacher's file), runs the technician's tests on the hidden action (in the
// background, with progress and cancel), reads the symptoms, names the setting and the
// direction, corrects it with sliders that show only relative moves, asks for hints, is scored,
// and exports the session report (PDF and CSV). The adjusters' true positions are never shown.
#pragma once

#include <QElapsedTimer>
#include <QWidget>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include "practice/session.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSlider;
class QSpinBox;

namespace pat::ui {

class PracticeRunner;

class PracticePanel : public QWidget {
  Q_OBJECT
 public:
  explicit PracticePanel(QWidget* parent = nullptr);

  /// Starts a seeded exercise on `action` ("grand", "upright" or a preset). Throws InputError.
  void start_seed(const std::string& action, std::uint64_t seed, int level);
  /// Starts a teacher's exercise file. Throws InputError naming the file and the field.
  void start_file(const std::string& path);
  /// Runs one of the technician's tests on the current (hidden, corrected) action.
  void run_test(PracticeTest test);
  /// Gives a diagnosis; returns the judgement (also shown).
  AnswerJudgement submit_answer(const std::vector<FaultAnswer>& answers);
  /// The next hint (also shown and kept in the history).
  QString request_hint();
  /// Gives up: shows the hidden settings (later answers no longer count).
  QString reveal_answer();
  /// Shows a running exercise again (the practice mode reopened): practiceActive(true) and the
  /// hidden action as corrected so far; nothing when none was started.
  void resume();
  /// Offers `kind` ("grand" or "upright", the action on screen) in the exercise form's action
  /// list, while no exercise runs (a running one keeps its own).
  void offer_action(const std::string& kind);
  /// Moves an adjuster relative to where it is (as the slider does). Throws InputError.
  void move_adjuster(const std::string& setting, double delta_mm);
  /// Measures the correction in the background and scores the session (scored() follows).
  void finish();
  /// Writes the report: PDF and CSV. Throws InputError.
  void export_report(const QString& pdf_path, const QString& csv_path);

  /// Whether a test's readings wait until the window has played the test (testShown); the window
  /// that plays them turns this on and calls shown_test_played(). Off (the default), they show as
  /// soon as they are read. Either way the session records the test when it is read, and any
  /// other step of the trainee's (another test, an answer, a hint, a move, finishing) shows the
  /// readings first.
  void set_readings_wait_for_playback(bool wait) { readings_wait_for_playback_ = wait; }
  /// The window has played the test shown, or has stopped showing it (the run stopped or was
  /// restarted, the practice mode closed): readings held for it appear.
  void shown_test_played();
  /// Readings have been taken and wait for the test to be played.
  bool readings_held() const { return static_cast<bool>(held_readings_); }

  const PracticeSession* session() const { return session_ ? session_.get() : nullptr; }
  PracticeRunner* runner() const { return runner_; }
  /// The symptom lines shown, and the status line (tests).
  QStringList symptom_lines() const;
  /// The scored sessions remembered between runs of the program (newest first).
  QStringList past_sessions() const;
  QString status_text() const;

 signals:
  /// The action the trainee now works on (hidden + moves): the window shows and plays it.
  void modelChanged(std::shared_ptr<const pat::ActionModel> model);
  /// An exercise started (true) or none is running (false): the window hides the regulation
  /// panel, whose values would give the answer away.
  void practiceActive(bool active);
  void scored(double total);
  /// A test started: the window plays it on the action from rest, under `input` (an input SPEC,
  /// "" = no finger), in which the test takes `duration_s` of simulated time. Also when an
  /// exercise starts or resumes, with no input: the hidden action is shown at rest.
  void testShown(const QString& input, double duration_s);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  /// The form's width: all of it, without a horizontal scroll bar, in the current font.
  /// The correction sliders' "moved …" labels at their widest reading's width.
  void fit_moved_labels();
  void fit_width();
  void begin(Exercise exercise, ActionModel regulated);
  /// Asks before an unscored exercise is replaced (the form's Start, a file opened); true: go on.
  bool leave_running_exercise();
  /// A yes/no question, No the default.
  bool confirm(const QString& title, const QString& question);
  void build_adjusters();
  void set_busy(bool busy);
  void show_status(const QString& text);
  /// `text` with the settings' identifiers replaced by the names the form shows.
  QString readable(QString text) const;
  void append_history();
  /// Shows readings held for playback, if any.
  void release_readings();
  void remember_session(const SessionScore& score);
  void show_past_sessions();
  double elapsed_s() const;
  void start_from_form();
  void open_file_from_dialog();
  void answer_from_form();
  void export_from_dialog();

  std::unique_ptr<PracticeSession> session_;
  std::shared_ptr<const ActionModel> regulated_;
  PracticeRunner* runner_;
  QElapsedTimer clock_;
  bool readings_wait_for_playback_ = false;
  bool shown_test_playing_ = false;      ///< the window plays the latest test (not yet played)
  std::function<void()> held_readings_;  ///< shows the latest test's readings, once

  QLineEdit* trainee_;  ///< the trainee's name, for the report and the past sessions
  QComboBox* action_;
  QSpinBox* seed_;
  QSpinBox* level_;
  QLabel* title_;
  std::vector<QPushButton*> test_buttons_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QListWidget* symptoms_;
  QComboBox* answer_setting_;
  QComboBox* answer_direction_;
  QComboBox* second_setting_;  ///< level 2: the second fault named
  QComboBox* second_direction_;
  QPushButton* answer_button_;
  QPushButton* hint_button_;
  QPushButton* reveal_button_;
  QPushButton* finish_button_;
  QPushButton* export_button_;
  QScrollArea* scroll_ = nullptr;
  QWidget* correction_box_ = nullptr;  ///< the sliders and the finish button
  QWidget* adjusters_box_;
  std::map<std::string, QSlider*> sliders_;
  std::map<std::string, QLabel*> moved_labels_;
  QListWidget* history_;
  QListWidget* past_sessions_;  ///< scored sessions kept in the settings, newest first
  QLabel* status_;
};

}  // namespace pat::ui

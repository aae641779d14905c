#include "practice_panel.h"

#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "export_folder.h"
#include "focus_wheel.h"
#include "model/preset_loader.h"
#include "practice/exercise.h"
#include "practice_report.h"
#include "practice_runner.h"
#include "save_paths.h"
#include "setting_names.h"
#include "step_slider.h"

namespace pat::ui {
namespace {

/// Slider resolution: one step is 0.01 mm of adjuster travel.
constexpr double kSliderStepMm = 0.01;
/// Relative travel the sliders offer either way (mm); the adjuster's physical stop may come
/// earlier (the move is then refused with the engine's message).
constexpr int kSliderSpanSteps = 400;

QString test_title(PracticeTest test) {
  switch (test) {
    case PracticeTest::Rest:
      return QObject::tr("Rest geometry");
    case PracticeTest::SlowPress:
      return QObject::tr("Slow key press");
    case PracticeTest::ForteBlow:
      return QObject::tr("Forte blow");
    case PracticeTest::Repetition:
      return QObject::tr("Repeated notes");
  }
  return {};
}

/// The readings of a test, " (label value unit; …)", or "" when none has a value.
/// A reading as the list shows it: a fraction of the hammer's travel as a percentage, a count
/// (no unit: strikes of one blow) as a whole number, else two decimals ("0.00", not "-0.00").
QString reading_value_text(const Observation& o, double raw) {
  const bool fraction = o.unit == "fraction";
  double value = fraction ? 100.0 * raw : raw;
  if (std::abs(value) < 0.005) value = 0.0;
  const bool count = o.unit.empty() && value == std::round(value);
  return QStringLiteral("%1 %2")
      .arg(value, 0, 'f', count ? 0 : 2)
      .arg(fraction ? QStringLiteral("%") : QString::fromStdString(o.unit))
      .trimmed();
}

/// The regulation tolerance in the units a reading is shown in: ±0.05 mm, or ±1 % for a
/// fraction shown in percent (DESIGN.md section 3; the regulation panel's targets).
double shown_tolerance(const Observation& o) {
  return o.unit == "fraction" ? 1.0 : 0.05;
}

/// " (label value; …)" of the readings, each that differs from the regulated action's by more
/// than the rounding of the digits shown followed by that one ("45.45 mm, regulated action
/// 45.00 mm"); `differing` counts those, `outside` those beyond the regulation tolerance.
/// (Shown to hundredths, 0.00 against −0.01 may be a difference of 0.005: 0.015 is the least
/// that is surely more than rounding.)
QString readings_text(const std::vector<Observation>& seen,
                      const std::vector<Observation>& regulated, int& differing, int& outside) {
  QStringList readings;
  differing = 0;
  outside = 0;
  for (const Observation& o : seen) {
    if (!o.value) continue;
    QString text = QString::fromStdString(o.label) + " " + reading_value_text(o, *o.value);
    const Observation* reg = find_observation(regulated, o.id);
    const double scale = o.unit == "fraction" ? 100.0 : 1.0;  // in the units shown
    const double off = reg && reg->value ? std::abs(*o.value - *reg->value) * scale : 0.0;
    if (off >= 0.015) {
      text += QObject::tr(", regulated action %1").arg(reading_value_text(o, *reg->value));
      ++differing;
      if (off > shown_tolerance(o) + 1e-9) ++outside;
    }
    readings << text;
  }
  return readings.isEmpty() ? QString() : " (" + readings.join("; ") + ")";
}

/// Long lines wrap to the list's width instead of scrolling sideways.
void wrap_lines(QListWidget* list) {
  list->setWordWrap(true);
  list->setResizeMode(QListView::Adjust);
  list->setTextElideMode(Qt::ElideNone);
  list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
}

}  // namespace

PracticePanel::PracticePanel(QWidget* parent) : QWidget(parent) {
  runner_ = new PracticeRunner(this);
  // the form scrolls; the status line under it stays in view, so an answer's judgement, a hint
  // or the score shows wherever the trainee has scrolled to
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* scroll = scroll_ = new QScrollArea(this);
  scroll->setObjectName("practice_scroll");
  auto* content = new QWidget;
  auto* column = new QVBoxLayout(content);

  auto* start_box = new QGroupBox(tr("Exercise"), this);
  auto* start_form = new QFormLayout(start_box);
  // the trainee's name heads the report and the past sessions (remembered: a student's own
  // machine keeps it; on a shared one the next student types theirs)
  trainee_ = new QLineEdit(QSettings().value("practice/trainee").toString(), start_box);
  trainee_->setObjectName("practice_trainee");
  trainee_->setPlaceholderText(tr("name for the report"));
  trainee_->setMaxLength(80);
  start_form->addRow(tr("Trainee"), trainee_);
  connect(trainee_, &QLineEdit::textEdited, this, [this](const QString& name) {
    QSettings().setValue("practice/trainee", name);
    if (session_) session_->set_trainee(name.toStdString());
  });
  action_ = new FocusWheel<QComboBox>(start_box);
  action_->setObjectName("practice_action");
  action_->addItems({"grand", "upright"});
  seed_ = new FocusWheel<QSpinBox>(start_box);
  seed_->setRange(0, 1000000);
  level_ = new FocusWheel<QSpinBox>(start_box);
  level_->setRange(1, 2);
  level_->setToolTip(tr("Level 1 hides one setting, level 2 two"));
  start_form->addRow(tr("Action"), action_);
  // the seed chooses the hidden fault: the same number gives every student the same exercise
  seed_->setToolTip(
      tr("Each number hides a different fault; give a class the same number for "
         "the same exercise"));
  start_form->addRow(tr("Exercise number"), seed_);
  start_form->addRow(tr("Level"), level_);
  auto* start_row = new QHBoxLayout;
  auto* start_button = new QPushButton(tr("Start"), start_box);
  auto* file_button = new QPushButton(tr("Open exercise file…"), start_box);
  start_row->addWidget(start_button);
  start_row->addWidget(file_button);
  start_form->addRow(start_row);
  title_ = new QLabel(tr("No exercise running."), start_box);
  title_->setWordWrap(true);
  start_form->addRow(title_);
  column->addWidget(start_box);
  connect(start_button, &QPushButton::clicked, this, &PracticePanel::start_from_form);
  connect(file_button, &QPushButton::clicked, this, &PracticePanel::open_file_from_dialog);

  auto* tests_box = new QGroupBox(tr("Technician's tests on this action"), this);
  auto* tests_layout = new QVBoxLayout(tests_box);
  auto* buttons = new QGridLayout;  // two by two: the dock stays narrow
  for (PracticeTest test : all_tests()) {
    auto* b = new QPushButton(test_title(test), tests_box);
    b->setEnabled(false);
    connect(b, &QPushButton::clicked, this, [this, test] { run_test(test); });
    const int n = static_cast<int>(test_buttons_.size());
    buttons->addWidget(b, n / 2, n % 2);
    test_buttons_.push_back(b);
  }
  tests_layout->addLayout(buttons);
  auto* progress_row = new QHBoxLayout;
  progress_ = new QProgressBar(tests_box);
  progress_->setRange(0, 100);
  cancel_ = new QPushButton(tr("Cancel"), tests_box);
  cancel_->setEnabled(false);
  progress_row->addWidget(progress_, 1);
  progress_row->addWidget(cancel_);
  tests_layout->addLayout(progress_row);
  symptoms_ = new QListWidget(tests_box);
  wrap_lines(symptoms_);
  symptoms_->setMinimumHeight(120);
  tests_layout->addWidget(symptoms_);
  column->addWidget(tests_box);
  connect(cancel_, &QPushButton::clicked, runner_, &PracticeRunner::cancel);

  auto* answer_box = new QGroupBox(tr("Diagnosis"), this);
  auto* answer_grid = new QGridLayout(answer_box);
  answer_setting_ = new FocusWheel<QComboBox>(answer_box);
  answer_direction_ = new FocusWheel<QComboBox>(answer_box);
  second_setting_ = new FocusWheel<QComboBox>(answer_box);
  second_direction_ = new FocusWheel<QComboBox>(answer_box);
  for (QComboBox* d : {answer_direction_, second_direction_}) {
    d->addItem(tr("more than its target"), "more");
    d->addItem(tr("less than its target"), "less");
    d->setPlaceholderText(tr("more or less?"));
  }
  // no choice made for the student: an answer needs both chosen (each exercise starts unchosen)
  for (QComboBox* setting : {answer_setting_, second_setting_})
    setting->setPlaceholderText(tr("which setting?"));
  second_setting_->setToolTip(tr("Level 2: the second hidden setting"));
  answer_setting_->setObjectName("answer_setting");
  answer_direction_->setObjectName("answer_direction");
  second_setting_->setObjectName("second_setting");
  second_direction_->setObjectName("second_direction");
  answer_button_ = new QPushButton(tr("Answer"), answer_box);
  hint_button_ = new QPushButton(tr("Hint"), answer_box);
  answer_button_->setObjectName("answer_button");
  hint_button_->setObjectName("hint_button");
  answer_grid->addWidget(answer_setting_, 0, 0);
  answer_grid->addWidget(answer_direction_, 0, 1);
  answer_grid->addWidget(second_setting_, 1, 0);
  answer_grid->addWidget(second_direction_, 1, 1);
  reveal_button_ = new QPushButton(tr("Give up: show the answer"), answer_box);
  reveal_button_->setObjectName("reveal_button");
  reveal_button_->setToolTip(tr("Shows the hidden settings; answers given after it do not count"));
  answer_grid->addWidget(answer_button_, 2, 0);
  answer_grid->addWidget(hint_button_, 2, 1);
  answer_grid->addWidget(reveal_button_, 3, 0, 1, 2);
  for (QWidget* w : std::initializer_list<QWidget*>{answer_setting_, answer_direction_,
                                                    second_setting_, second_direction_,
                                                    answer_button_, hint_button_, reveal_button_})
    w->setEnabled(false);
  second_setting_->hide();
  second_direction_->hide();
  column->addWidget(answer_box);
  connect(answer_button_, &QPushButton::clicked, this, &PracticePanel::answer_from_form);
  connect(hint_button_, &QPushButton::clicked, this, &PracticePanel::request_hint);
  connect(reveal_button_, &QPushButton::clicked, this, [this] {
    if (confirm(tr("Give up?"), tr("Show the hidden settings? Answers after this are judged but "
                                   "no longer scored.")))
      reveal_answer();
  });

  auto* correct_box = new QGroupBox(tr("Correction (relative moves; true positions hidden)"), this);
  correct_box->setObjectName("correction_box");
  correction_box_ = correct_box;
  auto* correct_layout = new QVBoxLayout(correct_box);
  adjusters_box_ = new QWidget(correct_box);
  adjusters_box_->setLayout(new QFormLayout);
  correct_layout->addWidget(adjusters_box_);
  auto* end_row = new QHBoxLayout;
  finish_button_ = new QPushButton(tr("Finish and score"), correct_box);
  export_button_ = new QPushButton(tr("Export report…"), correct_box);
  finish_button_->setEnabled(false);
  export_button_->setEnabled(false);
  end_row->addWidget(finish_button_);
  end_row->addWidget(export_button_);
  correct_layout->addLayout(end_row);
  column->addWidget(correct_box);
  connect(finish_button_, &QPushButton::clicked, this, &PracticePanel::finish);
  connect(export_button_, &QPushButton::clicked, this, &PracticePanel::export_from_dialog);

  auto* history_box = new QGroupBox(tr("History"), this);
  auto* history_layout = new QVBoxLayout(history_box);
  history_ = new QListWidget(history_box);
  wrap_lines(history_);
  history_layout->addWidget(history_);
  history_layout->addWidget(new QLabel(tr("Past sessions"), history_box));
  past_sessions_ = new QListWidget(history_box);
  wrap_lines(past_sessions_);
  past_sessions_->setMaximumHeight(90);
  history_layout->addWidget(past_sessions_);
  show_past_sessions();
  column->addWidget(history_box, 1);
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  // wider than fit_width's cap (very large text): scrolled sideways rather than cut
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  fit_width();
  outer->addWidget(scroll, 1);
  status_ = new QLabel(this);
  status_->setObjectName("practice_status");
  status_->setWordWrap(true);
  status_->setFrameShape(QFrame::StyledPanel);
  status_->setMargin(6);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  outer->addWidget(status_);

  connect(runner_, &PracticeRunner::progress, this, [this](double f, const QString& stage) {
    progress_->setValue(static_cast<int>(std::lround(100 * f)));
    progress_->setFormat(stage + " %p%");
  });
  connect(
      runner_, &PracticeRunner::observed, this,
      [this](int test, const std::vector<Observation>& seen,
             const std::vector<Observation>& regulated) {
        set_busy(false);
        if (!session_) return;
        const auto symptoms =
            session_->record_test(static_cast<PracticeTest>(test), seen, regulated, elapsed_s());
        const QString name = test_title(static_cast<PracticeTest>(test));
        // a test toward the diagnosis, or (once it is right) a check of the correction, which
        // the score does not count
        const int used = session_->tests_used() - session_->check_tests();
        const bool check = session_->tests_are_checks();
        const int number = session_->tests_used();
        held_readings_ = [this, name, symptoms, seen, regulated, used, check, number] {
          // a heading per test, so that a check's findings on the corrected action are not read
          // as more symptoms of the fault (they had run on under the earlier ones)
          auto* heading = new QListWidgetItem(
              check ? tr("Test %1, %2: a check of the correction").arg(number).arg(name)
                    : tr("Test %1, %2").arg(number).arg(name));
          QFont bold = symptoms_->font();
          bold.setBold(true);
          heading->setFont(bold);
          heading->setFlags(Qt::ItemIsEnabled);  // a heading, not a finding to select
          heading->setBackground(symptoms_->palette().alternateBase());
          symptoms_->addItem(heading);
          if (symptoms.empty()) {  // with the readings, which a correction is fine-tuned by
            // no symptom a player or a technician's quick look would notice (engine:
            // noticeable_difference), but the score holds each setting to the regulation
            // panel's tolerance (±0.05 mm), which is finer: a reading beyond it is named as
            // such, so that "nothing to notice" is not read as "regulated" (a blow 0.22 mm long
            // had been "no difference", then "out of tolerance" in the score)
            int differing = 0, outside = 0;
            const QString readings = readings_text(seen, regulated, differing, outside);
            QString verdict;
            if (differing == 0)
              verdict = tr("%1: the same as a regulated action%2.").arg(name, readings);
            else if (outside == 0)
              verdict = tr("%1: within the regulation tolerance (±0.05 mm) of a regulated "
                           "action%2.")
                            .arg(name, readings);
            else
              verdict =
                  tr("%1: no symptom a player would notice, but %2 outside the regulation "
                     "tolerance (±0.05 mm) of a regulated action's: not yet regulated%3.")
                      .arg(name,
                           outside == 1 ? tr("one reading is") : tr("%n readings are", "", outside),
                           readings);
            symptoms_->addItem(verdict);
          }
          for (const Symptom& s : symptoms)
            symptoms_->addItem(name + ": " + QString::fromStdString(s.text));
          symptoms_->scrollToBottom();
          append_history();  // its line names the symptoms too
          if (check)
            show_status(
                tr("%1 done: a check of the correction, not counted against economy.").arg(name));
          else
            show_status(used == 1 ? tr("%1 done (1 test used).").arg(name)
                                  : tr("%1 done (%2 tests used).").arg(name).arg(used));
        };
        // what the test found is seen on the action before it is read in words (a class watches
        // the hammer bounce before the list says "double strike")
        if (shown_test_playing_)
          show_status(tr("%1: read. What it found appears when the action on screen has played "
                         "it.")
                          .arg(name));
        else
          release_readings();
      });
  connect(runner_, &PracticeRunner::measured, this,
          [this](const std::vector<CorrectionReading>& readings) {
            set_busy(false);
            if (!session_) return;
            const SessionScore s = session_->score(readings, elapsed_s());
            append_history();
            // the hints' share only when some were taken ("hints −0.0" read as a penalty)
            const QString hints = s.hint_penalty > 0.0
                                      ? tr(", hints −%1").arg(s.hint_penalty, 0, 'f', 1)
                                      : tr(", no hints taken");
            // each part with its maximum, and how it was reached (the engine's notes: that only
            // the first answer is scored, how much of each fault was corrected, the tests)
            QStringList how;
            for (const std::string& note : s.notes)
              if (note.rfind("out of tolerance", 0) != 0)  // said below, as what to set next
                how << QString::fromStdString(note);
            show_status(tr("Score %1 / 100 (diagnosis %2 of 50, regulation %3 of 40, economy %4 "
                           "of 10%5). The hidden %6: %7.")
                            .arg(s.total, 0, 'f', 1)
                            .arg(s.diagnosis, 0, 'f', 1)
                            .arg(s.regulation, 0, 'f', 1)
                            .arg(s.economy, 0, 'f', 1)
                            .arg(hints)
                            .arg(QString::fromStdString(session_->answer_heading()),
                                 QString::fromStdString(session_->answer_text())) +
                        (s.out_of_tolerance.empty()
                             ? QString()
                             : tr(" Still out of tolerance, to set next: %1.")
                                   .arg(QString::fromStdString(s.out_of_tolerance))) +
                        tr(" How it was scored: %1.").arg(how.join("; ")));
            export_button_->setEnabled(true);
            remember_session(s);
            emit scored(s.total);
          });
  connect(runner_, &PracticeRunner::failed, this, [this](const QString& reason) {
    set_busy(false);
    show_status(tr("Stopped: %1").arg(reason));
  });
}

void PracticePanel::fit_width() {
  // the whole form without a horizontal scroll bar (24 px: the vertical one and the frame)
  int wanted = scroll_->widget()->sizeHint().width() + 24;
  // never more than half the screen (or of a window larger than it, as the regulation dock
  // measures): beyond that the form scrolls sideways
  const int room =
      std::max(screen() ? screen()->availableGeometry().width() : 0, window()->width()) / 2;
  if (room > 0) wanted = std::min(wanted, room);
  scroll_->setMinimumWidth(wanted);
}

void PracticePanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  // larger text for a class: the buttons and lines grow, and so must the dock (they were cut
  // at its right edge); measured once the layouts have taken the new font
  if (event->type() == QEvent::FontChange || event->type() == QEvent::ApplicationFontChange)
    QTimer::singleShot(0, this, [this] {
      fit_moved_labels();
      fit_width();
    });
}

void PracticePanel::fit_moved_labels() {
  // as wide as the widest reading they show: the slider beside one kept its length as "moved
  // 0.00 mm" became "moved +0.01 mm" (its handle had seemed to jump left at the first step)
  for (auto& [name, label] : moved_labels_)
    label->setMinimumWidth(label->fontMetrics().horizontalAdvance(tr("moved −9.99 mm")) + 4);
}

bool PracticePanel::leave_running_exercise() {
  if (!session_ || session_->final_score()) return true;
  return confirm(tr("Leave this exercise?"),
                 tr("The exercise under way (%1 tests used) is not scored yet; a new one replaces "
                    "it and it is not kept among the past sessions. Start the new one?")
                     .arg(session_->tests_used()));
}

bool PracticePanel::confirm(const QString& title, const QString& question) {
  return QMessageBox::question(this, title, question, QMessageBox::Yes | QMessageBox::No,
                               QMessageBox::No) == QMessageBox::Yes;
}

void PracticePanel::start_from_form() {
  if (!leave_running_exercise()) return;
  try {
    start_seed(action_->currentText().toStdString(), static_cast<std::uint64_t>(seed_->value()),
               level_->value());
  } catch (const std::exception& e) {
    show_status(QString::fromStdString(e.what()));
  }
}

void PracticePanel::open_file_from_dialog() {
  if (!leave_running_exercise()) return;
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open exercise"), QString::fromStdString(preset_directory() + "/exercises"),
      tr("Exercises (*.json)"));
  if (path.isEmpty()) return;
  try {
    start_file(path.toStdString());
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Cannot open the exercise"), QString::fromStdString(e.what()));
  }
}

void PracticePanel::start_seed(const std::string& action, std::uint64_t seed, int level) {
  ActionModel regulated = load_action(action);
  Exercise exercise = generate_exercise(regulated, action, seed, level);
  begin(std::move(exercise), std::move(regulated));
}

void PracticePanel::start_file(const std::string& path) {
  Exercise exercise = load_exercise(path);
  ActionModel regulated = load_action(exercise.action);
  begin(std::move(exercise), std::move(regulated));
}

void PracticePanel::begin(Exercise exercise, ActionModel regulated) {
  if (runner_->running()) {
    runner_->cancel();
    runner_->wait();
  }
  // an exercise whose action does not come to rest cannot be practised: refuse it here
  ActionModel hidden = hidden_model(regulated, exercise);
  try {
    find_rest_state(hidden);
  } catch (const std::runtime_error& e) {
    throw InputError((exercise.source_file.empty() ? exercise.title : exercise.source_file) +
                     ": impossible exercise, the deregulated action does not come to rest (" +
                     e.what() + ")");
  }
  runner_->reset_cache();
  held_readings_ = nullptr;  // the last exercise's
  shown_test_playing_ = false;
  regulated_ = std::make_shared<const ActionModel>(regulated);
  session_ = std::make_unique<PracticeSession>(std::move(exercise), std::move(regulated));
  session_->set_trainee(trainee_->text().toStdString());
  clock_.start();
  title_->setText(QString::fromStdString(session_->exercise().title) +
                  (session_->exercise().notes.empty()
                       ? QString()
                       : "\n" + QString::fromStdString(session_->exercise().notes)));
  symptoms_->clear();
  history_->clear();
  answer_setting_->clear();
  second_setting_->clear();
  for (const RegulationSetting& s : regulated_->regulation) {
    answer_setting_->addItem(setting_title(s.name), QString::fromStdString(s.name));
    second_setting_->addItem(setting_title(s.name), QString::fromStdString(s.name));
  }
  for (QComboBox* box : {answer_setting_, answer_direction_, second_setting_, second_direction_})
    box->setCurrentIndex(-1);  // the placeholder: nothing chosen yet
  second_setting_->setVisible(session_->exercise().level == 2);
  second_direction_->setVisible(session_->exercise().level == 2);
  build_adjusters();
  append_history();
  set_busy(false);
  export_button_->setEnabled(true);
  show_status(tr("Exercise started: run the tests, then answer."));
  emit practiceActive(true);
  emit modelChanged(std::make_shared<const ActionModel>(session_->current_model()));
  emit testShown(QString(), 0.0);  // at rest: nothing of it is seen before a test is run
}

void PracticePanel::build_adjusters() {
  auto* form = static_cast<QFormLayout*>(adjusters_box_->layout());
  while (form->rowCount() > 0) form->removeRow(0);
  sliders_.clear();
  moved_labels_.clear();
  for (const RegulationSetting& s : regulated_->regulation) {
    auto* row = new QWidget(adjusters_box_);
    auto* rows = new QVBoxLayout(row);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setSpacing(1);
    auto* layout = new QHBoxLayout;
    rows->addLayout(layout);
    auto* slider = new StepSlider(Qt::Horizontal, row);
    slider->setRange(-kSliderSpanSteps, kSliderSpanSteps);
    slider->setValue(0);
    // which way is which: the adjuster's part and what + does, as the regulation panel's tooltip
    // says it ("capstan (key pilot): + screws it up, raising the whippen (shorter blow)"), with
    // the slider's side named
    const Adjuster& adjuster = regulated_->adjusters[regulated_->adjuster_index(s.name)];
    const QString what = QString::fromStdString(adjuster.description)
                             .replace(QStringLiteral(": + "), tr(": to the right (+) "));
    slider->setToolTip(tr("Moves the %1 adjuster relative to where you found it.\n%2")
                           .arg(setting_title(s.name), what));
    auto* moved = new QLabel(tr("moved 0.00 mm"), row);
    layout->addWidget(slider, 1);
    layout->addWidget(moved);
    auto* direction = new QLabel(what, row);
    direction->setObjectName("direction_" + QString::fromStdString(s.name));
    direction->setWordWrap(true);
    direction->setForegroundRole(QPalette::PlaceholderText);  // grey: a caption, not a value
    rows->addWidget(direction);
    form->addRow(setting_title(s.name), row);
    sliders_[s.name] = slider;
    moved_labels_[s.name] = moved;
    fit_moved_labels();
    const std::string name = s.name;
    auto apply = [this, name, slider] {
      if (!session_) return;
      const double target = slider->value() * kSliderStepMm;
      const double delta = target - session_->moved_mm(name);
      if (std::abs(delta) < 0.5 * kSliderStepMm) return;
      try {
        move_adjuster(name, delta);
      } catch (const std::exception& e) {
        const QSignalBlocker block(slider);
        slider->setValue(static_cast<int>(std::lround(session_->moved_mm(name) / kSliderStepMm)));
        show_status(QString::fromStdString(e.what()));
      }
    };
    connect(slider, &QSlider::sliderReleased, this, apply);
    connect(slider, &QSlider::valueChanged, this, [slider, apply] {
      if (!slider->isSliderDown()) apply();  // keyboard and wheel steps
    });
  }
}

void PracticePanel::shown_test_played() {
  shown_test_playing_ = false;
  release_readings();
}

void PracticePanel::release_readings() {
  if (!held_readings_) return;
  const std::function<void()> show = std::move(held_readings_);
  held_readings_ = nullptr;
  show();
}

void PracticePanel::run_test(PracticeTest test) {
  if (!session_ || runner_->running()) return;
  release_readings();  // the previous test's, if its playback was cut short
  set_busy(true);
  progress_->setValue(0);
  const ShownTest shown = shown_test(test);
  emit testShown(QString::fromStdString(shown.input), shown.duration_s);
  // after the window has taken the test (its restart ends the one shown before, which must not
  // end this one)
  shown_test_playing_ = readings_wait_for_playback_ && shown.duration_s > 0.0;
  show_status(test == PracticeTest::Rest
                  ? tr("%1: the action rests on screen while it is measured.").arg(test_title(test))
                  : tr("%1: the action on screen plays it from rest while its readings are "
                       "taken.")
                        .arg(test_title(test)));
  runner_->observe(std::make_shared<const ActionModel>(session_->current_model()), regulated_,
                   test);
}

AnswerJudgement PracticePanel::submit_answer(const std::vector<FaultAnswer>& answers) {
  if (!session_) throw InputError("no exercise is running");
  release_readings();  // the history in the order of the session's
  const AnswerJudgement j = session_->answer(answers, elapsed_s());
  QStringList remarks;
  for (const std::string& r : j.remarks) remarks << QString::fromStdString(r);
  // only the first answer earns the diagnosis marks (session.h): said when a later one is right
  const QString scored = j.correct && session_->answers_given() > 1 && !session_->revealed()
                             ? tr(" (Only the first answer is scored: %1 of 50 for the "
                                  "diagnosis so far.)")
                                   .arg(session_->diagnosis_marks(), 0, 'f', 1)
                             : QString();
  QString remark = remarks.join("; ");
  if (!remark.isEmpty()) remark[0] = remark[0].toUpper();  // a sentence of its own
  show_status((j.correct ? tr("Correct. Now correct it with the sliders.") : tr("Not correct.")) +
              " " + remark + scored);
  // the sliders lie below the answer: brought into view for the instruction just given
  if (j.correct) {  // its top at the top (a box taller than the view would be centred)
    QScrollBar* bar = scroll_->verticalScrollBar();
    bar->setValue(std::min(correction_box_->y(), bar->maximum()));
  }
  append_history();
  return j;
}

void PracticePanel::answer_from_form() {
  if (!session_) return;
  const bool two = session_->exercise().level == 2;
  for (QComboBox* box : {answer_setting_, answer_direction_, second_setting_, second_direction_}) {
    if ((box == second_setting_ || box == second_direction_) && !two) continue;
    if (box->currentIndex() < 0) {
      show_status(two ? tr("Choose both settings and, for each, whether it is more or less than "
                           "its target, then Answer.")
                      : tr("Choose the setting and whether it is more or less than its target, "
                           "then Answer."));
      box->setFocus();
      return;
    }
  }
  std::vector<FaultAnswer> answers{{answer_setting_->currentData().toString().toStdString(),
                                    answer_direction_->currentData().toString().toStdString()}};
  if (session_->exercise().level == 2)
    answers.push_back({second_setting_->currentData().toString().toStdString(),
                       second_direction_->currentData().toString().toStdString()});
  submit_answer(answers);
}

QString PracticePanel::request_hint() {
  if (!session_) return {};
  release_readings();
  const QString hint = QString::fromStdString(session_->hint(elapsed_s()));
  show_status(tr("Hint: %1").arg(hint));
  append_history();
  return hint;
}

QString PracticePanel::reveal_answer() {
  if (!session_) return {};
  release_readings();
  const QString text = QString::fromStdString(session_->reveal(elapsed_s()));
  show_status(text + " " + tr("Answers from now on are judged but not scored."));
  hint_button_->setEnabled(false);    // nothing left to hint
  reveal_button_->setEnabled(false);  // nor to show again
  append_history();
  return text;
}

void PracticePanel::resume() {
  // a scored exercise is over (its answer is on show): the window stays on the regulated action
  if (!session_ || session_->final_score()) return;
  emit practiceActive(true);
  emit modelChanged(std::make_shared<const ActionModel>(session_->current_model()));
  emit testShown(QString(), 0.0);  // at rest: nothing of it is seen before a test is run
}

void PracticePanel::offer_action(const std::string& kind) {
  if (session_ && !session_->final_score()) return;
  const int index = action_->findText(QString::fromStdString(kind));
  if (index >= 0) action_->setCurrentIndex(index);
}

void PracticePanel::move_adjuster(const std::string& setting, double delta_mm) {
  if (!session_) throw InputError("no exercise is running");
  release_readings();
  session_->move_adjuster(setting, delta_mm, elapsed_s());
  const double moved = session_->moved_mm(setting);
  if (QSlider* slider = sliders_.count(setting) ? sliders_[setting] : nullptr) {
    const QSignalBlocker block(slider);
    slider->setValue(static_cast<int>(std::lround(moved / kSliderStepMm)));
  }
  if (moved_labels_.count(setting))
    moved_labels_[setting]->setText(
        tr("moved %1%2 mm").arg(moved >= 0 ? "+" : "").arg(moved, 0, 'f', 2));
  append_history();
  emit modelChanged(std::make_shared<const ActionModel>(session_->current_model()));
}

void PracticePanel::finish() {
  if (!session_ || runner_->running()) return;
  release_readings();
  set_busy(true);
  show_status(tr("Measuring the corrected action…"));
  runner_->measure(*session_);
}

void PracticePanel::export_report(const QString& pdf_path, const QString& csv_path) {
  if (!session_) throw InputError("no exercise is running: nothing to report");
  release_readings();
  write_session_pdf(pdf_path, *session_);
  write_session_csv(csv_path.toStdString(), *session_);
  show_status(tr("Report written: %1 and %2").arg(pdf_path, csv_path));
}

void PracticePanel::export_from_dialog() {
  // named after the trainee, so that a class's reports do not overwrite each other
  const QString who = QString::fromStdString(session_ ? session_->trainee() : std::string());
  const QString suggested =
      who.isEmpty() ? QString()
                    : tr("practice report %1.pdf")
                          .arg(QString(who).replace(QRegularExpression("[/\\\\:*?\"<>|]"), "_"));
  const QString pdf = ask_save_path(this, tr("Export the session report"), export_path(suggested),
                                    tr("PDF (*.pdf)"));
  if (pdf.isEmpty()) return;
  // "session", "session.pdf" and "session.csv" all make session.pdf and session.csv; the dialog
  // asked about the name chosen only
  const ReportPaths paths = report_paths(pdf);
  QStringList unconfirmed;
  for (const QString& p : {paths.pdf, paths.csv})
    if (p != pdf) unconfirmed << p;
  if (!confirm_replacing(this, unconfirmed)) return;
  try {
    export_report(paths.pdf, paths.csv);
    remember_export_folder(paths.pdf);
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Export failed"), QString::fromStdString(e.what()));
  }
}

QStringList PracticePanel::symptom_lines() const {
  QStringList lines;
  for (int i = 0; i < symptoms_->count(); ++i) lines << symptoms_->item(i)->text();
  return lines;
}

QString PracticePanel::status_text() const {
  return status_->text();
}

void PracticePanel::set_busy(bool busy) {
  const bool active = session_ != nullptr;
  for (QPushButton* b : test_buttons_) b->setEnabled(active && !busy);
  cancel_->setEnabled(busy);
  for (QWidget* w : std::initializer_list<QWidget*>{
           answer_setting_, answer_direction_, second_setting_, second_direction_, answer_button_,
           hint_button_, reveal_button_, finish_button_, adjusters_box_})
    w->setEnabled(active && !busy);
  if (session_ && session_->revealed()) {
    hint_button_->setEnabled(false);
    reveal_button_->setEnabled(false);
  }
  if (!busy) {
    progress_->setValue(progress_->maximum());
    progress_->setFormat(tr("ready"));
  }
}

QString PracticePanel::readable(QString text) const {
  if (!regulated_) return text;
  // the engine's identifiers ("lever_height") as the form names them ("lever height")
  for (const RegulationSetting& s : regulated_->regulation)
    text.replace(QRegularExpression(
                     "\\b" + QRegularExpression::escape(QString::fromStdString(s.name)) + "\\b"),
                 setting_title(s.name));
  return text;
}

void PracticePanel::show_status(const QString& text) {
  status_->setText(readable(text));
}

void PracticePanel::append_history() {
  if (!session_) return;
  const auto& events = session_->history();
  auto line = [&](std::size_t i) {
    return QStringLiteral("%1 s  %2: %3")
        .arg(events[i].t_s, 0, 'f', 1)
        .arg(QString::fromStdString(events[i].kind))
        .arg(readable(QString::fromStdString(events[i].detail)));
  };
  // the session's last move may have grown or gone since (steps one after another are one
  // move, steps that undo each other none): the last line shown is written again
  const int kept = std::max(0, static_cast<int>(events.size()) - 1);
  while (history_->count() > kept) delete history_->takeItem(history_->count() - 1);
  for (std::size_t i = static_cast<std::size_t>(history_->count()); i < events.size(); ++i)
    history_->addItem(line(i));
  history_->scrollToBottom();
}

/// How many scored sessions the settings keep.
constexpr int kPastSessionsKept = 50;

void PracticePanel::remember_session(const SessionScore& score) {
  QSettings settings;
  QStringList past = settings.value("practice/past_sessions").toStringList();
  const QString who = QString::fromStdString(session_->trainee());
  past.prepend(
      tr("%1  %2: %3/100 (%4, %5, %6 s)")
          .arg(QDateTime::currentDateTime().toString(Qt::ISODate))
          .arg((who.isEmpty() ? QString() : who + ", ") +
               QString::fromStdString(session_->exercise().title))
          .arg(score.total, 0, 'f', 1)
          .arg((score.tests_used == 1 ? tr("1 test") : tr("%1 tests").arg(score.tests_used)) +
               (score.check_tests == 0   ? QString()
                : score.check_tests == 1 ? tr(", 1 of them a check")
                                         : tr(", %1 of them checks").arg(score.check_tests)))
          .arg(score.hints_used == 1 ? tr("1 hint") : tr("%1 hints").arg(score.hints_used))
          .arg(score.time_s, 0, 'f', 0));
  while (past.size() > kPastSessionsKept) past.removeLast();
  settings.setValue("practice/past_sessions", past);
  show_past_sessions();
}

void PracticePanel::show_past_sessions() {
  past_sessions_->clear();
  past_sessions_->addItems(QSettings().value("practice/past_sessions").toStringList());
}

QStringList PracticePanel::past_sessions() const {
  QStringList lines;
  for (int i = 0; i < past_sessions_->count(); ++i) lines << past_sessions_->item(i)->text();
  return lines;
}

double PracticePanel::elapsed_s() const {
  return clock_.isValid() ? clock_.elapsed() / 1000.0 : 0.0;
}

}  // namespace pat::ui

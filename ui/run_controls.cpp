#include "run_controls.h"

#include <QComboBox>
#include <QEvent>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

#include "input_spec_form.h"
#include "playback_controller.h"

namespace pat::ui {
namespace {

struct BlowLevel {
  const char* name;
  double force_n;
};
// key-front forces from soft to very loud (DESIGN.md section 2, F2: ~2 N to ~50 N)
const BlowLevel kBlows[] = {{"pp", 2}, {"p", 5}, {"mf", 12}, {"f", 25}, {"ff", 50}};
constexpr int kBlowMs = 40;

QToolButton* tool_button(QWidget* parent, QStyle::StandardPixmap icon, const QString& text,
                         const QString& tip) {
  auto* button = new QToolButton(parent);
  button->setIcon(parent->style()->standardIcon(icon));
  button->setText(text);
  button->setToolTip(tip);
  button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  return button;
}

}  // namespace

const std::vector<double>& RunControls::speeds() {
  static const std::vector<double> s{1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001};
  return s;
}

RunControls::RunControls(PlaybackController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller) {
  auto* rows = new QVBoxLayout(this);
  rows->setContentsMargins(4, 2, 4, 2);
  rows->setSpacing(2);
  auto* top = new QHBoxLayout;
  auto* bottom = new QHBoxLayout;
  rows->addLayout(top);
  rows->addLayout(bottom);

  input_ = new InputSpecForm(this);
  top->addWidget(input_, 1);
  auto* start = new QPushButton(tr("Start from rest"), this);
  start->setToolTip(tr("A new run from the action at rest, driven by the chosen input"));
  top->addWidget(start);
  connect(start, &QPushButton::clicked, this, [this] { emit startRequested(input_->spec()); });

  auto* rewind = tool_button(this, QStyle::SP_MediaSkipBackward, tr("Rewind"),
                             tr("Back to just before the last blow struck (Home); again: to the "
                                "one before, then to the oldest frame kept"));
  const int large = PlaybackController::kLargeStepFrames;
  auto* back = tool_button(this, QStyle::SP_MediaSeekBackward, tr("Step back"),
                           tr("One frame back (Left); with Shift, %1 frames").arg(large));
  play_ = tool_button(this, QStyle::SP_MediaPlay, tr("Play"), tr("Play or pause (P)"));
  auto* step = tool_button(this, QStyle::SP_MediaSeekForward, tr("Step"),
                           tr("One frame forward (Right); with Shift, %1 frames").arg(large));
  for (QToolButton* b : {rewind, back, play_, step}) bottom->addWidget(b);
  connect(rewind, &QToolButton::clicked, controller_, &PlaybackController::rewind);
  // Shift held while clicking takes the larger step, as with the arrow keys
  auto frames = [] {
    return QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier)
               ? PlaybackController::kLargeStepFrames
               : 1;
  };
  connect(back, &QToolButton::clicked, controller_,
          [this, frames] { controller_->step_back(frames()); });
  connect(step, &QToolButton::clicked, controller_,
          [this, frames] { controller_->step_forward(frames()); });
  connect(play_, &QToolButton::clicked, this, [this] {
    if (controller_->playing())
      controller_->pause();
    else
      controller_->play();
  });
  connect(controller_, &PlaybackController::playingChanged, this, &RunControls::update_play_button);

  bottom->addSpacing(12);
  bottom->addWidget(new QLabel(tr("Speed:"), this));
  speed_ = new QComboBox(this);
  for (double s : speeds())
    speed_->addItem(s == 1.0 ? tr("real time") : tr("1/%1").arg(qRound(1.0 / s)), s);
  speed_->setToolTip(tr("Playback speed: simulated time per wall-clock time"));
  bottom->addWidget(speed_);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this](int i) { controller_->set_speed(speeds()[i]); });
  factor_ = new QLabel(this);
  factor_->setObjectName("achieved_speed");
  fit_fixed_widths();
  factor_->setToolTip(tr("Real-time factor achieved: simulated time shown per wall second"));
  bottom->addWidget(factor_);
  connect(controller_, &PlaybackController::realtimeFactorChanged, this, [this](double f) {
    // in the speed list's own terms: "real time" or a fraction 1/N
    if (!(f > 0.0))
      factor_->setText(tr("achieved —"));
    else if (f >= 0.995)
      factor_->setText(f < 1.005 ? tr("achieved real time") : tr("achieved ×%1").arg(f, 0, 'f', 2));
    else
      // one decimal below 10 (what rounds to 10.0 reads "10", like the speed list)
      factor_->setText(tr("achieved 1/%1").arg(1.0 / f, 0, 'f', 1.0 / f < 9.95 ? 1 : 0));
  });

  bottom->addSpacing(12);
  // a blow struck into the run on screen, whatever input it started with (the row above)
  bottom->addWidget(new QLabel(tr("Strike now:"), this));
  blow_ = new QComboBox(this);
  for (const BlowLevel& b : kBlows) blow_->addItem(tr("%1  %2 N").arg(b.name).arg(b.force_n));
  blow_->setToolTip(tr("Strength of a blow struck into the run on screen (Strike, or the space "
                       "bar): from the moment it is struck, a %1 ms force pulse at the key front "
                       "drives the key instead of the run input. Keys 1–5 strike pp to ff "
                       "directly.")
                        .arg(kBlowMs));
  bottom->addWidget(blow_);
  auto* strike = new QPushButton(tr("Strike (space)"), this);
  strike->setToolTip(tr("Strike the key now with the chosen blow; keys 1–5 strike pp to ff"));
  connect(strike, &QPushButton::clicked, this, [this] { controller_->strike(blow_spec()); });
  bottom->addWidget(strike);
  bottom->addStretch(1);

  set_blow_level(3);
  set_speed_index(3);
  update_play_button(false);
}

std::string RunControls::blow_spec(int level) const {
  const int i = level >= 1 && level <= 5 ? level - 1 : blow_->currentIndex();
  return "force:pulse:" + QString::number(kBlows[i].force_n).toStdString() + ":" +
         std::to_string(kBlowMs);
}

void RunControls::set_blow_level(int level) {
  blow_->setCurrentIndex(std::clamp(level, 1, 5) - 1);
}

void RunControls::set_speed_index(int index) {
  speed_->setCurrentIndex(std::clamp(index, 0, speed_->count() - 1));
  controller_->set_speed(speeds()[speed_->currentIndex()]);
}

int RunControls::speed_index() const {
  return speed_->currentIndex();
}

void RunControls::update_play_button(bool playing) {
  play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  play_->setText(playing ? tr("Pause") : tr("Play"));
}

void RunControls::fit_fixed_widths() {
  // a fixed width, the widest reading's: the toolbar does not shift as the reading changes
  const QFontMetrics metrics(factor_->font());
  int widest = 0;
  for (const QString& sample : {tr("achieved real time"), tr("achieved 1/1000"),
                                tr("achieved 1/9.9"), tr("achieved ×9.99"), tr("achieved —")})
    widest = std::max(widest, metrics.horizontalAdvance(sample));
  factor_->setFixedWidth(widest + 8);
  // and Play as wide as Pause: the buttons after it stayed 11 pixels to the right while playing
  const QString shown = play_->text();
  int play_width = 0;
  for (const QString& text : {tr("Play"), tr("Pause")}) {
    play_->setText(text);
    play_width = std::max(play_width, play_->sizeHint().width());
  }
  play_->setText(shown);
  play_->setFixedWidth(play_width);
}

void RunControls::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange && factor_ && play_) fit_fixed_widths();  // larger text
}

}  // namespace pat::ui

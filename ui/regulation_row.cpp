#include "regulation_row.h"

#include <QDoubleSpinBox>
#include <QFontMetrics>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>
#include <algorithm>
#include <cmath>

#include "clamping_spin_box.h"
#include "setting_names.h"
#include "step_slider.h"

namespace pat::ui {
namespace {

constexpr double kSliderStepsPerMm = 100.0;  // 0.01 mm per slider step

}  // namespace

RegulationRow::RegulationRow(const Adjuster& adjuster, const RegulationSetting* setting,
                             QGridLayout* grid, int row, QWidget* parent)
    : name_(adjuster.name) {
  if (setting) setting_ = *setting;
  const QString tip = QString::fromStdString(
      adjuster.description + (setting ? "\nmeasured: " + setting->measurement : std::string()));
  // the setting in bold, and under it, smaller, the part the technician turns for it
  const QString part = adjuster_part(adjuster);
  name_label_ = new QLabel(parent);
  name_label_->setTextFormat(Qt::RichText);
  name_label_->setText(
      QStringLiteral("<b>%1</b>").arg(setting_title(adjuster.name).toHtmlEscaped()) +
      (part.isEmpty() ? QString()
                      : QStringLiteral("<br><span style=\"color:#333; font-size:small\">"
                                       "%1</span>")
                            .arg(part.toHtmlEscaped())));
  name_label_->setToolTip(tip);

  slider_ = new StepSlider(Qt::Horizontal, parent);
  slider_->setRange(static_cast<int>(std::round(adjuster.min * 1e3 * kSliderStepsPerMm)),
                    static_cast<int>(std::round(adjuster.max * 1e3 * kSliderStepsPerMm)));
  slider_->setToolTip(tip);
  slider_->setMinimumWidth(60);  // the window fits 1024 pixels (a projector)
  spin_ = new ClampingSpinBox(parent);
  spin_->setRange(adjuster.min * 1e3, adjuster.max * 1e3);
  spin_->setDecimals(2);
  spin_->setSingleStep(0.05);
  spin_->setSuffix(" mm");
  // the adjuster's travel said where it is typed; a number beyond it goes to its end
  const QString travel = tr("Its adjuster turns from %1 to %2 mm (a number beyond is taken to "
                            "the nearest end).")
                             .arg(adjuster_mm_text(adjuster.min * 1e3, 2, true))
                             .arg(adjuster_mm_text(adjuster.max * 1e3, 2, true));
  spin_->setToolTip(tip + "\n" + travel);
  spin_->setKeyboardTracking(false);
  // named for a screen reader by the setting they turn (their label is rich text beside them)
  const QString accessible = tr("%1 adjuster").arg(setting_title(adjuster.name));
  slider_->setAccessibleName(accessible);
  spin_->setAccessibleName(tr("%1, mm from regulated").arg(accessible));
  name_label_->setBuddy(spin_);

  measured_label_ = new QLabel(tr("—"), parent);
  fit_to_font();  // bold, and wide enough
  measured_label_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  measured_label_->setToolTip(tr("Measured the way a technician measures it"));
  target_label_ = new QLabel(parent);
  if (setting_)
    // "10.00 ± 0.05 mm": the unit once, after the tolerance (the dock stays narrow)
    target_label_->setText(
        tr("%1 ± %2")
            .arg(setting_value_text(setting_->target, setting_->unit).section(' ', 0, 0))
            .arg(setting_value_text(setting_->tolerance, setting_->unit)));
  else
    target_label_->setText(tr("no target"));
  target_label_->setToolTip(setting_ ? QString::fromStdString(setting_->source) : QString());

  grid->addWidget(name_label_, row, 0);
  grid->addWidget(slider_, row, 1);
  grid->addWidget(spin_, row, 2);
  grid->addWidget(measured_label_, row, 3);
  grid->addWidget(target_label_, row, 4);
  set_value_mm(adjuster.value * 1e3);

  connect(slider_, &QSlider::valueChanged, this, [this](int steps) {
    const double mm = steps / kSliderStepsPerMm;
    const QSignalBlocker block(spin_);
    spin_->setValue(mm);
    emit valueChanged(mm);
  });
  connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double mm) {
    const QSignalBlocker block(slider_);
    slider_->setValue(static_cast<int>(std::round(mm * kSliderStepsPerMm)));
    emit valueChanged(mm);
  });
}

RegulationRow::~RegulationRow() = default;

double RegulationRow::value_mm() const {
  return spin_->value();
}

void RegulationRow::set_value_mm(double mm) {
  const QSignalBlocker block_slider(slider_), block_spin(spin_);
  spin_->setValue(mm);
  slider_->setValue(static_cast<int>(std::round(mm * kSliderStepsPerMm)));
}

bool RegulationRow::set_measured(double value, const QString& note) {
  const bool news = note != note_;
  measured_ = value;
  note_ = note;
  failure_.clear();
  measuring_ = false;
  show_reading();
  return news;
}

bool RegulationRow::set_measurement_failed(const QString& reason) {
  const bool news = failure_ != reason;
  failure_ = reason;
  note_.clear();
  measured_.reset();
  measuring_ = false;
  show_reading();
  return news;
}

void RegulationRow::set_measuring() {
  measuring_ = true;
  show_reading();
}

void RegulationRow::set_replayed(bool replayed) {
  replayed_ = replayed;
  slider_->setEnabled(!replayed);
  spin_->setEnabled(!replayed);
  show_reading();
}

void RegulationRow::show_reading() {
  if (replayed_) {
    measured_label_->setText(tr("replay"));
    measured_label_->setStyleSheet("color: #888888; padding: 1px 3px;");
    measured_label_->setToolTip(
        tr("A replay is on screen: its adjuster is shown as the replay turned it; the "
           "deregulation demo's measured value over time is in the Analyses tab. Start from "
           "rest returns to the live action."));
    return;
  }
  if (measured_) {
    // within tolerance or not, and which way, in the text too: not by colour alone (a washed-out
    // projector, a colour-blind student)
    const bool bad = out_of_tolerance();
    const bool above = setting_ && *measured_ > setting_->target;
    const QString value = setting_value_text(*measured_, unit());
    const bool marked = setting_ && !measuring_;
    const QString mark = !marked ? QString() : !bad ? QString(" ✓") : above ? " ▲" : " ▼";
    measured_label_->setText(value + mark);
    measured_label_->setAccessibleName(
        !marked ? value
        : !bad  ? tr("%1, within tolerance").arg(value)
                : tr("%1, %2 the target").arg(value, above ? tr("above") : tr("below")));
    // the note ("read with the drop screw out of the way …") as a sentence of its own, and the
    // marks' meaning
    QString tip = note_.isEmpty() ? tr("Measured the way a technician measures it")
                                  : note_.left(1).toUpper() + note_.mid(1) + ".";
    if (setting_)
      tip += "\n" + (bad ? tr("▲ above, ▼ below the target's tolerance")
                         : tr("✓ within the target's tolerance"));
    measured_label_->setToolTip(tip);
    measured_label_->setStyleSheet(
        measuring_ ? "color: #888888; padding: 1px 3px;"
        : setting_ ? (bad ? "color: white; background: #c0392b; padding: 1px 3px;"
                          : "color: white; background: #1e8449; padding: 1px 3px;")
                   : "");
  } else if (!failure_.isEmpty()) {
    measured_label_->setText(tr("no reading"));
    measured_label_->setStyleSheet("color: #c0392b; padding: 1px 3px;");
    measured_label_->setToolTip(failure_);
  } else {
    measured_label_->setText(tr("—"));
    measured_label_->setStyleSheet(measuring_ ? "color: #888888;" : "");
    measured_label_->setToolTip(tr("Measured the way a technician measures it"));
  }
}

void RegulationRow::fit_to_font() {
  // the panel's font in bold: a label with a style sheet (its colours) keeps the font it was
  // polished with, so a larger text has to be given to it
  QFont bold = measured_label_->parentWidget() ? measured_label_->parentWidget()->font()
                                               : measured_label_->font();
  bold.setBold(true);
  measured_label_->setFont(bold);
  // wide enough for "no reading" in bold (its reason in the tooltip): the columns do not move
  // when a reading fails
  // and for the widest reading with its mark: the column does not jump as marks change
  const QFontMetrics metrics(measured_label_->font());
  measured_label_->setMinimumWidth(std::max({72, metrics.horizontalAdvance(tr("no reading")) + 10,
                                             metrics.horizontalAdvance("00.00 mm ▲") + 10}));
}

bool RegulationRow::out_of_tolerance() const {
  return setting_ && measured_ && std::abs(*measured_ - setting_->target) > setting_->tolerance;
}

}  // namespace pat::ui

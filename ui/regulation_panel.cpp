#include "regulation_panel.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextCursor>
#include <QVBoxLayout>
#include <algorithm>

namespace pat::ui {

RegulationPanel::RegulationPanel(QWidget* parent) : QWidget(parent) {
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(6, 4, 6, 4);
  title_ = new QLabel(this);
  fit_title_font();
  column->addWidget(title_);
  grid_host_ = new QWidget(this);
  grid_ = new QGridLayout(grid_host_);
  grid_->setContentsMargins(0, 0, 0, 0);
  grid_->setHorizontalSpacing(6);
  grid_->setColumnStretch(1, 1);
  column->addWidget(grid_host_);
  // the readings' marks, explained where a class sees them (a tooltip is not seen on a
  // projector); under the rows, outside their grid (its columns keep their widths)
  auto* key = new QLabel(tr("✓ within tolerance   ▲ above   ▼ below the target"), this);
  key->setObjectName("tolerance_key");
  key->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  column->addWidget(key);
  buttons_ = new QVBoxLayout;
  column->addLayout(buttons_);
  auto* reset = add_button(tr("Reset to regulated"),
                           tr("Every adjuster back to its regulated position (0 mm)"));
  connect(reset, &QPushButton::clicked, this, &RegulationPanel::resetRequested);
  log_ = new QPlainTextEdit(this);
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(500);
  log_->setPlaceholderText(tr("Regulation steps and messages appear here."));
  column->addWidget(log_, 1);
}

void RegulationPanel::add_widget(QWidget* widget) {
  buttons_->addWidget(widget);
}

QPushButton* RegulationPanel::add_button(const QString& text, const QString& tip) {
  auto* button = new QPushButton(text, this);
  button->setToolTip(tip);
  buttons_->addWidget(button);
  return button;
}

void RegulationPanel::set_model(const ActionModel& model) {
  rows_.clear();
  // a fresh grid: the old row widgets go with their host
  auto* old_host = grid_host_;
  grid_host_ = new QWidget(this);
  grid_ = new QGridLayout(grid_host_);
  grid_->setContentsMargins(0, 0, 0, 0);
  grid_->setHorizontalSpacing(6);
  grid_->setColumnStretch(1, 1);
  static_cast<QVBoxLayout*>(layout())->replaceWidget(old_host, grid_host_);
  old_host->deleteLater();

  title_text_ = tr("Regulation — %1").arg(QString::fromStdString(model.name));
  replaying_ = false;
  title_->setText(title_text_);
  const QStringList headers{tr("setting"), tr("adjuster"), tr("position"), tr("measured"),
                            tr("target")};
  for (int c = 0; c < headers.size(); ++c) {
    auto* label = new QLabel("<i>" + headers[c] + "</i>", grid_host_);
    grid_->addWidget(label, 0, c);
  }
  // the technician's order when the model lists its settings, else the adjusters' order
  std::vector<std::string> names;
  for (const RegulationSetting& s : model.regulation) names.push_back(s.name);
  for (const Adjuster& a : model.adjusters)
    if (std::find(names.begin(), names.end(), a.name) == names.end()) names.push_back(a.name);
  int row = 1;
  for (const std::string& name : names) {
    const int a = model.adjuster_index(name);
    if (a < 0) continue;
    const auto setting = std::find_if(model.regulation.begin(), model.regulation.end(),
                                      [&](const RegulationSetting& s) { return s.name == name; });
    auto r = std::make_unique<RegulationRow>(
        model.adjusters[a], setting != model.regulation.end() ? &*setting : nullptr, grid_, row++,
        grid_host_);
    connect(r.get(), &RegulationRow::valueChanged, this,
            [this, name](double mm) { emit adjusterChanged(name, mm); });
    rows_.push_back(std::move(r));
  }
}

void RegulationPanel::show_adjusters(const ActionModel& model) {
  for (const auto& r : rows_) {
    const int a = model.adjuster_index(r->name());
    if (a >= 0) r->set_value_mm(model.adjusters[a].value * 1e3);
  }
}

void RegulationPanel::set_replay(const ActionModel* replayed) {
  const bool replaying = replayed != nullptr;
  if (replaying != replaying_) {
    replaying_ = replaying;
    for (const auto& r : rows_) r->set_replayed(replaying);
    title_->setText(replaying ? tr("%1 (replay)").arg(title_text_) : title_text_);
    // why the sliders do not move, and the way back, where the class reads the panel's messages
    if (replaying)
      log(
          tr("A recorded replay: the settings show the recording's screws and cannot be turned; "
             "Start from rest returns to the live action."));
  }
  if (replayed) show_adjusters(*replayed);
}

RegulationRow* RegulationPanel::row(const std::string& name) const {
  for (const auto& r : rows_)
    if (r->name() == name) return r.get();
  return nullptr;
}

void RegulationPanel::log(const QString& line) {
  log_->appendPlainText(line);
  // the newest line in full view (appendPlainText alone can leave a wrapped last line half
  // below the edge)
  log_->moveCursor(QTextCursor::End);
  log_->ensureCursorVisible();
}

void RegulationPanel::clear_log() {
  log_->clear();
}

QString RegulationPanel::log_text() const {
  return log_->toPlainText();
}

void RegulationPanel::fit_title_font() {
  QFont heading = font();  // the panel's: it follows the application's (larger text)
  heading.setBold(true);
  heading.setPointSizeF(heading.pointSizeF() + 1);
  title_->setFont(heading);
}

void RegulationPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() != QEvent::FontChange) return;
  if (title_) fit_title_font();
  for (const auto& row : rows_) row->fit_to_font();
}

}  // namespace pat::ui

#include "input_spec_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStringList>

namespace pat::ui {
namespace {

// one input kind: its SPEC prefix, menu text and up to three parameters
struct Kind {
  const char* prefix;
  const char* text;
  struct Param {
    const char* label;
    double min, max, value, step;
    int decimals;
  } params[3];
  int param_count;
  bool stroke;  // motion kinds: full or half stroke
};

const Kind kKinds[] = {
    {"", "no finger (action at rest)", {}, 0, false},
    {"mass", "mass on the key tip", {{"mass (kg)", 0.05, 5, 1, 0.05, 2}}, 1, false},
    {"force:const", "constant force", {{"force (N)", 0.1, 100, 5, 0.5, 1}}, 1, false},
    {"force:pulse",
     "force pulse (a blow)",
     {{"force (N)", 0.1, 100, 20, 1, 1}, {"held (ms)", 1, 1000, 40, 5, 0}},
     2,
     false},
    {"force:double",
     "double blow",
     {{"force (N)", 0.1, 100, 20, 1, 1},
      {"held (ms)", 1, 1000, 30, 5, 0},
      {"gap (ms)", 1, 2000, 60, 5, 0}},
     3,
     false},
    {"motion:sine", "sine key motion", {{"frequency (Hz)", 0.1, 40, 3, 0.5, 2}}, 1, true},
    {"motion:chirp",
     "chirp key motion",
     {{"from (Hz)", 0.1, 40, 2, 0.5, 2},
      {"to (Hz)", 0.1, 40, 20, 0.5, 2},
      {"over (s)", 0.1, 120, 10, 1, 1}},
     3,
     true},
    {"motion:press",
     "slow press (to the bottom, held)",
     {{"press (s)", 0.05, 10, 1, 0.1, 2}},
     1,
     false},
    {"csv", "force or motion from CSV", {}, 0, false},
};
constexpr int kKindCount = sizeof(kKinds) / sizeof(kKinds[0]);

QString number(double x) {
  return QString::number(x, 'g', 10);
}

}  // namespace

InputSpecForm::InputSpecForm(QWidget* parent) : QWidget(parent) {
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  // the input a run starts with; a blow struck into the run on screen is the run controls' own
  auto* kind_label = new QLabel(tr("Run input:"), this);
  row->addWidget(kind_label);
  kind_ = new QComboBox(this);
  kind_label->setBuddy(kind_);
  for (const Kind& k : kKinds) kind_->addItem(tr(k.text));
  kind_->setToolTip(
      tr("What drives the key in a run started from rest (Start from rest): a force at the key "
         "front, a mass on it, or a prescribed key motion (then the finger force is computed)"));
  row->addWidget(kind_);
  for (int i = 0; i < 3; ++i) {
    value_label_[i] = new QLabel(this);
    value_[i] = new QDoubleSpinBox(this);
    value_[i]->setMaximumWidth(100);
    value_label_[i]->setBuddy(value_[i]);  // the label names the value (and to a screen reader)
    row->addWidget(value_label_[i]);
    row->addWidget(value_[i]);
    connect(value_[i], &QDoubleSpinBox::valueChanged, this, &InputSpecForm::specChanged);
  }
  stroke_ = new QComboBox(this);
  stroke_->addItems({tr("full"), tr("half")});
  stroke_->setToolTip(tr("full: the whole key stroke; half: between full dip and half release"));
  row->addWidget(stroke_);
  csv_path_ = new QLineEdit(this);
  csv_path_->setPlaceholderText(tr("CSV with time_s and key_force_n or key_angle_deg"));
  browse_ = new QPushButton(tr("Browse…"), this);
  row->addWidget(csv_path_, 1);
  row->addWidget(browse_);
  row->addStretch(0);
  connect(browse_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Key input from CSV"), {},
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (!path.isEmpty()) csv_path_->setText(path);
  });
  connect(kind_, &QComboBox::currentIndexChanged, this, [this] {
    show_fields();
    emit specChanged();
  });
  connect(stroke_, &QComboBox::currentIndexChanged, this, &InputSpecForm::specChanged);
  connect(csv_path_, &QLineEdit::textChanged, this, &InputSpecForm::specChanged);
  kind_->setCurrentIndex(3);
  show_fields();
}

void InputSpecForm::show_fields() {
  const Kind& k = kKinds[kind_->currentIndex()];
  for (int i = 0; i < 3; ++i) {
    const bool shown = i < k.param_count;
    value_label_[i]->setVisible(shown);
    value_[i]->setVisible(shown);
    if (!shown) continue;
    const Kind::Param& p = k.params[i];
    value_label_[i]->setText(tr(p.label));
    value_[i]->setAccessibleName(tr(p.label).remove(':').trimmed());
    const QSignalBlocker block(value_[i]);
    value_[i]->setRange(p.min, p.max);
    value_[i]->setDecimals(p.decimals);
    value_[i]->setSingleStep(p.step);
    value_[i]->setValue(p.value);
  }
  stroke_->setVisible(k.stroke);
  const bool csv = QString(k.prefix) == "csv";
  csv_path_->setVisible(csv);
  browse_->setVisible(csv);
}

std::string InputSpecForm::spec() const {
  const Kind& k = kKinds[kind_->currentIndex()];
  const QString prefix = k.prefix;
  if (prefix.isEmpty()) return {};
  if (prefix == "csv") return "csv:" + csv_path_->text().toStdString();
  if (prefix == "mass") return "mass:" + number(value_[0]->value()).toStdString() + "kg";
  QStringList parts{prefix};
  for (int i = 0; i < k.param_count; ++i) parts << number(value_[i]->value());
  if (k.stroke) parts << (stroke_->currentIndex() == 0 ? "full" : "half");
  return parts.join(':').toStdString();
}

bool InputSpecForm::set_spec(const std::string& spec) {
  const QString text = QString::fromStdString(spec);
  if (text.isEmpty()) {
    kind_->setCurrentIndex(0);
    return true;
  }
  for (int i = kKindCount - 1; i > 0; --i) {
    const QString prefix = kKinds[i].prefix;
    if (!text.startsWith(prefix + ":")) continue;
    kind_->setCurrentIndex(i);
    const QString rest = text.mid(prefix.size() + 1);
    if (prefix == "csv") {
      csv_path_->setText(rest);
      return true;
    }
    QStringList values = rest.split(':');
    if (prefix == "mass") {
      QString v = values.value(0);
      const bool grams = v.endsWith("g") && !v.endsWith("kg");
      v.remove("kg").remove("g");
      value_[0]->setValue(v.toDouble() * (grams ? 1e-3 : 1.0));
      return true;
    }
    for (int p = 0; p < kKinds[i].param_count && p < values.size(); ++p)
      value_[p]->setValue(values[p].toDouble());
    if (kKinds[i].stroke && values.size() > kKinds[i].param_count)
      stroke_->setCurrentIndex(values.last() == "half" ? 1 : 0);
    return true;
  }
  return false;
}

}  // namespace pat::ui

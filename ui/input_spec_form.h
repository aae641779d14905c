// The choice of key input with its parameters, giving an input SPEC (DESIGN.md section 5):
// mass:1kg, force:const:N, force:pulse:N:MS, force:double:N:MS:GAP_MS,
// motion:sine:HZ[:full|half], motion:chirp:F0:F1:S[:full|half], csv:PATH, or none.
#pragma once

#include <QWidget>
#include <string>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace pat::ui {

class InputSpecForm : public QWidget {
  Q_OBJECT
 public:
  explicit InputSpecForm(QWidget* parent = nullptr);

  /// The SPEC of the current choice ("" = no finger on the key).
  std::string spec() const;
  /// Selects the form matching a SPEC (unknown kinds leave the form as it is); returns whether
  /// the SPEC was understood.
  bool set_spec(const std::string& spec);

 signals:
  void specChanged();

 private:
  void show_fields();
  QComboBox* kind_;
  QDoubleSpinBox* value_[3];
  QLabel* value_label_[3];
  QComboBox* stroke_;
  QLineEdit* csv_path_;
  QPushButton* browse_;
};

}  // namespace pat::ui

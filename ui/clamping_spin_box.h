// A millimetre field that takes a number typed beyond its range to the nearest end of it.
//
// QDoubleSpinBox refuses each keystroke that would leave its range, so "99" typed into a
// ±4 mm field left it at its value without a word. Here a number out of range is accepted
// while typed and brought to the nearest end when it is entered (Enter, or focus leaving); an
// emptied field or a lone sign goes back to the value it had.
#pragma once

#include <QDoubleSpinBox>

namespace pat::ui {

class ClampingSpinBox : public QDoubleSpinBox {
 public:
  explicit ClampingSpinBox(QWidget* parent = nullptr);

  QValidator::State validate(QString& text, int& position) const override;
  void fixup(QString& text) const override;

 private:
  /// The number in `text` (suffix and spaces taken off), if it reads as one.
  bool read_number(const QString& text, double& value) const;
};

}  // namespace pat::ui

// One regulation setting in the panel: the adjuster's slider and spin box (mm from its
// regulated position, within its physical range; the sign convention in the tooltip), the
// live measured value, and the target with its tolerance band (red when out of tolerance).
#pragma once

#include <QWidget>
#include <optional>

#include "model/action_model.h"

class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QSlider;

namespace pat::ui {

class RegulationRow : public QObject {
  Q_OBJECT
 public:
  /// Adds the row's widgets (children of `parent`) to `grid` at `row`; `setting` may be null
  /// (no target known).
  RegulationRow(const Adjuster& adjuster, const RegulationSetting* setting, QGridLayout* grid,
                int row, QWidget* parent);
  ~RegulationRow() override;

  const std::string& name() const { return name_; }
  /// Adjuster position, mm.
  double value_mm() const;
  /// Moves slider and spin box without emitting valueChanged.
  void set_value_mm(double mm);
  /// The measured value (setting's unit); colours it against the tolerance band.
  /// A reading; `note` (how it was read, when not as the action stands) goes to its tooltip.
  /// True when the note is new (not the one shown with the previous reading).
  bool set_measured(double value, const QString& note = {});
  /// The measurement could not be taken: shows why.
  /// Shows "no reading" with `reason` in its tooltip; true when the reason is new (not the one
  /// shown already), for the caller to say it once where the class can read it.
  bool set_measurement_failed(const QString& reason);
  /// A new measurement is being taken.
  void set_measuring();
  /// A recorded replay is on screen (true; the deregulation demo) or the live action again
  /// (false). In a replay the adjuster cannot be moved (the replay cannot change) and the
  /// measured column reads "replay": the readings that arrive are the live action's, kept for
  /// when it returns.
  void set_replayed(bool replayed);
  bool replayed() const { return replayed_; }
  /// Refits the measured value's column to the current font (larger text).
  void fit_to_font();
  std::optional<double> measured() const { return measured_; }
  bool out_of_tolerance() const;
  QSlider* slider() const { return slider_; }
  QDoubleSpinBox* spin_box() const { return spin_; }
  QLabel* measured_label() const { return measured_label_; }
  /// The setting's unit ("mm", or "fraction"); "mm" for an adjuster without a setting.
  std::string unit() const { return setting_ ? setting_->unit : std::string("mm"); }

 signals:
  /// The user moved the adjuster (mm).
  void valueChanged(double mm);

 private:
  std::string name_;
  std::optional<RegulationSetting> setting_;
  QLabel* name_label_;
  QSlider* slider_;
  QDoubleSpinBox* spin_;
  QLabel* measured_label_;
  QLabel* target_label_;
  std::optional<double> measured_;
  QString failure_;  ///< why the last reading failed; empty after a reading
  QString note_;     ///< how the last reading was taken, when not as the action stands
  bool measuring_ = false;
  bool replayed_ = false;
  /// Shows the reading kept (or "replay") in the measured column.
  void show_reading();
};

}  // namespace pat::ui

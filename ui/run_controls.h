// The run controls: input choice with its parameters and Start (from rest), play/pause, single
// step back and forward, rewind, playback speed (real time down to 1/1000) with the achieved
// real-time factor, and the strength of the blow struck from the keyboard (space, or 1–5).
#pragma once

#include <QWidget>
#include <string>

class QComboBox;
class QLabel;
class QToolButton;

namespace pat::ui {

class InputSpecForm;
class PlaybackController;

class RunControls : public QWidget {
  Q_OBJECT
 public:
  RunControls(PlaybackController* controller, QWidget* parent = nullptr);

  InputSpecForm* input_form() const { return input_; }
  /// The blow SPEC of a keyboard strike at `level` 1–5 (pianissimo to fortissimo), or at the
  /// chosen strength when level is 0.
  std::string blow_spec(int level = 0) const;
  void set_blow_level(int level);
  /// Playback speeds offered (simulated s per wall s), fastest first.
  static const std::vector<double>& speeds();
  void set_speed_index(int index);
  int speed_index() const;

 signals:
  /// Start pressed: a new run from rest with the input of the form.
  void startRequested(const std::string& spec);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void update_play_button(bool playing);
  /// Fixed widths in the current font, so that the toolbar does not shift: the achieved-speed
  /// readout's (its widest reading) and the Play button's (as wide as Pause).
  void fit_fixed_widths();
  PlaybackController* controller_;
  InputSpecForm* input_;
  QToolButton* play_ = nullptr;
  QComboBox* speed_;
  QComboBox* blow_;
  QLabel* factor_ = nullptr;
};

}  // namespace pat::ui

// The window's live plots: key and hammer angles, hammer–string gap, finger force, contact
// forces. Frames are appended as the display passes them; the time axes move together and
// follow the displayed time until the user zooms or pans one (Follow brings it back).
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "frame.h"

class QCheckBox;

namespace pat::ui {

class PlotPanel;

class PlotStack : public QWidget {
  Q_OBJECT
 public:
  explicit PlotStack(QWidget* parent = nullptr);

  /// Builds the series of a model's action (contacts differ between grand and upright).
  void set_model(const ActionModel& model);
  void clear();
  /// Appends frames (in time order) and moves the time axes if following.
  void append(const std::vector<Frame>& frames);
  /// The displayed time (a rewind moves it back inside the plotted data).
  void show_time(double t);
  /// The time the action view shows: a line on every plot (stepping back, rewinding or seeking
  /// moves it within the data already plotted; following, the time window keeps it in view).
  void mark_time(double t);
  void set_following(bool follow);
  bool following() const { return following_; }
  /// Width of the followed time window, s (0.25 s at first); applied at once when following.
  void set_window(double seconds);
  double window() const { return window_s_; }
  /// The whole run kept (up to its last 60 s) on the time axes, values fitted to it, growing as
  /// the run goes on until Follow or a zoom or pan by hand (a slow press's let-off and drop had
  /// scrolled away after 0.25 s; the axes had then stayed put while new blows ran off them).
  /// That mode stays through a new run (Start from rest, another blow's run) until Follow or a
  /// zoom or pan by hand ends it.
  void show_whole_run();
  bool showing_whole_run() const { return whole_run_; }

  std::vector<PlotPanel*> panels() const;
  PlotPanel* angles() const { return angles_; }
  PlotPanel* gap() const { return gap_; }
  PlotPanel* finger() const { return finger_; }
  PlotPanel* contacts() const { return contacts_; }

 signals:
  void followingChanged(bool follow);
  /// The whole-run mode began or ended (show_whole_run; Follow, a zoom or a pan).
  void wholeRunChanged(bool whole);

 private:
  void sync_time_range(PlotPanel* source, double lo, double hi);
  void replot();
  /// The time axes over the whole run kept, values fitted.
  void fit_whole_run();
  void set_whole_run(bool whole);

  PlotPanel* angles_;
  PlotPanel* gap_;
  PlotPanel* finger_;
  PlotPanel* contacts_;
  int key_body_ = 0, hammer_body_ = 0;
  std::vector<int> plotted_contacts_;  // contact index of each contact-force series
  bool following_ = true;
  bool whole_run_ = false;  // show_whole_run: the time axes grow with the run
  double window_s_ = 0.25;
  double latest_t_ = 0.0;
  std::optional<double> marked_t_;
  // replots at most about 30 times a second (the action view takes the full 60)
  QElapsedTimer since_replot_;
  QTimer deferred_replot_;
};

}  // namespace pat::ui

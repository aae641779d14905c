// The action's motion as a numbered PNG sequence, for slides or a video editor (aesthetics.md,
// what users ask for: a video of the animation): the action view drawn offscreen at the export
// size at simulated times t0, t0 + Δt, … ≤ t1 of a recorded run, framed, labelled and with the
// numbers shown as in the window; and frames.csv (frame, time_s) to put the times to the pictures.
#pragma once

#include <QSize>
#include <QString>
#include <functional>

#include "view_focus.h"

namespace pat::ui {

class FrameHistory;

struct AnimationOptions {
  double from_s = 0.0, to_s = 0.0;  ///< simulated time range, s (clamped to the recorded run)
  double interval_s = 1e-3;         ///< simulated time between pictures, s
  QSize size{1600, 1000};           ///< picture size, px
  ViewFocus focus = ViewFocus::whole;
  bool labels = true;
  bool measurements = true;  ///< the readout's gap and force and the arrows' newtons
};

/// Most pictures one export writes (2000: 80 s of video at 25 pictures a second).
inline constexpr int kMaxAnimationFrames = 2000;

/// The pictures' times: from_s, from_s + interval_s, … up to to_s, within the recorded run.
/// Throws InputError when the range holds no recorded time, the interval is not positive, or
/// more than kMaxAnimationFrames pictures would be written.
std::vector<double> animation_times(const FrameHistory& history, const AnimationOptions& options);

/// Writes frame_0000.png, frame_0001.png, … and frames.csv into `folder`, an existing folder
/// holding none of them: nothing is overwritten (InputError naming the first file in the way, or
/// the file that could not be written). `progress(done, total)` is called after each picture and
/// may return false to stop (the pictures written so far stay, with their frames.csv). Returns
/// the number of pictures written.
int export_action_animation(const FrameHistory& history, const AnimationOptions& options,
                            const QString& folder,
                            const std::function<bool(int done, int total)>& progress = {});

}  // namespace pat::ui

// The frames of a run kept for rewinding and replay: time-ordered, capped in length (the oldest
// frames are dropped first).
#pragma once

#include <deque>

#include "frame.h"

namespace pat::ui {

class FrameHistory {
 public:
  explicit FrameHistory(std::size_t capacity = 100000) : capacity_(capacity) {}

  void append(Frame frame);
  void clear() { frames_.clear(); }
  bool empty() const { return frames_.empty(); }
  std::size_t size() const { return frames_.size(); }
  const Frame& at(std::size_t i) const { return frames_[i]; }
  double first_time() const { return frames_.empty() ? 0.0 : frames_.front().t; }
  double last_time() const { return frames_.empty() ? 0.0 : frames_.back().t; }

  /// Index of the last frame at or before t (0 when t is before the first frame).
  std::size_t index_at(double t) const;
  /// The frame at t, with q, v and the readings (angles, gap, finger, contact forces, strap
  /// tensions) interpolated linearly between the two recorded frames around it (slow motion
  /// between samples), but a force or tension that is zero in either frame, which is the earlier
  /// frame's; the model and run from the earlier frame, and no events.
  Frame interpolated(double t) const;

 private:
  std::deque<Frame> frames_;
  std::size_t capacity_;
};

}  // namespace pat::ui

#include "frame_history.h"

#include <algorithm>

namespace pat::ui {

void FrameHistory::append(Frame frame) {
  frames_.push_back(std::move(frame));
  while (frames_.size() > capacity_) frames_.pop_front();
}

std::size_t FrameHistory::index_at(double t) const {
  const auto after = std::upper_bound(frames_.begin(), frames_.end(), t,
                                      [](double time, const Frame& f) { return time < f.t; });
  if (after == frames_.begin()) return 0;
  return static_cast<std::size_t>(after - frames_.begin()) - 1;
}

Frame FrameHistory::interpolated(double t) const {
  const std::size_t i = index_at(t);
  Frame frame = frames_[i];
  if (i + 1 < frames_.size() && t > frame.t) {
    const Frame& next = frames_[i + 1];
    // only within one model: a slider change between the two frames is not blended
    if (next.model == frame.model && next.t > frame.t) {
      const double w = std::clamp((t - frame.t) / (next.t - frame.t), 0.0, 1.0);
      frame.q = (1.0 - w) * frame.q + w * next.q;
      frame.v = (1.0 - w) * frame.v + w * next.v;
      frame.t = t;
      frame.events.clear();
    }
  }
  return frame;
}

}  // namespace pat::ui

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
  if (frames_.empty()) return Frame{};  // nothing recorded (a run cleared meanwhile)
  const std::size_t i = index_at(t);
  Frame frame = frames_[i];
  if (i + 1 < frames_.size() && t > frame.t) {
    const Frame& next = frames_[i + 1];
    // only within one model: a slider change between the two frames is not blended
    if (next.model == frame.model && next.t > frame.t) {
      const double w = std::clamp((t - frame.t) / (next.t - frame.t), 0.0, 1.0);
      frame.q = (1.0 - w) * frame.q + w * next.q;
      frame.v = (1.0 - w) * frame.v + w * next.v;
      // the readings too, so that the readout and the plots' values go with the parts drawn; a
      // contact force or strap tension that is zero at either end is not blended (the contact
      // opens or closes between the two frames: the earlier frame's state holds, as the felt's
      // "on the string" reading does)
      const auto blend = [w](double a, double b) { return (1.0 - w) * a + w * b; };
      const auto blend_all = [&](std::vector<double>& values, const std::vector<double>& to,
                                 bool contacts) {
        if (values.size() != to.size()) return;
        for (std::size_t k = 0; k < values.size(); ++k)
          if (!contacts || (values[k] > 0.0 && to[k] > 0.0)) values[k] = blend(values[k], to[k]);
      };
      blend_all(frame.angle_deg, next.angle_deg, false);
      blend_all(frame.contact_force_n, next.contact_force_n, true);
      blend_all(frame.strap_tension_n, next.strap_tension_n, true);
      frame.hammer_string_gap_mm = blend(frame.hammer_string_gap_mm, next.hammer_string_gap_mm);
      frame.finger_force_n = blend(frame.finger_force_n, next.finger_force_n);
      frame.t = t;
      frame.events.clear();
    }
  }
  return frame;
}

}  // namespace pat::ui

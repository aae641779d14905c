#include "analysis/progress.h"

#include <algorithm>

namespace pat {

void ProgressReporter::partial(double item_fraction, const std::string& stage) {
  std::lock_guard<std::mutex> lock(mutex_);
  const double within = std::clamp(item_fraction, 0.0, 1.0);
  report((static_cast<double>(done_) + within) / static_cast<double>(total_), stage);
}

void ProgressReporter::item_done(const std::string& stage) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = std::min(done_ + 1, total_);
  report(static_cast<double>(done_) / static_cast<double>(total_), stage);
}

void ProgressReporter::report(double fraction, const std::string& stage) {
  // called with mutex_ held: the callback sees reports one at a time and in order
  if (callback_ && !cancelled_.load() && !callback_(fraction, stage)) cancelled_.store(true);
}

}  // namespace pat

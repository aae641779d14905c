#include "analysis/progress.h"

#include <algorithm>
#include <chrono>

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
  last_fraction_ = fraction;
  last_stage_ = stage;
  if (callback_ && !cancelled_.load() && !callback_(fraction, stage)) cancelled_.store(true);
}

bool ProgressReporter::still_wanted() {
  if (cancelled_.load(std::memory_order_relaxed)) return false;
  if (!callback_ || calls_since_poll_.fetch_add(1, std::memory_order_relaxed) + 1 < kPollEvery)
    return true;
  calls_since_poll_.store(0, std::memory_order_relaxed);
  const long long now_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                               std::chrono::steady_clock::now().time_since_epoch())
                               .count();
  long long last_ms = last_poll_ms_.load(std::memory_order_relaxed);
  // one thread asks; the others go on until the answer
  if (now_ms - last_ms < kPollIntervalMs ||
      !last_poll_ms_.compare_exchange_strong(last_ms, now_ms, std::memory_order_relaxed))
    return true;
  std::lock_guard<std::mutex> lock(mutex_);
  report(last_fraction_, last_stage_);
  return !cancelled_.load();
}

}  // namespace pat

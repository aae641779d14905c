// Progress and cancellation of long analyses. The window shows the fraction in a non-modal
// progress bar and its Cancel button makes the callback return false; the command line passes
// no callback. An analysis made of independent runs counts them through one ProgressReporter,
// which is safe to call from several worker threads.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

namespace pat {

/// Fraction done in [0, 1] and a short description of the current stage ("2 Hz of 20");
/// return false to cancel.
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;

/// Thrown out of an analysis when its progress callback asked to cancel.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

/// Counts finished work items out of a total and forwards the fraction to a callback.
class ProgressReporter {
 public:
  ProgressReporter(ProgressCallback callback, std::size_t total_items)
      : callback_(std::move(callback)), total_(total_items == 0 ? 1 : total_items) {}

  /// Reports progress within the current item (0..1) without finishing it.
  void partial(double item_fraction, const std::string& stage);
  /// One item finished.
  void item_done(const std::string& stage);
  /// True once the callback has asked to cancel (from any thread).
  bool cancelled() const { return cancelled_.load(); }
  /// For the steps of a long item that reports nothing itself (a run, a sweep inside a study):
  /// false once cancelled. Every kPollEvery calls, and at most every kPollIntervalMs of wall
  /// time, it asks the callback again with the last fraction and stage, so that a Cancel is seen
  /// within a few tens of milliseconds, not when the item ends (a comparison's sweeps took
  /// seconds). From any thread; cheap enough for every integration step (a counter).
  bool still_wanted();
  /// Throws Cancelled if cancelled.
  void throw_if_cancelled() const {
    if (cancelled()) throw Cancelled();
  }

 private:
  void report(double fraction, const std::string& stage);

  static constexpr unsigned kPollEvery = 256;
  static constexpr long long kPollIntervalMs = 20;

  ProgressCallback callback_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  // the last report, given again by still_wanted()
  double last_fraction_ = 0.0;
  std::string last_stage_;
  std::atomic<unsigned> calls_since_poll_{0};
  std::atomic<long long> last_poll_ms_{0};
};

}  // namespace pat

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
  /// Throws Cancelled if cancelled.
  void throw_if_cancelled() const {
    if (cancelled()) throw Cancelled();
  }

 private:
  void report(double fraction, const std::string& stage);

  ProgressCallback callback_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
};

}  // namespace pat

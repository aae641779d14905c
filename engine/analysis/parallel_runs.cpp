#include "analysis/parallel_runs.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace pat {

unsigned default_thread_count() {
  return std::max(1u, std::thread::hardware_concurrency());
}

void run_parallel(std::size_t count, const std::function<void(std::size_t)>& job,
                  ProgressReporter* progress, unsigned threads) {
  if (threads == 0) threads = default_thread_count();
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;

  auto worker = [&] {
    for (;;) {
      if (failed.load() || (progress && progress->cancelled())) return;
      const std::size_t index = next.fetch_add(1);
      if (index >= count) return;
      try {
        job(index);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed.store(true);
        return;
      }
      if (progress) progress->item_done(std::to_string(index + 1) + " of " + std::to_string(count));
    }
  };

  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(threads);
    for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  if (first_error) std::rethrow_exception(first_error);
  if (progress) progress->throw_if_cancelled();
}

}  // namespace pat

// Independent runs of an analysis (sweep frequencies, sensitivity cases, diagnosis candidates)
// spread over the available cores. Each job gets its index and must not share mutable state with
// the others (each builds its own ActionDynamics / Simulator; an ActionModel is immutable and can
// be shared).
#pragma once

#include <cstddef>
#include <functional>

#include "analysis/progress.h"

namespace pat {

/// Runs job(0) … job(count − 1) on up to `threads` threads (0: one per core). Items are handed
/// out in index order. When `progress` is given, each finished job counts as one item, and after
/// a cancellation no new job starts and Cancelled is thrown once the running ones return. The
/// first exception thrown by a job is rethrown after all threads have stopped.
void run_parallel(std::size_t count, const std::function<void(std::size_t)>& job,
                  ProgressReporter* progress = nullptr, unsigned threads = 0);

/// Number of worker threads run_parallel uses for `threads` = 0.
unsigned default_thread_count();

}  // namespace pat

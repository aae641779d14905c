#include "analysis/parallel_runs.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace pat {
namespace {

TEST(ParallelRuns, RunsEveryIndexOnceAndReportsEachAsDone) {
  std::vector<std::atomic<int>> calls(100);
  double last_fraction = 0.0;
  int reports = 0;
  ProgressReporter progress(
      [&](double fraction, const std::string&) {
        EXPECT_GE(fraction, last_fraction);  // reports arrive in order, under the reporter's lock
        last_fraction = fraction;
        ++reports;
        return true;
      },
      calls.size());
  run_parallel(
      calls.size(), [&](std::size_t i) { ++calls[i]; }, &progress, 2);
  for (const auto& c : calls) EXPECT_EQ(c.load(), 1);
  EXPECT_EQ(reports, 100);
  EXPECT_DOUBLE_EQ(last_fraction, 1.0);
}

TEST(ParallelRuns, CancelStopsHandingOutJobsAndThrows) {
  std::atomic<int> started{0};
  ProgressReporter progress([](double fraction, const std::string&) { return fraction < 0.1; },
                            1000);
  EXPECT_THROW(run_parallel(
                   1000, [&](std::size_t) { ++started; }, &progress, 2),
               Cancelled);
  // cancelled at the first report at or above 10 %: at most one job per thread after that
  EXPECT_LT(started.load(), 110);
}

// A long item that reports nothing (a run, a sweep inside a study) asks again through
// still_wanted(): the callback hears the last report again within its polling interval (20 ms),
// so a Cancel pressed during the item is seen then, not when the item ends (closing the window
// during "Upright vs grand" had waited 14-27 s for the comparison's sweeps).
TEST(ParallelRuns, ALongItemAsksTheCallbackAgainAndSeesACancel) {
  int asked = 0;
  bool cancel = false;
  ProgressReporter progress(
      [&](double fraction, const std::string& stage) {
        EXPECT_EQ(fraction, 0.0);  // the item never finishes: the first report, given again
        EXPECT_EQ(stage, "starting");
        ++asked;
        return !cancel;
      },
      1);
  progress.partial(0.0, "starting");
  EXPECT_EQ(asked, 1);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed_ms = [&] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
  };
  // a busy item for 200 ms of wall time (ten polling intervals): asked again at least once
  while (elapsed_ms() < 200.0) ASSERT_TRUE(progress.still_wanted());
  EXPECT_GE(asked, 2);
  cancel = true;
  while (progress.still_wanted()) ASSERT_LT(elapsed_ms(), 10000.0) << "the cancel was not seen";
  EXPECT_TRUE(progress.cancelled());
}

TEST(ParallelRuns, FirstErrorIsRethrownAfterTheThreadsStop) {
  std::atomic<int> finished{0};
  EXPECT_THROW(run_parallel(
                   50,
                   [&](std::size_t i) {
                     if (i == 7) throw std::runtime_error("run 7 diverged");
                     ++finished;
                   },
                   nullptr, 2),
               std::runtime_error);
  EXPECT_LT(finished.load(), 50);
}

}  // namespace
}  // namespace pat

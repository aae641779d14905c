#include "analysis/parallel_runs.h"

#include <gtest/gtest.h>

#include <atomic>
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

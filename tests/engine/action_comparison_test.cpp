// Upright vs grand (analysis/action_comparison.h): the same blow on both actions, and a cancel
// that is seen while a run is still going.
#include "analysis/action_comparison.h"

#include <gtest/gtest.h>

#include <atomic>

#include "test_support.h"

namespace pat {
namespace {

// The mezzo-forte blow strikes on both actions, and the overlay holds each action's columns.
TEST(ActionComparison, TheSameBlowStrikesOnBothActions) {
  const ActionModel grand = test::shipped("grand"), upright = test::shipped("upright");
  ComparisonOptions options;
  options.repetition_limits = false;
  const ComparisonResult r = compare_actions({&grand, &upright}, options);
  ASSERT_EQ(r.actions.size(), 2u);
  for (const ActionComparison& a : r.actions) {
    ASSERT_TRUE(a.first_impact.has_value()) << a.action;
    // F3 of DESIGN.md: impact speeds of about 1 to 6 m/s from soft to very loud
    EXPECT_GT(a.first_impact->hammer_velocity, 1.0) << a.action;
    EXPECT_LT(a.first_impact->hammer_velocity, 6.0) << a.action;
    EXPECT_GE(r.overlay.column_index(a.action + "_hammer_angle_deg"), 0) << a.action;
  }
}

// A cancel given while no run has finished (the progress still at 0) stops the comparison: the
// runs ask again while they go (the window's Cancel, and closing it, had waited for whole sweeps:
// 14-27 s).
TEST(ActionComparison, ACancelIsSeenWhileTheFirstRunsGo) {
  const ActionModel grand = test::shipped("grand"), upright = test::shipped("upright");
  ComparisonOptions options;  // with the four sweeps: many seconds of work
  std::atomic<int> asked_before_any_finished{0};
  EXPECT_THROW(compare_actions({&grand, &upright}, options,
                               [&](double fraction, const std::string&) {
                                 if (fraction == 0.0) ++asked_before_any_finished;
                                 return false;
                               }),
               Cancelled);
  EXPECT_GE(asked_before_any_finished.load(), 1);
}

}  // namespace
}  // namespace pat

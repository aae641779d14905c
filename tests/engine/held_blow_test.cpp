// Issue 7: on the regulated upright a blow held down strikes the string once, from a soft to a
// very loud one; the backcheck then holds the hammer about where the regulation checks it.
// The grand's backcheck catches the rebound on its first pass, up to the regulation's forte blow
// (the measured Kawai grand, ../shared/data: caught about 18 mm from the string 22 ms after a
// fast strike, then held while the key is held).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "analysis/parallel_runs.h"
#include "test_support.h"

namespace pat {
namespace {

struct HeldBlow {
  std::size_t impacts = 0;
  double deepest_mm = 0.0;    // the largest hammer–string gap within 40 ms after the first strike
  double final_gap_mm = 0.0;  // hammer–string gap at the end of the run
  bool ok = false;
};

/// Each force held on the key for 0.5 s (the strike, the catch and the whippen's settling under
/// the held key), the runs in parallel.
std::vector<HeldBlow> held_blows(const ActionModel& model, const std::vector<double>& forces_n) {
  std::vector<HeldBlow> blows(forces_n.size());
  run_parallel(forces_n.size(), [&](std::size_t i) {
    const SimulationResult r = test::run(model, "force:const:" + std::to_string(forces_n[i]), 0.5);
    const auto impacts = test::events_of(r, "impact");
    const int gap = r.trace.column_index("hammer_string_gap_mm");
    HeldBlow& blow = blows[i];
    blow.ok = r.status == "ok" && gap >= 0 && !r.trace.rows.empty();
    blow.impacts = impacts.size();
    if (!blow.ok) return;
    blow.final_gap_mm = r.trace.rows.back()[gap];
    if (impacts.empty()) return;
    const double t_strike = impacts.front()->t;
    for (const auto& row : r.trace.rows)
      if (row[0] > t_strike && row[0] < t_strike + 0.04)
        blow.deepest_mm = std::max(blow.deepest_mm, row[gap]);
  });
  return blows;
}

TEST(HeldBlow, UprightStrikesOnceUnderEveryHeldForceFromFiveToSixtyNewtons) {
  const ActionModel upright = test::shipped("upright");
  const std::vector<double> forces_n = {5, 10, 15, 20, 30, 40, 50, 60};
  // (a second strike came at 54–110 ms with the earlier preset)
  const std::vector<HeldBlow> blows = held_blows(upright, forces_n);
  for (std::size_t i = 0; i < forces_n.size(); ++i) {
    std::printf("upright held %2.0f N: %zu impact(s), hammer held %.1f mm from the string\n",
                forces_n[i], blows[i].impacts, blows[i].final_gap_mm);
    ASSERT_TRUE(blows[i].ok) << forces_n[i] << " N";
    EXPECT_EQ(blows[i].impacts, 1u) << forces_n[i] << " N";
    // held near the regulated checking distance (16 mm): the punching and the capstan cushion
    // give a little more under a harder press, which lifts the whippen and with it the held
    // hammer a few mm (measured 13.7–16.7 mm); ±6 mm keeps the hammer clearly off the string and
    // clearly caught
    EXPECT_GT(blows[i].final_gap_mm, 16.0 - 6.0) << forces_n[i] << " N";
    EXPECT_LT(blows[i].final_gap_mm, 16.0 + 6.0) << forces_n[i] << " N";
  }
}

TEST(HeldBlow, GrandCatchesTheReboundOnItsFirstPassUpToTheForteBlow) {
  const ActionModel grand = test::shipped("grand");
  // up to kForteBlowNewtons (40 N), the blow the checking regulation reads
  const std::vector<double> forces_n = {5, 10, 20, 30, 40};
  const std::vector<HeldBlow> catches = held_blows(grand, forces_n);
  for (std::size_t i = 0; i < forces_n.size(); ++i) {
    std::printf(
        "grand held %2.0f N: %zu impact(s), deepest %.1f mm after the strike, held %.1f mm\n",
        forces_n[i], catches[i].impacts, catches[i].deepest_mm, catches[i].final_gap_mm);
    ASSERT_TRUE(catches[i].ok) << forces_n[i] << " N";
    EXPECT_EQ(catches[i].impacts, 1u) << forces_n[i] << " N";
    // caught where the tail wedges on the face, 19.0-19.9 mm (the regulation reads the first
    // touch, 16 mm); 25 mm is well short of the 45 mm rest the hammer fell to before the backcheck
    // felt was stiffened (a 40 N rebound went past the face to 55.5 mm, onto the rest rail)
    EXPECT_LT(catches[i].deepest_mm, 25.0) << forces_n[i] << " N";
    // still held at 0.5 s, near where it was caught (18.4-19.8 mm)
    EXPECT_GT(catches[i].final_gap_mm, 16.0 - 6.0) << forces_n[i] << " N";
    EXPECT_LT(catches[i].final_gap_mm, 16.0 + 6.0) << forces_n[i] << " N";
  }
}

}  // namespace
}  // namespace pat

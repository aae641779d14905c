// Issue 7: on the regulated upright a blow held down strikes the string once, from a soft to a
// very loud one; the backcheck then holds the hammer about where the regulation checks it.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "analysis/parallel_runs.h"
#include "test_support.h"

namespace pat {
namespace {

struct HeldBlow {
  std::size_t impacts = 0;
  double final_gap_mm = 0.0;  // hammer–string gap at the end of the run
  bool ok = false;
};

TEST(HeldBlow, UprightStrikesOnceUnderEveryHeldForceFromFiveToSixtyNewtons) {
  const ActionModel upright = test::shipped("upright");
  const std::vector<double> forces_n = {5, 10, 15, 20, 30, 40, 50, 60};
  std::vector<HeldBlow> blows(forces_n.size());
  run_parallel(forces_n.size(), [&](std::size_t i) {
    // 0.5 s: the strike (9–40 ms), the catch and the whippen's settling under the held key
    // (a second strike came at 54–110 ms with the earlier preset)
    const SimulationResult r =
        test::run(upright, "force:const:" + std::to_string(forces_n[i]), 0.5);
    const int gap = r.trace.column_index("hammer_string_gap_mm");
    blows[i].ok = r.status == "ok" && gap >= 0 && !r.trace.rows.empty();
    blows[i].impacts = test::events_of(r, "impact").size();
    if (blows[i].ok) blows[i].final_gap_mm = r.trace.rows.back()[gap];
  });
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

}  // namespace
}  // namespace pat

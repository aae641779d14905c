// pianoaction bench's W-method against CVODE at equal accuracy (issue 2, must-show 6: the speed
// figure and its ratio to CVODE at equal accuracy): the cheapest CVODE run at least as accurate
// as the W-method is the one compared.
#include <gtest/gtest.h>

#include "analysis/bench.h"

namespace pat {
namespace {

BenchCase make_case(const std::string& action, const std::string& integrator,
                    const std::string& setting, double realtime_factor, double error_deg) {
  BenchCase c;
  c.action = action;
  c.integrator = integrator;
  c.setting = setting;
  c.realtime_factor = realtime_factor;
  c.max_error_deg = error_deg;
  c.hammer_range_deg = 25.0;
  return c;
}

TEST(BenchComparison, TakesTheFastestCvodeAtLeastAsAccurateAsW2) {
  const std::vector<BenchCase> cases{
      make_case("grand", "w2", "h_s=1e-05", 7.0, 0.025),
      make_case("grand", "rodas", "rtol=1e-06", 5.0, 0.002),   // not CVODE
      make_case("grand", "cvode", "rtol=0.0001", 14.0, 0.55),  // faster but less accurate
      make_case("grand", "cvode", "rtol=1e-05", 10.0, 0.015),  // the one
      make_case("grand", "cvode", "rtol=1e-06", 7.5, 0.005),   // accurate but slower
      make_case("upright", "w2", "h_s=1e-05", 12.0, 0.18),
      make_case("upright", "cvode", "rtol=0.0001", 15.0, 0.21),  // less accurate
      make_case("upright", "cvode", "rtol=1e-05", 9.0, 0.18),    // as accurate: counts
  };
  const std::vector<EqualAccuracy> result = compare_at_equal_accuracy(cases);
  ASSERT_EQ(result.size(), 2u);
  EXPECT_EQ(result[0].action, "grand");
  ASSERT_TRUE(result[0].cvode.has_value());
  EXPECT_EQ(result[0].cvode->setting, "rtol=1e-05");
  EXPECT_DOUBLE_EQ(result[0].ratio, 0.7);
  EXPECT_EQ(result[1].action, "upright");
  ASSERT_TRUE(result[1].cvode.has_value());
  EXPECT_EQ(result[1].cvode->setting, "rtol=1e-05");
  EXPECT_DOUBLE_EQ(result[1].ratio, 12.0 / 9.0);
}

TEST(BenchComparison, NoCvodeAsAccurateGivesNoRatio) {
  const std::vector<BenchCase> cases{
      make_case("grand", "w2", "h_s=1e-05", 7.0, 0.001),
      make_case("grand", "cvode", "rtol=1e-07", 5.0, 0.0015),
  };
  const std::vector<EqualAccuracy> result = compare_at_equal_accuracy(cases);
  ASSERT_EQ(result.size(), 1u);
  EXPECT_FALSE(result[0].cvode.has_value());
  EXPECT_EQ(result[0].ratio, 0.0);
}

}  // namespace
}  // namespace pat

// The upright double-blow study (analysis/double_blow_study.h): fact F6 and its input checks.
#include "analysis/double_blow_study.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "test_support.h"

namespace pat {
namespace {

const DoubleBlowVariant& variant(const DoubleBlowStudy& study, const std::string& name) {
  for (const DoubleBlowVariant& v : study.variants)
    if (v.name == name) return v;
  ADD_FAILURE() << "no variant " << name;
  return study.variants.front();
}

TEST(DoubleBlowStudy, BridleStrapAndButtSpringEachBringTheHammerBack) {
  // the part of fact F6 (paper section 7.3, Fig. 25) the shipped upright reproduces: with both
  // parts the hammer is back on its rest rail well within the run; without the bridle strap it
  // comes back later (0.204 against 0.198 s after the impact), without the butt spring later
  // still (0.239 s) and without either not at all. (That the strap matters more does not hold:
  // the butt spring's share is the larger.)
  const DoubleBlowStudy study = double_blow_study(test::shipped("upright"));
  ASSERT_EQ(study.variants.size(), 4u);
  const DoubleBlowVariant& both = variant(study, "both");
  const DoubleBlowVariant& no_spring = variant(study, "no_butt_spring");
  const DoubleBlowVariant& neither = variant(study, "neither");
  for (const DoubleBlowVariant& v : study.variants) {
    EXPECT_TRUE(v.stop_cause.empty()) << v.name << ": " << v.stop_cause;
    // the first blow is the same in every variant and hits the string (F2: 1–6 m/s)
    EXPECT_GT(v.first_impact_velocity_mps, 1.0) << v.name;
    EXPECT_LT(v.first_impact_velocity_mps, 6.0) << v.name;
  }
  ASSERT_GT(both.hammer_return_s, 0.0);
  // the key is released 60 + 1 ms after the start and the impact is at about 23 ms: the return
  // takes at least the ~40 ms the key is still held after the impact
  EXPECT_GT(both.hammer_return_s, 0.035);
  auto later_or_never = [&](const DoubleBlowVariant& v) {
    return v.hammer_return_s < 0.0 || v.hammer_return_s > both.hammer_return_s;
  };
  const DoubleBlowVariant& no_bridle = variant(study, "no_bridle");
  EXPECT_TRUE(later_or_never(no_bridle)) << no_bridle.hammer_return_s;
  EXPECT_TRUE(later_or_never(no_spring)) << no_spring.hammer_return_s;
  EXPECT_TRUE(later_or_never(neither)) << neither.hammer_return_s;
  // the CSV has the hammer angle of each variant's double-blow run
  ASSERT_EQ(study.trace.columns.size(), 5u);
  EXPECT_EQ(study.trace.columns[1], "both_hammer_angle_deg");
  EXPECT_GT(study.trace.rows.size(), 1000u);
}

TEST(DoubleBlowStudy, NeedsAnUprightWithBridleAndButtSpring) {
  EXPECT_THROW(double_blow_study(test::shipped("grand")), InputError);
}

}  // namespace
}  // namespace pat

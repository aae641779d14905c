// The key alone falling onto the front-rail punching (analysis/key_fall.h): its free fall
// against the closed form of a rigid lever under gravity (energy quadrature), with and without
// the balance-pin friction, and its landing.
#include "analysis/key_fall.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "regulation/measurements.h"
#include "test_support.h"

namespace pat {
namespace {

/// The grand with the back-rail felt made force-free, so that the fall starts from a clean rest
/// (in the action the key back presses the back rail a little).
ActionModel without_back_rail_force(ActionModel model) {
  const int back = model.contact_index("key–back rail");
  EXPECT_GE(back, 0);
  model.contacts[back].law = FeltLaw{};
  return model;
}

/// Released from the key angle of the whole grand at rest.
KeyFallOptions from_grand_rest() {
  KeyFallOptions options;
  const ActionModel grand = test::shipped("grand");
  options.start_angle_rad = find_rest_state(grand).q[grand.landmarks.key];
  return options;
}

/// Fall time and key-front speed of a rigid lever from rest through the rotation θc, against a
/// constant friction torque A:  ½ I_p θ̇² = m g (y_c(0) − y_c(θ)) − A θ, t = ∫ dθ / θ̇
/// (substituting θ = θc s² removes the 1/√θ of the start).
struct LeverFall {
  double time_s, front_speed_mps;
};
LeverFall lever_fall(const ActionModel& model, double start_angle, double fall_angle,
                     double friction_torque) {
  const Body& key = model.bodies[model.landmarks.key];
  const double inertia = key.inertia_com + key.mass * (key.com - key.pivot).squaredNorm();
  auto com_height = [&](double angle) {
    const Vec2 r = key.com - key.pivot;
    return key.pivot.y() + std::sin(angle) * r.x() + std::cos(angle) * r.y();
  };
  auto rate = [&](double theta) {
    const double work =
        key.mass * kGravity * (com_height(start_angle) - com_height(start_angle + theta)) -
        friction_torque * theta;
    return std::sqrt(std::max(2.0 * work / inertia, 0.0));
  };
  const int n = 20000;
  double time = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = (i + 0.5) / n;
    time += 2.0 * fall_angle * s / rate(fall_angle * s * s) / n;
  }
  const double arm = (model.landmarks.key_front - key.pivot).norm();
  return {time, rate(fall_angle) * arm};
}

TEST(KeyFall, FrictionlessFallIsThatOfARigidLever) {
  ActionModel grand = without_back_rail_force(test::shipped("grand"));
  grand.bodies[grand.landmarks.key].friction = JointFriction{};
  const KeyFallResult r = key_fall(grand, from_grand_rest());
  ASSERT_GT(r.fall_time_s, 0.0);
  const LeverFall exact = lever_fall(grand, r.start_angle_rad, r.fall_angle_rad, 0.0);
  // both measured at the same step end; the integrator's 1e-7 tolerance and the quadrature's
  // 2e4 points leave < 1e-4 relative
  EXPECT_NEAR(r.fall_time_s, exact.time_s, 1e-4 * exact.time_s);
  EXPECT_NEAR(r.impact_velocity_mps, exact.front_speed_mps, 1e-4 * exact.front_speed_mps);
}

TEST(KeyFall, BalancePinFrictionSlowsTheFallByItsCoulombTorque) {
  const ActionModel grand = without_back_rail_force(test::shipped("grand"));
  const KeyFallResult r = key_fall(grand, from_grand_rest());
  ASSERT_GT(r.fall_time_s, 0.0);
  const double a = grand.bodies[grand.landmarks.key].friction.a_nm;
  const LeverFall exact = lever_fall(grand, r.start_angle_rad, r.fall_angle_rad, a);
  const LeverFall free = lever_fall(grand, r.start_angle_rad, r.fall_angle_rad, 0.0);
  // eq. 4 equals A only once |ω| ≫ ωt (0.05 rad/s, reached in ~1 ms of a ~50 ms fall) and its
  // B1 hump adds < 1e-3 A beyond; 1 % covers both
  EXPECT_NEAR(r.fall_time_s, exact.time_s, 0.01 * exact.time_s);
  EXPECT_NEAR(r.impact_velocity_mps, exact.front_speed_mps, 0.01 * exact.front_speed_mps);
  EXPECT_GT(r.fall_time_s, free.time_s);
}

TEST(KeyFall, KeyLandsAndRestsOnThePunching) {
  const KeyFallResult r = key_fall(test::shipped("grand"));
  ASSERT_GT(r.fall_time_s, 0.0);
  // the key front travels the key dip (10 mm, F1) before it meets the punching: the fall's first
  // touch and the regulation's reading of the dip are the same travel, found two ways (the
  // reading presses the key onto the punching; they differ by about 1 µm)
  const double dip = measure_setting(test::shipped("grand"), "key_dip");
  EXPECT_NEAR(r.fall_distance_mm, dip, 0.01);
  // at the end it rests on the punching, pressed into the felt by its front weight (< 0.5 mm)
  EXPECT_NEAR(r.final_dip_mm, r.fall_distance_mm, 0.5);
  EXPECT_GE(r.final_dip_mm, r.fall_distance_mm);
  // a felt punching absorbs most of the blow: any rebound is small against the fall
  EXPECT_LT(r.first_rebound_mm, 0.5 * r.fall_distance_mm);
  ASSERT_FALSE(r.trace.rows.empty());
  EXPECT_EQ(r.trace.columns.front(), "time_s");
}

// a duration whose trace would fill the memory is refused before the fall (1e308 s had run 42 s
// into bad_alloc)
TEST(KeyFall, ARunawayDurationIsRefusedBeforeAnyWork) {
  KeyFallOptions options;
  options.duration_s = 1e308;
  const std::string message = test::error_of([&] { key_fall(test::shipped("grand"), options); });
  EXPECT_NE(message.find("5 million trace rows"), std::string::npos) << message;
}

TEST(KeyFall, NeedsAKeyBottomContact) {
  ActionModel grand = test::shipped("grand");
  grand.landmarks.key_bottom_contact = -1;
  EXPECT_THROW(key_fall(grand), InputError);
}

}  // namespace
}  // namespace pat

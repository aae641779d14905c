// Force laws against their formulas (paper eqs. 2-4) and contact geometry against closed forms.
#include "dynamics/force_laws.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/contact_geometry.h"

namespace pat {
namespace {

FeltLaw sample_law() {
  FeltLaw law;
  law.loading = {5e3, 2e3, 2e3};  // a = 5 N/mm, b = 2 /mm, c = 2 N/mm in SI
  law.unloading = {2e3, 2.2e3, 0.5e3};
  law.alpha = 50.0;  // s/m
  return law;
}

TEST(FeltLaw, LoadingCurveIsTheExponentialLaw) {
  const FeltLaw law = sample_law();
  for (double x : {1e-5, 1e-4, 5e-4, 1e-3}) {
    const double expected = 5e3 * x * std::exp(2e3 * x) + 2e3 * x;
    // same formula evaluated twice: only rounding differs
    EXPECT_NEAR(felt_normal_force(law, x, 0.0), expected, 1e-12 * expected);
    EXPECT_NEAR(felt_normal_force(law, x, 0.3), expected, 1e-12 * expected);
  }
}

TEST(FeltLaw, UnloadingBlendsTowardTheUnloadingCurveWithTanh) {
  const FeltLaw law = sample_law();
  const double x = 5e-4;
  const double fl = felt_curve_force(law.loading, x), fu = felt_curve_force(law.unloading, x);
  for (double rate : {-1e-3, -0.01, -0.05}) {
    const double expected = fl + (fl - fu) * std::tanh(law.alpha * rate);
    EXPECT_NEAR(felt_normal_force(law, x, rate), expected, 1e-12 * fl);
  }
  // fast unloading reaches F_U (tanh → −1); 1e-9 relative is tanh's distance from −1 at 50·10
  EXPECT_NEAR(felt_normal_force(law, x, -10.0), fu, 1e-9 * fl);
  EXPECT_EQ(felt_normal_force(law, 0.0, 1.0), 0.0);
  EXPECT_EQ(felt_normal_force(law, -1e-4, -1.0), 0.0);
}

TEST(FeltLaw, StiffnessIsTheDerivative) {
  const FeltCurve c{5e3, 2e3, 2e3};
  const double x = 7e-4, h = 1e-9;
  const double numeric = (felt_curve_force(c, x + h) - felt_curve_force(c, x - h)) / (2 * h);
  // central difference error O(h² F''') is far below 1e-6 relative here
  EXPECT_NEAR(felt_curve_stiffness(c, x), numeric, 1e-6 * numeric);
}

TEST(Friction, RegularizedCoulombSaturatesAtMuTimesNormalForce) {
  const ContactFriction f{0.65, 1e-3};
  EXPECT_NEAR(friction_force(f, 2.0, 0.5e-3), -0.65 * 2.0 * std::tanh(0.5), 1e-15);
  EXPECT_NEAR(friction_force(f, 2.0, -0.1), 0.65 * 2.0, 1e-12);  // tanh(100) = 1 to 1e-87
  EXPECT_NEAR(friction_force(f, 2.0, 0.1), -0.65 * 2.0, 1e-12);
  EXPECT_EQ(friction_force(f, 2.0, 0.0), 0.0);
  EXPECT_EQ(friction_force(ContactFriction{0.0, 1e-3}, 2.0, 1.0), 0.0);
}

TEST(JointFriction, MatchesPaperEquation4AndOpposesMotion) {
  const JointFriction law{1.01e-3, 0.3, 0.1, 0.05};
  for (double w : {-2.0, -0.01, 0.02, 0.05, 1.0, 10.0}) {
    const double s = w / 0.05;
    const double expected = -1.01e-3 * (std::tanh(s) + 0.3 * s / (1 + 0.1 * s * s * s * s));
    EXPECT_NEAR(joint_friction_torque(law, w), expected, 1e-15);
    EXPECT_LT(joint_friction_torque(law, w) * w, 0.0);
  }
  EXPECT_EQ(joint_friction_torque(law, 0.0), 0.0);
}

TEST(ContactGeometry, CircleAgainstLineInterior) {
  ContactPatch p;
  // circle radius 2 mm whose centre is 1.5 mm above a horizontal segment: 0.5 mm overlap
  ASSERT_TRUE(circle_segment_patch(Vec2(0.0, 1.5e-3), 2e-3, Vec2(-1e-2, 0), Vec2(1e-2, 0),
                                   Vec2(0, 1), 0.0, p));
  EXPECT_NEAR(p.penetration, 0.5e-3, 1e-15);
  EXPECT_NEAR(p.normal.y(), 1.0, 1e-15);
  EXPECT_NEAR(p.point.y(), -0.25e-3, 1e-15);  // middle of the overlap
  EXPECT_FALSE(circle_segment_patch(Vec2(0.0, 2.5e-3), 2e-3, Vec2(-1e-2, 0), Vec2(1e-2, 0),
                                    Vec2(0, 1), 0.0, p));
}

TEST(ContactGeometry, HybridCornerIsContinuousWithTheFace) {
  // at the segment end the rounded-corner (circle-circle) and face (circle-line) penetrations
  // must agree, and past the end the penetration falls off with the distance to the corner
  const Vec2 s0(0, 0), s1(1e-2, 0), n(0, 1);
  const double corner = 0.8e-3, r = 6e-3;
  ContactPatch inside, outside;
  ASSERT_TRUE(circle_segment_patch(Vec2(1e-2 - 1e-9, 5.9e-3), r, s0, s1, n, corner, inside));
  ASSERT_TRUE(circle_segment_patch(Vec2(1e-2 + 1e-9, 5.9e-3), r, s0, s1, n, corner, outside));
  EXPECT_NEAR(inside.penetration, outside.penetration, 1e-9);  // continuity up to the 1e-9 shift
  ContactPatch far;
  const Vec2 c(1e-2 + 3e-3, 4e-3);
  const Vec2 corner_centre(1e-2, -corner);
  const double expected = r + corner - (c - corner_centre).norm();
  ASSERT_TRUE(circle_segment_patch(c, r, s0, s1, n, corner, far));
  EXPECT_NEAR(far.penetration, expected, 1e-15);
}

TEST(ContactGeometry, CircleCircle) {
  ContactPatch p;
  ASSERT_TRUE(circle_circle_patch(Vec2(3e-3, 4e-3), 3e-3, Vec2(0, 0), 3e-3, p));
  EXPECT_NEAR(p.penetration, 1e-3, 1e-15);  // 3 + 3 − 5 mm
  EXPECT_NEAR(p.normal.x(), 0.6, 1e-15);
  EXPECT_FALSE(circle_circle_patch(Vec2(6e-3, 8e-3), 3e-3, Vec2(0, 0), 3e-3, p));
}

TEST(ForceLaws, SmoothTanhMatchesStdTanh) {
  // the one-exp tanh of the friction laws, across both branches and the saturation
  for (double x = -40.0; x <= 40.0; x += 0.00137) {
    EXPECT_NEAR(smooth_tanh(x), std::tanh(x), 1e-15 * std::max(std::abs(std::tanh(x)), 1e-3)) << x;
  }
  for (double x : {1e-300, 1e-12, 0.0624, 0.0625, 0.0626})
    EXPECT_NEAR(smooth_tanh(x), std::tanh(x), 1e-15 * std::tanh(x)) << x;
  EXPECT_EQ(smooth_tanh(0.0), 0.0);
  EXPECT_EQ(smooth_tanh(1e3), 1.0);
  EXPECT_EQ(smooth_tanh(-1e3), -1.0);
}

}  // namespace
}  // namespace pat

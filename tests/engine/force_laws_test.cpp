// Force laws against their formulas (paper eqs. 2-4) and contact geometry against closed forms.
#include "dynamics/force_laws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

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

// The closed-form rate derivatives that the velocity Jacobian uses (force_laws.h), against central
// differences of the forces, at arguments where the (1 − T²) and B2 s⁴ terms matter: α ẋ, v/v_s
// and ω/ωt from 0.3 to 3 (at the near-zero rates of a resting action they are ≈ 1 and ≈ 0, and a
// wrong factor there would go unnoticed).
double central_difference(const std::function<double(double)>& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2 * h);
}

TEST(ForceLawSlopes, FeltDampingIsTheRateDerivativeWhileUnloading) {
  const FeltLaw law{{5e3, 2e3, 2e3}, {2e3, 2.5e3, 1e3}, 300.0};
  const double x = 7e-4;
  for (double alpha_rate : {-0.3, -1.0, -3.0}) {
    const double rate = alpha_rate / law.alpha;  // m/s
    const double h = 1e-6 * std::abs(rate);
    const double numeric =
        central_difference([&](double r) { return felt_normal_force(law, x, r); }, rate, h);
    // relative error of the difference O(h²) ≈ 1e-12, rounding ≈ 1e-16 / 1e-6: 1e-8 covers both
    EXPECT_NEAR(felt_normal_damping(law, x, rate), numeric, 1e-8 * std::abs(numeric)) << alpha_rate;
    EXPECT_GT(std::abs(numeric), 0.0);
  }
  EXPECT_EQ(felt_normal_damping(law, x, 0.5), 0.0);  // loading: no rate dependence
}

TEST(ForceLawSlopes, FrictionSlopeIsTheDerivativeInNormalForceAndSlip) {
  const ContactFriction friction{0.4, 1e-3};
  const double fn = 3.0;
  for (double ratio : {0.3, 1.0, 3.0}) {
    const double slip = ratio * friction.slip_velocity;
    const FrictionSlope slope = friction_slope(friction, fn, slip);
    const double per_slip = central_difference(
        [&](double v) { return friction_force(friction, fn, v); }, slip, 1e-6 * slip);
    const double per_force = central_difference(
        [&](double f) { return friction_force(friction, f, slip); }, fn, 1e-6 * fn);
    EXPECT_NEAR(slope.per_slip_velocity, per_slip, 1e-8 * std::abs(per_slip)) << ratio;
    EXPECT_NEAR(slope.per_normal_force, per_force, 1e-8 * std::abs(per_force)) << ratio;
  }
}

TEST(ForceLawSlopes, JointFrictionDampingIsTheDerivativeOfEquation4) {
  const JointFriction law{1e-3, 0.3, 0.1, 0.05};
  for (double ratio : {0.3, 1.0, 1.5, 3.0}) {  // s = 1.5: the B1 hump's derivative changes sign
    const double omega = ratio * law.omega_t;
    const double numeric = central_difference(
        [&](double w) { return joint_friction_torque(law, w); }, omega, 1e-6 * omega);
    EXPECT_NEAR(joint_friction_damping(law, omega), numeric, 1e-8 * std::abs(numeric)) << ratio;
  }
}

}  // namespace
}  // namespace pat

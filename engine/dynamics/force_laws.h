// Force laws of the paper (section 4.2): the hysteretic felt law, regularized Coulomb friction
// and the joint friction torque. Pure functions, SI units. Inline: they run for every contact
// and joint at every right-hand-side evaluation.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/table_exp.h"
#include "model/action_model.h"

namespace pat {

/// tanh(x) from one exp (a fraction of std::tanh's cost), within 1e-15 relative: an odd Taylor
/// series below |x| = 1/16, (1 − e^(−2|x|)) / (1 + e^(−2|x|)) with the sign of x above, and ±1
/// without the exp from |x| = 19 on (e^(−38) < 2^−54: 1 ± e rounds to 1, the same result).
inline double smooth_tanh(double x) {
  const double magnitude = std::abs(x);
  double y;
  if (magnitude < 0.0625) {
    // Taylor series to x¹³; the first omitted term, 929569/638512875 x¹⁵, is below 1e-19 x here
    const double x2 = x * x;
    y = magnitude *
        (1.0 + x2 * (-1.0 / 3.0 +
                     x2 * (2.0 / 15.0 +
                           x2 * (-17.0 / 315.0 +
                                 x2 * (62.0 / 2835.0 +
                                       x2 * (-1382.0 / 155925.0 + x2 * (21844.0 / 6081075.0)))))));
  } else if (magnitude < 19.0) {
    const double e = table_exp(-2.0 * magnitude);
    y = (1.0 - e) / (1.0 + e);
  } else {
    y = 1.0;
  }
  return std::copysign(y, x);
}

/// F(x) = a x e^(b x) + c x  (paper eq. 2); x = penetration (m) ≥ 0, F in N. The exponential
/// within about one unit in the last place (core/table_exp.h), for speed.
inline double felt_curve_force(const FeltCurve& curve, double x) {
  return curve.a * x * table_exp(curve.b * x) + curve.c * x;
}
/// dF/dx of the curve above, N/m.
inline double felt_curve_stiffness(const FeltCurve& curve, double x) {
  return curve.a * table_exp(curve.b * x) * (1.0 + curve.b * x) + curve.c;
}

/// Normal force of a hysteretic felt contact (paper eq. 3), N, never negative:
///   F_L(x) for ẋ ≥ 0, F_L(x) + (F_L(x) − F_U(x)) tanh(α ẋ) for ẋ < 0.
/// x: penetration (m), x_rate: ẋ (m/s). Returns 0 for x ≤ 0.
inline double felt_normal_force(const FeltLaw& law, double x, double x_rate) {
  if (x <= 0.0) return 0.0;
  const double loading = felt_curve_force(law.loading, x);
  if (x_rate >= 0.0) return std::max(loading, 0.0);
  const double unloading = felt_curve_force(law.unloading, x);
  // tanh(α ẋ) < 0 while unloading: the force moves from F_L toward F_U
  return std::max(loading + (loading - unloading) * smooth_tanh(law.alpha * x_rate), 0.0);
}

/// The felt normal force's rate derivative ∂F/∂ẋ (N·s/m), for the velocity Jacobian:
///   (F_L − F_U) α (1 − T²) with T = tanh(α ẋ) for ẋ < 0; 0 for ẋ ≥ 0 and where F is clamped
///   to 0 (x ≤ 0 or F ≤ 0).
inline double felt_normal_damping(const FeltLaw& law, double x, double x_rate) {
  if (x <= 0.0 || x_rate >= 0.0) return 0.0;
  const double loading = felt_curve_force(law.loading, x);
  const double unloading = felt_curve_force(law.unloading, x);
  const double blend = smooth_tanh(law.alpha * x_rate);
  if (!(loading + (loading - unloading) * blend > 0.0)) return 0.0;
  return (loading - unloading) * law.alpha * (1.0 - blend * blend);
}

/// Tangential friction force along the slip direction (N): −μ F_n tanh(v_t / v_s).
inline double friction_force(const ContactFriction& friction, double normal_force,
                             double slip_velocity) {
  if (friction.mu <= 0.0) return 0.0;
  return -friction.mu * normal_force * smooth_tanh(slip_velocity / friction.slip_velocity);
}

/// Partial derivatives of friction_force: ∂F_t/∂F_n = −μ T (dimensionless) and
/// ∂F_t/∂v_t = −μ F_n (1 − T²)/v_s (N·s/m), T = tanh(v_t / v_s).
struct FrictionSlope {
  double per_normal_force = 0.0;
  double per_slip_velocity = 0.0;
};
inline FrictionSlope friction_slope(const ContactFriction& friction, double normal_force,
                                    double slip_velocity) {
  if (friction.mu <= 0.0) return {};
  const double blend = smooth_tanh(slip_velocity / friction.slip_velocity);
  return {-friction.mu * blend,
          -friction.mu * normal_force * (1.0 - blend * blend) / friction.slip_velocity};
}

/// Joint friction torque (paper eq. 4), N·m, opposing ω:
///   −A (tanh(ω/ωt) + B1 (ω/ωt) / (1 + B2 (ω/ωt)^4)).
inline double joint_friction_torque(const JointFriction& law, double omega) {
  if (law.a_nm <= 0.0) return 0.0;
  const double s = omega / law.omega_t;
  const double s2 = s * s;
  return -law.a_nm * (smooth_tanh(s) + law.b1 * s / (1.0 + law.b2 * s2 * s2));
}

/// Its derivative dτ/dω (N·m·s/rad), s = ω/ωt, T = tanh(s):
///   −(A/ωt) ((1 − T²) + B1 (1 − 3 B2 s⁴) / (1 + B2 s⁴)²).
inline double joint_friction_damping(const JointFriction& law, double omega) {
  if (law.a_nm <= 0.0) return 0.0;
  const double s = omega / law.omega_t;
  const double s4 = s * s * s * s;
  const double blend = smooth_tanh(s);
  const double denominator = 1.0 + law.b2 * s4;
  return -law.a_nm / law.omega_t *
         ((1.0 - blend * blend) + law.b1 * (1.0 - 3.0 * law.b2 * s4) / (denominator * denominator));
}

}  // namespace pat

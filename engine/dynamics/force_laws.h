// Force laws of the paper (section 4.2): the hysteretic felt law, regularized Coulomb friction
// and the joint friction torque. Pure functions, SI units.
#pragma once

#include "model/action_model.h"

namespace pat {

/// tanh(x) from one exp (a fraction of std::tanh's cost), within 1e-15 relative: an odd Taylor
/// series below |x| = 1/16, (1 − e^(−2|x|)) / (1 + e^(−2|x|)) with the sign of x above.
double smooth_tanh(double x);

/// F(x) = a x e^(b x) + c x  (paper eq. 2); x = penetration (m) ≥ 0, F in N.
double felt_curve_force(const FeltCurve& curve, double x);
/// dF/dx of the curve above, N/m.
double felt_curve_stiffness(const FeltCurve& curve, double x);

/// Normal force of a hysteretic felt contact (paper eq. 3), N, never negative:
///   F_L(x) for ẋ ≥ 0, F_L(x) + (F_L(x) − F_U(x)) tanh(α ẋ) for ẋ < 0.
/// x: penetration (m), x_rate: ẋ (m/s). Returns 0 for x ≤ 0.
double felt_normal_force(const FeltLaw& law, double x, double x_rate);

/// Tangential friction force along the slip direction (N): −μ F_n tanh(v_t / v_s).
double friction_force(const ContactFriction& friction, double normal_force, double slip_velocity);

/// Joint friction torque (paper eq. 4), N·m, opposing ω:
///   −A (tanh(ω/ωt) + B1 (ω/ωt) / (1 + B2 (ω/ωt)^4)).
double joint_friction_torque(const JointFriction& law, double omega);

}  // namespace pat

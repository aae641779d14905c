#include "dynamics/force_laws.h"

#include <algorithm>
#include <cmath>

namespace pat {

double smooth_tanh(double x) {
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
  } else {
    const double e = std::exp(-2.0 * magnitude);  // underflows to 0 for large |x|: tanh = 1
    y = (1.0 - e) / (1.0 + e);
  }
  return std::copysign(y, x);
}

double felt_curve_force(const FeltCurve& curve, double x) {
  return curve.a * x * std::exp(curve.b * x) + curve.c * x;
}

double felt_curve_stiffness(const FeltCurve& curve, double x) {
  return curve.a * std::exp(curve.b * x) * (1.0 + curve.b * x) + curve.c;
}

double felt_normal_force(const FeltLaw& law, double x, double x_rate) {
  if (x <= 0.0) return 0.0;
  const double loading = felt_curve_force(law.loading, x);
  if (x_rate >= 0.0) return std::max(loading, 0.0);
  const double unloading = felt_curve_force(law.unloading, x);
  // tanh(α ẋ) < 0 while unloading: the force moves from F_L toward F_U
  return std::max(loading + (loading - unloading) * smooth_tanh(law.alpha * x_rate), 0.0);
}

double friction_force(const ContactFriction& friction, double normal_force, double slip_velocity) {
  if (friction.mu <= 0.0) return 0.0;
  return -friction.mu * normal_force * smooth_tanh(slip_velocity / friction.slip_velocity);
}

double joint_friction_torque(const JointFriction& law, double omega) {
  if (law.a_nm <= 0.0) return 0.0;
  const double s = omega / law.omega_t;
  const double s2 = s * s;
  return -law.a_nm * (smooth_tanh(s) + law.b1 * s / (1.0 + law.b2 * s2 * s2));
}

}  // namespace pat

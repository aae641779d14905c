// The velocity block of the Jacobian of the equations of motion (action_dynamics.h):
//
//   A_v = M_ff⁻¹ K_v,   K_v = ∂Q/∂q̇ = diag(dτ_j/dω_j − d_settle)
//        + Σ_contacts [ −D j_nᵀ j_n − (∂F_t/∂F_n) D j_tᵀ j_n + (∂F_t/∂v_t) j_tᵀ j_t ]
//        + Σ_taut straps [ −c j_sᵀ j_s ]
//
// with G = ∂(v_A(P) − v_B(P))/∂q̇ at the patch centre P, j_n = n·G (ẋ = −j_n q̇), j_t = t·G (the
// slip), D = ∂F_n/∂ẋ of the felt law, j_s = ∂L̇/∂q̇ of a strap and c its damping.
#include <cmath>

#include "dynamics/action_dynamics.h"
#include "dynamics/force_laws.h"

namespace pat {

void ActionDynamics::add_relative_velocity_rows(int body_a, int body_b, const Vec2& point,
                                                SmallVector& gx, SmallVector& gy) const {
  // ∂v(P)/∂q̇_j = ẑ × (P − o_j) for every joint j on the body's chain
  for (int side = 0; side < 2; ++side) {
    const int body = side == 0 ? body_a : body_b;
    if (body < 0) continue;
    const double sign = side == 0 ? 1.0 : -1.0;
    const BodyConstants& b = bodies_[body];
    for (int c = 0; c < b.chain_length; ++c) {
      const int j = b.chain[c];
      const Vec2 lever = perp(point - kin_[j].origin);
      gx[j] += sign * lever.x();
      gy[j] += sign * lever.y();
    }
  }
}

namespace {

/// K −= s · a bᵀ on the rows and columns `joints` (a and b given there, count entries).
void subtract_outer(SmallMatrix& k, double s, const double* a, const double* b, const int* joints,
                    int count) {
  if (s == 0.0) return;
  for (int i = 0; i < count; ++i) {
    if (a[i] == 0.0) continue;
    const double sa = s * a[i];
    for (int j = 0; j < count; ++j) k(joints[i], joints[j]) -= sa * b[j];
  }
}

/// K −= s · a bᵀ over the leading n×n block.
void subtract_outer(SmallMatrix& k, double s, const SmallVector& a, const SmallVector& b, int n) {
  if (s == 0.0) return;
  for (int i = 0; i < n; ++i) {
    if (a[i] == 0.0) continue;
    const double sa = s * a[i];
    for (int j = 0; j < n; ++j) k(i, j) -= sa * b[j];
  }
}

}  // namespace

bool ActionDynamics::velocity_jacobian(StateMatrix& jacobian) {
  if (!factor_valid_) return false;
  const DofVector& v = scratch_v_;  // the rates of the latest rhs()
  SmallMatrix k_v = SmallMatrix::Zero();
  for (int i = 0; i < n_; ++i)
    k_v(i, i) = joint_friction_damping(bodies_[i].friction, v[i]) - settling_damping_;

  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    if (!touching_[c]) continue;
    const ContactConstants& contact = contacts_[c];
    const ContactPatch& patch = patches_[c];
    // j_n and j_t on the contact's joints only (elsewhere G is zero: a joint on neither chain,
    // or on both, where the two chains' terms cancel exactly); the same sums in the same order
    // as over every joint
    const Vec2 tangent = perp(patch.normal);
    const int count = contact.joint_count;
    double j_n[kMaxDof], j_t[kMaxDof];
    double rate = 0.0, slip = 0.0;
    for (int k = 0; k < count; ++k) {
      const int j = contact.joints[k];
      // ∂(v_A(P) − v_B(P))/∂q̇_j = ± ẑ × (P − o_j)
      const Vec2 lever = perp(patch.point - kin_[j].origin);
      const double gx = contact.joint_sign[k] * lever.x(), gy = contact.joint_sign[k] * lever.y();
      j_n[k] = patch.normal.x() * gx + patch.normal.y() * gy;
      j_t[k] = tangent.x() * gx + tangent.y() * gy;
      rate -= j_n[k] * v[j];
      slip += j_t[k] * v[j];
    }
    const Contact& law = model_.contacts[c];
    const double damping = felt_normal_damping(law.law, patch.penetration, rate);
    subtract_outer(k_v, damping, j_n, j_n, contact.joints, count);
    if (law.friction.mu > 0.0) {
      const double normal_force = felt_normal_force(law.law, patch.penetration, rate);
      const FrictionSlope slope = friction_slope(law.friction, normal_force, slip);
      subtract_outer(k_v, slope.per_normal_force * damping, j_t, j_n, contact.joints, count);
      subtract_outer(k_v, -slope.per_slip_velocity, j_t, j_t, contact.joints, count);
    }
  }

  for (std::size_t s = 0; s < model_.straps.size(); ++s) {
    const Strap& strap = model_.straps[s];
    if (strap.damping == 0.0) continue;
    const Vec2 pa = transform(strap.body_a, strap.point_a);
    const Vec2 pb = transform(strap.body_b, strap.point_b);
    const Vec2 d = pb - pa;
    const double length = d.norm();
    if (!(length > strap_rest_length_[s] && length > 1e-12)) continue;
    const Vec2 dir = d / length;
    // L̇ = dir·(v_B(P_b) − v_A(P_a)) = j_s q̇ (the two ends are different points)
    SmallVector bx = SmallVector::Zero(), by = SmallVector::Zero();
    SmallVector ax = SmallVector::Zero(), ay = SmallVector::Zero();
    add_relative_velocity_rows(strap.body_b, -1, pb, bx, by);
    add_relative_velocity_rows(strap.body_a, -1, pa, ax, ay);
    const SmallVector j_s = dir.x() * (bx - ax) + dir.y() * (by - ay);
    double rate = 0.0;
    for (int j = 0; j < n_; ++j) rate += j_s[j] * v[j];
    if (strap.stiffness * (length - strap_rest_length_[s]) + strap.damping * rate <= 0.0) continue;
    subtract_outer(k_v, strap.damping, j_s, j_s, n_);
  }

  // A_v = M_ff⁻¹ K_v,ff with the factor of the latest rhs(), all columns in one pass
  const int m = free_count_;
  const int* const free_index = free_index_.data();
  SmallMatrix x;
  for (int column = 0; column < m; ++column)
    for (int i = 0; i < m; ++i) x(i, column) = k_v(free_index[i], free_index[column]);
  tree_.solve_columns(factor_, x, m);
  for (int column = 0; column < m; ++column)
    for (int i = 0; i < m; ++i) jacobian(m + i, m + column) = x(i, column);
  return true;
}

}  // namespace pat

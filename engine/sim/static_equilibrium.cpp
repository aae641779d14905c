#include "sim/static_equilibrium.h"

#include <Eigen/LU>
#include <cmath>

#include "dynamics/action_dynamics.h"

namespace pat {
namespace {

/// Joint accelerations at rest (v = 0) at q: the residual of the equilibrium.
DofVector residual(ActionDynamics& dynamics, const DofVector& q, DynamicsReading& reading) {
  dynamics.evaluate(0.0, q, DofVector::Zero(q.size()), reading);
  return reading.acceleration;
}

}  // namespace

bool damped_newton(const std::function<DofVector(const DofVector&)>& residual, DofVector& q,
                   int held, int max_iterations, double step_tolerance) {
  const int n = static_cast<int>(q.size());
  DofVector r = residual(q);
  // finite-difference step: 1e-7 rad moves a 0.2 m arm by 0.02 µm, far below felt
  // deformations (~0.1 mm) yet above rounding
  const double h = 1e-7;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    DofMatrix jacobian = DofMatrix::Identity(n, n);  // a held joint's row and column stay so
    for (int j = 0; j < n; ++j) {
      if (j == held) continue;
      DofVector qj = q;
      qj[j] += h;
      jacobian.col(j) = (residual(qj) - r) / h;
      if (held >= 0) jacobian(held, j) = 0.0;
    }
    DofVector step = -Eigen::PartialPivLU<DofMatrix>(jacobian).solve(r);
    if (held >= 0) step[held] = 0.0;
    if (!step.allFinite()) return false;
    // a Newton step larger than 0.02 rad leaves the region where the felt laws are smooth
    const double largest = step.cwiseAbs().maxCoeff();
    if (largest > 0.02) step *= 0.02 / largest;
    // halve the step until the residual decreases
    double scale = 1.0;
    DofVector q_next, r_next;
    for (int halving = 0; halving < 30; ++halving) {
      q_next = q + scale * step;
      r_next = residual(q_next);
      if (r_next.norm() < r.norm() || r_next.norm() < 1e-9) break;
      scale *= 0.5;
    }
    q = q_next;
    r = r_next;
    if (scale * largest < step_tolerance) return r.norm() < 1e-3;
  }
  return false;
}

bool solve_static_equilibrium(const ActionModel& model, const DofVector& guess, DofVector& q) {
  ActionDynamics dynamics(model, nullptr);
  DynamicsReading reading;
  q = guess;
  return damped_newton([&](const DofVector& x) { return residual(dynamics, x, reading); }, q, -1,
                       40, 1e-10);
}

RestState rest_state_near(const ActionModel& model, const RestState& near) {
  DofVector q;
  if (near.q.size() == model.dofs() && solve_static_equilibrium(model, near.q, q)) {
    // accept only a stable equilibrium: settle briefly from it would not move; checked by the
    // Jacobian of the accelerations having no positive real eigenvalue is costly, so instead
    // demand that every joint stays within 0.05 rad of the guess (a continuation step)
    if ((q - near.q).cwiseAbs().maxCoeff() < 0.05) {
      ActionDynamics dynamics(model, nullptr);
      RestState rest;
      rest.q = q;
      rest.hammer_string_gap = dynamics.hammer_string_gap(q);
      return rest;
    }
  }
  return find_rest_state(model);
}

}  // namespace pat

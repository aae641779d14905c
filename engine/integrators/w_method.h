// Fixed-step two-stage Rosenbrock-W method ROS2 (Verwer, Spee, Blom, Hundsdorfer 1999), the
// γ = 1 − 1/√2 root (L-stable, order 2 for ANY Jacobian approximation J):
//
//   W  = I − γ h J
//   K1 = W⁻¹ f(t, y)
//   K2 = W⁻¹ [ f(t + h, y + h K1) − 2 K1 ]
//   y⁺ = y + (3/2) h K1 + (1/2) h K2
//
// f_t is dropped by default (a W-method may use a zero t column in J: order 2 is kept). On a stiff
// component driven by a time-dependent input (y' = λ(y − g(t)) + g'(t), |hλ| ≫ 1) that leaves an
// O(h) lag, about 0.6 h·g'; set_time_derivative(true) adds the f_t terms (one more f per step):
//   K1 = W⁻¹ [f(t, y) + γh f_t],   K2 = W⁻¹ [f(t + h, y + h K1) − 2 K1 − γh f_t].
// J is frozen: it is re-evaluated on the first step, every `jacobian_refresh_steps` accepted steps
// and whenever the system's regime() (seen after f(t, y)) differs from the one at the last
// Jacobian evaluation. In between, every `velocity_jacobian_steps` steps, the velocity block
// ∂v'/∂v alone is replaced by the system's closed form at (t, y) where it offers one
// (OdeSystem::velocity_jacobian; a mechanical system's damping and friction, which the contacts
// switch on and off with the rates' signs), and W is refactored.
//
// For a second-order system y = (q, v), q' = v (n = dofs() > 0), J = [[0, I], [A_q, A_v]] and
// W x = r is solved through the n×n Schur complement
//   S   = I − hγ A_v − (hγ)² A_q
//   x_v = S⁻¹ (r_v + hγ A_q r_q),   x_q = r_q + hγ x_v.
// Otherwise (dofs() == 0, or extra states so that dim ≠ 2n) the full dim×dim W is factored.
// Units follow the system (SI: s, rad, rad/s).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "core/types.h"
#include "integrators/integrator_factory.h"
#include "integrators/ode_system.h"
#include "integrators/small_lu.h"

namespace pat {

/// Forward-difference Jacobian J = ∂f/∂y at (t, y), given f0 = f(t, y):
///   J(:, j) = (f(t, y + Δ_j e_j) − f0) / Δ_j,   Δ_j = √ε · max(|y_j|, s_j),
/// typical scale s_j = 1e-1 for the velocities v (rad/s, j in [n, 2n) when n = dofs() > 0) and
/// s_j = 1e-3 for everything else (positions in rad, general first-order states). Calls system.rhs
/// dimension() times, the velocity columns first (the positions stay those of y, which a system
/// may have memoized from f0); y_work and f_work are scratch vectors of length dimension(). No heap
/// allocation.
void forward_difference_jacobian(OdeSystem& system, double t, const StateVector& y,
                                 const StateVector& f0, StateVector& y_work, StateVector& f_work,
                                 StateMatrix& jacobian);

class WMethod2 final : public Integrator {
 public:
  /// Fills jacobian (dim×dim, already sized) with an approximation of ∂f/∂y at (t, y).
  using JacobianFunction =
      std::function<void(double t, const StateVector& y, StateMatrix& jacobian)>;

  /// γ = 1 − 1/√2.
  static constexpr double kGamma = 0.29289321881345247559915563789515;

  /// Throws InputError if options.fixed_step_s <= 0 or options.jacobian_refresh_steps < 1.
  explicit WMethod2(const IntegratorOptions& options);

  /// Replaces the finite-difference Jacobian (e.g. a deliberately wrong one in tests, or an
  /// analytic one). Called at the same refresh points; the system's velocity block is then not
  /// used. For dofs() > 0 only the lower rows (A_q, A_v) are used: the upper rows are [0 I] by
  /// construction. Pass {} to restore the finite differences.
  void set_jacobian_override(JacobianFunction jacobian);

  /// Includes the γh·f_t terms, f_t = ∂f/∂t by a forward difference in t at every step
  /// (increment √ε · max(|t|, 1e-3 s)). Off by default.
  void set_time_derivative(bool enabled) { use_time_derivative_ = enabled; }

  void initialize(OdeSystem& system, double t0, const StateVector& y0) override;
  /// One step of h = fixed_step_s, shortened to land exactly on t_max; if less than 1e-12 s
  /// remains, time() moves to t_max without a step.
  StepStatus step(double t_max) override;
  double time() const override { return t_; }
  const StateVector& state() const override { return y_; }
  const IntegratorStats& stats() const override { return stats_; }
  const std::string& failure_reason() const override { return failure_reason_; }
  const char* name() const override { return "w2"; }

 private:
  void evaluate_jacobian(std::uint64_t regime);
  void factor(double h);
  /// x = W⁻¹ r with the current factorization.
  void solve(const StateVector& r, StateVector& x);
  StepStatus fail(const std::string& reason);

  IntegratorOptions options_;
  JacobianFunction jacobian_override_;
  bool use_time_derivative_ = false;
  OdeSystem* system_ = nullptr;
  int dim_ = 0;
  int dofs_ = 0;
  bool use_schur_ = false;  ///< dofs_ > 0 and dim_ == 2 dofs_

  double t_ = 0.0;
  StateVector y_;
  IntegratorStats stats_;
  std::string failure_reason_;

  // Frozen Jacobian and the factorization of W (or of the Schur complement S).
  StateMatrix jacobian_;
  bool have_jacobian_ = false;
  std::uint64_t jacobian_regime_ = 0;
  long steps_since_jacobian_ = 0;
  bool factored_ = false;
  double factored_h_ = 0.0;
  Eigen::PartialPivLU<StateMatrix> lu_full_;
  SmallLu lu_schur_;
  SmallLu::Matrix hg_a_q_;  ///< hγ A_q of the factored W, for the Schur right-hand side

  // Scratch (sized in initialize(), no heap: fixed maximum size).
  StateVector f0_, f1_, f_t_, k1_, k2_, y_stage_, r_, y_work_, f_work_;
  SmallLu::Vector schur_rhs_;
};

}  // namespace pat

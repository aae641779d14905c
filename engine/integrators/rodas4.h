// RODAS4 (Hairer & Wanner, METH = 1): 6-stage, order-4 stiffly accurate Rosenbrock method with
// an embedded order-3 estimate, adaptive step. Offline accuracy reference (speed not a goal).
//
// Transformed form, γ = 0.25, stages i = 1..6:
//   (1/(hγ) I − J) u_i = f(t + c_i h, y + Σ_{j<i} a_ij u_j) + Σ_{j<i} (C_ij / h) u_j + h d_i f_t
//   y⁺ = y + Σ_{j≤5} a_6j u_j + u_6      (a_6j = a_5j for j ≤ 4, a_65 = 1)
//   err = u_6
// J = ∂f/∂y (forward differences, every step) and f_t = ∂f/∂t (forward difference in t).
//
// Error norm: RMS_i of u6_i / (atol + rtol · max(|y_i|, |y⁺_i|)); accept if ≤ 1.
// Next step: h · clamp(0.9 · err^(−1/4), 0.2, 6) (no growth right after a rejection), at most
// max_step_s, never past t_max. First step 1e-6 s. Failure when h < 1e-14 s.
#pragma once

#include <string>

#include "core/types.h"
#include "integrators/integrator_factory.h"
#include "integrators/ode_system.h"

namespace pat {

class Rodas4 final : public Integrator {
 public:
  /// Throws InputError unless the tolerances and max_step_s are positive.
  explicit Rodas4(const IntegratorOptions& options);

  void initialize(OdeSystem& system, double t0, const StateVector& y0) override;
  /// Takes one accepted step (after any number of rejected attempts) that ends at or before
  /// t_max; if less than 1e-12 s remains, time() moves to t_max without a step.
  StepStatus step(double t_max) override;
  double time() const override { return t_; }
  const StateVector& state() const override { return y_; }
  const IntegratorStats& stats() const override { return stats_; }
  const std::string& failure_reason() const override { return failure_reason_; }
  const char* name() const override { return "rodas"; }

  /// Step size the controller proposes for the next step (s).
  double next_step() const { return h_; }

 private:
  static constexpr int kStages = 6;

  StepStatus fail(const std::string& reason);

  IntegratorOptions options_;
  OdeSystem* system_ = nullptr;
  int dim_ = 0;
  double t_ = 0.0;
  double h_ = 0.0;
  StateVector y_;
  IntegratorStats stats_;
  std::string failure_reason_;

  StateMatrix jacobian_;
  Eigen::PartialPivLU<StateMatrix> lu_;
  StateVector f0_, f_t_, u_[kStages], y_stage_, f_stage_, rhs_, y_new_, y_work_, f_work_;
};

}  // namespace pat

// SUNDIALS CVODE (6.x) as an adaptive reference: variable-order BDF (orders 1–5), Newton
// iteration with a dense direct linear solver and CVODE's difference-quotient Jacobian.
//
// Local error control: ‖e‖_WRMS ≤ 1 with weights 1 / (rtol · |y_i| + atol).
// One step() call = one internal CVODE step (CV_ONE_STEP) with the stop time t_max, so steps
// never pass t_max. Largest step options.max_step_s, smallest 1e-14 s; at most 1e7 internal
// steps. A non-finite f is reported to CVODE as recoverable (it retries with a smaller step).
// SUNDIALS stays out of this header: its objects live in a private Impl, freed by the destructor.
#pragma once

#include <memory>
#include <string>

#include "core/types.h"
#include "integrators/integrator_factory.h"
#include "integrators/ode_system.h"

namespace pat {

class CvodeIntegrator final : public Integrator {
 public:
  /// Throws InputError unless the tolerances and max_step_s are positive.
  explicit CvodeIntegrator(const IntegratorOptions& options);
  ~CvodeIntegrator() override;
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// (Re)creates the CVODE solver for this system. Exceptions thrown by system.rhs() inside
  /// CVODE are rethrown by step().
  void initialize(OdeSystem& system, double t0, const StateVector& y0) override;
  /// One internal CVODE step ending at or before t_max (exactly t_max when the stop time is
  /// reached); if less than 1e-12 s remains, time() moves to t_max without a step.
  StepStatus step(double t_max) override;
  double time() const override { return t_; }
  const StateVector& state() const override { return y_; }
  const IntegratorStats& stats() const override { return stats_; }
  const std::string& failure_reason() const override { return failure_reason_; }
  const char* name() const override { return "cvode"; }

 private:
  struct Impl;

  StepStatus fail(const std::string& reason);
  void update_stats();

  IntegratorOptions options_;
  std::unique_ptr<Impl> impl_;
  double t_ = 0.0;
  StateVector y_;
  IntegratorStats stats_;
  std::string failure_reason_;
};

}  // namespace pat

#include "integrators/rodas4.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "integrators/w_method.h"  // forward_difference_jacobian

namespace pat {

namespace {

constexpr double kMinStep = 1e-12;    // less left before t_max: just move time there (s)
constexpr double kUnderflow = 1e-14;  // smallest step attempted (s)
constexpr double kInitialStep = 1e-6;

// Hairer's RODAS4 (METH = 1) in transformed form; row i holds the stage-i coefficients.
constexpr double kGamma = 0.25;
constexpr double kA[6][5] = {
    {},
    {1.544},
    {0.9466785280815826, 0.2557011698983284},
    {3.314825187068521, 2.896124015972201, 0.9986419139977817},
    {1.221224509226641, 6.019134481288629, 12.53708332932087, -0.6878860361058950},
    {1.221224509226641, 6.019134481288629, 12.53708332932087, -0.6878860361058950, 1.0},
};
constexpr double kC[6][5] = {
    {},
    {-5.6688},
    {-2.430093356833875, -0.2063599157091915},
    {-0.1073529058151375, -9.594562251023355, -20.47028614809616},
    {7.496443313967647, -10.24680431464352, -33.99990352819905, 11.70890893206160},
    {8.083246795921522, -7.981132988064893, -31.52159432874371, 16.31930543123136,
     -6.058818238834054},
};
constexpr double kNodes[6] = {0.0, 0.386, 0.21, 0.63, 1.0, 1.0};
constexpr double kD[6] = {0.25, -0.1043, 0.1035, -0.0362, 0.0, 0.0};

std::string format_time(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g s", t);
  return buffer;
}

}  // namespace

Rodas4::Rodas4(const IntegratorOptions& options) : options_(options) {
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0)) {
    throw InputError("rodas: tolerances must be positive");
  }
  if (!(options.max_step_s > 0.0)) throw InputError("rodas: maximum step must be positive");
}

void Rodas4::initialize(OdeSystem& system, double t0, const StateVector& y0) {
  const int dim = system.dimension();
  if (dim < 1 || dim > kMaxState || y0.size() != dim) {
    throw std::invalid_argument("rodas: bad system size (dimension " + std::to_string(dim) +
                                ", y0 length " + std::to_string(y0.size()) + ")");
  }
  system_ = &system;
  dim_ = dim;
  t_ = t0;
  h_ = std::min(kInitialStep, options_.max_step_s);
  y_ = y0;
  stats_ = IntegratorStats{};
  failure_reason_.clear();
  jacobian_.setZero(dim, dim);
  for (StateVector& u : u_) u.setZero(dim);
  for (StateVector* v : {&f0_, &f_t_, &y_stage_, &f_stage_, &rhs_, &y_new_, &y_work_, &f_work_}) {
    v->setZero(dim);
  }
}

StepStatus Rodas4::fail(const std::string& reason) {
  failure_reason_ = reason;
  return StepStatus::Failure;
}

StepStatus Rodas4::step(double t_max) {
  if (system_ == nullptr) return fail("rodas: step() called before initialize()");
  const double remaining = t_max - t_;
  if (remaining < kMinStep) {
    if (remaining <= -kMinStep) {
      return fail("rodas: t_max = " + format_time(t_max) + " is before the current time " +
                  format_time(t_));
    }
    t_ = std::max(t_, t_max);
    return StepStatus::Ok;
  }

  // f, J and f_t at (t, y): once per step, kept through rejected attempts.
  system_->rhs(t_, y_, f0_);
  ++stats_.rhs_evaluations;
  if (!f0_.allFinite()) return fail("rodas: non-finite derivative at t = " + format_time(t_));
  forward_difference_jacobian(*system_, t_, y_, f0_, y_work_, f_work_, jacobian_);
  stats_.rhs_evaluations += dim_;
  ++stats_.jacobian_updates;
  {
    const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
    const double t_plus = t_ + sqrt_eps * std::max(std::abs(t_), 1e-3);
    system_->rhs(t_plus, y_, f_work_);
    ++stats_.rhs_evaluations;
    f_t_ = (f_work_ - f0_) / (t_plus - t_);
  }

  bool rejected = false;
  for (;;) {
    double h = std::min(h_, options_.max_step_s);
    const bool last = h >= remaining - kMinStep;
    if (last) h = remaining;
    if (h < kUnderflow) return fail("step size underflow at t = " + format_time(t_));

    lu_.compute(StateMatrix::Identity(dim_, dim_) / (h * kGamma) - jacobian_);
    ++stats_.factorizations;
    for (int i = 0; i < kStages; ++i) {
      if (i == 0) {
        rhs_ = f0_;
      } else {
        y_stage_ = y_;
        for (int j = 0; j < i; ++j) y_stage_ += kA[i][j] * u_[j];
        system_->rhs(t_ + kNodes[i] * h, y_stage_, f_stage_);
        ++stats_.rhs_evaluations;
        rhs_ = f_stage_;
        for (int j = 0; j < i; ++j) rhs_ += (kC[i][j] / h) * u_[j];
      }
      if (kD[i] != 0.0) rhs_ += (h * kD[i]) * f_t_;
      u_[i] = lu_.solve(rhs_);
    }
    y_new_ = y_stage_ + u_[kStages - 1];

    double err = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const double scale =
          options_.absolute_tolerance +
          options_.relative_tolerance * std::max(std::abs(y_[i]), std::abs(y_new_[i]));
      const double e = u_[kStages - 1][i] / scale;
      err += e * e;
    }
    err = std::sqrt(err / dim_);
    if (!std::isfinite(err) || !y_new_.allFinite()) err = std::numeric_limits<double>::infinity();

    double factor = std::clamp(0.9 * std::pow(err, -0.25), 0.2, 6.0);
    if (err <= 1.0) {
      if (rejected) factor = std::min(factor, 1.0);
      // A step cut short by t_max says little about the step size: keep the earlier proposal.
      h_ = last ? std::max(h * factor, h_) : h * factor;
      y_ = y_new_;
      t_ = last ? t_max : t_ + h;
      ++stats_.steps;
      return StepStatus::Ok;
    }
    ++stats_.rejected_steps;
    rejected = true;
    h_ = h * factor;
  }
}

}  // namespace pat

#include "integrators/w_method.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/error.h"

namespace pat {

namespace {

// Less than this much time left before t_max: move time there without a step (s).
constexpr double kMinStep = 1e-12;
const double kSqrtEps = std::sqrt(std::numeric_limits<double>::epsilon());

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

std::string format_time(double t) {
  return format_number(t) + " s";
}

/// W x = r through the Schur complement (w_method.h) for n = N dofs, a compile-time size so that
/// the loops unroll (this runs twice per step): x_v = S⁻¹ (r_v + hγ A_q r_q), x_q = r_q + hγ x_v.
template <int N>
void schur_solve(const SmallLu& lu, const SmallLu::Matrix& hg_a_q, double hg, const StateVector& r,
                 SmallLu::Vector& schur_rhs, StateVector& x) {
  for (int i = 0; i < N; ++i) {
    double s = r[N + i];
    for (int j = 0; j < N; ++j) s += hg_a_q(i, j) * r[j];
    schur_rhs[i] = s;
  }
  lu.solve_in_place(schur_rhs);
  for (int i = 0; i < N; ++i) {
    x[i] = r[i] + hg * schur_rhs[i];
    x[N + i] = schur_rhs[i];
  }
}

/// S = I − hγ A_v − hγ (hγ A_q) and hγ A_q (w_method.h) for n = N dofs, from J's lower rows; then
/// S's LU factors. A compile-time size, like schur_solve.
template <int N>
void schur_factor(const StateMatrix& jacobian, double hg, SmallLu::Matrix& hg_a_q, SmallLu& lu) {
  SmallLu::Matrix s = SmallLu::Matrix::Zero();
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      hg_a_q(i, j) = hg * jacobian(N + i, j);
      s(i, j) = (i == j ? 1.0 : 0.0) - hg * jacobian(N + i, N + j) - hg * hg_a_q(i, j);
    }
  }
  lu.compute(s, N);  // a singular S gives non-finite K, reported by step()
}

static_assert(kMaxDof == 8, "extend WMethod2::solve's and factor's dispatch");

}  // namespace

void forward_difference_jacobian(OdeSystem& system, double t, const StateVector& y,
                                 const StateVector& f0, StateVector& y_work, StateVector& f_work,
                                 StateMatrix& jacobian) {
  const int dim = static_cast<int>(y.size());
  const int n = system.dofs();
  y_work = y;
  f_work.resize(dim);
  jacobian.resize(dim, dim);
  // velocity columns [n, 2n) first: they leave the positions as in y, so a system that memoizes
  // its position-dependent work (the contact geometry) reuses that of f0 for all of them
  for (int c = 0; c < dim; ++c) {
    const int j = c < n ? n + c : (c < 2 * n ? c - n : c);
    const double scale = (n > 0 && j >= n && j < 2 * n) ? 1e-1 : 1e-3;
    const double y_j = y[j];
    const double y_plus = y_j + kSqrtEps * std::max(std::abs(y_j), scale);
    const double delta = y_plus - y_j;  // the increment actually represented
    y_work[j] = y_plus;
    system.rhs(t, y_work, f_work);
    jacobian.col(j) = (f_work - f0) / delta;
    y_work[j] = y_j;
  }
}

WMethod2::WMethod2(const IntegratorOptions& options) : options_(options) {
  if (!(options.fixed_step_s > 0.0) || !std::isfinite(options.fixed_step_s)) {
    throw InputError("w2: fixed step must be positive (got " + format_time(options.fixed_step_s) +
                     ")");
  }
  if (options.jacobian_refresh_steps < 1) {
    throw InputError("w2: Jacobian refresh interval must be at least 1 step (got " +
                     std::to_string(options.jacobian_refresh_steps) + ")");
  }
}

void WMethod2::set_jacobian_override(JacobianFunction jacobian) {
  jacobian_override_ = std::move(jacobian);
  have_jacobian_ = false;  // take effect on the next step
}

void WMethod2::initialize(OdeSystem& system, double t0, const StateVector& y0) {
  const int dim = system.dimension();
  const int dofs = system.dofs();
  if (dim < 1 || dim > kMaxState || dofs < 0 || 2 * dofs > dim || y0.size() != dim) {
    throw std::invalid_argument("w2: bad system size (dimension " + std::to_string(dim) +
                                ", dofs " + std::to_string(dofs) + ", y0 length " +
                                std::to_string(y0.size()) + ")");
  }
  system_ = &system;
  dim_ = dim;
  dofs_ = dofs;
  use_schur_ = dofs > 0 && dim == 2 * dofs;
  t_ = t0;
  y_ = y0;
  stats_ = IntegratorStats{};
  failure_reason_.clear();

  jacobian_.setZero(dim, dim);
  have_jacobian_ = false;
  jacobian_regime_ = 0;
  steps_since_jacobian_ = 0;
  factored_ = false;
  factored_h_ = 0.0;
  for (StateVector* v : {&f0_, &f1_, &f_t_, &k1_, &k2_, &y_stage_, &r_, &y_work_, &f_work_}) {
    v->setZero(dim);
  }
  schur_rhs_.setZero();
  hg_a_q_.setZero();
}

void WMethod2::evaluate_jacobian(std::uint64_t regime) {
  if (jacobian_override_) {
    jacobian_.setZero(dim_, dim_);
    jacobian_override_(t_, y_, jacobian_);
  } else {
    forward_difference_jacobian(*system_, t_, y_, f0_, y_work_, f_work_, jacobian_);
    stats_.rhs_evaluations += dim_;
  }
  have_jacobian_ = true;
  jacobian_regime_ = regime;
  steps_since_jacobian_ = 0;
  factored_ = false;
  ++stats_.jacobian_updates;
}

void WMethod2::factor(double h) {
  const double hg = kGamma * h;
  if (use_schur_) {
    with_fixed_size(
        dofs_, [&](auto size) { schur_factor<size.value>(jacobian_, hg, hg_a_q_, lu_schur_); });
  } else {
    lu_full_.compute(StateMatrix::Identity(dim_, dim_) - hg * jacobian_);
  }
  factored_ = true;
  factored_h_ = h;
  ++stats_.factorizations;
}

void WMethod2::solve(const StateVector& r, StateVector& x) {
  if (use_schur_) {
    const double hg = kGamma * factored_h_;
    with_fixed_size(dofs_, [&](auto size) {
      schur_solve<size.value>(lu_schur_, hg_a_q_, hg, r, schur_rhs_, x);
    });
  } else {
    x = lu_full_.solve(r);
  }
}

StepStatus WMethod2::fail(const std::string& reason) {
  failure_reason_ = reason;
  return StepStatus::Failure;
}

StepStatus WMethod2::step(double t_max) {
  if (system_ == nullptr) return fail("w2: step() called before initialize()");
  const double remaining = t_max - t_;
  if (remaining < kMinStep) {
    if (remaining <= -kMinStep) {
      return fail("w2: t_max = " + format_time(t_max) + " is before the current time " +
                  format_time(t_));
    }
    t_ = std::max(t_, t_max);
    return StepStatus::Ok;
  }
  double h = options_.fixed_step_s;
  const bool last = remaining <= h + kMinStep;  // land exactly on t_max
  if (last) h = remaining;

  system_->rhs(t_, y_, f0_);
  ++stats_.rhs_evaluations;
  const std::uint64_t regime = system_->regime();
  if (!have_jacobian_ || steps_since_jacobian_ >= options_.jacobian_refresh_steps ||
      regime != jacobian_regime_) {
    evaluate_jacobian(regime);
  } else if (use_schur_ && !jacobian_override_ && options_.velocity_jacobian_steps > 0 &&
             steps_since_jacobian_ % options_.velocity_jacobian_steps == 0 &&
             system_->velocity_jacobian(jacobian_)) {
    factored_ = false;  // W changed: its velocity block is new
    ++stats_.velocity_jacobian_updates;
  }
  // W built for a step within 1e-12 (relative) is kept: same as J scaled by h_factored / h,
  // and a W-method is order 2 for any J.
  if (!factored_ || std::abs(h - factored_h_) > 1e-12 * factored_h_) factor(h);

  const double hg = kGamma * h;
  // K1 = W⁻¹ [f(t, y) (+ γh f_t)]
  if (use_time_derivative_) {
    const double t_plus = t_ + kSqrtEps * std::max(std::abs(t_), 1e-3);
    system_->rhs(t_plus, y_, f_work_);
    ++stats_.rhs_evaluations;
    f_t_ = (f_work_ - f0_) / (t_plus - t_);
    r_ = f0_ + hg * f_t_;
    solve(r_, k1_);
  } else {
    solve(f0_, k1_);
  }
  // K2 = W⁻¹ [f(t + h, y + h K1) − 2 K1 (− γh f_t)]
  y_stage_ = y_ + h * k1_;
  system_->rhs(t_ + h, y_stage_, f1_);
  ++stats_.rhs_evaluations;
  r_ = f1_ - 2.0 * k1_;
  if (use_time_derivative_) r_ -= hg * f_t_;
  solve(r_, k2_);
  // y⁺ = y + 1.5 h K1 + 0.5 h K2
  y_stage_ = y_ + (1.5 * h) * k1_ + (0.5 * h) * k2_;
  if (!y_stage_.allFinite()) {
    return fail("w2: non-finite state after the step from t = " + format_time(t_) +
                " (h = " + format_time(h) + ")");
  }
  y_ = y_stage_;
  t_ = last ? t_max : t_ + h;
  ++stats_.steps;
  ++steps_since_jacobian_;
  return StepStatus::Ok;
}

}  // namespace pat

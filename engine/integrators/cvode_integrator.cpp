#include "integrators/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <type_traits>

#include "core/error.h"

namespace pat {

static_assert(std::is_same_v<sunrealtype, double>, "SUNDIALS must be built in double precision");

namespace {

constexpr double kMinStep = 1e-12;  // less left before t_max: just move time there (s)
constexpr long kMaxInternalSteps = 10'000'000;
// Smallest internal step (s): ends the creep towards a point where f stops being finite.
constexpr double kMinInternalStep = 1e-14;

std::string format_time(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g s", t);
  return buffer;
}

// CVodeGetReturnFlagName returns a malloc'ed string in SUNDIALS 6.
std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string result = name != nullptr ? name : "CV_UNKNOWN";
  std::free(name);
  return result;
}

}  // namespace

// All SUNDIALS objects of one integrator. The context lives as long as the object; the solver,
// vector, matrix and linear solver are recreated by every initialize().
struct CvodeIntegrator::Impl {
  SUNContext context = nullptr;
  void* memory = nullptr;
  N_Vector y = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;

  OdeSystem* system = nullptr;
  int dim = 0;
  StateVector y_work, f_work;
  std::exception_ptr exception;  // thrown by system.rhs inside CVODE, rethrown by step()
  std::string message;           // last message from CVODE's error handler

  Impl() {
    if (SUNContext_Create(nullptr, &context) != 0) {
      throw std::runtime_error("cvode: SUNContext_Create failed");
    }
  }
  ~Impl() {
    release();
    SUNContext_Free(&context);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void release() {
    if (memory != nullptr) CVodeFree(&memory);
    if (linear_solver != nullptr) SUNLinSolFree(linear_solver);
    if (matrix != nullptr) SUNMatDestroy(matrix);
    if (y != nullptr) N_VDestroy(y);
    memory = nullptr;
    linear_solver = nullptr;
    matrix = nullptr;
    y = nullptr;
  }

  // f(t, y) for CVODE: 0 = ok, 1 = recoverable (non-finite f: CVODE retries with a smaller
  // step), -1 = unrecoverable (an exception, kept for step()).
  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<Impl*>(user_data);
    const sunrealtype* in = N_VGetArrayPointer(y);
    for (int i = 0; i < self->dim; ++i) self->y_work[i] = in[i];
    try {
      self->system->rhs(t, self->y_work, self->f_work);
    } catch (...) {
      self->exception = std::current_exception();
      return -1;
    }
    if (!self->f_work.allFinite()) return 1;
    sunrealtype* out = N_VGetArrayPointer(ydot);
    for (int i = 0; i < self->dim; ++i) out[i] = self->f_work[i];
    return 0;
  }

  static void error_handler(int /*error_code*/, const char* /*module*/, const char* function,
                            char* message, void* user_data) {
    auto* self = static_cast<Impl*>(user_data);
    self->message = std::string(function != nullptr ? function : "") + ": " +
                    (message != nullptr ? message : "");
  }

  void check(int flag, const char* what) const {
    if (flag < 0) {
      throw std::runtime_error(std::string("cvode: ") + what + " failed (" + flag_name(flag) +
                               (message.empty() ? "" : ": " + message) + ")");
    }
  }
};

CvodeIntegrator::CvodeIntegrator(const IntegratorOptions& options)
    : options_(options), impl_(std::make_unique<Impl>()) {
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0)) {
    throw InputError("cvode: tolerances must be positive");
  }
  if (!(options.max_step_s > 0.0)) throw InputError("cvode: maximum step must be positive");
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::initialize(OdeSystem& system, double t0, const StateVector& y0) {
  const int dim = system.dimension();
  if (dim < 1 || dim > kMaxState || y0.size() != dim) {
    throw std::invalid_argument("cvode: bad system size (dimension " + std::to_string(dim) +
                                ", y0 length " + std::to_string(y0.size()) + ")");
  }
  Impl& impl = *impl_;
  impl.release();
  impl.system = &system;
  impl.dim = dim;
  impl.y_work.setZero(dim);
  impl.f_work.setZero(dim);
  impl.exception = nullptr;
  impl.message.clear();
  t_ = t0;
  y_ = y0;
  stats_ = IntegratorStats{};
  failure_reason_.clear();

  impl.y = N_VNew_Serial(dim, impl.context);
  impl.memory = CVodeCreate(CV_BDF, impl.context);
  impl.matrix = SUNDenseMatrix(dim, dim, impl.context);
  if (impl.y == nullptr || impl.memory == nullptr || impl.matrix == nullptr) {
    impl.release();
    throw std::runtime_error("cvode: out of memory");
  }
  sunrealtype* data = N_VGetArrayPointer(impl.y);
  for (int i = 0; i < dim; ++i) data[i] = y0[i];
  impl.linear_solver = SUNLinSol_Dense(impl.y, impl.matrix, impl.context);
  if (impl.linear_solver == nullptr) {
    impl.release();
    throw std::runtime_error("cvode: SUNLinSol_Dense failed");
  }
  try {
    impl.check(CVodeSetErrHandlerFn(impl.memory, &Impl::error_handler, &impl),
               "CVodeSetErrHandlerFn");
    impl.check(CVodeInit(impl.memory, &Impl::rhs, t0, impl.y), "CVodeInit");
    impl.check(CVodeSetUserData(impl.memory, &impl), "CVodeSetUserData");
    impl.check(
        CVodeSStolerances(impl.memory, options_.relative_tolerance, options_.absolute_tolerance),
        "CVodeSStolerances");
    impl.check(CVodeSetLinearSolver(impl.memory, impl.linear_solver, impl.matrix),
               "CVodeSetLinearSolver");
    impl.check(CVodeSetMaxStep(impl.memory, options_.max_step_s), "CVodeSetMaxStep");
    impl.check(CVodeSetMaxNumSteps(impl.memory, kMaxInternalSteps), "CVodeSetMaxNumSteps");
    impl.check(CVodeSetMinStep(impl.memory, kMinInternalStep), "CVodeSetMinStep");
  } catch (...) {
    impl.release();
    throw;
  }
}

StepStatus CvodeIntegrator::fail(const std::string& reason) {
  failure_reason_ = reason;
  return StepStatus::Failure;
}

void CvodeIntegrator::update_stats() {
  void* memory = impl_->memory;
  long value = 0;
  if (CVodeGetNumSteps(memory, &value) == CV_SUCCESS) stats_.steps = value;
  if (CVodeGetNumErrTestFails(memory, &value) == CV_SUCCESS) stats_.rejected_steps = value;
  long linear_rhs = 0;
  if (CVodeGetNumRhsEvals(memory, &value) == CV_SUCCESS &&
      CVodeGetNumLinRhsEvals(memory, &linear_rhs) == CV_SUCCESS) {
    stats_.rhs_evaluations = value + linear_rhs;
  }
  if (CVodeGetNumJacEvals(memory, &value) == CV_SUCCESS) stats_.jacobian_updates = value;
  if (CVodeGetNumLinSolvSetups(memory, &value) == CV_SUCCESS) stats_.factorizations = value;
}

StepStatus CvodeIntegrator::step(double t_max) {
  Impl& impl = *impl_;
  if (impl.memory == nullptr) return fail("cvode: step() called before initialize()");
  const double remaining = t_max - t_;
  if (remaining < kMinStep) {
    if (remaining <= -kMinStep) {
      return fail("cvode: t_max = " + format_time(t_max) + " is before the current time " +
                  format_time(t_));
    }
    t_ = std::max(t_, t_max);
    return StepStatus::Ok;
  }

  impl.message.clear();
  int flag = CVodeSetStopTime(impl.memory, t_max);
  sunrealtype t_reached = t_;
  if (flag >= 0) flag = CVode(impl.memory, t_max, impl.y, &t_reached, CV_ONE_STEP);
  update_stats();
  if (impl.exception) {
    std::exception_ptr exception = impl.exception;
    impl.exception = nullptr;
    std::rethrow_exception(exception);
  }
  if (flag < 0) {
    return fail("cvode: " + flag_name(flag) + " at t = " + format_time(t_) +
                (impl.message.empty() ? "" : " (" + impl.message + ")"));
  }
  const sunrealtype* data = N_VGetArrayPointer(impl.y);
  for (int i = 0; i < impl.dim; ++i) y_[i] = data[i];
  t_ = flag == CV_TSTOP_RETURN ? t_max : std::min(static_cast<double>(t_reached), t_max);
  return StepStatus::Ok;
}

}  // namespace pat

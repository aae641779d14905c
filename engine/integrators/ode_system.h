// The first-order system the integrators solve: y' = f(t, y).
//
// Mechanical systems are second order: y = (q, v) with q' = v and v' = a(t, q, v), where q has
// dofs() entries. Integrators use that structure (the W-method solves an n×n Schur system
// instead of a 2n×2n one). A plain first-order system reports dofs() == 0.
#pragma once

#include <cstdint>

#include "core/types.h"

namespace pat {

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  /// Length of y.
  virtual int dimension() const = 0;
  /// Number n of second-order coordinates: y = (q[0..n), v[0..n)) with q' = v.
  /// 0 for a general first-order system.
  virtual int dofs() const { return 0; }

  /// dydt = f(t, y). Must not allocate on the heap.
  virtual void rhs(double t, const StateVector& y, StateVector& dydt) = 0;

  /// A signature of the discrete regime seen by the latest rhs() call (for a contact model:
  /// the bit set of active contacts). Integrators with a frozen Jacobian refresh it whenever
  /// this changes. Smooth systems return 0.
  virtual std::uint64_t regime() const { return 0; }

  /// For a second-order system, right after rhs(t, y): writes an approximation of the velocity
  /// block ∂v'/∂v of the Jacobian at that (t, y) into jacobian(n + i, n + j) (other entries
  /// untouched) and returns true; false if the system does not provide one.
  virtual bool velocity_jacobian(StateMatrix& /*jacobian*/) { return false; }
};

/// Counters every integrator keeps.
struct IntegratorStats {
  long steps = 0;                      ///< accepted steps
  long rejected_steps = 0;             ///< rejected by the error control (adaptive methods)
  long rhs_evaluations = 0;            ///< f evaluations, Jacobian ones included
  long jacobian_updates = 0;           ///< Jacobian evaluations
  long velocity_jacobian_updates = 0;  ///< w2: refreshes of the velocity block alone
  long factorizations = 0;             ///< LU factorizations of the iteration matrix
};

/// What one step() call did.
enum class StepStatus {
  Ok,       ///< a step was accepted; time() and state() moved forward
  Failure,  ///< the method cannot continue (step size underflow, non-finite state, solver error)
};

/// Common interface of the fixed-step W-method and the adaptive references.
///
/// Usage: initialize(), then call step(t_max) repeatedly; each call takes exactly one accepted
/// step that never passes t_max (the caller interpolates between steps with the cubic Hermite
/// polynomial built from (q, v) at both ends).
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual void initialize(OdeSystem& system, double t0, const StateVector& y0) = 0;
  virtual StepStatus step(double t_max) = 0;
  virtual double time() const = 0;
  virtual const StateVector& state() const = 0;
  virtual const IntegratorStats& stats() const = 0;
  /// Human-readable reason of the last Failure.
  virtual const std::string& failure_reason() const = 0;
  /// Short name used by the CLI: "w2", "rodas", "cvode".
  virtual const char* name() const = 0;
};

}  // namespace pat

// Static equilibrium of an action near a known configuration, by Newton's method: solves
// q̈(q, q̇ = 0) = 0 (gravity, springs, straps and felt contacts balance; friction and the felt
// hysteresis blend vanish at rest, as at the end of the damped settle in find_rest_state).
// Much cheaper than settling dynamically, so the regulation can re-measure the rest geometry
// after every small adjuster move (continuation from the previous rest state).
#pragma once

#include <functional>

#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

/// Damped Newton on residual(q) = 0 from the q given: finite-difference Jacobian (1e-7 rad),
/// steps clipped to 0.02 rad and halved until the residual decreases. Joint `held` (−1: none)
/// keeps its value (its Jacobian row and column are the identity, its step zero). Returns true
/// when a step falls below `step_tolerance` (rad) with |residual| < 1e-3, false when it does not
/// converge within `max_iterations`.
bool damped_newton(const std::function<DofVector(const DofVector&)>& residual, DofVector& q,
                   int held, int max_iterations, double step_tolerance);

/// Newton iterations from `guess` (q̈ residual, finite-difference Jacobian, step halving).
/// Returns true and the equilibrium in `q` when the step falls below 1e-10 rad; false when
/// it does not converge (the caller then settles dynamically).
bool solve_static_equilibrium(const ActionModel& model, const DofVector& guess, DofVector& q);

/// The rest state of `model`, from Newton started at `near` when it converges there to a
/// stable equilibrium, else from the dynamic settle (find_rest_state).
RestState rest_state_near(const ActionModel& model, const RestState& near);

}  // namespace pat

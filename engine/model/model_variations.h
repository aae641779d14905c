// What-if variants of an action for the analyses (a copy, never an edit in place): a spring made
// stronger or weaker, lead added at the key front.
#pragma once

#include <string>

#include "model/action_model.h"

namespace pat {

/// Copy of `model` with joint spring `name` scaled by `factor` ≥ 0 (stiffness and preload, so the
/// torque τ0 − k q is scaled at every angle). Throws InputError naming the spring or the factor.
ActionModel with_spring_factor(const ActionModel& model, const std::string& name, double factor);

/// Copy of `model` with a point mass of `grams` (may be negative to take lead out, but the key
/// keeps a positive mass) at the key front, folded into the key body by the parallel-axis
/// theorem: m' = m + Δm, c' = (m c + Δm p)/m', I' = I + m|c − c'|² + Δm|p − c'|².
ActionModel with_key_front_lead(const ActionModel& model, double grams);

}  // namespace pat

// Key travel geometry: how far the key turns from rest until it meets the front-rail punching.
#pragma once

#include "model/action_model.h"
#include "sim/simulation.h"

namespace pat {

/// Key angle (rad, > 0) from the rest state to first touch of the key-bottom contact.
double key_full_dip_angle(const ActionModel& model, const RestState& rest);

/// Key-front travel (m, downward) for a key angle (rad) from rest.
double key_front_travel(const ActionModel& model, const RestState& rest, double key_angle);

/// The input context (full dip) of a model at rest, for parse_input_spec.
InputContext input_context(const ActionModel& model, const RestState& rest);

}  // namespace pat

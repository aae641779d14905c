// Derived models: the immutable ActionModel is never changed in place; these functions return a
// modified copy (adjuster offsets, parts taken out for a run).
#pragma once

#include <map>
#include <string>

#include "model/action_model.h"

namespace pat {

/// Copy of `model` with adjuster `name` at `value_m` (m from its regulated position): every
/// feature it moves is offset by (value − current value) along its direction.
/// Throws InputError for an unknown adjuster or a value outside its physical range.
ActionModel with_adjuster(const ActionModel& model, const std::string& name, double value_m);

/// Copy of `model` without the spring or strap `part` (e.g. "bridle", "butt_spring",
/// "repetition_spring"). Throws InputError naming the parts that can be removed.
ActionModel without_part(const ActionModel& model, const std::string& part);

/// Where the model comes from, for messages about it: its file, and what was changed for the run
/// ("…/grand.json without jack_spring, adjusters turned"), so that a failure caused by a
/// --without or a --set is not blamed on the preset alone. Which adjusters is not said: these
/// messages reach the practice mode's student, whose hidden faults are turned adjusters.
std::string model_origin(const ActionModel& model);

/// The adjusters turned from their regulated positions, for a file's metadata: "regulated", or
/// e.g. "let_off=0.5mm drop=-0.2mm".
std::string adjuster_settings_text(const ActionModel& model);

/// What a file made from the model records of it in its metadata: `action` (grand or upright),
/// `preset` (the file read), `settings` (adjuster_settings_text) and, when parts were left out,
/// `without` ("bridle butt_spring").
std::map<std::string, std::string> model_metadata(const ActionModel& model);

/// Parses "NAME=MM" (as given to --set) and applies it.
ActionModel with_setting(const ActionModel& model, const std::string& assignment);

}  // namespace pat

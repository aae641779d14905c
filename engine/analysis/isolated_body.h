// One body of an action taken out of it, as a technician does for the swing test (the hammer on
// its flange) or the paper's key characterisation (the key alone on its balance pin): a
// one-joint model with the body's mass, inertia and joint friction, and only its contacts with
// the frame (rails, punchings). Springs, straps, adjusters and the other bodies are left out.
#pragma once

#include <string>

#include "model/action_model.h"

namespace pat {

/// A copy of body `body_name` of `action` alone on its joint. The body must hang on the frame
/// (parent −1). With `keep_frame_contacts` its contacts with the frame are kept (indices
/// renumbered, the key_bottom landmark kept when it is one of them). Throws InputError naming
/// the body when it does not exist or hangs on another body.
ActionModel isolated_body_model(const ActionModel& action, const std::string& body_name,
                                bool keep_frame_contacts);

}  // namespace pat

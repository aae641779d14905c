// Model extensions ("effects", DESIGN.md sections 4 and 5): named transformations of the
// immutable ActionModel, each with one primary value, so that any simulation can run with them
// and the dynamics need no knowledge of them.
//
//   shank_flex=HZ                 the hammer is split into shank and head, joined by a revolute
//                                 joint with a torsional spring k = (2π f)² J_head (J_head: the
//                                 head's moment of inertia about that joint) and light viscous
//                                 damping (ζ = 0.05): f is the first bending mode of the shank
//                                 with the shank held (closed form ω² = k / J_head).
//   backcheck_compliance=N_PER_MM the backcheck becomes a body on a wire: a revolute joint on the
//                                 body that carries it, placed so that the backcheck face moves
//                                 along the check contact's normal, with a torsional spring
//                                 k_t = k L² (L: wire length), so the face has linear stiffness k.
//   joint_friction.JOINT=FACTOR   the joint friction amplitude A of body JOINT times FACTOR.
//   repetition_spring=FACTOR      (grand) / butt_spring=FACTOR (upright): the spring's strength
//                                 times FACTOR (stiffness k and preload τ0 together: a stiffer
//                                 wire of the same shape).
//   felt_stiffness.CONTACT=FACTOR the contact's felt law (loading and unloading a and c) times
//                                 FACTOR; CONTACT is the contact's name or its column form
//                                 (e.g. hammer_head_string).
//   regulation_offset.SETTING=MM  the regulation adjuster SETTING moved by MM from its value.
#pragma once

#include <string>
#include <vector>

#include "model/action_model.h"

namespace pat {

/// One effect with its value in its unit (Hz, N/mm, factor or mm).
struct Effect {
  std::string name;  ///< e.g. "shank_flex", "joint_friction.hammer"
  double value = 0.0;
};

/// What an effect name means for a model: its family, unit, the value that leaves the model
/// unchanged (nullopt for shank_flex and backcheck_compliance: the rigid model is their limit),
/// its physical range and whether it is searched on a log scale.
struct EffectInfo {
  std::string name;
  std::string family;  ///< the part before the '.' (e.g. "joint_friction")
  std::string unit;    ///< "Hz", "N/mm", "factor", "mm"
  double min = 0.0;    ///< physical range of the value
  double max = 0.0;
  bool log_scale = false;
  bool has_neutral = false;  ///< a value exists that leaves the model unchanged
  double neutral = 0.0;
};

/// Parses "NAME=VALUE" (as given to --effect). Throws InputError naming the text.
Effect parse_effect(const std::string& assignment);

/// Describes an effect name for this model. Throws InputError for an unknown family, an unknown
/// joint, contact or setting (listing the valid ones), or a spring the action does not have.
EffectInfo describe_effect(const ActionModel& model, const std::string& name);

/// Copy of `model` with the effect applied. Throws InputError for an unknown name or a value
/// outside its physical range.
ActionModel with_effect(const ActionModel& model, const Effect& effect);

/// The candidate library the diagnosis fits for this model: every family, with the joints,
/// contacts and settings where an effect is visible in the hammer trace.
std::vector<EffectInfo> candidate_effects(const ActionModel& model);

/// "name=value unit" for messages and metadata.
std::string describe(const Effect& effect, const EffectInfo& info);

}  // namespace pat

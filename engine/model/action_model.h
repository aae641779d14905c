// The immutable description of a piano action (DESIGN.md section 1: the model, as opposed to the
// mutable simulation state in sim/sim_state.h).
//
// Geometry convention: every point (pivots, centres of mass, contact features, outlines) is given
// in one global frame, x toward the back of the action (away from the player), y up, at the
// drawing configuration q = 0. Joint coordinates are relative rotations (rad, counter-clockwise
// positive) from that configuration, so a body's absolute rotation is the sum of its own and its
// ancestors' coordinates. All values are SI.
#pragma once

#include <string>
#include <vector>

#include "core/types.h"

namespace pat {

/// Joint friction torque law (paper eq. 4, after Hirschkorn):
///   T = A (tanh(ω/ωt) + B1 (ω/ωt) / (1 + B2 (ω/ωt)^4)),   opposing the joint rate ω (rad/s).
struct JointFriction {
  double a_nm = 0.0;     ///< A, N·m
  double b1 = 0.0;       ///< B1, dimensionless
  double b2 = 0.0;       ///< B2, dimensionless
  double omega_t = 1.0;  ///< ωt, rad/s
};

/// A rigid body on a revolute joint; the joint has the body's name.
struct Body {
  std::string name;
  int parent = -1;           ///< index of the parent body, -1 for the frame (ground)
  Vec2 pivot;                ///< joint centre, m
  double mass = 0.0;         ///< kg
  Vec2 com;                  ///< centre of mass, m
  double inertia_com = 0.0;  ///< moment of inertia about the centre of mass, kg·m²
  JointFriction friction;
  /// +1 or −1: the sign that makes this body's trace angle positive in the direction of
  /// DESIGN.md section 5 (key front down, hammer toward the string, others: the way the key
  /// press moves them).
  double trace_sign = 1.0;
  std::vector<Vec2> outline;  ///< drawing polygon, m
};

/// Fixed parts drawn with the action (rails, string, buttons); they move only with adjusters.
struct Fixture {
  std::string name;
  std::vector<Vec2> outline;               ///< m
  std::string adjuster;                    ///< name of the adjuster that moves it, or empty
  Vec2 adjuster_direction = Vec2::Zero();  ///< unit direction of that motion
};

/// One loading or unloading curve of the felt law (paper eq. 2):  F(x) = a x e^(b x) + c x.
struct FeltCurve {
  double a = 0.0;  ///< N/m
  double b = 0.0;  ///< 1/m
  double c = 0.0;  ///< N/m
};

/// The hysteretic felt law (paper eq. 3):
///   F = F_L(x)                                 if ẋ ≥ 0,
///   F = F_L(x) + (F_L(x) − F_U(x)) tanh(α ẋ)   if ẋ < 0   (tends to F_U when unloading fast).
struct FeltLaw {
  FeltCurve loading;
  FeltCurve unloading;
  double alpha = 0.0;  ///< s/m
};

/// Regularized Coulomb friction that saturates with the tangential slip velocity:
///   F_t = −μ F_n tanh(v_t / v_s).
struct ContactFriction {
  double mu = 0.0;              ///< friction coefficient (0: frictionless contact)
  double slip_velocity = 1e-3;  ///< v_s, m/s
};

enum class ContactShape {
  CircleCircle,   ///< circle on body A against circle on body B
  CircleSegment,  ///< circle on A against a segment on B; past the ends, against the end points.
                  ///< With radius_b > 0 the segment's corners are rounded (hybrid contact).
};

/// An intermittent contact between body A (carrying a circle; radius 0 = a point) and body B.
/// The normal points from B toward A; penetration x > 0 means overlap.
struct Contact {
  std::string name;
  int body_a = -1;  ///< -1: the frame
  int body_b = -1;
  ContactShape shape = ContactShape::CircleSegment;
  Vec2 center_a;          ///< m
  double radius_a = 0.0;  ///< m
  Vec2 center_b;          ///< CircleCircle: centre of B's circle, m
  double radius_b = 0.0;  ///< CircleCircle: radius; CircleSegment: corner radius, m
  Vec2 segment_start;     ///< CircleSegment: end points on B, m
  Vec2 segment_end;
  Vec2 segment_normal;  ///< CircleSegment: unit normal toward A's free side
  FeltLaw law;
  ContactFriction friction;
  double max_penetration = 3e-3;  ///< beyond this the run stops as unphysical, m
  /// CircleSegment with sharp corners: ends of B's face that A's body cannot go round without
  /// crossing B (the jack's top leaving the repetition lever's window over its front wall drags
  /// the jack's flank through the wall). A circle pressed into the face that comes to lie behind
  /// the face's line past such an end stops the run as unphysical.
  bool closed_start = false, closed_end = false;
};

/// A torsional spring on one joint (between a body and its parent):
///   τ = τ0 − k q   acting on the joint coordinate q (τ0 = preload at q = 0).
struct JointSpring {
  std::string name;
  int body = -1;
  double stiffness = 0.0;  ///< k, N·m/rad
  double preload = 0.0;    ///< τ0, N·m
};

/// A tension-only strap (the upright's bridle strap) between two body points:
///   F = k (L − L0) + c L̇  when L > L0 (and F > 0), else 0; L0 = rest distance + slack.
struct Strap {
  std::string name;
  int body_a = -1;
  Vec2 point_a;
  int body_b = -1;
  Vec2 point_b;
  double slack = 0.0;      ///< m (adjusted by an adjuster)
  double stiffness = 0.0;  ///< N/m
  double damping = 0.0;    ///< N·s/m
};

/// Which geometric feature an adjuster moves.
struct AdjusterEffect {
  enum class Target { ContactA, ContactB, StrapSlack, StrapPointA, StrapPointB };
  Target target = Target::ContactB;
  int index = -1;                 ///< contact or strap index
  Vec2 direction = Vec2::Zero();  ///< unit direction of the motion (for geometry targets)
};

/// A regulation adjuster (DESIGN.md section 3): a screw, button, punching or wire expressed as
/// a distance (m) from its regulated position. Moving it offsets geometric features.
struct Adjuster {
  std::string name;
  std::string description;  ///< what the technician turns, and which way is positive
  double min = -3e-3;       ///< physical range, m
  double max = 3e-3;
  double value = 0.0;  ///< current offset from the regulated position, m
  std::vector<AdjusterEffect> effects;
};

/// Named points and elements the simulation and the measurements refer to.
struct ActionLandmarks {
  int key = -1;    ///< index of the key body
  Vec2 key_front;  ///< where the finger presses and key dip is measured, m
  int hammer = -1;
  Vec2 strike_point;                     ///< hammer felt top that meets the string, m
  Vec2 string_normal = Vec2(0.0, -1.0);  ///< unit normal of the string plane toward the hammer
  Vec2 string_point;                     ///< a point of the string plane, m
  int string_contact = -1;               ///< hammer–string contact
  int escapement_contact = -1;           ///< jack–knuckle (grand) or jack–butt (upright)
  int letoff_contact = -1;               ///< jack toe–let-off button
  int check_contact = -1;                ///< hammer–backcheck
  int key_bottom_contact = -1;           ///< key–front-rail punching
  int key_rest_contact = -1;  ///< key–back rail: what the key rests on at the top (optional)
};

/// A regulation setting (DESIGN.md section 3): the adjuster of the same name, what is measured,
/// the target and tolerance (in `unit`), listed in the technician's order.
struct RegulationSetting {
  std::string name;         ///< = the adjuster's name
  std::string measurement;  ///< what the technician measures, in words
  std::string unit;         ///< "mm" or "fraction"
  double target = 0.0;      ///< in unit
  double tolerance = 0.05;  ///< in unit
  std::string source;       ///< where the target comes from
  /// Another adjuster the technician moves out of the way when this setting cannot be
  /// regulated as found (e.g. the grand's drop screw turned down before let-off), and the
  /// position (m from its regulated position) it is moved to; empty when none.
  std::string clear_adjuster;
  double clear_position = 0.0;
};

/// The part an adjuster turns, from its description ("let-off button: + screws it down …" →
/// "let-off button"); empty when the description has no such head.
inline std::string adjuster_part_words(const std::string& description) {
  const std::size_t colon = description.find(':');
  return colon == std::string::npos ? std::string() : description.substr(0, colon);
}

/// A setting's or adjuster's identifier in words, as technicians write it: "key_dip" → "key dip",
/// "let_off" → "let-off".
inline std::string setting_words(const std::string& name) {
  std::string words = name;
  for (char& c : words)
    if (c == '_') c = ' ';
  return words == "let off" ? std::string("let-off") : words;
}

struct ActionModel {
  int schema = 1;
  std::string kind;  ///< "grand" or "upright"
  std::string name;
  std::string description;
  std::string source_file;  ///< path the model was read from (for messages)
  Vec2 gravity = Vec2(0.0, -kGravity);
  std::vector<Body> bodies;  ///< parents before children
  std::vector<Fixture> fixtures;
  std::vector<Contact> contacts;
  std::vector<JointSpring> springs;
  std::vector<Strap> straps;
  std::vector<Adjuster> adjusters;
  ActionLandmarks landmarks;
  std::vector<RegulationSetting> regulation;  ///< the seven settings, technician's order
  std::string preset_json;  ///< the preset text the model was read from (for writing it back)
  std::vector<std::string> removed_parts;  ///< springs and straps taken out (--without)

  int dofs() const { return static_cast<int>(bodies.size()); }
  int body_index(const std::string& name) const;
  int contact_index(const std::string& name) const;
  int spring_index(const std::string& name) const;
  int strap_index(const std::string& name) const;
  int adjuster_index(const std::string& name) const;
  int setting_index(const std::string& name) const;
};

}  // namespace pat

#include "model/effects.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "model/model_edits.h"
#include "sim/simulation.h"

namespace pat {
namespace {

// Damping ratio of the added flexible modes (shank, backcheck wire): wood and steel wire ring
// for several periods; 0.05 is an estimate (no published value in reference/parameters.md).
constexpr double kModeDampingRatio = 0.05;
// Share of the hammer mass in the head (felt + moulding) when the hammer is split: a grand
// treble hammer of about 11 g has a head of 7–8 g and a shank with knuckle of 3–4 g (estimate
// after reference/parameters.md section 1, hammer mass and centre of mass).
constexpr double kHeadMassFraction = 0.65;
// Radius of gyration of the head about its own centre of mass (a felt block about 25 mm
// high): estimate.
constexpr double kHeadGyrationRadius = 8e-3;
// The head joint sits this fraction of the way from the flange to the head along the shank.
constexpr double kHeadJointFraction = 0.85;
// Backcheck: a wire of this length (m) carrying a head of this mass (kg): estimates of a
// typical grand backcheck (wire about 30 mm above the key, wood and felt head about 3 g).
constexpr double kBackcheckWireLength = 30e-3;
constexpr double kBackcheckMass = 3e-3;

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

int find_contact(const ActionModel& model, const std::string& name) {
  for (std::size_t i = 0; i < model.contacts.size(); ++i)
    if (model.contacts[i].name == name || column_name(model.contacts[i].name) == name)
      return static_cast<int>(i);
  return -1;
}

std::vector<std::string> contact_names(const ActionModel& model) {
  std::vector<std::string> names;
  for (const Contact& c : model.contacts) names.push_back(column_name(c.name));
  return names;
}

std::string spring_effect_name(const ActionModel& model) {
  return model.kind == "upright" ? "butt_spring" : "repetition_spring";
}

/// Viscous joint damping c (N·m·s/rad) written as the joint friction law with B2 = 0:
/// T = A (tanh(ω/ωt) + B1 ω/ωt) with B1 = 1 and A = c ωt; ωt = 1e-3 rad/s makes the Coulomb
/// part (amplitude c·1e-3) negligible beside the viscous one.
JointFriction viscous_damping(double c) {
  JointFriction f;
  f.omega_t = 1e-3;
  f.a_nm = c * f.omega_t;
  f.b1 = 1.0;
  f.b2 = 0.0;
  return f;
}

/// Moves to `new_body` every contact feature of `body` that lies beyond the joint at `joint`
/// along `axis` (unit): those features ride on the new body.
void move_features_beyond(ActionModel& m, int body, int new_body, const Vec2& joint,
                          const Vec2& axis) {
  for (Contact& c : m.contacts) {
    if (c.body_a == body && (c.center_a - joint).dot(axis) > 0.0) c.body_a = new_body;
    if (c.body_b == body) {
      const Vec2 b = c.shape == ContactShape::CircleCircle
                         ? c.center_b
                         : Vec2(0.5 * (c.segment_start + c.segment_end));
      if ((b - joint).dot(axis) > 0.0) c.body_b = new_body;
    }
  }
}

ActionModel with_shank_flex(const ActionModel& model, double frequency_hz) {
  ActionModel m = model;
  const int h = model.landmarks.hammer;
  const Body hammer = model.bodies[h];
  const Vec2 axis = (hammer.com - hammer.pivot).normalized();
  const double reach = (model.landmarks.strike_point - hammer.pivot).dot(axis);
  const Vec2 joint = hammer.pivot + kHeadJointFraction * reach * axis;
  const Vec2 axis_end = hammer.pivot + reach * axis;
  const Vec2 head_com = 0.5 * (axis_end + model.landmarks.strike_point);

  // Split mass, centre of mass and inertia so that the locked pair equals the rigid hammer.
  double fraction = kHeadMassFraction;
  double head_mass = 0, shank_mass = 0, head_inertia = 0, shank_inertia = -1;
  Vec2 shank_com;
  for (; fraction > 0.2 && shank_inertia < 0.05 * hammer.inertia_com; fraction -= 0.05) {
    head_mass = fraction * hammer.mass;
    shank_mass = hammer.mass - head_mass;
    shank_com = (hammer.mass * hammer.com - head_mass * head_com) / shank_mass;
    head_inertia = head_mass * kHeadGyrationRadius * kHeadGyrationRadius;
    shank_inertia = hammer.inertia_com - head_inertia -
                    head_mass * (head_com - hammer.com).squaredNorm() -
                    shank_mass * (shank_com - hammer.com).squaredNorm();
  }
  if (shank_inertia <= 0)
    throw InputError("shank_flex: the hammer of '" + model.name +
                     "' cannot be split into shank and head (its inertia is too small for its "
                     "mass distribution)");
  if (static_cast<int>(m.bodies.size()) >= kMaxDof)
    throw InputError("shank_flex: the model already has " + std::to_string(m.bodies.size()) +
                     " joints, the most a model may have is " + std::to_string(kMaxDof));

  Body& shank = m.bodies[h];
  shank.mass = shank_mass;
  shank.com = shank_com;
  shank.inertia_com = shank_inertia;
  Body head;
  head.name = hammer.name + "_head";
  head.parent = h;
  head.pivot = joint;
  head.mass = head_mass;
  head.com = head_com;
  head.inertia_com = head_inertia;
  head.trace_sign = hammer.trace_sign;
  const double j_head = head_inertia + head_mass * (head_com - joint).squaredNorm();
  const double omega = 2.0 * kPi * frequency_hz;
  const double k = omega * omega * j_head;
  head.friction = viscous_damping(2.0 * kModeDampingRatio * std::sqrt(k * j_head));
  for (const Vec2& p : hammer.outline)
    if ((p - joint).dot(axis) > 0.0) head.outline.push_back(p);
  const int head_index = static_cast<int>(m.bodies.size());
  m.bodies.push_back(head);
  move_features_beyond(m, h, head_index, joint, axis);
  m.landmarks.hammer = head_index;  // the strike point rides on the head
  m.springs.push_back({"shank_flex", head_index, k, 0.0});
  return m;
}

ActionModel with_backcheck_compliance(const ActionModel& model, double n_per_mm) {
  ActionModel m = model;
  const int check = model.landmarks.check_contact;
  if (check < 0) throw InputError("backcheck_compliance: the action has no backcheck contact");
  if (static_cast<int>(m.bodies.size()) >= kMaxDof)
    throw InputError("backcheck_compliance: the model already has " +
                     std::to_string(m.bodies.size()) + " joints (at most " +
                     std::to_string(kMaxDof) + ")");
  Contact& c = m.contacts[check];
  const bool on_b = c.body_a == model.landmarks.hammer ||
                    (c.body_a >= 0 && model.bodies[c.body_a].name == "hammer");
  const int carrier = on_b ? c.body_b : c.body_a;
  const Vec2 face =
      on_b ? (c.shape == ContactShape::CircleCircle ? c.center_b
                                                    : Vec2(0.5 * (c.segment_start + c.segment_end)))
           : c.center_a;
  const Vec2 normal = c.shape == ContactShape::CircleSegment
                          ? c.segment_normal
                          : Vec2(c.center_a - c.center_b).normalized();
  // The wire's base lies L from the face across the normal: a rotation about it moves the face
  // along the normal, so k_t = k L² gives the face a linear stiffness k.
  const Vec2 base = face - kBackcheckWireLength * perp(normal);
  Body backcheck;
  backcheck.name = "backcheck";
  backcheck.parent = carrier;
  backcheck.pivot = base;
  backcheck.mass = kBackcheckMass;
  backcheck.com = face;
  backcheck.inertia_com = 0.0;
  backcheck.trace_sign = 1.0;
  const double kt = n_per_mm * 1e3 * kBackcheckWireLength * kBackcheckWireLength;
  const double j = kBackcheckMass * kBackcheckWireLength * kBackcheckWireLength;
  backcheck.friction = viscous_damping(2.0 * kModeDampingRatio * std::sqrt(kt * j));
  const int index = static_cast<int>(m.bodies.size());
  m.bodies.push_back(backcheck);
  if (on_b)
    c.body_b = index;
  else
    c.body_a = index;
  m.springs.push_back({"backcheck_wire", index, kt, 0.0});
  return m;
}

void check_range(const Effect& e, const EffectInfo& info) {
  if (!std::isfinite(e.value) || e.value < info.min - 1e-12 || e.value > info.max + 1e-12) {
    std::ostringstream out;
    out << "effect " << e.name << ": " << e.value << " " << info.unit
        << " is outside its physical range [" << info.min << ", " << info.max << "] " << info.unit;
    throw InputError(out.str());
  }
}

std::pair<std::string, std::string> split_name(const std::string& name) {
  const auto dot = name.find('.');
  if (dot == std::string::npos) return {name, ""};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

}  // namespace

Effect parse_effect(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--effect '" + assignment + "': expected NAME=VALUE, e.g. shank_flex=120");
  Effect e;
  e.name = assignment.substr(0, eq);
  const std::string number = assignment.substr(eq + 1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), e.value);
  if (number.empty() || error != std::errc() || end != number.data() + number.size() ||
      !std::isfinite(e.value))
    throw InputError("--effect '" + assignment + "': '" + number + "' is not a number");
  return e;
}

EffectInfo describe_effect(const ActionModel& model, const std::string& name) {
  const auto [family, part] = split_name(name);
  EffectInfo info;
  info.name = name;
  info.family = family;
  auto no_part = [&] {
    if (!part.empty())
      throw InputError("effect " + name + ": " + family + " takes no '." + part + "'");
  };
  if (family == "shank_flex") {
    no_part();
    info.unit = "Hz";
    info.min = 20.0, info.max = 1000.0, info.log_scale = true;
  } else if (family == "backcheck_compliance") {
    no_part();
    // a brass backcheck wire of 1.5 mm on 30 mm: 3EI/L³ ≈ 2.8 N/mm (E = 100 GPa); the range
    // covers thinner, longer and bent wires
    info.unit = "N/mm";
    info.min = 0.1, info.max = 20.0, info.log_scale = true;
  } else if (family == "joint_friction") {
    std::vector<std::string> joints;
    for (const Body& b : model.bodies) joints.push_back(b.name);
    if (model.body_index(part) < 0)
      throw InputError("effect " + name + ": the " + model.kind + " action has no joint '" + part +
                       "' (joints: " + joined(joints) + ")");
    info.unit = "factor";
    info.min = 0.05, info.max = 20.0, info.log_scale = true;
    info.has_neutral = true, info.neutral = 1.0;
  } else if (family == "repetition_spring" || family == "butt_spring") {
    no_part();
    if (family != spring_effect_name(model) || model.spring_index(family) < 0)
      throw InputError("effect " + name + ": the " + model.kind + " action has no " + family +
                       " (its spring effect is " + spring_effect_name(model) + ")");
    info.unit = "factor";
    info.min = 0.1, info.max = 10.0, info.log_scale = true;
    info.has_neutral = true, info.neutral = 1.0;
  } else if (family == "felt_stiffness") {
    if (find_contact(model, part) < 0)
      throw InputError("effect " + name + ": the " + model.kind + " action has no contact '" +
                       part + "' (contacts: " + joined(contact_names(model)) + ")");
    info.unit = "factor";
    info.min = 0.1, info.max = 10.0, info.log_scale = true;
    info.has_neutral = true, info.neutral = 1.0;
  } else if (family == "regulation_offset") {
    const int a = model.adjuster_index(part);
    if (a < 0) {
      std::vector<std::string> names;
      for (const Adjuster& adj : model.adjusters) names.push_back(adj.name);
      throw InputError("effect " + name + ": the " + model.kind + " action has no setting '" +
                       part + "' (settings: " + joined(names) + ")");
    }
    const Adjuster& adj = model.adjusters[a];
    info.unit = "mm";
    info.min = (adj.min - adj.value) * 1e3, info.max = (adj.max - adj.value) * 1e3;
    info.has_neutral = true, info.neutral = 0.0;
  } else {
    throw InputError("unknown effect '" + name +
                     "' (expected shank_flex, backcheck_compliance, joint_friction.JOINT, " +
                     spring_effect_name(model) +
                     ", felt_stiffness.CONTACT or regulation_offset.SETTING)");
  }
  return info;
}

ActionModel with_effect(const ActionModel& model, const Effect& effect) {
  const EffectInfo info = describe_effect(model, effect.name);
  check_range(effect, info);
  const auto [family, part] = split_name(effect.name);
  if (family == "shank_flex") return with_shank_flex(model, effect.value);
  if (family == "backcheck_compliance") return with_backcheck_compliance(model, effect.value);
  ActionModel m = model;
  if (family == "joint_friction") {
    m.bodies[model.body_index(part)].friction.a_nm *= effect.value;
  } else if (family == "felt_stiffness") {
    FeltLaw& law = m.contacts[find_contact(model, part)].law;
    for (FeltCurve* curve : {&law.loading, &law.unloading}) {
      curve->a *= effect.value;
      curve->c *= effect.value;
    }
  } else if (family == "regulation_offset") {
    const Adjuster& adj = model.adjusters[model.adjuster_index(part)];
    return with_adjuster(model, part, adj.value + effect.value * 1e-3);
  } else {  // repetition_spring / butt_spring
    JointSpring& s = m.springs[model.spring_index(family)];
    s.stiffness *= effect.value;
    s.preload *= effect.value;
  }
  return m;
}

std::vector<EffectInfo> candidate_effects(const ActionModel& model) {
  std::vector<std::string> names{"shank_flex", "backcheck_compliance"};
  for (const char* joint : {"key", "whippen", "hammer"})
    if (model.body_index(joint) >= 0) names.push_back(std::string("joint_friction.") + joint);
  if (model.spring_index(spring_effect_name(model)) >= 0)
    names.push_back(spring_effect_name(model));
  const ActionLandmarks& l = model.landmarks;
  for (int c : {l.string_contact, l.escapement_contact, l.check_contact, l.key_bottom_contact})
    if (c >= 0) names.push_back("felt_stiffness." + column_name(model.contacts[c].name));
  for (const Adjuster& a : model.adjusters) names.push_back("regulation_offset." + a.name);
  std::vector<EffectInfo> out;
  for (const std::string& n : names) out.push_back(describe_effect(model, n));
  return out;
}

std::string describe(const Effect& effect, const EffectInfo& info) {
  std::ostringstream out;
  out << effect.name << "=" << effect.value << " " << info.unit;
  return out.str();
}

}  // namespace pat

#include "dynamics/action_dynamics.h"

#include <algorithm>
#include <cmath>

#include "core/table_sincos.h"
#include "dynamics/contact_geometry.h"
#include "dynamics/force_laws.h"

namespace pat {

ActionDynamics::ActionDynamics(const ActionModel& model, const KeyInput* input)
    : model_(model), input_(input) {
  n_ = model.dofs();
  key_ = model.landmarks.key;
  key_prescribed_ = input && input->is_motion();
  for (int j = 0; j < n_; ++j)
    if (!(key_prescribed_ && j == key_)) free_index_.push_back(j);
  free_count_ = static_cast<int>(free_index_.size());
  // the free coordinates' tree: each one's nearest free ancestor (parents precede children)
  int free_parent[kMaxDof];
  for (int i = 0; i < free_count_; ++i) {
    free_parent[i] = -1;
    for (int j = model.bodies[free_index_[i]].parent; j >= 0 && free_parent[i] < 0;
         j = model.bodies[j].parent)
      for (int f = 0; f < i; ++f)
        if (free_index_[f] == j) free_parent[i] = f;
  }
  tree_.set_tree(free_parent, free_count_);

  bodies_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    const Body& body = model.bodies[k];
    BodyConstants& b = bodies_[k];
    b.parent = body.parent;
    b.pivot = body.pivot;
    b.arm_from_parent =
        body.parent < 0 ? Vec2(Vec2::Zero()) : Vec2(body.pivot - model.bodies[body.parent].pivot);
    b.mass = body.mass;
    b.inertia = body.inertia_com;
    b.com_offset = body.com - body.pivot;
    b.friction = body.friction;
    for (int j = k; j >= 0; j = model.bodies[j].parent) b.chain[b.chain_length++] = j;
  }
  // a mass placed on the key tip becomes part of the key (parallel-axis theorem)
  const double added = input ? input->added_mass_kg() : 0.0;
  if (added > 0.0) {
    BodyConstants& b = bodies_[key_];
    const Vec2 tip = model.landmarks.key_front;
    const Vec2 com = b.pivot + b.com_offset;
    const double m = b.mass;
    const Vec2 c = (m * com + added * tip) / (m + added);
    b.inertia += m * (com - c).squaredNorm() + added * (tip - c).squaredNorm();
    b.com_offset = c - b.pivot;
    b.mass = m + added;
  }
  key_front_offset_ = key_ >= 0 ? Vec2(model.landmarks.key_front - model.bodies[key_].pivot)
                                : model.landmarks.key_front;

  auto offset = [&](int body, const Vec2& point) -> Vec2 {
    return body < 0 ? point : Vec2(point - model.bodies[body].pivot);
  };
  for (const Contact& contact : model.contacts) {
    ContactConstants c;
    c.body_a = contact.body_a;
    c.body_b = contact.body_b;
    c.segment = contact.shape == ContactShape::CircleSegment;
    c.center_a = offset(contact.body_a, contact.center_a);
    c.radius_a = contact.radius_a;
    c.radius_b = contact.radius_b;
    if (c.segment) {
      c.start = offset(contact.body_b, contact.segment_start);
      c.direction = contact.segment_end - contact.segment_start;
      c.inverse_length2 = 1.0 / c.direction.squaredNorm();
      c.normal = contact.segment_normal;
    } else {
      c.center_b = offset(contact.body_b, contact.center_b);
    }
    contacts_.push_back(c);
  }
  for (const Strap& strap : model.straps)
    strap_rest_length_.push_back(
        (transform(strap.body_a, strap.point_a) - transform(strap.body_b, strap.point_b)).norm() +
        strap.slack);
  kin_.resize(n_);
  distances_.resize(contacts_.size());
  patches_.resize(contacts_.size());
  touching_.resize(contacts_.size());
  exact_.assign(contacts_.size(), 0);
  culls_.resize(contacts_.size());
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    // the joints on exactly one of the two chains
    auto on_chain = [&](int body, int joint) {
      if (body < 0) return false;
      const BodyConstants& b = bodies_[body];
      for (int k = 0; k < b.chain_length; ++k)
        if (b.chain[k] == joint) return true;
      return false;
    };
    ContactConstants& contact = contacts_[c];
    for (int j = 0; j < n_; ++j) {
      const bool on_a = on_chain(contact.body_a, j);
      if (on_a == on_chain(contact.body_b, j)) continue;
      contact.joint_sign[contact.joint_count] = on_a ? 1.0 : -1.0;
      contact.joints[contact.joint_count++] = j;
    }
    culls_[c].set_joints(contact.joints, contact.joint_count);
  }
  update_kinematics(DofVector::Zero(n_), DofVector::Zero(n_));  // the drawing configuration
  scratch_q_.resize(n_);
  scratch_v_.resize(n_);
  scratch_acceleration_.resize(n_);
}

void ActionDynamics::update_positions(const DofVector& q) {
  if (positions_valid_ && same_positions(q)) return;
  evaluated_ = false;
  for (int k = 0; k < n_; ++k) {
    const BodyConstants& body = bodies_[k];
    BodyKinematics& kk = kin_[k];
    if (body.parent < 0) {
      kk.angle = q[k];
      kk.origin = body.pivot;
    } else {
      const BodyKinematics& pk = kin_[body.parent];
      kk.arm_from_parent = rotate(body.arm_from_parent, pk.cos, pk.sin);
      kk.angle = pk.angle + q[k];
      kk.origin = pk.origin + kk.arm_from_parent;
    }
    table_sincos(kk.angle, kk.cos, kk.sin);
  }
  // the per-contact arrays by pointer: the flags are chars, whose stores may alias anything, and
  // would make the compiler reload every vector's data pointer after each of them
  ContactCull* const culls = culls_.data();
  ContactDistance* const distances = distances_.data();
  ContactPatch* const patches = patches_.data();
  const ContactConstants* const contacts = contacts_.data();
  char* const touching = touching_.data();
  char* const exact = exact_.data();
  const std::size_t count = contacts_.size();
  for (std::size_t c = 0; c < count; ++c) {
    double bound = 0.0;
    if (culls[c].still_open(q, bound)) {  // certainly apart: no force, no patch
      distances[c].penetration = bound;
      touching[c] = 0;
      exact[c] = 0;
      continue;
    }
    Vec2 center_a;  // the circle of A in the world, placed once for the distance and the patch
    distances[c] = contact_distance(contacts[c], center_a);
    touching[c] = patch_at(distances[c], center_a, contacts[c].radius_a, patches[c]);
    exact[c] = 1;
    if (touching[c])
      culls[c].disarm();
    else
      arm_cull(c, q, center_a);
  }
  positions_q_ = q;
  positions_valid_ = true;
}

void ActionDynamics::update_rates(const DofVector& v) {
  for (int k = 0; k < n_; ++k) {
    const int parent = bodies_[k].parent;
    BodyKinematics& kk = kin_[k];
    if (parent < 0) {
      kk.omega = v[k];
      kk.origin_velocity.setZero();
      kk.origin_bias_acceleration.setZero();
    } else {
      const BodyKinematics& pk = kin_[parent];
      const Vec2& arm = kk.arm_from_parent;
      kk.omega = pk.omega + v[k];
      kk.origin_velocity = pk.origin_velocity + pk.omega * perp(arm);
      // acceleration of a parent point with q̈ = 0: a_o − ω² r
      kk.origin_bias_acceleration = pk.origin_bias_acceleration - pk.omega * pk.omega * arm;
    }
  }
}

Vec2 ActionDynamics::transform(int body, const Vec2& rest_point) const {
  // the frame, or before the first kinematics update (the drawing configuration)
  if (body < 0 || kin_.empty()) return rest_point;
  return place(body, rest_point - bodies_[body].pivot);
}

ActionDynamics::StrapSpan ActionDynamics::strap_span(std::size_t s) const {
  const Strap& strap = model_.straps[s];
  StrapSpan span;
  span.a = transform(strap.body_a, strap.point_a);
  span.b = transform(strap.body_b, strap.point_b);
  span.length = (span.b - span.a).norm();
  span.stretch = span.length - strap_rest_length_[s];
  return span;
}

ContactDistance ActionDynamics::contact_distance(const ContactConstants& c, Vec2& center_a) const {
  center_a = place(c.body_a, c.center_a);
  if (!c.segment)
    return circle_circle_distance(center_a, c.radius_a, place(c.body_b, c.center_b), c.radius_b);
  if (c.body_b < 0)
    return circle_segment_distance(center_a, c.radius_a, c.start, c.direction, c.inverse_length2,
                                   c.normal, c.radius_b);
  // the segment is tested in B's own frame (its constants need no rotation), the normal rotated
  // back to the world
  const BodyKinematics& kb = kin_[c.body_b];
  const Vec2 local = rotate(center_a - kb.origin, kb.cos, -kb.sin);
  ContactDistance d = circle_segment_distance(local, c.radius_a, c.start, c.direction,
                                              c.inverse_length2, c.normal, c.radius_b);
  d.normal = rotate(d.normal, kb.cos, kb.sin);
  return d;
}

void ActionDynamics::arm_cull(std::size_t c, const DofVector& q, const Vec2& center_a) {
  const ContactConstants& contact = contacts_[c];
  const double gap = -distances_[c].penetration;
  double margin = gap;
  if (contact.segment) {
    // where the formula would jump (contact_geometry.h): the circle centre behind the face line
    Vec2 local = center_a;
    if (contact.body_b >= 0) {
      const BodyKinematics& kb = kin_[contact.body_b];
      local = rotate(center_a - kb.origin, kb.cos, -kb.sin);
    }
    const Vec2 rel = local - contact.start;
    const double height = contact.normal.dot(rel);
    if (height < 0.0) {
      if (contact.radius_b > 0.0) {
        margin = std::min(margin, -height);  // crossing the face line inside the segment
      } else {
        const double t = rel.dot(contact.direction) * contact.inverse_length2;
        const double length = std::sqrt(1.0 / contact.inverse_length2);
        margin = std::min(margin, (t < 0.0 ? -t : t - 1.0) * length);  // entering the span
      }
    }
  }
  // distances from each relevant pivot to the contact's points and to the other relevant pivots
  const ContactCull& cull = culls_[c];
  const Vec2 center_b = contact.segment ? center_a : place(contact.body_b, contact.center_b);
  double reach[kMaxDof];
  for (int k = 0; k < cull.joint_count(); ++k) {
    const Vec2& pivot = kin_[cull.joint(k)].origin;
    double r = std::max((center_a - pivot).norm(), (center_b - pivot).norm());
    for (int i = 0; i < cull.joint_count(); ++i)
      r = std::max(r, (kin_[cull.joint(i)].origin - pivot).norm());
    reach[k] = r;
  }
  culls_[c].arm(q, gap, margin, reach);
}

void ActionDynamics::contact_penetrations(const DofVector& q, std::vector<double>& penetration) {
  update_positions(q);
  penetration.resize(contacts_.size());
  for (std::size_t c = 0; c < contacts_.size(); ++c) penetration[c] = contact_penetration(c, q);
}

double ActionDynamics::contact_penetration(std::size_t c, const DofVector& q) {
  update_positions(q);
  if (!exact_[c]) {
    Vec2 center_a;
    distances_[c] = contact_distance(contacts_[c], center_a);
    exact_[c] = 1;
  }
  return distances_[c].penetration;
}

void ActionDynamics::contact_penetration_bounds(const DofVector& q,
                                                std::vector<double>& penetration) {
  update_positions(q);
  penetration.resize(contacts_.size());
  for (std::size_t c = 0; c < contacts_.size(); ++c) penetration[c] = distances_[c].penetration;
}

bool ActionDynamics::behind_face_end(std::size_t c, const DofVector& q) {
  const Contact& closed = model_.contacts[c];
  if (!closed.closed_start && !closed.closed_end) return false;
  const ContactConstants& contact = contacts_[c];
  update_positions(q);
  Vec2 local = place(contact.body_a, contact.center_a);
  if (contact.body_b >= 0) {
    const BodyKinematics& kb = kin_[contact.body_b];
    local = rotate(local - kb.origin, kb.cos, -kb.sin);
  }
  const Vec2 rel = local - contact.start;
  const double t = rel.dot(contact.direction) * contact.inverse_length2;
  return contact.normal.dot(rel) < 0.0 &&
         ((t < 0.0 && closed.closed_start) || (t > 1.0 && closed.closed_end));
}

void ActionDynamics::assemble(double finger, const DofVector& q, const DofVector& v,
                              std::vector<ContactReading>* readings,
                              std::vector<double>* tensions) {
  update_kinematics(q, v);
  evaluated_ = false;
  mass_.setZero();
  forces_.setZero();

  // the arrays by pointer and their sizes as locals: every store into forces_ and mass_ (doubles)
  // would otherwise make the compiler reload the vectors' data pointers and sizes
  const BodyConstants* const bodies = bodies_.data();
  const BodyKinematics* const kin = kin_.data();
  double* const forces = forces_.data();
  const int n = n_;

  // inertia, bias and gravity of each body (M: lower triangle; chains list descendants first)
  const Vec2 gravity = model_.gravity;
  for (int k = 0; k < n; ++k) {
    const BodyConstants& b = bodies[k];
    const BodyKinematics& kk = kin[k];
    const Vec2 r = rotate(b.com_offset, kk.cos, kk.sin);
    const Vec2 c = kk.origin + r;
    const Vec2 bias = kk.origin_bias_acceleration - kk.omega * kk.omega * r;
    const Vec2 load = b.mass * (gravity - bias);
    if (b.chain_length == 1) {  // a body on the frame (most of them): one joint
      const Vec2 arm = c - kk.origin;
      forces[k] += cross2(arm, load);
      mass_(k, k) += b.inertia + b.mass * arm.dot(arm);
      continue;
    }
    Vec2 arm[kMaxDof];  // c − o_i along the chain
    for (int a = 0; a < b.chain_length; ++a) {
      const int i = b.chain[a];
      arm[a] = c - kin[i].origin;
      forces[i] += cross2(arm[a], load);
    }
    for (int a = 0; a < b.chain_length; ++a) {
      for (int e = a; e < b.chain_length; ++e) {
        // chain[a] ≥ chain[e]: parents come before children
        mass_(b.chain[a], b.chain[e]) += b.inertia + b.mass * arm[a].dot(arm[e]);
      }
    }
  }

  // joint springs, joint friction, settling damping
  for (const JointSpring& spring : model_.springs)
    forces[spring.body] += spring.preload - spring.stiffness * q[spring.body];
  const double settling = settling_damping_;
  for (int k = 0; k < n; ++k) {
    forces[k] += joint_friction_torque(bodies[k].friction, v[k]);
    forces[k] -= settling * v[k];
  }

  // intermittent felt contacts
  std::uint64_t regime = 0;
  const ContactConstants* const contacts = contacts_.data();
  const ContactPatch* const patches = patches_.data();
  const char* const touching = touching_.data();
  const Contact* const laws = model_.contacts.data();
  const std::size_t count = contacts_.size();
  for (std::size_t c = 0; c < count; ++c) {
    if (!touching[c]) {
      if (readings) (*readings)[c] = ContactReading{};
      continue;
    }
    const ContactConstants& contact = contacts[c];
    const ContactPatch& patch = patches[c];
    regime |= std::uint64_t{1} << (c & 63);
    const Contact& law = laws[c];
    const Vec2 relative =
        velocity_at(contact.body_a, patch.point) - velocity_at(contact.body_b, patch.point);
    const double rate = -patch.normal.dot(relative);
    const double fn = felt_normal_force(law.law, patch.penetration, rate);
    const Vec2 tangent = perp(patch.normal);
    const double ft = friction_force(law.friction, fn, tangent.dot(relative));
    const Vec2 force = fn * patch.normal + ft * tangent;  // on A; B gets the opposite
    add_point_force(contact.body_a, patch.point, force, forces_);
    add_point_force(contact.body_b, patch.point, -force, forces_);
    if (readings) {
      ContactReading& reading = (*readings)[c];
      reading.active = true;
      reading.penetration = patch.penetration;
      reading.penetration_rate = rate;
      reading.normal_force = fn;
      reading.friction_force = ft;
      reading.point = patch.point;
      reading.normal = patch.normal;
    }
  }
  regime_ = regime;

  // tension-only straps
  for (std::size_t s = 0; s < model_.straps.size(); ++s) {
    const Strap& strap = model_.straps[s];
    const StrapSpan span = strap_span(s);
    double tension = 0.0;
    if (span.stretch > 0.0 && span.length > 1e-12) {
      const Vec2 dir = (span.b - span.a) / span.length;
      const double rate =
          dir.dot(velocity_at(strap.body_b, span.b) - velocity_at(strap.body_a, span.a));
      tension = std::max(strap.stiffness * span.stretch + strap.damping * rate, 0.0);
      add_point_force(strap.body_a, span.a, tension * dir, forces_);
      add_point_force(strap.body_b, span.b, -tension * dir, forces_);
    }
    if (tensions) (*tensions)[s] = tension;
  }

  // the finger force at the key front
  if (finger != 0.0)
    add_point_force(key_, place(key_, key_front_offset_), Vec2(0.0, -finger), forces_);
}

void ActionDynamics::remember_evaluation(double finger, const DofVector& v,
                                         const DofVector& acceleration) {
  if (key_prescribed_ || !factor_valid_) return;
  evaluated_ = true;
  evaluated_finger_ = finger;
  evaluated_v_ = v;
  evaluated_acceleration_ = acceleration;
}

DofMatrix ActionDynamics::assembled_mass() const {
  DofMatrix mass(n_, n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) mass(i, j) = mass_entry(i, j);
  return mass;
}

void ActionDynamics::expand(double t, const StateVector& y, DofVector& q, DofVector& v) const {
  q.resize(n_);
  v.resize(n_);
  const int* const free_index = free_index_.data();  // not reloaded after each store below
  const int free_count = free_count_;
  for (int i = 0; i < free_count; ++i) {
    q[free_index[i]] = y[i];
    v[free_index[i]] = y[free_count + i];
  }
  if (key_prescribed_) {
    const KeyMotionSample m = input_->motion(t);
    q[key_] = key_rest_angle_ + m.angle;
    v[key_] = m.rate;
  }
}

StateVector ActionDynamics::compress(const DofVector& q, const DofVector& v) const {
  StateVector y(2 * free_count_);
  for (int i = 0; i < free_count_; ++i) {
    y[i] = q[free_index_[i]];
    y[free_count_ + i] = v[free_index_[i]];
  }
  return y;
}

void ActionDynamics::rhs(double t, const StateVector& y, StateVector& dydt) {
  expand(t, y, scratch_q_, scratch_v_);
  const double finger = applied_force(t);
  if (evaluated_) update_positions(scratch_q_);  // clears evaluated_ if q differs
  if (evaluated_ && finger == evaluated_finger_ &&
      (scratch_v_.array() == evaluated_v_.array()).all()) {
    scratch_acceleration_ = evaluated_acceleration_;  // the same inputs: the same result
  } else {
    assemble(finger, scratch_q_, scratch_v_, nullptr, nullptr);
    solve_accelerations(t, scratch_acceleration_);
  }
  const int* const free_index = free_index_.data();
  const int free_count = free_count_;
  dydt.resize(2 * free_count);
  for (int i = 0; i < free_count; ++i) {
    dydt[i] = y[free_count + i];
    dydt[free_count + i] = scratch_acceleration_[free_index[i]];
  }
}

void ActionDynamics::solve_accelerations(double t, DofVector& acceleration) {
  acceleration.resize(n_);
  // factor a copy of the tree entries: mass_ stays whole for evaluate()'s key residual
  SmallVector rhs;
  double key_acc = 0.0;
  if (key_prescribed_) key_acc = input_->motion(t).acceleration;  // M_ff q̈_f = f_f − M_fk q̈_k
  const int* const free_index = free_index_.data();  // not reloaded after each store below
  const int free_count = free_count_;
  for (int i = 0; i < free_count; ++i) {
    const int ji = free_index[i];
    rhs[i] = key_prescribed_ ? forces_[ji] - mass_entry(ji, key_) * key_acc : forces_[ji];
    factor_(i, i) = mass_(ji, ji);
    for (int j = tree_.parent(i); j >= 0; j = tree_.parent(j))
      factor_(i, j) = mass_(ji, free_index[j]);
  }
  // a non-positive-definite M (never for a valid model) gives NaN, which the integrators report
  // as a failure
  factor_valid_ = tree_.solve_in_place(factor_, rhs);
  if (!factor_valid_) rhs.setConstant(std::nan(""));
  for (int i = 0; i < free_count; ++i) acceleration[free_index[i]] = rhs[i];
  if (key_prescribed_) acceleration[key_] = key_acc;
}

void ActionDynamics::evaluate(double t, const DofVector& q, const DofVector& v,
                              DynamicsReading& out) {
  out.contacts.resize(model_.contacts.size());
  out.strap_tension.resize(model_.straps.size());
  const double finger = applied_force(t);
  assemble(finger, q, v, &out.contacts, &out.strap_tension);
  // lever arm of a downward finger force at the key front
  const Vec2 front = place(key_, key_front_offset_);
  const double arm = cross2(front - kin_[key_].origin, Vec2(0.0, -1.0));
  solve_accelerations(t, out.acceleration);
  remember_evaluation(finger, v, out.acceleration);
  if (!key_prescribed_) {
    if (!input_) {
      out.finger_force = 0.0;
    } else if (input_->added_mass_kg() > 0.0) {
      // the force the mass exerts on the key: m (g − downward acceleration of the key front)
      out.finger_force = input_->added_mass_kg() * (kGravity - arm * out.acceleration[key_]);
    } else {
      out.finger_force = finger;
    }
    return;
  }
  // the finger supplies what the key's own equation lacks
  double residual = -forces_[key_];
  for (int j = 0; j < n_; ++j) residual += mass_entry(key_, j) * out.acceleration[j];
  out.finger_force = residual / arm;
}

DofMatrix ActionDynamics::mass_matrix(const DofVector& q) {
  const DofVector v = DofVector::Zero(n_);
  assemble(0.0, q, v, nullptr, nullptr);  // M does not depend on the finger
  return assembled_mass();
}

Vec2 ActionDynamics::point_position(int body, const Vec2& rest_point, const DofVector& q) {
  update_positions(q);
  return transform(body, rest_point);
}

Vec2 ActionDynamics::point_velocity(int body, const Vec2& rest_point, const DofVector& q,
                                    const DofVector& v) {
  update_kinematics(q, v);
  return velocity_at(body, transform(body, rest_point));
}

double ActionDynamics::hammer_string_gap(const DofVector& q) {
  const ActionLandmarks& l = model_.landmarks;
  const Vec2 strike = point_position(l.hammer, l.strike_point, q);
  return l.string_normal.dot(strike - l.string_point);
}

double ActionDynamics::mechanical_energy(const DofVector& q, const DofVector& v) {
  const DofMatrix mass = mass_matrix(q);  // also updates the kinematics at q
  double energy = 0.5 * v.dot(mass * v);
  for (int k = 0; k < n_; ++k) {
    const Vec2 c = place(k, bodies_[k].com_offset);
    energy -= bodies_[k].mass * model_.gravity.dot(c);
  }
  for (const JointSpring& spring : model_.springs)
    energy +=
        0.5 * spring.stiffness * q[spring.body] * q[spring.body] - spring.preload * q[spring.body];
  // a taut strap stores ½ k (L − L0)² (its damping only dissipates)
  for (std::size_t s = 0; s < model_.straps.size(); ++s) {
    const double stretch = strap_span(s).stretch;
    if (stretch > 0.0) energy += 0.5 * model_.straps[s].stiffness * stretch * stretch;
  }
  return energy;
}

}  // namespace pat

#include "dynamics/action_dynamics.h"

#include <cmath>

#include "dynamics/contact_geometry.h"
#include "dynamics/force_laws.h"
#include "dynamics/small_cholesky.h"

namespace pat {
namespace {

/// Accelerations from M a = f; a non-positive-definite M (never for a valid model) gives NaN,
/// which the integrators report as a failure.
void solve_or_nan(DofMatrix& mass, DofVector& forces) {
  if (!cholesky_solve_in_place(mass, forces)) forces.setConstant(std::nan(""));
}

}  // namespace

ActionDynamics::ActionDynamics(const ActionModel& model, const KeyInput* input)
    : model_(model), input_(input) {
  n_ = model.dofs();
  key_ = model.landmarks.key;
  key_prescribed_ = input && input->is_motion();
  for (int j = 0; j < n_; ++j)
    if (!(key_prescribed_ && j == key_)) free_index_.push_back(j);
  free_count_ = static_cast<int>(free_index_.size());

  chain_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    for (int j = k; j >= 0; j = model.bodies[j].parent) chain_[k].push_back(j);
  }
  mass_.resize(n_);
  com_.resize(n_);
  inertia_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    mass_[k] = model.bodies[k].mass;
    com_[k] = model.bodies[k].com;
    inertia_[k] = model.bodies[k].inertia_com;
  }
  // a mass placed on the key tip becomes part of the key (parallel-axis theorem)
  const double added = input ? input->added_mass_kg() : 0.0;
  if (added > 0.0) {
    const Vec2 tip = model.landmarks.key_front;
    const double m = mass_[key_];
    const Vec2 c = (m * com_[key_] + added * tip) / (m + added);
    inertia_[key_] += m * (com_[key_] - c).squaredNorm() + added * (tip - c).squaredNorm();
    com_[key_] = c;
    mass_[key_] = m + added;
  }
  for (const Strap& strap : model.straps)
    strap_rest_length_.push_back(
        (transform(strap.body_a, strap.point_a) - transform(strap.body_b, strap.point_b)).norm() +
        strap.slack);
  kin_.resize(n_);
  scratch_mass_.resize(n_, n_);
  scratch_forces_.resize(n_);
  scratch_q_.resize(n_);
  scratch_v_.resize(n_);
}

void ActionDynamics::update_kinematics(const DofVector& q, const DofVector& v) {
  for (int k = 0; k < n_; ++k) {
    const Body& body = model_.bodies[k];
    BodyKinematics& kk = kin_[k];
    if (body.parent < 0) {
      kk.angle = q[k];
      kk.omega = v[k];
      kk.origin = body.pivot;
      kk.origin_velocity.setZero();
      kk.origin_bias_acceleration.setZero();
    } else {
      const BodyKinematics& pk = kin_[body.parent];
      const Vec2 arm = rotate(body.pivot - model_.bodies[body.parent].pivot, pk.cos, pk.sin);
      kk.angle = pk.angle + q[k];
      kk.omega = pk.omega + v[k];
      kk.origin = pk.origin + arm;
      kk.origin_velocity = pk.origin_velocity + pk.omega * perp(arm);
      // acceleration of a parent point with q̈ = 0: a_o − ω² r
      kk.origin_bias_acceleration = pk.origin_bias_acceleration - pk.omega * pk.omega * arm;
    }
    kk.cos = std::cos(kk.angle);
    kk.sin = std::sin(kk.angle);
  }
}

Vec2 ActionDynamics::transform(int body, const Vec2& rest_point) const {
  // the frame, or before the first kinematics update (the drawing configuration)
  if (body < 0 || kin_.empty()) return rest_point;
  const BodyKinematics& k = kin_[body];
  return k.origin + rotate(rest_point - model_.bodies[body].pivot, k.cos, k.sin);
}

Vec2 ActionDynamics::velocity_at(int body, const Vec2& world_point) const {
  if (body < 0) return Vec2::Zero();
  const BodyKinematics& k = kin_[body];
  return k.origin_velocity + k.omega * perp(world_point - k.origin);
}

void ActionDynamics::add_point_force(int body, const Vec2& point, const Vec2& force,
                                     DofVector& generalized) const {
  if (body < 0) return;
  for (int j : chain_[body]) generalized[j] += cross2(point - kin_[j].origin, force);
}

void ActionDynamics::applied_key_force(double t, const DofVector& q, DofVector& forces) const {
  (void)q;
  if (!input_ || input_->is_motion()) return;
  const double f = input_->force_n(t);
  if (f != 0.0)
    add_point_force(key_, transform(key_, model_.landmarks.key_front), Vec2(0.0, -f), forces);
}

Vec2 ActionDynamics::segment_normal(const Contact& contact) const {
  return contact.body_b < 0
             ? contact.segment_normal
             : rotate(contact.segment_normal, kin_[contact.body_b].cos, kin_[contact.body_b].sin);
}

bool ActionDynamics::contact_patch(const Contact& contact, ContactPatch& patch) const {
  const Vec2 center_a = transform(contact.body_a, contact.center_a);
  if (contact.shape == ContactShape::CircleCircle)
    return circle_circle_patch(center_a, contact.radius_a,
                               transform(contact.body_b, contact.center_b), contact.radius_b,
                               patch);
  return circle_segment_patch(center_a, contact.radius_a,
                              transform(contact.body_b, contact.segment_start),
                              transform(contact.body_b, contact.segment_end),
                              segment_normal(contact), contact.radius_b, patch);
}

void ActionDynamics::contact_penetrations(const DofVector& q, std::vector<double>& penetration) {
  update_kinematics(q, DofVector::Zero(n_));
  penetration.resize(model_.contacts.size());
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const Contact& contact = model_.contacts[c];
    const Vec2 center_a = transform(contact.body_a, contact.center_a);
    penetration[c] =
        contact.shape == ContactShape::CircleCircle
            ? circle_circle_penetration(center_a, contact.radius_a,
                                        transform(contact.body_b, contact.center_b),
                                        contact.radius_b)
            : circle_segment_penetration(center_a, contact.radius_a,
                                         transform(contact.body_b, contact.segment_start),
                                         transform(contact.body_b, contact.segment_end),
                                         segment_normal(contact), contact.radius_b);
  }
}

void ActionDynamics::assemble(double t, const DofVector& q, const DofVector& v, DofMatrix& mass,
                              DofVector& forces, std::vector<ContactReading>* readings,
                              std::vector<double>* tensions) {
  update_kinematics(q, v);
  mass.setZero(n_, n_);
  forces.setZero(n_);

  // inertia, bias and gravity of each body
  for (int k = 0; k < n_; ++k) {
    const BodyKinematics& kk = kin_[k];
    const Vec2 r = rotate(com_[k] - model_.bodies[k].pivot, kk.cos, kk.sin);
    const Vec2 c = kk.origin + r;
    const Vec2 bias = kk.origin_bias_acceleration - kk.omega * kk.omega * r;
    const Vec2 load = mass_[k] * (model_.gravity - bias);
    for (int i : chain_[k]) {
      const Vec2 ri = c - kin_[i].origin;
      forces[i] += cross2(ri, load);
      for (int j : chain_[k]) mass(i, j) += inertia_[k] + mass_[k] * ri.dot(c - kin_[j].origin);
    }
  }

  // joint springs, joint friction, settling damping
  for (const JointSpring& spring : model_.springs)
    forces[spring.body] += spring.preload - spring.stiffness * q[spring.body];
  for (int k = 0; k < n_; ++k) {
    forces[k] += joint_friction_torque(model_.bodies[k].friction, v[k]);
    forces[k] -= settling_damping_ * v[k];
  }

  // intermittent felt contacts
  regime_ = 0;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const Contact& contact = model_.contacts[c];
    ContactPatch patch;
    const bool touching = contact_patch(contact, patch);
    if (!touching) {
      if (readings) (*readings)[c] = ContactReading{};
      continue;
    }
    regime_ |= std::uint64_t{1} << (c & 63);
    const Vec2 relative =
        velocity_at(contact.body_a, patch.point) - velocity_at(contact.body_b, patch.point);
    const double rate = -patch.normal.dot(relative);
    const double fn = felt_normal_force(contact.law, patch.penetration, rate);
    const Vec2 tangent = perp(patch.normal);
    const double ft = friction_force(contact.friction, fn, tangent.dot(relative));
    const Vec2 force = fn * patch.normal + ft * tangent;  // on A; B gets the opposite
    add_point_force(contact.body_a, patch.point, force, forces);
    add_point_force(contact.body_b, patch.point, -force, forces);
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

  // tension-only straps
  for (std::size_t s = 0; s < model_.straps.size(); ++s) {
    const Strap& strap = model_.straps[s];
    const Vec2 pa = transform(strap.body_a, strap.point_a);
    const Vec2 pb = transform(strap.body_b, strap.point_b);
    const Vec2 d = pb - pa;
    const double length = d.norm();
    double tension = 0.0;
    if (length > strap_rest_length_[s] && length > 1e-12) {
      const Vec2 dir = d / length;
      const double rate = dir.dot(velocity_at(strap.body_b, pb) - velocity_at(strap.body_a, pa));
      tension =
          std::max(strap.stiffness * (length - strap_rest_length_[s]) + strap.damping * rate, 0.0);
      add_point_force(strap.body_a, pa, tension * dir, forces);
      add_point_force(strap.body_b, pb, -tension * dir, forces);
    }
    if (tensions) (*tensions)[s] = tension;
  }

  applied_key_force(t, q, forces);
}

void ActionDynamics::expand(double t, const StateVector& y, DofVector& q, DofVector& v) const {
  q.resize(n_);
  v.resize(n_);
  for (int i = 0; i < free_count_; ++i) {
    q[free_index_[i]] = y[i];
    v[free_index_[i]] = y[free_count_ + i];
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
  assemble(t, scratch_q_, scratch_v_, scratch_mass_, scratch_forces_, nullptr, nullptr);
  solve_accelerations(t, scratch_mass_, scratch_forces_, scratch_acceleration_);
  dydt.resize(2 * free_count_);
  dydt.head(free_count_) = y.tail(free_count_);
  for (int i = 0; i < free_count_; ++i)
    dydt[free_count_ + i] = scratch_acceleration_[free_index_[i]];
}

void ActionDynamics::solve_accelerations(double t, const DofMatrix& mass, const DofVector& forces,
                                         DofVector& acceleration) const {
  acceleration.resize(n_);
  if (!key_prescribed_) {
    DofMatrix factor = mass;
    acceleration = forces;
    solve_or_nan(factor, acceleration);
    return;
  }
  // prescribed key: M_ff q̈_f = f_f − M_fk q̈_k
  const double key_acc = input_->motion(t).acceleration;
  DofMatrix mff(free_count_, free_count_);
  DofVector acc_f(free_count_);
  for (int i = 0; i < free_count_; ++i) {
    const int ji = free_index_[i];
    acc_f[i] = forces[ji] - mass(ji, key_) * key_acc;
    for (int j = 0; j < free_count_; ++j) mff(i, j) = mass(ji, free_index_[j]);
  }
  solve_or_nan(mff, acc_f);
  for (int i = 0; i < free_count_; ++i) acceleration[free_index_[i]] = acc_f[i];
  acceleration[key_] = key_acc;
}

void ActionDynamics::evaluate(double t, const DofVector& q, const DofVector& v,
                              DynamicsReading& out) {
  out.contacts.resize(model_.contacts.size());
  out.strap_tension.resize(model_.straps.size());
  DofMatrix mass;
  DofVector forces;
  assemble(t, q, v, mass, forces, &out.contacts, &out.strap_tension);
  // lever arm of a downward finger force at the key front
  const Vec2 front = transform(key_, model_.landmarks.key_front);
  const double arm = cross2(front - kin_[key_].origin, Vec2(0.0, -1.0));
  solve_accelerations(t, mass, forces, out.acceleration);
  if (!key_prescribed_) {
    if (!input_) {
      out.finger_force = 0.0;
    } else if (input_->added_mass_kg() > 0.0) {
      // the force the mass exerts on the key: m (g − downward acceleration of the key front)
      out.finger_force = input_->added_mass_kg() * (kGravity - arm * out.acceleration[key_]);
    } else {
      out.finger_force = input_->force_n(t);
    }
    return;
  }
  // the finger supplies what the key's own equation lacks
  const double residual = mass.row(key_).dot(out.acceleration) - forces[key_];
  out.finger_force = residual / arm;
}

DofMatrix ActionDynamics::mass_matrix(const DofVector& q) {
  DofVector v = DofVector::Zero(n_);
  DofMatrix mass;
  DofVector forces;
  assemble(0.0, q, v, mass, forces, nullptr, nullptr);
  return mass;
}

Vec2 ActionDynamics::point_position(int body, const Vec2& rest_point, const DofVector& q) {
  update_kinematics(q, DofVector::Zero(n_));
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
    const Vec2 c = transform(k, com_[k]);
    energy -= mass_[k] * model_.gravity.dot(c);
  }
  for (const JointSpring& spring : model_.springs)
    energy +=
        0.5 * spring.stiffness * q[spring.body] * q[spring.body] - spring.preload * q[spring.body];
  return energy;
}

}  // namespace pat

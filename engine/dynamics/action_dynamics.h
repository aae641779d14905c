// Equations of motion of a planar tree of rigid bodies on revolute joints, in relative joint
// coordinates (paper section 3.1; numerics.md section 5):
//
//   M(q) q̈ + c(q, q̇) = Q(q, q̇, t)
//
//   M_ij = Σ_{k ∈ desc(i) ∩ desc(j)} [ I_k + m_k (c_k − o_i)·(c_k − o_j) ]
//   c    = Σ_k J_kᵀ m_k a⁰_k       (a⁰_k: centre-of-mass acceleration at q̈ = 0)
//   Q    = gravity + felt contacts (with friction) + joint springs + joint friction + straps
//          + the key input (a force at the key front, or a point mass on it).
//
// With a motion input the key angle is prescribed (rheonomic): the key is removed from the
// integrated state, M_ff q̈_f = (Q − c)_f − M_fk q̈_k, and the finger force is the key row's
// residual (M q̈ + c − Q)_k divided by the key-front lever arm.
//
// Integrated state y = (q_f, q̇_f) of the free coordinates (all of them with a force input).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamics/contact_geometry.h"
#include "inputs/key_input.h"
#include "integrators/ode_system.h"
#include "model/action_model.h"

namespace pat {

/// What a contact does at one instant.
struct ContactReading {
  bool active = false;
  double penetration = 0.0;       ///< m
  double penetration_rate = 0.0;  ///< m/s
  double normal_force = 0.0;      ///< N
  double friction_force = 0.0;    ///< N, along the tangent ẑ × n
  Vec2 point = Vec2::Zero();      ///< m
  Vec2 normal = Vec2(0.0, 1.0);
};

/// Everything evaluated at one (t, q, q̇).
struct DynamicsReading {
  DofVector acceleration;     ///< q̈ of every joint (prescribed key included)
  double finger_force = 0.0;  ///< downward force at the key front, N
  std::vector<ContactReading> contacts;
  std::vector<double> strap_tension;  ///< N
};

class ActionDynamics : public OdeSystem {
 public:
  /// `input` may be null (the action at rest, no finger). Both must outlive this object.
  ActionDynamics(const ActionModel& model, const KeyInput* input);

  int dimension() const override { return 2 * free_count_; }
  int dofs() const override { return free_count_; }
  void rhs(double t, const StateVector& y, StateVector& dydt) override;
  std::uint64_t regime() const override { return regime_; }

  /// Extra viscous joint damping (N·m·s/rad) used only to settle the action to rest.
  void set_settling_damping(double damping) { settling_damping_ = damping; }

  const ActionModel& model() const { return model_; }
  bool key_prescribed() const { return key_prescribed_; }
  /// Joint coordinates relative to which a prescribed key angle is measured (the rest state).
  void set_key_rest_angle(double angle) { key_rest_angle_ = angle; }

  /// Full joint coordinates and rates from an integrated state at time t.
  void expand(double t, const StateVector& y, DofVector& q, DofVector& v) const;
  /// Integrated state from full coordinates (drops the key when it is prescribed).
  StateVector compress(const DofVector& q, const DofVector& v) const;

  /// Evaluates accelerations, contact readings and the finger force at full (q, q̇).
  void evaluate(double t, const DofVector& q, const DofVector& v, DynamicsReading& out);

  /// Signed contact penetrations at q (m): > 0 overlap, < 0 minus the gap still open. Geometry
  /// only: cheap enough to call after every step for events, the unphysical-penetration check
  /// and the technician's gap measurements.
  void contact_penetrations(const DofVector& q, std::vector<double>& penetration);

  /// Mass matrix at q (the point mass of a mass input included).
  DofMatrix mass_matrix(const DofVector& q);

  /// Position (m) of a point given at rest on body `body` (-1: the frame), at q.
  Vec2 point_position(int body, const Vec2& rest_point, const DofVector& q);
  /// Velocity (m/s) of that point at (q, q̇).
  Vec2 point_velocity(int body, const Vec2& rest_point, const DofVector& q, const DofVector& v);

  /// Hammer–string gap (m) at q: distance of the strike point from the string plane.
  double hammer_string_gap(const DofVector& q);

  /// Kinetic + gravitational potential + spring energy (J), for conservation tests.
  double mechanical_energy(const DofVector& q, const DofVector& v);

 private:
  struct BodyKinematics {
    double angle = 0.0, cos = 1.0, sin = 0.0, omega = 0.0;
    Vec2 origin, origin_velocity, origin_bias_acceleration;
  };
  void update_kinematics(const DofVector& q, const DofVector& v);
  Vec2 transform(int body, const Vec2& rest_point) const;
  Vec2 velocity_at(int body, const Vec2& world_point) const;
  /// Adds the generalized force of a force F applied at world point P of `body`.
  void add_point_force(int body, const Vec2& point, const Vec2& force,
                       DofVector& generalized) const;
  void assemble(double t, const DofVector& q, const DofVector& v, DofMatrix& mass,
                DofVector& forces, std::vector<ContactReading>* readings,
                std::vector<double>* tensions);
  void applied_key_force(double t, const DofVector& q, DofVector& forces) const;
  /// q̈ of every joint from the assembled M and forces (prescribed key included).
  void solve_accelerations(double t, const DofMatrix& mass, const DofVector& forces,
                           DofVector& acceleration) const;
  /// Unit normal of a segment contact's face in the world, at the current kinematics.
  Vec2 segment_normal(const Contact& contact) const;
  /// Geometry of contact c at the current kinematics; false when apart.
  bool contact_patch(const Contact& contact, ContactPatch& patch) const;

  const ActionModel& model_;
  const KeyInput* input_;
  int n_ = 0;
  int key_ = 0;
  bool key_prescribed_ = false;
  int free_count_ = 0;
  std::vector<int> free_index_;          // integrated coordinate → joint
  std::vector<std::vector<int>> chain_;  // ancestors of each body, itself included
  // mass properties with a mass input folded into the key
  std::vector<double> mass_;
  std::vector<Vec2> com_;
  std::vector<double> inertia_;
  std::vector<double> strap_rest_length_;
  std::vector<BodyKinematics> kin_;
  double settling_damping_ = 0.0;
  double key_rest_angle_ = 0.0;
  std::uint64_t regime_ = 0;
  // scratch, so that rhs() does not allocate
  DofMatrix scratch_mass_;
  DofVector scratch_forces_, scratch_q_, scratch_v_, scratch_acceleration_;
};

}  // namespace pat

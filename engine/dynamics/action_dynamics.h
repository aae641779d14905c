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

#include "dynamics/contact_cull.h"
#include "dynamics/contact_geometry.h"
#include "dynamics/tree_ldl.h"
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
  /// `input` may be null (the action at rest, no finger). Both must outlive this object, and the
  /// model must not change while it lives (its geometry is precomputed here).
  ActionDynamics(const ActionModel& model, const KeyInput* input);

  int dimension() const override { return 2 * free_count_; }
  int dofs() const override { return free_count_; }
  void rhs(double t, const StateVector& y, StateVector& dydt) override;
  std::uint64_t regime() const override { return regime_; }
  /// A_v ≈ ∂q̈_f/∂q̇_f at the latest rhs() state: M_ff⁻¹ K_v with K_v = ∂Q/∂q̇ of the joint
  /// friction, the settling damping, the felts' hysteresis, the contact friction and the strap
  /// damping (closed forms, force_laws.h); the velocity-dependent inertia terms (−∂c/∂q̇, not
  /// stiff) are left out, which a W-method allows. A few hundred operations, against dofs()
  /// evaluations for the finite differences. False if M was not positive definite.
  bool velocity_jacobian(StateMatrix& jacobian) override;

  /// Extra viscous joint damping (N·m·s/rad) used only to settle the action to rest.
  void set_settling_damping(double damping) {
    settling_damping_ = damping;
    evaluated_ = false;
  }

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
  /// only (memoized with the positions): cheap enough to call after every step for events, the
  /// unphysical-penetration check and the technician's gap measurements.
  void contact_penetrations(const DofVector& q, std::vector<double>& penetration);
  /// The same where a contact may touch; where it is certainly apart (contact_cull.h), an upper
  /// bound of its penetration instead (negative, m). Enough for what needs the signs only (events,
  /// the unphysical-penetration check), and cheaper.
  void contact_penetration_bounds(const DofVector& q, std::vector<double>& penetration);
  /// Contact c's signed penetration at q (m), exact even where contact_penetration_bounds gives
  /// a bound: for the one contact whose distance near zero matters (the key's bottom).
  double contact_penetration(std::size_t c, const DofVector& q);
  /// Whether contact c's circle lies behind the line of B's face (m·(p − s0) < 0) beyond one of
  /// the face's closed ends (t* < 0 with closed_start, t* > 1 with closed_end), at q. A circle
  /// pressed into the face that ends up there has gone round an end that A's body cannot pass
  /// without crossing B (action_model.h); the model has no contact for what meets then (A's
  /// flank, B's corner), so the simulator stops the run there.
  bool behind_face_end(std::size_t c, const DofVector& q);

  /// Mass matrix at q (the point mass of a mass input included).
  DofMatrix mass_matrix(const DofVector& q);

  /// Position (m) of a point given at rest on body `body` (-1: the frame), at q.
  Vec2 point_position(int body, const Vec2& rest_point, const DofVector& q);
  /// Velocity (m/s) of that point at (q, q̇).
  Vec2 point_velocity(int body, const Vec2& rest_point, const DofVector& q, const DofVector& v);

  /// Hammer–string gap (m) at q: distance of the strike point from the string plane.
  double hammer_string_gap(const DofVector& q);

  /// Kinetic + gravitational potential + joint-spring and taut-strap energy (J), for
  /// conservation tests (felt contacts and friction are left out).
  double mechanical_energy(const DofVector& q, const DofVector& v);

 private:
  /// Constants of one body, precomputed at construction. Offsets are from the body's pivot at
  /// the drawing configuration q = 0 (a point's world position is origin + R(θ) offset).
  struct BodyConstants {
    int parent = -1;
    Vec2 pivot;            ///< m, at q = 0
    Vec2 arm_from_parent;  ///< pivot − parent pivot, m (zero for a body on the frame)
    Vec2 com_offset;       ///< centre of mass − pivot, m
    double mass = 0.0, inertia = 0.0;
    JointFriction friction;
    int chain_length = 0;
    int chain[kMaxDof] = {};  ///< the body itself, then its ancestors
  };
  /// Constants of one contact, with its features as offsets on their bodies (world points for
  /// the frame). A segment on B is tested in B's own frame:  p = Rᵦᵀ (c_A − o_B),
  /// t* = (p − s0)·u / |u|², x = r_A − m·(p − s0) inside [0, 1], else the rounded corner
  /// (contact_geometry.h).
  struct ContactConstants {
    int body_a = -1, body_b = -1;
    bool segment = true;
    Vec2 center_a = Vec2::Zero();  ///< circle of A
    double radius_a = 0.0;
    Vec2 center_b = Vec2::Zero();  ///< circle of B (circle–circle)
    double radius_b = 0.0;         ///< circle of B, or the corner radius ρ of a segment
    /// segment s0, u = s1 − s0, unit normal m (B's frame)
    Vec2 start = Vec2::Zero(), direction = Vec2::Zero(), normal = Vec2::Zero();
    double inverse_length2 = 0.0;  ///< 1 / |u|², 1/m²
    /// The joints that move one body and not the other, ascending, with +1 where the joint is on
    /// A's chain and −1 on B's: the relative velocity v_A(P) − v_B(P) depends on these rates only.
    int joint_count = 0;
    int joints[kMaxDof] = {};
    double joint_sign[kMaxDof] = {};
  };
  struct BodyKinematics {
    double angle = 0.0, cos = 1.0, sin = 0.0, omega = 0.0;
    Vec2 origin = Vec2::Zero(), arm_from_parent = Vec2::Zero();  ///< world, m
    Vec2 origin_velocity = Vec2::Zero(), origin_bias_acceleration = Vec2::Zero();
  };
  /// Body positions and contact geometry at q. Memoized: a call with the same q as the previous
  /// one (bit for bit) does nothing. That is exact, and it saves the sines, cosines and contact
  /// geometry of the Jacobian's velocity columns and of a step-end penetration pass followed by
  /// the next step's first evaluation.
  void update_positions(const DofVector& q);
  /// q equals the memoized positions_q_ (a plain loop that stops at the first difference: it
  /// runs on every evaluation).
  bool same_positions(const DofVector& q) const {
    if (positions_q_.size() != q.size()) return false;
    for (Eigen::Index i = 0; i < q.size(); ++i)
      if (positions_q_[i] != q[i]) return false;
    return true;
  }
  /// Body rates at q̇ (after update_positions).
  void update_rates(const DofVector& v);
  void update_kinematics(const DofVector& q, const DofVector& v) {
    update_positions(q);
    update_rates(v);
  }
  Vec2 transform(int body, const Vec2& rest_point) const;
  /// Strap s at the current positions: its end points (world, m), length and stretch L − L0 (m,
  /// > 0 taut).
  struct StrapSpan {
    Vec2 a, b;
    double length = 0.0, stretch = 0.0;
  };
  StrapSpan strap_span(std::size_t s) const;
  /// World position of a point given as an offset from the body's pivot (frame: world point).
  Vec2 place(int body, const Vec2& offset) const {
    if (body < 0) return offset;
    const BodyKinematics& k = kin_[body];
    return k.origin + rotate(offset, k.cos, k.sin);
  }
  Vec2 velocity_at(int body, const Vec2& world_point) const {
    if (body < 0) return Vec2::Zero();
    const BodyKinematics& k = kin_[body];
    return k.origin_velocity + k.omega * perp(world_point - k.origin);
  }
  /// Adds the generalized force of a force F applied at world point P of `body`.
  void add_point_force(int body, const Vec2& point, const Vec2& force,
                       SmallVector& generalized) const {
    if (body < 0) return;
    const BodyConstants& b = bodies_[body];
    const BodyKinematics* const kin = kin_.data();  // not reloaded after each store below
    for (int c = 0; c < b.chain_length; ++c) {
      const int j = b.chain[c];
      generalized[j] += cross2(point - kin[j].origin, force);
    }
  }
  /// Adds ∂(v_A(P) − v_B(P))/∂q̇ (a = body_a, b = body_b; P a world point) to the rows gx, gy.
  void add_relative_velocity_rows(int body_a, int body_b, const Vec2& point, SmallVector& gx,
                                  SmallVector& gy) const;
  /// Downward finger force (N) at the key front at time t: the force input's, else 0.
  double applied_force(double t) const {
    return input_ && !input_->is_motion() ? input_->force_n(t) : 0.0;
  }
  /// Fills mass_ and forces_ at (q, q̇) with the applied finger force `finger` (N, the only
  /// explicit time dependence of a force-driven action); readings and tensions may be null.
  void assemble(double finger, const DofVector& q, const DofVector& v,
                std::vector<ContactReading>* readings, std::vector<double>* tensions);
  /// Records evaluate()'s accelerations at (q̇, finger) for rhs() to reuse (force inputs only:
  /// with a prescribed key the motion's time enters too).
  void remember_evaluation(double finger, const DofVector& v, const DofVector& acceleration);
  /// q̈ of every joint from mass_ and forces_ (prescribed key included).
  void solve_accelerations(double t, DofVector& acceleration);
  /// Signed distance and normal of a contact at the current positions; `center_a` receives the
  /// world position of A's circle (the patch needs it too).
  ContactDistance contact_distance(const ContactConstants& contact, Vec2& center_a) const;
  /// Arms contact c's cull after its distance was found open at q (A's circle at center_a).
  void arm_cull(std::size_t c, const DofVector& q, const Vec2& center_a);
  DofMatrix assembled_mass() const;
  /// M_ij of the assembled (lower-triangle) mass matrix.
  double mass_entry(int i, int j) const { return i >= j ? mass_(i, j) : mass_(j, i); }

  const ActionModel& model_;
  const KeyInput* input_;
  int n_ = 0;
  int key_ = 0;
  bool key_prescribed_ = false;
  int free_count_ = 0;
  std::vector<int> free_index_;  // integrated coordinate → joint
  // bodies with a mass input folded into the key, contacts and straps in body frames
  std::vector<BodyConstants> bodies_;
  std::vector<ContactConstants> contacts_;
  std::vector<double> strap_rest_length_;
  Vec2 key_front_offset_;
  std::vector<BodyKinematics> kin_;
  // memo of update_positions(): its q, and the contact patches there
  DofVector positions_q_;
  bool positions_valid_ = false;
  std::vector<ContactDistance> distances_;  // signed, every contact (bounds where culled)
  std::vector<ContactCull> culls_;          // per contact: the certified "still apart" test
  std::vector<char> exact_;                 // distances_[c] computed, not bounded
  std::vector<ContactPatch> patches_;
  std::vector<char> touching_;
  double settling_damping_ = 0.0;
  double key_rest_angle_ = 0.0;
  std::uint64_t regime_ = 0;
  // assembled M (lower triangle only: read it through mass_entry) and forces Q − c
  SmallMatrix mass_ = SmallMatrix::Zero();
  SmallVector forces_ = SmallVector::Zero();
  // the free coordinates' tree and the factor of M_ff on it (scratch of solve_accelerations)
  TreeLdl tree_;
  SmallMatrix factor_ = SmallMatrix::Zero();
  bool factor_valid_ = false;  // factor_ holds the factor of the latest assembled M_ff
  // evaluate()'s assembly and solve, at the memoized positions: a trace sample at a step end
  // followed by the next step's f(t, y) at the same state evaluates once. Cleared by a new
  // position update, a new assembly, or a change of the settling damping.
  bool evaluated_ = false;
  double evaluated_finger_ = 0.0;
  DofVector evaluated_v_, evaluated_acceleration_;
  // scratch, so that rhs() does not allocate
  DofVector scratch_q_, scratch_v_, scratch_acceleration_;
};

}  // namespace pat

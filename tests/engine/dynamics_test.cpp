// Multibody dynamics against closed forms and conservation laws.
//
//      o  pivot (0, 0)                     o pivot
//       \                                   \   body 0
//        \  body 0 (rod)                     o  joint of body 1 on body 0
//         * centre of mass                    \  body 1
//
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dynamics/action_dynamics.h"
#include "dynamics/contact_geometry.h"
#include "integrators/integrator_factory.h"
#include "model/model_edits.h"
#include "sim/static_equilibrium.h"
#include "test_support.h"

namespace pat {
namespace {

Body rod(const std::string& name, int parent, Vec2 pivot, Vec2 com, double mass, double inertia) {
  Body b;
  b.name = name;
  b.parent = parent;
  b.pivot = pivot;
  b.com = com;
  b.mass = mass;
  b.inertia_com = inertia;
  return b;
}

/// Pendulum models: no contacts, no friction, only gravity.
ActionModel pendulum(bool double_pendulum) {
  ActionModel m;
  m.kind = "grand";
  m.bodies.push_back(rod("key", -1, Vec2(0, 0), Vec2(0.1, 0), 0.012, 3e-5));
  if (double_pendulum)
    m.bodies.push_back(rod("hammer", 0, Vec2(0.2, 0), Vec2(0.3, 0), 0.008, 2e-5));
  m.landmarks.key = 0;
  m.landmarks.hammer = double_pendulum ? 1 : 0;
  m.landmarks.key_front = Vec2(0.2, 0);
  return m;
}

double energy_drift(const ActionModel& model, double h, double duration) {
  ActionDynamics dynamics(model, nullptr);
  IntegratorOptions options;
  options.fixed_step_s = h;
  auto integrator = make_integrator("w2", options);
  DofVector q = DofVector::Constant(model.dofs(), 0.0), v = DofVector::Zero(model.dofs());
  q[0] = -0.3;  // released from 0.3 rad below horizontal
  const double e0 = dynamics.mechanical_energy(q, v);
  integrator->initialize(dynamics, 0.0, dynamics.compress(q, v));
  double worst = 0.0;
  while (integrator->time() < duration - 1e-12) {
    EXPECT_EQ(integrator->step(duration), StepStatus::Ok);
    dynamics.expand(integrator->time(), integrator->state(), q, v);
    worst = std::max(worst, std::abs(dynamics.mechanical_energy(q, v) - e0));
  }
  const double scale = model.bodies[0].mass * kGravity * 0.1;  // m g d, the energy scale
  return worst / scale;
}

/// Energy drift at steps h and h/2 over `duration`: below 1e-6 of m g d at h, and second order.
void expect_small_second_order_drift(const ActionModel& model, double h, double duration) {
  const double coarse = energy_drift(model, h, duration);
  const double fine = energy_drift(model, 0.5 * h, duration);
  std::printf("energy drift / (m g d): %.3g at %g s, %.3g at half the step\n", coarse, h, fine);
  EXPECT_LT(coarse, 1e-6);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.0);
}

TEST(Dynamics, PendulumConservesEnergyWithoutFriction) {
  // The W-method's global error is O(h²), so is the energy drift: halving the step divides it by
  // about 4 (3–5 allows for the error constant's own O(h) change). At 1e-4 s over 2 s it is
  // 3.2e-8 of m g d; 1e-6 leaves room for other compilers' rounding but not for an error in the
  // mass matrix or the bias terms, which drifts by 1e-3 and more.
  expect_small_second_order_drift(pendulum(false), 1e-4, 2.0);
}

TEST(Dynamics, DoublePendulumConservesEnergy) {
  // exercises the coupled mass matrix and the Coriolis/centrifugal bias terms; 7.8e-8 of m g d
  // at 5e-5 s over 1 s, the bound as above, and second order as above
  expect_small_second_order_drift(pendulum(true), 5e-5, 1.0);
}

/// Time of the second upward crossing of q0 + `level` by body 0 of an integrated single-body
/// model started at (q0 + offset, 0), linearly interpolated between steps (s).
double second_crossing(ActionDynamics& dynamics, double start, double level, double t_max) {
  IntegratorOptions options;
  options.fixed_step_s = 1e-5;
  auto integrator = make_integrator("w2", options);
  DofVector q(1), v(1);
  q[0] = start;
  v[0] = 0.0;
  integrator->initialize(dynamics, 0.0, dynamics.compress(q, v));
  double previous = start - level, crossing = -1.0;
  int crossings = 0;
  while (integrator->time() < t_max && crossings < 2) {
    const double t0 = integrator->time();
    EXPECT_EQ(integrator->step(t_max), StepStatus::Ok);
    const double now = integrator->state()[0] - level;
    if ((now > 0) != (previous > 0)) {
      ++crossings;
      crossing = t0 + (integrator->time() - t0) * previous / (previous - now);
    }
    previous = now;
  }
  return crossing;
}

TEST(Dynamics, JointSpringOscillatesAboutItsPreloadedRestWithItsClosedFormPeriod) {
  // one body on a torsion spring τ = τ0 − k q, no gravity: rest at q* = τ0 / k, period
  // T = 2π sqrt(I_pivot / k) at any amplitude (the spring is linear)
  ActionModel m = pendulum(false);
  m.gravity = Vec2::Zero();
  JointSpring spring;
  spring.body = 0;
  spring.stiffness = 0.02;  // N·m/rad
  spring.preload = 0.004;   // N·m: rest at 0.2 rad
  m.springs.push_back(spring);
  const Body& b = m.bodies[0];
  const double inertia = b.inertia_com + b.mass * 0.1 * 0.1;  // about the pivot, kg·m²
  const double period = 2 * kPi * std::sqrt(inertia / spring.stiffness);
  const double rest = spring.preload / spring.stiffness;
  ActionDynamics dynamics(m, nullptr);
  // released 0.1 rad above its rest: crosses the rest going down at T/4, going up at 3T/4
  const double crossing = second_crossing(dynamics, rest + 0.1, rest, 2 * period);
  // the step error of w2 at 1e-5 s on a 0.14 s period is ~1e-8 of it; 1e-5 of T is the
  // interpolation of the crossing
  EXPECT_NEAR(crossing, 0.75 * period, 1e-5 * period);
  // and mechanical_energy counts the spring's ½ k q² − τ0 q: conserved along the swing
  DofVector q(1), v(1);
  q[0] = rest + 0.1;
  v[0] = 0.0;
  const double e0 = dynamics.mechanical_energy(q, v);
  q[0] = rest;
  v[0] = -0.1 * std::sqrt(spring.stiffness / inertia);  // the energy moved into speed at rest
  EXPECT_NEAR(dynamics.mechanical_energy(q, v), e0, 1e-12 * std::abs(e0) + 1e-15);
}

TEST(Dynamics, TautStrapActsAsAOneSidedSpringAndConservesEnergyWithoutDamping) {
  // a rod (pivot at the origin, end at r = 0.2 m) tied by a strap to a frame point 5 cm above its
  // end, strap just taut at q = 0, no gravity. Swinging down, the end stretches the strap by
  // r sin q: a spring k r² about the pivot, so from ω0 it stops at q = −ω0 sqrt(I / (k r²)).
  // Swinging up the strap goes slack and pulls nothing.
  ActionModel m = pendulum(false);
  m.gravity = Vec2::Zero();
  Strap strap;
  strap.body_a = -1;
  strap.point_a = Vec2(0.2, 0.05);
  strap.body_b = 0;
  strap.point_b = Vec2(0.2, 0.0);
  strap.stiffness = 200.0;  // N/m
  m.straps.push_back(strap);
  ActionDynamics dynamics(m, nullptr);
  IntegratorOptions options;
  options.fixed_step_s = 1e-5;
  auto integrator = make_integrator("w2", options);
  const double omega0 = 2.0, r = 0.2;  // rad/s, m
  DofVector q(1), v(1);
  q[0] = 0.0;
  v[0] = -omega0;
  const double e0 = dynamics.mechanical_energy(q, v);
  integrator->initialize(dynamics, 0.0, dynamics.compress(q, v));
  double lowest = 0.0, worst = 0.0;
  while (integrator->time() < 0.05 - 1e-12) {
    ASSERT_EQ(integrator->step(0.05), StepStatus::Ok);
    dynamics.expand(integrator->time(), integrator->state(), q, v);
    lowest = std::min(lowest, q[0]);
    worst = std::max(worst, std::abs(dynamics.mechanical_energy(q, v) - e0));
  }
  const Body& b = m.bodies[0];
  const double inertia = b.inertia_com + b.mass * 0.1 * 0.1;  // about the pivot, kg·m²
  const double turning = omega0 * std::sqrt(inertia / (strap.stiffness * r * r));  // 8.66 mrad
  // the stretch is r sin q to within q²/6 ≈ 1e-5 relative (and the strap's tilt less): 1e-3
  EXPECT_NEAR(lowest, -turning, 1e-3 * turning);
  // back above q = 0 after half a spring period (4.7 ms), the strap slack: it leaves freely
  // with the speed it came with (elastic, undamped)
  EXPECT_GT(q[0], 0.0);
  EXPECT_NEAR(v[0], omega0, 1e-4 * omega0);
  // energy, strap included (mechanical_energy): 1.2e-6 of ½ I ω0² measured. The tension's kink at
  // L = L0, crossed twice, costs the W-method its order there; 1e-5 still fails for a wrong
  // stiffness term or a strap energy left out (an error of order 1)
  EXPECT_LT(worst, 1e-5 * 0.5 * inertia * omega0 * omega0);
}

// Bending the wire a strap hangs on moves the strap's end, not the strap's length: an end moved
// 2 mm away from the other along the strap stretches it 2 mm (the rest length had been measured
// again from the moved end, so such an adjuster did nothing).
TEST(Dynamics, MovingAStrapsEndByItsAdjusterStretchesTheStrap) {
  ActionModel m = pendulum(false);
  Strap strap;
  strap.body_a = -1;
  strap.point_a = Vec2(0.2, 0.05);
  strap.body_b = 0;
  strap.point_b = Vec2(0.2, 0.0);
  strap.slack = 1e-3;       // m
  strap.stiffness = 200.0;  // N/m
  m.straps.push_back(strap);
  // the tension at rest in the drawing configuration: k × stretch when taut
  auto tension = [](const ActionModel& model) {
    ActionDynamics dynamics(model, nullptr);
    DynamicsReading reading;
    dynamics.evaluate(0.0, DofVector::Zero(1), DofVector::Zero(1), reading);
    return reading.strap_tension.at(0);
  };
  using Target = AdjusterEffect::Target;
  for (const Target target : {Target::StrapPointA, Target::StrapPointB}) {
    ActionModel edited = m;
    Adjuster wire;
    wire.name = "wire";
    AdjusterEffect effect;
    effect.target = target;
    effect.index = 0;
    effect.direction = target == Target::StrapPointA ? Vec2(0.0, 1.0) : Vec2(0.0, -1.0);  // away
    wire.effects.push_back(effect);
    edited.adjusters.push_back(wire);
    EXPECT_EQ(tension(edited), 0.0);  // 1 mm slack
    // the slack taken up and 1 mm more: 0.2 N (metres rounded: 1e-9 N)
    EXPECT_NEAR(tension(with_adjuster(edited, "wire", 2e-3)), 0.2, 1e-9);
    EXPECT_EQ(tension(with_adjuster(edited, "wire", -2e-3)), 0.0);  // 3 mm slack
  }
}

// ∫0^x F_L(s) ds of a felt curve F = a s e^(b s) + c s (J): the potential of an elastic felt.
double felt_potential(const FeltCurve& curve, double x) {
  if (x <= 0.0) return 0.0;
  const double b = curve.b;
  const double exponential =
      std::abs(b * x) < 1e-8
          ? curve.a * x * x / 2.0
          : curve.a * ((x / b - 1.0 / (b * b)) * std::exp(b * x) + 1.0 / (b * b));
  return exponential + curve.c * x * x / 2.0;
}

// The whole action made conservative (felts elastic: unloading = loading; no contact or joint
// friction, no strap damping), kicked from rest by a key turning at 3 rad/s: kinetic, gravity,
// spring, strap and felt energy together stay constant as the parts strike, escape, fall and
// bounce through their contacts for 0.1 s, and the W-method's drift shrinks with the step (a
// wrong generalized force of a contact, or one on the wrong body, breaks it at once: an error of
// the order of the kick). Measured, as a share of the kick's energy at 1e-5 and 5e-6 s: grand
// 6.7e-5 and 9.7e-6, upright 7.6e-5 and 1.4e-5 (ratios 7 and 5, second order with the felts'
// stiffening kinks); tolerances: 5e-4, and at most a third of that drift at the half step.
TEST(Dynamics, AnElasticFrictionlessActionConservesEnergyThroughItsContacts) {
  for (const char* name : {"grand", "upright"}) {
    ActionModel m = test::shipped(name);
    for (Body& b : m.bodies) b.friction = JointFriction{};
    for (Contact& c : m.contacts) {
      c.law.unloading = c.law.loading;
      c.friction.mu = 0.0;
    }
    for (Strap& s : m.straps) s.damping = 0.0;
    const RestState rest = find_rest_state(m);
    ActionDynamics dynamics(m, nullptr);
    const int n = m.dofs();
    DofVector q0 = rest.q, v0 = DofVector::Zero(n);
    v0[m.landmarks.key] = -3.0;  // rad/s, the key front going down
    auto total_energy = [&](const DofVector& q, const DofVector& v) {
      std::vector<double> penetration;
      dynamics.contact_penetrations(q, penetration);
      double e = dynamics.mechanical_energy(q, v);
      for (std::size_t c = 0; c < penetration.size(); ++c)
        e += felt_potential(m.contacts[c].law.loading, penetration[c]);
      return e;
    };
    const double e0 = total_energy(q0, v0);
    const double kick = e0 - total_energy(q0, DofVector::Zero(n));  // the kinetic energy given
    ASSERT_GT(kick, 0.0);
    std::vector<double> drift;
    for (const double h : {1e-5, 5e-6}) {
      IntegratorOptions options;
      options.fixed_step_s = h;
      auto integrator = make_integrator("w2", options);
      DofVector q = q0, v = v0;
      integrator->initialize(dynamics, 0.0, dynamics.compress(q, v));
      double worst = 0.0, deepest = 0.0;
      std::vector<double> penetration;
      while (integrator->time() < 0.1 - 1e-12) {
        ASSERT_EQ(integrator->step(0.1), StepStatus::Ok) << name;
        dynamics.expand(integrator->time(), integrator->state(), q, v);
        worst = std::max(worst, std::abs(total_energy(q, v) - e0));
        dynamics.contact_penetrations(q, penetration);
        deepest = std::max(deepest, penetration[m.landmarks.string_contact]);
      }
      EXPECT_GT(deepest, 0.0) << name << ": the hammer must reach the string";
      drift.push_back(worst / kick);
    }
    EXPECT_LT(drift[0], 5e-4) << name;
    EXPECT_LT(drift[1], drift[0] / 3.0) << name << ": the drift must shrink with the step";
  }
}

TEST(Dynamics, SmallOscillationPeriodMatchesClosedForm) {
  // T = 2π sqrt(I_pivot / (m g d)) for a physical pendulum hanging down
  ActionModel m = pendulum(false);
  const Body& b = m.bodies[0];
  ActionDynamics dynamics(m, nullptr);
  IntegratorOptions options;
  options.fixed_step_s = 1e-5;
  auto integrator = make_integrator("w2", options);
  DofVector q(1), v(1);
  q[0] = -kPi / 2 + 1e-3;  // 1 mrad from hanging straight down
  v[0] = 0.0;
  integrator->initialize(dynamics, 0.0, dynamics.compress(q, v));
  const double d = 0.1;
  const double period =
      2 * kPi * std::sqrt((b.inertia_com + b.mass * d * d) / (b.mass * kGravity * d));
  // the angle crosses the hanging position at T/4 and 3T/4; measure the second crossing
  double previous = q[0] + kPi / 2, crossing = -1.0;
  int crossings = 0;
  while (integrator->time() < 2 * period && crossings < 2) {
    const double t0 = integrator->time();
    integrator->step(2 * period);
    const double now = integrator->state()[0] + kPi / 2;
    if ((now > 0) != (previous > 0)) {
      ++crossings;
      crossing = t0 + (integrator->time() - t0) * previous / (previous - now);
    }
    previous = now;
  }
  // amplitude 1 mrad: the nonlinear period correction is θ²/16 ≈ 6e-8, the step error ~1e-9
  EXPECT_NEAR(crossing, 0.75 * period, 1e-5 * period);
}

TEST(Dynamics, MassMatrixIsTheKineticEnergyAndPositiveDefiniteInReachableConfigurations) {
  for (const std::string name : {"grand", "upright"}) {
    const ActionModel model = test::shipped(name);
    const SimulationResult r = test::run(model, "force:double:40:30:50", 0.25);
    ActionDynamics dynamics(model, nullptr);
    const auto& rows = r.trace.rows;
    ASSERT_GT(rows.size(), 100u);
    for (std::size_t i = 0; i < rows.size(); i += 50) {
      DofVector q(model.dofs());
      for (int k = 0; k < model.dofs(); ++k)
        q[k] = r.rest.q[k] + rad(rows[i][1 + k]) * model.bodies[k].trace_sign;
      const DofMatrix mass = dynamics.mass_matrix(q);
      // M is assembled as a lower triangle and mirrored, so it is symmetric by construction; what
      // can be wrong is its content. ½ vᵀ M v must be the kinetic energy summed body by body,
      // Σ ½ m |v_c|² + ½ I_c ω², with v_c from the point kinematics, for any rates v.
      DofVector v(model.dofs());
      for (int k = 0; k < model.dofs(); ++k) v[k] = std::sin(1.7 * k + 0.3 * i);  // rad/s
      double kinetic = 0.0;
      for (int k = 0; k < model.dofs(); ++k) {
        const Body& body = model.bodies[k];
        double omega = 0.0;  // the body's absolute rate: its joint and every ancestor's
        for (int j = k; j >= 0; j = model.bodies[j].parent) omega += v[j];
        const Vec2 vc = dynamics.point_velocity(k, body.com, q, v);
        kinetic += 0.5 * body.mass * vc.squaredNorm() + 0.5 * body.inertia_com * omega * omega;
      }
      // two sums of the same few products: equal to rounding (1e-12 relative is 10⁴ ulps)
      EXPECT_NEAR(0.5 * v.dot(mass * v), kinetic, 1e-12 * kinetic) << name << " row " << i;
      Eigen::SelfAdjointEigenSolver<DofMatrix> eigen(mass);
      EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0) << name << " row " << i;
    }
  }
}

TEST(Dynamics, PointMassOnTheKeyAddsItsInertia) {
  // a 1 kg mass at the key front (0.22 m) adds m r² = 0.0484 kg m² about the balance pin
  const ActionModel model = test::shipped("grand");
  const RestState rest = find_rest_state(model);
  const auto mass_input = parse_input_spec("mass:1kg", input_context(model, rest));
  ActionDynamics bare(model, nullptr), loaded(model, mass_input.get());
  const int key = model.landmarks.key;
  const Vec2 arm = model.landmarks.key_front - model.bodies[key].pivot;
  const double expected = bare.mass_matrix(rest.q)(key, key) + arm.squaredNorm();
  EXPECT_NEAR(loaded.mass_matrix(rest.q)(key, key), expected, 1e-12);
}

/// Joint coordinates along a forte double blow, every `stride`-th trace row.
std::vector<DofVector> forte_configurations(const ActionModel& model, const RestState& rest,
                                            std::size_t stride) {
  const SimulationResult r = test::run(model, "force:double:40:30:50", 0.25);
  std::vector<DofVector> out;
  for (std::size_t i = 0; i < r.trace.rows.size(); i += stride) {
    DofVector q(model.dofs());
    for (int k = 0; k < model.dofs(); ++k)
      q[k] = rest.q[k] + rad(r.trace.rows[i][1 + k]) * model.bodies[k].trace_sign;
    out.push_back(q);
  }
  return out;
}

TEST(Dynamics, ContactGeometryInBodyFramesMatchesWorldFrameGeometry) {
  // The dynamics tests a segment in its own body's frame with precomputed constants; the plain
  // world-frame functions of contact_geometry.h are the reference (signed: gaps too). Both are
  // exact formulas, so
  // they agree to rounding (1e-12 m, far below any penetration that matters, ~1e-5 m).
  for (const std::string name : {"grand", "upright"}) {
    const ActionModel model = test::shipped(name);
    const RestState rest = find_rest_state(model);
    ActionDynamics dynamics(model, nullptr);
    int touching = 0;
    for (const DofVector& q : forte_configurations(model, rest, 5)) {
      std::vector<double> optimized;
      dynamics.contact_penetrations(q, optimized);
      for (std::size_t c = 0; c < model.contacts.size(); ++c) {
        const Contact& contact = model.contacts[c];
        auto world = [&](int body, const Vec2& p) { return dynamics.point_position(body, p, q); };
        double angle_b = 0.0;  // absolute rotation of B: the sum of its chain's coordinates
        for (int j = contact.body_b; j >= 0; j = model.bodies[j].parent) angle_b += q[j];
        const Vec2 center_a = world(contact.body_a, contact.center_a);
        const double reference =
            contact.shape == ContactShape::CircleCircle
                ? circle_circle_penetration(center_a, contact.radius_a,
                                            world(contact.body_b, contact.center_b),
                                            contact.radius_b)
                : circle_segment_penetration(
                      center_a, contact.radius_a, world(contact.body_b, contact.segment_start),
                      world(contact.body_b, contact.segment_end),
                      rotate(contact.segment_normal, std::cos(angle_b), std::sin(angle_b)),
                      contact.radius_b);
        EXPECT_NEAR(optimized[c], reference, 1e-12) << name << " " << contact.name;
        touching += reference > 0.0;
      }
    }
    EXPECT_GT(touching, 100) << name;  // the comparison saw contacts, not only gaps
  }
}

TEST(Dynamics, MemoizedPositionsGiveTheSameEvaluationAsAFreshObject) {
  // rhs() reuses the body positions and contact geometry when q repeats; that must be exact
  const ActionModel model = test::shipped("grand");
  const RestState rest = find_rest_state(model);
  const auto input = parse_input_spec("force:const:30", input_context(model, rest));
  ActionDynamics reused(model, input.get());
  for (const DofVector& q : forte_configurations(model, rest, 40)) {
    const DofVector v1 = DofVector::Constant(model.dofs(), 0.7);
    DofVector v2 = v1;
    v2[0] += 1e-3;
    DynamicsReading first, second, fresh_reading;
    reused.evaluate(0.01, q, v1, first);
    reused.evaluate(0.01, q, v2, second);  // same q: positions memoized
    ActionDynamics fresh(model, input.get());
    fresh.evaluate(0.01, q, v2, fresh_reading);
    for (int k = 0; k < model.dofs(); ++k)
      EXPECT_EQ(second.acceleration[k], fresh_reading.acceleration[k]);
    for (std::size_t c = 0; c < model.contacts.size(); ++c)
      EXPECT_EQ(second.contacts[c].normal_force, fresh_reading.contacts[c].normal_force);
  }
}

// A circle pressed into a face that goes round one of its closed ends lies behind the face's line
// past that end (action_dynamics.h); the simulator stops there. The grand's jack top against the
// repetition lever's window (upper end closed): at rest and tripped short of the window it is in
// front; swung 40 degrees it is above the window's upper end, behind it. Past the open lower end,
// or on a contact without closed ends, nothing is reported.
TEST(ContactPassThrough, AJackSwungOverTheLeverWindowIsBehindItsClosedEnd) {
  ActionModel grand = test::shipped("grand");
  const int window = grand.contact_index("jack–repetition lever window");
  const int jack = grand.body_index("jack");
  const int lever = grand.body_index("lever");
  ASSERT_GE(window, 0);
  ASSERT_TRUE(grand.contacts[window].closed_end);
  ASSERT_FALSE(grand.contacts[window].closed_start);
  const DofVector rest = find_rest_state(grand).q;
  {
    ActionDynamics dynamics(grand, nullptr);
    DofVector q = rest;
    EXPECT_FALSE(dynamics.behind_face_end(window, q));
    q[jack] += 10.0 * kPi / 180.0;  // tripped: its top 5 mm nearer the window, 2.5 mm short
    EXPECT_FALSE(dynamics.behind_face_end(window, q));
    q[lever] += 10.0 * kPi / 180.0;  // the lever pushed down: the window's top below the jack's
    q[jack] += 10.0 * kPi / 180.0;   // and the jack's top past the window's front face
    EXPECT_TRUE(dynamics.behind_face_end(window, q));
  }
  grand.contacts[window].closed_end = false;  // an open end: going round it is allowed
  ActionDynamics dynamics(grand, nullptr);
  DofVector q = rest;
  q[lever] += 10.0 * kPi / 180.0;
  q[jack] += 20.0 * kPi / 180.0;
  EXPECT_FALSE(dynamics.behind_face_end(window, q));
}

}  // namespace
}  // namespace pat

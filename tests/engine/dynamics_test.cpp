// Multibody dynamics against closed forms and conservation laws.
//
//      o  pivot (0, 0)                     o pivot
//       \                                   \   body 0
//        \  body 0 (rod)                     o  joint of body 1 on body 0
//         * centre of mass                    \  body 1
//
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/action_dynamics.h"
#include "dynamics/contact_geometry.h"
#include "integrators/integrator_factory.h"
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

TEST(Dynamics, PendulumConservesEnergyWithoutFriction) {
  // W-method error is O(h²): 1e-4 s over 2 s keeps the drift below 1e-4 of m g d
  EXPECT_LT(energy_drift(pendulum(false), 1e-4, 2.0), 1e-4);
}

TEST(Dynamics, DoublePendulumConservesEnergy) {
  // exercises the coupled mass matrix and the Coriolis/centrifugal bias terms
  EXPECT_LT(energy_drift(pendulum(true), 5e-5, 1.0), 1e-3);
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

TEST(Dynamics, MassMatrixSymmetricPositiveDefiniteInReachableConfigurations) {
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
      EXPECT_LT((mass - mass.transpose()).norm(), 1e-15 * mass.norm()) << name;
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

// Model extensions (model/effects.h): each checked against a closed form.
#include "model/effects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "dynamics/force_laws.h"
#include "model/model_edits.h"
#include "regulation/measurements.h"
#include "test_support.h"

namespace pat {
namespace {

/// Free vibration of joint `body` released from `deflection_rad` off rest (the rest state is
/// handed to the Simulator with that joint moved; no input), sampled every 10 µs for
/// `duration_s`. Returns the frequency (Hz) from the mean spacing of the zero crossings of the
/// angle about its mean.
double free_vibration_hz(const ActionModel& model, int body, double deflection_rad,
                         double duration_s) {
  RestState rest = find_rest_state(model);
  rest.q[body] += deflection_rad;
  SimulationOptions options;
  options.duration_s = duration_s;
  options.sample_interval_s = 1e-5;
  const SimulationResult r = simulate(model, nullptr, options, &rest);
  EXPECT_EQ(r.status, "ok") << r.stop_cause;
  const int col = r.trace.column_index(column_name(model.bodies[body].name) + "_angle_deg");
  std::vector<double> t, x;  // the angle from the deflected start; only its crossings matter
  for (const auto& row : r.trace.rows) {
    t.push_back(row[0]);
    x.push_back(row[col]);
  }
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> crossings;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double a = x[i - 1] - mean, b = x[i] - mean;
    if (a < 0 && b >= 0) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a));
  }
  if (crossings.size() < 3) return 0.0;
  return static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

TEST(Effects, ShankFlexKeepsTheRigidHammersMassCentreAndInertia) {
  const ActionModel grand = test::shipped("grand");
  const ActionModel flex = with_effect(grand, {"shank_flex", 150.0});
  ASSERT_EQ(flex.dofs(), grand.dofs() + 1);
  const Body& rigid = grand.bodies[grand.landmarks.hammer];
  const Body& shank = flex.bodies[grand.landmarks.hammer];
  const Body& head = flex.bodies.back();
  EXPECT_EQ(head.parent, grand.landmarks.hammer);
  EXPECT_EQ(flex.landmarks.hammer, flex.dofs() - 1);  // the strike point rides on the head
  // locked together, the two parts are the rigid hammer (sums exact up to rounding)
  EXPECT_NEAR(shank.mass + head.mass, rigid.mass, 1e-15);
  const Vec2 com = (shank.mass * shank.com + head.mass * head.com) / rigid.mass;
  EXPECT_NEAR((com - rigid.com).norm(), 0.0, 1e-15);
  const double inertia = shank.inertia_com + shank.mass * (shank.com - rigid.com).squaredNorm() +
                         head.inertia_com + head.mass * (head.com - rigid.com).squaredNorm();
  EXPECT_NEAR(inertia, rigid.inertia_com, 1e-15);
  EXPECT_GT(shank.inertia_com, 0.0);
  // the string contact moved to the head, the knuckle stayed on the shank
  EXPECT_EQ(flex.contacts[flex.landmarks.string_contact].body_a, flex.landmarks.hammer);
  EXPECT_EQ(flex.contacts[flex.landmarks.escapement_contact].body_a, grand.landmarks.hammer);
}

TEST(Effects, ShankFlexRingsAtTheRequestedFrequencyWithTheShankHeld) {
  const ActionModel grand = test::shipped("grand");
  for (double f : {60.0, 150.0}) {
    ActionModel flex = with_effect(grand, {"shank_flex", f});
    // hold the shank: a huge moment of inertia (not mass: gravity stays as it was)
    flex.bodies[grand.landmarks.hammer].inertia_com *= 1e7;
    const double measured = free_vibration_hz(flex, flex.dofs() - 1, rad(0.2), 12.0 / f);
    // closed form: ω² = k / J_head, damped by ζ = 0.05: f_d = f √(1 − ζ²) = 0.99875 f.
    // Tolerance 0.5 %: gravity's pendulum stiffness on the head (m g d ≈ 1e-3 N·m/rad against
    // k ≥ 0.4 N·m/rad: < 0.3 %) and the W-method's phase error at h ω < 0.01 (< 1e-4).
    EXPECT_NEAR(measured, f * std::sqrt(1.0 - 0.05 * 0.05), 0.005 * f) << "f = " << f;
  }
}

TEST(Effects, BackcheckWireHasTheRequestedLinearStiffness) {
  const ActionModel grand = test::shipped("grand");
  const double k_n_per_mm = 2.0;
  ActionModel soft = with_effect(grand, {"backcheck_compliance", k_n_per_mm});
  const int wire = soft.dofs() - 1;
  EXPECT_EQ(soft.bodies[wire].name, "backcheck");
  EXPECT_EQ(soft.contacts[soft.landmarks.check_contact].body_b, wire);
  // a rotation δ about the wire base moves the face by L δ along the contact normal, and the
  // torsional spring resists with k_t δ: the linear stiffness is k_t / L² = k
  const JointSpring& spring = soft.springs.back();
  const double length = (soft.bodies[wire].com - soft.bodies[wire].pivot).norm();
  EXPECT_NEAR(spring.stiffness / (length * length), k_n_per_mm * 1e3, 1e-9);
  // and the head (a point mass at the face) rings at f = √(k/m) / 2π with the key held
  soft.bodies[soft.landmarks.key].inertia_com *= 1e7;
  const double expected = std::sqrt(k_n_per_mm * 1e3 / soft.bodies[wire].mass) / (2 * kPi);
  const double measured = free_vibration_hz(soft, wire, rad(0.5), 12.0 / expected);
  // ζ = 0.05 lowers it by 0.125 %; gravity on the 3 g head about a 30 mm wire adds < 0.1 %
  EXPECT_NEAR(measured, expected * std::sqrt(1.0 - 0.05 * 0.05), 0.005 * expected);
}

// Toward its rigid limit: the stiffest wire allowed (20 N/mm, seven times a real brass wire's
// 2.8) reads a checking distance near the rigid backcheck's, and nearer than a real wire's
// (measured: rigid 16.00, 20 N/mm 15.84, 2 N/mm 17.02 mm). A tenth of the compliance leaves
// less than a quarter of the deviation, and under 0.25 mm.
TEST(Effects, AStifferBackcheckWireChecksNearerTheRigidBackcheck) {
  const ActionModel grand = test::shipped("grand");
  const double rigid = measure_setting(grand, "checking");
  const double stiff =
      measure_setting(with_effect(grand, {"backcheck_compliance", 20.0}), "checking");
  const double soft =
      measure_setting(with_effect(grand, {"backcheck_compliance", 2.0}), "checking");
  std::printf("checking: rigid %.3f, 20 N/mm %.3f, 2 N/mm %.3f mm\n", rigid, stiff, soft);
  EXPECT_LT(std::abs(stiff - rigid), 0.25);
  EXPECT_LT(std::abs(stiff - rigid), 0.25 * std::abs(soft - rigid));
}

TEST(Effects, FactorsScaleTheirLawsExactly) {
  const ActionModel grand = test::shipped("grand");
  const int hammer = grand.body_index("hammer");
  const ActionModel friction = with_effect(grand, {"joint_friction.hammer", 2.5});
  for (double w : {-3.0, 0.01, 0.4})
    EXPECT_DOUBLE_EQ(joint_friction_torque(friction.bodies[hammer].friction, w),
                     2.5 * joint_friction_torque(grand.bodies[hammer].friction, w));
  const int s = grand.landmarks.string_contact;
  const std::string contact = column_name(grand.contacts[s].name);
  const ActionModel felt = with_effect(grand, {"felt_stiffness." + contact, 0.5});
  for (double x : {1e-4, 5e-4})
    for (double v : {-0.5, 0.0, 0.5})
      EXPECT_NEAR(felt_normal_force(felt.contacts[s].law, x, v),
                  0.5 * felt_normal_force(grand.contacts[s].law, x, v), 1e-12);
  const int rep = grand.spring_index("repetition_spring");
  const ActionModel spring = with_effect(grand, {"repetition_spring", 1.5});
  EXPECT_DOUBLE_EQ(spring.springs[rep].stiffness, 1.5 * grand.springs[rep].stiffness);
  EXPECT_DOUBLE_EQ(spring.springs[rep].preload, 1.5 * grand.springs[rep].preload);
  const ActionModel upright = test::shipped("upright");
  const int butt = upright.spring_index("butt_spring");
  EXPECT_DOUBLE_EQ(with_effect(upright, {"butt_spring", 0.5}).springs[butt].stiffness,
                   0.5 * upright.springs[butt].stiffness);
}

TEST(Effects, RegulationOffsetMovesTheAdjuster) {
  const ActionModel grand = test::shipped("grand");
  const ActionModel moved = with_effect(grand, {"regulation_offset.let_off", 0.8});
  const ActionModel set = with_adjuster(
      grand, "let_off", grand.adjusters[grand.adjuster_index("let_off")].value + 0.8e-3);
  for (std::size_t c = 0; c < grand.contacts.size(); ++c) {
    EXPECT_EQ(moved.contacts[c].segment_start, set.contacts[c].segment_start);
    EXPECT_EQ(moved.contacts[c].center_b, set.contacts[c].center_b);
  }
  // the let-off button moved, so the let-off contact differs from the regulated model
  const int l = grand.landmarks.letoff_contact;
  EXPECT_GT((moved.contacts[l].center_b - grand.contacts[l].center_b).norm() +
                (moved.contacts[l].segment_start - grand.contacts[l].segment_start).norm(),
            0.7e-3);
}

TEST(Effects, BadNamesAndValuesAreNamed) {
  const ActionModel grand = test::shipped("grand");
  const ActionModel upright = test::shipped("upright");
  auto message = [](const ActionModel& m, const std::string& text) {
    try {
      with_effect(m, parse_effect(text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(grand, "wobble=2").find("unknown effect 'wobble'"), std::string::npos);
  EXPECT_NE(message(grand, "joint_friction.elbow=2").find("no joint 'elbow'"), std::string::npos);
  EXPECT_NE(message(grand, "felt_stiffness.nose=2").find("no contact 'nose'"), std::string::npos);
  EXPECT_NE(message(grand, "regulation_offset.tone=1").find("no setting 'tone'"),
            std::string::npos);
  EXPECT_NE(message(grand, "butt_spring=2").find("repetition_spring"), std::string::npos);
  EXPECT_NE(message(upright, "repetition_spring=2").find("butt_spring"), std::string::npos);
  EXPECT_NE(message(grand, "shank_flex=5").find("outside its physical range"), std::string::npos);
  EXPECT_NE(message(grand, "shank_flex=abc").find("not a number"), std::string::npos);
  EXPECT_NE(message(grand, "shank_flex").find("NAME=VALUE"), std::string::npos);
}

TEST(Effects, EveryCandidateRunsAStrikeAtItsTestValue) {
  // each extension is usable on its own in a simulation (both actions)
  for (const char* kind : {"grand", "upright"}) {
    const ActionModel model = test::shipped(kind);
    for (const EffectInfo& info : candidate_effects(model)) {
      const double value = info.has_neutral
                               ? (info.unit == "mm" ? info.neutral + 0.3 : info.neutral * 1.5)
                               : std::sqrt(info.min * info.max);
      const ActionModel m = with_effect(model, {info.name, value});
      const SimulationResult r = test::run(m, "force:pulse:20:60", 0.06);  // impact ≈ 25 ms
      EXPECT_EQ(r.status, "ok") << kind << " " << info.name << ": " << r.stop_cause;
      EXPECT_FALSE(test::events_of(r, "impact").empty()) << kind << " " << info.name;
    }
  }
}

}  // namespace
}  // namespace pat

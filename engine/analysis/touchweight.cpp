#include "analysis/touchweight.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "dynamics/action_dynamics.h"
#include "inputs/key_input.h"
#include "sim/simulation.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

/// Why a held key may find no balance: its parts keep moving there, which a setting or a weight
/// that moved the action's rest (a key that falls to its punching on its own) does.
constexpr const char* kNoBalanceHint =
    ": the other parts keep moving there (a setting or a key weight may have moved the action's "
    "rest, e.g. a key heavy enough in front to fall to its punching on its own)";

/// The key held still at a fixed angle from rest (a motion input that never moves).
class HeldKey : public KeyInput {
 public:
  explicit HeldKey(double angle) : angle_(angle) {}
  bool is_motion() const override { return true; }
  double force_n(double) const override { return 0.0; }
  KeyMotionSample motion(double) const override { return {angle_, 0.0, 0.0}; }
  const std::string& spec() const override { return spec_; }

 private:
  double angle_;
  std::string spec_ = "held";
};

/// One key position: the other bodies in static equilibrium with the key held.
class HeldKeyBalance {
 public:
  HeldKeyBalance(const ActionModel& model, double key_rest_angle, double key_angle)
      : model_(model), input_(key_angle), dynamics_(model, &input_) {
    dynamics_.set_key_rest_angle(key_rest_angle);
    key_ = model.landmarks.key;
    key_angle_ = key_rest_angle + key_angle;
  }

  /// Newton on the free joints' accelerations at rest (as solve_static_equilibrium, the key
  /// row removed). Returns false when it does not converge.
  bool solve(DofVector& q) {
    q[key_] = key_angle_;
    return damped_newton([this](const DofVector& x) { return residual(x); }, q, key_, 60, 1e-11);
  }

  /// Finger force (N, downward) that holds the key at q with everything at rest.
  double balance_force(const DofVector& q) {
    dynamics_.evaluate(0.0, q, DofVector::Zero(q.size()), reading_);
    return reading_.finger_force;
  }

  /// Σ μ F_n |slip rate| over rubbing contacts for joint rates `v` (N·m/s); normal forces from
  /// the state at rest. The slip rate is read back from the regularized law
  /// F_t = −μ F_n tanh(v_t / v_s) at rates so small (≤ 1e-4 v_s) that tanh is linear to 1e-8.
  double contact_friction_power(const DofVector& q, const DofVector& v) {
    DynamicsReading at_rest;
    dynamics_.evaluate(0.0, q, DofVector::Zero(q.size()), at_rest);
    double largest = v.cwiseAbs().maxCoeff();
    if (largest == 0.0) return 0.0;
    // a 1e-6 rad/s rate moves a 0.2 m arm by 2e-7 m/s ≤ 2e-4 of the smallest v_s used (1 mm/s)
    const double scale = 1e-6 / largest;
    dynamics_.evaluate(0.0, q, DofVector(v * scale), reading_);
    double power = 0.0;
    for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
      const ContactFriction& law = model_.contacts[c].friction;
      const ContactReading& moving = reading_.contacts[c];
      if (law.mu <= 0.0 || !moving.active || moving.normal_force <= 0.0) continue;
      const double ratio =
          std::min(std::abs(moving.friction_force) / (law.mu * moving.normal_force), 1.0 - 1e-15);
      const double slip_rate = law.slip_velocity * std::atanh(ratio) / scale;
      power += law.mu * std::max(at_rest.contacts[c].normal_force, 0.0) * slip_rate;
    }
    return power;
  }

 private:
  DofVector residual(const DofVector& q) {
    dynamics_.evaluate(0.0, q, DofVector::Zero(q.size()), reading_);
    DofVector r = reading_.acceleration;
    r[key_] = 0.0;
    return r;
  }

  const ActionModel& model_;
  HeldKey input_;
  ActionDynamics dynamics_;
  DynamicsReading reading_;
  int key_ = 0;
  double key_angle_ = 0.0;
};

/// Horizontal lever arm (m) of a world point about the key's balance pin at rest.
double key_arm(const ActionModel& model, ActionDynamics& dynamics, const DofVector& rest_q,
               const Vec2& world_point) {
  const Vec2 pin =
      dynamics.point_position(model.landmarks.key, model.bodies[model.landmarks.key].pivot, rest_q);
  return world_point.x() - pin.x();
}

/// A technician weighs a key off from its rest on the back rail. A key weighted at the front
/// (lead) may lift off it and sink onto what stops it (the capstan lifting the whippen, the
/// damper lift, the front-rail punching), or hover near its balance and never settle; dips
/// measured from there would be another window of the stroke. It is weighed from where its back
/// rail just touches instead, held there with the other parts in balance: a front-heavy key's
/// balance weight comes out below 0 g (it must be held up). `settled`: the action's rest, when
/// it found one, or why not (`unsettled`); `sunk_mm`: how far the key front had sunk from the
/// back rail by itself (0 when it rests there or within 0.01 mm of it, NaN when it did not
/// settle).
RestState key_on_back_rail(const ActionModel& action, ActionDynamics& dynamics,
                           const std::optional<RestState>& settled, const std::string& unsettled,
                           double& sunk_mm) {
  sunk_mm = 0.0;
  const int back_rail = action.landmarks.key_rest_contact;
  const int key = action.landmarks.key;
  if (settled) {
    if (back_rail < 0) return *settled;  // the preset names no back rail: its rest is the start
    DynamicsReading reading;
    dynamics.evaluate(0.0, settled->q, DofVector::Zero(settled->q.size()), reading);
    if (reading.contacts[back_rail].active && reading.contacts[back_rail].normal_force > 0.0)
      return *settled;
  } else if (back_rail < 0) {
    throw std::runtime_error(
        "touchweight: " + unsettled +
        " (and the preset names no back rail, landmarks.contacts.key_rest, to hold the key on)");
  }
  // the other parts' rest with the key on its back rail: the same action with the key's weight
  // moved as far behind its pin as its front lies before it, which settles there (the key's own
  // weight does not enter the other parts' balance once the key is held)
  ActionModel tail_heavy = action;
  Body& tail_heavy_key = tail_heavy.bodies[key];
  tail_heavy_key.com = 2.0 * tail_heavy_key.pivot - action.landmarks.key_front;
  RestState start;
  try {
    start = find_rest_state(tail_heavy);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("touchweight: with the key held on its back rail, ") +
                             e.what());
  }
  // the key angle at which the back rail just touches (penetration 0), by bisection: the front
  // lifted (angle down) presses the key's tail into the rail
  std::vector<double> penetration;
  const auto back_rail_penetration = [&](double key_angle) {
    DofVector q = start.q;
    q[key] = key_angle;
    dynamics.contact_penetrations(q, penetration);
    return penetration[back_rail];
  };
  double lifted = start.q[key];
  for (int i = 0; i < 40 && back_rail_penetration(lifted) < 0.0; ++i) lifted -= 0.01;
  for (int i = 0; i < 40 && back_rail_penetration(lifted + 0.01) >= 0.0; ++i) lifted += 0.01;
  double open = lifted + 0.01;
  if (back_rail_penetration(lifted) < 0.0 || back_rail_penetration(open) >= 0.0)
    throw std::runtime_error("touchweight: the key never meets '" +
                             action.contacts[back_rail].name + "' when lifted");
  for (int i = 0; i < 60; ++i) {  // to 1e-18 rad of the 0.01 rad bracket, far below need
    const double middle = 0.5 * (open + lifted);
    (back_rail_penetration(middle) < 0.0 ? open : lifted) = middle;
  }
  if (!HeldKeyBalance(action, 0.0, lifted).solve(start.q))
    throw std::runtime_error(
        "touchweight: no static equilibrium with the key held on its back "
        "rail ('" +
        action.contacts[back_rail].name + "')");
  sunk_mm = settled ? (dynamics.point_position(key, action.landmarks.key_front, start.q).y() -
                       dynamics.point_position(key, action.landmarks.key_front, settled->q).y()) *
                          1e3
                    : std::nan("");
  // micrometres (a back rail just unloaded) are no sinking to speak of
  if (std::isfinite(sunk_mm) && sunk_mm < 0.01) sunk_mm = 0.0;
  return start;
}

}  // namespace

CsvTable TouchweightResult::table() const {
  CsvTable t;
  t.columns = {"dip_mm", "downweight_g", "upweight_g", "balance_weight_g", "friction_weight_g"};
  for (const TouchweightPoint& p : curve) {
    const double b = p.balance_force_n / kGravity * 1e3, f = p.friction_force_n / kGravity * 1e3;
    t.rows.push_back({p.dip_mm, b + f, b - f, b, f});
  }
  return t;
}

std::string key_rest_note(const TouchweightResult& result) {
  const std::string heavy =
      result.balance_weight_g < 0.0 ? "the key is front-heavy (balance weight below 0 g): " : "";
  if (std::isnan(result.key_sinks_mm))
    return heavy +
           "the action does not settle by itself (the key hovers near its balance); weighed from "
           "the key's back rail, held there";
  if (result.key_sinks_mm > 0.0)
    return heavy + "left alone, the key front sinks " + format_fixed(result.key_sinks_mm, 2) +
           " mm off its back rail; weighed from the back rail, held there";
  return "";
}

TouchweightResult measure_touchweight(const ActionModel& action, const TouchweightOptions& options,
                                      const ProgressCallback& progress) {
  const int key = action.landmarks.key;
  if (key < 0) throw InputError(action.source_file + ": the action names no key");
  if (options.positions < 2 || !(options.window_end_mm > options.window_start_mm) ||
      options.window_start_mm <= 0.0)
    throw InputError(
        "touchweight: the measuring window must run from a positive dip to a "
        "larger one with at least two positions");
  std::optional<RestState> settled;
  std::string unsettled;  // why no rest was found
  try {
    settled = find_rest_state(action);
  } catch (const InputError&) {
    throw;  // a broken model is said as such
  } catch (const std::runtime_error& e) {
    // a key weighted near its balance may hover and never settle: weighed from its back rail
    unsettled = e.what();
  }
  ActionDynamics rest_dynamics(action, nullptr);
  TouchweightResult result;
  // the measurement starts from the key on its back rail (a front-heavy key held up there)
  const RestState rest =
      key_on_back_rail(action, rest_dynamics, settled, unsettled, result.key_sinks_mm);
  const Body& key_body = action.bodies[key];
  const double front_arm =
      key_arm(action, rest_dynamics, rest.q,
              rest_dynamics.point_position(key, action.landmarks.key_front, rest.q));
  // small-angle map from dip to key angle (the exact dip is measured back at each position)
  const double dip_per_rad = -front_arm;  // the front is in front of the pin (x < 0)
  if (!(dip_per_rad > 0.0))
    throw InputError(action.source_file + ": the key front must lie in front of the balance pin");
  const Vec2 front0 = rest_dynamics.point_position(key, action.landmarks.key_front, rest.q);

  result.curve.resize(options.positions);
  ProgressReporter reporter(progress, options.positions);
  std::vector<std::string> failures(options.positions);
  run_parallel(
      options.positions,
      [&](std::size_t i) {
        const double dip_target =
            options.window_start_mm + (options.window_end_mm - options.window_start_mm) *
                                          static_cast<double>(i) / (options.positions - 1);
        const double angle = dip_target * 1e-3 / dip_per_rad;
        // continuation from rest in small key steps, then the neighbours for dq/dθ
        DofVector q = rest.q;
        const int substeps = 4;
        for (int s = 1; s <= substeps; ++s) {
          HeldKeyBalance step(action, rest.q[key], angle * s / substeps);
          if (!step.solve(q)) {
            failures[i] = "no static equilibrium with the key front held " +
                          format_number(dip_target, 3) + " mm down" + kNoBalanceHint;
            return;
          }
        }
        // 1e-5 rad of key ≈ 2 µm at the front: small against the mm-scale changes of the lever
        // ratios, large against the Newton tolerance (1e-11 rad)
        const double delta = 1e-5;
        DofVector q_minus = q, q_plus = q;
        HeldKeyBalance minus(action, rest.q[key], angle - delta);
        HeldKeyBalance plus(action, rest.q[key], angle + delta);
        HeldKeyBalance here(action, rest.q[key], angle);
        if (!minus.solve(q_minus) || !plus.solve(q_plus)) {
          failures[i] = "no static equilibrium next to the key front held " +
                        format_number(dip_target, 3) + " mm down" + kNoBalanceHint;
          return;
        }
        const DofVector dq_dangle = (q_plus - q_minus) / (2.0 * delta);
        ActionDynamics geometry(action, nullptr);
        const double dip_m =
            front0.y() - geometry.point_position(key, action.landmarks.key_front, q).y();
        const double dy_dangle =
            (geometry.point_position(key, action.landmarks.key_front, q_minus).y() -
             geometry.point_position(key, action.landmarks.key_front, q_plus).y()) /
            (2.0 * delta);
        double joint_power = 0.0;  // Σ A_j |q̇_j| per unit key rate
        for (int j = 0; j < action.dofs(); ++j)
          joint_power += action.bodies[j].friction.a_nm * std::abs(dq_dangle[j]);
        const double contact_power = here.contact_friction_power(q, dq_dangle);
        TouchweightPoint& point = result.curve[i];
        point.dip_mm = dip_m * 1e3;
        point.balance_force_n = here.balance_force(q);
        point.friction_force_n = (joint_power + contact_power) / dy_dangle;
        reporter.item_done("key front " + std::to_string(dip_target) + " mm");
      },
      &reporter);
  for (const std::string& failure : failures)
    if (!failure.empty()) throw std::runtime_error("touchweight: " + failure);

  // the work-equivalent weights over the window (trapezoid rule over the sampled dips)
  double down = 0.0, up = 0.0, span = 0.0;
  for (std::size_t i = 0; i + 1 < result.curve.size(); ++i) {
    const TouchweightPoint& a = result.curve[i];
    const TouchweightPoint& b = result.curve[i + 1];
    const double width = b.dip_mm - a.dip_mm;
    down += 0.5 * width *
            (a.balance_force_n + a.friction_force_n + b.balance_force_n + b.friction_force_n);
    up += 0.5 * width *
          (a.balance_force_n - a.friction_force_n + b.balance_force_n - b.friction_force_n);
    span += width;
  }
  down /= span;
  up /= span;
  const double grams_per_newton = 1e3 / kGravity;
  result.downweight_g = down * grams_per_newton;
  result.upweight_g = up * grams_per_newton;
  result.balance_weight_g = 0.5 * (result.downweight_g + result.upweight_g);
  result.friction_weight_g = 0.5 * (result.downweight_g - result.upweight_g);

  // key ratio from the capstan (the key's contact with the whippen) at rest
  DynamicsReading reading;
  rest_dynamics.evaluate(0.0, rest.q, DofVector::Zero(rest.q.size()), reading);
  const int whippen = action.body_index("whippen");
  result.key_ratio = std::nan("");
  for (std::size_t c = 0; c < action.contacts.size(); ++c) {
    const Contact& contact = action.contacts[c];
    const bool capstan = (contact.body_a == key && contact.body_b == whippen) ||
                         (contact.body_b == key && contact.body_a == whippen);
    if (capstan && whippen >= 0 && reading.contacts[c].active) {
      result.key_ratio =
          key_arm(action, rest_dynamics, rest.q, reading.contacts[c].point) / -front_arm;
      break;
    }
  }
  // strike weight: the hammer with its shank (pin → strike point) horizontal
  if (action.landmarks.hammer >= 0) {
    const Body& hammer = action.bodies[action.landmarks.hammer];
    const Vec2 shank = action.landmarks.strike_point - hammer.pivot;
    result.strike_weight_g =
        hammer.mass * 1e3 * (hammer.com - hammer.pivot).dot(shank) / shank.squaredNorm();
  }
  // front weight: the key's own weight moment about the pin, read at the key front
  const Vec2 com = rest_dynamics.point_position(key, key_body.com, rest.q);
  result.front_weight_g =
      key_body.mass * 1e3 * key_arm(action, rest_dynamics, rest.q, com) / front_arm;
  return result;
}

}  // namespace pat

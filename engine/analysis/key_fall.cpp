#include "analysis/key_fall.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "analysis/isolated_body.h"
#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "integrators/integrator_factory.h"
#include "sim/simulation.h"

namespace pat {

KeyFallResult key_fall(const ActionModel& action, const KeyFallOptions& options,
                       const ProgressCallback& progress) {
  if (action.landmarks.key < 0)
    throw InputError(action.source_file + ": the action names no key (landmarks.key)");
  check_trace_rows(options.duration_s, options.sample_interval_s);
  const ActionModel alone =
      isolated_body_model(action, action.bodies[action.landmarks.key].name, true);
  const int punching = alone.landmarks.key_bottom_contact;
  if (punching < 0)
    throw InputError(action.source_file +
                     ": the action names no key–front-rail contact (landmarks.key_bottom)");

  KeyFallResult result;
  result.start_angle_rad = options.start_angle_rad
                               ? *options.start_angle_rad
                               : find_rest_state(action).q[action.landmarks.key];

  ActionDynamics dynamics(alone, nullptr);
  IntegratorOptions integrator_options;
  integrator_options.relative_tolerance = options.relative_tolerance;
  integrator_options.absolute_tolerance = options.relative_tolerance * 1e-2;
  integrator_options.max_step_s = 1e-4;  // resolves the ~1 ms felt contact
  std::unique_ptr<Integrator> integrator = make_integrator("rodas", integrator_options);
  StateVector y0(2);
  y0 << result.start_angle_rad, 0.0;
  integrator->initialize(dynamics, 0.0, y0);

  DofVector q(1), v(1);
  q[0] = result.start_angle_rad;
  v[0] = 0.0;
  const Vec2 front0 = dynamics.point_position(0, alone.landmarks.key_front, q);
  auto dip_mm = [&](const DofVector& qq) {
    return (front0.y() - dynamics.point_position(0, alone.landmarks.key_front, qq).y()) * 1e3;
  };
  std::vector<double> penetration;
  DynamicsReading reading;
  result.trace.columns = {"time_s", "key_angle_deg", "key_front_dip_mm", "punching_force_n"};
  auto add_row = [&](double t) {
    dynamics.evaluate(t, q, v, reading);
    result.trace.rows.push_back({t, (q[0] - result.start_angle_rad) * 180.0 / M_PI, dip_mm(q),
                                 reading.contacts[punching].normal_force});
  };
  add_row(0.0);
  double next_sample = options.sample_interval_s;
  bool touching = false;
  double next_report = 0.0;
  while (integrator->time() < options.duration_s) {
    if (integrator->step(options.duration_s) != StepStatus::Ok)
      throw std::runtime_error("key fall: the integrator failed: " + integrator->failure_reason());
    const double t = integrator->time();
    q[0] = integrator->state()[0];
    v[0] = integrator->state()[1];
    dynamics.contact_penetrations(q, penetration);
    const bool now_touching = penetration[punching] > 0.0;
    const double dip = dip_mm(q);
    if (now_touching && !touching && result.fall_time_s < 0.0) {
      // first contact: the step end just past it (steps ≤ 0.1 ms, a key-front error < 0.1 mm/s
      // · 0.1 ms at the ~0.2 m/s impact speed is negligible)
      result.fall_time_s = t;
      result.fall_distance_mm = dip;
      result.fall_angle_rad = q[0] - result.start_angle_rad;
      result.impact_velocity_mps =
          dynamics.point_velocity(0, alone.landmarks.key_front, q, v).norm();
    }
    if (!now_touching && touching) ++result.bounces;
    // the first rebound: how far the key front rises above its first-contact height while
    // it is off the punching for the first time
    if (result.bounces == 1 && !now_touching)
      result.first_rebound_mm = std::max(result.first_rebound_mm, result.fall_distance_mm - dip);
    touching = now_touching;
    if (options.sample_interval_s > 0.0 && t >= next_sample) {
      add_row(t);
      next_sample += options.sample_interval_s *
                     std::ceil((t - next_sample) / options.sample_interval_s + 1e-12);
      if (next_sample <= t) next_sample += options.sample_interval_s;
    }
    if (progress && t >= next_report) {
      next_report = t + 0.05 * options.duration_s;
      if (!progress(t / options.duration_s, "key fall")) throw Cancelled();
    }
  }
  result.final_dip_mm = dip_mm(q);
  return result;
}

}  // namespace pat

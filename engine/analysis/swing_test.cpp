#include "analysis/swing_test.h"

#include <cmath>
#include <memory>

#include "analysis/isolated_body.h"
#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "integrators/integrator_factory.h"

namespace pat {

SwingResult swing_test(const ActionModel& action, const SwingOptions& options,
                       const ProgressCallback& progress) {
  if (action.landmarks.hammer < 0)
    throw InputError(action.source_file + ": the action names no hammer (landmarks.hammer)");
  const ActionModel alone =
      isolated_body_model(action, action.bodies[action.landmarks.hammer].name, false);
  const Body& hammer = alone.bodies[0];
  const Vec2 arm = hammer.com - hammer.pivot;  // at q = 0
  const double g = alone.gravity.norm();
  if (g <= 0.0) throw InputError(action.source_file + ": the swing test needs gravity");
  const Vec2 down = alone.gravity / g;

  SwingResult result;
  result.pin_to_com_m = arm.norm();
  result.inertia_about_pin_kgm2 = hammer.inertia_com + hammer.mass * arm.squaredNorm();
  const double weight_moment = hammer.mass * g * result.pin_to_com_m;  // m g d, N·m
  const double stick = std::asin(std::min(1.0, hammer.friction.a_nm / weight_moment));
  result.stick_angle_deg = stick * 180.0 / M_PI;

  // φ(q) = angle from `down` to the arm rotated by q (counter-clockwise positive)
  const double phi_at_zero = std::atan2(down.x() * arm.y() - down.y() * arm.x(), down.dot(arm));
  // release on the side the hammer already leans to at q = 0
  const double phi0 = phi_at_zero >= 0.0 ? options.release_angle_rad : -options.release_angle_rad;
  const double q0 = phi0 - phi_at_zero;

  ActionDynamics dynamics(alone, nullptr);
  IntegratorOptions integrator_options;
  integrator_options.relative_tolerance = options.relative_tolerance;
  integrator_options.absolute_tolerance = options.relative_tolerance * 1e-2;
  integrator_options.max_step_s = 2e-3;
  std::unique_ptr<Integrator> integrator = make_integrator("rodas", integrator_options);
  StateVector y0(2);
  y0 << q0, 0.0;
  integrator->initialize(dynamics, 0.0, y0);

  result.trace.columns = {"time_s", "swing_angle_deg", "swing_rate_deg_per_s"};
  const double to_deg = 180.0 / M_PI;
  auto add_row = [&](double t, double phi, double rate) {
    result.trace.rows.push_back({t, phi * to_deg, rate * to_deg});
  };
  add_row(0.0, phi0, 0.0);
  // released within the stick angle: the pin's friction holds it where it is, no swing at all
  if (std::abs(phi0) <= stick) {
    result.stopped = true;
    result.stop_time_s = 0.0;
    return result;
  }
  double next_sample = options.sample_interval_s;
  double t_prev = 0.0, phi_prev = phi0, rate_prev = 0.0;
  double next_report = 0.0;
  while (integrator->time() < options.max_duration_s) {
    if (integrator->step(options.max_duration_s) != StepStatus::Ok)
      throw std::runtime_error("swing test: the integrator failed: " +
                               integrator->failure_reason());
    const double t = integrator->time();
    const double phi = integrator->state()[0] - q0 + phi0;
    const double rate = integrator->state()[1];
    while (options.sample_interval_s > 0.0 && next_sample <= t) {
      // linear interpolation between step ends is enough for a plotted trace
      const double s = (next_sample - t_prev) / (t - t_prev);
      add_row(next_sample, phi_prev + s * (phi - phi_prev), rate_prev + s * (rate - rate_prev));
      next_sample += options.sample_interval_s;
    }
    if (rate_prev != 0.0 && (rate == 0.0 || (rate > 0.0) != (rate_prev > 0.0))) {
      // a turning point between the step ends: where the rate crosses zero; the angle there is
      // interpolated with the cubic Hermite through both ends (its slope is the rate)
      const double s = rate_prev / (rate_prev - rate);
      const double h = t - t_prev;
      const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
      const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
      const double phi_turn = h00 * phi_prev + h10 * h * rate_prev + h01 * phi + h11 * h * rate;
      const double t_turn = t_prev + s * h;
      ++result.half_swings;
      result.turning_times_s.push_back(t_turn);
      result.turning_amplitudes_deg.push_back(std::abs(phi_turn) * to_deg);
      if (result.half_swings == 1) result.first_half_period_s = t_turn;
      if (std::abs(phi_turn) <= stick) {
        result.stopped = true;
        result.stop_time_s = t_turn;
        break;
      }
    }
    // no longer able to leave the stick zone: its energy above hanging is below what a
    // turning point at φ_stick holds (covers a swing that dies out without turning, and a
    // release just outside the zone that creeps down to hanging without one)
    const double energy =
        0.5 * result.inertia_about_pin_kgm2 * rate * rate + weight_moment * (1.0 - std::cos(phi));
    if (energy <= weight_moment * (1.0 - std::cos(stick))) {
      result.stopped = true;
      result.stop_time_s = t;
      break;
    }
    t_prev = t;
    phi_prev = phi;
    rate_prev = rate;
    if (progress && t >= next_report) {
      next_report = t + 0.05 * options.max_duration_s;
      if (!progress(t / options.max_duration_s, "swing")) throw Cancelled();
    }
  }
  if (!result.stopped) result.stop_time_s = integrator->time();
  result.round_trips = 0.5 * result.half_swings;
  return result;
}

}  // namespace pat

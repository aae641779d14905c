#include "sim/simulation.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dynamics/action_dynamics.h"

namespace pat {
namespace {

std::string part_name(const ActionModel& model, int body) {
  return body < 0 ? std::string("frame") : model.bodies[body].name;
}

std::string format_mm(double metres) {
  std::ostringstream out;
  out.precision(3);
  out << metres * 1e3;
  return out.str();
}

/// Cubic Hermite interpolation of (q, v) between two step ends (q' = v exactly).
void hermite(double t0, const DofVector& q0, const DofVector& v0, double t1, const DofVector& q1,
             const DofVector& v1, double t, DofVector& q, DofVector& v) {
  const double h = t1 - t0;
  const double s = h > 0.0 ? (t - t0) / h : 1.0;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
               h11 = s3 - s2;
  q = h00 * q0 + h10 * h * v0 + h01 * q1 + h11 * h * v1;
  // derivative of the position polynomial
  const double d00 = (6 * s2 - 6 * s) / h, d10 = 3 * s2 - 4 * s + 1, d01 = (-6 * s2 + 6 * s) / h,
               d11 = 3 * s2 - 2 * s;
  v = h > 0.0 ? DofVector(d00 * q0 + d10 * v0 + d01 * q1 + d11 * v1) : v1;
}

}  // namespace

std::string column_name(const std::string& name) {
  std::string out;
  bool gap = false;
  for (unsigned char c : name) {
    if (std::isalnum(c)) {
      if (gap && !out.empty()) out += '_';
      out += static_cast<char>(std::tolower(c));
      gap = false;
    } else {
      gap = true;
    }
  }
  return out;
}

std::vector<std::string> trace_columns(const ActionModel& model) {
  std::vector<std::string> columns{"time_s"};
  for (const Body& b : model.bodies) columns.push_back(column_name(b.name) + "_angle_deg");
  columns.push_back("hammer_string_gap_mm");
  columns.push_back("finger_force_n");
  for (const Contact& c : model.contacts) columns.push_back(column_name(c.name) + "_force_n");
  for (const Strap& s : model.straps) columns.push_back(column_name(s.name) + "_tension_n");
  return columns;
}

RestState find_rest_state(const ActionModel& model) {
  ActionDynamics dynamics(model, nullptr);
  IntegratorOptions io;
  io.fixed_step_s = 2e-5;
  auto integrator = make_integrator("w2", io);
  const int n = model.dofs();
  DofVector q = DofVector::Zero(n), v = DofVector::Zero(n);
  // damped phase, then a free phase to let contacts find their own balance
  const double phases[2][2] = {{0.4, 0.02}, {0.3, 0.0}};
  double t = 0.0;
  for (const auto& phase : phases) {
    dynamics.set_settling_damping(phase[1]);
    integrator->initialize(dynamics, t, dynamics.compress(q, v));
    const double t_end = t + phase[0];
    while (integrator->time() < t_end - 1e-12) {
      if (integrator->step(t_end) != StepStatus::Ok)
        throw std::runtime_error(model.source_file + ": the action does not settle at rest (" +
                                 integrator->failure_reason() + ")");
    }
    t = integrator->time();
    dynamics.expand(t, integrator->state(), q, v);
  }
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(q[i]) || std::abs(v[i]) > 1e-2)
      throw std::runtime_error(model.source_file + ": the action does not come to rest (joint '" +
                               model.bodies[i].name + "' still moves)");
  RestState rest;
  rest.q = q;
  rest.hammer_string_gap = dynamics.hammer_string_gap(q);
  return rest;
}

SimulationResult simulate(const ActionModel& model, const KeyInput* input,
                          const SimulationOptions& options, const RestState* given_rest) {
  SimulationResult result;
  result.rest = given_rest ? *given_rest : find_rest_state(model);
  const DofVector& q_rest = result.rest.q;
  const int n = model.dofs();
  const ActionLandmarks& marks = model.landmarks;

  ActionDynamics dynamics(model, input);
  dynamics.set_key_rest_angle(q_rest[marks.key]);
  auto integrator = make_integrator(options.integrator, options.integrator_options);
  DofVector q0 = q_rest, v0 = DofVector::Zero(n);
  integrator->initialize(dynamics, 0.0, dynamics.compress(q0, v0));
  dynamics.expand(0.0, integrator->state(), q0, v0);

  if (options.sample_interval_s > 0.0) {
    result.trace.columns = trace_columns(model);
    result.trace.metadata["action"] = model.kind;
    result.trace.metadata["preset"] = model.source_file;
    result.trace.metadata["input"] = input ? input->spec() : "none";
    result.trace.metadata["integrator"] = options.integrator;
    std::string settings, removed;
    for (const Adjuster& a : model.adjusters)
      if (a.value != 0.0)
        settings += (settings.empty() ? "" : " ") + a.name + "=" + format_mm(a.value) + "mm";
    for (const std::string& part : model.removed_parts)
      removed += (removed.empty() ? "" : " ") + part;
    result.trace.metadata["settings"] = settings.empty() ? "regulated" : settings;
    if (!removed.empty()) result.trace.metadata["without"] = removed;
  }
  DynamicsReading reading;
  auto record = [&](double t, const DofVector& q, const DofVector& v) {
    dynamics.evaluate(t, q, v, reading);
    std::vector<double> row;
    row.reserve(result.trace.columns.size());
    row.push_back(t);
    for (int k = 0; k < n; ++k) row.push_back(model.bodies[k].trace_sign * deg(q[k] - q_rest[k]));
    row.push_back(dynamics.hammer_string_gap(q) * 1e3);
    row.push_back(reading.finger_force);
    for (const ContactReading& c : reading.contacts) row.push_back(c.normal_force);
    for (double tension : reading.strap_tension) row.push_back(tension);
    result.trace.rows.push_back(std::move(row));
  };
  double next_sample = 0.0;
  if (options.sample_interval_s > 0.0) {
    record(0.0, q0, v0);
    next_sample = options.sample_interval_s;
  }

  // contact penetrations at step ends (geometry only) drive events and the stop check
  std::vector<double> previous, current;
  dynamics.contact_penetrations(q0, previous);
  bool impact_since_check = false;
  double last_key_bottom = -1.0;
  double last_letoff_active = -1.0;
  DofVector q1, v1, qs, vs;
  const auto wall_start = std::chrono::steady_clock::now();
  const double t_end = options.duration_s;

  while (integrator->time() < t_end - 1e-12) {
    const double t0 = integrator->time();
    if (integrator->step(t_end) != StepStatus::Ok) {
      result.status = "stopped";
      result.stop_cause = "the integrator failed: " + integrator->failure_reason();
      break;
    }
    const double t1 = integrator->time();
    dynamics.expand(t1, integrator->state(), q1, v1);
    bool finite = true;
    for (int i = 0; i < n; ++i) finite = finite && std::isfinite(q1[i]) && std::isfinite(v1[i]);
    if (!finite) {
      result.status = "stopped";
      result.stop_cause = "the simulation diverged (non-finite state)";
      break;
    }
    dynamics.contact_penetrations(q1, current);

    // unphysical penetration ends the run, naming the contact and its two parts
    for (std::size_t c = 0; c < model.contacts.size(); ++c) {
      const Contact& contact = model.contacts[c];
      if (current[c] > contact.max_penetration) {
        result.status = "stopped";
        result.stop_cause = "unphysical penetration in contact '" + contact.name + "' (" +
                            part_name(model, contact.body_a) + " into " +
                            part_name(model, contact.body_b) + "): " + format_mm(current[c]) +
                            " mm, limit " + format_mm(contact.max_penetration) + " mm";
        break;
      }
    }

    // events
    auto became_active = [&](int c) { return c >= 0 && current[c] > 0.0 && previous[c] <= 0.0; };
    auto gap_at = [&](const DofVector& q) { return dynamics.hammer_string_gap(q); };
    if (marks.letoff_contact >= 0 && current[marks.letoff_contact] > 0.0) last_letoff_active = t1;
    if (marks.escapement_contact >= 0 && previous[marks.escapement_contact] > 0.0 &&
        current[marks.escapement_contact] <= 0.0 && last_letoff_active >= 0.0 &&
        t1 - last_letoff_active < 2e-3) {
      result.events.push_back({"escapement", t1, 0.0, gap_at(q1)});
    }
    if (became_active(marks.string_contact)) {
      // strike-point speed toward the string just before contact
      const Vec2 vel = dynamics.point_velocity(marks.hammer, marks.strike_point, q0, v0);
      result.events.push_back({"impact", t1, -marks.string_normal.dot(vel), gap_at(q1)});
      impact_since_check = true;
    }
    if (became_active(marks.check_contact) && impact_since_check) {
      result.events.push_back({"check", t1, 0.0, gap_at(q1)});
      impact_since_check = false;
    }
    if (became_active(marks.key_bottom_contact)) {
      if (last_key_bottom < 0.0 || t1 - last_key_bottom > 5e-3)
        result.events.push_back({"key_bottom", t1, 0.0, gap_at(q1)});
      last_key_bottom = t1;
    } else if (marks.key_bottom_contact >= 0 && current[marks.key_bottom_contact] > 0.0) {
      last_key_bottom = t1;
    }

    // trace rows on the sampling grid, interpolated between step ends
    while (options.sample_interval_s > 0.0 && next_sample <= t1 + 1e-12) {
      hermite(t0, q0, v0, t1, q1, v1, next_sample, qs, vs);
      record(next_sample, qs, vs);
      next_sample += options.sample_interval_s;
    }
    q0 = q1;
    v0 = v1;
    std::swap(previous, current);
    if (result.status != "ok") break;
    if (options.on_step && !options.on_step(t1)) {
      result.status = "stopped";
      result.stop_cause = "cancelled";
      break;
    }
  }
  const auto wall_end = std::chrono::steady_clock::now();
  result.end_time = integrator->time();
  result.steps = integrator->stats().steps;
  result.rhs_evaluations = integrator->stats().rhs_evaluations;
  result.wall_time_s = std::chrono::duration<double>(wall_end - wall_start).count();
  result.realtime_factor = result.wall_time_s > 0.0 ? result.end_time / result.wall_time_s : 0.0;
  return result;
}

}  // namespace pat

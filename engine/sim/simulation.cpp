#include "sim/simulation.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/format.h"
#include "dynamics/action_dynamics.h"
#include "model/model_edits.h"
#include "sim/simulator.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

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
  auto settle = [&] {
    for (const auto& phase : phases) {
      dynamics.set_settling_damping(phase[1]);
      integrator->initialize(dynamics, t, dynamics.compress(q, v));
      const double t_end = t + phase[0];
      while (integrator->time() < t_end - 1e-12) {
        if (integrator->step(t_end) != StepStatus::Ok)
          throw std::runtime_error(model_origin(model) + ": the action does not settle at rest (" +
                                   integrator->failure_reason() + ")");
      }
      t = integrator->time();
      dynamics.expand(t, integrator->state(), q, v);
    }
  };
  // The settle ends with the felts still creeping (joint speeds up to 1e-2 rad/s) or a joint
  // chattering on a stiff felt: polish to the static equilibrium next to where it is, so that the
  // rest state is the same equilibrium whichever way it was reached (a settle, or Newton
  // continuation from a neighbouring model in the regulation) and the measurements taken from it
  // repeat to well below their tolerances. A part still swinging slowly far from it (the
  // repetition lever floating on its spring under the hammer when the whippen sits low) gets
  // two more settles.
  for (int round = 0;; ++round) {
    settle();
    DofVector q_static;
    if (q.allFinite() && solve_static_equilibrium(model, q, q_static) &&
        (q_static - q).cwiseAbs().maxCoeff() < 0.05) {
      q = q_static;
      break;
    }
    int moving = -1;
    for (int i = 0; i < n && moving < 0; ++i)
      if (!std::isfinite(q[i]) || std::abs(v[i]) > 1e-2) moving = i;
    if (moving < 0) break;
    if (round == 2 || !q.allFinite())
      throw std::runtime_error(model_origin(model) + ": the action does not come to rest (joint '" +
                               model.bodies[moving].name + "' still moves)");
  }
  RestState rest;
  rest.q = q;
  rest.hammer_string_gap = dynamics.hammer_string_gap(q);
  return rest;
}

void check_trace_rows(double duration_s, double sample_interval_s) {
  // a trace row holds every angle and contact force (about 30 numbers): 5 million rows are over
  // a gigabyte; more than that is a slip in the sampling interval or the duration
  constexpr double kMaxTraceRows = 5e6;
  if (sample_interval_s > 0.0 && duration_s / sample_interval_s > kMaxTraceRows)
    throw InputError("sampling every " + format_number(sample_interval_s) + " s for " +
                     format_number(duration_s) + " s makes more than 5 million trace " +
                     "rows: sample less often or simulate a shorter time");
}

SimulationResult simulate(const ActionModel& model, const KeyInput* input,
                          const SimulationOptions& options, const RestState* given_rest) {
  check_trace_rows(options.duration_s, options.sample_interval_s);  // before any work
  // the caller owns model and input for the whole call
  Simulator sim(borrow(model), input ? borrow(*input) : nullptr, options, given_rest);
  SimulationResult result;
  result.rest = sim.rest();

  if (options.sample_interval_s > 0.0) {
    result.trace.columns = trace_columns(model);
    result.trace.metadata = model_metadata(model);
    result.trace.metadata["input"] = input ? input->spec() : "none";
    result.trace.metadata["integrator"] = options.integrator;
  }
  auto record = [&](double t, const DofVector& q, const DofVector& v) {
    result.trace.rows.push_back(sim.trace_row(t, q, v));
  };
  // sample k at k·interval, computed as k / rate when the rate is a whole number of samples per
  // second (1e4 for 1e-4 s), so that the times are the decimals they stand for (0.0003, not the
  // 0.00030000000000000003 of 3·1e-4 or of a running sum)
  std::size_t sample_index = 0;
  const double rate = options.sample_interval_s > 0.0 ? 1.0 / options.sample_interval_s : 0.0;
  const double whole_rate = std::round(rate);  // samples per second, when a whole number
  const bool is_whole = rate > 0.0 && std::abs(rate - whole_rate) <= 1e-9 * rate;
  auto sample_time = [&](std::size_t k) {
    return is_whole ? static_cast<double>(k) / whole_rate
                    : static_cast<double>(k) * options.sample_interval_s;
  };
  double next_sample = 0.0;
  if (options.sample_interval_s > 0.0) {
    record(0.0, sim.q(), sim.v());
    next_sample = sample_time(++sample_index);
  }

  DofVector qs, vs;
  const auto wall_start = std::chrono::steady_clock::now();
  const double t_end = options.duration_s;
  while (sim.time() < t_end - 1e-12) {
    const bool running = sim.step(t_end);
    // trace rows on the sampling grid, interpolated between step ends (the failing step too,
    // when it produced a finite state)
    while (options.sample_interval_s > 0.0 && next_sample <= sim.time() + 1e-12 &&
           sim.time() > sim.previous_time()) {
      if (std::abs(next_sample - sim.time()) <= 1e-12) {
        // a sample on the step end (the usual case: the sampling interval is a multiple of the
        // step) is the step end itself; the dynamics then reuse its memoized positions
        if (!sim.q().allFinite() || !sim.v().allFinite()) break;
        record(next_sample, sim.q(), sim.v());
        next_sample = sample_time(++sample_index);
        continue;
      }
      hermite(sim.previous_time(), sim.previous_q(), sim.previous_v(), sim.time(), sim.q(), sim.v(),
              next_sample, qs, vs);
      if (!qs.allFinite() || !vs.allFinite()) break;
      record(next_sample, qs, vs);
      next_sample = sample_time(++sample_index);
    }
    if (!running) break;
    if (options.on_step && !options.on_step(sim.time())) {
      sim.stop("cancelled");
      break;
    }
  }
  const auto wall_end = std::chrono::steady_clock::now();
  if (options.trace_final_state && options.sample_interval_s > 0.0 &&
      sim.time() > result.trace.rows.back()[0] + 1e-12 && sim.q().allFinite() &&
      sim.v().allFinite())
    record(sim.time(), sim.q(), sim.v());
  sim.finish_events();
  result.status = sim.stopped() ? "stopped" : "ok";
  result.stop_cause = sim.stop_cause();
  result.events = sim.events();
  result.end_time = reported_time(sim.time());
  result.steps = sim.steps();
  result.rhs_evaluations = sim.rhs_evaluations();
  result.wall_time_s = std::chrono::duration<double>(wall_end - wall_start).count();
  result.realtime_factor = result.wall_time_s > 0.0 ? result.end_time / result.wall_time_s : 0.0;
  return result;
}

}  // namespace pat

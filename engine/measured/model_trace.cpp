#include "measured/model_trace.h"

#include <cmath>

#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat {
namespace {

double interpolate(const std::vector<double>& v, double dt, double t) {
  if (v.empty()) return 0.0;
  if (t <= 0) return v.front();
  const double x = t / dt;
  const std::size_t i = static_cast<std::size_t>(x);
  if (i + 1 >= v.size()) return v.back();
  const double f = x - static_cast<double>(i);
  return v[i] + f * (v[i + 1] - v[i]);
}

}  // namespace

double ModelTrace::hammer_at(double t) const {
  return interpolate(hammer_deg, dt, t);
}
double ModelTrace::key_at(double t) const {
  return interpolate(key_deg, dt, t);
}

ModelTrace simulate_trace(const ActionModel& model, const std::string& input_spec,
                          double duration_s, double dt, const RestState* known_rest) {
  const RestState rest = known_rest ? *known_rest : find_rest_state(model);
  const auto input = parse_input_spec(input_spec, input_context(model, rest));
  SimulationOptions options;
  options.duration_s = duration_s;
  options.sample_interval_s = dt;
  const SimulationResult result = simulate(model, input.get(), options, &rest);
  ModelTrace out;
  out.dt = dt;
  const int hammer_col = result.trace.column_index("hammer_angle_deg");
  const int key_col = result.trace.column_index("key_angle_deg");
  const int time_col = result.trace.column_index("time_s");
  const std::size_t n = static_cast<std::size_t>(std::floor(duration_s / dt + 1e-9)) + 1;
  out.hammer_deg.reserve(n);
  out.key_deg.reserve(n);
  std::size_t row = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    while (row + 1 < result.trace.rows.size() && result.trace.rows[row + 1][time_col] <= t + 1e-12)
      ++row;
    if (result.trace.rows.empty()) {
      out.hammer_deg.push_back(0.0);
      out.key_deg.push_back(0.0);
    } else {
      out.hammer_deg.push_back(result.trace.rows[row][hammer_col]);
      out.key_deg.push_back(result.trace.rows[row][key_col]);
    }
    if (!input->is_motion() && input->added_mass_kg() == 0.0)
      out.key_force_n.push_back(input->force_n(t));
  }
  out.completed = result.status == "ok";
  out.stop_cause = result.stop_cause;
  for (const SimEvent& e : result.events) {
    if (e.type == "impact") out.impact_t.push_back(e.t);
    if (e.type == "escapement") out.escapement_t.push_back(e.t);
    if (e.type == "check") out.check_t.push_back(e.t);
  }
  return out;
}

}  // namespace pat

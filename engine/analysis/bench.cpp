#include "analysis/bench.h"

#include <cmath>
#include <sstream>

#include "model/preset_loader.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat {
namespace {

std::vector<double> hammer_angles(const SimulationResult& result, const ActionModel& model) {
  const std::string column = column_name(model.bodies[model.landmarks.hammer].name) + "_angle_deg";
  return result.trace.column(column);
}

std::string format_setting(const char* name, double value) {
  std::ostringstream out;
  out << name << "=" << value;
  return out.str();
}

}  // namespace

std::vector<BenchCase> run_bench(const BenchOptions& options) {
  std::vector<BenchCase> cases;
  for (const std::string& action : options.actions) {
    const ActionModel model = load_action(action);
    const RestState rest = find_rest_state(model);
    const auto input = parse_input_spec(options.input, input_context(model, rest));

    SimulationOptions reference_options;
    reference_options.duration_s = options.duration_s;
    reference_options.integrator = "rodas";
    reference_options.integrator_options.relative_tolerance = 1e-9;
    reference_options.integrator_options.absolute_tolerance = 1e-11;
    const SimulationResult reference = simulate(model, input.get(), reference_options, &rest);
    const std::vector<double> truth = hammer_angles(reference, model);
    double lo = 0.0, hi = 0.0;
    for (double x : truth) lo = std::min(lo, x), hi = std::max(hi, x);

    struct Variant {
      const char* integrator;
      const char* label;
      double value;
    };
    const Variant variants[] = {{"w2", "h_s", 1e-5},     {"rodas", "rtol", 1e-6},
                                {"cvode", "rtol", 1e-4}, {"cvode", "rtol", 1e-5},
                                {"cvode", "rtol", 1e-6}, {"cvode", "rtol", 1e-7}};
    for (const Variant& v : variants) {
      SimulationOptions o;
      o.duration_s = options.duration_s;
      o.integrator = v.integrator;
      if (std::string(v.integrator) == "w2") {
        o.integrator_options.fixed_step_s = v.value;
      } else {
        o.integrator_options.relative_tolerance = v.value;
        o.integrator_options.absolute_tolerance = v.value * 1e-2;
      }
      const SimulationResult run = simulate(model, input.get(), o, &rest);
      const std::vector<double> angles = hammer_angles(run, model);
      BenchCase c;
      c.action = action;
      c.integrator = v.integrator;
      c.setting = format_setting(v.label, v.value);
      c.realtime_factor = run.realtime_factor;
      c.wall_time_s = run.wall_time_s;
      c.steps = run.steps;
      c.hammer_range_deg = hi - lo;
      const std::size_t n = std::min(angles.size(), truth.size());
      for (std::size_t i = 0; i < n; ++i)
        c.max_error_deg = std::max(c.max_error_deg, std::abs(angles[i] - truth[i]));
      if (angles.size() != truth.size()) c.max_error_deg = INFINITY;  // the run stopped early
      cases.push_back(c);
    }
  }
  return cases;
}

std::vector<EqualAccuracy> compare_at_equal_accuracy(const std::vector<BenchCase>& cases) {
  std::vector<EqualAccuracy> comparisons;
  for (const BenchCase& w2 : cases) {
    if (w2.integrator != "w2") continue;
    EqualAccuracy e;
    e.action = w2.action;
    e.w2_realtime_factor = w2.realtime_factor;
    e.w2_error_deg = w2.max_error_deg;
    for (const BenchCase& c : cases) {
      if (c.action != w2.action || c.integrator != "cvode" ||
          !(c.max_error_deg <= w2.max_error_deg))
        continue;
      if (!e.cvode || c.realtime_factor > e.cvode->realtime_factor) e.cvode = c;
    }
    if (e.cvode && e.cvode->realtime_factor > 0.0)
      e.ratio = w2.realtime_factor / e.cvode->realtime_factor;
    comparisons.push_back(e);
  }
  return comparisons;
}

}  // namespace pat

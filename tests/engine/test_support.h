// Shared helpers for the engine tests: loading the shipped presets and running them.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "inputs/key_input.h"
#include "model/preset_loader.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat::test {

/// The message of the InputError `f` throws, or "no error".
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

inline ActionModel shipped(const std::string& name) {
  return load_action(std::string(PAT_PRESET_DIR) + "/" + name + ".json");
}

/// Simulates a shipped-style model under an input SPEC with the default W-method.
inline SimulationResult run(const ActionModel& model, const std::string& spec, double duration,
                            const std::string& integrator = "w2", double rtol = 1e-6) {
  const RestState rest = find_rest_state(model);
  const auto input = parse_input_spec(spec, input_context(model, rest));
  SimulationOptions options;
  options.duration_s = duration;
  options.integrator = integrator;
  options.integrator_options.relative_tolerance = rtol;
  options.integrator_options.absolute_tolerance = rtol * 1e-2;
  return simulate(model, input.get(), options, &rest);
}

inline std::vector<const SimEvent*> events_of(const SimulationResult& r, const std::string& type) {
  std::vector<const SimEvent*> out;
  for (const SimEvent& e : r.events)
    if (e.type == type) out.push_back(&e);
  return out;
}

}  // namespace pat::test

// Creates an integrator by its command-line name.
#pragma once

#include <memory>
#include <string>

#include "integrators/ode_system.h"

namespace pat {

struct IntegratorOptions {
  double fixed_step_s = 1e-5;        ///< w2: step size
  int jacobian_refresh_steps = 20;   ///< w2: Jacobian age limit (also refreshed on regime change)
  double relative_tolerance = 1e-6;  ///< rodas, cvode
  double absolute_tolerance = 1e-8;  ///< rodas, cvode (on every component of y)
  double max_step_s = 1e-3;          ///< rodas, cvode: largest step allowed
};

/// name: "w2", "rodas" or "cvode". Throws InputError for any other name.
std::unique_ptr<Integrator> make_integrator(const std::string& name,
                                            const IntegratorOptions& options);

}  // namespace pat

// Creates an integrator by its command-line name.
#pragma once

#include <memory>
#include <string>

#include "integrators/ode_system.h"

namespace pat {

/// A w2 step (s) that resolves a key held after a blow: the hammer's tail wedged on the grand's
/// backcheck, held by the leather's stiff regularized friction (README, Limits). At the default
/// 1e-5 s w2 chatters there; from this step on it agrees with the references. The window uses it.
inline constexpr double kW2HeldKeyStepS = 5e-6;

struct IntegratorOptions {
  double fixed_step_s = 1e-5;  ///< w2: step size
  /// w2: Jacobian age limit in steps (it is also refreshed on a regime change)
  int jacobian_refresh_steps = 200;
  /// w2: between those refreshes, the velocity block of J is refreshed every this many steps
  /// from the system's closed form (OdeSystem::velocity_jacobian) where it has one; 0: never.
  /// Measured on the grand's bench double blow (1 s, h = 1e-5 s): the hammer error against the
  /// reference moved between 0.15 % and 1.4 % of its range with the age limit alone (20 to 200
  /// steps; the felts' hysteresis and the friction are kinked in the rates, so a frozen velocity
  /// block is right or wrong by chance), and stays at 0.10 % with this refresh every 5 steps,
  /// for any age limit from 20 to 2000. The position block matters little there.
  int velocity_jacobian_steps = 5;
  double relative_tolerance = 1e-6;  ///< rodas, cvode
  double absolute_tolerance = 1e-8;  ///< rodas, cvode (on every component of y)
  double max_step_s = 1e-3;          ///< rodas, cvode: largest step allowed
};

/// name: "w2", "rodas" or "cvode". Throws InputError for any other name.
std::unique_ptr<Integrator> make_integrator(const std::string& name,
                                            const IntegratorOptions& options);

}  // namespace pat

// Static touchweight (Stanwood's metrology, domain.md section 4), found the way a technician
// finds it with weights at the key front: the key is pressed (or let rise) so slowly that
// inertia vanishes and every joint and contact that moves is fully in its Coulomb friction.
//
// Quasi-static limit, by virtual work at each key-front dip y (the key held, every other body in
// static equilibrium, q(y) by Newton):
//   F0(y)   = the frictionless balance force at the key front (the key row's residual)
//   Ff(y)   = Σ_joints A_j |dq_j/dy|  +  Σ_contacts μ_c F_n,c |ds_c/dy|
//             (A: eq. 4's Coulomb level; s_c: tangential slip of a rubbing contact; dq/dy by
//              central differences of the equilibria; first order in μ: the friction's own
//              effect on the normal forces is left out)
//   going down:  F_down(y) = F0 + Ff,   rising:  F_up(y) = F0 − Ff.
// Downweight DW and upweight UW are the work-equivalent weights over the measuring window:
// DW = (1/Δy) ∫ F_down dy, UW = (1/Δy) ∫ F_up dy (trapezoid rule), in grams (F / g) — the
// weight that takes the key through the window at a steady slow pace doing the same work. (The
// largest F_down / smallest F_up would mix the lever-ratio change along the stroke into the
// friction weight: a frictionless action would show one.) Balance weight BW = (DW + UW)/2, friction
// weight F = (DW − UW)/2. Key ratio KR = (horizontal arm of the capstan contact) / (horizontal arm
// of the key front), both from the balance pin at rest. Strike weight SW = m_h (c − o)·u / |s − o|:
// the hammer's weight read at the strike point s with the shank (o → s, unit u) horizontal. Front
// weight FW: the key alone on its pin, at the key front (positive: front heavy).
#pragma once

#include <string>
#include <vector>

#include "analysis/progress.h"
#include "io/csv.h"
#include "model/action_model.h"

namespace pat {

struct TouchweightOptions {
  /// Measuring window (key-front dip, mm): after the first millimetre, before the damper pickup
  /// (technicians weigh off without the dampers, which add their own load; the shipped grand's
  /// damper starts lifting at about 3.2 mm) and long before let-off.
  double window_start_mm = 1.0;
  double window_end_mm = 3.0;
  int positions = 9;  ///< equally spaced dips in the window (≥ 2)
};

struct TouchweightPoint {
  double dip_mm = 0.0;
  double balance_force_n = 0.0;   ///< F0
  double friction_force_n = 0.0;  ///< Ff
};

struct TouchweightResult {
  double downweight_g = 0.0;
  double upweight_g = 0.0;
  double balance_weight_g = 0.0;
  double friction_weight_g = 0.0;
  double key_ratio = 0.0;
  double strike_weight_g = 0.0;
  double front_weight_g = 0.0;
  /// How far the key front sinks by itself from its back rail (mm): 0 for a key that rests on
  /// it; a front-heavy key is weighed from the back rail, held there (balance weight < 0 g).
  double key_sinks_mm = 0.0;
  std::vector<TouchweightPoint> curve;
  /// dip_mm, downweight_g, upweight_g, balance_weight_g, friction_weight_g per position
  CsvTable table() const;
};

/// What a key that does not rest on its back rail by itself was weighed from, in a sentence
/// ("" for a key that rests there): front-heavy or not, how far its front sinks alone.
std::string key_rest_note(const TouchweightResult& result);

/// Measures the touchweight of `action` from its rest state (a key that does not rest on its
/// back rail by itself, from there: TouchweightResult::key_sinks_mm). Positions run in parallel
/// (run_parallel); `progress` (may be empty) counts them and can cancel (throws Cancelled).
/// Throws std::runtime_error when the held-key equilibrium cannot be found.
TouchweightResult measure_touchweight(const ActionModel& action,
                                      const TouchweightOptions& options = {},
                                      const ProgressCallback& progress = {});

}  // namespace pat

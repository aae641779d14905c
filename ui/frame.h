// One recorded instant of a running simulation: what the view draws and the plots show.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/types.h"
#include "model/action_model.h"

namespace pat::ui {

struct Frame {
  double t = 0.0;  ///< simulated time, s
  DofVector q;     ///< joint coordinates, rad
  DofVector v;     ///< joint rates, rad/s
  /// Trace angles (deg from rest, DESIGN.md section 5 signs), one per body.
  std::vector<double> angle_deg;
  double hammer_string_gap_mm = 0.0;
  double finger_force_n = 0.0;
  std::vector<double> contact_force_n;  ///< normal force of every contact
  std::vector<double> strap_tension_n;  ///< tension of every strap (the upright's bridle)
  /// Events (escapement, impact, check, key_bottom) found in the step that ended here.
  std::vector<std::string> events;
  /// The model this frame was computed with (adjusters change while the action runs).
  std::shared_ptr<const ActionModel> model;
  int run = 0;  ///< the run it belongs to (frames of a replaced run are dropped)
  /// Inputs asked for from the window (a blow, a grab of the key) up to this serial number took
  /// effect since the frame before, at simulated time inputs_applied_t (s); 0: none did.
  int inputs_applied_through = 0;
  double inputs_applied_t = 0.0;
};

}  // namespace pat::ui

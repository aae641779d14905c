// A key input for a measured strike whose input was not recorded (the real sensor traces in
// shared/data have only the hammer): a parameterised finger force per strike, a pulse
// force:pulse:N:MS whose force N makes the model's rise time (motion onset to impact) equal the
// measured one and whose length MS follows how long the hammer is held in check (a trace that
// ends with the hammer still held gets a pulse that outlasts the 0.5 s kept of it).
#pragma once

#include <string>

#include "measured/measured_data.h"
#include "model/action_model.h"

namespace pat {

struct EstimatedInput {
  std::string spec;  ///< force:pulse:N:MS
  double force_n = 0.0;
  double pulse_ms = 0.0;
  double measured_rise_s = 0.0;
  double model_rise_s = 0.0;
  /// The first strike of the trial, its time axis moved so that the motion onset falls at the
  /// model's onset under the estimated input (at most 0.5 s kept).
  MeasuredTrial trial;
  double file_shift_s = 0.0;  ///< time in the file = time in `trial` + file_shift_s
};

/// Throws InputError naming the file when no strike is visible in its hammer trace.
EstimatedInput estimate_key_input(const ActionModel& model, const MeasuredTrial& trial);

}  // namespace pat

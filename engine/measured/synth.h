// Measured-like data from the model (pianoaction synth, DESIGN.md sections 4 and 5): the model
// with effects hidden in it, sampled like a high-speed camera, with Gaussian noise and a
// calibration error (time and angle offsets), seeded.
#pragma once

#include <string>
#include <vector>

#include "io/csv.h"
#include "model/action_model.h"
#include "model/effects.h"

namespace pat {

struct SynthOptions {
  double duration_s = 0.5;        ///< length of the written trace, s
  std::vector<Effect> effects;    ///< hidden in the model, applied in order
  double noise_deg = 0.0;         ///< σ of the Gaussian noise on the angles, deg
  double fps = 2000.0;            ///< samples per second
  double time_offset_s = 0.0;     ///< file time = model time + offset
  double angle_offset_deg = 0.0;  ///< added to the hammer angle (calibration error)
  unsigned long long seed = 1;
};

/// The trace in the measured-data format: "# action:", "# input:" metadata (plus the synth
/// settings under "# synth_*" keys, which the diagnosis never reads), columns time_s,
/// hammer_angle_deg, key_angle_deg, and key_force_n for force inputs. Samples at k/fps for
/// k = 0 … duration·fps; before the input starts (model time < 0) the action is at rest.
/// Throws InputError for bad options or effects, std::runtime_error if the run stops.
CsvTable synthesize(const ActionModel& model, const std::string& input_spec,
                    const SynthOptions& options);

}  // namespace pat

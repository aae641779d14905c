// Alignment of a model trace with a measured trace: the nuisance offsets of a measurement
// (a time offset of its clock and an angle offset of its calibration) are estimated by least
// squares, and the residual that remains is what the model gets wrong.
//
//   measured(t_i) ≈ model(t_i − δt) + δθ,   δθ = mean of measured(t_i) − model(t_i − δt),
//   δt ∈ [−max_shift, max_shift] minimises Σ r_i²: a 0.2 ms grid, then golden-section search
//   in the best grid cell (the cost is smooth in δt at that scale because the model trace is
//   interpolated linearly on a 0.1 ms grid). max_shift = 0: δt = 0 (a model driven by the
//   file's own key column runs on the file's clock).
#pragma once

#include <vector>

#include "measured/measured_data.h"
#include "measured/model_trace.h"

namespace pat {

struct Alignment {
  double time_offset_s = 0.0;     ///< δt: file time = model time + δt
  double angle_offset_deg = 0.0;  ///< δθ
  std::vector<double> residual;   ///< measured − aligned model, deg, one per sample
  double rss = 0.0;               ///< Σ residual², deg²
};

Alignment align(const MeasuredTrial& trial, const ModelTrace& model, double max_shift_s = 10e-3);

}  // namespace pat

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

#include <cstddef>
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

/// Samples at rest a trial needs before its angle offset is taken from them (5 ms at 2000 fps;
/// with the noise σ the offset is then known to σ/√10 ≈ 0.3 σ).
inline constexpr std::size_t kMinRestSamplesForOffset = 10;

/// The same alignment with the angle offset taken where the model cannot be wrong but for the
/// calibration, the action at rest (`at_rest`, one flag per sample): the mean residual there
/// goes into δθ, and the residual and Σ r² follow. align()'s least-squares δθ is the mean of the
/// whole residual, so a model wrong during the stroke (a flexing shank: 3.5° rms in the check)
/// would show its mean error where it is right (5.1° "at rest"); that offset stays the one the
/// fits use. Unchanged with fewer than kMinRestSamplesForOffset samples at rest.
Alignment referenced_to_rest(const Alignment& alignment, const std::vector<bool>& at_rest);

}  // namespace pat

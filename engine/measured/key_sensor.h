// The key's own sensor in a raw recording (hammer_damper_2K_17b.txt column 2 of shared/data: a
// CNY-70 under the back of the key, calibrated by the data set's author as the displacement at
// the key front) turned into key angles, so that the measured key motion can drive the model
// (DESIGN.md section 4.1) instead of an estimated finger force.
//
//   d(r)  = p(r) − p_rest                       key-front dip, in → m (× 0.0254)
//   θ     = asin(d / a)                         key angle from rest, down positive (deg)
//
// p(r) is the calibration's position at reading r (monotone cubic, sensor_calibration.h), p_rest
// the median position over the window's first 50 ms (the key at rest), and a the horizontal
// distance from the key's balance pin to its front (the model's key_front landmark: 220 mm on
// the grand). The front also stands h = 22 mm above the pin: its drop is a·sin θ + h·(1 − cos θ),
// and the second term is at most 0.03 mm at 3° (left out); it also moves h·sin θ ≈ 1.2 mm
// sideways, which a sensor under the key does not see.
//
// Smoothing. Near rest the sensor barely responds (its first calibration step is 1/32 in of
// key travel for 0.0015 of normalized reading), so its noise there is about ±0.1 mm of key
// front. A prescribed key motion is differentiated twice (the spline of the csv input gives the
// key's acceleration), which turns that noise at 2000 samples/s into accelerations of hundreds
// of m/s², as large as a real press. The dip is therefore smoothed by a Gaussian of σ = 2 ms
// (zero phase, truncated at 3σ, renormalized at the window's ends): the acceleration noise
// drops to about 6 m/s² at the key front (σ_n √(Δt · 3 / (8 √π σ⁵))) while a press, 20–40 ms
// from rest to the punching, keeps its shape (its corners are rounded by about 2 ms).
#pragma once

#include <string>
#include <vector>

#include "measured/sensor_calibration.h"
#include "model/action_model.h"

namespace pat {

/// Gaussian smoothing width of the key trace (s); see the file comment.
inline constexpr double kKeySmoothingSigmaS = 2e-3;

struct KeyAngles {
  std::vector<double> angle_deg;  ///< smoothed key angle from rest, down positive
  double rest_position_in = 0.0;  ///< p_rest
  double front_arm_m = 0.0;       ///< a
  double deepest_dip_mm = 0.0;    ///< the largest smoothed key-front dip in the window
};

/// The key front's horizontal distance from the key's pivot (m) in `model`. Throws InputError
/// naming the preset when the key front stands on the pivot's vertical.
double key_front_arm_m(const ActionModel& model);

/// Key angles for a window of readings (fraction of the ADC's full scale) sampled at `rate_hz`
/// (at least 5 samples of rest; the caller has checked the window's length). Throws InputError
/// naming the calibration file when a reading's dip exceeds a fifth of the key front's arm (no
/// key dips so far), or when the key only rises above its rest by more than 1 mm and never
/// goes down as far (a sensor that runs against its points).
KeyAngles key_angles_from_sensor(const std::vector<double>& reading, double rate_hz,
                                 const SensorCalibration& calibration, double front_arm_m);

}  // namespace pat

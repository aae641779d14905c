#include "measured/key_sensor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/format.h"
#include "measured/rest_level.h"

namespace pat {

namespace {

constexpr double kMetresPerInch = 0.0254;
/// A key front dips about 10 mm on an arm of about 220 mm: a fifth of the arm (44 mm) is no key.
constexpr double kMostDipOfArm = 0.2;
/// Less than this (m) is no press: a window whose dips stay under it and go as far above rest
/// has a sensor running against its points.
constexpr double kLeastPressM = 1e-3;

/// Zero-phase Gaussian smoothing of σ = sigma_samples, truncated at 3σ; near the ends the
/// weights that fall inside are renormalized.
std::vector<double> gaussian_smoothed(const std::vector<double>& x, double sigma_samples) {
  const int half = static_cast<int>(std::ceil(3.0 * sigma_samples));
  std::vector<double> weight(static_cast<std::size_t>(2 * half + 1));
  for (int k = -half; k <= half; ++k)
    weight[static_cast<std::size_t>(k + half)] =
        std::exp(-0.5 * (k / sigma_samples) * (k / sigma_samples));
  const int n = static_cast<int>(x.size());
  std::vector<double> out(x.size());
  for (int i = 0; i < n; ++i) {
    double sum = 0.0, total = 0.0;
    for (int k = std::max(-half, -i); k <= std::min(half, n - 1 - i); ++k) {
      const double w = weight[static_cast<std::size_t>(k + half)];
      sum += w * x[static_cast<std::size_t>(i + k)];
      total += w;
    }
    out[static_cast<std::size_t>(i)] = sum / total;
  }
  return out;
}

}  // namespace

double key_front_arm_m(const ActionModel& model) {
  const int key = model.landmarks.key;
  const double arm = std::abs(model.landmarks.key_front.x() -
                              model.bodies[static_cast<std::size_t>(key)].pivot.x());
  if (!(arm > 1e-3))
    throw InputError(located_message(model.source_file, "landmarks.key_front_mm",
                                     "the key front stands on the key's pivot, so a key-front "
                                     "dip has no key angle"));
  return arm;
}

KeyAngles key_angles_from_sensor(const std::vector<double>& reading, double rate_hz,
                                 const SensorCalibration& calibration, double front_arm_m) {
  KeyAngles out;
  out.front_arm_m = front_arm_m;
  std::vector<double> position(reading.size());
  for (std::size_t i = 0; i < reading.size(); ++i)
    position[i] = calibration.position_at(reading[i]);
  const std::size_t rest_count = rest_sample_count(reading.size(), rate_hz);
  out.rest_position_in = median(std::vector<double>(
      position.begin(), position.begin() + static_cast<std::ptrdiff_t>(rest_count)));
  std::vector<double> dip_m(position.size());
  double deepest_raw_m = 0.0;
  for (std::size_t i = 0; i < position.size(); ++i) {
    dip_m[i] = (position[i] - out.rest_position_in) * kMetresPerInch;
    deepest_raw_m = std::max(deepest_raw_m, dip_m[i]);
    // checked before smoothing, so that the sample named is the one that reads so
    if (std::abs(dip_m[i]) > kMostDipOfArm * front_arm_m) {
      std::ostringstream problem;
      problem << "the key sensor's reading " << reading[i] << " (sample " << i
              << " of the window) gives a key-front dip of " << format_fixed(1e3 * dip_m[i], 1)
              << " mm, more than a fifth of the key front's " << format_fixed(1e3 * front_arm_m, 0)
              << " mm arm (a key dips about 10 mm): these points do not calibrate this sensor";
      throw InputError(located_message(calibration.path, "", problem.str()));
    }
  }
  // a key pressed moves its front down: readings that only go the other way belong to a sensor
  // that runs opposite to these points (another sensor's rows?)
  const double shallowest_raw_m = *std::min_element(dip_m.begin(), dip_m.end());
  if (deepest_raw_m < kLeastPressM && shallowest_raw_m < -kLeastPressM) {
    std::ostringstream problem;
    problem << "the key sensor's readings give key-front dips from "
            << format_fixed(1e3 * shallowest_raw_m, 2) << " to "
            << format_fixed(1e3 * deepest_raw_m, 2)
            << " mm: the key only rises above its rest, so the reading runs the other way from "
               "these points (another sensor's rows?)";
    throw InputError(located_message(calibration.path, "", problem.str()));
  }
  dip_m = gaussian_smoothed(dip_m, kKeySmoothingSigmaS * rate_hz);
  out.angle_deg.resize(dip_m.size());
  for (std::size_t i = 0; i < dip_m.size(); ++i) {
    out.angle_deg[i] = std::asin(dip_m[i] / front_arm_m) * 180.0 / kPi;  // |dip| < arm / 5
    out.deepest_dip_mm = std::max(out.deepest_dip_mm, 1e3 * dip_m[i]);
  }
  return out;
}

}  // namespace pat

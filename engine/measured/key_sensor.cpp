#include "measured/key_sensor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace pat {

namespace {

constexpr double kMetresPerInch = 0.0254;

double median(std::vector<double> x) {
  const auto middle = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), middle, x.end());
  return *middle;
}

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
  // rest: the first 50 ms, at least 5 samples and at most a quarter of the window (as the hammer)
  const std::size_t rest_count = std::max<std::size_t>(
      5, std::min<std::size_t>(reading.size() / 4,
                               static_cast<std::size_t>(std::lround(0.05 * rate_hz))));
  out.rest_position_in = median(std::vector<double>(
      position.begin(), position.begin() + static_cast<std::ptrdiff_t>(rest_count)));
  std::vector<double> dip_m(position.size());
  for (std::size_t i = 0; i < position.size(); ++i)
    dip_m[i] = (position[i] - out.rest_position_in) * kMetresPerInch;
  dip_m = gaussian_smoothed(dip_m, kKeySmoothingSigmaS * rate_hz);
  out.angle_deg.resize(dip_m.size());
  for (std::size_t i = 0; i < dip_m.size(); ++i) {
    const double ratio = dip_m[i] / front_arm_m;
    if (std::abs(ratio) >= 1.0) {
      std::ostringstream problem;
      problem << "the key sensor's reading " << reading[i] << " gives a key-front dip of "
              << 1e3 * dip_m[i] << " mm, more than the key front's " << 1e3 * front_arm_m
              << " mm arm (sample " << i << " of the window): these points do not calibrate "
              << "a key-front displacement";
      throw InputError(located_message(calibration.path, "", problem.str()));
    }
    out.angle_deg[i] = std::asin(ratio) * 180.0 / kPi;
    out.deepest_dip_mm = std::max(out.deepest_dip_mm, 1e3 * dip_m[i]);
  }
  return out;
}

}  // namespace pat

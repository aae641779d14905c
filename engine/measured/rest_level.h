// The rest level at the start of a measured window, shared by the hammer's and the key's raw
// sensors (raw_import.h, key_sensor.h) and the noise estimate (measured_data.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pat {

/// Median of the values (the upper one of the two middle values for an even count); `x` must
/// not be empty.
inline double median(std::vector<double> x) {
  const auto middle = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), middle, x.end());
  return *middle;
}

/// The samples at the start of a window of `count` samples at `rate_hz` that are taken as the
/// part at rest: the first 50 ms, at least 5 and at most a quarter of the window.
inline std::size_t rest_sample_count(std::size_t count, double rate_hz) {
  return std::max<std::size_t>(
      5, std::min<std::size_t>(count / 4, static_cast<std::size_t>(std::lround(0.05 * rate_hz))));
}

}  // namespace pat

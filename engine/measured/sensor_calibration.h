// Calibration points of a position sensor (the format of shared/data/kawai-kg3c/calibration.csv,
// from the data set's author): '#' header lines, a header row with `position_in` (displacement at
// the sensor spot, inches) and `normalized_reading`, optionally `sensor` (e.g. hammer, damper),
// then one point per row. A header line gives, for each sensor, the offset and gain that make the
// ADC reading (fraction of full scale) a normalized reading:
//
//   normalized_reading = (reading − offset) / gain      "... hammer offset 0.69 gain 0.29 ..."
//
// The inverse curve, position(normalized_reading), is interpolated by a monotone piecewise cubic
// (Fritsch–Carlson: Hermite cubics whose slopes at the points are the weighted harmonic mean of
// the neighbouring secants, zero at a local extremum of the data), so a monotone set of points
// gives a monotone curve through every point, without the overshoot of a spline. Outside the
// points it continues along the first or last secant.
#pragma once

#include <string>
#include <vector>

namespace pat {

/// x → y through points with strictly increasing x and monotone y (Fritsch–Carlson).
class MonotoneCubic {
 public:
  MonotoneCubic() = default;
  /// `x` strictly increasing, `y` monotone, at least two points (not checked here: the caller
  /// validates user data with its own messages).
  MonotoneCubic(std::vector<double> x, std::vector<double> y);
  double operator()(double x) const;

 private:
  std::vector<double> x_, y_, slope_;
};

struct SensorCalibration {
  std::string path;
  std::string sensor;   ///< the rows used ("hammer"), empty when the file has no sensor column
  double offset = 0.0;  ///< ADC reading (fraction of full scale) at normalized reading 0
  double gain = 1.0;    ///< ADC reading change per unit normalized reading
  std::vector<double> normalized_reading;  ///< at the points, strictly monotone
  std::vector<double> position;            ///< at the points, in, strictly increasing
  MonotoneCubic position_of_reading;       ///< in, of the normalized reading
  /// The sensors of a file with a sensor column, in the order their rows first appear (the
  /// order of the recording's columns, as in the data set's calibration.csv); empty without.
  std::vector<std::string> sensors;
  /// The recording the points belong to, when a header line names it ("... points for
  /// NAME.txt ..."); empty when none does.
  std::string recording;

  /// Position at the sensor (in) for an ADC reading (fraction of full scale).
  double position_at(double reading) const {
    return position_of_reading((reading - offset) / gain);
  }
};

/// Reads calibration points; when the file has a `sensor` column only the rows of `sensor` are
/// used, and the offset and gain are the ones the header names for that sensor ("SENSOR offset X
/// gain Y"; without a sensor column: "offset X gain Y"). Throws InputError naming the file, the
/// line and the problem: missing file, missing column, a value that is not a number, no offset
/// and gain in the header, a zero gain, fewer than two points for the sensor, positions that do
/// not increase, or readings that are not strictly monotone (rising or falling) along them.
SensorCalibration read_sensor_calibration(const std::string& path, const std::string& sensor);

}  // namespace pat

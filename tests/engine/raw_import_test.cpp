// import-raw (engine/measured/raw_import.h): raw hammer-shank sensor traces turned into hammer
// angles. Synthetic raw traces are made from a known angle trace through a known sensor curve and
// must come back; the author's calibration points are interpolated monotonically; every kind of
// bad input is named.
#include "measured/raw_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>

#include "core/error.h"
#include "dynamics/action_dynamics.h"
#include "measured/measured_data.h"
#include "test_support.h"

namespace pat {
namespace {

constexpr double kRate = 2000.0;       // samples/s, as the paper's camera and the 2K files
constexpr double kContactDeg = 19.5;   // θ_c given to the import (the tests need no preset)
constexpr double kRoundingDeg = 1e-4;  // import_raw rounds angles to 1e-4 deg (error ≤ 5e-5)

/// A strike (deg): rest for 60 ms, a quadratic rise to θ_c in 20 ms (the peak falls on sample
/// 160), a half-cosine rebound to 60 % of θ_c in 15 ms, then held in check; 0.3 s in all.
std::vector<double> strike_angles() {
  std::vector<double> theta;
  for (int i = 0; i < 600; ++i) {
    const double t = i / kRate;
    double a = 0.0;
    if (t > 0.08)
      a = kContactDeg -
          0.4 * kContactDeg * (t < 0.095 ? 0.5 * (1 - std::cos(kPi * (t - 0.08) / 0.015)) : 1.0);
    else if (t > 0.06)
      a = kContactDeg * std::pow((t - 0.06) / 0.02, 2);
    theta.push_back(a);
  }
  return theta;
}

/// A strongly curved sensor like the CNY-70 (reading rises ever faster as the shank nears it):
/// fraction of the reading span at travel s ∈ [0, 1].
double curved(double s) {
  return (std::exp(3.0 * s) - 1.0) / (std::exp(3.0) - 1.0);
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("pat_rawimport_" + name)).string();
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

/// Writes readings (one a line) as normalized values or as 24-bit counts.
std::string write_raw(const std::string& name, const std::vector<double>& reading,
                      bool counts = false) {
  std::ostringstream text;
  text.precision(17);
  for (double r : reading) {
    if (counts)
      text << std::llround(r * 16777216.0) << "\n";
    else
      text << r << "\n";
  }
  return write_file(name, text.str());
}

std::vector<double> sensor(const std::vector<double>& theta,
                           const std::function<double(double)>& reading_of_deg) {
  std::vector<double> r;
  for (double a : theta) r.push_back(reading_of_deg(a));
  return r;
}

RawImport import_file(const std::string& path, const RawImportOptions& base = {}) {
  RawImportOptions o = base;
  o.rate_hz = o.rate_hz != 0 ? o.rate_hz : kRate;
  o.contact_angle_deg = kContactDeg;
  o.action = "grand";
  return import_raw(read_raw_trace(path, 1), o);
}

std::vector<double> angles(const RawImport& r) {
  std::vector<double> a;
  for (const auto& row : r.table.rows) a.push_back(row[1]);
  return a;
}

double max_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

/// The author's hammer points (shared/data/kawai-kg3c/calibration.csv, Greg Zweigle, MIT).
const char* kAuthorCalibration =
    "# Sensor calibration points for hammer_damper_2K_17b.txt (from the data set's author).\n"
    "# normalized_reading: (raw - offset) / gain, with hammer offset 0.69 gain 0.29, damper "
    "offset 0.3 gain 0.58.\n"
    "sensor,position_in,normalized_reading\n"
    "hammer,0.000000,0\nhammer,0.015625,0.015\nhammer,0.031250,0.04\nhammer,0.046875,0.11\n"
    "hammer,0.062500,0.17\nhammer,0.078125,0.28\nhammer,0.093750,0.39\nhammer,0.109375,0.57\n"
    "hammer,0.125000,0.75\nhammer,0.140625,0.9\nhammer,0.148438,1\n"
    "damper,0.00000,0\ndamper,0.03125,0.0015\ndamper,0.06250,0.0035\n";

TEST(RawImport, LinearSensorIsRecoveredExactly) {
  const std::vector<double> theta = strike_angles();
  const auto path =
      write_raw("linear.txt", sensor(theta, [](double a) { return 0.21 + 0.011 * a; }));
  const RawImport r = import_file(path);
  ASSERT_TRUE(r.strike);
  EXPECT_FALSE(r.strike->reversed);
  EXPECT_EQ(r.strike->peak_index, 160u);
  EXPECT_NEAR(r.peak_t_s, 0.08, 1e-12);
  // the estimate is exact for a linear sensor: only the output rounding remains
  EXPECT_LE(max_error(angles(r), theta), kRoundingDeg);
  EXPECT_EQ(r.table.metadata.at("action"), "grand");
  EXPECT_NE(r.table.metadata.at("calibration").find("estimated"), std::string::npos);
  // the result is a valid measured-data table whose strike is found where the data peak
  const MeasuredTrial trial = measured_from_table(r.table, path, "grand");
  const auto events = detect_events(trial.t, trial.hammer_deg, 0.0);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().type, "impact");
  EXPECT_NEAR(events.front().t, 0.08, 0.5 / kRate);
}

TEST(RawImport, ReversedSensorGivesTheSameAngles) {
  // readings that fall as the hammer rises (a sensor on the other side of the shank)
  const std::vector<double> theta = strike_angles();
  const auto path =
      write_raw("reversed.txt", sensor(theta, [](double a) { return 0.8 - 0.011 * a; }));
  const RawImport r = import_file(path);
  ASSERT_TRUE(r.strike);
  EXPECT_TRUE(r.strike->reversed);
  EXPECT_LE(max_error(angles(r), theta), kRoundingDeg);
  EXPECT_NE(r.table.metadata.at("calibration").find("reversed sensor"), std::string::npos);
}

TEST(RawImport, CountsAndNormalizedReadingsGiveTheSameAngles) {
  const std::vector<double> theta = strike_angles();
  const auto reading = sensor(theta, [](double a) { return 0.215 + 0.013 * a; });
  const RawImport normalized = import_file(write_raw("normalized.txt", reading));
  const RawImport counts = import_file(write_raw("counts.txt", reading, true));
  EXPECT_NE(counts.table.metadata.at("source").find("ADC counts out of 2^24"), std::string::npos);
  EXPECT_NE(normalized.table.metadata.at("source").find("normalized readings"), std::string::npos);
  // counts are the readings rounded to 2^-24 of full scale: 6e-8 / 0.25 of the stroke, far
  // below the 1e-4 deg output rounding (which may then differ by one unit)
  EXPECT_LE(max_error(angles(normalized), angles(counts)), 1.5 * kRoundingDeg);
  EXPECT_NEAR(counts.table.rows[0][2], normalized.table.rows[0][2], 0.5 / 16777216.0);
}

TEST(RawImport, CurvedSensorWithoutPointsIsOffByItsDepartureFromTheChord) {
  // without calibration points the sensor is taken as linear between rest and peak: exact at
  // both, and in between off by exactly the curve's departure from that chord, never more
  const std::vector<double> theta = strike_angles();
  const auto path = write_raw(
      "curved.txt", sensor(theta, [](double a) { return 0.2 + 0.25 * curved(a / kContactDeg); }));
  const RawImport r = import_file(path);
  const std::vector<double> a = angles(r);
  double bound = 0;
  for (double t : theta)
    bound = std::max(bound, std::abs(kContactDeg * curved(t / kContactDeg) - t));
  EXPECT_LE(max_error(a, theta), bound + kRoundingDeg);
  EXPECT_NEAR(a[0], 0.0, kRoundingDeg);
  EXPECT_NEAR(a[160], kContactDeg, kRoundingDeg);
  // monotone: the estimated angle orders the samples as the true angle does
  for (std::size_t i = 1; i < a.size(); ++i)
    if (theta[i] > theta[i - 1] + 1e-9) {
      EXPECT_GE(a[i], a[i - 1]) << i;
    }
}

TEST(RawImport, CurvedSensorWithItsCalibrationPointsIsRecovered) {
  // calibration points sampled from the same curve at 11 equal steps of travel (as the author's
  // 1/64 in steps); the sensor reads (normalized) 0 at rest and 1 at the string, offset 0.2 and
  // gain 0.25 of full scale
  std::ostringstream cal;
  cal.precision(17);
  cal << "# sensor offset 0.2 gain 0.25\nposition_in,normalized_reading\n";
  for (int k = 0; k <= 10; ++k) cal << 0.015 * k << "," << curved(k / 10.0) << "\n";
  RawImportOptions o;
  o.calibration = read_sensor_calibration(write_file("curved_cal.csv", cal.str()), "hammer");
  const std::vector<double> theta = strike_angles();
  const auto path =
      write_raw("curved_points.txt",
                sensor(theta, [](double a) { return 0.2 + 0.25 * curved(a / kContactDeg); }));
  const RawImport r = import_file(path, o);
  EXPECT_NE(r.table.metadata.at("calibration").find("calibration points"), std::string::npos);
  // The inverse curve (travel of reading) is interpolated by Fritsch–Carlson cubics, third-order
  // accurate on smooth data: with points 0.1 of the travel apart the error on this curve is
  // 0.24 % of the travel (evaluated densely), against 34 % for the chord of the estimate above.
  // 0.5 % of the travel (0.1 deg) leaves room for the rounding and no more.
  EXPECT_LE(max_error(angles(r), theta), 0.005 * kContactDeg);
}

TEST(RawImport, AuthorsPointsAreInterpolatedThroughEveryPointAndMonotone) {
  const SensorCalibration c =
      read_sensor_calibration(write_file("author.csv", kAuthorCalibration), "hammer");
  EXPECT_EQ(c.sensor, "hammer");
  EXPECT_DOUBLE_EQ(c.offset, 0.69);
  EXPECT_DOUBLE_EQ(c.gain, 0.29);
  ASSERT_EQ(c.position.size(), 11u);  // the damper rows are not used
  for (std::size_t k = 0; k < c.position.size(); ++k)
    EXPECT_NEAR(c.position_at(0.69 + 0.29 * c.normalized_reading[k]), c.position[k], 1e-12) << k;
  double previous = -1.0;
  for (int i = 0; i <= 2000; ++i) {  // normalized −0.1 … 1.1: the ends continue along secants
    const double p = c.position_at(0.69 + 0.29 * (-0.1 + 1.2 * i / 2000.0));
    EXPECT_GT(p, previous) << i;
    previous = p;
  }
  // the damper's own offset and gain are found for the damper rows
  const SensorCalibration d =
      read_sensor_calibration(write_file("author_damper.csv", kAuthorCalibration), "damper");
  EXPECT_DOUBLE_EQ(d.offset, 0.3);
  EXPECT_DOUBLE_EQ(d.gain, 0.58);
}

TEST(RawImport, FallingCalibrationPointsGiveAFallingMonotoneCurve) {
  const SensorCalibration c = read_sensor_calibration(
      write_file("falling.csv",
                 "# offset 0 gain 1\nposition_in,normalized_reading\n0,1\n0.05,"
                 "0.9\n0.1,0.6\n0.15,0\n"),
      "hammer");
  EXPECT_TRUE(c.sensor.empty());
  double previous = -1.0;  // reading 1 is the rest position 0
  for (int i = 0; i <= 1000; ++i) {
    const double p = c.position_at(1.0 - i / 1000.0);
    EXPECT_GE(p, previous - 1e-15) << i;
    previous = p;
  }
  EXPECT_NEAR(c.position_at(0.6), 0.1, 1e-15);
}

TEST(RawImport, ContactAngleIsTheClosedFormRotationOfTheStrikePoint) {
  // The grand's hammer turns about a pivot on the frame; the strike point at rest is o + u and
  // after a rotation φ (trace sign σ) its height over the string plane is
  //   n·(o + R(σφ) u − p) = A cos φ + B sin φ − C,  A = n·u, B = σ n·(J u), C = n·(p − o),
  // zero at φ = atan2(B, A) ± acos(C / √(A² + B²)); the contact is the first root after rest.
  const ActionModel grand = test::shipped("grand");
  const double theta_c = hammer_contact_angle_deg(grand);
  const RestState rest = find_rest_state(grand);
  ActionDynamics dynamics(grand, nullptr);
  const ActionLandmarks& l = grand.landmarks;
  const Body& hammer = grand.bodies[static_cast<std::size_t>(l.hammer)];
  ASSERT_EQ(hammer.parent, -1);
  const Vec2 o = hammer.pivot;
  const Vec2 u = dynamics.point_position(l.hammer, l.strike_point, rest.q) - o;
  const Vec2 ju(-u.y(), u.x());
  const double A = l.string_normal.dot(u), B = hammer.trace_sign * l.string_normal.dot(ju);
  const double C = l.string_normal.dot(l.string_point - o);
  double phi = 2 * kPi;
  for (double branch : {-1.0, 1.0}) {
    const double root = std::atan2(B, A) + branch * std::acos(C / std::hypot(A, B));
    phi = std::min(phi, root - 2 * kPi * std::floor(root / (2 * kPi)));  // in [0, 2π)
  }
  EXPECT_NEAR(theta_c, phi * 180.0 / kPi, 1e-8);  // the bisection stops at 1e-12 rad
  // a blow of 45 mm at a strike radius of about 140 mm: roughly 19 degrees
  EXPECT_GT(theta_c, 15.0);
  EXPECT_LT(theta_c, 25.0);
}

TEST(RawImport, ShippedStrikeAgreesWithThePreset) {
  // assets/measured maps the calibration's last point (string contact) to the grand's contact
  // angle; the strike peaks at normalized reading 1.006, 0.4 % of the travel beyond that point
  // (felt compression), so its peak lies within 1 % of θ_c unless the preset's geometry has
  // changed since the file was made (then run the import-raw command of its README again)
  const MeasuredTrial trial = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_fast_strike.csv", "grand");
  const double theta_c = hammer_contact_angle_deg(test::shipped("grand"));
  const double peak = *std::max_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  EXPECT_NEAR(peak, theta_c, 0.01 * theta_c);
}

// ---- bad input -------------------------------------------------------------------------------

using test::error_of;

void expect_message(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(RawImport, BadRawFilesAreNamed) {
  const std::string missing = temp_path("does_not_exist.txt");
  expect_message(error_of([&] { read_raw_trace(missing, 1); }), {missing, "cannot open"});
  const auto text = write_file("text.txt", "0.2 0.3\n0.2 0.3\n0.2 abc\n");
  expect_message(error_of([&] { read_raw_trace(text, 2); }),
                 {text, "line 3, column 2", "'abc' is not a finite number"});
  const auto nan = write_file("nan.txt", "0.2\nnan\n");
  expect_message(error_of([&] { read_raw_trace(nan, 1); }), {"line 2", "'nan'"});
  const auto two = write_file("two.txt", "0.2,0.3\n0.2,0.3\n");
  expect_message(error_of([&] { read_raw_trace(two, 3); }),
                 {two, "line 1", "column 3 is out of range", "the line has 2 columns"});
  expect_message(error_of([&] { read_raw_trace(two, 0); }), {"--column", "counted from 1"});
  const auto mixed = write_file("mixed.txt", "3600000\n0.5\n");
  expect_message(error_of([&] { read_raw_trace(mixed, 1); }),
                 {"line 2", "neither a normalized reading in [0, 1] nor a whole ADC count"});
  const std::string folder = std::filesystem::temp_directory_path().string();
  expect_message(error_of([&] { read_raw_trace(folder, 1); }), {"a folder"});
  const auto empty = write_file("empty.txt", "# nothing\n\n");
  expect_message(error_of([&] { read_raw_trace(empty, 1); }), {empty, "no samples"});
  // a blank line between samples would shift the later ones by a period; at the end it is fine
  const auto gap = write_file("gap.txt", "0.2\n0.3\n\n0.4\n");
  expect_message(error_of([&] { read_raw_trace(gap, 1); }), {gap, "line 3", "blank line"});
  EXPECT_EQ(read_raw_trace(write_file("tail.txt", "0.2\n0.3\n\n\n"), 1).reading.size(), 2u);
}

TEST(RawImport, BadRatesWindowsAndMissingStrikesAreNamed) {
  const std::vector<double> theta = strike_angles();
  const auto path = write_raw("good.txt", sensor(theta, [](double a) { return 0.21 + 0.011 * a; }));
  RawImportOptions o;
  o.rate_hz = -5;
  expect_message(error_of([&] { import_file(path, o); }), {"--rate must be a positive"});
  o.rate_hz = 500;
  expect_message(error_of([&] { import_file(path, o); }), {"--rate 500", "too slow"});
  o.rate_hz = 0;
  o.from_s = 0.1;
  o.to_s = 0.105;
  expect_message(error_of([&] { import_file(path, o); }), {path, "only 11 samples", "at least 20"});
  o.from_s = 0.2;
  o.to_s = 0.1;
  expect_message(error_of([&] { import_file(path, o); }), {"--from", "end after it starts"});
  // a window from before the file's start is named alone (it had printed "--to inf s"); a window
  // ending far past the file's end is the whole file (1e17 s had overflowed the sample index)
  o.from_s = -1.0;
  o.to_s = std::numeric_limits<double>::infinity();
  expect_message(error_of([&] { import_file(path, o); }), {"--from -1 s", "0 s or later"});
  RawImportOptions far;
  far.to_s = 1e17;
  EXPECT_EQ(import_file(path, far).table.rows.size(), import_file(path).table.rows.size());

  const auto flat = write_raw("flat.txt", std::vector<double>(400, 0.3));
  expect_message(error_of([&] { import_file(flat); }),
                 {flat, "no strike found in column 1", "never leaves its rest level"});
  // pushed slowly to the string and held: no rebound
  std::vector<double> push(600, 0.2);
  for (std::size_t i = 100; i < 600; ++i) push[i] = 0.2 + 0.2 * std::min(1.0, (i - 100) / 300.0);
  const auto held = write_raw("held.txt", push);
  expect_message(error_of([&] { import_file(held); }), {"not followed within 20 ms by a rebound"});
  // with calibration points no strike is needed
  RawImportOptions with_points;
  with_points.calibration =
      read_sensor_calibration(write_file("flat_cal.csv", kAuthorCalibration), "hammer");
  EXPECT_FALSE(import_file(flat, with_points).strike);
}

TEST(RawImport, BadCalibrationFilesAreNamed) {
  auto error_for = [](const std::string& name, const std::string& text) {
    const std::string path = write_file(name, text);
    return error_of([&] { read_sensor_calibration(path, "hammer"); });
  };
  const std::string gain = "# hammer offset 0.69 gain 0.29\n";
  expect_message(error_of([] { read_sensor_calibration(temp_path("no_cal.csv"), "hammer"); }),
                 {"no_cal.csv", "cannot open"});
  expect_message(error_for("cal_column.csv", gain + "sensor,position_in\nhammer,0\n"),
                 {"line 2", "missing column 'normalized_reading'"});
  expect_message(
      error_for("cal_text.csv", gain + "sensor,position_in,normalized_reading\nhammer,0,0\n"
                                       "hammer,0.1,zero\n"),
      {"line 4, normalized_reading", "'zero' is not a finite number"});
  expect_message(
      error_for("cal_fields.csv", gain + "sensor,position_in,normalized_reading\nhammer,0\n"),
      {"line 3", "2 fields, the header has 3"});
  expect_message(error_for("cal_gain.csv",
                           "sensor,position_in,normalized_reading\nhammer,0,0\nhammer,0.1,1\n"),
                 {"header", "no offset and gain for sensor 'hammer'"});
  expect_message(
      error_for("cal_one.csv", gain + "sensor,position_in,normalized_reading\nhammer,0,0\n"
                                      "damper,0.1,1\n"),
      {"only 1 'hammer' point", "at least two"});
  expect_message(
      error_for("cal_bump.csv", gain + "sensor,position_in,normalized_reading\nhammer,0,0\n"
                                       "hammer,0.1,0.5\nhammer,0.2,0.4\n"),
      {"line 5", "not monotone", "does not continue the rise from 0.5"});
  expect_message(
      error_for("cal_order.csv", gain + "sensor,position_in,normalized_reading\nhammer,0,0\n"
                                        "hammer,0.2,0.5\nhammer,0.1,0.6\n"),
      {"line 5", "positions must increase"});
  expect_message(error_for("cal_zero.csv",
                           "# hammer offset 0.69 gain 0\nsensor,position_in,normalized_reading\n"
                           "hammer,0,0\nhammer,0.1,1\n"),
                 {"gain of hammer is zero"});
}

// ---- the key's own sensor (key_sensor.h) -----------------------------------------------------

constexpr double kKeyArmM = 0.22;         // key front's arm given to the import (the grand's)
constexpr double kKeyRestIn = 0.05;       // the key sensor's position at rest (not its zero)
constexpr double kKeyInPerReading = 0.5;  // linear key points: 0.5 in at normalized reading 1

/// Calibration points for a two-column recording: hammer (column 1), key (column 2), both linear.
const char* kTwoSensorCalibration =
    "# points for two_columns.txt: hammer offset 0 gain 1, key offset 0.3 gain 0.58\n"
    "sensor,position_in,normalized_reading\n"
    "hammer,0,0\nhammer,1,1\nkey,0,0\nkey,0.5,1\n";

/// Writes hammer and key readings as two columns; the key's from its front dip (m).
std::string write_two_columns(const std::string& name, const std::vector<double>& key_dip_m) {
  const std::vector<double> theta = strike_angles();
  std::ostringstream text;
  text.precision(17);
  for (std::size_t i = 0; i < key_dip_m.size(); ++i) {
    const double hammer = 0.21 + 0.011 * theta[std::min(i, theta.size() - 1)];
    const double position_in = kKeyRestIn + key_dip_m[i] / 0.0254;
    text << hammer << "," << 0.3 + 0.58 * position_in / kKeyInPerReading << "\n";
  }
  return write_file(name, text.str());
}

RawImport import_with_key(const std::string& path) {
  // a calibration file of this test's own: the tests run in parallel processes
  const std::string cal =
      write_file(std::filesystem::path(path).stem().string() + "_cal.csv", kTwoSensorCalibration);
  RawImportOptions o;
  o.calibration = read_sensor_calibration(cal, "hammer");
  o.key_calibration = read_sensor_calibration(cal, "key");
  o.key_trace = read_raw_trace(path, 2);
  o.key_front_arm_m = kKeyArmM;
  return import_file(path, o);
}

TEST(RawImport, KeySensorGivesTheAngleOfTheKeyFrontsDip) {
  // rest 60 ms, a raised-cosine press of 10 mm in 30 ms, held: 0.3 s
  std::vector<double> dip;
  for (int i = 0; i < 600; ++i) {
    const double t = i / kRate;
    dip.push_back(t < 0.06   ? 0.0
                  : t < 0.09 ? 5e-3 * (1 - std::cos(kPi * (t - 0.06) / 0.03))
                             : 1e-2);
  }
  const RawImport r = import_with_key(write_two_columns("two_columns.txt", dip));
  ASSERT_TRUE(r.key);
  EXPECT_NEAR(r.key->rest_position_in, kKeyRestIn, 1e-12);
  EXPECT_NEAR(r.key->deepest_dip_mm, 10.0, 1e-9);
  const auto& columns = r.table.columns;
  const auto key_column = std::find(columns.begin(), columns.end(), "key_angle_deg");
  ASSERT_NE(key_column, columns.end());
  const auto k = static_cast<std::size_t>(key_column - columns.begin());
  double flat_error = 0.0, ramp_error = 0.0;
  for (std::size_t i = 0; i < dip.size(); ++i) {
    const double expected = std::asin(dip[i] / kKeyArmM) * 180.0 / kPi;
    const double error = std::abs(r.table.rows[i][k] - expected);
    const double t = i / kRate;
    // the Gaussian reaches 3σ = 6 ms: beyond that from the ramp it averages a constant
    const bool flat = t < 0.06 - 6e-3 || t > 0.09 + 6e-3;
    (flat ? flat_error : ramp_error) = std::max(flat ? flat_error : ramp_error, error);
  }
  EXPECT_LE(flat_error, 1e-5);  // the file's rounding (5e-6 deg) and the truncated tails
  // the smoothing's bias on the ramp is about σ²/2 times the dip's curvature: 0.5 · (2 ms)² ·
  // 5 mm · (π / 30 ms)² = 0.11 mm at most, 0.029 deg on a 220 mm arm
  EXPECT_LE(ramp_error, 0.035);
  EXPECT_GT(ramp_error, 0.005);  // and it is there: the trace is smoothed
  // diagnose reads the key column as the measured key motion
  const MeasuredTrial trial = measured_from_table(r.table, "two_columns.txt", "grand");
  ASSERT_EQ(trial.key_deg.size(), dip.size());
  EXPECT_NE(r.table.metadata.at("key_calibration").find("sigma 2 ms"), std::string::npos);
}

TEST(RawImport, KeySmoothingCutsTheSensorNoiseByTheGaussiansFactor) {
  // white noise of σ_n on the key front at rest: a Gaussian of σ = 4 samples leaves
  // σ_n (2 √π σ)^(-1/2) = 0.266 σ_n
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1e-4);  // 0.1 mm, as the real sensor near rest
  std::vector<double> dip(4000);
  for (double& d : dip) d = noise(random);
  const RawImport r = import_with_key(write_two_columns("noisy_key.txt", dip));
  ASSERT_TRUE(r.key);
  double sum = 0.0, sum2 = 0.0;
  for (double a : r.key->angle_deg) {
    const double mm = std::sin(a * kPi / 180.0) * kKeyArmM;
    sum += mm, sum2 += mm * mm;
  }
  const double n = static_cast<double>(dip.size());
  const double ratio = std::sqrt(sum2 / n - (sum / n) * (sum / n)) / 1e-4;
  // about 4000 / 14 = 280 independent values after smoothing: the sample deviation's own
  // spread is 1 / √(2 · 280) = 4 %; 12 % is three of those
  EXPECT_NEAR(ratio, 1.0 / std::sqrt(2.0 * std::sqrt(kPi) * 4.0), 0.12 * 0.266);
}

TEST(RawImport, KeySensorWithoutItsPointsOrOfAnotherLengthIsNamed) {
  const std::vector<double> dip(400, 0.0);
  const std::string path = write_two_columns("key_no_points.txt", dip);
  RawImportOptions o;
  o.calibration =
      read_sensor_calibration(write_file("key_no_points_cal.csv", kTwoSensorCalibration), "hammer");
  o.key_trace = read_raw_trace(path, 2);
  o.key_front_arm_m = kKeyArmM;
  expect_message(error_of([&] { import_file(path, o); }),
                 {"column 2", "needs its calibration points"});
  o.key_calibration = read_sensor_calibration(temp_path("key_no_points_cal.csv"), "key");
  o.key_trace->reading.pop_back();
  expect_message(error_of([&] { import_file(path, o); }),
                 {path, "key's column 2 has 399 samples", "hammer's column 1 400"});
  // a reading whose dip no key makes (11.9 mm on a 20 mm arm): the sample is named
  o.key_trace = read_raw_trace(path, 2);
  o.key_front_arm_m = 0.02;
  o.key_trace->reading[300] = 0.9;
  expect_message(error_of([&] { import_file(path, o); }),
                 {"key_no_points_cal.csv", "reading 0.9 (sample 300 of the window)",
                  "more than a fifth of the key front's 20 mm arm"});
  // a sensor running against its points: the key only rises above its rest
  std::vector<double> rising(400, 0.0);
  for (std::size_t i = 200; i < 400; ++i) rising[i] = -5e-3;
  const std::string against = write_two_columns("key_against.txt", rising);
  o.key_trace = read_raw_trace(against, 2);
  o.key_front_arm_m = kKeyArmM;
  expect_message(error_of([&] { import_file(against, o); }),
                 {"key_no_points_cal.csv", "the key only rises above its rest"});
}

}  // namespace
}  // namespace pat

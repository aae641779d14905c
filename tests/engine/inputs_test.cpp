// Key inputs (inputs/key_input.h): every SPEC form, the spline, and helpful errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/types.h"
#include "inputs/cubic_spline.h"
#include "inputs/key_input.h"

namespace pat {
namespace {

namespace fs = std::filesystem;

constexpr double kFullDip = 0.04;  // rad: about 10 mm of key dip on a 0.25 m lever
constexpr double kEps = std::numeric_limits<double>::epsilon();

InputContext context() {
  InputContext c;
  c.full_dip_angle_rad = kFullDip;
  return c;
}

std::unique_ptr<KeyInput> parse(const std::string& spec) {
  return parse_input_spec(spec, context());
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The InputError message parse_input_spec gives, or "" (and a failure) if none.
std::string spec_error(const std::string& spec, const InputContext& c = context()) {
  try {
    parse_input_spec(spec, c);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for '" << spec << "'";
  return "";
}

// Checks rate and acceleration against central differences of the angle at time t.
// For θ with |θ'''| ≤ d3 and |θ''''| ≤ d4 near t, the central differences have truncation
// errors ≤ d3 h²/6 (rate) and ≤ d4 h²/12 (acceleration); the angle itself carries a round-off
// δ ≈ 4 ε A, which the differences amplify to δ/h and 4δ/h². The tolerance is twice the sum.
void expect_consistent_derivatives(const KeyInput& input, double t, double d3, double d4) {
  const double hr = 1e-6, ha = 1e-4;
  const double delta = 4.0 * kEps * kFullDip;
  const auto angle = [&](double s) { return input.motion(s).angle; };
  const KeyMotionSample m = input.motion(t);
  const double rate_fd = (angle(t + hr) - angle(t - hr)) / (2.0 * hr);
  const double acc_fd = (angle(t + ha) - 2.0 * angle(t) + angle(t - ha)) / (ha * ha);
  EXPECT_NEAR(m.rate, rate_fd, 2.0 * (d3 * hr * hr / 6.0 + delta / hr)) << "t = " << t;
  EXPECT_NEAR(m.acceleration, acc_fd, 2.0 * (d4 * ha * ha / 12.0 + 4.0 * delta / (ha * ha)))
      << "t = " << t;
}

// Bounds on the 3rd and 4th derivatives of (A/2)(1 − cos φ) with |φ'| ≤ w, |φ''| ≤ r, φ''' = 0.
double third_bound(double w, double r) {
  return 0.5 * kFullDip * (w * w * w + 3.0 * w * r);
}
double fourth_bound(double w, double r) {
  return 0.5 * kFullDip * (w * w * w * w + 6.0 * w * w * r + 3.0 * r * r);
}

// A fresh folder under the system temporary folder, removed at the end of the test.
class InputsCsvTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device random;
    std::ostringstream name;
    name << "pat_inputs_test_" << std::hex << random() << random();
    dir_ = fs::temp_directory_path() / name.str();
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write_text(const std::string& name, const std::string& text) const {
    const std::string file = (dir_ / name).string();
    std::ofstream out(file, std::ios::binary);
    out << text;
    return file;
  }
  fs::path dir_;
};

TEST_F(InputsCsvTest, ARecordingShorterThanTheRunSaysItsLastValueIsHeld) {
  const auto force = parse("csv:" + write_text("f.csv", "time_s,key_force_n\n0,0\n0.05,20\n"));
  EXPECT_EQ(force->given_until_s(), 0.05);
  EXPECT_EQ(input_notes(*force, 0.1),
            "the input ends at 0.05 s; its last force, 20 N, is held to the run's end at 0.1 s");
  EXPECT_EQ(input_notes(*force, std::numeric_limits<double>::infinity()),
            "the input ends at 0.05 s; its last force, 20 N, is held after it");
  EXPECT_EQ(input_notes(*force, 0.04), "");  // the run ends first
  // 0.02 rad = 1.146 deg
  const auto angle =
      parse("csv:" + write_text("a.csv", "time_s,key_angle_deg\n0,0\n0.1,0.5\n0.2,1.146\n"));
  EXPECT_EQ(input_notes(*angle, 1.0),
            "the input ends at 0.2 s; its last key angle, 1.146 deg, is held to the run's end at "
            "1 s");
  // a recording that begins after the run ends: the run sees none of it, and is told so
  const auto late = parse("csv:" + write_text("late.csv", "time_s,key_force_n\n0.5,0\n0.6,20\n"));
  EXPECT_EQ(input_notes(*late, 0.1),
            "the input begins at 0.5 s, after the run's end at 0.1 s: the action stays at rest "
            "for the whole run");
  // a SPEC defined for all time has nothing to say
  EXPECT_EQ(input_notes(*parse("motion:sine:5"), 10.0), "");
  EXPECT_EQ(parse("force:const:3")->given_until_s(), std::numeric_limits<double>::infinity());
}

TEST(MassInput, OneKilogramAddsMassAndNoForce) {
  const auto input = parse("mass:1kg");
  EXPECT_FALSE(input->is_motion());
  EXPECT_EQ(input->added_mass_kg(), 1.0);
  for (double t : {0.0, 0.01, 1.0}) EXPECT_EQ(input->force_n(t), 0.0);
  EXPECT_EQ(input->spec(), "mass:1kg");
  EXPECT_DOUBLE_EQ(parse("mass:250g")->added_mass_kg(), 0.25);
  EXPECT_EQ(parse("force:const:3")->added_mass_kg(), 0.0);
}

TEST(ForceInput, ConstantFromTimeZero) {
  const auto input = parse("force:const:12.5");
  EXPECT_FALSE(input->is_motion());
  EXPECT_EQ(input->force_n(0.0), 12.5);
  EXPECT_EQ(input->force_n(3.0), 12.5);
  EXPECT_EQ(input->force_n(-1e-3), 0.0);
  EXPECT_EQ(parse("force:const:-2")->force_n(1.0), -2.0);  // lifting the key is allowed
}

TEST(ForceInput, PulseRampsOneMillisecondHoldsThenZero) {
  const auto input = parse("force:pulse:20:5");
  EXPECT_EQ(input->force_n(0.0), 0.0);
  EXPECT_NEAR(input->force_n(0.00025), 5.0, 1e-9);
  EXPECT_NEAR(input->force_n(0.0005), 10.0, 1e-9);
  EXPECT_NEAR(input->force_n(0.001), 20.0, 1e-9);
  EXPECT_EQ(input->force_n(0.0035), 20.0);
  EXPECT_EQ(input->force_n(0.0059), 20.0);
  EXPECT_NEAR(input->force_n(0.0065), 10.0, 1e-9);  // down ramp from 6 ms to 7 ms
  EXPECT_NEAR(input->force_n(0.00699), 0.2, 1e-9);
  EXPECT_EQ(input->force_n(0.0070001), 0.0);
  EXPECT_EQ(input->force_n(0.5), 0.0);
}

TEST(ForceInput, DoublePulseStartsGapAfterTheFirstEnds) {
  const auto input = parse("force:double:20:5:10");
  // First pulse ends at 1 + 5 + 1 = 7 ms; the second starts at 7 + 10 = 17 ms.
  EXPECT_NEAR(input->force_n(0.0035), 20.0, 1e-9);
  for (double t : {0.0070001, 0.01, 0.0169999}) EXPECT_EQ(input->force_n(t), 0.0) << t;
  EXPECT_EQ(input->force_n(0.017 - 1e-9), 0.0);
  EXPECT_NEAR(input->force_n(0.017 + 1e-9), 20.0 * 1e-9 / 1e-3, 1e-9);
  EXPECT_NEAR(input->force_n(0.0175), 10.0, 1e-9);
  EXPECT_NEAR(input->force_n(0.020), 20.0, 1e-9);
  EXPECT_NEAR(input->force_n(0.0235), 10.0, 1e-9);
  EXPECT_EQ(input->force_n(0.0240001), 0.0);
  EXPECT_EQ(input->force_n(1.0), 0.0);

  const auto touching = parse("force:double:20:5:0");  // no gap: ramps meet at 7 ms
  EXPECT_NEAR(touching->force_n(0.0075), 10.0, 1e-9);
  EXPECT_NEAR(touching->force_n(0.0065), 10.0, 1e-9);
}

TEST(MotionInput, FullSineAngleRateAccelerationAndRange) {
  const double f = 5.0, w = 2.0 * kPi * f;
  const auto input = parse("motion:sine:5");
  EXPECT_TRUE(input->is_motion());
  EXPECT_EQ(input->force_n(0.1), 0.0);
  EXPECT_EQ(input->motion(0.0).angle, 0.0);
  EXPECT_NEAR(input->motion(0.1).angle, kFullDip, 1e-15);  // half a period: full dip
  EXPECT_NEAR(input->motion(0.05).angle, 0.5 * kFullDip, 1e-15);
  EXPECT_NEAR(input->motion(0.05).rate, 0.5 * kFullDip * w, 1e-12);
  for (double t = 0.0013; t < 0.6; t += 0.0371) {
    expect_consistent_derivatives(*input, t, third_bound(w, 0), fourth_bound(w, 0));
  }
  double lo = 1.0, hi = -1.0;
  for (double t = 0.0; t < 0.6; t += 1e-4) {
    lo = std::min(lo, input->motion(t).angle);
    hi = std::max(hi, input->motion(t).angle);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, kFullDip * (1 + 4 * kEps));
  EXPECT_NEAR(hi, kFullDip, 1e-9);
}

TEST(MotionInput, HalfSineGoesToFullDipThenBetweenFullAndHalf) {
  const double f = 4.0, w = 2.0 * kPi * f, t0 = 1.0 / (2.0 * f);
  const auto input = parse("motion:sine:4:half");
  EXPECT_EQ(input->spec(), "motion:sine:4:half");
  EXPECT_NEAR(input->motion(t0).angle, kFullDip, 1e-15);
  EXPECT_NEAR(input->motion(t0 + 1.0 / (2.0 * f)).angle, 0.5 * kFullDip, 1e-15);
  EXPECT_NEAR(input->motion(t0 + 1.0 / f).angle, kFullDip, 1e-15);
  // Stay 1 ms away from t0, where the acceleration jumps from −A/2 ω² to −A/4 ω².
  for (double t = 0.0013; t < 1.0; t += 0.0237) {
    if (std::abs(t - t0) < 1e-3) continue;
    expect_consistent_derivatives(*input, t, third_bound(w, 0), fourth_bound(w, 0));
  }
  double previous = -1.0, lo = 1.0, hi = -1.0;
  for (double t = 0.0; t < 1.0; t += 1e-4) {
    const double a = input->motion(t).angle;
    if (t < t0) {
      EXPECT_GE(a, previous) << "first descent is monotonic";
      previous = a;
    } else {
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  }
  EXPECT_GE(lo, 0.5 * kFullDip * (1 - 4 * kEps));
  EXPECT_LE(hi, kFullDip * (1 + 4 * kEps));
  EXPECT_NEAR(lo, 0.5 * kFullDip, 1e-9);
  EXPECT_NEAR(hi, kFullDip, 1e-9);
  EXPECT_EQ(parse("motion:sine:4:full")->motion(0.2).angle,
            parse("motion:sine:4")->motion(0.2).angle);
}

// From a full-stroke sample, |φ'| = |rate| / ((A/2) |sin φ|) with |sin φ| from the angle.
double full_frequency_hz(const KeyMotionSample& m) {
  const double half = 0.5 * kFullDip, c = (m.angle - half) / half;
  return std::abs(m.rate) / (half * std::sqrt(1.0 - c * c)) / (2.0 * kPi);
}

TEST(MotionInput, ChirpInstantaneousFrequencySweepsLinearlyThenHolds) {
  const double f0 = 2.0, f1 = 20.0, sweep = 1.0;
  const auto input = parse("motion:chirp:2:20:1");
  EXPECT_TRUE(input->is_motion());
  int checked = 0;
  for (double t = 0.003; t < 1.5; t += 0.0071) {
    const KeyMotionSample m = input->motion(t);
    const double c = (m.angle - 0.5 * kFullDip) / (0.5 * kFullDip);
    if (1.0 - c * c < 0.01) continue;  // |sin φ| < 0.1: the ratio is ill-conditioned
    const double expected = t <= sweep ? f0 + (f1 - f0) * t / sweep : f1;
    EXPECT_NEAR(full_frequency_hz(m), expected, 1e-9 * expected) << "t = " << t;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  // Phase at the end of the sweep: 2π (2 + 9) = 22π, so the angle is back at rest.
  EXPECT_NEAR(input->motion(sweep).angle, 0.0, 1e-15);
  EXPECT_NEAR(input->motion(sweep + 1e-9).angle, input->motion(sweep - 1e-9).angle, 1e-12);

  const double w = 2.0 * kPi * f1, r = 2.0 * kPi * (f1 - f0) / sweep;
  for (double t = 0.0013; t < 1.5; t += 0.0237) {
    if (std::abs(t - sweep) < 1e-3) continue;  // φ'' jumps at the end of the sweep
    expect_consistent_derivatives(*input, t, third_bound(w, r), fourth_bound(w, r));
  }
}

TEST(MotionInput, HalfChirpStartsWithAHalfPeriodAtF0) {
  const double f0 = 3.0, f1 = 9.0, sweep = 2.0, t0 = 1.0 / (2.0 * f0);
  const auto input = parse("motion:chirp:3:9:2:half");
  EXPECT_NEAR(input->motion(0.5 * t0).angle, 0.5 * kFullDip, 1e-15);
  EXPECT_NEAR(input->motion(t0).angle, kFullDip, 1e-15);
  for (double t = t0 + 0.002; t < 3.0; t += 0.0113) {
    const KeyMotionSample m = input->motion(t);
    EXPECT_GE(m.angle, 0.5 * kFullDip * (1 - 4 * kEps));
    EXPECT_LE(m.angle, kFullDip * (1 + 4 * kEps));
    // angle = A − (A/4)(1 − cos φ), rate = −(A/4) sin φ φ'.
    const double c = 1.0 - 4.0 * (kFullDip - m.angle) / kFullDip;
    if (1.0 - c * c < 0.01) continue;
    const double hz = std::abs(m.rate) / (0.25 * kFullDip * std::sqrt(1.0 - c * c)) / (2 * kPi);
    const double tau = t - t0;
    const double expected = tau <= sweep ? f0 + (f1 - f0) * tau / sweep : f1;
    EXPECT_NEAR(hz, expected, 1e-9 * expected) << "t = " << t;
  }
  const double w = 2.0 * kPi * f1, r = 2.0 * kPi * (f1 - f0) / sweep;
  for (double t = 0.0013; t < 3.0; t += 0.0237) {
    if (std::abs(t - t0) < 1e-3 || std::abs(t - t0 - sweep) < 1e-3) continue;
    expect_consistent_derivatives(*input, t, third_bound(w, r), fourth_bound(w, r));
  }
}

TEST(MotionInput, SlowPressReachesFullDipAlongAHalfCosineAndHolds) {
  const double seconds = 0.8, w = kPi / seconds;
  const auto input = parse("motion:press:0.8");
  EXPECT_TRUE(input->is_motion());
  EXPECT_EQ(input->spec(), "motion:press:0.8");
  EXPECT_EQ(input->motion(0.0).angle, 0.0);
  EXPECT_EQ(input->motion(0.0).rate, 0.0);  // starts from rest: no jerk of the key
  EXPECT_NEAR(input->motion(0.5 * seconds).angle, 0.5 * kFullDip, 1e-15);
  EXPECT_NEAR(input->motion(0.5 * seconds).rate, 0.5 * kFullDip * w, 1e-15);  // fastest here
  EXPECT_NEAR(input->motion(seconds * (1 - 1e-9)).angle, kFullDip, 1e-15);
  for (double t : {seconds, seconds + 0.1, 5.0}) {  // held at full dip
    EXPECT_EQ(input->motion(t).angle, kFullDip);
    EXPECT_EQ(input->motion(t).rate, 0.0);
    EXPECT_EQ(input->motion(t).acceleration, 0.0);
  }
  for (double t = 0.0013; t < seconds - 1e-3; t += 0.0237)
    expect_consistent_derivatives(*input, t, third_bound(w, 0), fourth_bound(w, 0));
  double previous = -1.0;
  for (double t = 0.0; t < 1.2; t += 1e-3) {
    EXPECT_GE(input->motion(t).angle, previous) << "the press never lifts the key, t = " << t;
    previous = input->motion(t).angle;
  }
}

TEST(CubicSpline, ReproducesACubicsDerivativesAwayFromTheEnds) {
  // p(x) = 1 + 2x − 3x² + x³/2 on [0, 4]. The natural end condition (p'' = 0) is wrong by
  // |p''| = 6 at both ends; that error decays by a factor 2 − √3 ≈ 0.27 per knot, so 20 knots
  // (x = 1) from the ends it is below 6 · 0.27^20 ≈ 2e-11. Inside, the spline is the cubic.
  const auto p = [](double x) { return 1 + x * (2 + x * (-3 + 0.5 * x)); };
  const auto dp = [](double x) { return 2 + x * (-6 + 1.5 * x); };
  const auto ddp = [](double x) { return -6 + 3 * x; };
  std::vector<double> x, y;
  for (int i = 0; i <= 80; ++i) {
    x.push_back(0.05 * i);
    y.push_back(p(x.back()));
  }
  const CubicSpline spline(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(spline.evaluate(x[i]).value, y[i], 1e-13);
  for (double s = 1.0; s <= 3.0; s += 0.0137) {
    const CubicSpline::Sample v = spline.evaluate(s);
    EXPECT_NEAR(v.value, p(s), 1e-12) << s;
    EXPECT_NEAR(v.first, dp(s), 1e-10) << s;
    EXPECT_NEAR(v.second, ddp(s), 1e-9) << s;
  }
  // Natural ends; the end values are held outside.
  EXPECT_NEAR(spline.evaluate(0.0).second, 0.0, 1e-12);
  EXPECT_EQ(spline.evaluate(-1.0).value, p(0.0));
  EXPECT_EQ(spline.evaluate(-1.0).first, 0.0);
  EXPECT_EQ(spline.evaluate(5.0).value, p(4.0));
  EXPECT_EQ(spline.evaluate(5.0).second, 0.0);
}

TEST(CubicSpline, TwoPointsMakeALineAndBadKnotsThrow) {
  const CubicSpline line({1.0, 3.0}, {2.0, 6.0});
  EXPECT_DOUBLE_EQ(line.evaluate(2.5).value, 5.0);
  EXPECT_DOUBLE_EQ(line.evaluate(2.5).first, 2.0);
  EXPECT_EQ(line.evaluate(2.5).second, 0.0);
  EXPECT_THROW(CubicSpline({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
}

TEST_F(InputsCsvTest, ForceIsInterpolatedLinearlyAndHeldAtTheEnds) {
  // a file may start after t = 0 when it starts at rest (0.05 N: within kCsvRestForceN)
  const std::string file = write_text("force.csv",
                                      "# input: recorded\ntime_s,key_force_n\n0.005,0.05\n0.01,2\n"
                                      "0.02,12\n0.04,4\n");
  const auto input = parse("csv:" + file);
  EXPECT_FALSE(input->is_motion());
  EXPECT_EQ(input->spec(), "csv:" + file);
  EXPECT_TRUE(input->note().empty());
  EXPECT_EQ(input->force_n(0.0), 0.05);
  EXPECT_EQ(input->force_n(0.005), 0.05);
  EXPECT_NEAR(input->force_n(0.0075), 1.025, 1e-12);
  EXPECT_EQ(input->force_n(0.01), 2.0);
  EXPECT_NEAR(input->force_n(0.015), 7.0, 1e-12);
  EXPECT_NEAR(input->force_n(0.03), 8.0, 1e-12);
  EXPECT_EQ(input->force_n(0.04), 4.0);
  EXPECT_EQ(input->force_n(9.0), 4.0);
}

TEST_F(InputsCsvTest, MotionIsSplinedInRadiansAndHeldAtTheEnds) {
  // A smooth stroke sampled at 1 kHz: the spline must match it and its derivatives closely.
  const double f = 5.0, w = 2.0 * kPi * f, amp_deg = 2.0;
  std::ostringstream text;
  text.precision(17);
  text << "# action: grand\ntime_s,key_angle_deg,key_force_n\n";
  for (int i = 0; i <= 400; ++i) {
    const double t = 1e-3 * i;
    text << t << "," << 0.5 * amp_deg * (1 - std::cos(w * t)) << ",0\n";
  }
  const auto input = parse("csv:" + write_text("motion.csv", text.str()));
  EXPECT_TRUE(input->is_motion());  // a key_angle_deg column wins over key_force_n
  // and the run says so: the force column is not used
  EXPECT_NE(input->note().find("key_force_n is not used"), std::string::npos) << input->note();
  const double amp = rad(amp_deg);
  EXPECT_NEAR(input->motion(0.1).angle, amp, 1e-15);  // a knot
  // Interpolation errors of a cubic spline with knot spacing h, far from the ends (standard
  // bounds: 5/384 h⁴, h³/24 and h²/8 + h²/12 times |θ''''|), with a safety factor of 2 or more.
  const double h = 1e-3, d4 = 0.5 * amp * w * w * w * w;
  for (double t = 0.05; t < 0.35; t += 0.0113) {
    const KeyMotionSample m = input->motion(t);
    EXPECT_NEAR(m.angle, 0.5 * amp * (1 - std::cos(w * t)), d4 * h * h * h * h / 16) << t;
    EXPECT_NEAR(m.rate, 0.5 * amp * w * std::sin(w * t), d4 * h * h * h / 12) << t;
    EXPECT_NEAR(m.acceleration, 0.5 * amp * w * w * std::cos(w * t), d4 * h * h / 2.4) << t;
  }
  const KeyMotionSample before = input->motion(-0.5), after = input->motion(2.0);
  EXPECT_EQ(before.angle, 0.0);
  EXPECT_EQ(before.rate, 0.0);
  EXPECT_NEAR(after.angle, input->motion(0.4).angle, 1e-15);
  EXPECT_EQ(after.rate, 0.0);
  EXPECT_EQ(after.acceleration, 0.0);
}

TEST_F(InputsCsvTest, CsvErrorsNameTheFileAndLine) {
  const std::string decreasing = write_text(
      "trace.csv", "# action: grand\n\ntime_s,key_force_n\n0,0\n0.001,1\n0.005,2\n0.004,3\n");
  std::string message = spec_error("csv:" + decreasing);
  EXPECT_TRUE(contains(message, decreasing + ": time_s must increase (line 7: 0.004 after 0.005)"))
      << message;

  const std::string repeated = write_text("repeated.csv", "time_s,key_force_n\n0,0\n0,1\n");
  message = spec_error("csv:" + repeated);
  EXPECT_TRUE(contains(message, "time_s must increase (line 3: 0 after 0)")) << message;

  const std::string no_value = write_text("nothing.csv", "time_s,hammer_angle_deg\n0,0\n1,1\n");
  message = spec_error("csv:" + no_value);
  EXPECT_TRUE(contains(message, no_value + ": needs a key_force_n or key_angle_deg column"))
      << message;

  const std::string no_time = write_text("notime.csv", "t,key_force_n\n0,0\n1,1\n");
  message = spec_error("csv:" + no_time);
  EXPECT_TRUE(contains(message, no_time + ": needs a time_s column")) << message;

  const std::string one_row = write_text("one.csv", "time_s,key_force_n\n0,0\n");
  message = spec_error("csv:" + one_row);
  EXPECT_TRUE(contains(message, "needs at least 2 rows of data (got 1)")) << message;

  const std::string bad_row = write_text("bad.csv", "time_s,key_force_n\n0,0\n1,x\n");
  message = spec_error("csv:" + bad_row);
  EXPECT_TRUE(contains(message, bad_row + ": line 3: 'x' in column key_force_n is not a number"))
      << message;

  message = spec_error("csv:" + (dir_ / "absent.csv").string());
  EXPECT_TRUE(contains(message, "absent.csv")) << message;

  // a key angle no key can take (the context's full dip is 0.04 rad, 2.29 deg)
  const std::string deep = write_text("deep.csv", "time_s,key_angle_deg\n0,0\n0.01,50\n");
  message = spec_error("csv:" + deep);
  EXPECT_TRUE(contains(message, deep + ": key_angle_deg 50 on line 3 is beyond the key's travel "
                                       "(0 at rest, full dip 2.29 deg; accepted from -1.15 to "
                                       "3.44)"))
      << message;
}

// A ramp with sharp corners (0 → 2 deg in 5 ms, held, back): the natural spline through it, which
// the key would follow, swings 0.34 deg (17 % of the 2 deg range) below its foot before the ramp,
// beyond the 10 % a sampled smooth stroke can need. The same ramp with its corners rounded (a
// half cosine sampled every millisecond) is accepted and followed within 1 % of its range.
TEST_F(InputsCsvTest, AFileStartingLaterMustStartAtRest) {
  // every run starts at t = 0 at rest; a first row at 0.5 s would be held from 0: a force of
  // 1 N or a key 1 deg down from the start would be a guess, so the file is refused with the
  // row, the value and what to do
  const std::string force = write_text("late_force.csv", "time_s,key_force_n\n0.5,1\n0.6,1\n");
  std::string message = spec_error("csv:" + force);
  EXPECT_NE(message.find("late_force.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  EXPECT_NE(message.find("key_force_n 1 N"), std::string::npos) << message;
  EXPECT_NE(message.find("held from 0 to 0.5 s"), std::string::npos) << message;
  const std::string angle =
      write_text("late_angle.csv", "time_s,key_angle_deg\n0.5,1\n0.55,1.5\n0.6,1\n");
  message = spec_error("csv:" + angle);
  EXPECT_NE(message.find("key_angle_deg 1 deg"), std::string::npos) << message;
  // at rest within the tolerances (0.1 N, 0.1 deg): accepted, rest held until the first row
  EXPECT_EQ(parse("csv:" + write_text("late_rest.csv", "time_s,key_force_n\n0.5,0\n0.6,5\n"))
                ->force_n(0.2),
            0.0);
  EXPECT_NEAR(parse("csv:" + write_text("late_rest_angle.csv",
                                        "time_s,key_angle_deg\n0.5,0.05\n0.55,0.5\n0.6,1\n"))
                  ->motion(0.2)
                  .angle,
              rad(0.05), 1e-15);
}

TEST_F(InputsCsvTest, AMotionWithCornersTheSplineOvershootsIsRefused) {
  const std::string ramp =
      write_text("ramp.csv", "time_s,key_angle_deg\n0,0\n0.01,0\n0.015,2\n0.05,2\n0.06,0\n0.1,0\n");
  const std::string message = spec_error("csv:" + ramp);
  EXPECT_TRUE(contains(message, ramp + ": key_angle_deg changes too abruptly between lines 2 and "
                                       "3"))
      << message;
  EXPECT_TRUE(contains(message, "record the motion more finely or round its corners")) << message;

  std::ostringstream rounded;
  rounded << "time_s,key_angle_deg\n";
  for (int ms = 0; ms <= 100; ++ms) {
    const double t = 1e-3 * ms;
    double deg = 0.0;  // 0 → 2 deg over 10–20 ms, held, back over 50–60 ms
    if (t > 0.01 && t < 0.02) deg = 1.0 - std::cos(kPi * (t - 0.01) / 0.01);
    if (t >= 0.02 && t <= 0.05) deg = 2.0;
    if (t > 0.05 && t < 0.06) deg = 1.0 + std::cos(kPi * (t - 0.05) / 0.01);
    rounded << t << "," << deg << "\n";
  }
  const auto input = parse("csv:" + write_text("rounded.csv", rounded.str()));
  for (double t = 0.0; t <= 0.1; t += 1.3e-4) {
    const double angle = input->motion(t).angle;
    EXPECT_GT(angle, rad(-0.02)) << t;
    EXPECT_LT(angle, rad(2.02)) << t;
  }
}

TEST(InputSpec, BadSpecsSayWhatIsExpected) {
  struct Case {
    std::string spec, expected;
  };
  const std::vector<Case> cases = {
      {"force:pulse:20",
       "input SPEC 'force:pulse:20': expected force:pulse:N:MS (newtons, milliseconds)"},
      {"foo:1",
       "unknown input SPEC 'foo:1' (expected mass:, force:const:, force:pulse:, force:double:, "
       "motion:sine:, motion:chirp:, motion:press: or csv:)"},
      {"", "unknown input SPEC ''"},
      {"force:push:3", "unknown input SPEC 'force:push:3'"},
      {"force:const", "expected force:const:N (newtons)"},
      {"force:const:abc", "input SPEC 'force:const:abc': 'abc' is not a number"},
      {"force:const:1,5", "'1,5' is not a number"},
      {"force:const:nan", "'nan' is not a finite number"},
      {"force:const:inf", "'inf' is not a finite number"},
      {"force:pulse:20:0", "the pulse length MS must be positive (got 0 ms)"},
      {"force:pulse:20:-5", "the pulse length MS must be positive (got -5 ms)"},
      {"force:double:20:5", "expected force:double:N:MS:GAP_MS"},
      {"force:double:20:5:-1", "the gap GAP_MS must not be negative (got -1 ms)"},
      {"mass:1", "expected mass:Mkg or mass:Mg"},
      {"mass:1lb", "expected mass:Mkg or mass:Mg"},
      {"mass:-1kg", "the mass must not be negative (got -1kg)"},
      {"mass:infkg", "the mass is not a finite number"},
      {"motion:sine:0", "the frequency must be positive (got 0 Hz)"},
      {"motion:sine:-3", "the frequency must be positive (got -3 Hz)"},
      {"motion:sine:5:quarter", "unknown stroke 'quarter' (expected full or half)"},
      {"motion:sine", "expected motion:sine:HZ[:full|half] (hertz)"},
      {"motion:chirp:1:10", "expected motion:chirp:F0:F1:SECONDS[:full|half]"},
      {"motion:chirp:0:10:1", "the start frequency F0 must be positive"},
      {"motion:chirp:1:-10:1", "the end frequency F1 must be positive"},
      {"motion:chirp:1:10:0", "the sweep duration SECONDS must be positive (got 0 s)"},
      {"motion:chirp:1:10:1:up", "unknown stroke 'up'"},
      {"motion:press", "expected motion:press:SECONDS (seconds to full dip)"},
      {"motion:press:1:2", "expected motion:press:SECONDS"},
      {"motion:press:0", "the press duration SECONDS must be positive (got 0 s)"},
      {"motion:press:x", "expected motion:press:SECONDS"},
      {"motion:press:1e-9", "the press must take at least 0.005 s (got 1e-09 s)"},
      {"csv:", "expected csv:PATH"},
  };
  for (const Case& c : cases) {
    const std::string message = spec_error(c.spec);
    EXPECT_TRUE(contains(message, c.expected)) << "SPEC '" << c.spec << "' gave: " << message;
  }
  const std::string no_dip = spec_error("motion:sine:5", InputContext{});
  EXPECT_TRUE(contains(no_dip, "full-dip angle")) << no_dip;
  const std::string press_no_dip = spec_error("motion:press:1", InputContext{});
  EXPECT_TRUE(contains(press_no_dip, "full-dip angle")) << press_no_dip;
}

TEST(InputSpec, NumbersAreLocaleIndependentAndSpacesAreIgnored) {
  EXPECT_EQ(parse("force:const:+1.5e1")->force_n(1.0), 15.0);
  EXPECT_EQ(parse(" force:const: 2.5 ")->force_n(1.0), 2.5);
  EXPECT_DOUBLE_EQ(parse("mass:0.5 kg")->added_mass_kg(), 0.5);
}

}  // namespace
}  // namespace pat

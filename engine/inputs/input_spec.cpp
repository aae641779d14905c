// Input SPEC parsing and the key inputs it makes (inputs/key_input.h).
//
// Choices beyond the header's description:
//   - numbers are parsed with std::from_chars (locale-independent); a leading '+' is accepted;
//     NaN and infinities are rejected; spaces around fields are ignored;
//   - masses must not be negative (0 is accepted), pulse lengths, frequencies and chirp
//     durations must be positive, the double-pulse gap must not be negative (0: the second pulse
//     starts as the first ends); forces may have either sign (negative lifts the key);
//   - csv:PATH takes everything after "csv:" as the path (it may contain ':'); a file with both
//     key_angle_deg and key_force_n is a motion input (the angle is prescribed, and note() says
//     the force column is not used);
//   - before t = 0 every input is at rest (zero force, zero angle).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/format.h"
#include "core/types.h"
#include "inputs/cubic_spline.h"
#include "inputs/key_input.h"
#include "io/csv.h"

namespace pat {
namespace {

constexpr double kRampS = 1e-3;  // force pulse ramps up and down in 1 ms

constexpr const char* kKnownSpecs =
    "expected mass:, force:const:, force:pulse:, force:double:, motion:sine:, motion:chirp:, "
    "motion:press: or csv:";

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = s.find(separator, start);
    parts.push_back(trim(s.substr(start, at == std::string_view::npos ? s.npos : at - start)));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

std::string number_text(double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, ec == std::errc() ? ptr : buffer);
}

[[noreturn]] void spec_error(const std::string& spec, const std::string& problem) {
  throw InputError(located_message("input SPEC '" + spec + "'", "", problem));
}

// Parses the start of `text` as a number; `rest` receives what follows it.
bool parse_number_prefix(std::string_view text, double& value, std::string_view& rest) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return false;
  }
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc()) return false;
  rest = text.substr(static_cast<std::size_t>(ptr - text.data()));
  return true;
}

// A whole field as a finite number; `form` is the expected SPEC form for the message.
double parse_field(const std::string& spec, std::string_view field, const std::string& form) {
  double value = 0.0;
  std::string_view rest;
  if (field.empty()) spec_error(spec, "a number is missing (" + form + ")");
  if (!parse_number_prefix(field, value, rest) || !rest.empty()) {
    spec_error(spec, "'" + std::string(field) + "' is not a number (" + form + ")");
  }
  if (!std::isfinite(value)) {
    spec_error(spec, "'" + std::string(field) + "' is not a finite number (" + form + ")");
  }
  return value;
}

void require_positive(const std::string& spec, double value, const std::string& what,
                      const std::string& unit) {
  if (!(value > 0.0)) {
    spec_error(spec, what + " must be positive (got " + number_text(value) + " " + unit + ")");
  }
}

void require_key_frequency(const std::string& spec, double hz, const std::string& what) {
  require_positive(spec, hz, what, "Hz");
  if (hz > kMaxKeyMotionHz)
    spec_error(spec, what + " must be at most " + number_text(kMaxKeyMotionHz) + " Hz (got " +
                         number_text(hz) + " Hz): no key is moved faster");
}

class InputBase : public KeyInput {
 public:
  explicit InputBase(std::string spec) : spec_(std::move(spec)) {}
  const std::string& spec() const override { return spec_; }
  std::string note() const override { return note_; }
  void set_note(std::string note) { note_ = std::move(note); }

 private:
  std::string spec_;
  std::string note_;
};

class ForceInput : public InputBase {
 public:
  using InputBase::InputBase;
  bool is_motion() const override { return false; }
  KeyMotionSample motion(double) const override { return {}; }
};

class MotionInput : public InputBase {
 public:
  using InputBase::InputBase;
  bool is_motion() const override { return true; }
  double force_n(double) const override { return 0.0; }
};

// The key pressed from rest to full dip along a half cosine in duration_s, then held there (the
// technician's slow press).
class PressMotion final : public MotionInput {
 public:
  PressMotion(std::string spec, double depth, double duration_s)
      : MotionInput(std::move(spec)),
        depth_(depth),
        omega_(kPi / duration_s),
        duration_s_(duration_s) {}

  KeyMotionSample motion(double t) const override {
    if (t < 0.0) return {};
    if (t >= duration_s_) return {depth_, 0.0, 0.0};
    const double half_depth = 0.5 * depth_, c = std::cos(omega_ * t), s = std::sin(omega_ * t);
    return {half_depth * (1.0 - c), half_depth * omega_ * s, half_depth * omega_ * omega_ * c};
  }

 private:
  double depth_;       // rad from rest: full dip
  double omega_;       // rad/s: half a cosine period in the press
  double duration_s_;  // s
};

// A point mass resting on the key front; no applied force.
class MassInput final : public ForceInput {
 public:
  MassInput(std::string spec, double mass_kg) : ForceInput(std::move(spec)), mass_kg_(mass_kg) {}
  double force_n(double) const override { return 0.0; }
  double added_mass_kg() const override { return mass_kg_; }

 private:
  double mass_kg_;
};

class ConstantForce final : public ForceInput {
 public:
  ConstantForce(std::string spec, double force) : ForceInput(std::move(spec)), force_(force) {}
  double force_n(double t) const override { return t >= 0.0 ? force_ : 0.0; }

 private:
  double force_;
};

// One or two trapezoidal pulses: 1 ms up, held, 1 ms down.
class PulseForce final : public ForceInput {
 public:
  PulseForce(std::string spec, double force, double hold_s, bool twice, double gap_s)
      : ForceInput(std::move(spec)),
        force_(force),
        slope_(force / kRampS),
        hold_end_(kRampS + hold_s),
        end_(2.0 * kRampS + hold_s),
        second_start_(twice ? end_ + gap_s : std::numeric_limits<double>::infinity()) {}

  double force_n(double t) const override {
    return t < second_start_ ? pulse(t) : pulse(t - second_start_);
  }

 private:
  double pulse(double s) const {
    if (s <= 0.0 || s >= end_) return 0.0;
    if (s < kRampS) return slope_ * s;
    if (s <= hold_end_) return force_;
    return slope_ * (end_ - s);
  }

  double force_, slope_, hold_end_, end_, second_start_;
};

// Sine (f0 = f1) or linear chirp key strokes between rest and full dip (or full dip and half).
class StrokeMotion final : public MotionInput {
 public:
  StrokeMotion(std::string spec, double amplitude, double f0, double f1, double sweep_s, bool half)
      : MotionInput(std::move(spec)),
        amplitude_(amplitude),
        half_(half),
        omega0_(2.0 * kPi * f0),
        omega1_(2.0 * kPi * f1),
        sweep_s_(sweep_s),
        omega_rate_(std::isfinite(sweep_s) ? 2.0 * kPi * (f1 - f0) / sweep_s : 0.0),
        phase_at_sweep_end_(
            std::isfinite(sweep_s) ? sweep_s * (omega0_ + 0.5 * omega_rate_ * sweep_s) : 0.0),
        t0_(half ? 0.5 / f0 : 0.0) {}

  KeyMotionSample motion(double t) const override {
    if (t < 0.0) return {};
    const double half_a = 0.5 * amplitude_;
    if (!half_) {
      double phi, dphi, ddphi;
      phase(t, phi, dphi, ddphi);
      const double c = std::cos(phi), s = std::sin(phi);
      return {half_a * (1.0 - c), half_a * s * dphi, half_a * (c * dphi * dphi + s * ddphi)};
    }
    if (t < t0_) {  // first descent: half a period of the full stroke at f0
      const double c = std::cos(omega0_ * t), s = std::sin(omega0_ * t);
      return {half_a * (1.0 - c), half_a * omega0_ * s, half_a * omega0_ * omega0_ * c};
    }
    double phi, dphi, ddphi;
    phase(t - t0_, phi, dphi, ddphi);
    const double c = std::cos(phi), s = std::sin(phi), quarter_a = 0.25 * amplitude_;
    return {amplitude_ - quarter_a * (1.0 - c), -quarter_a * s * dphi,
            -quarter_a * (c * dphi * dphi + s * ddphi)};
  }

 private:
  // Phase (rad) and its first two derivatives at time tau (s) since the phase origin.
  void phase(double tau, double& phi, double& dphi, double& ddphi) const {
    if (tau <= sweep_s_) {
      phi = tau * (omega0_ + 0.5 * omega_rate_ * tau);
      dphi = omega0_ + omega_rate_ * tau;
      ddphi = omega_rate_;
    } else {
      phi = phase_at_sweep_end_ + omega1_ * (tau - sweep_s_);
      dphi = omega1_;
      ddphi = 0.0;
    }
  }

  double amplitude_;
  bool half_;
  double omega0_, omega1_;  // rad/s
  double sweep_s_;          // chirp duration (s); infinite for a sine
  double omega_rate_;       // dω/dt (rad/s²)
  double phase_at_sweep_end_;
  double t0_;  // start of the half-stroke oscillation (s)
};

// Force from a CSV, linear between rows, end values held.
class CsvForce final : public ForceInput {
 public:
  CsvForce(std::string spec, std::vector<double> t, std::vector<double> f)
      : ForceInput(std::move(spec)), t_(std::move(t)), f_(std::move(f)), slope_(t_.size() - 1) {
    for (std::size_t i = 0; i + 1 < t_.size(); ++i) {
      slope_[i] = (f_[i + 1] - f_[i]) / (t_[i + 1] - t_[i]);
    }
  }

  double force_n(double t) const override {
    if (t <= t_.front()) return f_.front();
    if (t >= t_.back()) return f_.back();
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
    return f_[i] + slope_[i] * (t - t_[i]);
  }
  double given_until_s() const override { return t_.back(); }
  double given_from_s() const override { return t_.front(); }

 private:
  std::vector<double> t_, f_, slope_;
};

// Key angle from a CSV through a natural cubic spline, end values held.
class CsvMotion final : public MotionInput {
 public:
  CsvMotion(std::string spec, CubicSpline spline)
      : MotionInput(std::move(spec)), spline_(std::move(spline)) {}

  KeyMotionSample motion(double t) const override {
    const CubicSpline::Sample s = spline_.evaluate(t);
    return {s.value, s.first, s.second};
  }
  double given_until_s() const override { return spline_.x_max(); }
  double given_from_s() const override { return spline_.x_min(); }

 private:
  CubicSpline spline_;
};

// Physical line number of data row `row` (0-based) in a CSV, following read_csv's rules (blank
// and '#' lines skipped, the first other line is the header); 0 if not found. Only used to word
// error messages, so reading the file again is fine.
int data_row_line(const std::string& path, std::size_t row) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  int number = 0;
  bool header_seen = false;
  std::size_t rows_seen = 0;
  while (std::getline(in, line)) {
    ++number;
    std::string_view view(line);
    if (number == 1 && view.substr(0, 3) == "\xEF\xBB\xBF") view.remove_prefix(3);
    while (!view.empty() && (view.back() == '\r' || view.back() == ' ' || view.back() == '\t')) {
      view.remove_suffix(1);
    }
    view = trim(view);
    if (view.empty() || view.front() == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    if (rows_seen++ == row) return number;
  }
  return 0;
}

/// Where data row `row` (0-based) is, for a message: "line N" of the file, or "row N+1" when its
/// line cannot be found.
std::string data_row_place(const std::string& path, std::size_t row) {
  const int line = data_row_line(path, row);
  return line > 0 ? "line " + std::to_string(line) : "row " + std::to_string(row + 1);
}

/// How far the spline through a recorded key motion may stray beyond the recorded angles, as a
/// fraction of their range: the true motion of a sampled smooth stroke peaks between samples,
/// above the highest one by (π f Δt)²/2 of its half-range at most (5 % for a 10 Hz stroke
/// sampled at only 100 Hz); a spline forced round the sharp corner of a ramp or a step strays
/// by a third or more (a 2.5° ramp over 5 ms: 1.2° past its top, 0.7° below its foot).
constexpr double kSplineStrayOfRange = 0.1;

/// Throws InputError naming the lines between which the spline through (t_i, angle_i) strays
/// beyond the recorded angles by more than kSplineStrayOfRange of their range: a motion with
/// corners the key would be driven past (with the huge accelerations of the corners).
void check_spline_follows_the_data(const std::string& path, const std::vector<double>& t,
                                   const std::vector<double>& angle, const CubicSpline& spline) {
  const auto [lowest, highest] = std::minmax_element(angle.begin(), angle.end());
  const double range = *highest - *lowest;
  if (!(range > 0.0)) return;
  constexpr int kSamplesPerInterval = 8;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    for (int k = 1; k < kSamplesPerInterval; ++k) {
      const double at = t[i] + (t[i + 1] - t[i]) * k / kSamplesPerInterval;
      const double value = spline.evaluate(at).value;
      const double stray = std::max(value - *highest, *lowest - value);
      if (stray <= kSplineStrayOfRange * range) continue;
      const int first = data_row_line(path, i), second = data_row_line(path, i + 1);
      const std::string where =
          first > 0 && second > 0
              ? "lines " + std::to_string(first) + " and " + std::to_string(second)
              : "rows " + std::to_string(i + 1) + " and " + std::to_string(i + 2);
      throw InputError(located_message(
          path, "",
          "key_angle_deg changes too abruptly between " + where +
              ": the smooth curve through the rows (which gives the "
              "key's rate and acceleration) passes " +
              format_fixed(stray * 180.0 / kPi, 2) +
              " deg beyond the recorded angles there; record the motion more finely or round "
              "its corners"));
    }
  }
}

/// Key angles a recorded motion may hold, as fractions of the full dip (rad from rest): a little
/// above rest (a key lifted off its back rail) to half a dip beyond the punching (a key pressed
/// hard into its felt sinks a millimetre or so; half a dip is five). Beyond, no key can be.
constexpr double kLowestAngleOfDip = -0.5, kDeepestAngleOfDip = 1.5;

std::unique_ptr<KeyInput> parse_csv_input(const std::string& spec, const std::string& path,
                                          double full_dip_angle_rad) {
  const CsvTable table = read_csv(path);
  const int time_column = table.column_index("time_s");
  const int angle_column = table.column_index("key_angle_deg");
  const int force_column = table.column_index("key_force_n");
  if (time_column < 0) {
    throw InputError(located_message(path, "", "needs a time_s column"));
  }
  if (angle_column < 0 && force_column < 0) {
    throw InputError(located_message(path, "", "needs a key_force_n or key_angle_deg column"));
  }
  if (table.rows.size() < 2) {
    throw InputError(located_message(
        path, "", "needs at least 2 rows of data (got " + std::to_string(table.rows.size()) + ")"));
  }
  std::vector<double> time = table.column("time_s");
  for (std::size_t i = 1; i < time.size(); ++i) {
    if (time[i] > time[i - 1]) continue;
    throw InputError(located_message(path, "",
                                     "time_s must increase (" + data_row_place(path, i) + ": " +
                                         number_text(time[i]) + " after " +
                                         number_text(time[i - 1]) + ")"));
  }
  // the run starts at t = 0 at rest and holds the first row until its time: a file starting
  // later must start at rest, or the action would be held pressed by a guess
  auto require_rest_before_first_row = [&](const char* column, double value, double at_rest,
                                           const char* unit) {
    if (time.front() <= 0.0 || std::abs(value) <= at_rest) return;
    throw InputError(located_message(
        path, "",
        std::string("starts at time_s ") + number_text(time.front()) + " s with " + column + " " +
            number_text(value) + " " + unit + " (" + data_row_place(path, 0) +
            "): every run starts at t = 0 at rest, and this value would be held from 0 to " +
            number_text(time.front()) + " s; add a row at rest at time 0 or shift the times to " +
            "start at 0"));
  };
  if (angle_column >= 0) {
    std::vector<double> angle = table.column("key_angle_deg");
    require_rest_before_first_row("key_angle_deg", angle.front(), kCsvRestAngleDeg, "deg");
    for (std::size_t i = 0; i < angle.size(); ++i) {
      const double a = rad(angle[i]);
      // a known full dip (0: not known here) bounds the angles a key can take
      if (full_dip_angle_rad > 0.0 && (a < kLowestAngleOfDip * full_dip_angle_rad ||
                                       a > kDeepestAngleOfDip * full_dip_angle_rad)) {
        const double dip_deg = full_dip_angle_rad * 180.0 / kPi;
        throw InputError(located_message(
            path, "",
            "key_angle_deg " + number_text(angle[i]) + " on " + data_row_place(path, i) +
                " is beyond the key's travel (0 at rest, full dip " + format_fixed(dip_deg, 2) +
                " deg; accepted from " + format_fixed(kLowestAngleOfDip * dip_deg, 2) + " to " +
                format_fixed(kDeepestAngleOfDip * dip_deg, 2) + ")"));
      }
      angle[i] = a;
    }
    CubicSpline spline(time, angle);
    check_spline_follows_the_data(path, time, angle, spline);
    // the run starts at t = 0 with the action at rest: a recording already away from rest there
    // would move the key in no time (1 deg at t = 0 asked a 135 N finger force and threw the
    // hammer); one starting later at rest was refused above
    const double start_deg = spline.evaluate(0.0).value * 180.0 / kPi;
    if (time.front() <= 0.0 && std::abs(start_deg) > kCsvRestAngleDeg)
      throw InputError(located_message(
          path, "",
          "key_angle_deg is " + number_text(start_deg) + " deg at time_s 0 (" +
              data_row_place(path, 0) +
              "): every run starts at t = 0 with the key at rest (0 deg), so the key would jump "
              "there in no time; start the recording at rest, or take its rest angle off every "
              "row"));
    auto motion = std::make_unique<CsvMotion>(spec, std::move(spline));
    if (force_column >= 0)
      motion->set_note(path +
                       ": has key_angle_deg and key_force_n; the key follows key_angle_deg and "
                       "key_force_n is not used (the finger force is computed)");
    return motion;
  }
  std::vector<double> force = table.column("key_force_n");
  require_rest_before_first_row("key_force_n", force.front(), kCsvRestForceN, "N");
  return std::make_unique<CsvForce>(spec, std::move(time), std::move(force));
}

bool parse_stroke(const std::string& spec, std::string_view field) {
  if (field == "full") return false;
  if (field == "half") return true;
  spec_error(spec, "unknown stroke '" + std::string(field) + "' (expected full or half)");
}

void require_full_dip(const std::string& spec, const InputContext& context) {
  if (!(context.full_dip_angle_rad > 0.0) || !std::isfinite(context.full_dip_angle_rad)) {
    spec_error(spec, "motion inputs need the action's full-dip angle, which is not known (got " +
                         number_text(context.full_dip_angle_rad) + " rad)");
  }
}

}  // namespace

std::unique_ptr<KeyInput> parse_input_spec(const std::string& spec, const InputContext& context) {
  const std::string_view text = trim(spec);
  if (text.substr(0, 4) == "csv:") {
    const std::string path(trim(text.substr(4)));
    if (path.empty())
      spec_error(spec,
                 "expected csv:PATH (a CSV file with time_s and "
                 "key_force_n or key_angle_deg)");
    return parse_csv_input(spec, path, context.full_dip_angle_rad);
  }

  const std::vector<std::string_view> f = split(text, ':');
  const std::string_view kind = f[0];
  const std::string_view sub = f.size() > 1 ? f[1] : std::string_view();

  if (kind == "mass") {
    const std::string form = "expected mass:Mkg or mass:Mg, e.g. mass:1kg or mass:250g";
    if (f.size() != 2) spec_error(spec, form);
    double value = 0.0;
    std::string_view unit;
    if (!parse_number_prefix(f[1], value, unit)) spec_error(spec, form);
    unit = trim(unit);
    if (unit != "kg" && unit != "g") spec_error(spec, form);
    if (!std::isfinite(value)) spec_error(spec, "the mass is not a finite number (" + form + ")");
    if (value < 0.0) {
      spec_error(spec, "the mass must not be negative (got " + std::string(f[1]) + ")");
    }
    return std::make_unique<MassInput>(spec, unit == "kg" ? value : value / 1000.0);
  }

  if (kind == "force" && sub == "const") {
    const std::string form = "expected force:const:N (newtons)";
    if (f.size() != 3) spec_error(spec, form);
    return std::make_unique<ConstantForce>(spec, parse_field(spec, f[2], form));
  }

  if (kind == "force" && (sub == "pulse" || sub == "double")) {
    const bool twice = sub == "double";
    const std::string form = twice ? "expected force:double:N:MS:GAP_MS (newtons, milliseconds, "
                                     "milliseconds)"
                                   : "expected force:pulse:N:MS (newtons, milliseconds)";
    if (f.size() != (twice ? 5u : 4u)) spec_error(spec, form);
    const double force = parse_field(spec, f[2], form);
    const double hold_ms = parse_field(spec, f[3], form);
    require_positive(spec, hold_ms, "the pulse length MS", "ms");
    double gap_ms = 0.0;
    if (twice) {
      gap_ms = parse_field(spec, f[4], form);
      if (gap_ms < 0.0) {
        spec_error(spec,
                   "the gap GAP_MS must not be negative (got " + number_text(gap_ms) + " ms)");
      }
    }
    return std::make_unique<PulseForce>(spec, force, hold_ms / 1000.0, twice, gap_ms / 1000.0);
  }

  if (kind == "motion" && sub == "sine") {
    const std::string form = "expected motion:sine:HZ[:full|half] (hertz)";
    if (f.size() != 3 && f.size() != 4) spec_error(spec, form);
    const double hz = parse_field(spec, f[2], form);
    require_key_frequency(spec, hz, "the frequency");
    const bool half = f.size() == 4 && parse_stroke(spec, f[3]);
    require_full_dip(spec, context);
    return std::make_unique<StrokeMotion>(spec, context.full_dip_angle_rad, hz, hz,
                                          std::numeric_limits<double>::infinity(), half);
  }

  if (kind == "motion" && sub == "chirp") {
    const std::string form =
        "expected motion:chirp:F0:F1:SECONDS[:full|half] (hertz, hertz, seconds)";
    if (f.size() != 5 && f.size() != 6) spec_error(spec, form);
    const double f0 = parse_field(spec, f[2], form);
    const double f1 = parse_field(spec, f[3], form);
    const double seconds = parse_field(spec, f[4], form);
    require_key_frequency(spec, f0, "the start frequency F0");
    require_key_frequency(spec, f1, "the end frequency F1");
    require_positive(spec, seconds, "the sweep duration SECONDS", "s");
    const bool half = f.size() == 6 && parse_stroke(spec, f[5]);
    require_full_dip(spec, context);
    return std::make_unique<StrokeMotion>(spec, context.full_dip_angle_rad, f0, f1, seconds, half);
  }

  if (kind == "motion" && sub == "press") {
    const std::string form = "expected motion:press:SECONDS (seconds to full dip)";
    if (f.size() != 3) spec_error(spec, form);
    const double seconds = parse_field(spec, f[2], form);
    require_positive(spec, seconds, "the press duration SECONDS", "s");
    // no faster than the fastest stroke accepted: half a period at kMaxKeyMotionHz
    const double shortest_s = 0.5 / kMaxKeyMotionHz;
    if (seconds < shortest_s)
      spec_error(spec, "the press must take at least " + number_text(shortest_s) + " s (got " +
                           number_text(seconds) + " s), half a period of the fastest key motion " +
                           "accepted (" + number_text(kMaxKeyMotionHz) +
                           " Hz): no key is pressed faster");
    require_full_dip(spec, context);
    return std::make_unique<PressMotion>(spec, context.full_dip_angle_rad, seconds);
  }

  throw InputError("unknown input SPEC '" + spec + "' (" + kKnownSpecs + ")");
}

std::string input_notes(const KeyInput& input, double run_end_s) {
  std::string notes = input.note();
  const double t_end = input.given_until_s();
  if (input.given_from_s() >= run_end_s) {
    // a recording that begins after the run ends: the run sees none of it
    notes += (notes.empty() ? "" : "; ") +
             ("the input begins at " + format_number(input.given_from_s(), 6) +
              " s, after the run's end at " + format_number(run_end_s, 6) +
              " s: the action stays at rest for the whole run");
  } else if (t_end < run_end_s) {
    const std::string last =
        input.is_motion()
            ? "key angle, " + format_number(input.motion(t_end).angle * 180.0 / kPi, 4) + " deg,"
            : "force, " + format_number(input.force_n(t_end), 4) + " N,";
    notes +=
        (notes.empty() ? "" : "; ") +
        ("the input ends at " + format_number(t_end, 6) + " s; its last " + last + " is held ") +
        (std::isfinite(run_end_s) ? "to the run's end at " + format_number(run_end_s, 6) + " s"
                                  : std::string("after it"));
  }
  return notes;
}

}  // namespace pat

// What drives the key: a force at the key front, or a prescribed key motion.
//
// Sign conventions: a force is positive downward (pressing the key); a key angle is in radians
// from the rest position, positive when the key front goes down.
#pragma once

#include <limits>
#include <memory>
#include <string>

namespace pat {

/// Highest frequency of a key motion (motion:sine, motion:chirp, sweeps), Hz. A finger trills at
/// about 10–15 Hz and the actions stop repeating near 11–20 Hz (fact F4); 100 Hz leaves room
/// for any study while refusing numbers that are slips (1e6 Hz: every 1e-5 s step would land
/// on the same phase and the key would never move).
constexpr double kMaxKeyMotionHz = 100.0;

/// Prescribed key angle and its first two time derivatives (rad, rad/s, rad/s²).
struct KeyMotionSample {
  double angle = 0.0;
  double rate = 0.0;
  double acceleration = 0.0;
};

class KeyInput {
 public:
  virtual ~KeyInput() = default;
  /// true: the key angle is prescribed (motion()) and the finger force is an output.
  /// false: force_n() is applied at the key front and the key moves freely.
  virtual bool is_motion() const = 0;
  /// Downward force at the key front (N) at time t (s). Force inputs only.
  virtual double force_n(double t) const = 0;
  /// Prescribed key angle at time t (s). Motion inputs only.
  virtual KeyMotionSample motion(double t) const = 0;
  /// A point mass placed on the key front at t = 0 (kg): its weight and its inertia act on
  /// the key through the dynamics (the paper's 1 kg test). 0 for other inputs.
  virtual double added_mass_kg() const { return 0.0; }
  /// The SPEC the input was made from, for metadata and messages.
  virtual const std::string& spec() const = 0;
  /// The time the input is given up to (s): a recorded file's last row; infinity for a SPEC
  /// defined for all time. Later the input holds its last value.
  virtual double given_until_s() const { return std::numeric_limits<double>::infinity(); }
  /// Time (s) of the input's first given value: a recording's first row (before it the run is
  /// at rest); 0 for the generated inputs.
  virtual double given_from_s() const { return 0.0; }
  /// What the user should know about how the input was read, in words (empty: nothing), e.g.
  /// that a CSV with both a force and a key angle column drives the key by its angle.
  virtual std::string note() const { return {}; }
};

/// How near rest the first row of a CSV input starting after t = 0 must be (its value is held
/// from t = 0, when every run starts at rest): 0.1 N, under half of the smallest force that
/// moves a key (an upweight of 20–30 g, 0.2–0.3 N, fact F9); 0.1°, 0.4 mm at a 220 mm key front,
/// four times the key sensor's scatter at rest (engine/measured/key_sensor.h).
constexpr double kCsvRestForceN = 0.1;
constexpr double kCsvRestAngleDeg = 0.1;

/// Model quantities the input SPECs need.
struct InputContext {
  /// Key angle at full dip (rad, > 0): where the key front meets the front-rail punching.
  double full_dip_angle_rad = 0.0;
};

/// Parses an input SPEC (DESIGN.md section 5):
///   mass:1kg  mass:250g          a point mass on the key tip (the number and unit kg or g)
///   force:const:N                a constant force of N newtons from t = 0
///   force:pulse:N:MS             N newtons held MS milliseconds, with 1 ms linear ramps up
///                                (from t = 0) and down, then zero
///   force:double:N:MS:GAP_MS     two such pulses; the second starts GAP_MS after the end of the
///                                first one's down ramp
///   motion:sine:HZ[:full|half]   full (default): angle = A/2 (1 − cos 2πf t), A = full dip;
///                                half: a first half period of the full-stroke sine brings the key
///                                to full dip, then it oscillates between A and A/2:
///                                angle = A − A/4 (1 − cos 2πf (t − t0)), t0 = 1/(2f)
///   motion:chirp:F0:F1:SECONDS[:full|half]
///                                the same with the phase φ(t) = 2π(F0 t + (F1−F0) t²/(2 SECONDS)),
///                                frequency held at F1 after SECONDS; half mode: the first descent
///                                is a half period at F0, then φ counts from t0 = 1/(2 F0)
///   motion:press:SECONDS         the technician's slow press: the key goes from rest to full dip
///                                along a half cosine in SECONDS, angle = A/2 (1 − cos πt/SECONDS),
///                                and is held at full dip after it
///   csv:PATH                     a CSV (io/csv.h) with time_s and either key_force_n (force) or
///                                key_angle_deg (motion); force is interpolated linearly, the angle
///                                with a natural cubic spline (which gives rate and acceleration);
///                                before the first and after the last row the end value is held,
///                                so a file whose first row comes after t = 0 must start at rest
///                                (force within kCsvRestForceN, angle within kCsvRestAngleDeg);
///                                with both columns the angle drives the key (note() says so).
/// Throws InputError naming the SPEC (and the file and line for csv:) and what is wrong.
std::unique_ptr<KeyInput> parse_input_spec(const std::string& spec, const InputContext& context);

/// What the user should know of `input` for a run ending at `run_end_s` (infinity: a run without
/// an end, the window's), in words: its note(), and for a recording that ends first, that its
/// last value is held ("the input ends at 0.05 s; its last force, 20 N, is held to the run's end
/// at 0.1 s" or "… is held after it"). Empty when there is nothing to say.
std::string input_notes(const KeyInput& input, double run_end_s);

}  // namespace pat

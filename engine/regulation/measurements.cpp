#include "regulation/measurements.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/parallel_runs.h"
#include "core/error.h"
#include "core/format.h"
#include "dynamics/action_dynamics.h"
#include "model/model_edits.h"
#include "regulation/technician_tests.h"
#include "sim/key_travel.h"

namespace pat {
namespace {

std::string setting_names(const ActionModel& model) {
  std::string names;
  for (const RegulationSetting& s : model.regulation) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

const RegulationSetting& find_setting(const ActionModel& model, const std::string& name) {
  const int index = model.setting_index(name);
  if (index < 0)
    throw InputError("unknown setting '" + name + "' for the " + model.kind +
                     " action (expected one of: " + setting_names(model) + ")");
  return model.regulation[index];
}

/// The contact an adjuster moves (its first contact effect), or -1.
int adjusted_contact(const ActionModel& model, const std::string& adjuster) {
  const int index = model.adjuster_index(adjuster);
  if (index < 0) return -1;
  for (const AdjusterEffect& e : model.adjusters[index].effects)
    if (e.target == AdjusterEffect::Target::ContactA ||
        e.target == AdjusterEffect::Target::ContactB)
      return e.index;
  return -1;
}

/// Jack position (grand): the back edge of the jack top (the end of the escapement contact's
/// segment nearest the strings, +x) relative to the knuckle core (the contact circle's centre),
/// measured along the jack top; + means the edge lies toward the strings (jack too deep).
double jack_position_mm(const ActionModel& model, const RestState& rest) {
  const Contact& c = model.contacts[model.landmarks.escapement_contact];
  if (c.shape != ContactShape::CircleSegment)
    throw std::runtime_error("jack_position needs a circle-segment knuckle-jack contact");
  ActionDynamics dynamics(model, nullptr);
  const Vec2 core = dynamics.point_position(c.body_a, c.center_a, rest.q);
  const Vec2 s0 = dynamics.point_position(c.body_b, c.segment_start, rest.q);
  const Vec2 s1 = dynamics.point_position(c.body_b, c.segment_end, rest.q);
  const Vec2 edge = s0.x() > s1.x() ? s0 : s1;
  const Vec2 along = (edge - (s0.x() > s1.x() ? s1 : s0)).normalized();
  return (edge - core).dot(along) * 1e3;
}

/// Repetition lever height (grand, mm): the knuckle–jack gap at rest while the lever carries the
/// knuckle. A lever screwed below the point where the knuckle settles on the jack (the gap then
/// stays at minus the felt's compression under the hammer, whatever the screw) is read as the
/// technician sees it: the lever top stands clear below the knuckle, and that gap counts
/// negative. Both parts are contact gaps, so the reading is continuous where the knuckle passes
/// from the lever onto the jack.
double lever_height_mm(const ActionModel& model, const RestState& rest) {
  const double jack_gap = contact_gap(model, model.landmarks.escapement_contact, rest.q);
  // the knuckle–lever contact: between the hammer and the body the height screw holds
  const int screw = adjusted_contact(model, "lever_height");
  const int lever = screw >= 0 ? model.contacts[screw].body_a : -1;
  const int hammer = model.landmarks.hammer;
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    const Contact& c = model.contacts[i];
    if (lever >= 0 && c.body_a == hammer && c.body_b == lever)
      return (jack_gap - std::max(contact_gap(model, static_cast<int>(i), rest.q), 0.0)) * 1e3;
  }
  throw std::runtime_error(
      "lever_height needs a contact between the hammer and the repetition lever");
}

/// Bridle strap slack at rest (mm): how much farther apart its ends can move before it pulls.
double bridle_slack_mm(const ActionModel& model, const RestState& rest) {
  const int strap_index = model.strap_index("bridle");
  if (strap_index < 0) throw std::runtime_error("this action has no bridle strap (removed?)");
  const Strap& strap = model.straps[strap_index];
  ActionDynamics dynamics(model, nullptr);
  const DofVector zero = DofVector::Zero(model.dofs());
  // the strap's free length: its ends' distance in the preset configuration plus its slack
  const double free_length = (dynamics.point_position(strap.body_a, strap.point_a, zero) -
                              dynamics.point_position(strap.body_b, strap.point_b, zero))
                                 .norm() +
                             strap.slack;
  const double length = (dynamics.point_position(strap.body_a, strap.point_a, rest.q) -
                         dynamics.point_position(strap.body_b, strap.point_b, rest.q))
                            .norm();
  return (free_length - length) * 1e3;
}

}  // namespace

namespace {

bool within(double measured, double target, double tolerance) {
  return std::abs(measured - target) <= tolerance;  // false for NaN
}

}  // namespace

bool within_tolerance(const RegulationSetting& setting, double measured) {
  return within(measured, setting.target, setting.tolerance);
}

bool SettingReading::within_tolerance() const {
  return within(measured, target, tolerance);
}

double measure_setting(const ActionModel& model, const std::string& name,
                       const RestState* given_rest) {
  find_setting(model, name);
  const RestState rest = given_rest ? *given_rest : find_rest_state(model);
  const ActionLandmarks& marks = model.landmarks;
  if (name == "key_dip")
    return key_front_travel(model, rest, key_full_dip_angle(model, rest)) * 1e3;
  if (name == "hammer_blow") return rest.hammer_string_gap * 1e3;
  if (name == "lever_height") return lever_height_mm(model, rest);
  if (name == "lost_motion") return contact_gap(model, marks.escapement_contact, rest.q) * 1e3;
  if (name == "jack_position") return jack_position_mm(model, rest);
  if (name == "bridle") return bridle_slack_mm(model, rest);
  if (name == "let_off" || name == "drop" || name == "damper_lift") {
    const SlowPressReading press = slow_press(
        model, rest, name == "damper_lift" ? adjusted_contact(model, name) : -1, name != "drop");
    if (name == "let_off") return press.let_off_gap * 1e3;
    if (name == "drop") return press.drop_gap * 1e3;
    return press.damper_lift_fraction;
  }
  if (name == "checking") return forte_blow(model, rest).checked_gap * 1e3;
  throw InputError("setting '" + name + "' has no measurement procedure");
}

double measure_aftertouch(const ActionModel& model, const RestState* given_rest) {
  const RestState rest = given_rest ? *given_rest : find_rest_state(model);
  const SlowPressReading press = slow_press(model, rest, -1, true);
  if (!std::isfinite(press.aftertouch))
    throw std::runtime_error("in a slow key press the jack never lets the hammer off");
  return press.aftertouch * 1e3;
}

SettingReading read_setting(const ActionModel& model, const RegulationSetting& s,
                            const RestState* rest) {
  SettingReading r;
  r.name = s.name;
  r.unit = s.unit;
  r.target = s.target;
  r.tolerance = s.tolerance;
  r.adjuster_mm = model.adjusters[model.adjuster_index(s.name)].value * 1e3;
  const auto unreadable = [&](const std::string& why) {
    r.measured = std::numeric_limits<double>::quiet_NaN();
    r.problem = why;
  };
  try {
    r.measured = measure_setting(model, s.name, rest);
  } catch (const HammerCarriedElsewhere& e) {
    const int clear = s.clear_adjuster.empty() ? -1 : model.adjuster_index(s.clear_adjuster);
    // nothing to do when the adjuster is already at its clear position or beyond it, farther
    // out of the way
    const double turned = clear < 0 ? 0.0 : model.adjusters[clear].value;
    if (clear < 0 ||
        (s.clear_position >= 0.0 ? turned >= s.clear_position : turned <= s.clear_position)) {
      unreadable(e.what());
      return r;
    }
    // what a technician does on seeing it: the part that carries the hammer moved out of the
    // way, the setting read, and (as the note says) the part to be set afterwards
    std::string part = adjuster_part_words(model.adjusters[clear].description);
    if (part.empty()) part = setting_words(s.clear_adjuster) + " adjuster";
    try {
      r.measured =
          measure_setting(with_adjuster(model, s.clear_adjuster, s.clear_position), s.name);
      const std::string held = format_fixed(e.held_gap() * 1e3, 1);
      const std::string position =
          (s.clear_position > 0.0 ? "+" : "") + format_fixed(s.clear_position * 1e3, 2);
      r.note = "read with the " + part + " out of the way (" + setting_words(s.clear_adjuster) +
               " " + position + " mm), as technicians read " + setting_words(s.name) +
               "; as the action stands the hammer is carried on to " + held +
               " mm from the string and held there, so its " + setting_words(s.name) +
               " is not seen";
    } catch (const std::exception& again) {
      unreadable(std::string(e.what()) + "; with the " + part + " out of the way: " + again.what());
    }
  } catch (const std::exception& e) {
    unreadable(e.what());
  }
  return r;
}

std::vector<SettingReading> read_settings(const ActionModel& model,
                                          const ProgressCallback& progress, unsigned threads) {
  const RestState rest = find_rest_state(model);
  std::vector<SettingReading> readings(model.regulation.size());
  ProgressReporter reporter(progress, readings.size());
  run_parallel(
      readings.size(),
      [&](std::size_t i) { readings[i] = read_setting(model, model.regulation[i], &rest); },
      &reporter, threads);
  return readings;
}

std::vector<SettingReading> measure_settings(const ActionModel& model) {
  std::vector<SettingReading> readings = read_settings(model, {}, 1);
  for (const SettingReading& r : readings)
    if (!r.problem.empty()) throw std::runtime_error(r.problem);
  return readings;
}

std::string regulation_state(const ActionModel& model) {
  const std::string offsets = adjuster_settings_text(model);
  if (offsets == "regulated") return offsets;
  const std::vector<SettingReading> readings = read_settings(model, {}, 1);
  const bool within = std::all_of(readings.begin(), readings.end(),
                                  [](const SettingReading& r) { return r.within_tolerance(); });
  return within ? "regulated" : offsets;
}

}  // namespace pat

#include "model/model_edits.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/format.h"

namespace pat {
namespace {

std::string mm(double metres) {
  std::ostringstream out;
  out << metres * 1e3 << " mm";
  return out.str();
}

std::string adjuster_names(const ActionModel& model) {
  std::string names;
  for (const Adjuster& a : model.adjusters) names += (names.empty() ? "" : ", ") + a.name;
  return names;
}

}  // namespace

ActionModel with_adjuster(const ActionModel& model, const std::string& name, double value_m) {
  const int index = model.adjuster_index(name);
  if (index < 0)
    throw InputError("unknown setting '" + name + "' for the " + model.kind +
                     " action (expected one of: " + adjuster_names(model) + ")");
  const Adjuster& adjuster = model.adjusters[index];
  if (!std::isfinite(value_m) || value_m < adjuster.min - 1e-12 || value_m > adjuster.max + 1e-12)
    throw InputError("setting '" + name + "': " + mm(value_m) + " is outside its physical range [" +
                     mm(adjuster.min) + ", " + mm(adjuster.max) + "]");
  ActionModel out = model;
  const double delta = value_m - adjuster.value;
  for (const AdjusterEffect& e : adjuster.effects) {
    const Vec2 shift = delta * e.direction;
    switch (e.target) {
      case AdjusterEffect::Target::ContactA:
        out.contacts[e.index].center_a += shift;
        break;
      case AdjusterEffect::Target::ContactB: {
        Contact& c = out.contacts[e.index];
        c.center_b += shift;
        c.segment_start += shift;
        c.segment_end += shift;
        break;
      }
      case AdjusterEffect::Target::StrapSlack:
        out.straps[e.index].slack += delta;
        break;
      case AdjusterEffect::Target::StrapPointA:
      case AdjusterEffect::Target::StrapPointB: {
        // the tape keeps its length when the end it hangs on moves (bending the bridle wire): its
        // rest length is the span between the ends in the drawing configuration plus the slack
        // (ActionDynamics), so the slack gives what the span gains
        Strap& strap = out.straps[e.index];
        const double span_before = (strap.point_a - strap.point_b).norm();
        (e.target == AdjusterEffect::Target::StrapPointA ? strap.point_a : strap.point_b) += shift;
        strap.slack -= (strap.point_a - strap.point_b).norm() - span_before;
        break;
      }
    }
  }
  for (Fixture& f : out.fixtures)
    if (f.adjuster == name)
      for (Vec2& p : f.outline) p += delta * f.adjuster_direction;
  out.adjusters[index].value = value_m;
  return out;
}

ActionModel without_part(const ActionModel& model, const std::string& part) {
  ActionModel out = model;
  const int spring = model.spring_index(part);
  const int strap = model.strap_index(part);
  if (spring >= 0) {
    out.springs.erase(out.springs.begin() + spring);
  } else if (strap >= 0) {
    out.straps.erase(out.straps.begin() + strap);
  } else {
    std::string names;
    for (const JointSpring& s : model.springs) names += (names.empty() ? "" : ", ") + s.name;
    for (const Strap& s : model.straps) names += (names.empty() ? "" : ", ") + s.name;
    throw InputError("--without " + part + ": the " + model.kind +
                     " action has no such part (removable parts: " + names + ")");
  }
  out.removed_parts.push_back(part);
  return out;
}

std::string model_origin(const ActionModel& model) {
  std::string changes;
  for (const std::string& part : model.removed_parts)
    changes += (changes.empty() ? " without " : ", without ") + part;
  // which adjusters, and how far, is left out: the practice mode's hidden faults are adjusters
  // turned, and these messages reach the student
  for (const Adjuster& a : model.adjusters) {
    if (a.value == 0.0) continue;
    changes += changes.empty() ? " with adjusters turned" : ", adjusters turned";
    break;
  }
  return model.source_file + changes;
}

std::string adjuster_settings_text(const ActionModel& model) {
  std::string settings;
  for (const Adjuster& a : model.adjusters)
    if (a.value != 0.0)
      settings +=
          (settings.empty() ? "" : " ") + a.name + "=" + format_number(a.value * 1e3) + "mm";
  return settings.empty() ? "regulated" : settings;
}

std::map<std::string, std::string> model_metadata(const ActionModel& model) {
  std::map<std::string, std::string> metadata{{"action", model.kind},
                                              {"preset", model.source_file},
                                              {"settings", adjuster_settings_text(model)}};
  std::string removed;
  for (const std::string& part : model.removed_parts)
    removed += (removed.empty() ? "" : " ") + part;
  if (!removed.empty()) metadata["without"] = removed;
  return metadata;
}

ActionModel with_setting(const ActionModel& model, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + assignment + "': expected NAME=MM, e.g. let_off=0.5");
  const std::string name = assignment.substr(0, eq);
  const std::string number = assignment.substr(eq + 1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
    throw InputError("--set '" + assignment + "': '" + number + "' is not a number of millimetres");
  return with_adjuster(model, name, value * 1e-3);
}

}  // namespace pat

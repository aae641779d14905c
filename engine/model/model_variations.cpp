#include "model/model_variations.h"

#include <cmath>

#include "core/error.h"
#include "core/format.h"

namespace pat {

ActionModel with_spring_factor(const ActionModel& model, const std::string& name, double factor) {
  const int index = model.spring_index(name);
  if (index < 0) {
    std::string names;
    for (const JointSpring& s : model.springs) names += (names.empty() ? "" : ", ") + s.name;
    throw InputError(model.source_file + ": no spring named '" + name + "' (springs: " + names +
                     ")");
  }
  // ten times a spring's strength is beyond any spring a technician fits; more is a slip (1e308
  // had been refused as "the action does not settle at rest", naming no option)
  constexpr double kStrongestFactor = 10.0;
  if (!(factor >= 0.0) || !(factor <= kStrongestFactor))
    throw InputError("spring factor for '" + name + "' must be from 0 to 10, got " +
                     format_number(factor));
  ActionModel out = model;
  out.springs[index].stiffness *= factor;
  out.springs[index].preload *= factor;
  return out;
}

ActionModel with_key_front_lead(const ActionModel& model, double grams) {
  if (model.landmarks.key < 0) throw InputError(model.source_file + ": the action has no key");
  // a key carries a few leads of about 10 g; ±200 g is beyond any key (1e308 had been refused as
  // "the action does not settle at rest")
  constexpr double kHeaviestLeadG = 200.0;
  if (!(std::abs(grams) <= kHeaviestLeadG))
    throw InputError("key front lead must be within ±200 g, got " + format_number(grams) + " g");
  ActionModel out = model;
  Body& key = out.bodies[model.landmarks.key];
  const double dm = grams * 1e-3;
  const double m = key.mass + dm;
  if (m <= 0.0)
    throw InputError("key front lead " + std::to_string(grams) + " g leaves the key (" +
                     std::to_string(key.mass * 1e3) + " g) without mass");
  const Vec2 tip = model.landmarks.key_front;
  const Vec2 com = (key.mass * key.com + dm * tip) / m;
  const double inertia =
      key.inertia_com + key.mass * (key.com - com).squaredNorm() + dm * (tip - com).squaredNorm();
  if (inertia <= 0.0) throw InputError("key front lead leaves the key without inertia");
  key.mass = m;
  key.com = com;
  key.inertia_com = inertia;
  return out;
}

}  // namespace pat

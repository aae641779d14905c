#include "model/preset_loader.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/format.h"
#include "model/model_edits.h"

#ifndef PAT_PRESET_DIR
#define PAT_PRESET_DIR "presets"
#endif

namespace pat {
namespace {

using nlohmann::json;

constexpr double kMm = 1e-3;
constexpr double kFarthestPointMm = 10000.0;  // ten metres: see PresetReader::point

std::string type_name(const json& value) {
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  if (value.is_boolean()) return "a boolean";
  return "null";
}

/// The JSON path of field `key` of the object at `path` ("" is the root: "schema", not ".schema").
std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

/// "bodies[3] (hammer)": an item of a list by its place and, where it has one, its name.
std::string item_path(const std::string& list, std::size_t i, const json& item) {
  std::string path = list + "[" + std::to_string(i) + "]";
  if (item.is_object() && item.contains("name") && item["name"].is_string())
    path += " (" + item["name"].get<std::string>() + ")";
  return path;
}

/// Reads fields with their JSON path, so that every message names the field.
class PresetReader {
 public:
  explicit PresetReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw InputError(located_message(source_, path, problem));
  }

  const json& field(const json& object, const std::string& path, const char* key) const {
    if (!object.is_object()) fail(path, "expected an object, got " + type_name(object));
    read_keys_[&object].insert(key);
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing field '") + key + "'");
    return *it;
  }

  const json* optional(const json& object, const char* key) const {
    if (object.is_object()) read_keys_[&object].insert(key);
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  double number(const json& object, const std::string& path, const char* key) const {
    const json& value = field(object, path, key);
    if (!value.is_number()) fail(child(path, key), "expected a number, got " + type_name(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(child(path, key), "must be a finite number");
    return x;
  }

  double number_or(const json& object, const std::string& path, const char* key,
                   double fallback) const {
    return optional(object, key) ? number(object, path, key) : fallback;
  }

  double positive(const json& object, const std::string& path, const char* key) const {
    const double x = number(object, path, key);
    if (x <= 0.0) fail(child(path, key), "must be positive (got " + format(x) + ")");
    return x;
  }

  double nonnegative(const json& object, const std::string& path, const char* key,
                     double fallback) const {
    if (!optional(object, key)) return fallback;
    const double x = number(object, path, key);
    if (x < 0.0) fail(child(path, key), "must not be negative (got " + format(x) + ")");
    return x;
  }

  std::string text(const json& object, const std::string& path, const char* key) const {
    const json& value = field(object, path, key);
    if (!value.is_string()) fail(child(path, key), "expected a string, got " + type_name(value));
    return value.get<std::string>();
  }

  /// An item's "name": a string, not empty (commands and messages refer to parts by it).
  std::string name(const json& object, const std::string& path) const {
    std::string value = text(object, path, "name");
    if (value.find_first_not_of(" \t") == std::string::npos)
      fail(child(path, "name"), "a name must not be empty");
    return value;
  }

  const json& array(const json& object, const std::string& path, const char* key) const {
    const json& value = field(object, path, key);
    if (!value.is_array()) fail(child(path, key), "expected an array, got " + type_name(value));
    return value;
  }

  Vec2 point(const json& value, const std::string& path, double scale) const {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      fail(path, "expected a pair of numbers [x, y]");
    const Vec2 p(value[0].get<double>(), value[1].get<double>());
    if (!p.allFinite()) fail(path, "must be finite numbers");
    // a position in mm: a piano action is well within a metre of its key's balance point; ten
    // metres is a slip (1e300 mm had loaded and run)
    if (scale == kMm && p.cwiseAbs().maxCoeff() > kFarthestPointMm)
      fail(path, "lies " + format(p.cwiseAbs().maxCoeff()) + " mm away: positions in an action " +
                     "are within ±" + format(kFarthestPointMm) + " mm");
    return p * scale;
  }

  /// `x`, read at `key`, no larger in size than `most`: beyond, no part of an action has it (a
  /// slip of units or a typo, which had loaded and run).
  double at_most(double x, const std::string& path, const char* key, double most) const {
    if (std::abs(x) > most)
      fail(child(path, key), std::string(x < 0.0 ? "must be at least -" : "must be at most ") +
                                 format(most) + " (got " + format(x) + ")");
    return x;
  }

  /// A positive number no larger than `most` (a mass, an inertia).
  double positive_at_most(const json& object, const std::string& path, const char* key,
                          double most) const {
    return at_most(positive(object, path, key), path, key, most);
  }

  Vec2 point(const json& object, const std::string& path, const char* key, double scale) const {
    return point(field(object, path, key), child(path, key), scale);
  }

  Vec2 unit(const json& object, const std::string& path, const char* key) const {
    const Vec2 v = point(object, path, key, 1.0);
    if (v.norm() < 1e-9) fail(child(path, key), "direction must not be zero");
    return v.normalized();
  }

  std::vector<Vec2> polygon(const json& object, const std::string& path, const char* key) const {
    std::vector<Vec2> points;
    const json& list = array(object, path, key);
    for (std::size_t i = 0; i < list.size(); ++i)
      points.push_back(point(list[i], child(path, key) + "[" + std::to_string(i) + "]", kMm));
    return points;
  }

  /// Every object names where its numbers come from.
  void require_source(const json& object, const std::string& path) const {
    const json& source = field(object, path, "source");
    if (!source.is_string() && !source.is_object())
      fail(path + ".source", "expected a string or an object of sources");
  }

  static std::string format(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  }

  /// Fails on a field the reader never asked for in an object it read (a misspelt "fricton"
  /// would otherwise load silently as a hammer without friction), naming the fields it knows
  /// there. Objects it did not read into (a source's free text) are not checked, nor are the
  /// fields that only document: `kDocumentationFields`.
  void check_unknown_fields(const json& value, const std::string& path) const {
    if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i)
        check_unknown_fields(value[i], item_path(path, i, value[i]));
      return;
    }
    if (!value.is_object()) return;
    const auto read = read_keys_.find(&value);
    for (const auto& [key, item] : value.items()) {
      // "_comment", "$comment": the usual ways of commenting JSON
      const bool comment = !key.empty() && (key[0] == '_' || key[0] == '$');
      if (read != read_keys_.end() && !read->second.count(key) &&
          !kDocumentationFields.count(key) && !comment) {
        std::string known;
        for (const std::string& k : read->second) known += (known.empty() ? "" : ", ") + k;
        fail(child(path, key),
             "a field that is not read here: misspelt, or not used by this kind of item (the "
             "fields read here are " +
                 known + ")");
      }
      check_unknown_fields(item, child(path, key));
    }
  }

 private:
  /// Fields that document a value and are never read: where it comes from, notes for a reader.
  inline static const std::set<std::string> kDocumentationFields = {
      "source", "note", "notes", "references", "comment", "description"};
  std::string source_;
  /// The fields asked for in each object read (present or not).
  mutable std::map<const json*, std::set<std::string>> read_keys_;
};

int body_reference(const PresetReader& r, const ActionModel& model, const json& object,
                   const std::string& path, const char* key) {
  const json& value = r.field(object, path, key);
  if (value.is_null()) return -1;
  if (!value.is_string()) r.fail(child(path, key), "expected a body name or null for the frame");
  const std::string name = value.get<std::string>();
  if (name == "frame") return -1;
  const int index = model.body_index(name);
  if (index < 0) r.fail(child(path, key), "unknown body '" + name + "'");
  return index;
}

FeltCurve read_curve(const PresetReader& r, const json& object, const std::string& path) {
  FeltCurve curve;
  // F = a x e^(b x) + c x with x in mm: a, c in N/mm, b in 1/mm → SI
  curve.a = r.nonnegative(object, path, "a_n_per_mm", 0.0) / kMm;
  curve.b = r.number_or(object, path, "b_per_mm", 0.0) / kMm;
  curve.c = r.nonnegative(object, path, "c_n_per_mm", 0.0) / kMm;
  if (curve.a == 0.0 && curve.c == 0.0) r.fail(path, "a felt curve needs a_n_per_mm or c_n_per_mm");
  return curve;
}

// The first penetration (m) in (0, max_penetration] where the unloading curve pushes harder
// than the loading one, if any: such a felt gives back more energy than it takes (the unloading
// branch of the paper's eq. 3 lies above the loading branch). Sampled every 1/400 of the range,
// with the exact exponential.
/// F = a x e^(b x) + c x (N, x in m) with the exact exponential (for the check below and its
/// message; the dynamics use felt_curve_force's faster one).
double exact_felt_force(const FeltCurve& curve, double x) {
  return curve.a * x * std::exp(curve.b * x) + curve.c * x;
}

std::optional<double> unloading_above_loading(const FeltLaw& law, double max_penetration) {
  constexpr int kSamples = 400;
  for (int i = 1; i <= kSamples; ++i) {
    const double x = max_penetration * i / kSamples;
    const double loading = exact_felt_force(law.loading, x);
    if (exact_felt_force(law.unloading, x) > loading + 1e-9 * std::abs(loading)) return x;
  }
  return std::nullopt;
}

FeltLaw read_felt(const PresetReader& r, const json& object, const std::string& path) {
  r.require_source(object, path);
  FeltLaw law;
  law.loading = read_curve(r, r.field(object, path, "loading"), path + ".loading");
  law.unloading = read_curve(r, r.field(object, path, "unloading"), path + ".unloading");
  law.alpha = r.nonnegative(object, path, "alpha_s_per_mm", 0.0) / kMm;
  return law;
}

// A body's parent is listed before it (the tree is built in the list's order): a parent named
// later, or the body itself, is named as such, not as an unknown body.
void check_parent_order(const PresetReader& r, const json& list, std::size_t i,
                        const std::string& path, const std::string& name) {
  const json* parent = r.optional(list[i], "parent");
  if (!parent || !parent->is_string()) return;
  const std::string wanted = parent->get<std::string>();
  if (wanted == name) r.fail(path + ".parent", "a body cannot be its own parent");
  for (std::size_t j = i + 1; j < list.size(); ++j) {
    const json* later = list[j].is_object() ? r.optional(list[j], "name") : nullptr;
    if (later && later->is_string() && later->get<std::string>() == wanted)
      r.fail(path + ".parent", "its parent '" + wanted + "' is listed after it (bodies[" +
                                   std::to_string(j) + "]): list each parent before its children");
  }
}

// Springs and straps are removed by name (--without NAME): each name once among them.
void check_part_name_free(const PresetReader& r, const ActionModel& model, const std::string& path,
                          const std::string& name) {
  for (const JointSpring& spring : model.springs)
    if (spring.name == name)
      r.fail(path + ".name", "duplicate name: a spring is named '" + name + "'");
  for (const Strap& strap : model.straps)
    if (strap.name == name)
      r.fail(path + ".name", "duplicate name: a strap is named '" + name + "'");
}

void read_bodies(const PresetReader& r, const json& root, ActionModel& model) {
  const json& list = r.array(root, "", "bodies");
  if (list.empty()) r.fail("bodies", "an action needs at least one body");
  if (static_cast<int>(list.size()) > kMaxDof)
    r.fail("bodies", "at most " + std::to_string(kMaxDof) + " bodies are supported");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    const std::string path = item_path("bodies", i, item);
    Body body;
    body.name = r.name(item, path);
    if (model.body_index(body.name) >= 0) r.fail(path + ".name", "duplicate body name");
    check_parent_order(r, list, i, path, body.name);
    body.parent = body_reference(r, model, item, path, "parent");
    body.pivot = r.point(item, path, "pivot_mm", kMm);
    // 100 kg and 10^7 g·cm² (100 kg at 10 cm): beyond any part of an action
    body.mass = r.positive_at_most(item, path, "mass_g", 1e5) * 1e-3;
    body.com = r.point(item, path, "com_mm", kMm);
    body.inertia_com = r.positive_at_most(item, path, "inertia_com_g_cm2", 1e7) * 1e-7;  // → kg·m²
    if (const json* f = r.optional(item, "friction")) {
      const std::string fpath = path + ".friction";
      body.friction.a_nm = r.nonnegative(*f, fpath, "a_n_mm", 0.0) * 1e-3;
      body.friction.b1 = r.number_or(*f, fpath, "b1", 0.0);
      body.friction.b2 = r.nonnegative(*f, fpath, "b2", 0.0);
      body.friction.omega_t = r.positive(*f, fpath, "omega_t_rad_per_s");
    }
    const double trace_sign = r.number_or(item, path, "trace_sign", 1.0);
    if (trace_sign != 1.0 && trace_sign != -1.0)
      r.fail(path + ".trace_sign",
             "must be 1 or -1 (got " + PresetReader::format(trace_sign) + ")");
    body.trace_sign = trace_sign;
    body.outline = r.polygon(item, path, "outline_mm");
    r.require_source(item, path);
    model.bodies.push_back(body);
  }
}

void read_contacts(const PresetReader& r, const json& root, ActionModel& model) {
  std::vector<std::pair<std::string, FeltLaw>> laws;
  if (const json* felts = r.optional(root, "felts")) {
    if (!felts->is_object()) r.fail("felts", "expected an object of named felt laws");
    for (auto it = felts->begin(); it != felts->end(); ++it)
      laws.emplace_back(it.key(), read_felt(r, it.value(), "felts." + it.key()));
  }
  const json& list = r.array(root, "", "contacts");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    const std::string path = item_path("contacts", i, item);
    Contact contact;
    contact.name = r.name(item, path);
    if (model.contact_index(contact.name) >= 0) r.fail(path + ".name", "duplicate contact name");
    contact.body_a = body_reference(r, model, item, path, "body_a");
    contact.body_b = body_reference(r, model, item, path, "body_b");
    if (contact.body_a == contact.body_b) r.fail(path, "body_a and body_b must differ");
    contact.center_a = r.point(item, path, "center_a_mm", kMm);
    contact.radius_a = r.nonnegative(item, path, "radius_a_mm", 0.0) * kMm;
    const std::string shape = r.text(item, path, "shape");
    if (shape == "circle_circle") {
      contact.shape = ContactShape::CircleCircle;
      contact.center_b = r.point(item, path, "center_b_mm", kMm);
      contact.radius_b = r.nonnegative(item, path, "radius_b_mm", 0.0) * kMm;
    } else if (shape == "circle_segment" || shape == "hybrid") {
      contact.shape = ContactShape::CircleSegment;
      const json& seg = r.array(item, path, "segment_mm");
      if (seg.size() != 2) r.fail(path + ".segment_mm", "expected two end points");
      contact.segment_start = r.point(seg[0], path + ".segment_mm[0]", kMm);
      contact.segment_end = r.point(seg[1], path + ".segment_mm[1]", kMm);
      if ((contact.segment_end - contact.segment_start).norm() < 1e-6)
        r.fail(path + ".segment_mm", "the segment has no length");
      contact.segment_normal = r.unit(item, path, "normal");
      // the face's normal must stand square to it: the distance's switch between the face and
      // its end corners is continuous only then, and the cull of apart contacts relies on that
      // (contact_geometry.h, contact_cull.h). Rounded input within 0.1° is taken as given: it
      // leaves a step of at most r·sin(0.1°) at the span's ends (under 10 µm for a 5 mm felt).
      {
        const Vec2 along = (contact.segment_end - contact.segment_start).normalized();
        const double off = std::asin(std::min(1.0, std::abs(along.dot(contact.segment_normal))));
        if (off > 0.1 * kPi / 180.0)
          r.fail(path + ".normal", "not perpendicular to segment_mm (off by " +
                                       format_number(off * 180.0 / kPi) +
                                       "°; the normal must stand square to the face)");
      }
      contact.radius_b = r.nonnegative(item, path, "corner_radius_mm", 0.0) * kMm;
      if (r.optional(item, "closed_end")) {
        const std::string closed = r.text(item, path, "closed_end");
        if (closed != "start" && closed != "end" && closed != "both")
          r.fail(path + ".closed_end",
                 "unknown end '" + closed + "' (expected start, end or both: segment_mm[0], [1])");
        if (contact.radius_b > 0.0)
          r.fail(path + ".closed_end", "a hybrid contact's corners are rounded, none is closed");
        contact.closed_start = closed != "end";
        contact.closed_end = closed != "start";
      }
    } else {
      r.fail(path + ".shape",
             "unknown shape '" + shape + "' (expected circle_circle, circle_segment or hybrid)");
    }
    const json& felt = r.field(item, path, "felt");
    if (felt.is_string()) {
      bool found = false;
      for (const auto& [name, law] : laws)
        if (name == felt.get<std::string>()) contact.law = law, found = true;
      if (!found) r.fail(path + ".felt", "unknown felt law '" + felt.get<std::string>() + "'");
    } else {
      contact.law = read_felt(r, felt, path + ".felt");
    }
    if (const json* f = r.optional(item, "friction")) {
      contact.friction.mu = r.nonnegative(*f, path + ".friction", "mu", 0.0);
      contact.friction.slip_velocity =
          r.positive(*f, path + ".friction", "slip_velocity_mm_per_s") * kMm;
    }
    // the deepest a felt is pressed before the run stops as unphysical: 25 mm is thicker than
    // any felt of an action (the presets' deepest is 6 mm, the hammer's)
    contact.max_penetration = r.positive_at_most(item, path, "max_penetration_mm", 25.0) * kMm;
    if (const auto x = unloading_above_loading(contact.law, contact.max_penetration)) {
      auto force = [&](const FeltCurve& k) {
        return format_fixed(exact_felt_force(k, *x), 2) + " N";
      };
      r.fail(path + ".felt",
             (felt.is_string() ? "felt law '" + felt.get<std::string>() + "': its" : "its") +
                 std::string(" unloading curve pushes harder than its loading curve at ") +
                 format_fixed(*x / kMm, 2) + " mm (" + force(contact.law.unloading) + " against " +
                 force(contact.law.loading) + "), within this contact's " +
                 format_fixed(contact.max_penetration / kMm, 2) +
                 " mm max_penetration_mm: the felt would give back more energy than it takes "
                 "(unloading must stay at or below loading)");
    }
    r.require_source(item, path);
    model.contacts.push_back(contact);
  }
}

void read_springs_and_straps(const PresetReader& r, const json& root, ActionModel& model) {
  const json& springs = r.array(root, "", "springs");
  for (std::size_t i = 0; i < springs.size(); ++i) {
    const json& item = springs[i];
    const std::string path = item_path("springs", i, item);
    JointSpring spring;
    spring.name = r.name(item, path);
    check_part_name_free(r, model, path, spring.name);
    spring.body = body_reference(r, model, item, path, "body");
    if (spring.body < 0) r.fail(path + ".body", "a joint spring acts on a body's joint");
    // an action's springs: 10-30 N·mm/rad and preloads of a few tens of N·mm (presets); 1e4
    // of either (10 N·m, 100 N at 10 cm) is beyond any of them
    constexpr double kStrongestSpring = 1e4;
    spring.stiffness = r.at_most(r.nonnegative(item, path, "stiffness_n_mm_per_rad", 0.0), path,
                                 "stiffness_n_mm_per_rad", kStrongestSpring) *
                       1e-3;
    spring.preload =
        r.at_most(r.number(item, path, "preload_n_mm"), path, "preload_n_mm", kStrongestSpring) *
        1e-3;
    r.require_source(item, path);
    model.springs.push_back(spring);
  }
  if (const json* straps = r.optional(root, "straps")) {
    for (std::size_t i = 0; i < straps->size(); ++i) {
      const json& item = (*straps)[i];
      const std::string path = item_path("straps", i, item);
      Strap strap;
      strap.name = r.name(item, path);
      check_part_name_free(r, model, path, strap.name);
      strap.body_a = body_reference(r, model, item, path, "body_a");
      strap.point_a = r.point(item, path, "point_a_mm", kMm);
      strap.body_b = body_reference(r, model, item, path, "body_b");
      strap.point_b = r.point(item, path, "point_b_mm", kMm);
      // a strap's slack within the action's reach (±1 m), its stiffness within 500 times the
      // bridle's 20 N/mm (upright preset)
      strap.slack = r.at_most(r.number(item, path, "slack_mm"), path, "slack_mm", 1000.0) * kMm;
      strap.stiffness = r.positive_at_most(item, path, "stiffness_n_per_mm", 1e4) / kMm;
      strap.damping = r.nonnegative(item, path, "damping_n_s_per_mm", 0.0) / kMm;
      r.require_source(item, path);
      model.straps.push_back(strap);
    }
  }
}

void read_adjusters(const PresetReader& r, const json& root, ActionModel& model) {
  const json& list = r.array(root, "", "adjusters");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    const std::string path = item_path("adjusters", i, item);
    Adjuster adjuster;
    adjuster.name = r.name(item, path);
    for (const Adjuster& before : model.adjusters)
      if (before.name == adjuster.name) r.fail(path + ".name", "duplicate adjuster name");
    adjuster.description = r.text(item, path, "description");
    const Vec2 range = r.point(item, path, "range_mm", kMm);
    adjuster.min = range.x();
    adjuster.max = range.y();
    if (adjuster.min >= adjuster.max)
      r.fail(path + ".range_mm", "expected [min, max] with min < max");
    const json& moves = r.array(item, path, "moves");
    for (std::size_t m = 0; m < moves.size(); ++m) {
      const json& move = moves[m];
      const std::string mpath = path + ".moves[" + std::to_string(m) + "]";
      AdjusterEffect effect;
      if (r.optional(move, "contact")) {
        const std::string name = r.text(move, mpath, "contact");
        effect.index = model.contact_index(name);
        if (effect.index < 0) r.fail(mpath + ".contact", "unknown contact '" + name + "'");
        const std::string side = r.text(move, mpath, "side");
        if (side != "a" && side != "b") r.fail(mpath + ".side", "expected \"a\" or \"b\"");
        effect.target =
            side == "a" ? AdjusterEffect::Target::ContactA : AdjusterEffect::Target::ContactB;
        effect.direction = r.unit(move, mpath, "direction");
      } else if (r.optional(move, "strap")) {
        const std::string name = r.text(move, mpath, "strap");
        effect.index = model.strap_index(name);
        if (effect.index < 0) r.fail(mpath + ".strap", "unknown strap '" + name + "'");
        const std::string what = r.text(move, mpath, "field");
        if (what == "slack") {
          effect.target = AdjusterEffect::Target::StrapSlack;
        } else if (what == "point_a" || what == "point_b") {
          effect.target = what == "point_a" ? AdjusterEffect::Target::StrapPointA
                                            : AdjusterEffect::Target::StrapPointB;
          effect.direction = r.unit(move, mpath, "direction");
        } else {
          r.fail(mpath + ".field", "expected slack, point_a or point_b");
        }
      } else {
        r.fail(mpath, "a move names a contact or a strap");
      }
      adjuster.effects.push_back(effect);
    }
    model.adjusters.push_back(adjuster);
  }
}

/// Offsets found by a regulation (`regulated_offset_mm`, written by write_preset) are baked
/// into the geometry (fixtures included): that position becomes the regulated one (0), and the
/// physical range stays relative to it.
void apply_regulated_offsets(const PresetReader& r, const json& root, ActionModel& model) {
  const json& list = r.array(root, "", "adjusters");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = item_path("adjusters", i, list[i]);
    const double offset = r.number_or(list[i], path, "regulated_offset_mm", 0.0) * kMm;
    const Adjuster original = model.adjusters[i];
    // regulations move the adjuster within its physical range, which stays relative to the
    // regulated position: a preset regulated again can carry an offset beyond the range, but not
    // beyond the adjuster's whole travel (max − min), which no turn of a real screw exceeds
    const double travel = original.max - original.min;
    if (std::abs(offset) > travel)
      r.fail(path + ".regulated_offset_mm",
             "must be within ±" + PresetReader::format(travel / kMm) +
                 " mm, the whole travel of the adjuster's range_mm [" +
                 PresetReader::format(original.min / kMm) + ", " +
                 PresetReader::format(original.max / kMm) + "] (got " +
                 PresetReader::format(offset / kMm) + ")");
    if (offset == 0.0) continue;
    model.adjusters[i].min = model.adjusters[i].max = offset;
    model = with_adjuster(model, original.name, offset);
    model.adjusters[i].min = original.min;
    model.adjusters[i].max = original.max;
    model.adjusters[i].value = 0.0;
  }
}

void read_regulation(const PresetReader& r, const json& root, ActionModel& model) {
  const json& list = r.array(root, "", "regulation");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    const std::string path = item_path("regulation", i, item);
    RegulationSetting setting;
    setting.name = r.text(item, path, "name");
    if (model.adjuster_index(setting.name) < 0)
      r.fail(path + ".name", "no adjuster named '" + setting.name + "'");
    if (model.setting_index(setting.name) >= 0)
      r.fail(path + ".name", "setting '" + setting.name + "' is listed twice");
    setting.measurement = r.text(item, path, "measurement");
    setting.unit = r.text(item, path, "unit");
    if (setting.unit != "mm" && setting.unit != "fraction")
      r.fail(path + ".unit", "expected \"mm\" or \"fraction\", got \"" + setting.unit + "\"");
    setting.target = r.number(item, path, "target");
    setting.tolerance = r.positive(item, path, "tolerance");
    setting.source = r.text(item, path, "source");
    if (r.optional(item, "clear_first")) {
      const json& clear = item.at("clear_first");
      const std::string cpath = path + ".clear_first";
      setting.clear_adjuster = r.text(clear, cpath, "adjuster");
      const int index = model.adjuster_index(setting.clear_adjuster);
      if (index < 0 || setting.clear_adjuster == setting.name)
        r.fail(cpath + ".adjuster",
               "expected another adjuster, got '" + setting.clear_adjuster + "'");
      setting.clear_position = r.number(clear, cpath, "position_mm") * kMm;
      if (index >= 0 && (setting.clear_position < model.adjusters[index].min ||
                         setting.clear_position > model.adjusters[index].max))
        r.fail(cpath + ".position_mm", "outside the adjuster's physical range");
      r.text(clear, cpath, "reason");
    }
    model.regulation.push_back(setting);
  }
}

void read_fixtures(const PresetReader& r, const json& root, ActionModel& model) {
  const json& list = r.array(root, "", "fixtures");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    const std::string path = item_path("fixtures", i, item);
    Fixture fixture;
    fixture.name = r.text(item, path, "name");
    fixture.outline = r.polygon(item, path, "outline_mm");
    if (r.optional(item, "adjuster")) {
      fixture.adjuster = r.text(item, path, "adjuster");
      if (model.adjuster_index(fixture.adjuster) < 0)
        r.fail(path + ".adjuster", "unknown adjuster '" + fixture.adjuster + "'");
      fixture.adjuster_direction = r.unit(item, path, "direction");
    }
    model.fixtures.push_back(fixture);
  }
}

int contact_reference(const PresetReader& r, const ActionModel& model, const json& object,
                      const std::string& path, const char* key) {
  const std::string name = r.text(object, path, key);
  const int index = model.contact_index(name);
  if (index < 0) r.fail(child(path, key), "unknown contact '" + name + "'");
  return index;
}

void read_landmarks(const PresetReader& r, const json& root, ActionModel& model) {
  const json& l = r.field(root, "", "landmarks");
  ActionLandmarks& out = model.landmarks;
  out.key = body_reference(r, model, l, "landmarks", "key");
  out.hammer = body_reference(r, model, l, "landmarks", "hammer");
  if (out.key < 0 || out.hammer < 0) r.fail("landmarks", "key and hammer must name bodies");
  out.key_front = r.point(l, "landmarks", "key_front_mm", kMm);
  out.strike_point = r.point(l, "landmarks", "strike_point_mm", kMm);
  out.string_point = r.point(l, "landmarks", "string_point_mm", kMm);
  out.string_normal = r.unit(l, "landmarks", "string_normal");
  const json& c = r.field(l, "landmarks", "contacts");
  out.string_contact = contact_reference(r, model, c, "landmarks.contacts", "string");
  out.escapement_contact = contact_reference(r, model, c, "landmarks.contacts", "escapement");
  out.letoff_contact = contact_reference(r, model, c, "landmarks.contacts", "let_off");
  out.check_contact = contact_reference(r, model, c, "landmarks.contacts", "check");
  out.key_bottom_contact = contact_reference(r, model, c, "landmarks.contacts", "key_bottom");
  if (r.optional(c, "key_rest"))  // optional: touchweight checks the key starts from it
    out.key_rest_contact = contact_reference(r, model, c, "landmarks.contacts", "key_rest");
}

std::string read_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(located_message(path, "", "is a folder, not a preset file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(located_message(path, "", "cannot open the preset file"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string preset_directory() {
  if (const char* env = std::getenv("PAT_PRESET_DIR")) return env;
  return PAT_PRESET_DIR;
}

std::string json_error_without_id(const std::exception& e) {
  // "[json.exception.out_of_range.406] number overflow parsing '1e999'": the text after the id
  const std::string text = e.what();
  const std::size_t end_of_id = text.rfind("] ", text.find(' '));
  return end_of_id == std::string::npos ? text : text.substr(end_of_id + 2);
}

ActionModel parse_action(const std::string& json_text, const std::string& source_name) {
  json root;
  if (json_text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(located_message(source_name, "", "the preset file is empty"));
  try {
    root = json::parse(json_text);
  } catch (const json::parse_error& e) {
    // turn the byte offset into a line and column
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < json_text.size(); ++i) {
      if (json_text[i] == '\n')
        ++line, column = 1;
      else
        ++column;
    }
    throw InputError(located_message(
        source_name, "line " + std::to_string(line) + ", column " + std::to_string(column),
        "malformed JSON"));
  } catch (const json::out_of_range& e) {
    // a number beyond a double's range ("1e999"): the library says which
    throw InputError(
        located_message(source_name, "", "malformed JSON: " + json_error_without_id(e)));
  }
  const PresetReader r(source_name);
  if (!root.is_object()) r.fail("", "a preset is a JSON object");
  const double schema = r.number(root, "", "schema");
  if (schema != kPresetSchema)
    r.fail("schema", "unsupported schema " + PresetReader::format(schema) +
                         " (this program reads " + std::to_string(kPresetSchema) + ")");
  ActionModel model;
  model.source_file = source_name;
  model.kind = r.text(root, "", "kind");
  if (model.kind != "grand" && model.kind != "upright")
    r.fail("kind", "expected \"grand\" or \"upright\", got \"" + model.kind + "\"");
  model.name = r.text(root, "", "name");
  model.description = r.text(root, "", "description");
  read_bodies(r, root, model);
  read_contacts(r, root, model);
  read_springs_and_straps(r, root, model);
  read_adjusters(r, root, model);
  read_fixtures(r, root, model);
  apply_regulated_offsets(r, root, model);
  read_landmarks(r, root, model);
  read_regulation(r, root, model);
  r.check_unknown_fields(root, "");
  model.preset_json = json_text;
  return model;
}

ActionModel load_action(const std::string& name_or_path) {
  std::string path = name_or_path;
  if (name_or_path == "grand" || name_or_path == "upright")
    path = preset_directory() + "/" + name_or_path + ".json";
  else if (!std::filesystem::exists(path))  // a mistyped action name, or a file not there
    throw InputError(located_message(
        path, "", "no such preset file (an action is grand, upright or a preset file's path)"));
  return parse_action(read_file(path), path);
}

}  // namespace pat

#include "regulation/regulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "core/format.h"
#include "model/model_edits.h"
#include "regulation/technician_tests.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

/// An adjuster moved out of the way, and where to (m from its regulated position).
struct ClearMove {
  std::string adjuster;
  double position = 0.0;
};

/// Thrown out of a setting's search when its reading shows that another adjuster must first be
/// moved out of the way: searching on would only meet the same failure at every position.
struct ClearFirst {
  std::string why;
  ClearMove move;
};

/// The adjuster that moves the backcheck (the feature of the check contact) and the end of its
/// range that takes the backcheck away from the hammer; none when no adjuster moves it. With n
/// the contact normal (from B toward A), moving B's feature along d by x changes the gap by
/// −x d·n, moving A's by +x d·n.
std::optional<ClearMove> backcheck_out_of_the_way(const ActionModel& model) {
  const int check = model.landmarks.check_contact;
  if (check < 0) return std::nullopt;
  const Contact& contact = model.contacts[check];
  const Vec2 normal = contact.shape == ContactShape::CircleSegment
                          ? contact.segment_normal
                          : Vec2((contact.center_a - contact.center_b).normalized());
  for (const Adjuster& adjuster : model.adjusters)
    for (const AdjusterEffect& effect : adjuster.effects) {
      const bool on_b = effect.target == AdjusterEffect::Target::ContactB;
      if (effect.index != check || !(on_b || effect.target == AdjusterEffect::Target::ContactA))
        continue;
      const double opening = (on_b ? -1.0 : 1.0) * effect.direction.dot(normal);
      return ClearMove{adjuster.name, opening > 0.0 ? adjuster.max : adjuster.min};
    }
  return std::nullopt;
}

/// One setting's measurement as a function of its adjuster position (m), with the rest state
/// carried from one evaluation to the next (Newton continuation).
class SettingProbe {
 public:
  /// `may_ask_to_clear`: a reading that shows the hammer carried by another part (the setting's
  /// clear_adjuster, e.g. the drop screw) or stopped by the backcheck on its way up throws
  /// ClearFirst with the move that frees it (else the setting is unmeasurable there).
  SettingProbe(const ActionModel& model, const RegulationSetting& setting, RestState& rest,
               bool may_ask_to_clear)
      : model_(model), setting_(setting), rest_(rest) {
    if (!may_ask_to_clear) return;
    if (!setting.clear_adjuster.empty())
      carried_cure_ = ClearMove{setting.clear_adjuster, setting.clear_position};
    backcheck_cure_ = backcheck_out_of_the_way(model);
    if (backcheck_cure_ && backcheck_cure_->adjuster == setting.name) backcheck_cure_.reset();
  }

  /// measured − target (the setting's unit), or nothing when it cannot be measured there.
  std::optional<double> error_at(double adjuster_m, std::string* why = nullptr) {
    ++evaluations_;
    try {
      ActionModel moved = with_adjuster(model_, setting_.name, adjuster_m);
      RestState rest = rest_state_near(moved, rest_);
      const double value = measure_setting(moved, setting_.name, &rest);
      rest_ = rest;
      return value - setting_.target;
    } catch (const HammerCarriedElsewhere& e) {
      // a technician who sees the repetition lever carry the hammer turns the drop screw down
      // at once, rather than trying every position of the let-off button first
      if (carried_cure_) throw ClearFirst{e.what(), *carried_cure_};
      if (why) *why = e.what();
      return std::nullopt;
    } catch (const BackcheckStopsTheRisingHammer& e) {
      // one who sees the backcheck rub the rising hammer bends it back first
      if (backcheck_cure_) throw ClearFirst{e.what(), *backcheck_cure_};
      if (why) *why = e.what();
      return std::nullopt;
    } catch (const std::exception& e) {
      if (why) *why = e.what();
      return std::nullopt;
    }
  }
  int evaluations() const { return evaluations_; }

 private:
  const ActionModel& model_;
  const RegulationSetting& setting_;
  RestState& rest_;
  std::optional<ClearMove> carried_cure_, backcheck_cure_;
  int evaluations_ = 0;
};

/// Distances (mm) from the adjuster's position at which an unmeasurable setting is tried, on
/// either side, nearest first.
constexpr double kMeasurableSearchMm[] = {0.5, 1.0, 2.0, 3.0, 4.0};

/// Distances (mm) from the start at which a stalled bracket search looks for a change of sign:
/// these, then every further millimetre up to the far end of the adjuster's range (a start at
/// one end of a ±4 mm range may have its target near the other).
constexpr double kBracketScanMm[] = {0.5, 1.0, 1.5, 2.0, 3.0};

struct Found {
  bool ok = false;
  double adjuster_m = 0.0;
  double error = 0.0;
  std::string message;
};

/// Finds the adjuster position where the measurement meets its target: a bracket around the
/// target found by secant steps from the current position, then false position with the
/// Illinois modification (a bracketing method like bisection, converging superlinearly).
Found find_adjuster(SettingProbe& probe, const Adjuster& adjuster, const RegulationSetting& setting,
                    double x0, double e0, double aim) {
  Found found;
  // Bracket the target: a small probe step gives the slope, then secant steps (at most four
  // times the previous step, clamped to the physical range) until the error changes sign.
  const double step0 = 0.2e-3;
  double xa = x0, ea = e0;
  double xb = x0 + step0 <= adjuster.max ? x0 + step0 : x0 - step0;
  std::string why;
  std::vector<std::string> tried;  // for the message when the target is out of reach
  auto probe_at = [&](double x) -> std::optional<double> {
    // a position where the action cannot be measured (e.g. the jack never escapes) is pulled
    // back toward the last measurable one
    for (int tries = 0; tries < 2; ++tries) {
      if (auto e = probe.error_at(x, &why)) {
        tried.push_back(format_number(*e + setting.target) + " " + setting.unit + " at " +
                        format_number(x * 1e3) + " mm");
        return e;
      }
      tried.push_back("unmeasurable at " + format_number(x * 1e3) + " mm (" + why + ")");
      x = 0.5 * (x + xa);
      xb = x;
    }
    return std::nullopt;
  };
  auto eb = probe_at(xb);
  bool bracketed = false;
  for (int expansion = 0; eb && expansion < 8; ++expansion) {
    if (std::abs(*eb) <= aim) {  // the secant landed on the target
      found.ok = true;
      found.adjuster_m = xb;
      found.error = *eb;
      return found;
    }
    if ((*eb > 0.0) != (ea > 0.0)) {
      bracketed = true;
      break;
    }
    const double slope = (*eb - ea) / (xb - xa);
    const double limit = 4.0 * std::abs(xb - xa);
    double xn = std::isfinite(slope) && slope != 0.0 ? xb - *eb / slope : xb + (xb - xa);
    // a secant pointing away from the target (non-monotone region) still moves on outward
    if ((xn - xb) * (xb - xa) < 0.0 && std::abs(*eb) > std::abs(ea)) xn = xb - (xb - xa);
    xn = std::clamp(xn, xb - limit, xb + limit);
    xn = std::clamp(xn, adjuster.min, adjuster.max);
    if (std::abs(xn - xb) < 1e-9) break;  // at the end of the range, still short of the target
    xa = xb;
    ea = *eb;
    xb = xn;
    eb = probe_at(xb);
  }
  if (!bracketed) {
    // The secant stalled: a flat stretch (another part takes over, e.g. the repetition lever
    // carries the hammer into the string whatever the drop screw until the screw meets it) or
    // the edge of the measurable region. Scan outward on both sides of the start for a change
    // of sign, nearest first, and bracket it with the last point of the start's sign.
    double same_x[2] = {x0, x0}, same_e[2] = {e0, e0};
    double probed_x[2] = {x0, x0};  // the last position probed on each side
    std::vector<double> distances(std::begin(kBracketScanMm), std::end(kBracketScanMm));
    const double span_mm = (adjuster.max - adjuster.min) * 1e3;
    for (double d = distances.back() + 1.0; d < span_mm + 1.0; d += 1.0) distances.push_back(d);
    for (double distance : distances) {
      for (int side = 0; side < 2 && !bracketed; ++side) {
        const double x =
            std::clamp(x0 + (side == 0 ? 1.0 : -1.0) * distance * 1e-3, adjuster.min, adjuster.max);
        if (x == same_x[side] || x == probed_x[side]) continue;  // at the end of the range
        probed_x[side] = x;
        const auto e = probe.error_at(x, &why);
        if (!e) {
          tried.push_back("unmeasurable at " + format_number(x * 1e3) + " mm (" + why + ")");
          continue;
        }
        tried.push_back(format_number(*e + setting.target) + " " + setting.unit + " at " +
                        format_number(x * 1e3) + " mm");
        if (std::abs(*e) <= aim) {
          found.ok = true;
          found.adjuster_m = x;
          found.error = *e;
          return found;
        }
        if ((*e > 0.0) != (e0 > 0.0)) {
          xa = same_x[side];
          ea = same_e[side];
          xb = x;
          eb = e;
          bracketed = true;
        } else {
          same_x[side] = x;
          same_e[side] = *e;
        }
      }
      if (bracketed) break;
    }
  }
  if (!bracketed) {
    found.message = "setting '" + setting.name + "': the target " + format_number(setting.target) +
                    " " + setting.unit + " is out of reach within the adjuster's range [" +
                    format_number(adjuster.min * 1e3) + ", " + format_number(adjuster.max * 1e3) +
                    "] mm (measured ";
    for (std::size_t i = 0; i < tried.size(); ++i) found.message += (i ? "; " : "") + tried[i];
    found.message += ")";
    return found;
  }
  double lo = xa, e_lo = ea, hi = xb, e_hi = *eb;
  if (hi < lo) {
    std::swap(lo, hi);
    std::swap(e_lo, e_hi);
  }
  int retained = 0;  // Illinois: which end was kept twice in a row (-1 lo, +1 hi)
  for (int iteration = 0; iteration < 40; ++iteration) {
    double x = (lo * e_hi - hi * e_lo) / (e_hi - e_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    std::string why;
    const auto e = probe.error_at(x, &why);
    if (!e) {  // unmeasurable inside a bracket measured at both ends: give up for this pass
      found.message = "setting '" + setting.name + "' cannot be measured at " +
                      format_number(x * 1e3) + " mm: " + why;
      return found;
    }
    if (std::abs(*e) <= aim || hi - lo < 1e-7) {
      found.ok = std::abs(*e) <= setting.tolerance;
      found.adjuster_m = x;
      found.error = *e;
      if (!found.ok)
        found.message = "setting '" + setting.name + "' jumps across its target near " +
                        format_number(x * 1e3) + " mm (measured " +
                        format_number(*e + setting.target) + " " + setting.unit + ")";
      return found;
    }
    if ((*e > 0.0) == (e_lo > 0.0)) {
      lo = x;
      e_lo = *e;
      if (retained == 1) e_hi *= 0.5;
      retained = 1;
    } else {
      hi = x;
      e_hi = *e;
      if (retained == -1) e_lo *= 0.5;
      retained = -1;
    }
  }
  found.message = "setting '" + setting.name + "' did not converge in 40 iterations";
  return found;
}

/// One setting's turn in a pass: measured where its adjuster is (or, when it cannot be measured
/// there, at the nearest position where it can), and searched for when out of tolerance.
/// `model` and `rest` follow the adjuster.
struct SettingOutcome {
  RegulationStep step;
  bool within = true;   ///< it was within tolerance as found
  std::string failure;  ///< why it could not be regulated in this pass
};

SettingOutcome regulate_setting(ActionModel& model, const RegulationSetting& setting,
                                RestState& rest, int pass, bool may_ask_to_clear) {
  SettingOutcome outcome;
  const Adjuster adjuster = model.adjusters[model.adjuster_index(setting.name)];
  SettingProbe probe(model, setting, rest, may_ask_to_clear);
  std::string why;
  double x0 = adjuster.value;
  auto e0 = probe.error_at(x0, &why);
  // Where the setting cannot be measured (a let-off button so high that the jack never
  // trips, a drop screw so high that the repetition lever carries the hammer to the string),
  // the technician turns the adjuster until the action shows the setting again: positions
  // ever farther on either side, within the physical range.
  for (double distance : kMeasurableSearchMm) {
    if (e0) break;
    for (double side : {1.0, -1.0}) {
      const double x =
          std::clamp(adjuster.value + side * distance * 1e-3, adjuster.min, adjuster.max);
      if (x == x0) continue;
      std::string ignored;
      if ((e0 = probe.error_at(x, &ignored))) {
        x0 = x;
        break;
      }
    }
  }
  RegulationStep step{
      pass, setting.name, x0 * 1e3, e0 ? *e0 + setting.target : std::nan(""), setting.target, 1,
      {}};
  if (e0 && x0 != adjuster.value) {
    // measurable only away from where it was: move there before searching on
    outcome.within = false;
    model = with_adjuster(model, setting.name, x0);
  }
  if (!e0) {
    // settings interact (e.g. let-off cannot be read while the drop screw lets the
    // repetition lever carry the hammer): go on, and try again in the next pass
    outcome.within = false;
    step.note = "cannot be measured yet: " + why;
    outcome.failure = ("setting '" + setting.name + "' cannot be measured: " + why);
  } else if (std::abs(*e0) > setting.tolerance) {
    outcome.within = false;
    // aim well inside the tolerance: later settings disturb earlier ones slightly
    const Found found = find_adjuster(probe, adjuster, setting, x0, *e0, 0.3 * setting.tolerance);
    if (found.ok) {
      // `rest` already is the rest state there: the probe's last measurement was taken there
      model = with_adjuster(model, setting.name, found.adjuster_m);
      step.adjuster_mm = found.adjuster_m * 1e3;
      step.measured = found.error + setting.target;
    } else {
      step.note = found.message;
      outcome.failure = (found.message);
    }
    step.evaluations = probe.evaluations();
  }
  outcome.step = step;
  return outcome;
}

/// A setting's turn in a pass, the way a technician clears a deadlock between two settings:
/// when its reading shows another part in the way (the repetition lever carrying the hammer
/// because the drop screw is too high, a backcheck that stops the rising hammer), or it fails
/// and the preset names an adjuster to clear first, that adjuster is moved out of the way and
/// the setting is tried again (each adjuster once); the moved one is set later in the pass.
/// `model` and `rest` follow every move.
SettingOutcome regulate_clearing_the_way(ActionModel& model, const RegulationSetting& setting,
                                         RestState& rest, int pass) {
  SettingOutcome outcome;
  std::vector<std::string> cleared;  // adjusters moved out of the way for this setting
  std::string notes;
  bool may_ask_to_clear = true;
  for (;;) {
    std::optional<ClearMove> cure;
    bool asked = false;
    try {
      outcome = regulate_setting(model, setting, rest, pass, may_ask_to_clear);
    } catch (const ClearFirst& clear) {
      outcome = SettingOutcome{};
      outcome.within = false;
      const Adjuster& adjuster = model.adjusters[model.adjuster_index(setting.name)];
      outcome.step = RegulationStep{
          pass, setting.name, adjuster.value * 1e3, std::nan(""), setting.target, 0, {}};
      outcome.failure = "setting '" + setting.name + "' cannot be measured: " + clear.why;
      cure = clear.move;
      asked = true;
    }
    // the preset's clear_first also answers failures that do not say what is in the way
    if (!cure && !outcome.failure.empty() && !setting.clear_adjuster.empty())
      cure = ClearMove{setting.clear_adjuster, setting.clear_position};
    if (!cure) break;
    if (std::find(cleared.begin(), cleared.end(), cure->adjuster) != cleared.end()) {
      if (!asked || !may_ask_to_clear) break;
      may_ask_to_clear = false;  // moved already: search as it is
      continue;
    }
    cleared.push_back(cure->adjuster);
    model = with_adjuster(model, cure->adjuster, cure->position);
    rest = rest_state_near(model, rest);
    notes += (notes.empty() ? "first " : "; then ") + outcome.failure + "; then with '" +
             cure->adjuster + "' at " + format_number(cure->position * 1e3) + " mm";
  }
  if (!notes.empty()) {
    outcome.within = false;
    outcome.step.note = notes + (outcome.step.note.empty() ? "" : ": " + outcome.step.note);
  }
  return outcome;
}

}  // namespace

RegulationResult regulate(const ActionModel& model, const RegulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RegulationResult result;
  result.model = model;
  RestState rest = find_rest_state(model);
  std::vector<std::string> failures;
  for (int pass = 1; pass <= options.max_passes && !result.converged; ++pass) {
    result.passes = pass;
    // each pass starts from the rest state found afresh, as the final measurement will: the
    // forte blow (checking) is sensitive enough that a rest state continued through many
    // adjustments reads a few hundredths of a millimetre differently
    if (pass > 1) rest = find_rest_state(result.model);
    failures.clear();
    bool all_within = true;
    for (const RegulationSetting& setting : model.regulation) {
      SettingOutcome outcome = regulate_clearing_the_way(result.model, setting, rest, pass);
      if (!outcome.within) all_within = false;
      if (!outcome.failure.empty()) failures.push_back(outcome.failure);
      const RegulationStep& step = outcome.step;
      result.steps.push_back(step);
      if (options.on_step && !options.on_step(step)) {
        result.message = "cancelled";
        return result;
      }
    }
    result.converged = all_within;
  }
  if (!result.converged) {
    result.message = "not within tolerance after " + std::to_string(result.passes) + " passes";
    for (const std::string& f : failures) result.message += "; " + f;
  }
  try {
    result.settings = measure_settings(result.model);
  } catch (const std::exception& e) {
    result.converged = false;
    result.message += std::string(result.message.empty() ? "" : "; ") + e.what();
  }
  for (const SettingReading& r : result.settings) result.converged &= r.within_tolerance();
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void write_preset(const ActionModel& model, const std::string& path) {
  if (model.preset_json.empty())
    throw InputError(path + ": the model was not read from a preset, nothing to write");
  if (!model.removed_parts.empty())
    throw InputError(path + ": a model with parts removed (--without) is not written as a preset");
  nlohmann::ordered_json root = nlohmann::ordered_json::parse(model.preset_json);
  auto& adjusters = root.at("adjusters");
  for (std::size_t i = 0; i < model.adjusters.size(); ++i) {
    const Adjuster& a = model.adjusters[i];
    auto& item = adjusters.at(i);
    if (item.at("name").get<std::string>() != a.name)
      throw std::logic_error("write_preset: adjuster order differs from the preset text");
    const double previous = item.value("regulated_offset_mm", 0.0);
    // round to 0.1 µm: far below any setting's tolerance, and a readable file
    const double offset = std::round((previous + a.value * 1e3) * 1e4) / 1e4;
    if (offset != 0.0)
      item["regulated_offset_mm"] = offset;
    else
      item.erase("regulated_offset_mm");
  }
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError(path + ": cannot write the preset (cannot create " + temporary + ")");
    out << root.dump(1) << "\n";
    if (!out.flush()) {
      std::remove(temporary.c_str());
      throw InputError(path + ": writing the preset failed");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw InputError(path + ": cannot replace the file with the regulated preset");
  }
}

}  // namespace pat

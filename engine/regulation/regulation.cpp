#include "regulation/regulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "model/model_edits.h"
#include "sim/static_equilibrium.h"

namespace pat {
namespace {

std::string format(double value, int precision = 3) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

/// One setting's measurement as a function of its adjuster position (m), with the rest state
/// carried from one evaluation to the next (Newton continuation).
class SettingProbe {
 public:
  SettingProbe(const ActionModel& model, const RegulationSetting& setting, RestState& rest)
      : model_(model), setting_(setting), rest_(rest) {}

  /// measured − target (the setting's unit), or nothing when it cannot be measured there.
  std::optional<double> error_at(double adjuster_m, std::string* why = nullptr) {
    ++evaluations_;
    try {
      ActionModel moved = with_adjuster(model_, setting_.name, adjuster_m);
      RestState rest = rest_state_near(moved, rest_);
      const double value = measure_setting(moved, setting_.name, &rest);
      rest_ = rest;
      return value - setting_.target;
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
  int evaluations_ = 0;
};

struct Found {
  bool ok = false;
  double adjuster_m = 0.0;
  double error = 0.0;
  std::string message;
};

/// Finds the adjuster position where the measurement meets its target: a bracket around the
/// target found by secant steps from the current position, then false position with the
/// Illinois modification (a bracketing method like bisection, converging superlinearly).
Found find_adjuster(SettingProbe& probe, const Adjuster& adjuster,
                    const RegulationSetting& setting, double x0, double e0, double aim) {
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
        tried.push_back(format(*e + setting.target) + " " + setting.unit + " at " +
                        format(x * 1e3) + " mm");
        return e;
      }
      tried.push_back("unmeasurable at " + format(x * 1e3) + " mm (" + why + ")");
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
    found.message = "setting '" + setting.name + "': the target " + format(setting.target) + " " +
                    setting.unit + " is out of reach within the adjuster's range [" +
                    format(adjuster.min * 1e3) + ", " + format(adjuster.max * 1e3) +
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
    if (!e) {  // unmeasurable inside the bracket: plain bisection of the side kept
      found.message = "setting '" + setting.name + "' cannot be measured at " +
                      format(x * 1e3) + " mm: " + why;
      return found;
    }
    if (std::abs(*e) <= aim || hi - lo < 1e-7) {
      found.ok = std::abs(*e) <= setting.tolerance;
      found.adjuster_m = x;
      found.error = *e;
      if (!found.ok)
        found.message = "setting '" + setting.name + "' jumps across its target near " +
                        format(x * 1e3) + " mm (measured " + format(*e + setting.target) + " " +
                        setting.unit + ")";
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

}  // namespace

RegulationResult regulate(const ActionModel& model, const RegulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RegulationResult result;
  result.model = model;
  RestState rest = find_rest_state(model);
  std::vector<std::string> failures;
  for (int pass = 1; pass <= options.max_passes && !result.converged; ++pass) {
    result.passes = pass;
    failures.clear();
    bool all_within = true;
    for (const RegulationSetting& setting : model.regulation) {
      const Adjuster& adjuster =
          result.model.adjusters[result.model.adjuster_index(setting.name)];
      SettingProbe probe(result.model, setting, rest);
      std::string why;
      const auto e0 = probe.error_at(adjuster.value, &why);
      RegulationStep step{pass, setting.name, adjuster.value * 1e3,
                          e0 ? *e0 + setting.target : std::nan(""), setting.target, 1};
      if (!e0) {
        // settings interact (e.g. let-off cannot be read while the drop screw lets the
        // repetition lever carry the hammer): go on, and try again in the next pass
        all_within = false;
        step.note = "cannot be measured yet: " + why;
        failures.push_back("setting '" + setting.name + "' cannot be measured: " + why);
      } else if (std::abs(*e0) > setting.tolerance) {
        all_within = false;
        // aim well inside the tolerance: later settings disturb earlier ones slightly
        const Found found =
            find_adjuster(probe, adjuster, setting, adjuster.value, *e0, 0.3 * setting.tolerance);
        if (found.ok) {
          result.model = with_adjuster(result.model, setting.name, found.adjuster_m);
          rest = rest_state_near(result.model, rest);
          step.adjuster_mm = found.adjuster_m * 1e3;
          step.measured = found.error + setting.target;
        } else {
          step.note = found.message;
          failures.push_back(found.message);
        }
        step.evaluations = probe.evaluations();
      }
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
  if (!model.removed_parts.empty())
    throw InputError(path + ": a model with parts removed (--without) is not written as a preset");
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path + ": cannot write the preset (cannot create " + temporary + ")");
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

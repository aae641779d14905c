// How far each adjuster drifts in a neglected piano, for the practice exercises (issue 7).
//
// A range is a magnitude in adjuster millimetres (the adjuster's own unit, DESIGN.md section 3):
// the hidden offset is drawn uniformly in [min_mm, max_mm] with a random sign. `sense` is the
// sign of d(measured)/d(adjuster) near the regulated position: +1 when moving the adjuster by
// +1 mm makes the technician's measurement larger. The answer's direction (`more`/`less` of the
// measured value relative to its target) is sense × sign(offset), so checking an answer needs
// no simulation; tests/engine/practice_test.cpp verifies every sense by simulating both signs.
#pragma once

#include <string>
#include <vector>

namespace pat {

struct NeglectRange {
  std::string setting;
  double min_mm = 0.0;  ///< smallest drift, adjuster mm
  double max_mm = 0.0;  ///< largest drift, adjuster mm
  int sense = +1;       ///< sign of d(measured)/d(adjuster)
  std::string source;   ///< where the amount comes from
  /// 0: both signs; +1 / −1: only that adjuster sign, where the model cannot yet show the other
  /// direction (model_limit says why).
  int only_sign = 0;
  std::string model_limit;
};

/// The ranges of an action kind ("grand" or "upright"), one per setting, technician's order.
/// Throws InputError for another kind.
const std::vector<NeglectRange>& neglect_ranges(const std::string& kind);

/// The range of one setting; throws InputError naming the setting and the kind.
const NeglectRange& neglect_range(const std::string& kind, const std::string& setting);

}  // namespace pat

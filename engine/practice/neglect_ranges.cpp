#include "practice/neglect_ranges.h"

#include "core/error.h"

namespace pat {
namespace {

// Sources are the domain notes (shared/reference/domain.md, sections 1–3) and their references;
// they give the drift as a change of the measured value. The adjuster ranges are those that give
// that change on the shipped presets, whose sensitivities (measured / adjuster, from
// measure_setting at ±0.1, ±0.3, ±1 mm) are quoted; PracticeSymptoms checks every sense by
// simulation. Where the present model cannot show one direction, the range is one-sided and
// model_limit says why.

const std::vector<NeglectRange> kGrand = {
    {"key_dip", 0.5, 1.5, -1,
     "front-rail punchings compress and keys bed in: the spec band is .390–.420 in (0.76 mm, "
     "[SK]); a neglected keyboard reads 1 mm or more off it [AZ][GW]. Model: 1.0 mm/mm"},
    {"jack_position", 0.1, 0.2, +1,
     "the jack regulating button felt packs and the screw turns with use; the target is an "
     "alignment [SW], a neglected action is visibly off by 0.5–1 mm. Model: ≈5 mm/mm"},
    {"lever_height", 0.1, 0.25, +1,
     "target a paper's thickness (≈0.2 mm) [LPT]; the lever felt and spring settle by a few "
     "tenths of a millimetre. Model: ≈3 mm/mm upward; downward the gap closes at −0.07 mm"},
    {"hammer_blow", 0.1, 0.3, -1,
     "hammer felt wear and capstan felt compression: specs differ by 3 mm (44.5 vs 47.6 mm "
     "[SW]), an uneven hammer line by a few mm, never >5/16 in above the rail [EF10]. Model: "
     "≈12 mm of blow per mm of capstan"},
    {"let_off", 0.1, 0.2, +1,
     "let-off drifts by about 1 mm (1/16–1/8 in band [QRS], 1.5–2.5 mm [PTG-L]) as the button "
     "felt compresses or the screw turns. Model: ≈6 mm/mm (0.56 mm at −0.2 mm, 2.77 mm at "
     "+0.2 mm; from +0.25 mm the jack no longer escapes before the key bottoms)"},
    {"drop", 0.1, 0.2, +1,
     "drop ≤1/16 in (1.6 mm) below let-off [SW][QRS]: a drift of 0.5–1.5 mm. Model: ≈5 mm/mm "
     "(2.06 mm at −0.2 mm, 3.93 mm at +0.2 mm; from −0.3 mm the jack no longer escapes)"},
    {"checking", 0.5, 1.0, -1,
     "checking 14–16 mm [ANT], ≈5/8 in [PP]: backcheck wires bend with use by a few mm. Model: "
     "≈−2 mm/mm (the preset's + bends toward the hammer, so the catch comes nearer the "
     "string); from −1.75 mm the tail passes below the backcheck's face, from +1.75 mm the face "
     "stops the rising hammer"},
};

const std::vector<NeglectRange> kUpright = {
    {"hammer_blow", 1.0, 2.0, -1,
     "46 mm [LEE] vs 1 3/4 in [JPU] vs ≈47 mm old uprights [RW]: hammer rail felt compresses by "
     "a few mm [PTG-B]. Model: ≈2 mm/mm"},
    {"key_dip", 0.5, 1.5, -1,
     "front-rail punchings compress (spinets just under 3/8 in [AZ]; 1 mm is a neglected key). "
     "Model: 1.0 mm/mm"},
    {"lost_motion", 0.1, 0.3, -1,
     "key and capstan felts compress: lost motion grows from minimal toward 1/16 in (1.6 mm) and "
     "beyond [JPU][RW]. Model: ≈1.2 mm of gap per mm of capstan (0.89 mm at −0.5 mm); from "
     "about +0.25 mm the jack meets the butt at rest"},
    {"let_off", 0.1, 0.25, +1,
     "let-off 1/8 in [IG], 1–3 mm [BS]: the button drifts by about 1 mm. Model: ≈6 mm/mm "
     "(0.98 mm at −0.25 mm, 6.2 mm at +0.5 mm; from −0.5 mm the jack lifts the hammer into "
     "the string before its toe trips)"},
    {"checking", 0.25, 0.5, -1,
     "backcheck ≈5/8 in from the string [PM]; wires bend a few mm. Model: ≈−6 mm/mm (17.76 mm "
     "at −0.25 mm, 14.79 mm at +0.25 mm; 0.25 mm moves the catch by about 1.5 mm, more than the "
     "1 mm an eye follows on a moving hammer); from about +0.75 mm the backcheck holds the hammer "
     "so near the string that a held forte blow strikes twice"},
    {"bridle", 1.0, 2.5, +1,
     "bridle tapes stretch or are mis-hooked: slack is not specified numerically [JG], a few mm "
     "is visible. Model: 1.0 mm/mm"},
    {"damper_lift", 0.1, 0.25, -1,
     "lift at 1/3–1/2 of the hammer travel [PROPTN][BS]: a spoon drifts by a fraction of that "
     "band. Model: ≈1 travel fraction per mm"},
};

}  // namespace

const std::vector<NeglectRange>& neglect_ranges(const std::string& kind) {
  if (kind == "grand") return kGrand;
  if (kind == "upright") return kUpright;
  throw InputError("no neglect ranges for a '" + kind + "' action (grand or upright)");
}

const NeglectRange& neglect_range(const std::string& kind, const std::string& setting) {
  for (const NeglectRange& r : neglect_ranges(kind))
    if (r.setting == setting) return r;
  throw InputError("no neglect range for setting '" + setting + "' of the " + kind + " action");
}

}  // namespace pat

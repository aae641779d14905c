// Symptoms in the technician's words (domain notes section 3: blocking, double strike, failure
// to repeat, no checking, lost motion, …), derived from the observations of the hidden action
// compared with the same observations of the regulated action. Nothing here knows which setting
// is wrong: each rule reads one observed quantity and says what a technician would call it.
#pragma once

#include <string>
#include <vector>

#include "practice/observations.h"

namespace pat {

struct Symptom {
  std::string id;           ///< stable keyword, e.g. "blocking", "double_strike", "excess_gap"
  std::string text;         ///< one sentence with the numbers
  std::string observation;  ///< the observation it was read from
};

/// The smallest difference a technician notices in an observation (its unit): what counts as
/// "differs measurably". Dip block and feeler gauges read 0.05–0.1 mm, a let-off gauge or ruler
/// about 0.25 mm, the backcheck catch point (a moving hammer) about 1 mm; a strike more or less
/// in three cycles; 5 % of the forte impact speed (a difference in loudness of about 0.4 dB).
double noticeable_difference(const std::string& observation_id);

/// The symptoms of an action from its observations `seen` and the regulated action's
/// `regulated` (same ids; observations missing from `regulated` are skipped). Only differences
/// at least noticeable_difference are reported; empty when the action behaves as regulated.
std::vector<Symptom> describe_symptoms(const std::vector<Observation>& seen,
                                       const std::vector<Observation>& regulated);

/// Whether two observation lists differ measurably in at least one quantity (a number that
/// moved by a noticeable difference, or one that is read in one and missing in the other).
bool differ_measurably(const std::vector<Observation>& a, const std::vector<Observation>& b);

}  // namespace pat

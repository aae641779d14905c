// Names of the regulation settings and their adjusters as a class reads them: "let-off", not
// the preset's identifier "let_off"; the part an adjuster turns ("let-off button"), the head of
// its description before the ':' that says which way is positive.
#pragma once

#include <QString>
#include <string>

#include "model/action_model.h"

namespace pat::ui {

/// "key_dip" → "key dip", "let_off" → "let-off" (the technicians' spelling).
inline QString setting_title(const std::string& name) {
  return QString::fromStdString(setting_words(name));
}

/// The part the adjuster turns, from its description ("let-off button: + screws it down …" →
/// "let-off button"); empty when the description has no such head.
inline QString adjuster_part(const Adjuster& adjuster) {
  const std::size_t colon = adjuster.description.find(':');
  if (colon == std::string::npos) return {};
  return QString::fromStdString(adjuster.description.substr(0, colon));
}

}  // namespace pat::ui

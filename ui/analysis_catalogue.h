// The analyses the window offers (DESIGN.md section 6), each a named task built from the current
// model. The task runs in the AnalysisRunner's worker thread and must only read the model it was
// given (models are immutable and shared).
#pragma once

#include <QString>
#include <functional>
#include <memory>
#include <vector>

#include "analysis_result.h"
#include "model/action_model.h"

namespace pat::ui {

struct AnalysisEntry {
  QString name;         ///< menu and combo text
  QString description;  ///< tooltip: what is run and what it shows
  /// True when the analysis applies to this action (some are upright or grand only).
  std::function<bool(const ActionModel&)> applies = [](const ActionModel&) { return true; };
  std::function<AnalysisTask(std::shared_ptr<const ActionModel>)> make;
};

/// Every analysis, in the order a class meets them.
std::vector<AnalysisEntry> analysis_catalogue();

}  // namespace pat::ui

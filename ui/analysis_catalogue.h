// The analyses the window offers (DESIGN.md section 6), each a named task built from the current
// model and the choices made in the panel's form. The task runs in the AnalysisRunner's worker
// thread and must only read the model it was given (models are immutable and shared).
#pragma once

#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "analysis_result.h"
#include "model/action_model.h"

namespace pat::ui {

/// A choice made before running an analysis, shown as a form row above Run.
struct AnalysisParameter {
  enum class Kind {
    choice,     ///< one word of `choices` (a combo box); the first is the default
    number,     ///< a value in [minimum, maximum] with `unit` (a spin box)
    files,      ///< one or more files chosen with a file dialog, each checked on choosing
    checklist,  ///< a subset of `items(model)` (a list of check boxes), all checked by default
  };
  QString key;    ///< its name in AnalysisSettings
  QString label;  ///< form label
  QString tooltip;
  Kind kind = Kind::choice;
  QStringList choices;
  double minimum = 0.0, maximum = 0.0, value = 0.0, step = 1.0;
  int decimals = 1;
  QString unit;
  std::function<QStringList(const ActionModel&)> items;
  /// files: "file: problem" for each file that cannot be used with this model (empty: all good)
  std::function<QStringList(const QStringList& paths, const ActionModel&)> check_files;
  QString file_filter;  ///< files: the dialog's filter, e.g. "CSV (*.csv)"

  /// A choice among `choices` (the first is the default).
  static AnalysisParameter choice(QString key, QString label, QString tooltip,
                                  QStringList choices) {
    AnalysisParameter p;
    p.key = std::move(key);
    p.label = std::move(label);
    p.tooltip = std::move(tooltip);
    p.choices = std::move(choices);
    return p;
  }
};

/// key → value: QString (choice), double (number), QStringList (files, checklist).
using AnalysisSettings = QVariantMap;

struct AnalysisEntry {
  QString name;         ///< menu and combo text
  QString description;  ///< tooltip: what is run and what it shows
  /// True when the analysis applies to this action (some are upright or grand only).
  std::function<bool(const ActionModel&)> applies = [](const ActionModel&) { return true; };
  std::vector<AnalysisParameter> parameters;
  /// False for an analysis that runs on both actions (its result's summary then names none).
  bool on_the_window_action = true;
  /// False for an analysis no regulation setting changes (the swing test: the hammer alone on
  /// its flange): a setting moved after it ran is then not news under its result.
  bool uses_the_settings = true;
  /// Builds the task; throws InputError when the settings cannot be run (the panel shows it).
  std::function<AnalysisTask(std::shared_ptr<const ActionModel>, const AnalysisSettings&)> make;
};

/// Every analysis, in the order a class meets them.
std::vector<AnalysisEntry> analysis_catalogue();

}  // namespace pat::ui

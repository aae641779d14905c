// The Analyses dock: choose an analysis of the current action, run it in the background with a
// non-modal progress bar and Cancel, read its summary and table, look at its plots (cursors,
// zoom) and export them (PNG, PDF, SVG, CSV) or the table (CSV). The window stays live.
#pragma once

#include <QWidget>
#include <functional>
#include <memory>
#include <vector>

#include "analysis_catalogue.h"
#include "plot_panel.h"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace pat::ui {

class AnalysisRunner;

class AnalysesPanel : public QWidget {
  Q_OBJECT
 public:
  /// `current_model` gives the window's action at the moment Run is pressed.
  AnalysesPanel(std::function<std::shared_ptr<const ActionModel>()> current_model,
                QWidget* parent = nullptr);

  /// Lists the analyses that apply to `model` (called when the action changes).
  void set_model(const ActionModel& model);
  /// Runs the analysis named `name` (as the Run button does); false when unknown or busy.
  bool run(const QString& name);
  void cancel();

  AnalysisRunner* runner() const { return runner_; }
  QStringList analysis_names() const;
  QString summary() const;
  QTableWidget* table() const { return table_; }
  std::vector<PlotPanel*> plots() const { return plots_; }
  /// Shows a result computed elsewhere (the deregulation demo) as if run here.
  void show_result(const QString& title, const AnalysisResult& result);
  /// Writes the result table as CSV (quantity,value,unit). Throws InputError naming the file.
  void write_table_csv(const QString& path) const;

 signals:
  /// The user asked to export these plots (the window owns the file dialog and the size).
  void exportRequested(const std::vector<pat::ui::PlotPanel*>& plots, const QString& what);

 private:
  void set_busy(bool busy);
  void clear_result();

  std::function<std::shared_ptr<const ActionModel>()> current_model_;
  std::vector<AnalysisEntry> catalogue_;
  AnalysisRunner* runner_;
  QComboBox* choice_;
  QLabel* description_;
  QPushButton* run_button_;
  QProgressBar* progress_;
  QLabel* stage_;
  QLabel* summary_;
  QTableWidget* table_;
  QTabWidget* plot_tabs_;
  QPushButton* export_plots_;
  QPushButton* export_table_;
  std::vector<PlotPanel*> plots_;
  QString result_title_;
};

}  // namespace pat::ui

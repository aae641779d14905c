// The Analyses dock: choose an analysis of the current action and its settings (a form under
// the choice: stroke, frequencies, measured files, candidates), run it in the background with a
// non-modal progress bar and Cancel, read its summary and table, look at its plots (cursors,
// zoom) and tables in tabs, and export them (PNG, PDF, SVG, CSV), the table (CSV) or the
// analysis's own report. The window stays live.
#pragma once

#include <QVariantMap>
#include <QWidget>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "analysis_catalogue.h"
#include "plot_panel.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSplitter;
class QTableWidget;
class QTabWidget;
class QScrollArea;
class QResizeEvent;
class QEvent;

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
  /// Chooses the analysis named `name` and shows its settings form; false when unknown or busy.
  bool choose(const QString& name);
  /// Runs the analysis named `name` (as the Run button does) with the settings of its form;
  /// false when unknown, busy, or when the settings cannot run (the summary says why).
  bool run(const QString& name);
  void cancel();

  AnalysisRunner* runner() const { return runner_; }
  QStringList analysis_names() const;
  QString summary() const;
  /// The line under the selector: the chosen analysis's description, or where a shown result
  /// from elsewhere comes from.
  QString description() const;
  QTableWidget* table() const { return table_; }
  std::vector<PlotPanel*> plots() const { return plots_; }
  /// Changes whenever the result shown is cleared or replaced (its plots deleted).
  int result_serial() const { return result_serial_; }
  /// The tables of the result that have their own columns (ranking, cycles), one tab each.
  std::vector<QTableWidget*> grids() const { return grids_; }

  /// The settings of the chosen analysis as its form shows them.
  AnalysisSettings settings() const;
  /// Sets one setting of the chosen analysis as its form row would (a choice's word, a number,
  /// a list of files or ticked candidates). Files are checked at once: bad ones are left out
  /// and named in the form with their problem. False when the analysis has no such setting.
  bool set_parameter(const QString& key, const QVariant& value);
  /// What is wrong with the files last chosen (empty when all could be read).
  QString file_problems() const;
  /// Writes the result's own report into `folder` (when it has one, as the diagnosis does)
  /// with every plot of the result as a PNG. Throws InputError naming what cannot be written.
  void write_report(const QString& folder) const;
  bool has_report() const { return static_cast<bool>(result_.write_report); }
  /// Shows a result computed elsewhere (the deregulation demo) as if run here.
  /// `action` (the kind it ran on, e.g. "grand"), when given, is named in the summary; `model`
  /// is the action it ran on, as result_model() gives it.
  void show_result(const QString& title, const AnalysisResult& result,
                   const QString& action = QString(),
                   std::shared_ptr<const ActionModel> model = nullptr);
  /// Says under the result when the window's action (current_model) is no longer the one the
  /// result ran on: a setting moved since Run, another action or preset. The window calls it
  /// when its action changes; a result shown calls it too.
  void compare_with_window();
  /// That sentence (empty when the result is the window's action as it is).
  QString since_run_note() const;
  /// While a practice exercise hides the window's settings the sentence is not made (it would
  /// name the hidden setting); when they are shown again it is.
  void set_settings_hidden(bool hidden);
  /// The action the shown result ran on, with its settings as they were at Run (they may have
  /// moved since); null when none is shown or the result is not one action's (Upright vs grand).
  std::shared_ptr<const ActionModel> result_model() const { return result_model_; }
  /// Writes the result table as CSV (quantity,value,unit), and each of the result's other
  /// tables (a sweep's cycles, a diagnosis's candidates) beside it as PATH-STEM_TABLE.csv with
  /// its own columns. Returns the files written. Throws InputError naming the file.
  QStringList write_table_csv(const QString& path) const;
  /// The files write_table_csv(path) writes, `path` first.
  QStringList table_csv_paths(const QString& path) const;

 protected:
  /// Refits the summary's height to the new width.
  void resizeEvent(QResizeEvent* event) override;
  /// Refits the summary's height to a new font (View › Larger text).
  void changeEvent(QEvent* event) override;

 signals:
  /// The user asked to export these plots (the window owns the file dialog and the size).
  void exportRequested(const std::vector<pat::ui::PlotPanel*>& plots, const QString& what);

 private:
  void set_busy(bool busy);
  void clear_result();
  const AnalysisEntry* chosen_entry() const;
  /// Rebuilds the settings form for the chosen analysis and the current model.
  void rebuild_form(const ActionModel* model);
  /// The line under the selector for entry `index`: its description, and when the result shown
  /// is another analysis's, that it is.
  void describe_choice(int index);
  void remember(const QString& key, const QVariant& value);
  void choose_files(const QString& key);
  void add_grid(const AnalysisGrid& grid);

  std::function<std::shared_ptr<const ActionModel>()> current_model_;
  std::vector<AnalysisEntry> catalogue_;
  AnalysisRunner* runner_;
  QComboBox* choice_;
  QLabel* description_;
  QPushButton* run_button_;
  QProgressBar* progress_;
  QLabel* stage_;
  QLabel* summary_;
  QScrollArea* summary_scroll_;   ///< holds the summary, at most a few lines high
  QLabel* since_run_;             ///< compare_with_window's sentence, hidden when empty
  bool settings_hidden_ = false;  ///< a practice exercise runs: no sentence
  /// Sets the summary, its scroll area as high as its text up to six lines.
  void set_summary(const QString& text);
  void fit_summary();
  /// The table's name column as wide as its names, up to 55 % of the table.
  void fit_table_columns();
  QTableWidget* table_;
  QTabWidget* plot_tabs_;
  QSplitter* results_;  ///< the table above the plot tabs
  QPushButton* export_plots_;
  QPushButton* export_table_;
  QPushButton* export_report_;
  QWidget* form_host_;
  QFormLayout* form_;
  QLabel* file_problems_;
  std::map<QString, QWidget*> editors_;  ///< the chosen analysis's settings, by key
  /// "analysis/kind/key" → the value last set (per action kind: candidates, files and
  /// frequencies differ between the grand and the upright)
  QVariantMap remembered_;
  QString form_kind_;  ///< the kind of action the form was built for
  std::vector<PlotPanel*> plots_;
  int result_serial_ = 0;
  std::vector<QTableWidget*> grids_;
  AnalysisResult result_;
  QString result_title_;
  QString running_action_;  ///< the kind of action the running analysis runs on
  std::shared_ptr<const ActionModel> running_model_;  ///< the action it runs on (null: both)
  std::shared_ptr<const ActionModel> result_model_;
};

}  // namespace pat::ui

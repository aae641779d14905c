// The regulation panel: one row per setting of the current action (its adjusters, in the
// technician's order), "Reset to regulated", and a log of what the regulation did.
#pragma once

#include <QWidget>
#include <memory>
#include <vector>

#include "model/action_model.h"
#include "regulation_row.h"

class QGridLayout;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QVBoxLayout;

namespace pat::ui {

class RegulationPanel : public QWidget {
  Q_OBJECT
 public:
  explicit RegulationPanel(QWidget* parent = nullptr);

  /// Rebuilds the rows for a model (a new action or preset).
  void set_model(const ActionModel& model);
  /// Moves the rows to a model's adjuster positions (no signals).
  void show_adjusters(const ActionModel& model);
  /// A recorded replay on screen (its frame's model: the rows show its adjusters, cannot be
  /// moved and read "replay"), or nullptr: the live action again (the caller shows its
  /// adjusters).
  void set_replay(const ActionModel* replayed);
  bool replaying() const { return replaying_; }
  const std::vector<std::unique_ptr<RegulationRow>>& rows() const { return rows_; }
  RegulationRow* row(const std::string& name) const;
  /// Adds a line to the log under the rows (regulation steps, messages).
  void log(const QString& line);
  void clear_log();
  /// The log's text, lines in order.
  QString log_text() const;
  /// A button under the rows (the window adds the regulation actions).
  /// Adds a widget (a row of options) below the buttons added so far.
  void add_widget(QWidget* widget);
  QPushButton* add_button(const QString& text, const QString& tip);

 signals:
  /// The user moved adjuster `name` to `mm`.
  void adjusterChanged(const std::string& name, double mm);
  void resetRequested();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  /// The title's font: the panel's, bold and 1 pt larger.
  void fit_title_font();
  QGridLayout* grid_;
  QWidget* grid_host_;
  QVBoxLayout* buttons_;
  QLabel* title_ = nullptr;
  QString title_text_;  // "Regulation — <action>"
  bool replaying_ = false;
  QPlainTextEdit* log_;
  std::vector<std::unique_ptr<RegulationRow>> rows_;
};

}  // namespace pat::ui

#include "analyses_panel.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextStream>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "analysis_plots.h"
#include "analysis_runner.h"
#include "core/error.h"
#include "export_folder.h"
#include "plot_export.h"
#include "plot_panel.h"
#include "result_settings_note.h"
#include "save_paths.h"

namespace pat::ui {
namespace {

QString csv_field(const QString& text) {
  if (!text.contains(',') && !text.contains('"')) return text;
  QString quoted = text;
  quoted.replace('"', "\"\"");
  return '"' + quoted + '"';
}

QStringList checked_items(const QListWidget* list) {
  QStringList names;
  for (int i = 0; i < list->count(); ++i)
    if (list->item(i)->checkState() == Qt::Checked) names << list->item(i)->text();
  return names;
}

// Editors keep their parameter's kind and key in properties (the form is rebuilt per analysis).
const char* kKindProperty = "pat_parameter_kind";
const char* kPathsProperty = "pat_paths";

}  // namespace

AnalysesPanel::AnalysesPanel(std::function<std::shared_ptr<const ActionModel>()> current_model,
                             QWidget* parent)
    : QWidget(parent), current_model_(std::move(current_model)) {
  runner_ = new AnalysisRunner(this);
  auto* layout = new QVBoxLayout(this);
  choice_ = new QComboBox(this);
  description_ = new QLabel(this);
  description_->setObjectName("analysis_description");
  description_->setWordWrap(true);
  // its colour by the palette, not a style sheet: a label with a style sheet keeps the font it
  // was polished with, and stayed small when the class's larger text was chosen
  {
    QPalette grey = description_->palette();
    grey.setColor(QPalette::WindowText, QColor(0x44, 0x44, 0x44));
    description_->setPalette(grey);
  }
  run_button_ = new QPushButton(tr("Run"), this);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setTextVisible(false);
  progress_->hide();
  stage_ = new QLabel(this);
  stage_->hide();
  summary_ = new QLabel(this);
  summary_->setObjectName("analysis_summary");
  summary_->setWordWrap(true);
  {
    QFont bold = summary_->font();  // the weight alone: its size follows the panel's
    bold.setBold(true);
    summary_->setFont(bold);
  }
  summary_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  // a long summary (a sweep's, with the paper's figures) scrolls within a few lines instead of
  // squeezing the plots under it to a strip without its axis titles
  summary_scroll_ = new QScrollArea(this);
  summary_scroll_->setWidget(summary_);
  summary_scroll_->setWidgetResizable(true);
  summary_scroll_->setFrameShape(QFrame::NoFrame);
  summary_scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  since_run_ = new QLabel(this);
  since_run_->setObjectName("analysis_since_run");
  since_run_->setWordWrap(true);
  since_run_->setStyleSheet("color: #8a4b00;");  // dark amber: a caution, not an error
  since_run_->hide();
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("quantity"), tr("value"), tr("unit")});
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setMinimumHeight(70);
  table_->setWordWrap(false);  // a value on one line (a cut one is in full in its tooltip)
  plot_tabs_ = new QTabWidget(this);
  plot_tabs_->setMinimumHeight(200);
  // the table and the plots share the height; the user drags the handle between them
  results_ = new QSplitter(Qt::Vertical, this);
  results_->setChildrenCollapsible(false);
  results_->addWidget(table_);
  results_->addWidget(plot_tabs_);
  results_->setStretchFactor(0, 1);
  results_->setStretchFactor(1, 3);
  results_->hide();  // until there is a result; the summary line says how to get one
  set_summary(
      tr("Choose an analysis and press Run: it runs on the action in the window, "
         "as regulated there."));
  export_plots_ = new QPushButton(tr("Export plots…"), this);
  export_table_ = new QPushButton(tr("Export table (CSV)…"), this);
  export_report_ = new QPushButton(tr("Export report…"), this);
  export_report_->setToolTip(
      tr("The analysis's own report (as on the command line) and every plot as PNG, in a folder"));
  export_plots_->setEnabled(false);
  export_table_->setEnabled(false);
  export_report_->hide();
  form_host_ = new QWidget(this);
  form_ = new QFormLayout(form_host_);
  form_->setContentsMargins(0, 0, 0, 0);
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  file_problems_ = new QLabel(this);
  file_problems_->setWordWrap(true);
  file_problems_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  file_problems_->setStyleSheet("color: #b00000;");
  file_problems_->hide();

  auto* run_row = new QHBoxLayout;
  run_row->addWidget(choice_, 1);
  run_row->addWidget(run_button_);
  auto* export_row = new QHBoxLayout;
  export_row->addWidget(export_plots_);
  export_row->addWidget(export_table_);
  export_row->addWidget(export_report_);
  layout->addLayout(run_row);
  layout->addWidget(description_);
  layout->addWidget(form_host_);
  layout->addWidget(file_problems_);
  layout->addWidget(progress_);
  layout->addWidget(stage_);
  layout->addWidget(summary_scroll_);
  layout->addWidget(since_run_);
  layout->addWidget(results_, 1);
  layout->addStretch(0);
  layout->addLayout(export_row);

  connect(choice_, &QComboBox::currentIndexChanged, this, [this](int index) {
    describe_choice(index);
    rebuild_form(current_model_ ? current_model_().get() : nullptr);
  });
  // picking the shown entry again restores its description (a result from elsewhere replaced it)
  connect(choice_, &QComboBox::activated, this, &AnalysesPanel::describe_choice);
  connect(run_button_, &QPushButton::clicked, this, [this] {
    if (runner_->running())
      cancel();
    else
      run(choice_->currentText());
  });
  connect(runner_, &AnalysisRunner::progress, this, [this](double fraction, const QString& stage) {
    progress_->setValue(static_cast<int>(1000 * fraction));
    stage_->setText(stage);
  });
  connect(runner_, &AnalysisRunner::finished, this,
          [this](const QString& title, const AnalysisResult& result) {
            set_busy(false);
            show_result(title, result, running_action_, running_model_);
          });
  connect(runner_, &AnalysisRunner::cancelled, this, [this](const QString& title) {
    set_busy(false);
    set_summary(tr("%1: cancelled.").arg(title));
  });
  connect(runner_, &AnalysisRunner::failed, this,
          [this](const QString& title, const QString& message) {
            set_busy(false);
            set_summary(tr("%1 failed: %2").arg(title, message));
          });
  connect(export_plots_, &QPushButton::clicked, this,
          [this] { emit exportRequested(plots_, result_title_); });
  connect(export_table_, &QPushButton::clicked, this, [this] {
    const QString path =
        ask_save_path(this, tr("Export the table"), export_folder(), tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    // the further tables go beside it, under names the dialog did not ask about
    if (!confirm_replacing(this, table_csv_paths(path).mid(1))) return;
    try {
      const QStringList written = write_table_csv(path);
      remember_export_folder(path);
      if (written.size() > 1) stage_->setText(tr("Tables written: %1").arg(written.join(", ")));
    } catch (const std::exception& e) {
      QMessageBox::warning(this, tr("Export failed"), QString::fromStdString(e.what()));
    }
  });
  connect(export_report_, &QPushButton::clicked, this, [this] {
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Report folder"), export_folder());
    if (folder.isEmpty() || !confirm_writing_into(this, folder)) return;
    try {
      write_report(folder);
      remember_export_folder(folder);
      set_summary(summary_->text() + "\n" + tr("Report written to %1.").arg(folder));
    } catch (const std::exception& e) {
      QMessageBox::warning(this, tr("Export failed"), QString::fromStdString(e.what()));
    }
  });
  catalogue_ = analysis_catalogue();
}

void AnalysesPanel::set_model(const ActionModel& model) {
  const QString previous = choice_->currentText();
  choice_->clear();
  for (std::size_t i = 0; i < catalogue_.size(); ++i)
    if (catalogue_[i].applies(model)) choice_->addItem(catalogue_[i].name, static_cast<int>(i));
  const int again = choice_->findText(previous);
  if (again >= 0) choice_->setCurrentIndex(again);
  rebuild_form(&model);
  compare_with_window();
}

const AnalysisEntry* AnalysesPanel::chosen_entry() const {
  if (choice_->currentIndex() < 0) return nullptr;
  return &catalogue_[choice_->itemData(choice_->currentIndex()).toInt()];
}

void AnalysesPanel::remember(const QString& key, const QVariant& value) {
  if (const AnalysisEntry* entry = chosen_entry())
    remembered_[entry->name + '/' + form_kind_ + '/' + key] = value;
}

void AnalysesPanel::rebuild_form(const ActionModel* model) {
  while (form_->rowCount() > 0) form_->removeRow(0);
  editors_.clear();
  file_problems_->clear();
  file_problems_->hide();
  const AnalysisEntry* entry = chosen_entry();
  form_kind_ = model ? QString::fromStdString(model->kind) : QString();
  form_host_->setVisible(entry && !entry->parameters.empty());
  if (!entry) return;
  for (const AnalysisParameter& p : entry->parameters) {
    const QVariant kept = remembered_.value(entry->name + '/' + form_kind_ + '/' + p.key);
    QWidget* editor = nullptr;
    switch (p.kind) {
      case AnalysisParameter::Kind::choice: {
        auto* combo = new QComboBox(form_host_);
        combo->addItems(p.choices);
        if (kept.isValid()) combo->setCurrentText(kept.toString());
        connect(combo, &QComboBox::currentTextChanged, this,
                [this, key = p.key](const QString& text) { remember(key, text); });
        editor = combo;
        break;
      }
      case AnalysisParameter::Kind::number: {
        auto* spin = new QDoubleSpinBox(form_host_);
        spin->setRange(p.minimum, p.maximum);
        spin->setDecimals(p.decimals);
        spin->setSingleStep(p.step);
        spin->setSuffix(p.unit.isEmpty() ? QString() : " " + p.unit);
        spin->setValue(kept.isValid() ? kept.toDouble() : p.value);
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, key = p.key](double v) { remember(key, v); });
        editor = spin;
        break;
      }
      case AnalysisParameter::Kind::files: {
        auto* row = new QWidget(form_host_);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        auto* button = new QPushButton(tr("Choose…"), row);
        auto* names = new QLabel(tr("none chosen"), row);
        names->setObjectName("names");
        names->setWordWrap(true);
        h->addWidget(button);
        h->addWidget(names, 1);
        row->setProperty(kPathsProperty, QStringList());
        connect(button, &QPushButton::clicked, this, [this, key = p.key] { choose_files(key); });
        editor = row;
        break;
      }
      case AnalysisParameter::Kind::checklist: {
        auto* list = new QListWidget(form_host_);
        const QStringList items = model && p.items ? p.items(*model) : QStringList();
        const QStringList ticked = kept.isValid() ? kept.toStringList() : items;
        for (const QString& name : items) {
          auto* item = new QListWidgetItem(name, list);
          item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
          item->setCheckState(ticked.contains(name) ? Qt::Checked : Qt::Unchecked);
        }
        list->setMaximumHeight(84);
        connect(list, &QListWidget::itemChanged, this,
                [this, list, key = p.key] { remember(key, checked_items(list)); });
        editor = list;
        break;
      }
    }
    editor->setProperty(kKindProperty, static_cast<int>(p.kind));
    editor->setToolTip(p.tooltip);
    form_->addRow(p.label, editor);
    editors_[p.key] = editor;
    if (p.kind == AnalysisParameter::Kind::files && kept.isValid()) set_parameter(p.key, kept);
  }
}

AnalysisSettings AnalysesPanel::settings() const {
  AnalysisSettings values;
  for (const auto& [key, editor] : editors_) {
    switch (static_cast<AnalysisParameter::Kind>(editor->property(kKindProperty).toInt())) {
      case AnalysisParameter::Kind::choice:
        values[key] = static_cast<QComboBox*>(editor)->currentText();
        break;
      case AnalysisParameter::Kind::number:
        values[key] = static_cast<QDoubleSpinBox*>(editor)->value();
        break;
      case AnalysisParameter::Kind::files:
        values[key] = editor->property(kPathsProperty).toStringList();
        break;
      case AnalysisParameter::Kind::checklist:
        values[key] = checked_items(static_cast<QListWidget*>(editor));
        break;
    }
  }
  return values;
}

bool AnalysesPanel::set_parameter(const QString& key, const QVariant& value) {
  const auto found = editors_.find(key);
  if (found == editors_.end()) return false;
  QWidget* editor = found->second;
  switch (static_cast<AnalysisParameter::Kind>(editor->property(kKindProperty).toInt())) {
    case AnalysisParameter::Kind::choice: {
      auto* combo = static_cast<QComboBox*>(editor);
      const int index = combo->findText(value.toString());
      if (index < 0) return false;
      combo->setCurrentIndex(index);
      return true;
    }
    case AnalysisParameter::Kind::number:
      static_cast<QDoubleSpinBox*>(editor)->setValue(value.toDouble());
      return true;
    case AnalysisParameter::Kind::checklist: {
      auto* list = static_cast<QListWidget*>(editor);
      const QStringList ticked = value.toStringList();
      for (int i = 0; i < list->count(); ++i)
        list->item(i)->setCheckState(ticked.contains(list->item(i)->text()) ? Qt::Checked
                                                                            : Qt::Unchecked);
      return true;
    }
    case AnalysisParameter::Kind::files:
      break;
  }
  // files: each is read now; the bad ones are left out and named with their problem
  const AnalysisParameter* parameter = nullptr;
  for (const AnalysisParameter& p : chosen_entry()->parameters)
    if (p.key == key) parameter = &p;
  const std::shared_ptr<const ActionModel> model = current_model_ ? current_model_() : nullptr;
  QStringList good, names;
  QStringList problems;
  for (const QString& path : value.toStringList()) {
    const QStringList bad =
        parameter->check_files && model ? parameter->check_files({path}, *model) : QStringList();
    if (bad.isEmpty()) {
      good << path;
      names << QFileInfo(path).fileName();
    } else {  // the message names the file; its name is enough in the narrow dock
      for (QString message : bad) problems << message.replace(path, QFileInfo(path).fileName());
    }
  }
  editor->setProperty(kPathsProperty, good);
  editor->findChild<QLabel*>("names")->setText(names.isEmpty() ? tr("none chosen")
                                                               : names.join(", "));
  file_problems_->setText(problems.isEmpty() ? QString()
                                             : tr("Not loaded:\n%1").arg(problems.join('\n')));
  file_problems_->setVisible(!problems.isEmpty());
  remember(key, good);
  return true;
}

QString AnalysesPanel::file_problems() const {
  return file_problems_->text();
}

void AnalysesPanel::choose_files(const QString& key) {
  const AnalysisEntry* entry = chosen_entry();
  QString filter;
  for (const AnalysisParameter& p : entry->parameters)
    if (p.key == key) filter = p.file_filter;
  const QStringList paths =
      QFileDialog::getOpenFileNames(this, tr("Measured files"), QString(), filter);
  if (!paths.isEmpty()) set_parameter(key, paths);
}

QStringList AnalysesPanel::analysis_names() const {
  QStringList names;
  for (int i = 0; i < choice_->count(); ++i) names << choice_->itemText(i);
  return names;
}

bool AnalysesPanel::choose(const QString& name) {
  const int index = choice_->findText(name);
  if (index < 0 || runner_->running()) return false;
  choice_->setCurrentIndex(index);
  return true;
}

bool AnalysesPanel::run(const QString& name) {
  const int index = choice_->findText(name);
  const std::shared_ptr<const ActionModel> model = current_model_ ? current_model_() : nullptr;
  if (index < 0 || !model || runner_->running()) return false;
  choice_->setCurrentIndex(index);
  const AnalysisEntry& entry = catalogue_[choice_->itemData(index).toInt()];
  AnalysisTask task;
  try {
    task = entry.make(model, settings());
  } catch (const std::exception& e) {  // settings that cannot run: said next to the form
    // the result shown stays (an 80 s table, not yet exported, must not go for a typo)
    QString message = tr("%1: %2").arg(entry.name, QString::fromStdString(e.what()));
    if (!result_title_.isEmpty())
      message += "\n" + tr("Nothing was run; shown below: the last %1 result.").arg(result_title_);
    set_summary(message);
    return false;
  }
  clear_result();
  set_summary(tr("%1: running…").arg(entry.name));
  set_busy(true);
  running_action_ = entry.on_the_window_action ? QString::fromStdString(model->kind) : QString();
  running_model_ = entry.on_the_window_action ? model : nullptr;
  runner_->start(entry.name, std::move(task));
  return true;
}

void AnalysesPanel::cancel() {
  runner_->cancel();
  stage_->setText(tr("cancelling…"));
}

QString AnalysesPanel::summary() const {
  return summary_->text();
}

QString AnalysesPanel::description() const {
  return description_->text();
}

void AnalysesPanel::set_busy(bool busy) {
  run_button_->setText(busy ? tr("Cancel") : tr("Run"));
  choice_->setEnabled(!busy);
  form_host_->setEnabled(!busy);
  progress_->setVisible(busy);
  stage_->setVisible(busy);
  progress_->setValue(0);
  stage_->clear();
}

void AnalysesPanel::describe_choice(int index) {
  if (index < 0) {
    description_->clear();
    return;
  }
  QString description = catalogue_[choice_->itemData(index).toInt()].description;
  // the result below is another analysis's until this one runs: said, so that a sensitivity
  // table is not read under the sweep's description
  if (!result_title_.isEmpty() && result_title_ != choice_->itemText(index))
    description +=
        "\n" + tr("Shown below: the last %1 result; press Run for this one.").arg(result_title_);
  description_->setText(description);
}

void AnalysesPanel::clear_result() {
  table_->setRowCount(0);
  while (plot_tabs_->count() > 0) {
    QWidget* page = plot_tabs_->widget(0);
    plot_tabs_->removeTab(0);
    page->deleteLater();
  }
  plots_.clear();
  ++result_serial_;
  grids_.clear();
  result_ = AnalysisResult{};
  result_title_.clear();
  result_model_.reset();
  since_run_->clear();
  since_run_->hide();
  export_plots_->setEnabled(false);
  export_table_->setEnabled(false);
  export_report_->hide();
}

void AnalysesPanel::show_result(const QString& title, const AnalysisResult& result,
                                const QString& action, std::shared_ptr<const ActionModel> model) {
  clear_result();
  result_title_ = title;
  result_model_ = std::move(model);
  // the result names its action: it stays on show when the window changes to the other one
  const QString heading = action.isEmpty() ? title : tr("%1 (%2)").arg(title, action);
  set_summary(result.summary.isEmpty() ? heading : heading + ": " + result.summary);
  table_->setRowCount(static_cast<int>(result.table.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    const AnalysisTableRow& row = result.table[r];
    table_->setItem(r, 0, new QTableWidgetItem(row.quantity));
    table_->setItem(r, 1, new QTableWidgetItem(row.value));
    table_->item(r, 1)->setToolTip(row.value);  // long values (errors in words) in full
    table_->setItem(r, 2, new QTableWidgetItem(row.unit));
  }
  for (int r = 0; r < table_->rowCount(); ++r)
    table_->item(r, 0)->setToolTip(table_->item(r, 0)->text());
  fit_table_columns();
  QTimer::singleShot(0, this, [this] { fit_table_columns(); });  // once laid out
  for (const AnalysisPlot& p : result.plots) {
    PlotPanel* panel = make_analysis_plot_panel(p, plot_tabs_);
    plots_.push_back(panel);
    plot_tabs_->addTab(panel, p.tab.isEmpty() ? p.title : p.tab);
    plot_tabs_->setTabToolTip(plot_tabs_->count() - 1, p.title);
  }
  for (const AnalysisGrid& grid : result.grids) add_grid(grid);
  // a result with a table only gets the whole height; with plots, the table shows up to six
  // rows (the summary line says the headline) and the plots the rest
  results_->show();
  plot_tabs_->setVisible(plot_tabs_->count() > 0);
  if (plot_tabs_->count() > 0) {
    const int rows = std::min(table_->rowCount(), 6);
    const int row_height = table_->verticalHeader()->defaultSectionSize();
    const int table_height =
        table_->horizontalHeader()->height() + rows * row_height + 2 * table_->frameWidth() + 2;
    const int total = std::max(results_->height(), table_height + plot_tabs_->minimumHeight());
    results_->setSizes({table_height, total - table_height});
  }
  // the selector and its description name the analysis shown; a result from elsewhere (the
  // regulation panel's deregulation demo) says so instead
  const int entry = choice_->findText(title);
  if (entry >= 0 && !runner_->running()) {
    choice_->setCurrentIndex(entry);  // its form follows (a changed index rebuilds it)
    description_->setText(catalogue_[choice_->itemData(entry).toInt()].description);
  } else if (entry < 0) {
    description_->setText(tr("Shown: %1 (not one of the analyses above; choose one and press "
                             "Run to replace it).")
                              .arg(title));
  }
  result_ = result;
  export_plots_->setEnabled(!plots_.empty());
  export_table_->setEnabled(table_->rowCount() > 0);
  export_report_->setVisible(static_cast<bool>(result.write_report));
  compare_with_window();  // a setting moved while it ran
}

void AnalysesPanel::compare_with_window() {
  const std::shared_ptr<const ActionModel> window = current_model_ ? current_model_() : nullptr;
  // the catalogue's entry of the result shown (none for one from elsewhere: the demo's)
  const AnalysisEntry* entry = nullptr;
  for (const AnalysisEntry& e : catalogue_)
    if (e.name == result_title_) entry = &e;
  const QString note =
      result_model_ && window && !settings_hidden_
          ? settings_moved_note(*result_model_, *window, !entry || entry->uses_the_settings)
          : QString();
  since_run_->setText(note);
  since_run_->setVisible(!note.isEmpty());
}

void AnalysesPanel::set_settings_hidden(bool hidden) {
  settings_hidden_ = hidden;
  compare_with_window();
}

QString AnalysesPanel::since_run_note() const {
  return since_run_->text();
}

void AnalysesPanel::add_grid(const AnalysisGrid& grid) {
  auto* view =
      new QTableWidget(static_cast<int>(grid.rows.size()), grid.columns.size(), plot_tabs_);
  view->setHorizontalHeaderLabels(grid.columns);
  view->verticalHeader()->hide();
  view->setEditTriggers(QAbstractItemView::NoEditTriggers);
  for (int r = 0; r < view->rowCount(); ++r)
    for (int c = 0; c < view->columnCount() && c < grid.rows[r].size(); ++c)
      view->setItem(r, c, new QTableWidgetItem(grid.rows[r][c]));
  view->resizeColumnsToContents();
  view->horizontalHeader()->setStretchLastSection(true);
  grids_.push_back(view);
  plot_tabs_->addTab(view, grid.title);
}

void AnalysesPanel::write_report(const QString& folder) const {
  if (!QDir().mkpath(folder)) throw InputError(folder.toStdString() + ": cannot create the folder");
  if (result_.write_report) result_.write_report(folder);
  for (std::size_t i = 0; i < plots_.size(); ++i)
    export_plots({plots_[i]},
                 QDir(folder).filePath(
                     QString("plot%1_%2.png").arg(i + 1).arg(file_stem(plots_[i]->title()))),
                 QSize(1200, 700));
}

QStringList AnalysesPanel::write_table_csv(const QString& path) const {
  auto write = [](const QString& file_path, const QStringList& columns,
                  const std::vector<QStringList>& rows) {
    QFile file(file_path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
      throw InputError(file_path.toStdString() +
                       ": cannot write: " + file.errorString().toStdString());
    QTextStream out(&file);
    QStringList fields;
    for (const QString& c : columns) fields << csv_field(c);
    out << fields.join(',') << '\n';
    for (const QStringList& row : rows) {
      fields.clear();
      for (const QString& v : row) fields << csv_field(v);
      out << fields.join(',') << '\n';
    }
  };
  std::vector<QStringList> rows;
  for (int r = 0; r < table_->rowCount(); ++r)
    rows.push_back(
        {table_->item(r, 0)->text(), table_->item(r, 1)->text(), table_->item(r, 2)->text()});
  const QStringList paths = table_csv_paths(path);
  write(paths[0], {"quantity", "value", "unit"}, rows);
  for (std::size_t g = 0; g < result_.grids.size(); ++g)
    write(paths[static_cast<int>(g) + 1], result_.grids[g].columns, result_.grids[g].rows);
  return paths;
}

QStringList AnalysesPanel::table_csv_paths(const QString& path) const {
  QStringList paths{path};
  const QFileInfo info(path);
  for (std::size_t g = 0; g < result_.grids.size(); ++g) {
    const AnalysisGrid& grid = result_.grids[g];
    QString grid_path =
        info.dir().filePath(info.completeBaseName() + "_" + file_stem(grid.title) + ".csv");
    if (paths.contains(grid_path))  // two tables of one title: numbered
      grid_path = info.dir().filePath(
          QString("%1_%2_%3.csv").arg(info.completeBaseName(), file_stem(grid.title)).arg(g + 1));
    paths << grid_path;
  }
  return paths;
}

void AnalysesPanel::set_summary(const QString& text) {
  summary_->setText(text);
  fit_summary();
}

void AnalysesPanel::fit_summary() {
  const int width = summary_scroll_->viewport()->width() > 0 ? summary_scroll_->viewport()->width()
                                                             : summary_scroll_->width();
  const int lines = 6 * summary_->fontMetrics().lineSpacing();
  summary_scroll_->setFixedHeight(std::min(summary_->heightForWidth(std::max(width, 100)), lines));
}

void AnalysesPanel::fit_table_columns() {
  // the quantities' names take at most 55 % of the width, the values and units the rest (a long
  // name cut, in full in its tooltip): sized to their contents, they had pushed the values to "…"
  table_->resizeColumnToContents(2);
  table_->resizeColumnToContents(0);
  const int widest_name = table_->viewport()->width() * 11 / 20;
  if (widest_name > 0 && table_->columnWidth(0) > widest_name)
    table_->setColumnWidth(0, widest_name);
}

void AnalysesPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) fit_summary();  // the class text scale
}

void AnalysesPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  fit_summary();
  fit_table_columns();
}

}  // namespace pat::ui

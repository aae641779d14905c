#include "analyses_panel.h"

#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextStream>
#include <QVBoxLayout>

#include "analysis_runner.h"
#include "core/error.h"
#include "plot_panel.h"

namespace pat::ui {
namespace {

const QColor kSeriesColours[] = {QColor(31, 119, 180),  QColor(214, 39, 40),  QColor(44, 160, 44),
                                 QColor(148, 103, 189), QColor(255, 127, 14), QColor(23, 190, 207)};

QString csv_field(const QString& text) {
  if (!text.contains(',') && !text.contains('"')) return text;
  QString quoted = text;
  quoted.replace('"', "\"\"");
  return '"' + quoted + '"';
}

}  // namespace

AnalysesPanel::AnalysesPanel(std::function<std::shared_ptr<const ActionModel>()> current_model,
                             QWidget* parent)
    : QWidget(parent), current_model_(std::move(current_model)) {
  runner_ = new AnalysisRunner(this);
  auto* layout = new QVBoxLayout(this);
  choice_ = new QComboBox(this);
  description_ = new QLabel(this);
  description_->setWordWrap(true);
  description_->setStyleSheet("color: #444;");
  run_button_ = new QPushButton(tr("Run"), this);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setTextVisible(false);
  progress_->hide();
  stage_ = new QLabel(this);
  stage_->hide();
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  summary_->setStyleSheet("font-weight: bold;");
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("quantity"), tr("value"), tr("unit")});
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  plot_tabs_ = new QTabWidget(this);
  plot_tabs_->setMinimumHeight(220);
  export_plots_ = new QPushButton(tr("Export plots…"), this);
  export_table_ = new QPushButton(tr("Export table (CSV)…"), this);
  export_plots_->setEnabled(false);
  export_table_->setEnabled(false);

  auto* run_row = new QHBoxLayout;
  run_row->addWidget(choice_, 1);
  run_row->addWidget(run_button_);
  auto* export_row = new QHBoxLayout;
  export_row->addWidget(export_plots_);
  export_row->addWidget(export_table_);
  layout->addLayout(run_row);
  layout->addWidget(description_);
  layout->addWidget(progress_);
  layout->addWidget(stage_);
  layout->addWidget(summary_);
  layout->addWidget(table_, 1);
  layout->addWidget(plot_tabs_, 2);
  layout->addLayout(export_row);

  connect(choice_, &QComboBox::currentIndexChanged, this, [this](int index) {
    const int entry = choice_->itemData(index).toInt();
    description_->setText(index >= 0 ? catalogue_[entry].description : QString());
  });
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
            show_result(title, result);
          });
  connect(runner_, &AnalysisRunner::cancelled, this, [this](const QString& title) {
    set_busy(false);
    summary_->setText(tr("%1: cancelled.").arg(title));
  });
  connect(runner_, &AnalysisRunner::failed, this,
          [this](const QString& title, const QString& message) {
            set_busy(false);
            summary_->setText(tr("%1 failed: %2").arg(title, message));
          });
  connect(export_plots_, &QPushButton::clicked, this,
          [this] { emit exportRequested(plots_, result_title_); });
  connect(export_table_, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export the table"), {}, tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    try {
      write_table_csv(path);
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
}

QStringList AnalysesPanel::analysis_names() const {
  QStringList names;
  for (int i = 0; i < choice_->count(); ++i) names << choice_->itemText(i);
  return names;
}

bool AnalysesPanel::run(const QString& name) {
  const int index = choice_->findText(name);
  const std::shared_ptr<const ActionModel> model = current_model_ ? current_model_() : nullptr;
  if (index < 0 || !model || runner_->running()) return false;
  choice_->setCurrentIndex(index);
  const AnalysisEntry& entry = catalogue_[choice_->itemData(index).toInt()];
  clear_result();
  summary_->setText(tr("%1: running…").arg(entry.name));
  set_busy(true);
  runner_->start(entry.name, entry.make(model));
  return true;
}

void AnalysesPanel::cancel() {
  runner_->cancel();
  stage_->setText(tr("cancelling…"));
}

QString AnalysesPanel::summary() const {
  return summary_->text();
}

void AnalysesPanel::set_busy(bool busy) {
  run_button_->setText(busy ? tr("Cancel") : tr("Run"));
  choice_->setEnabled(!busy);
  progress_->setVisible(busy);
  stage_->setVisible(busy);
  progress_->setValue(0);
  stage_->clear();
}

void AnalysesPanel::clear_result() {
  table_->setRowCount(0);
  while (plot_tabs_->count() > 0) {
    QWidget* page = plot_tabs_->widget(0);
    plot_tabs_->removeTab(0);
    page->deleteLater();
  }
  plots_.clear();
  export_plots_->setEnabled(false);
  export_table_->setEnabled(false);
}

void AnalysesPanel::show_result(const QString& title, const AnalysisResult& result) {
  clear_result();
  result_title_ = title;
  summary_->setText(result.summary.isEmpty() ? title : title + ": " + result.summary);
  table_->setRowCount(static_cast<int>(result.table.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    const AnalysisTableRow& row = result.table[r];
    table_->setItem(r, 0, new QTableWidgetItem(row.quantity));
    table_->setItem(r, 1, new QTableWidgetItem(row.value));
    table_->setItem(r, 2, new QTableWidgetItem(row.unit));
  }
  table_->resizeColumnToContents(0);
  for (const AnalysisPlot& p : result.plots) {
    auto* panel = new PlotPanel(p.title, p.y_title, plot_tabs_);
    panel->set_x_axis(p.x_title, p.x_column, "x", p.x_unit, 1.0);
    for (std::size_t s = 0; s < p.series.size(); ++s) {
      const AnalysisSeries& series = p.series[s];
      const int id = panel->add_series(series.label, series.column,
                                       kSeriesColours[s % std::size(kSeriesColours)]);
      panel->set_data(id, series.x, series.y);
      if (series.points) panel->set_points_only(id);
    }
    if (!p.x_categories.empty()) panel->set_x_categories(p.x_categories);
    panel->fit_all();
    plots_.push_back(panel);
    plot_tabs_->addTab(panel, p.title);
  }
  export_plots_->setEnabled(!plots_.empty());
  export_table_->setEnabled(table_->rowCount() > 0);
}

void AnalysesPanel::write_table_csv(const QString& path) const {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
    throw InputError(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
  QTextStream out(&file);
  out << "quantity,value,unit\n";
  for (int r = 0; r < table_->rowCount(); ++r)
    out << csv_field(table_->item(r, 0)->text()) << ',' << csv_field(table_->item(r, 1)->text())
        << ',' << csv_field(table_->item(r, 2)->text()) << '\n';
}

}  // namespace pat::ui

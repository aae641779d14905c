#include "plot_export.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "io/csv.h"
#include "plot_panel.h"
#include "save_paths.h"

namespace pat::ui {
namespace {

// the least height (layout units) a stacked plot is laid out at when the picture allows it:
// title, plot area, ticks and axis title
constexpr double kMinimumPlotUnits = 150.0;

// the plots one above the other, sharing the height equally beyond the room a legend under a
// plot needs (the contact forces' two rows of six had been squeezed into each other and cut at
// the picture's bottom edge), so that every plot area keeps the same height
std::vector<std::pair<PlotPanel*, QRect>> stacked(const std::vector<PlotPanel*>& plots,
                                                  QSize size) {
  std::vector<std::pair<PlotPanel*, QRect>> out;
  const int n = static_cast<int>(plots.size());
  int legends = 0;
  for (const PlotPanel* plot : plots) legends += plot->legend_height_below();
  // never more than half the picture for legends: a tiny export shares it equally instead
  if (legends > size.height() / 2) legends = 0;
  const int shared = size.height() - legends;
  int top = 0;
  for (int i = 0; i < n; ++i) {
    const int extra = legends > 0 ? plots[i]->legend_height_below() : 0;
    const int height = shared * (i + 1) / n - shared * i / n + extra;
    out.push_back({plots[i], QRect(0, top, size.width(), height)});
    top += height;
  }
  return out;
}

// one table of plots that share their rows' x values (plot_csv_files): the x column, then every
// plot's series, row by row
CsvTable merged_table(const std::vector<CsvTable>& tables, const std::vector<std::size_t>& group,
                      const QString& x_column) {
  CsvTable merged;
  merged.columns.push_back(x_column.toStdString());
  const CsvTable& first = tables[group.front()];
  for (const auto& row : first.rows) merged.rows.push_back({row[0]});
  for (const std::size_t p : group) {
    const CsvTable& table = tables[p];
    for (const auto& [key, value] : table.metadata) merged.metadata.emplace(key, value);
    for (std::size_t c = 1; c < table.columns.size(); ++c)
      merged.columns.push_back(table.columns[c]);
    for (std::size_t r = 0; r < merged.rows.size(); ++r)
      merged.rows[r].insert(merged.rows[r].end(), table.rows[r].begin() + 1, table.rows[r].end());
  }
  if (!merged.rows.empty()) {
    merged.metadata["range"] = std::to_string(merged.rows.front()[0]) + " to " +
                               std::to_string(merged.rows.back()[0]) + " (" +
                               x_column.toStdString() + ")";
  }
  merged.metadata["exported_by"] = "pianoaction (visible range of the plots)";
  return merged;
}

QStringList write_csv_files(const std::vector<PlotPanel*>& plots, const QString& path,
                            const std::map<std::string, std::string>& metadata,
                            const ApproveFiles& approve) {
  std::vector<CsvTable> tables;
  std::vector<PlotCsvShape> shapes;
  for (const PlotPanel* plot : plots) {
    tables.push_back(plot->visible_table());
    PlotCsvShape shape{plot->x_column(), plot->title(), {}, {}};
    for (const auto& row : tables.back().rows) shape.x.push_back(row[0]);
    if (const auto names = tables.back().metadata.find(shape.x_column.toStdString());
        names != tables.back().metadata.end())
      shape.x_names = names->second;
    shapes.push_back(std::move(shape));
  }
  const std::vector<PlotCsvFile> files = plot_csv_files(shapes, path);
  QStringList paths;
  for (const PlotCsvFile& file : files) paths << file.path;
  if (approve && !approve(paths)) return {};
  for (const PlotCsvFile& file : files) {
    CsvTable table = merged_table(tables, file.plots, shapes[file.plots.front()].x_column);
    for (const auto& [key, value] : metadata) table.metadata[key] = value;
    write_csv(file.path.toStdString(), table);
  }
  return paths;
}

[[noreturn]] void fail(const QString& path, const std::string& problem) {
  throw InputError(located_message(path.toStdString(), "", problem));
}

/// Opens `file` (a QSaveFile: written beside its target, which is replaced only by commit()).
void open_for_saving(QSaveFile& file, const QString& path, const char* kind) {
  if (QFileInfo(path).isDir()) fail(path, std::string("a folder has that name, not a ") + kind);
  if (!file.open(QIODevice::WriteOnly))
    fail(path,
         std::string("cannot write the ") + kind + " file: " + file.errorString().toStdString());
}

/// Puts the finished file in place (what was there is replaced only now, in one step); fails,
/// naming `path`, when nothing was written or it cannot be put there (the old file is kept).
void commit_saved(QSaveFile& file, const QString& path, const char* kind) {
  if (file.size() <= 0) {
    file.cancelWriting();
    fail(path, std::string("could not write the ") + kind + " file");
  }
  if (!file.commit())
    fail(path,
         std::string("could not write the ") + kind + " file: " + file.errorString().toStdString());
}

}  // namespace

ExportFormat export_format(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "png") return ExportFormat::Png;
  if (suffix == "pdf") return ExportFormat::Pdf;
  if (suffix == "svg") return ExportFormat::Svg;
  if (suffix == "csv") return ExportFormat::Csv;
  if (suffix.isEmpty())
    fail(path, "no file extension to tell the plot format (use .png, .pdf, .svg or .csv)");
  fail(path, "unknown plot format '." + suffix.toStdString() + "' (use .png, .pdf, .svg or .csv)");
}

std::vector<PlotCsvFile> plot_csv_files(const std::vector<PlotCsvShape>& plots,
                                        const QString& path) {
  std::vector<PlotCsvFile> files;
  const QFileInfo info(path);
  const auto beside = [&](const QString& part) {  // in the folder `path` names, as it names it
    const QString name = info.completeBaseName() + "_" + part + ".csv";
    return path.contains('/') ? QDir(info.path()).filePath(name) : name;
  };
  for (std::size_t p = 0; p < plots.size(); ++p) {
    auto same_rows = [&](const PlotCsvFile& file) {
      const PlotCsvShape& first = plots[file.plots.front()];
      return first.x_column == plots[p].x_column && first.x == plots[p].x &&
             first.x_names == plots[p].x_names;
    };
    const auto shared = std::find_if(files.begin(), files.end(), same_rows);
    if (shared != files.end()) {
      shared->plots.push_back(p);
      continue;
    }
    const QString title_stem = file_stem(plots[p].title).isEmpty() ? QString("plot%1").arg(p + 1)
                                                                   : file_stem(plots[p].title);
    // named after its x column, or after its title when a file has that x column already
    const bool x_has_a_file = std::any_of(files.begin(), files.end(), [&](const PlotCsvFile& f) {
      return plots[f.plots.front()].x_column == plots[p].x_column;
    });
    QString file_path = files.empty()  ? path
                        : x_has_a_file ? beside(title_stem)
                                       : beside(file_stem(plots[p].x_column));
    const auto taken = [&](const QString& candidate) {
      return std::any_of(files.begin(), files.end(),
                         [&](const PlotCsvFile& f) { return f.path == candidate; });
    };
    for (int n = 2; taken(file_path); ++n)  // two plots of one title over one x: numbered
      file_path = beside(title_stem + QString("_%1").arg(n));
    files.push_back({file_path, {p}});
  }
  return files;
}

QStringList export_plots(const std::vector<PlotPanel*>& plots, const QString& path, QSize size,
                         const std::map<std::string, std::string>& metadata,
                         const ApproveFiles& approve) {
  if (plots.empty()) fail(path, "there is no plot to export");
  if (size.width() < 50 || size.height() < 50 || size.width() > 20000 || size.height() > 20000)
    fail(path, "export size must be between 50 and 20000 pixels a side");
  const ExportFormat format = export_format(path);
  const QFileInfo dir(QFileInfo(path).absolutePath());
  if (!dir.isDir() || !dir.isWritable()) fail(path, "the folder does not exist or is read-only");

  // a large picture is the plots laid out at about 800 units wide and drawn larger, text
  // included (at 1600 pixels the screen's 9 pt text was a quarter of its width's share)
  // ... unless that leaves a plot less than kMinimumPlotUnits high (four plots in 1000 pixels
  // had 125 each: the contact legend's second row was cut at the bottom): then less larger
  int legends = 0;
  for (const PlotPanel* plot : plots) legends += plot->legend_height_below();
  const double tall_enough =
      size.height() / (kMinimumPlotUnits * static_cast<double>(plots.size()) + legends);
  const double scale = std::max(1.0, std::min(size.width() / kExportLayoutWidth, tall_enough));
  const QSize layout(static_cast<int>(size.width() / scale),
                     static_cast<int>(size.height() / scale));
  switch (format) {
    case ExportFormat::Png: {
      QImage image(size, QImage::Format_ARGB32_Premultiplied);
      image.fill(Qt::white);
      PlotPanel::render(image, stacked(plots, layout), scale);
      if (!image.save(path, "PNG")) fail(path, "could not write the PNG file");
      break;
    }
    case ExportFormat::Pdf: {
      QSaveFile file(path);
      open_for_saving(file, path, "PDF");
      {
        QPdfWriter writer(&file);
        writer.setResolution(72);
        writer.setPageSize(QPageSize(QSizeF(size), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setCreator("pianoaction");
        PlotPanel::render(writer, stacked(plots, layout), scale);
      }  // the writer finishes the document here
      commit_saved(file, path, "PDF");
      break;
    }
    case ExportFormat::Svg: {
      QSaveFile file(path);
      open_for_saving(file, path, "SVG");
      {
        QSvgGenerator generator;
        generator.setOutputDevice(&file);
        generator.setSize(size);
        generator.setViewBox(QRect(QPoint(0, 0), size));
        generator.setTitle("Piano Action Trainer plots");
        PlotPanel::render(generator, stacked(plots, layout), scale);
      }
      commit_saved(file, path, "SVG");
      break;
    }
    case ExportFormat::Csv:
      return write_csv_files(plots, path, metadata, approve);
  }
  return {path};
}

}  // namespace pat::ui

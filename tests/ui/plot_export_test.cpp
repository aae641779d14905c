// Plots and their export (issue 5): PNG, PDF and SVG files of one or all plots at a chosen
// size, CSV of the visible time range, cursors with Δt and Δvalue, and the trace plots the
// command line's --plot writes.
#include "plot_export.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFontMetrics>
#include <QImage>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <memory>

#include "analysis_plots.h"
#include "core/error.h"
#include "export_folder.h"
#include "io/csv.h"
#include "model/preset_loader.h"
#include "plot_panel.h"
#include "plot_stack.h"
#include "save_paths.h"
#include "ui_test_support.h"

using pat::ui::PlotPanel;

class PlotExportTest : public QObject {
  Q_OBJECT
 private slots:
  void init();
  void png_pdf_svg_have_their_magic_and_size();
  void csv_holds_the_visible_range_only();
  void cursors_give_delta_t_and_delta_value();
  void unknown_extension_and_bad_folder_are_refused();
  void analysis_plots_are_written_headless();
  void a_csv_keeps_every_sample_and_gives_plots_of_other_rows_their_own_file();
  void flat_series_keeps_a_bounded_value_axis();
  void a_narrow_plot_puts_its_legend_under_it();
  void a_large_picture_is_drawn_larger_not_wider();
  void export_dialogs_open_in_the_last_export_folder_or_documents();
  void the_live_plots_span_a_chosen_window_or_the_whole_run();
  void a_legend_under_a_stacked_plot_keeps_its_height();
  void a_picture_draws_no_value_tick_above_its_plot_area();
  void a_name_typed_without_a_suffix_takes_the_chosen_formats();

 private:
  QByteArray head(const QString& path, int n = 64) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.read(n) : QByteArray();
  }
  std::unique_ptr<PlotPanel> angles_, gap_;
  QTemporaryDir dir_;
};

void PlotExportTest::flat_series_keeps_a_bounded_value_axis() {
  // a finger force of zero refitted at every replot (30 Hz for minutes) must keep its band of
  // about ±1 N instead of growing with each refit's padding
  pat::ui::PlotPanel flat("Finger force", "force (N)");
  const int s = flat.add_series("finger force", "finger_force_n", Qt::red);
  for (int i = 0; i < 100; ++i) flat.append(s, i * 1e-3, 0.0);
  flat.set_x_range(0.0, 0.1);
  for (int i = 0; i < 1000; ++i) flat.fit_values();
  const auto [lo, hi] = flat.value_range();
  QVERIFY2(lo <= 0.0 && hi >= 0.0 && hi - lo < 5.0, qPrintable(QString("%1 %2").arg(lo).arg(hi)));
}

// A legend wider than most of the plot area (a narrow panel, larger text) would cover the value
// axis' ticks and the traces: it goes under the plot while the panel is narrow, and back inside,
// top right, once it is wide again.
void PlotExportTest::a_narrow_plot_puts_its_legend_under_it() {
  angles_->resize(700, 260);
  angles_->grab();  // lays out and replots
  QVERIFY(!angles_->legend_below());
  QVERIFY(angles_->plot_area_rect().contains(angles_->legend_rect()));
  angles_->resize(190, 260);
  angles_->grab();
  QVERIFY(angles_->legend_below());
  QVERIFY2(angles_->legend_rect().top() >= angles_->plot_area_rect().bottom(),
           qPrintable(QString("legend from y %1, plot area to %2")
                          .arg(angles_->legend_rect().top())
                          .arg(angles_->plot_area_rect().bottom())));
  angles_->resize(700, 260);
  angles_->grab();
  QVERIFY(!angles_->legend_below());
  QVERIFY(angles_->plot_area_rect().contains(angles_->legend_rect()));
  // a picture of another size leaves the legend on screen where it was
  pat::ui::export_plots({angles_.get()}, dir_.filePath("narrow.png"), QSize(200, 300));
  QVERIFY(!angles_->legend_below());
  angles_->resize(190, 260);
  angles_->grab();
  QVERIFY(angles_->legend_below());
  pat::ui::export_plots({angles_.get()}, dir_.filePath("wide.png"), QSize(900, 300));
  QVERIFY(angles_->legend_below());
}

// A 1600x1000 picture is the 800x500 one drawn twice as large (text and lines included), not
// the plots spread over more pixels with the screen's small text: halved, it matches the small
// one nearly pixel for pixel.
void PlotExportTest::a_large_picture_is_drawn_larger_not_wider() {
  const QString small = dir_.filePath("small.png"), large = dir_.filePath("large.png");
  pat::ui::export_plots({angles_.get()}, small, QSize(800, 500));
  pat::ui::export_plots({angles_.get()}, large, QSize(1600, 1000));
  const QImage a(small),
      b = QImage(large).scaled(800, 500, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  QCOMPARE(QImage(large).size(), QSize(1600, 1000));
  double difference = 0.0;
  for (int y = 0; y < 500; ++y)
    for (int x = 0; x < 800; ++x)
      difference += std::abs(qGray(a.pixel(x, y)) - qGray(b.pixel(x, y)));
  difference /= 800.0 * 500.0;
  // anti-aliasing and font hinting differ between the sizes: 1.4 grey levels on average; the
  // same plots laid out at 1600 pixels (small text, other ticks) differ by 5.4
  QVERIFY2(difference < 3.0, qPrintable(QString("mean difference %1 grey levels").arg(difference)));
}

void PlotExportTest::init() {
  angles_ = std::make_unique<PlotPanel>("Key and hammer", "angle (deg)");
  gap_ = std::make_unique<PlotPanel>("Gap", "gap (mm)");
  angles_->add_series("key", "key_angle_deg", Qt::blue);
  angles_->add_series("hammer", "hammer_angle_deg", Qt::red);
  gap_->add_series("gap", "hammer_string_gap_mm", Qt::darkGreen);
  for (int i = 0; i <= 100; ++i) {
    const double t = i * 1e-3;
    angles_->append(0, t, 2.0 * t / 0.1);
    angles_->append(1, t, 30.0 * t / 0.1);
    gap_->append(0, t, 45.0 - 44.0 * t / 0.1);
  }
  angles_->fit_all();
  gap_->fit_all();
}

void PlotExportTest::png_pdf_svg_have_their_magic_and_size() {
  const std::vector<PlotPanel*> both{angles_.get(), gap_.get()};
  const QString png = dir_.filePath("all.png"), pdf = dir_.filePath("all.pdf"),
                svg = dir_.filePath("one.svg");
  pat::ui::export_plots(both, png, QSize(900, 700));
  pat::ui::export_plots(both, pdf, QSize(900, 700));
  pat::ui::export_plots({gap_.get()}, svg, QSize(640, 300));
  QVERIFY(head(png).startsWith("\x89PNG\r\n\x1a\n"));
  QVERIFY(head(pdf).startsWith("%PDF"));
  QVERIFY(head(svg, 400).contains("<svg"));
  const QImage image(png);
  QCOMPARE(image.size(), QSize(900, 700));
  // both plots are in the image: the upper and the lower half each have drawn (non-white) pixels
  auto inked = [&](int y0, int y1) {
    int count = 0;
    for (int y = y0; y < y1; y += 3)
      for (int x = 0; x < image.width(); x += 3) count += image.pixel(x, y) != qRgb(255, 255, 255);
    return count;
  };
  QVERIFY(inked(0, 350) > 500);
  QVERIFY(inked(350, 700) > 500);
  QFile svg_file(svg);
  QVERIFY(svg_file.open(QIODevice::ReadOnly));
  QVERIFY(svg_file.readAll().contains("gap (mm)"));  // axis title with its unit

  // a panel on screen too short for its y title shows the unit alone; a picture of it with room
  // has the whole title, and the screen keeps its own
  // (a title longer than any panel's shortest plot area)
  PlotPanel forces("Forces", "normal force at the contact point (N)");
  forces.add_series("capstan", "capstan_n", Qt::blue);
  for (int i = 0; i <= 10; ++i) forces.append(0, i * 1e-3, i);
  forces.resize(400, forces.minimumHeight());
  forces.show();
  QVERIFY2(pat::ui::test::wait_until([&] { return forces.y_label_shown() == "N"; }),
           qPrintable(forces.y_label_shown()));
  const QString tall = dir_.filePath("tall.svg");
  pat::ui::export_plots({&forces}, tall, QSize(640, 900));
  QFile tall_file(tall);
  QVERIFY(tall_file.open(QIODevice::ReadOnly));
  QVERIFY(tall_file.readAll().contains("normal force at the contact point (N)"));
  QCOMPARE(forces.y_label_shown(), QString("N"));
}

void PlotExportTest::csv_holds_the_visible_range_only() {
  angles_->set_x_range(0.020, 0.040);
  gap_->set_x_range(0.020, 0.040);
  const QString path = dir_.filePath("visible.csv");
  pat::ui::export_plots({angles_.get(), gap_.get()}, path, QSize(800, 600),
                        {{"action", "grand"}, {"input", "force:pulse:20:40"}});
  const pat::CsvTable table = pat::read_csv(path.toStdString());
  QCOMPARE(table.columns, (std::vector<std::string>{"time_s", "key_angle_deg", "hammer_angle_deg",
                                                    "hammer_string_gap_mm"}));
  // what the window knows about the run goes into the '#' lines
  QCOMPARE(table.metadata.at("action"), std::string("grand"));
  QCOMPARE(table.metadata.at("input"), std::string("force:pulse:20:40"));
  QCOMPARE(table.rows.size(), std::size_t(21));
  QVERIFY(std::abs(table.rows.front()[0] - 0.020) < 1e-12);
  QVERIFY(std::abs(table.rows.back()[0] - 0.040) < 1e-12);
  QVERIFY(std::abs(table.rows[10][2] - 30.0 * 0.030 / 0.1) < 1e-9);
  QVERIFY(std::abs(table.rows[10][3] - (45.0 - 44.0 * 0.3)) < 1e-9);
}

void PlotExportTest::cursors_give_delta_t_and_delta_value() {
  QVERIFY(angles_->cursor_readout().isEmpty());
  // one cursor: the screen says how to place the other, an exported picture does not
  angles_->set_cursor(0, 0.010);
  const QString svg = dir_.filePath("one_cursor.svg");
  pat::ui::export_plots({angles_.get()}, svg, QSize(640, 300));
  QFile svg_file(svg);
  QVERIFY(svg_file.open(QIODevice::ReadOnly));
  const QByteArray picture = svg_file.readAll();
  QVERIFY(picture.contains("A at 10.00 ms"));
  QVERIFY(!picture.contains("right click"));
  angles_->set_cursor(0, 0.010);
  angles_->set_cursor(1, 0.050);
  const QString readout = angles_->cursor_readout();
  QVERIFY2(readout.contains("Δt = 40.00 ms"), qPrintable(readout));
  QVERIFY2(readout.contains("Δ hammer = 12.00 deg"), qPrintable(readout));
  QVERIFY2(readout.contains("Δ key = 0.80 deg"), qPrintable(readout));
  // the changes go beside the times where the plot is wide enough, not a line each (three
  // lines had squeezed a short plot's data into a strip)
  const QSize size_before = angles_->size();
  angles_->resize(1200, 300);
  QVERIFY2(angles_->cursor_readout().count('\n') == 0, qPrintable(angles_->cursor_readout()));
  angles_->resize(size_before);
  // two cursors on the same values: no rounding noise ("6.858e-16 deg")
  angles_->set_cursor(1, 0.010 + 1e-12);
  QVERIFY2(angles_->cursor_readout().contains("Δ hammer = 0.00 deg") &&
               !angles_->cursor_readout().contains("e-"),
           qPrintable(angles_->cursor_readout()));
  QVERIFY(!angles_->value_at(0, 0.5).has_value());  // outside the data
  // PAT_UI_SHOTS=DIR keeps a picture of the readout (in its row under the title, clear of the
  // legend) for a person to look at
  const QString shots = qEnvironmentVariable("PAT_UI_SHOTS");
  if (!shots.isEmpty())
    pat::ui::export_plots({angles_.get()}, shots + "/cursor_readout.png", QSize(500, 300));
}

void PlotExportTest::unknown_extension_and_bad_folder_are_refused() {
  try {
    pat::ui::export_plots({gap_.get()}, dir_.filePath("plot.bmp"), QSize(400, 300));
    QFAIL("a .bmp export was accepted");
  } catch (const pat::InputError& e) {
    QVERIFY(QString(e.what()).contains("plot.bmp"));
  }
  QVERIFY_THROWS_EXCEPTION(
      pat::InputError,
      pat::ui::export_plots({gap_.get()}, "/nonexistent/dir/p.png", QSize(400, 300)));
  // a PDF or SVG writer that cannot write its file says nothing: a name already taken by a
  // folder had been reported as exported (the folder "existed"); the export fails, naming the
  // file, and leaves the folder as it was, with nothing beside it
  for (const char* name : {"taken.pdf", "taken.svg"}) {
    QVERIFY(QDir(dir_.path()).mkpath(name));
    try {
      pat::ui::export_plots({gap_.get()}, dir_.filePath(name), QSize(400, 300));
      QFAIL(qPrintable(QString("an export onto the folder %1 was reported written").arg(name)));
    } catch (const pat::InputError& e) {
      QVERIFY2(QString(e.what()).contains(name), e.what());
    }
    QVERIFY(QFileInfo(dir_.filePath(name)).isDir());
    QCOMPARE(QDir(dir_.path()).entryList({QString(name) + "*"}, QDir::Files), QStringList());
  }
  // an existing file is replaced by the new picture, in one step once it is whole
  const QString pdf = dir_.filePath("again.pdf");
  QFile old(pdf);
  QVERIFY(old.open(QIODevice::WriteOnly));
  old.write("old contents");
  old.close();
  pat::ui::export_plots({gap_.get()}, pdf, QSize(400, 300));
  QVERIFY(head(pdf).startsWith("%PDF"));
  QCOMPARE(QDir(dir_.path()).entryList({"again.pdf*"}, QDir::Files), QStringList{"again.pdf"});
}

// The command line's --plot path: plots of series over any x axis, stacked in one file.
void PlotExportTest::analysis_plots_are_written_headless() {
  pat::ui::AnalysisPlot angles{"Key and hammer", "time (s)", "time_s", "s", "angle (deg)", {}};
  pat::ui::AnalysisSeries hammer{"hammer", "hammer_angle_deg", {}, {}};
  for (int i = 0; i < 50; ++i) {
    hammer.x.push_back(i * 1e-3);
    hammer.y.push_back(0.5 * i);
  }
  angles.series.push_back(hammer);
  pat::ui::AnalysisPlot strikes{"Strikes", "setting", "setting_index", "", "strikes", {}};
  strikes.series.push_back({"strikes", "strikes", {0, 1, 2}, {1, 2, 1}, true});
  strikes.x_categories = {"key_dip", "let_off", "drop"};
  std::unique_ptr<PlotPanel> panel(pat::ui::make_analysis_plot_panel(angles));
  QCOMPARE(panel->series_count(), 1);
  QCOMPARE(panel->point_count(0), std::size_t(50));
  const QString pdf = dir_.filePath("plots.pdf");
  pat::ui::write_analysis_plots({angles, strikes}, pdf);
  QVERIFY(head(pdf).startsWith("%PDF"));
  const QString png = dir_.filePath("plots.png");
  pat::ui::write_analysis_plots({angles, strikes}, png);
  QCOMPARE(QImage(png).size(), pat::ui::stacked_plot_size(2));  // 300 px per stacked plot
  // a CSV of named positions says which name each number is (the sensitivity plot's
  // setting_index could not be read on its own)
  const QString csv = dir_.filePath("strikes.csv");
  pat::ui::write_analysis_plots({strikes}, csv);
  const pat::CsvTable table = pat::read_csv(csv.toStdString());
  QCOMPARE(table.columns.front(), std::string("setting_index"));
  QCOMPARE(table.metadata.at("setting_index"), std::string("0 key_dip; 1 let_off; 2 drop"));
}

// A steps sweep's plots: a frequency held for several cycles has a sample per cycle at one x. The
// CSV had written the first cycle's value for each, and merging with the strike-speed plot (no
// sample where a cycle missed the string) kept one row per frequency. Now every sample is a row,
// and plots whose rows have other x values (another axis, or fewer samples) get their own file.
void PlotExportTest::a_csv_keeps_every_sample_and_gives_plots_of_other_rows_their_own_file() {
  pat::ui::AnalysisPlot strikes{
      "Strikes per cycle", "key frequency (Hz)", "frequency_hz", "Hz", "strikes", {}};
  strikes.series.push_back({"strikes", "strikes", {10, 10, 10, 10.5, 10.5}, {1, 1, 2, 1, 0}, true});
  pat::ui::AnalysisPlot speed{
      "Hammer speed at each strike", "key frequency (Hz)", "frequency_hz", "Hz", "speed (m/s)", {}};
  speed.series.push_back(
      {"speed", "strike_velocity_mps", {10, 10, 10, 10.5}, {3.1, 3.2, 2.9, 3.3}, true});
  pat::ui::AnalysisPlot trace{"Key", "time (s)", "time_s", "s", "angle (deg)", {}};
  trace.series.push_back({"key", "key_angle_deg", {0, 0.1, 0.2}, {0, 1, 2}});
  // two series over the same repeated x pair sample by sample
  pat::ui::AnalysisPlot both{"Both", "key frequency (Hz)", "frequency_hz", "Hz", "n", {}};
  both.series.push_back({"a", "a", {10, 10, 10, 10.5, 10.5}, {5, 6, 7, 8, 9}, true});
  both.series.push_back({"b", "b", {10, 10, 10, 10.5, 10.5}, {15, 16, 17, 18, 19}, true});
  // a series with fewer samples at a repeated x gives none for the ranks it lacks: that row is
  // left out, not filled with a sample of another rank
  pat::ui::AnalysisPlot fewer{"Fewer", "key frequency (Hz)", "frequency_hz", "Hz", "n", {}};
  fewer.series.push_back({"a", "a", {10, 10, 10.5}, {5, 6, 8}, true});
  fewer.series.push_back({"b", "b", {10, 10.5}, {15, 18}, true});
  {
    const QString fewer_path = dir_.filePath("fewer.csv");
    pat::ui::write_analysis_plots({fewer}, fewer_path);
    const std::vector<std::vector<double>> rows{{10, 5, 15}, {10.5, 8, 18}};
    QCOMPARE(pat::read_csv(fewer_path.toStdString()).rows, rows);
  }

  QStringList asked;
  const QString path = dir_.filePath("sweep.csv");
  const QStringList written = pat::ui::write_analysis_plots({strikes, speed, trace, both}, path, {},
                                                            [&](const QStringList& files) {
                                                              asked = files;
                                                              return true;
                                                            });
  const QStringList expected{path, dir_.filePath("sweep_hammer_speed_at_each_strike.csv"),
                             dir_.filePath("sweep_time_s.csv")};
  QCOMPARE(written, expected);
  QCOMPARE(asked, expected);  // asked before anything was written

  const pat::CsvTable cycles = pat::read_csv(path.toStdString());
  QCOMPARE(cycles.columns, (std::vector<std::string>{"frequency_hz", "strikes", "a", "b"}));
  const std::vector<std::vector<double>> cycle_rows{
      {10, 1, 5, 15}, {10, 1, 6, 16}, {10, 2, 7, 17}, {10.5, 1, 8, 18}, {10.5, 0, 9, 19}};
  QCOMPARE(cycles.rows, cycle_rows);
  const pat::CsvTable speeds = pat::read_csv(expected[1].toStdString());
  const std::vector<std::vector<double>> speed_rows{{10, 3.1}, {10, 3.2}, {10, 2.9}, {10.5, 3.3}};
  QCOMPARE(speeds.rows, speed_rows);
  QCOMPARE(pat::read_csv(expected[2].toStdString()).rows.size(), std::size_t(3));

  // declined: nothing written
  const QString declined = dir_.filePath("declined.csv");
  QVERIFY(pat::ui::write_analysis_plots({strikes, trace}, declined, {}, [](const QStringList&) {
            return false;
          }).isEmpty());
  QVERIFY(!QFileInfo::exists(declined));
  QVERIFY(!QFileInfo::exists(dir_.filePath("declined_time_s.csv")));

  // names: a relative path keeps its folder as given; two plots of one title over one x numbered
  using pat::ui::PlotCsvShape;
  // (an untitled plot by its place); the same x values named otherwise do not share rows
  const std::vector<PlotCsvShape> shapes{{"time_s", "A", {0, 1}, ""},
                                         {"time_s", "A", {0, 2}, ""},
                                         {"time_s", "A", {0, 3}, ""},
                                         {"frequency_hz", "", {1}, ""},
                                         {"frequency_hz", "", {2}, ""},
                                         {"setting_index", "S", {0, 1}, "0 drop; 1 let_off"},
                                         {"setting_index", "T", {0, 1}, "0 key_dip; 1 drop"}};
  const auto files = pat::ui::plot_csv_files(shapes, "out.csv");
  QCOMPARE(files.size(), std::size_t(7));
  QCOMPARE(files[0].path, QString("out.csv"));
  QCOMPARE(files[1].path, QString("out_a.csv"));
  QCOMPARE(files[2].path, QString("out_a_2.csv"));
  QCOMPARE(files[3].path, QString("out_frequency_hz.csv"));
  QCOMPARE(files[4].path, QString("out_plot5.csv"));
  QCOMPARE(files[5].path, QString("out_setting_index.csv"));
  QCOMPARE(files[6].path, QString("out_t.csv"));
  QCOMPARE(pat::ui::plot_csv_files(shapes, "/out.csv")[1].path, QString("/out_a.csv"));
}

// An export dialog opens where the last export went, or in the documents folder (or home), not in
// the working directory the program was started from (a build tree, when run from there).
void PlotExportTest::export_dialogs_open_in_the_last_export_folder_or_documents() {
  QSettings().remove("export_folder");
  const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  const QString first = pat::ui::export_folder();
  QVERIFY2(first == documents || first == QDir::homePath(), qPrintable(first));
  const QString file = dir_.filePath("plots.png");
  pat::ui::remember_export_folder(file);
  QCOMPARE(pat::ui::export_folder(), dir_.path());
  QCOMPARE(pat::ui::export_path("report.pdf"), dir_.filePath("report.pdf"));
  pat::ui::remember_export_folder(dir_.path());  // a report written into a folder
  QCOMPARE(pat::ui::export_folder(), dir_.path());
  QSettings().setValue("export_folder", dir_.filePath("gone"));  // since removed: not offered
  QVERIFY(pat::ui::export_folder() != dir_.filePath("gone"));
  QSettings().remove("export_folder");
}

// The live plots follow the time in a window of the chosen span, and show the whole run on demand
// (a 1.4 s slow press's let-off and drop had scrolled out of the fixed 0.25 s).
void PlotExportTest::the_live_plots_span_a_chosen_window_or_the_whole_run() {
  const pat::ActionModel model = pat::load_action("grand");
  pat::ui::PlotStack stack;
  stack.set_model(model);
  std::vector<pat::ui::Frame> frames;
  for (int i = 0; i <= 1500; ++i) {
    pat::ui::Frame f;
    f.t = 1e-3 * i;
    f.angle_deg.assign(model.bodies.size(), std::sin(f.t));
    f.contact_force_n.assign(model.contacts.size(), 0.0);
    frames.push_back(f);
  }
  stack.append(frames);
  auto width = [&] {
    const auto [lo, hi] = stack.angles()->x_range();
    return hi - lo;
  };
  QVERIFY2(std::abs(width() - 0.25) < 1e-9, qPrintable(QString::number(width())));
  stack.set_window(1.0);  // following: applied at once
  QVERIFY2(std::abs(width() - 1.0) < 1e-9, qPrintable(QString::number(width())));
  stack.show_whole_run();
  QVERIFY(!stack.following());
  const auto [lo, hi] = stack.angles()->x_range();
  QCOMPARE(lo, 0.0);
  QCOMPARE(hi, 1.5);
  for (pat::ui::PlotPanel* panel : stack.panels())
    QCOMPARE(panel->x_range(), stack.angles()->x_range());
  // the run goes on (another blow): the whole of it stays on the axes (they had stayed on
  // 0–1.5 s while the new frames ran off them)
  std::vector<pat::ui::Frame> later;
  for (int i = 1501; i <= 2500; ++i) {
    pat::ui::Frame f = frames.front();
    f.t = 1e-3 * i;
    later.push_back(f);
  }
  stack.append(later);
  QCOMPARE(stack.angles()->x_range().second, 2.5);
  QCOMPARE(stack.angles()->x_range().first, 0.0);
  // a new run (Start from rest clears the plots) keeps the whole-run mode: it had gone back to
  // following, and the next slow press's let-off and drop scrolled away again
  QSignalSpy whole_changed(&stack, &pat::ui::PlotStack::wholeRunChanged);
  stack.clear();
  QVERIFY(stack.showing_whole_run());
  QVERIFY(!stack.following());
  stack.append(frames);
  QCOMPARE(stack.angles()->x_range().first, 0.0);
  QCOMPARE(stack.angles()->x_range().second, 1.5);
  QCOMPARE(whole_changed.count(), 0);
  // the run's plots share their samples: their CSV is one table, every frame a row
  const QString run_csv = dir_.filePath("run.csv");
  QCOMPARE(pat::ui::export_plots(stack.panels(), run_csv, QSize(800, 600)), QStringList{run_csv});
  QCOMPARE(pat::read_csv(run_csv.toStdString()).rows.size(), frames.size());
  // Follow brings the sliding window back
  stack.set_following(true);
  QVERIFY(!stack.showing_whole_run());
  QCOMPARE(whole_changed.count(), 1);
  QVERIFY2(std::abs(width() - 1.0) < 1e-9, qPrintable(QString::number(width())));
}

// The window's four plots exported at 1600x1000: the contact forces' legend (two rows under its
// plot) keeps the height it needs inside its share of the picture (it was squeezed into one row's
// height and cut at the bottom edge).
void PlotExportTest::a_legend_under_a_stacked_plot_keeps_its_height() {
  const pat::ActionModel model = pat::load_action("grand");
  pat::ui::PlotStack stack;
  stack.resize(740, 360);
  stack.set_model(model);
  std::vector<pat::ui::Frame> frames;
  for (int i = 0; i <= 300; ++i) {
    pat::ui::Frame f;
    f.t = 1e-3 * i;
    f.angle_deg.assign(model.bodies.size(), std::sin(20 * f.t));
    f.contact_force_n.assign(model.contacts.size(), 10.0 * std::cos(20 * f.t));
    frames.push_back(f);
  }
  stack.append(frames);
  stack.show();
  QVERIFY(QTest::qWaitForWindowExposed(&stack));
  pat::ui::PlotPanel* contacts = stack.contacts();
  QVERIFY(contacts->legend_below());
  const int needed = contacts->legend_height_below();
  const QString path = dir_.filePath("stack.png");
  pat::ui::export_plots(stack.panels(), path, QSize(1600, 1000), {});
  // the render laid the panel out at its share: the legend got the rows it needs
  const QRect legend = contacts->legend_rect();
  QVERIFY2(legend.height() >= needed,
           qPrintable(QString("legend %1 px high, needs %2").arg(legend.height()).arg(needed)));
}

// A picture lays the plot out at its own height, and the legend's headroom is refitted to it:
// the value axis' ticks must follow that range. They had been made for the range before it, so
// a 300 px analysis plot showed a tick label and sub-ticks above its plot area, up into the
// title's row (the touchweight plot's "70" over a range that ended at 67).
void PlotExportTest::a_picture_draws_no_value_tick_above_its_plot_area() {
  const QString path = dir_.filePath("short.png");
  // 800 px wide: drawn at the layout's own scale, so the plot area's rect is in the picture's
  // pixels
  pat::ui::export_plots({angles_.get()}, path, QSize(800, 300));
  const QImage image(path);
  const QRect area = angles_->plot_area_rect();
  const int label_height = QFontMetrics(QApplication::font()).height();
  // left of the plot area and above its top tick label's reach: only white
  int dark = 0;
  for (int y = 0; y < area.top() - label_height; ++y)
    for (int x = 0; x < area.left(); ++x)
      if (qGray(image.pixel(x, y)) < 160) ++dark;
  QVERIFY2(dark == 0, qPrintable(QString("%1 dark pixels left of the plot area, above y %2")
                                     .arg(dark)
                                     .arg(area.top() - label_height)));
}

// A teacher who picks "PDF" in the save dialog and types "lesson1" gets lesson1.pdf (the dialogs
// add no suffix themselves, and the export refused a name without one); a name with its own
// suffix keeps it, and a name on a dotted folder still gets one.
void PlotExportTest::a_name_typed_without_a_suffix_takes_the_chosen_formats() {
  using pat::ui::with_filter_suffix;
  const QString plots = "PNG images (*.png);;PDF (*.pdf);;SVG (*.svg)";
  QCOMPARE(with_filter_suffix("/tmp/lesson1", "PDF (*.pdf)", plots), QString("/tmp/lesson1.pdf"));
  QCOMPARE(with_filter_suffix("/tmp/lesson1", "PNG images (*.png)", plots),
           QString("/tmp/lesson1.png"));
  // a suffix the dialog offers is kept, whichever format is selected
  QCOMPARE(with_filter_suffix("/tmp/lesson1.svg", "PDF (*.pdf)", plots),
           QString("/tmp/lesson1.svg"));
  QCOMPARE(with_filter_suffix("/tmp/lesson1.PDF", "PNG images (*.png)", plots),
           QString("/tmp/lesson1.PDF"));
  // a dot in the name that is no format's suffix ("v2.1"), or in a folder's name, gets one
  QCOMPARE(with_filter_suffix("/tmp/plots v2.1", "PDF (*.pdf)", plots),
           QString("/tmp/plots v2.1.pdf"));
  QCOMPARE(with_filter_suffix("/tmp/v1.2/plots", "CSV (*.csv)", "CSV (*.csv)"),
           QString("/tmp/v1.2/plots.csv"));
  QCOMPARE(with_filter_suffix("/tmp/mine", "Action presets (*.json)", "Action presets (*.json)"),
           QString("/tmp/mine.json"));
  QCOMPARE(with_filter_suffix("/tmp/any", "All files (*)", "All files (*)"), QString("/tmp/any"));
  QCOMPARE(with_filter_suffix("", "PDF (*.pdf)", plots), QString());
  // and the files it would replace beyond the one confirmed are found
  const QString existing = dir_.filePath("exists.csv");
  QFile file(existing);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.close();
  QCOMPARE(pat::ui::existing_files({existing, dir_.filePath("new.csv")}), QStringList{existing});
}

QTEST_MAIN(PlotExportTest)
#include "plot_export_test.moc"

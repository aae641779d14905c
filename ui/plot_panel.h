// One plot of time series, the only class that includes <qcustomplot.h> (DESIGN.md section 1:
// a move to another plotting library touches this class only). Axis titles carry units; two
// cursors (A: left click, B: right click) show Δt and Δvalue of every series; wheel zooms,
// left drag pans. Plots render onto any paint device for export (plot_export.h).
#pragma once

#include <QColor>
#include <QFontMetricsF>
#include <QRect>
#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "io/csv.h"

class QCustomPlot;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCPTextElement;
class QPaintDevice;

namespace pat::ui {

class PlotPanel : public QWidget {
  Q_OBJECT
 public:
  /// `y_title` names the quantity with its unit, e.g. "gap (mm)".
  PlotPanel(const QString& title, const QString& y_title, QWidget* parent = nullptr);
  ~PlotPanel() override;

  /// Adds a series; `column` is its CSV column name with the unit (e.g. hammer_angle_deg).
  int add_series(const QString& label, const QString& column, const QColor& colour);
  int series_count() const { return static_cast<int>(series_.size()); }
  QString series_label(int series) const;
  /// Appends one point (times in increasing order), t in s.
  void append(int series, double t, double value);
  void set_data(int series, const std::vector<double>& t, const std::vector<double>& values);
  void clear_data();
  /// Drops points older than t (keeps memory bounded in long runs).
  void remove_before(double t);
  std::size_t point_count(int series) const;

  /// The x axis (default: time). `column` names it in CSV exports; the cursor readout shows
  /// Δ`symbol` and x multiplied by readout_scale in readout_unit (time: t, ms, scale 1000).
  void set_x_axis(const QString& title, const QString& column, const QString& symbol,
                  const QString& readout_unit, double readout_scale);
  /// Names the integer positions 0, 1, … of the x axis (categories such as settings) and
  /// leaves half a category of margin at each end.
  void set_x_categories(const std::vector<QString>& names);
  /// Draws a series as markers without a line (one result per cycle or per case).
  void set_points_only(int series);
  /// A labelled vertical line at x (the maximum frequency of a sweep, an impact); labels of
  /// successive markers are stacked downwards so that close ones stay readable.
  void add_marker(double x, const QString& label);
  int marker_count() const { return static_cast<int>(markers_.size()); }
  /// A solid vertical line at the time the action view shows (none: hidden); left out of
  /// exports.
  void set_time_mark(std::optional<double> t);
  std::optional<double> time_mark() const { return time_mark_; }
  /// The value axis spans at least this much (in its unit) when fitted, so that the settling
  /// noise of an action at rest does not fill the plot as if it moved (default 0: any span).
  void set_minimum_value_span(double span) { minimum_value_span_ = span; }

  QString title() const { return title_; }
  QString y_title() const { return y_title_; }
  /// The y axis's title as drawn: y_title(), or its unit alone on a plot area too short for it.
  QString y_label_shown() const;
  /// The x axis' CSV column (time_s unless set_x_axis named another).
  QString x_column() const { return x_column_; }
  void set_x_range(double lo, double hi);
  std::pair<double, double> x_range() const;
  std::pair<double, double> value_range() const;
  /// Fits the value axis to the data within the time range shown.
  void fit_values();
  /// Fits both axes to all data.
  void fit_all();
  /// Replots at the next event-loop turn (several calls coalesce into one).
  void request_replot();

  /// The axes' tick label size (pt): the widget's font's, 9 pt at least; it follows a change of
  /// the font (the View menu's larger text for a class).
  double tick_label_point_size() const;
  /// Where the legend is (widget pixels) and whether it sits under the plot area, and the plot
  /// area itself, for tests.
  QRect legend_rect() const;
  bool legend_below() const { return legend_below_; }
  /// The height (px) a legend under the plot takes (0 when it sits inside the plot area).
  int legend_height_below() const;
  QRect plot_area_rect() const;

  void set_cursors_enabled(bool enabled);
  bool cursors_enabled() const { return cursors_enabled_; }
  /// Places cursor 0 (A) or 1 (B) at time t.
  void set_cursor(int which, double t);
  std::optional<double> cursor(int which) const;
  /// Value of a series at time t (linear interpolation), if t is within its data.
  std::optional<double> value_at(int series, double t) const;
  /// The series' `rank`-th sample at exactly `x` (none when it has fewer there), or value_at(x)
  /// when it has no sample there.
  std::optional<double> sample_at(int series, double x, int rank) const;
  /// "Δt = … ms, Δ<series> = … <unit>" for the two cursors (empty without both).
  QString cursor_readout() const;

  /// Draws plots into `device`, each in its rectangle (pixels before `scale`), with one painter
  /// (a PDF or SVG device takes a single painter session); `scale` enlarges everything drawn,
  /// text and lines with the rest, as a high-resolution picture does.
  static void render(QPaintDevice& device, const std::vector<std::pair<PlotPanel*, QRect>>& plots,
                     double scale = 1.0);
  /// The series within the time range shown: time_s and one column per series (values taken
  /// at each series' own sample times; series of one plot share them in this program).
  CsvTable visible_table() const;

 signals:
  /// The user zoomed or panned the time axis (not emitted for set_x_range).
  void userChangedTimeRange(double lo, double hi);
  /// A replot finished; `ms` is the wall time it took (QCustomPlot's own measure).
  void replotted(double ms);

 protected:
  void changeEvent(QEvent* event) override;
  /// The cursor readout wraps to the new width (its changes beside the times where they fit).
  void resizeEvent(QResizeEvent* event) override;

 private:
  /// Sets the title, axis, legend, readout and marker fonts from the widget's font.
  void apply_fonts();
  /// The most ticks (2–8) whose labels fit `width_px` side by side on the x axis as it stands,
  /// for the step the ticker rounds to and the digits its labels then have.
  int x_tick_count(double width_px, const QFontMetricsF& ticks) const;
  /// The panel's minimum height for its fonts and its legend's place (plot_panel.cpp).
  void update_minimum_height();
  /// update_minimum_height() once the event loop is back (from inside a layout or replot).
  void schedule_minimum_height();
  /// The y axis's title as it fits the plot area's height: the whole, or the unit alone;
  /// `replot`: asks for a replot when it changes (not while a picture is drawn).
  void fit_y_label(bool replot = true);
  /// Cursor lines and the readout row; `for_export`: without the on-screen instruction ("click:
  /// A, right click: B"), which means nothing in an exported picture.
  void update_cursor_items(bool for_export = false);
  /// Puts each marker's label on the side of its line with more room in the x range shown.
  void align_marker_labels();
  /// Takes the legend out of the plot area into a row under it (categories, many series;
  /// `for_good`), or for as long as the plot area is too narrow for it inside.
  void move_legend_below(bool for_good = true);
  /// Puts a legend moved below for a narrow plot area back inside it, top right.
  void move_legend_inside();
  /// Moves the legend below or back inside as the plot area's width asks; true when it moved.
  bool place_legend_for_width();
  /// The legend's width on one row (px), whatever its wrap.
  double legend_row_width() const;
  /// Below the plot: the legend wrapped into as many columns as the panel's width holds; true
  /// when that changed.
  bool wrap_legend_to_width();

  QString title_;
  QString y_title_;
  QString x_column_ = "time_s";
  QString x_symbol_ = "t";
  std::size_t categories_ = 0;           ///< named x positions (0: a numeric axis)
  std::vector<QString> category_names_;  ///< their names, for the CSV's `#` line
  bool points_only_ = false;             ///< some series are markers only (fit_all pads x)
  QString x_readout_unit_ = "ms";
  double x_readout_scale_ = 1e3;
  QCustomPlot* plot_;
  struct Series {
    QCPGraph* graph;
    QString label, column;
  };
  std::vector<Series> series_;
  std::vector<std::pair<QCPItemStraightLine*, QCPItemText*>> markers_;
  QCPItemStraightLine* cursor_lines_[2] = {nullptr, nullptr};
  QCPTextElement* title_element_ = nullptr;
  QCPItemText* readout_ = nullptr;         ///< hidden: the anchor of the markers' labels
  QCPTextElement* readout_row_ = nullptr;  ///< the cursor readout, while there is one
  QCPItemStraightLine* time_mark_line_ = nullptr;
  std::optional<double> time_mark_;
  double minimum_value_span_ = 0.0;
  bool legend_below_ = false;
  bool legend_below_for_good_ = false;  ///< below whatever the width (categories, many series)
  QMargins legend_margins_inside_;
  bool rendering_ = false;     ///< drawn into a picture (render()): the legend stays where it is
  int readout_width_px_ = -1;  ///< the width the cursor readout wraps to (render: the picture's)
  int fitted_height_px_ = -1;  ///< the plot area's height the value axis was last fitted for
  std::optional<double> cursors_[2];
  bool cursors_enabled_ = true;
  bool setting_range_ = false;
  QPoint press_position_;
};

}  // namespace pat::ui

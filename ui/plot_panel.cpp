#include "plot_panel.h"

#include <qcustomplot.h>

#include <QEvent>
#include <QFontMetricsF>
#include <QImage>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace pat::ui {
namespace {

constexpr int kMinimumHeightPx = 120;  // a panel at the normal text size

const QColor kCursorColours[2] = {QColor(0, 120, 0), QColor(160, 0, 160)};
const char* kCursorNames[2] = {"A", "B"};

// the unit at the end of an axis title or column name ("gap (mm)" → "mm", "x_force_n" → "n")
QString unit_of(const QString& column) {
  const int underscore = column.lastIndexOf('_');
  if (underscore < 0) return {};
  const QString unit = column.mid(underscore + 1);
  if (unit == "n") return "N";
  return unit;
}

}  // namespace

PlotPanel::PlotPanel(const QString& title, const QString& y_title, QWidget* parent)
    : QWidget(parent), title_(title), y_title_(y_title), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  setMinimumHeight(kMinimumHeightPx);

  // title above; the legend inside the plot, top right, over headroom left by fit_values()
  plot_->plotLayout()->insertRow(0);
  title_element_ = new QCPTextElement(plot_, title);
  plot_->plotLayout()->addElement(0, 0, title_element_);
  plot_->legend->setVisible(true);
  plot_->legend->setBorderPen(QPen(QColor(200, 200, 200)));
  plot_->legend->setBrush(QColor(255, 255, 255, 210));
  plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  plot_->legend->setRowSpacing(0);
  plot_->legend->setColumnSpacing(6);
  plot_->legend->setIconSize(16, 8);
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignRight | Qt::AlignTop);
  plot_->xAxis->setLabel(tr("time (s)"));
  plot_->yAxis->setLabel(y_title);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->axisRect()->setRangeDrag(Qt::Horizontal);
  plot_->axisRect()->setRangeZoom(Qt::Horizontal);
  plot_->setNoAntialiasingOnDrag(true);
  // on screen, lines as separate segments instead of one stroked polyline: a replot of the live
  // plots takes about half the time (pianoaction bench --window), which leaves the action view
  // its 60 frames a second; the joins of the 2 px lines do not show at this data density.
  // Exports (render()) draw full polylines.
  plot_->setPlottingHint(QCP::phFastPolylines, true);

  for (int i = 0; i < 2; ++i) {
    cursor_lines_[i] = new QCPItemStraightLine(plot_);
    cursor_lines_[i]->setPen(QPen(kCursorColours[i], 1.5, Qt::DashLine));
    cursor_lines_[i]->setVisible(false);
  }
  time_mark_line_ = new QCPItemStraightLine(plot_);
  time_mark_line_->setPen(QPen(QColor(90, 90, 90, 170), 1.5));
  time_mark_line_->setVisible(false);
  // an invisible anchor at the top left of the plot area: the markers' labels hang from it
  // (the cursor readout itself is a row under the title, update_cursor_items)
  readout_ = new QCPItemText(plot_);
  readout_->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
  readout_->position->setType(QCPItemPosition::ptAxisRectRatio);
  readout_->position->setCoords(0.01, 0.02);

  readout_->setBrush(QColor(255, 255, 255, 220));
  readout_->setPadding(QMargins(4, 2, 4, 2));
  readout_->setTextAlignment(Qt::AlignLeft);
  readout_->setVisible(false);
  apply_fonts();
  // the legend's headroom and the tick counts depend on the plot area's height in pixels: once a
  // layout gives it a new height (a resize, the first show, an export at its own size), fit again
  connect(plot_, &QCustomPlot::afterLayout, this, [this] {
    // a legend wider than most of a narrow plot area covers the value axis' ticks and the
    // traces (the key and hammer legend with larger text): it goes below while that lasts
    // (not while a picture is drawn: its layout at the picture's size would move the legend of
    // the plot on screen)
    if (!rendering_ && place_legend_for_width()) {
      fit_values();
      request_replot();
      return;
    }
    // from the overhead this layout shows, once this replot is over: a new minimum resizes the
    // panel at once, and a replot asked for inside this one would be dropped, leaving the old
    // layout painted at the new size
    if (!rendering_) schedule_minimum_height();
    fit_y_label(!rendering_);                                      // a picture at its own size too
    if (plot_->axisRect()->height() == fitted_height_px_) return;  // the same: no new replot
    fit_values();
    request_replot();
  });

  connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
          [this](const QCPRange& range) {
            if (!setting_range_) emit userChangedTimeRange(range.lower, range.upper);
          });
  connect(plot_, &QCustomPlot::beforeReplot, this, &PlotPanel::align_marker_labels);
  connect(plot_, &QCustomPlot::afterReplot, this, [this] { emit replotted(plot_->replotTime()); });
  connect(plot_, &QCustomPlot::mousePress, this,
          [this](QMouseEvent* event) { press_position_ = event->pos(); });
  connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent* event) {
    // a click (not a drag) places a cursor: left A, right B
    if (!cursors_enabled_ || (event->pos() - press_position_).manhattanLength() > 3) return;
    const int which = event->button() == Qt::RightButton ? 1 : 0;
    set_cursor(which, plot_->xAxis->pixelToCoord(event->pos().x()));
  });
}

PlotPanel::~PlotPanel() = default;

int PlotPanel::add_series(const QString& label, const QString& column, const QColor& colour) {
  QCPGraph* graph = plot_->addGraph();
  graph->setName(label);
  graph->setPen(QPen(colour, 2.0));
  graph->setAdaptiveSampling(true);
  series_.push_back({graph, label, column});
  // many series: the legend wraps into rows of three, under the plot, where it covers no data
  // (inside, two rows of it hid the peaks of the contact forces)
  plot_->legend->setWrap(series_count() > 4 ? 3 : 0);
  plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);  // re-arranged with the wrap
  if (series_count() > 4) move_legend_below();
  return series_count() - 1;
}

QString PlotPanel::series_label(int series) const {
  return series_[series].label;
}

void PlotPanel::append(int series, double t, double value) {
  series_[series].graph->addData(t, value);
}

void PlotPanel::set_data(int series, const std::vector<double>& t,
                         const std::vector<double>& values) {
  series_[series].graph->setData(QVector<double>(t.begin(), t.end()),
                                 QVector<double>(values.begin(), values.end()), true);
}

void PlotPanel::clear_data() {
  for (Series& s : series_) s.graph->data()->clear();
  for (auto& c : cursors_) c.reset();
  update_cursor_items();
}

void PlotPanel::remove_before(double t) {
  for (Series& s : series_) s.graph->data()->removeBefore(t);
}

std::size_t PlotPanel::point_count(int series) const {
  return static_cast<std::size_t>(series_[series].graph->data()->size());
}

void PlotPanel::set_x_range(double lo, double hi) {
  setting_range_ = true;
  plot_->xAxis->setRange(lo, hi);
  setting_range_ = false;
}

std::pair<double, double> PlotPanel::x_range() const {
  return {plot_->xAxis->range().lower, plot_->xAxis->range().upper};
}

std::pair<double, double> PlotPanel::value_range() const {
  return {plot_->yAxis->range().lower, plot_->yAxis->range().upper};
}

void PlotPanel::apply_fonts() {
  // from the widget's font (the application's, larger for a class: View menu), 9 pt at least
  QFont axis_font = font();
  axis_font.setPointSizeF(std::max(9.0, axis_font.pointSizeF()));
  QFont label_font = axis_font;
  label_font.setBold(true);
  QFont legend_font = axis_font;
  legend_font.setPointSizeF(axis_font.pointSizeF() - 0.5);
  title_element_->setFont(label_font);
  plot_->legend->setFont(legend_font);
  for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) {
    axis->setLabelFont(label_font);
    axis->setTickLabelFont(axis_font);
  }
  update_minimum_height();
  readout_->setFont(axis_font);
  if (readout_row_) readout_row_->setFont(axis_font);
  for (auto& [line, text] : markers_) text->setFont(axis_font);
}

double PlotPanel::tick_label_point_size() const {
  return plot_->xAxis->tickLabelFont().pointSizeF();
}

void PlotPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  if (cursors_enabled_ && cursors_[0] && cursors_[1]) {
    update_cursor_items();
    request_replot();
  }
}

void PlotPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() != QEvent::FontChange) return;
  apply_fonts();
  fit_values();  // the legend's height, and so its headroom, changed with the font
  request_replot();
}

void PlotPanel::fit_values() {
  const double height_px = plot_->axisRect()->height(), width_px = plot_->axisRect()->width();
  fitted_height_px_ = static_cast<int>(height_px);  // fitted for this height, data or not
  // the data's own value range within the time range shown (not the axis range: a flat line
  // must not inherit, and keep growing, the padded range of the previous fit)
  bool any = false;
  QCPRange range;
  for (Series& s : series_) {
    bool found = false;
    const QCPRange r = s.graph->getValueRange(found, QCP::sdBoth, plot_->xAxis->range());
    if (!found) continue;
    range = any ? QCPRange(std::min(range.lower, r.lower), std::max(range.upper, r.upper)) : r;
    any = true;
  }
  if (!any) return;
  // categories compare sizes (errors, frequencies, changes): the axis shows zero
  if (categories_ > 0) range = QCPRange(std::min(range.lower, 0.0), std::max(range.upper, 0.0));
  // a flat line gets a visible band around it, and an almost flat one at least the minimum span
  const double span = std::max(minimum_value_span_, 1e-9);
  if (range.size() < span) {
    const double half = (minimum_value_span_ > 0.0 ? minimum_value_span_ : 2.0) / 2.0;
    const bool never_negative = range.lower >= 0.0;
    range = QCPRange(range.center() - half, range.center() + half);
    // data that never go below zero (a force at rest, a gap) keep a band that does not either
    if (never_negative && range.lower < 0.0) range = QCPRange(0.0, range.size());
  }
  // headroom at the top for the legend (none when it is under the plot): as many value units as
  // the legend's height in pixels takes of the plot area, so that no trace runs under it; before
  // the plot has its size, 30 % of the range per legend row
  const double pad = 0.08 * range.size();
  const double shown = range.size() + 2.0 * pad;
  double headroom = 0.0;
  // the band at the top the data keep out of: the inset legend's, and the marker labels' (one
  // text row each from 1.5 rows down, add_marker), which had covered the points at the top of a
  // sweep's "strikes per cycle"
  double top_px = 0.0;
  int top_rows = 0;  // before the plot has its size: 30 % of the range per row
  if (!legend_below_) {
    constexpr int kLegendMarginPx = 8;  // the inset's gap to the frame, and some air
    top_px = plot_->legend->minimumOuterSizeHint().height() + kLegendMarginPx;
    top_rows = (series_count() + 2) / 3;
  }
  if (!markers_.empty()) {
    const double line_px = QFontMetrics(readout_->font()).height() + 4.0;
    const int label_rows = static_cast<int>(std::min<std::size_t>(markers_.size(), 5));
    top_px = std::max(top_px, line_px * (1.5 + label_rows) + 2.0);
    top_rows = std::max(top_rows, label_rows + 1);
  }
  if (top_px > 0.0)
    headroom = height_px > 2.0 * top_px ? shown * top_px / (height_px - top_px)
                                        : 0.3 * top_rows * range.size();
  plot_->yAxis->setRange(range.lower - pad, range.upper + pad + headroom);
  // as many ticks as the plot's size gives room for: their labels must not run together on a
  // short or narrow plot. A label is a line high; along x its width follows the step the
  // ticker will take (0–5 ms in 0.5 ms steps is ten labels "0.0035" wide, which ran together)
  if (height_px > 0.0 && width_px > 0.0) {
    const QFontMetricsF ticks(plot_->xAxis->tickLabelFont());
    plot_->yAxis->ticker()->setTickCount(
        std::clamp(static_cast<int>(height_px / (2.0 * ticks.height())), 2, 6));
    plot_->xAxis->ticker()->setTickCount(x_tick_count(width_px, ticks));
  }
}

int PlotPanel::x_tick_count(double width_px, const QFontMetricsF& ticks) const {
  const QCPRange range = plot_->xAxis->range();
  if (categories_ > 0 || !(range.size() > 0.0)) return std::clamp(int(width_px / 60.0), 2, 8);
  const double digit_px = ticks.horizontalAdvance(QStringLiteral("0"));
  const double magnitude = std::max(std::abs(range.lower), std::abs(range.upper));
  const int integer_digits = magnitude >= 1.0 ? int(std::floor(std::log10(magnitude))) + 1 : 1;
  for (int count = 8; count > 2; --count) {
    // the step the ticker rounds range/count to (QCPAxisTicker's readability strategy: the
    // nearest of 1, 2, 2.5, 5 and 10 times a power of ten), and the decimals its labels need
    const double raw = range.size() / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (const double mantissa : {2.0, 2.5, 5.0, 10.0})
      if (std::abs(raw / power - mantissa) < std::abs(raw / power - step / power))
        step = mantissa * power;
    const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)) +
                                         (std::abs(step / power - 2.5) < 1e-9 ? 1 : 0));
    const double label_px = (integer_digits + decimals + (decimals > 0 ? 1 : 0)) * digit_px;
    const int labels = int(std::floor(range.size() / step)) + 1;
    if (labels * (label_px + 2.5 * digit_px) <= width_px) return count;  // a gap of 2.5 digits
  }
  return 2;
}

void PlotPanel::fit_all() {
  setting_range_ = true;
  plot_->rescaleAxes();
  if (categories_ > 0) {
    plot_->xAxis->setRange(-0.5, double(categories_) - 0.5);
  } else if (points_only_) {  // whole markers at both ends
    const QCPRange r = plot_->xAxis->range();
    const double pad = std::max(0.02 * r.size(), 1e-9);
    plot_->xAxis->setRange(r.lower - pad, r.upper + pad);
  }
  setting_range_ = false;
  fit_values();
}

void PlotPanel::request_replot() {
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PlotPanel::set_cursors_enabled(bool enabled) {
  cursors_enabled_ = enabled;
  update_cursor_items();
  request_replot();
}

void PlotPanel::set_cursor(int which, double t) {
  cursors_[which] = t;
  update_cursor_items();
  request_replot();
}

std::optional<double> PlotPanel::cursor(int which) const {
  return cursors_[which];
}

std::optional<double> PlotPanel::value_at(int series, double t) const {
  const auto data = series_[series].graph->data();
  if (data->isEmpty() || t < data->constBegin()->key || t > (data->constEnd() - 1)->key)
    return std::nullopt;
  auto after = data->findBegin(t, false);
  if (after == data->constEnd()) return (data->constEnd() - 1)->value;
  if (after->key <= t || after == data->constBegin()) return after->value;
  const auto before = after - 1;
  const double w = (t - before->key) / (after->key - before->key);
  return before->value + w * (after->value - before->value);
}

std::optional<double> PlotPanel::sample_at(int series, double x, int rank) const {
  const auto data = series_[series].graph->data();
  auto it = data->findBegin(x, false);
  if (it == data->constEnd() || it->key != x) return value_at(series, x);
  for (int r = 0; r < rank; ++r) {
    if (it + 1 == data->constEnd() || (it + 1)->key != x) return std::nullopt;  // none of that rank
    ++it;
  }
  return it->value;
}

QString PlotPanel::cursor_readout() const {
  if (!cursors_[0] || !cursors_[1]) return {};
  const double a = *cursors_[0], b = *cursors_[1];
  QStringList lines;
  const double k = x_readout_scale_;
  lines << tr("A %1 %4  B %2 %4  Δ%5 = %3 %4")
               .arg(a * k, 0, 'f', 2)
               .arg(b * k, 0, 'f', 2)
               .arg((b - a) * k, 0, 'f', 2)
               .arg(x_readout_unit_)
               .arg(x_symbol_);
  // the changes to the hundredth of the unit (deg, mm, N, m/s), a fraction to the thousandth: no
  // "6.858e-16 deg" for two frames at rest, no "-0.00"
  QStringList changes;
  for (int s = 0; s < series_count(); ++s) {
    const auto va = value_at(s, a), vb = value_at(s, b);
    if (!va || !vb) continue;
    const QString unit = unit_of(series_[s].column);
    const int decimals = unit.isEmpty() || unit == "fraction" ? 3 : 2;
    const double change = *vb - *va;
    changes << tr("Δ %1 = %2 %3")
                   .arg(series_[s].label)
                   .arg(std::abs(change) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : change, 0, 'f',
                        decimals)
                   .arg(unit);
  }
  // on as few lines as the plot's width takes (a line each squeezed a short plot's data into a
  // strip): the cursors' times, then the changes, side by side where they fit
  const QFontMetricsF metrics(plot_->xAxis->tickLabelFont());
  const double room = std::max(100, (readout_width_px_ > 0 ? readout_width_px_ : width()) - 20);
  for (const QString& change : changes) {
    const QString joined = lines.back() + QStringLiteral("   ") + change;
    if (metrics.horizontalAdvance(joined) <= room)
      lines.back() = joined;
    else
      lines << change;
  }
  return lines.join('\n');
}

void PlotPanel::update_cursor_items(bool for_export) {
  for (int i = 0; i < 2; ++i) {
    const bool shown = cursors_enabled_ && cursors_[i].has_value();
    cursor_lines_[i]->setVisible(shown);
    if (shown) {
      cursor_lines_[i]->point1->setCoords(*cursors_[i], 0.0);
      cursor_lines_[i]->point2->setCoords(*cursors_[i], 1.0);
    }
  }
  QString text = cursors_enabled_ ? cursor_readout() : QString();
  if (text.isEmpty() && cursors_enabled_ && (cursors_[0] || cursors_[1])) {
    const int which = cursors_[0] ? 0 : 1;
    text = tr("%1 at %2 %3")
               .arg(kCursorNames[which])
               .arg(*cursors_[which] * x_readout_scale_, 0, 'f', 2)
               .arg(x_readout_unit_);
    if (!for_export) text += " " + tr("(click: A, right click: B)");
  }
  // the readout in a row of its own under the title, while there is one: inside the plot it ran
  // into the legend and covered data
  if (text.isEmpty()) {
    if (readout_row_) {
      plot_->plotLayout()->remove(readout_row_);  // deletes it
      plot_->plotLayout()->simplify();
      readout_row_ = nullptr;
    }
    return;
  }
  if (!readout_row_) {
    plot_->plotLayout()->insertRow(1);
    readout_row_ = new QCPTextElement(plot_, QString(), readout_->font());
    readout_row_->setTextFlags(Qt::AlignLeft | Qt::AlignVCenter);
    readout_row_->setTextColor(QColor(40, 40, 40));
    readout_row_->setMargins(QMargins(8, 0, 8, 2));
    plot_->plotLayout()->addElement(1, 0, readout_row_);
  }
  readout_row_->setText(text);
}

void PlotPanel::align_marker_labels() {
  // a marker's label sits on the side of its line that has more room (never cut at the edge)
  const double middle = plot_->xAxis->range().center();
  for (auto& [line, text] : markers_)
    text->setPositionAlignment(
        (line->point1->coords().x() > middle ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
}

void PlotPanel::render(QPaintDevice& device, const std::vector<std::pair<PlotPanel*, QRect>>& plots,
                       double scale) {
  QCPPainter painter(&device);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setMode(QCPPainter::pmNoCaching);  // full polylines (not the screen's fast segments)
  painter.fillRect(QRect(0, 0, device.width(), device.height()), Qt::white);
  painter.scale(scale, scale);
  for (const auto& [panel, rect] : plots) {
    panel->readout_width_px_ = rect.width();  // the readout wraps to the picture's width
    panel->update_cursor_items(true);
    panel->readout_width_px_ = -1;
    panel->align_marker_labels();  // drawing to a file replots nothing: its range as it is now
    panel->time_mark_line_->setVisible(false);
    painter.save();
    painter.translate(rect.topLeft());
    panel->rendering_ = true;
    const QString screen_y_label = panel->plot_->yAxis->label();  // the picture fits its own
    // a first pass, drawn nowhere, lays the plot out at the picture's size, where the legend's
    // headroom is refitted (the afterLayout handler); the ticks of the pass drawn follow that
    // range (made for the range before it, they stood above the plot area, into the title's row)
    QImage nowhere(1, 1, QImage::Format_ARGB32_Premultiplied);
    QCPPainter layout_pass(&nowhere);
    panel->plot_->toPainter(&layout_pass, rect.width(), rect.height());
    layout_pass.end();
    panel->plot_->toPainter(&painter, rect.width(), rect.height());
    panel->plot_->yAxis->setLabel(screen_y_label);
    panel->rendering_ = false;
    painter.restore();
    panel->time_mark_line_->setVisible(panel->time_mark_.has_value());
    panel->update_cursor_items();  // the screen's readout again
  }
}

void PlotPanel::set_time_mark(std::optional<double> t) {
  time_mark_ = t;
  time_mark_line_->setVisible(t.has_value());
  if (t) {
    time_mark_line_->point1->setCoords(*t, 0.0);
    time_mark_line_->point2->setCoords(*t, 1.0);
  }
}

void PlotPanel::set_x_axis(const QString& title, const QString& column, const QString& symbol,
                           const QString& readout_unit, double readout_scale) {
  plot_->xAxis->setLabel(title);
  x_symbol_ = symbol;
  x_column_ = column;
  x_readout_unit_ = readout_unit;
  x_readout_scale_ = readout_scale;
  request_replot();
}

void PlotPanel::set_x_categories(const std::vector<QString>& names) {
  auto ticker = QSharedPointer<QCPAxisTickerText>::create();
  for (std::size_t i = 0; i < names.size(); ++i) ticker->addTick(double(i), names[i]);
  plot_->xAxis->setTicker(ticker);
  const bool rotated = names.size() > 4;
  plot_->xAxis->setTickLabelRotation(rotated ? 30 : 0);
  if (rotated) {
    // a rotated label runs right of its tick; QCustomPlot drops a label that would cross the
    // widget's edge, so the last category needs room on the right
    const QFontMetrics metrics(plot_->xAxis->tickLabelFont());
    const int run = int(std::ceil(metrics.horizontalAdvance(names.back()) * std::cos(M_PI / 6)));
    plot_->axisRect()->setMinimumMargins(QMargins(0, 0, run, 0));
  }
  categories_ = names.size();
  category_names_ = names;
  // a few points often sit right where an inset legend would be: the legend goes under the plot
  move_legend_below();
}

void PlotPanel::move_legend_below(bool for_good) {
  legend_below_for_good_ = legend_below_for_good_ || for_good;
  if (legend_below_ || !plot_->axisRect()->insetLayout()->take(plot_->legend)) return;
  plot_->axisRect()->insetLayout()->simplify();
  legend_margins_inside_ = plot_->legend->margins();
  const int row = plot_->plotLayout()->rowCount();
  plot_->plotLayout()->addElement(row, 0, plot_->legend);
  plot_->plotLayout()->setRowStretchFactor(row, 0.001);
  // a short panel squeezes it first; its rows apart and the last one's descenders inside (with
  // no spacing and a 1 px margin the "j" of "jack–knuckle" touched "backcheck" below it and the
  // "g" of "string" was cut at 1366x768)
  const int descent = QFontMetrics(plot_->legend->font()).descent();
  plot_->legend->setMargins(QMargins(6, 0, 6, 1 + descent));
  plot_->legend->setRowSpacing(2);
  plot_->legend->setBorderPen(Qt::NoPen);
  legend_below_ = true;
  schedule_minimum_height();  // (called from a layout: see the afterLayout handler)
}

void PlotPanel::update_minimum_height() {
  // room for the data between the title, the ticks, the axis title and a legend below: about
  // eight lines of the text at least (120 px at 9 pt), so that larger text does not squeeze the
  // traces into a strip (the window's splitter keeps the plots this tall); and what the panel
  // lays out around the data (the plot's title, the axes' ticks and titles, a legend below) with
  // 2.5 lines of tick labels of data: the upright's plots in the class's larger text had their
  // legends cut off. No more: the action view above them is what the class looks at.
  const QFontMetricsF ticks(plot_->xAxis->tickLabelFont());
  const QFontMetricsF titles(plot_->xAxis->labelFont());
  const double data = 2.5 * ticks.height();
  // around the data: as laid out, once it has been (the plot's margins follow the tick labels),
  // else the plot's title, the x ticks and title, a legend below and some margin
  // (as laid out, a legend squeezed by a short panel reads short: never less than its own need)
  const int laid_out = plot_->axisRect()->height();
  const double needed = 2.0 * titles.height() + ticks.height() + legend_height_below() + 24.0;
  const double around =
      laid_out > 0 && height() > laid_out ? std::max<double>(height() - laid_out, needed) : needed;
  // and never less than the plot's own layout needs at its smallest (title, axis rect with its
  // ticks, a wrapped legend below): under it the legend's rows were drawn cut (the contact
  // forces' two rows at 1366x768)
  // (once laid out: before, the plot widget has no size of its own yet)
  const QMargins axis_margins = plot_->axisRect()->margins();
  const int layout_minimum =
      laid_out <= 0
          ? 0
          // (public on the layout element, protected on the text element)
          : static_cast<const QCPLayoutElement*>(title_element_)->minimumOuterSizeHint().height() +
                axis_margins.top() + axis_margins.bottom() +
                std::max(static_cast<int>(std::ceil(data)),
                         plot_->axisRect()->minimumSize().height()) +
                legend_height_below() +
                plot_->plotLayout()->rowSpacing() * (plot_->plotLayout()->rowCount() - 1) +
                (height() - plot_->height());
  setMinimumHeight(std::max({kMinimumHeightPx, static_cast<int>(std::ceil(8.0 * ticks.height())),
                             static_cast<int>(std::ceil(around + data)), layout_minimum}));
}

void PlotPanel::schedule_minimum_height() {
  QMetaObject::invokeMethod(
      this,
      [this] {
        const int before = height();
        update_minimum_height();
        if (height() != before) request_replot();  // laid out again at the new height
      },
      Qt::QueuedConnection);
}

void PlotPanel::fit_y_label(bool replot) {
  // the y title is drawn turned along the data; on a plot area shorter than it (a short panel,
  // larger text) it ran into the plot's title: the unit alone then ("angle (deg)" → "deg"), as
  // the plot's title names the quantity. It may reach a line past the area (the corner below it
  // is free of x tick labels).
  const QFontMetricsF metrics(plot_->yAxis->labelFont());
  const double room =
      plot_->axisRect()->height() + QFontMetricsF(plot_->xAxis->tickLabelFont()).height();
  QString label = y_title_;
  const qsizetype open = y_title_.lastIndexOf('('), close = y_title_.lastIndexOf(')');
  if (metrics.horizontalAdvance(y_title_) > room && open >= 0 && close > open + 1)
    label = y_title_.mid(open + 1, close - open - 1);
  if (plot_->yAxis->label() != label) {
    plot_->yAxis->setLabel(label);
    if (replot) request_replot();
  }
}

QString PlotPanel::y_label_shown() const {
  return plot_->yAxis->label();
}

int PlotPanel::legend_height_below() const {
  return legend_below_ ? plot_->legend->minimumOuterSizeHint().height() : 0;
}

QRect PlotPanel::legend_rect() const {
  return plot_->legend->outerRect();
}

QRect PlotPanel::plot_area_rect() const {
  return plot_->axisRect()->rect();
}

void PlotPanel::move_legend_inside() {
  if (!legend_below_ || legend_below_for_good_ || !plot_->plotLayout()->take(plot_->legend)) return;
  plot_->plotLayout()->simplify();  // the legend's row goes
  plot_->axisRect()->insetLayout()->addElement(plot_->legend, Qt::AlignRight | Qt::AlignTop);
  plot_->legend->setMargins(legend_margins_inside_);
  plot_->legend->setRowSpacing(0);
  plot_->legend->setBorderPen(QPen(QColor(200, 200, 200)));
  plot_->legend->setWrap(0);  // one row, inside (at most four series are ever moved back)
  plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
  legend_below_ = false;
  schedule_minimum_height();
}

bool PlotPanel::place_legend_for_width() {
  bool changed = false;
  if (!legend_below_for_good_) {
    // inside while the legend on one row takes at most this share of the plot area's width;
    // back inside only below a smaller one, so that a width at the edge does not move it to and
    // fro (its one-row width: below, it may be wrapped into more rows)
    constexpr double kMostOfTheWidth = 0.7, kBackInside = 0.6;
    const double legend_px = legend_row_width();
    const double area_px = plot_->axisRect()->width();
    if (area_px <= 0) return false;
    if (!legend_below_ && legend_px > kMostOfTheWidth * area_px) {
      move_legend_below(false);
      changed = true;
    } else if (legend_below_ && legend_px < kBackInside * area_px) {
      move_legend_inside();
      changed = !legend_below_;
    }
  }
  if (legend_below_) changed = wrap_legend_to_width() || changed;
  return changed;
}

double PlotPanel::legend_row_width() const {
  const int n = plot_->legend->itemCount();
  double width = plot_->legend->margins().left() + plot_->legend->margins().right();
  for (int i = 0; i < n; ++i)
    width += plot_->legend->item(i)->minimumOuterSizeHint().width() +
             (i > 0 ? plot_->legend->columnSpacing() : 0);
  return width;
}

bool PlotPanel::wrap_legend_to_width() {
  // under the plot the legend takes as many columns as the panel's width holds (four long
  // names on one row had been cut to "with both par", "without the bridle st"), at most three
  // for many series (rows of three, add_series)
  const int n = plot_->legend->itemCount();
  if (n <= 1) return false;
  double widest = 0.0;
  for (int i = 0; i < n; ++i)
    widest = std::max(widest,
                      static_cast<double>(plot_->legend->item(i)->minimumOuterSizeHint().width()));
  const double room = width() - plot_->legend->margins().left() - plot_->legend->margins().right();
  int columns = legend_row_width() <= width()
                    ? n
                    : std::clamp(static_cast<int>((room + plot_->legend->columnSpacing()) /
                                                  (widest + plot_->legend->columnSpacing())),
                                 1, n);
  if (n > 4) columns = std::min(columns, 3);
  const int wrap = columns >= n ? 0 : columns;
  if (plot_->legend->wrap() == wrap) return false;
  plot_->legend->setWrap(wrap);
  plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);  // re-arranged with the wrap
  schedule_minimum_height();  // a legend of more rows needs more height
  return true;
}

void PlotPanel::set_points_only(int series) {
  QCPGraph* graph = series_.at(series).graph;
  graph->setLineStyle(QCPGraph::lsNone);
  graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 6));
  points_only_ = true;
}

void PlotPanel::add_marker(double x, const QString& label) {
  const QColor colour(120, 120, 120);
  auto* line = new QCPItemStraightLine(plot_);
  line->setPen(QPen(colour, 1.5, Qt::DashDotLine));
  line->point1->setCoords(x, 0.0);
  line->point2->setCoords(x, 1.0);
  auto* text = new QCPItemText(plot_);
  // y in pixels below the top of the plot area (the readout's anchor sits there): under the
  // legend's first row, one text line further down for each earlier marker
  text->position->setTypeX(QCPItemPosition::ptPlotCoords);
  text->position->setParentAnchorY(readout_->position);
  text->position->setTypeY(QCPItemPosition::ptAbsolute);
  const double line_px = QFontMetrics(readout_->font()).height() + 4.0;
  text->position->setCoords(x, line_px * (1.5 + double(markers_.size() % 5)));
  text->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
  text->setText(label);
  text->setFont(readout_->font());
  text->setColor(colour.darker(160));
  text->setBrush(QColor(255, 255, 255, 200));
  text->setPadding(QMargins(3, 1, 3, 1));
  markers_.emplace_back(line, text);
  request_replot();
}

CsvTable PlotPanel::visible_table() const {
  CsvTable table;
  table.columns.push_back(x_column_.toStdString());
  for (const Series& s : series_) table.columns.push_back(s.column.toStdString());
  // named positions: the CSV's numbers say which name each is ("0 hammer blow; 1 key dip; …")
  if (!category_names_.empty()) {
    QStringList names;
    for (std::size_t i = 0; i < category_names_.size(); ++i)
      names << QStringLiteral("%1 %2").arg(i).arg(category_names_[i]);
    table.metadata[x_column_.toStdString()] = names.join("; ").toStdString();
  }
  if (series_.empty()) return table;
  const QCPRange range = plot_->xAxis->range();
  const auto base = series_.front().graph->data();
  // a row per sample of the first series, with its own value (a frequency held for several
  // cycles has a sample per cycle at one x: the first cycle's value had been written for each);
  // another series at that x gives its sample of the same rank there (none of that rank: the row
  // is left out), or else its interpolation
  for (auto it = base->findBegin(range.lower, false); it != base->constEnd(); ++it) {
    if (it->key > range.upper) break;
    int rank = 0;  // how many samples before this one have its x
    for (auto before = it; before != base->constBegin() && (before - 1)->key == it->key; --before)
      ++rank;
    std::vector<double> row{it->key, it->value};
    for (int s = 1; s < series_count(); ++s) {
      const auto v = sample_at(s, it->key, rank);
      if (!v) break;
      row.push_back(*v);
    }
    // rows where a series has no value are left out (every value written is a sample)
    if (row.size() == table.columns.size()) table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace pat::ui

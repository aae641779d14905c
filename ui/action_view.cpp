#include "action_view.h"

#include <QHash>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>

#include "action_style.h"
#include "label_placer.h"
#include "setting_names.h"

namespace pat::ui {
namespace {

constexpr double kKeyGrabRadiusPx = 24.0;
// how far beyond the checking close-up's region (a share of the view's width) parts are named
constexpr double kCheckingNamesReach = 0.125;
// room kept free of labels around the knuckle or butt and the jack top (px)
constexpr double kEscapementRoomPx = 4.0;
// a contact force below this (N) is drawn as no contact at all: no arrow, and the readout's gap
// is not called "felt on the string"
constexpr double kShownForceN = 1e-3;
// the named points of the bodies are a group of their own (LabelPlacer::NamedStyle::group)
constexpr int kBodyGroup = 1;

// Distance (px) from p to the segment from a to b.
double distance_to_segment(const QPointF& p, const QPointF& a, const QPointF& b) {
  const QPointF ab = b - a;
  const double length2 = QPointF::dotProduct(ab, ab);
  const double u =
      length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return QLineF(p, a + u * ab).length();
}

// A point well inside a polygon (screen): of a 20 × 20 grid over its bounds, the one inside it
// and inside `within` that lies farthest from its edges (depth counted up to kDeepEnoughPx: of
// equally deep points in a long bar, the one nearest its middle); empty when none does.
std::optional<QPointF> deepest_point(const QPolygonF& polygon, const QRectF& within) {
  if (polygon.size() < 3) return std::nullopt;
  const QRectF bounds = polygon.boundingRect();
  constexpr int kGrid = 20;
  constexpr double kDeepEnoughPx = 8.0, kPerPxFromMiddle = 0.02;
  QPointF middle(0, 0);
  for (const QPointF& p : polygon) middle += p;
  middle /= static_cast<double>(polygon.size());
  std::optional<QPointF> best;
  double best_depth = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const QPointF p(bounds.left() + bounds.width() * (i + 0.5) / kGrid,
                      bounds.top() + bounds.height() * (j + 0.5) / kGrid);
      if (!within.contains(p) || !polygon.containsPoint(p, Qt::OddEvenFill)) continue;
      double depth = std::numeric_limits<double>::infinity();
      for (qsizetype k = 0; k < polygon.size(); ++k)
        depth =
            std::min(depth, distance_to_segment(p, polygon[k], polygon[(k + 1) % polygon.size()]));
      const double score =
          std::min(depth, kDeepEnoughPx) - kPerPxFromMiddle * QLineF(p, middle).length();
      if (score > best_depth) {
        best_depth = score;
        best = p;
      }
    }
  }
  return best;
}

// Where the hammer meets the string: the strike point at rest carried to the string plane (m).
Vec2 string_point_struck(const ActionLandmarks& marks) {
  return marks.strike_point -
         marks.string_normal.dot(marks.strike_point - marks.string_point) * marks.string_normal;
}

// a close-up's labels grow with its scale, but stay small enough for this many lines of them to
// fit the view's height below the readout
constexpr double kLabelLinesInView = 14.0;
// a part named by a label in a close-up lies at least this far inside the view (px)
constexpr double kNamedPointMarginPx = 4.0;
/// The time and gap readout's font: the view's, 3 pt larger, bold.
QFont readout_font(QFont font) {
  font.setPointSizeF(font.pointSizeF() + 3);
  font.setBold(true);
  return font;
}
/// The readout's band along the top (px), from the readout font's metrics: its line and some
/// air (34 px at a 9 pt font).
double readout_band_px(const QFontMetricsF& readout_metrics) {
  return readout_metrics.height() + 14.0;
}

// text on a translucent white box, readable over any part (cheaper than a stroked text path)
void draw_label(QPainter& painter, const QPointF& at, const QString& text, const QColor& colour) {
  const QFontMetricsF metrics(painter.font());
  const QRectF box = LabelPlacer::padded_box(at, metrics.horizontalAdvance(text), metrics);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(255, 255, 255, 190));
  painter.drawRoundedRect(box, 3, 3);
  painter.setPen(colour);
  painter.drawText(at, text);
}

void draw_arrow(QPainter& painter, const QPointF& from, const QPointF& to, const QColor& colour) {
  painter.setPen(QPen(colour, 3.0, Qt::SolidLine, Qt::RoundCap));
  painter.drawLine(from, to);
  const QPointF d = to - from;
  const double length = std::hypot(d.x(), d.y());
  if (length < 1.0) return;
  const QPointF u = d / length, n(-u.y(), u.x());
  const double head = std::min(10.0, length * 0.5);
  QPolygonF tip;
  tip << to << to - head * u + 0.5 * head * n << to - head * u - 0.5 * head * n;
  painter.setPen(Qt::NoPen);
  painter.setBrush(colour);
  painter.drawPolygon(tip);
}

// Pixels per metre at which the whole action fills the view at the window's usual size.
constexpr double kWholeActionScale = 1500.0;

/// The point of a closed outline polygon (body rest coordinates, m) nearest to `p`.
Vec2 nearest_outline_point(const std::vector<Vec2>& outline, const Vec2& p) {
  Vec2 best = outline.empty() ? p : outline.front();
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2& a = outline[i];
    const Vec2 ab = outline[(i + 1) % outline.size()] - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-18), 0.0, 1.0);
    const Vec2 q = a + t * ab;
    if ((q - p).squaredNorm() < (best - p).squaredNorm()) best = q;
  }
  return best;
}
}  // namespace

ActionView::ActionView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(320, 240);
  setMouseTracking(true);
  setFocusPolicy(Qt::ClickFocus);
  setAccessibleName(tr("Piano action"));
  setAccessibleDescription(
      tr("The action drawn as it moves; drag the key front down to play the key, the space bar "
         "strikes a blow"));
  setToolTip(
      tr("Wheel: zoom · right or middle drag: pan · double click: fit\n"
         "View menu: close-ups of the escapement (Ctrl+2) and the checking (Ctrl+3)\n"
         "Left drag on the key front (the ring): play the key"));
}

void ActionView::show_frame(const Frame& frame) {
  if (frame.model != model_) {
    model_ = frame.model;
    dynamics_ = std::make_unique<ActionDynamics>(*model_, nullptr);
    const Body& key = model_->bodies[model_->landmarks.key];
    key_arm_m_ = std::max(1e-3, std::abs(model_->landmarks.key_front.x() - key.pivot.x()));
  }
  frame_ = frame;
  dynamics_->evaluate(frame.t, frame.q, frame.v, reading_);
  if (!fitted_) fit();
  update();
}

void ActionView::reset_view() {
  fitted_ = false;
  label_offsets_.clear();  // another action's places
  frame_.reset();
  model_.reset();
  dynamics_.reset();
  update();
}

void ActionView::set_labels_visible(bool visible) {
  labels_ = visible;
  update();
}

void ActionView::set_measurements_visible(bool visible) {
  measurements_ = visible;
  update();
}

QTransform ActionView::model_to_widget() const {
  return QTransform(scale_, 0, 0, -scale_, offset_.x(), offset_.y());
}

QPointF ActionView::to_screen(const Vec2& p) const {
  return {offset_.x() + scale_ * p.x(), offset_.y() - scale_ * p.y()};
}

Vec2 ActionView::to_model(const QPointF& p) const {
  return {(p.x() - offset_.x()) / scale_, (offset_.y() - p.y()) / scale_};
}

Vec2 ActionView::body_point(int body, const Vec2& rest_point) {
  return dynamics_->point_position(body, rest_point, frame_->q);
}

const std::optional<Vec2>& ActionView::inner_point(int body) {
  if (inner_points_model_ != model_) {  // a new model (an adjuster moved, another action)
    inner_points_model_ = model_;
    inner_points_.assign(model_->bodies.size(), std::nullopt);
    // found in the rest outline drawn at the whole action's scale (px), where the depth and
    // the pull to the middle are weighed
    for (std::size_t b = 0; b < model_->bodies.size(); ++b) {
      QPolygonF outline;
      for (const Vec2& p : model_->bodies[b].outline)
        outline << QPointF(p.x(), -p.y()) * kWholeActionScale;
      if (const auto at = deepest_point(outline, outline.boundingRect()))
        inner_points_[b] = Vec2(at->x(), -at->y()) / kWholeActionScale;
    }
  }
  return inner_points_[body];
}

std::optional<QPointF> ActionView::key_front_on_screen() const {
  if (!frame_ || !dynamics_) return std::nullopt;
  auto* self = const_cast<ActionView*>(this);
  return to_screen(self->body_point(model_->landmarks.key, model_->landmarks.key_front));
}

double ActionView::rest_aspect(const ActionModel& model) {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  auto include = [&](const Vec2& p) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  };
  for (const Body& b : model.bodies)
    for (const Vec2& p : b.outline) include(p);
  for (const Fixture& f : model.fixtures)
    for (const Vec2& p : f.outline) include(p);
  return x1 > x0 && y1 > y0 ? (y1 - y0) / (x1 - x0) : 0.5;
}

std::optional<ModelBox> ActionView::focus_region(const ActionModel& model, ViewFocus focus) {
  const ActionLandmarks& marks = model.landmarks;
  std::vector<int> contacts;
  if (focus == ViewFocus::escapement) contacts = {marks.escapement_contact, marks.letoff_contact};
  if (focus == ViewFocus::checking) contacts = {marks.check_contact};
  if (contacts.empty()) return std::nullopt;
  ModelBox box{Vec2::Constant(1e9), Vec2::Constant(-1e9)};
  auto include = [&](const Vec2& p, double radius) {
    box.low = box.low.cwiseMin(p - Vec2::Constant(radius));
    box.high = box.high.cwiseMax(p + Vec2::Constant(radius));
  };
  for (int c : contacts) {
    if (c < 0 || c >= static_cast<int>(model.contacts.size())) return std::nullopt;
    const Contact& contact = model.contacts[c];
    include(contact.center_a, contact.radius_a);
    if (contact.shape == ContactShape::CircleCircle) {
      include(contact.center_b, contact.radius_b);
    } else {
      include(contact.segment_start, 0.0);
      include(contact.segment_end, 0.0);
    }
  }
  if (focus == ViewFocus::escapement && marks.hammer >= 0 &&
      marks.hammer < static_cast<int>(model.bodies.size())) {
    // the hammer's centre pin: the whole butt (the upright's) or knuckle and flange (the grand's)
    // in sight, not only the face the jack pushes
    include(model.bodies[marks.hammer].pivot, 0.0);
  }
  if (focus == ViewFocus::checking) {
    // the hammer head at rest and where it meets the string (the string in sight: the catch is
    // judged by its distance from it)
    include(marks.strike_point, 0.0);
    include(string_point_struck(marks), 0.0);
  }
  // room for the parts' motion during a blow: the jack and the knuckle or butt rise several mm
  // (the region is their size at rest); the checking region already spans the hammer's travel
  const bool escapement = focus == ViewFocus::escapement;
  const Vec2 room = ((escapement ? 0.4 : 0.25) * (box.high - box.low))
                        .cwiseMax(Vec2::Constant(escapement ? 10e-3 : 6e-3));
  box.low -= room;
  box.high += room;
  return box;
}

void ActionView::set_focus(ViewFocus focus) {
  focus_ = focus;
  label_offsets_.clear();  // places found at another scale
  fitted_ = false;
  if (frame_) fit();
  update();
}

void ActionView::fit() {
  if (!frame_ || width() <= 0 || height() <= 0) return;
  std::optional<ModelBox> box = focus_region(*model_, focus_);
  double margin = 0.0;  // a close-up's region has its own room
  if (!box) {
    box = ModelBox{Vec2::Constant(1e9), Vec2::Constant(-1e9)};
    auto include = [&](const Vec2& p) {
      box->low = box->low.cwiseMin(p);
      box->high = box->high.cwiseMax(p);
    };
    // the parts where the preset draws them (the action at rest), not where they are now: a
    // refit during a blow had framed the risen hammer a little differently each time
    for (int b = 0; b < model_->dofs(); ++b)
      for (const Vec2& p : model_->bodies[b].outline) include(p);
    for (const Fixture& f : model_->fixtures)
      for (const Vec2& p : f.outline) include(p);
    margin = 0.06;
  }
  const Vec2 size = box->high - box->low;
  if (!(size.x() > 0.0 && size.y() > 0.0)) return;
  const double w = size.x() * (1 + 2 * margin), h = size.y() * (1 + 2 * margin);
  const Vec2 centre = 0.5 * (box->low + box->high);
  // below the time and gap readout drawn along the top
  const double band = readout_band_px(QFontMetricsF(readout_font(font())));
  const double usable_height = std::max(1.0, height() - band);
  scale_ = std::min(width() / w, usable_height / h);
  offset_ = QPointF(width() / 2.0 - scale_ * centre.x(),
                    band + usable_height / 2.0 + scale_ * centre.y());
  fitted_ = true;
}

void ActionView::resizeEvent(QResizeEvent*) {
  if (frame_) fit();
}

void ActionView::paintEvent(QPaintEvent*) {
  {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), QColor(250, 250, 246));
    if (!frame_) {
      painter.setPen(QColor(90, 90, 90));
      painter.drawText(rect(), Qt::AlignCenter, tr("Starting the simulation…"));
      return;
    }
    paint_frame(painter);
  }
  emit framePainted();
}

void ActionView::paint_frame(QPainter& painter) {
  const ActionModel& model = *model_;
  drawn_labels_.clear();
  drawn_label_details_.clear();
  QFont label_font = font();
  // labels grow in a close-up (about 1.5 px/mm when the whole action fits a 770 px view), up to
  // half as large again, so that they stay readable from the back of a classroom
  const double zoom = std::clamp(std::sqrt(scale_ / kWholeActionScale), 1.0, 1.5);
  const double unzoomed_pt = std::max(9.0, label_font.pointSizeF());
  label_font.setPointSizeF(unzoomed_pt * zoom);
  label_font.setBold(true);
  // but not so large that the close-up holds fewer than kLabelLinesInView lines of them below
  // the readout: with the class's larger text a 580 px wide close-up lost its force values first
  const double below_readout = height() - readout_band_px(QFontMetricsF(readout_font(font())));
  if (const double line = QFontMetricsF(label_font).height();
      zoom > 1.0 && line > below_readout / kLabelLinesInView)
    label_font.setPointSizeF(
        std::max(unzoomed_pt, label_font.pointSizeF() * below_readout / kLabelLinesInView / line));
  painter.setFont(label_font);

  // the drawn fixtures and bodies, which the rails' and fixtures' labels keep off
  std::vector<QPolygonF> drawn_shapes;
  std::vector<QPolygonF> body_shapes(model.dofs());  // each body's, for its name
  // fixtures
  for (const Fixture& f : model.fixtures) {
    QPolygonF polygon;
    for (const Vec2& p : f.outline) polygon << to_screen(p);
    drawn_shapes.push_back(polygon);
    const QColor colour = fixture_colour(f.name);
    painter.setPen(QPen(colour.darker(160), 1.5));
    painter.setBrush(f.name == "string" ? colour : colour.lighter(120));
    painter.drawPolygon(polygon);
  }
  // bodies, parents first (children drawn over them)
  for (int b = 0; b < model.dofs(); ++b) {
    const Body& body = model.bodies[b];
    QPolygonF polygon;
    for (const Vec2& p : body.outline) polygon << to_screen(body_point(b, p));
    body_shapes[b] = polygon;
    // a pivot away from the drawn part (the grand's damper lever turns on a flange behind the
    // string): the arm that joins them, so that the pivot does not float on its own
    QPolygonF rest_outline;
    for (const Vec2& p : body.outline) rest_outline << QPointF(p.x(), p.y());
    if (!body.outline.empty() &&
        !rest_outline.containsPoint(QPointF(body.pivot.x(), body.pivot.y()), Qt::OddEvenFill)) {
      const Vec2 foot = nearest_outline_point(body.outline, body.pivot);
      painter.setPen(QPen(body_colour(body.name).darker(170), 2.5, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(to_screen(body_point(body.parent, body.pivot)),
                       to_screen(body_point(b, foot)));
    }
    QColor fill = body_colour(body.name);
    fill.setAlpha(215);
    painter.setPen(QPen(fill.darker(200), 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(fill);
    painter.drawPolygon(polygon);
  }
  // straps (the upright's bridle): a cord between its two points, solid while it pulls
  std::vector<QPointF> strap_middles;
  for (std::size_t k = 0; k < model.straps.size(); ++k) {
    const Strap& strap = model.straps[k];
    const QPointF a = to_screen(body_point(strap.body_a, strap.point_a));
    const QPointF b = to_screen(body_point(strap.body_b, strap.point_b));
    const bool pulling = k < reading_.strap_tension.size() && reading_.strap_tension[k] > 1e-3;
    painter.setPen(QPen(QColor(120, 40, 30), pulling ? 2.5 : 1.5,
                        pulling ? Qt::SolidLine : Qt::DashLine, Qt::RoundCap));
    painter.drawLine(a, b);
    strap_middles.push_back(0.5 * (a + b));
  }
  // the backcheck: its head behind the check face, on a wire down to the body that carries it
  const int check = model.landmarks.check_contact;
  std::optional<QPointF> backcheck_label_at;
  if (check >= 0 && model.contacts[check].shape == ContactShape::CircleSegment &&
      model.contacts[check].body_b >= 0) {
    const Contact& c = model.contacts[check];
    constexpr double kHeadDepth = 4e-3;  // m, drawn thickness of the head behind its face
    const Vec2 back = -kHeadDepth * c.segment_normal;
    QPolygonF head;
    for (const Vec2& p :
         {c.segment_start, c.segment_end, Vec2(c.segment_end + back), Vec2(c.segment_start + back)})
      head << to_screen(body_point(c.body_b, p));
    const Vec2 wire_top = c.segment_start + 0.5 * back;
    const Vec2 wire_foot = nearest_outline_point(model.bodies[c.body_b].outline, wire_top);
    painter.setPen(QPen(QColor(90, 90, 90), 2.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(to_screen(body_point(c.body_b, wire_top)),
                     to_screen(body_point(c.body_b, wire_foot)));
    painter.setPen(QPen(QColor(95, 60, 30), 1.5));
    painter.setBrush(QColor(170, 120, 70, 230));
    painter.drawPolygon(head);
    drawn_shapes.push_back(head);
    backcheck_label_at = to_screen(body_point(c.body_b, c.segment_end + back));
  }
  // contact features: felts, buttons, capstan, jack top, backcheck face (moved by the adjusters)
  painter.setBrush(Qt::NoBrush);
  // a drawn circle as an octagon around it, for the labels to keep off
  auto circle_shape = [](const QPointF& centre, double radius) {
    QPolygonF octagon;
    for (int k = 0; k < 8; ++k)
      octagon << centre + QPointF(radius * std::cos(k * M_PI / 4), radius * std::sin(k * M_PI / 4));
    return octagon;
  };
  for (const Contact& c : model.contacts) {
    const QColor ink(60, 60, 60, 170);
    painter.setPen(QPen(ink, 1.5));
    if (c.radius_a > 0.0) {
      const QPointF centre = to_screen(body_point(c.body_a, c.center_a));
      painter.drawEllipse(centre, c.radius_a * scale_, c.radius_a * scale_);
      drawn_shapes.push_back(circle_shape(centre, c.radius_a * scale_ + 1.0));
    }
    if (c.shape == ContactShape::CircleCircle && c.radius_b > 0.0) {
      const QPointF centre = to_screen(body_point(c.body_b, c.center_b));
      painter.drawEllipse(centre, c.radius_b * scale_, c.radius_b * scale_);
      drawn_shapes.push_back(circle_shape(centre, c.radius_b * scale_ + 1.0));
    } else if (c.shape == ContactShape::CircleSegment) {
      painter.setPen(QPen(ink, 3.0, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(to_screen(body_point(c.body_b, c.segment_start)),
                       to_screen(body_point(c.body_b, c.segment_end)));
    }
  }
  // pivots
  painter.setPen(QPen(Qt::black, 1.5));
  painter.setBrush(Qt::white);
  for (int b = 0; b < model.dofs(); ++b) {
    const Body& body = model.bodies[b];
    painter.drawEllipse(to_screen(body_point(body.parent, body.pivot)), 4.0, 4.0);
  }
  // active contacts with their force arrows (length grows with the square root of the force)
  struct Label {
    QPointF anchor;
    QString text;
    QColor colour;
    bool small;
    bool keep_clear = false;         // of the drawing (LabelPlacer::place_clear)
    std::optional<QPointF> feature;  // the part the label names: joined by a leader line when
                                     // the label had to move away from it
    QString key = {};                // names it from frame to frame (default: its text)
    int body = -1;                   // the body it names (a part's name over its shape)
    double force_n = 0.0;            // a force value's force: the larger placed first
  };
  std::vector<Label> labels;  // in placement priority
  std::vector<Label> force_labels, fixture_labels;
  active_contacts_ = 0;
  drawn_arrows_.clear();
  for (std::size_t c = 0; c < reading_.contacts.size(); ++c) {
    const ContactReading& r = reading_.contacts[c];
    if (!r.active || r.normal_force <= kShownForceN) continue;
    ++active_contacts_;
    const QPointF at = to_screen(r.point);
    double length = std::clamp(14.0 * std::sqrt(r.normal_force), 10.0, 90.0);
    const QPointF direction(r.normal.x(), -r.normal.y());
    // in a close-up the arrow may point out of the view: shortened to end inside it (its label
    // still gives the force), but never below the shortest arrow
    const QRectF inside = QRectF(rect()).adjusted(4, 4, -4, -22);  // room for the label below
    while (length > 10.0 && inside.contains(at) && !inside.contains(at + direction * length))
      length = std::max(10.0, length - 4.0);
    const QPointF tip = at + direction * length;
    painter.setPen(QPen(contact_colour(), 2.0));
    painter.setBrush(Qt::white);
    painter.drawEllipse(at, 5.0, 5.0);
    draw_arrow(painter, at, tip, contact_colour());
    drawn_arrows_.push_back({static_cast<int>(c), at, tip, r.normal_force, r.friction_force});
    if (r.normal_force >= 0.5 && measurements_)
      force_labels.push_back({tip + QPointF(4, 4), QString::number(r.normal_force, 'f', 1) + " N",
                              contact_colour().darker(130), true, false, tip,
                              QStringLiteral("force %1").arg(c), -1, r.normal_force});
  }
  // the largest forces first: where two arrows meet at one part (the jack and the repetition
  // lever under the knuckle) the push that drives the action keeps its value
  std::stable_sort(force_labels.begin(), force_labels.end(),
                   [](const Label& a, const Label& b) { return a.force_n > b.force_n; });
  // key front: where the finger presses (drag it to play the key)
  const QPointF key_front = to_screen(body_point(model.landmarks.key, model.landmarks.key_front));
  painter.setPen(QPen(QColor(0, 110, 200), playing_key_ ? 4.0 : 2.5));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(key_front, 9.0, 9.0);

  // time and gap readout, in a band of its own along the top (parts framed outside a close-up's
  // region pass under it). When the view is too narrow for the full words (larger text in a
  // class): "hammer–string" goes first, then the font shrinks toward the view's own, and only
  // then do the words go ("580.6 ms  gap 45.05 mm  0.0 N")
  const QFont big = readout_font(font());
  const QFontMetricsF big_metrics(big);
  const double band = readout_band_px(big_metrics);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(250, 250, 246));
  painter.drawRect(QRectF(0, 0, width(), band));
  painter.setPen(QPen(QColor(215, 215, 210), 1.0));
  painter.drawLine(QPointF(0, band), QPointF(width(), band));
  const double t_ms = frame_->t * 1e3;
  const double gap_mm = frame_->hammer_string_gap_mm;
  // to 0.1 N, without a "-0.0" for a finger that barely holds a key led by the mouse
  const double finger_n = std::abs(frame_->finger_force_n) < 0.05 ? 0.0 : frame_->finger_force_n;
  // the gap is read at a point fixed on the felt, which stands up to 0.3 mm behind the felt's
  // nearest point near the string (README, limits): while the felt presses the string the
  // readout says so, instead of a gap the drawing's string force contradicts
  const int string_contact = model.landmarks.string_contact;
  const bool on_string = string_contact >= 0 &&
                         string_contact < static_cast<int>(frame_->contact_force_n.size()) &&
                         frame_->contact_force_n[string_contact] > kShownForceN;
  const QString gap_text =
      on_string ? tr("felt on the string") : tr("%1 mm").arg(gap_mm, 0, 'f', 2);
  const QString full = tr("t = %1 ms   hammer–string gap %2   finger %3 N")
                           .arg(t_ms, 0, 'f', 2)
                           .arg(gap_text)
                           .arg(finger_n, 0, 'f', 1);
  const QString shorter = tr("t = %1 ms   gap %2   finger %3 N")
                              .arg(t_ms, 0, 'f', 1)
                              .arg(gap_text)
                              .arg(finger_n, 0, 'f', 1);
  const QString shortest = tr("%1 ms  gap %2  %3 N")
                               .arg(t_ms, 0, 'f', 1)
                               .arg(on_string ? tr("0 (on string)") : gap_text)
                               .arg(finger_n, 0, 'f', 1);
  const double room = width() - 20.0;
  QFont readout_font_used = big;
  QString readout = measurements_ ? full : tr("t = %1 ms").arg(t_ms, 0, 'f', 2);
  if (measurements_ && QFontMetricsF(big).horizontalAdvance(full) > room) {
    readout = shorter;
    // 0.5 pt steps down to the view's own size, bold
    QFont smaller = big;
    while (QFontMetricsF(smaller).horizontalAdvance(shorter) > room &&
           smaller.pointSizeF() - 0.5 >= font().pointSizeF())
      smaller.setPointSizeF(smaller.pointSizeF() - 0.5);
    readout_font_used = smaller;
    if (QFontMetricsF(smaller).horizontalAdvance(shorter) > room) {
      readout = shortest;
      readout_font_used = big;
    }
  }
  readout_ = readout;
  painter.setFont(readout_font_used);
  draw_label(painter,
             QPointF(10, 0.5 * (band + QFontMetricsF(readout_font_used).ascent() -
                                QFontMetricsF(readout_font_used).descent())),
             readout, QColor(20, 20, 20));
  if (!labels_) return;

  // labels without overlap, in this order: the knuckle or butt, the bodies, the finger, the
  // fixtures and adjusters, the forces, the rails
  LabelPlacer placer{QRectF(rect())};
  placer.reserve(QRectF(0, 0, width(), band));  // the readout's band, all of it
  for (const QPolygonF& shape : drawn_shapes) placer.avoid(shape);
  for (int b = 0; b < model.dofs(); ++b) placer.avoid(body_shapes[b], b);
  // where escapement happens stays in sight: the knuckle or butt and the jack top, a few
  // pixels around them, take no label
  if (const int e = model.landmarks.escapement_contact; e >= 0) {
    const Contact& c = model.contacts[e];
    const auto keep_free = [&](int body, const Vec2& point, double radius_m) {
      const QPointF at = to_screen(body_point(body, point));
      const double r = radius_m * scale_ + kEscapementRoomPx;
      placer.reserve(QRectF(at - QPointF(r, r), at + QPointF(r, r)));
    };
    keep_free(c.body_a, c.center_a, c.radius_a);
    if (c.shape == ContactShape::CircleCircle) {
      keep_free(c.body_b, c.center_b, c.radius_b);
    } else {
      const QPointF a = to_screen(body_point(c.body_b, c.segment_start));
      const QPointF b = to_screen(body_point(c.body_b, c.segment_end));
      placer.reserve(QRectF(a, b).normalized().adjusted(-kEscapementRoomPx, -kEscapementRoomPx,
                                                        kEscapementRoomPx, kEscapementRoomPx));
    }
  }
  // each part's name over a point well inside its own outline (as seen), moved off with a
  // leader when other names or parts are in the way; never nearer another part's point
  const bool close_up = focus_ != ViewFocus::whole || scale_ >= 2.0 * kWholeActionScale;
  // where a part may be named: in the view, and in the checking close-up near the region it
  // frames (within an eighth of the view's width: the hammer head, backcheck and string, not
  // the escapement's parts in its corner)
  QRectF named_area = QRectF(rect()).adjusted(kNamedPointMarginPx, band + kNamedPointMarginPx,
                                              -kNamedPointMarginPx, -kNamedPointMarginPx);
  if (const std::optional<ModelBox> region = focus_region(model, focus_);
      close_up && focus_ == ViewFocus::checking && region) {
    const double near_px = kCheckingNamesReach * width();
    named_area &= QRectF(to_screen(region->low), to_screen(region->high))
                      .normalized()
                      .adjusted(-near_px, -near_px, near_px, near_px);
  }
  const auto nameable = [&](const QPointF& p) { return named_area.contains(p); };

  // a body's name a little further in, so that it is read whole
  const QRectF shown = named_area.adjusted(16, 16, -16, -16);
  const QFontMetricsF body_metrics(label_font);
  for (int b = 0; b < model.dofs(); ++b) {
    const Body& body = model.bodies[b];
    // the joint is called "lever" (DESIGN.md); a technician calls the part the repetition lever
    const QString name =
        body.name == "lever" ? tr("repetition lever") : QString::fromStdString(body.name);
    // the body's own inner point (found once per model, so the name moves with its part); in
    // a close-up that leaves it out of view, the deepest point of what is in view
    std::optional<QPointF> inside;
    if (const std::optional<Vec2>& own = inner_point(b))
      if (const QPointF at = to_screen(body_point(b, *own)); shown.contains(at)) inside = at;
    if (!inside) inside = deepest_point(body_shapes[b], shown);
    if (!inside) continue;  // out of the view
    const QPointF centred(inside->x() - 0.5 * body_metrics.horizontalAdvance(name),
                          inside->y() + 0.5 * (body_metrics.ascent() - body_metrics.descent()));
    Label label{centred, name, body_colour(body.name).darker(250), false, true, inside};
    label.body = b;
    labels.push_back(label);
    placer.add_feature(*inside, kBodyGroup);
  }
  labels.push_back({key_front + QPointF(-24, 28), tr("finger"), QColor(0, 90, 170), false});
  // the adjustable fixtures (buttons, screws) and the string before the forces, rails last
  std::vector<Label> rail_labels;
  for (const Fixture& f : model.fixtures) {
    if (f.outline.empty()) continue;
    Vec2 lowest = f.outline.front(), highest = f.outline.front(), low = f.outline.front(),
         high = f.outline.front();
    for (const Vec2& p : f.outline) {
      lowest = p.y() < lowest.y() ? p : lowest;
      highest = p.y() > highest.y() ? p : highest;
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    // below a rail or button; beside the top end of a tall, thin part (an upright's vertical
    // string), whose lower end sits among the moving parts
    const Vec2 size = high - low;
    const bool tall = size.y() > 4.0 * size.x();
    const QPointF anchor =
        tall ? to_screen(highest) + QPointF(6, 4) : to_screen(lowest) + QPointF(-10, 15);
    const Label label{anchor, QString::fromStdString(f.name),    QColor(70, 70, 70), true,
                      true,   to_screen(tall ? highest : lowest)};
    (f.adjuster.empty() && f.name != "string" ? rail_labels : fixture_labels).push_back(label);
  }
  if (backcheck_label_at)
    fixture_labels.push_back({*backcheck_label_at + QPointF(6, -4), tr("backcheck"),
                              QColor(70, 70, 70), true, true, *backcheck_label_at});
  // what each regulation adjuster turns, named as in its description ("capstan (key pilot)",
  // "jack regulating screw"), where it acts, in the close-ups (the whole action has no room for
  // them); those drawn as fixtures or as the backcheck are named already
  for (const Adjuster& adjuster : model.adjusters) {
    if (!close_up) break;
    bool named = false;  // a fixture it moves (a button, a screw) or the backcheck
    for (const Fixture& f : model.fixtures) named = named || f.adjuster == adjuster.name;
    for (const AdjusterEffect& effect : adjuster.effects)
      named = named || (effect.target == AdjusterEffect::Target::ContactB &&
                        effect.index == model.landmarks.check_contact);
    const QString name = adjuster_part(adjuster);
    if (named || name.isEmpty() || adjuster.effects.empty()) continue;
    const AdjusterEffect& effect = adjuster.effects.front();
    std::optional<QPointF> at;
    if (effect.target == AdjusterEffect::Target::ContactA) {
      const Contact& c = model.contacts[effect.index];
      at = to_screen(body_point(c.body_a, c.center_a));
    } else if (effect.target == AdjusterEffect::Target::ContactB) {
      const Contact& c = model.contacts[effect.index];
      const Vec2 feature = c.shape == ContactShape::CircleSegment
                               ? Vec2(0.5 * (c.segment_start + c.segment_end))
                               : c.center_b;
      at = to_screen(body_point(c.body_b, feature));
    } else if (effect.index >= 0 && effect.index < static_cast<int>(strap_middles.size())) {
      at = strap_middles[effect.index];
    }
    if (at)
      fixture_labels.push_back({*at + QPointF(6, -6), name, QColor(70, 70, 70), true, true, *at});
  }
  // the part the jack lifts, where escapement happens: the grand's knuckle (a circle on the
  // hammer), the upright's butt (the face on the hammer)
  const int escapement = model.landmarks.escapement_contact;
  if (escapement >= 0) {
    const Contact& c = model.contacts[escapement];
    const int hammer = model.landmarks.hammer;
    std::optional<QPointF> part, at;  // the part's point, and the label's anchor beside it
    if (c.body_a == hammer && c.radius_a > 0.0) {
      part = to_screen(body_point(hammer, c.center_a));
      at = *part + QPointF(c.radius_a * scale_ + 3, -6);
    } else if (c.body_b == hammer && c.shape == ContactShape::CircleSegment) {
      part = to_screen(body_point(hammer, 0.5 * (c.segment_start + c.segment_end)));
      at = *part + QPointF(6, -6);
    }
    if (at)
      // first of all: the escapement is what the close-up is for
      labels.insert(labels.begin(),
                    {*at, model.kind == "grand" ? tr("knuckle") : tr("butt"),
                     body_colour(model.bodies[hammer].name).darker(250), true, false, part});
  }
  // in a close-up, a part whose point lies beyond the view is not named, nor in the checking
  // close-up one outside the region it frames (the escapement's screws in its corner)
  if (close_up) {
    // the string named where the hammer meets it when its end is out of the region
    for (Label& l : fixture_labels)
      if (l.text == "string" && l.feature && !nameable(*l.feature)) {
        l.feature = to_screen(string_point_struck(model.landmarks));
        l.anchor = *l.feature + QPointF(6, -6);
      }
    const auto at_edge = [&](const Label& l) { return l.feature && !nameable(*l.feature); };
    std::erase_if(fixture_labels, at_edge);
    std::erase_if(rail_labels, at_edge);
    std::erase_if(labels, at_edge);  // the bodies' names and the knuckle's or butt's
    // a force's newtons likewise only where it acts in the framed region (the checking
    // close-up showed the escapement's 15 N in its corner)
    std::erase_if(force_labels, [&](const Label& l) { return !nameable(l.anchor); });
  }
  // in a close-up the push of the jack on the knuckle or butt comes right after their name: the
  // other names took its place in the escapement close-up of the class's larger text
  if (close_up && escapement >= 0) {
    const QString escapement_force = QStringLiteral("force %1").arg(escapement);
    const auto push = std::find_if(force_labels.begin(), force_labels.end(),
                                   [&](const Label& l) { return l.key == escapement_force; });
    if (push != force_labels.end()) {
      // after the knuckle's or butt's name when it is drawn (else first of all)
      const QString part = model.kind == "grand" ? tr("knuckle") : tr("butt");
      const auto named = std::find_if(labels.begin(), labels.end(),
                                      [&](const Label& l) { return l.body < 0 && l.text == part; });
      labels.insert(named == labels.end() ? labels.begin() : named + 1, *push);
      force_labels.erase(push);
    }
  }
  labels.insert(labels.end(), fixture_labels.begin(), fixture_labels.end());
  labels.insert(labels.end(), force_labels.begin(), force_labels.end());
  labels.insert(labels.end(), rail_labels.begin(), rail_labels.end());
  // the points the parts' names point at (not the bodies', added above, nor the force arrows'
  // tips): a name placed nearer another part's point than its own would name the wrong part
  for (const Label& l : labels)
    if (l.feature && l.body < 0 && l.key.isEmpty()) placer.add_feature(*l.feature);
  QFont small = label_font;
  small.setBold(false);
  QHash<QString, QPointF> offsets;  // this paint's, for the next one
  for (const Label& l : labels) {
    painter.setFont(l.small ? small : label_font);
    const QFontMetricsF metrics(painter.font());
    const QString key = l.key.isEmpty() ? l.text : l.key;
    const auto previous_at = label_offsets_.find(key);
    const std::optional<QPointF> previous =
        previous_at == label_offsets_.end() ? std::nullopt : std::optional(*previous_at);
    std::optional<QPointF> at;
    std::optional<QLineF> leader;
    if (l.feature) {
      LabelPlacer::NamedStyle style;
      style.keep_clear = l.keep_clear;
      if (l.body >= 0) {  // a part's name: over its own shape, among the parts' names
        style.may_cover_point = true;
        style.own_shape = l.body;
        style.group = kBodyGroup;
      }
      const auto placed =
          placer.place_named(l.anchor, *l.feature, l.text, metrics, style, previous);
      if (placed) {
        at = placed->baseline;
        leader = placed->leader;
      }
    } else {
      at = l.keep_clear ? placer.place_clear(l.anchor, l.text, metrics, previous)
                        : placer.place(l.anchor, l.text, metrics, previous);
    }
    if (!at) continue;
    if (leader) {  // a thin line from the part to the nearest point of its label
      painter.setPen(QPen(QColor(90, 90, 90, 200), 1.0));
      painter.drawLine(*leader);
    }
    draw_label(painter, *at, l.text, l.colour);
    offsets.insert(key, *at - l.anchor);
    drawn_labels_.push_back(l.text);
    drawn_label_details_.push_back(
        {l.text, LabelPlacer::text_box(*at, metrics.horizontalAdvance(l.text), metrics), l.feature,
         leader, l.body < 0 && l.key.isEmpty() && l.feature.has_value(), l.body});
  }
  label_offsets_ = offsets;
}

void ActionView::wheelEvent(QWheelEvent* event) {
  // from a fifth of the whole action's usual scale (the action a small patch) to a hundred times
  // it (0.15 mm a pixel, the felts' compression in view): beyond, a lost view with nothing on it
  // (a view already beyond an end, a tiny window or a close-up on a huge screen, is not snapped
  // back the other way: the wheel only stops moving it further)
  const double turn = std::pow(1.0015, event->angleDelta().y());
  const double lowest = 0.2 * kWholeActionScale, highest = 100.0 * kWholeActionScale;
  double wanted = scale_ * turn;
  if (turn > 1.0 && wanted > highest) wanted = std::max(scale_, highest);
  if (turn < 1.0 && wanted < lowest) wanted = std::min(scale_, lowest);
  const double factor = wanted / scale_;
  const QPointF at = event->position();
  offset_ = at + (offset_ - at) * factor;
  scale_ *= factor;
  update();
}

void ActionView::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
    panning_ = true;
    drag_start_ = event->position();
    offset_at_drag_ = offset_;
    setCursor(Qt::ClosedHandCursor);
    return;
  }
  if (event->button() == Qt::LeftButton && frame_) {
    const auto front = key_front_on_screen();
    if (front && QLineF(*front, event->position()).length() <= kKeyGrabRadiusPx) {
      playing_key_ = true;
      const int key = model_->landmarks.key;
      key_angle_at_press_ = frame_->angle_deg[key] * model_->bodies[key].trace_sign * M_PI / 180.0;
      press_y_m_ = to_model(event->position()).y();
      update();
    }
  }
}

void ActionView::mouseMoveEvent(QMouseEvent* event) {
  if (panning_) {
    offset_ = offset_at_drag_ + (event->position() - drag_start_);
    update();
  } else if (playing_key_) {
    const double down_m = press_y_m_ - to_model(event->position()).y();
    emit keyPlayed(key_angle_at_press_ + down_m / key_arm_m_);
  } else if (frame_) {
    const auto front = key_front_on_screen();
    const bool over_key = front && QLineF(*front, event->position()).length() <= kKeyGrabRadiusPx;
    setCursor(over_key ? Qt::PointingHandCursor : Qt::ArrowCursor);
  }
}

void ActionView::mouseReleaseEvent(QMouseEvent* event) {
  if (panning_ && (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton)) {
    panning_ = false;
    setCursor(Qt::ArrowCursor);
  }
  if (playing_key_ && event->button() == Qt::LeftButton) {
    playing_key_ = false;
    emit keyReleased();
    update();
  }
}

QString ActionView::arrow_tooltip(const QPointF& at) const {
  constexpr double kReachPx = 8.0;  // the base circle's radius (5 px) and its pen, with a margin
  const DrawnArrow* nearest = nullptr;
  double nearest_px = kReachPx;
  for (const DrawnArrow& arrow : drawn_arrows_) {
    const double px = distance_to_segment(at, arrow.base, arrow.tip);  // to the arrow's shaft
    if (px <= nearest_px) {
      nearest_px = px;
      nearest = &arrow;
    }
  }
  if (!nearest || !model_ || nearest->contact >= static_cast<int>(model_->contacts.size()))
    return {};
  const QString name = QString::fromStdString(model_->contacts[nearest->contact].name);
  if (!measurements_) return tr("%1: touching").arg(name);
  QString text = tr("%1: %2 N pressing").arg(name).arg(nearest->normal_force_n, 0, 'f', 1);
  if (std::abs(nearest->friction_force_n) >= 0.05)
    text += tr(", %1 N friction").arg(std::abs(nearest->friction_force_n), 0, 'f', 1);
  return text;
}

bool ActionView::event(QEvent* event) {
  if (event->type() == QEvent::ToolTip) {
    const auto* help = static_cast<QHelpEvent*>(event);
    const QString text = arrow_tooltip(help->pos());
    if (!text.isEmpty()) {
      // kept only while the pointer stays near where it was asked for (the arrows move as the
      // run plays)
      constexpr int kStayPx = 8;
      QToolTip::showText(
          help->globalPos(), text, this,
          QRect(help->pos() - QPoint(kStayPx, kStayPx), QSize(2 * kStayPx, 2 * kStayPx)));
      return true;
    }
    QToolTip::hideText();  // an arrow's name shown before does not stay over empty space
    // elsewhere the view's own tooltip, if any
  }
  return QWidget::event(event);
}

void ActionView::mouseDoubleClickEvent(QMouseEvent* event) {
  // a double click on empty space refits the whole action; the second press of two quick key
  // strokes on the key's ring, or of a pan, is that press (a teacher's zoom is kept)
  const auto front = frame_ ? key_front_on_screen() : std::nullopt;
  const bool on_key = front && QLineF(*front, event->position()).length() <= kKeyGrabRadiusPx;
  if (event->button() != Qt::LeftButton || on_key) {
    mousePressEvent(event);
    return;
  }
  set_focus(ViewFocus::whole);
}

}  // namespace pat::ui

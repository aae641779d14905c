#include "label_placer.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace pat::ui {
namespace {

// Costs of a named label's position, in pixels of leader (see the header)
constexpr double kLeaderThroughLabelCost = 200;  // a leader passes through a label
constexpr double kNearerOtherCost = 100.0;       // nearer another named point than its own ...
constexpr double kNearerOtherPerPx = 2.0;        // ... plus this per pixel it is nearer
constexpr double kNearerMarginPx = 8.0;          // "nearer" unless its own is this much nearer
constexpr double kCoversOwnPointCost = 40.0;     // the text lies over the point it names
constexpr double kCoveredPointCostClear = 10.0;  // per grid point on the drawing (keep_clear)
constexpr double kCoveredPointCost = 2.0;        // the same for the other labels (forces)
// a label stays where it was while that costs at most this much more than the best position:
// about the leader growing by three lines' height, or six covered grid points
constexpr double kKeepPreviousMarginPx = 60.0;

bool segment_meets_rect(const QLineF& segment, const QRectF& rect) {
  if (rect.contains(segment.p1()) || rect.contains(segment.p2())) return true;
  const QLineF edges[] = {{rect.topLeft(), rect.topRight()},
                          {rect.topRight(), rect.bottomRight()},
                          {rect.bottomRight(), rect.bottomLeft()},
                          {rect.bottomLeft(), rect.topLeft()}};
  for (const QLineF& edge : edges)
    if (segment.intersects(edge, nullptr) == QLineF::BoundedIntersection) return true;
  return false;
}

double distance_to_rect(const QPointF& point, const QRectF& rect) {
  const double dx = std::max({rect.left() - point.x(), 0.0, point.x() - rect.right()});
  const double dy = std::max({rect.top() - point.y(), 0.0, point.y() - rect.bottom()});
  return std::hypot(dx, dy);
}

}  // namespace

int LabelPlacer::covered_points(const QRectF& box, int own_shape) const {
  constexpr int kColumns = 6, kRows = 3;
  int covered = 0;
  for (int i = 0; i < kColumns; ++i) {
    for (int j = 0; j < kRows; ++j) {
      const QPointF point(box.left() + box.width() * (i + 0.5) / kColumns,
                          box.top() + box.height() * (j + 0.5) / kRows);
      for (const Shape& shape : avoided_) {
        if (own_shape >= 0 && shape.id == own_shape) continue;
        if (shape.bounds.contains(point) && shape.polygon.containsPoint(point, Qt::OddEvenFill)) {
          ++covered;
          break;
        }
      }
    }
  }
  return covered;
}

QLineF LabelPlacer::leader_to(const QPointF& feature, const QRectF& box) {
  return {feature, QPointF(std::clamp(feature.x(), box.left(), box.right()),
                           std::clamp(feature.y(), box.top(), box.bottom()))};
}

bool LabelPlacer::is_free(const QRectF& box) const {
  if (!bounds_.contains(box)) return false;
  for (const QRectF& other : taken_)
    if (other.intersects(box)) return false;
  return true;
}

std::optional<QPointF> LabelPlacer::place(const QPointF& anchor, const QString& text,
                                          const QFontMetricsF& metrics, bool keep_clear,
                                          std::optional<QPointF> previous) {
  const double w = metrics.horizontalAdvance(text), h = metrics.height();
  // below/above first, then to the sides
  const QPointF near[] = {{0, 0},        {0, h},       {0, -h},       {0, 2 * h},
                          {0, -2 * h},   {w * 0.6, 0}, {-w * 0.6, 0}, {w * 0.6, h},
                          {-w * 0.6, h}, {0, 3 * h},   {0, -3 * h}};
  // a label kept clear of the drawing may also go wholly to the left, or diagonally up
  const QPointF wider[] = {{-w - 6, 0}, {-w - 6, -h}, {-w - 6, h}, {w * 0.6, -h}, {-w * 0.6, -h}};
  std::vector<QPointF> offsets;
  offsets.reserve(1 + std::size(near) + std::size(wider));
  // where it was, when its own place (the anchor) is taken: it goes back there once free
  if (previous && !is_free(padded_box(anchor, w, metrics))) offsets.push_back(*previous);
  for (const QPointF& offset : near) offsets.push_back(offset);
  if (keep_clear)
    for (const QPointF& offset : wider) offsets.push_back(offset);
  std::optional<QPointF> best;
  QRectF best_box;
  int best_covered = 0;
  for (const QPointF& offset : offsets) {
    const QPointF baseline = anchor + offset;
    const QRectF box = padded_box(baseline, w, metrics);
    if (!is_free(box)) continue;
    const int covered = keep_clear ? covered_points(box) : 0;
    if (!best || covered < best_covered) {
      best = baseline;
      best_box = box;
      best_covered = covered;
    }
    if (best_covered == 0) break;
  }
  if (best) taken_.push_back(best_box);
  return best;
}

double LabelPlacer::named_cost(const QRectF& box, const QRectF& text_box, const QPointF& feature,
                               const NamedStyle& style, double worst_wanted) const {
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  if (!is_free(box)) return kInfinite;
  const QLineF leader = leader_to(feature, text_box);
  const double own = leader.length();  // the text's distance from its point
  const bool drawn = own > kMinLeaderPx;
  double cost = own;
  if (own == 0.0 && !style.may_cover_point) cost += kCoversOwnPointCost;
  // a label that sits nearer another named point than its own names the wrong part
  double nearest_other = kInfinite;
  for (const Feature& other : features_) {
    if (other.group != style.group || QLineF(other.point, feature).length() < 1.0)
      continue;  // another group's, or its own point
    nearest_other = std::min(nearest_other, distance_to_rect(other.point, text_box));
  }
  if (nearest_other < own) return kInfinite;  // it would name that part: better left out
  if (nearest_other < own + kNearerMarginPx)
    cost += kNearerOtherCost + kNearerOtherPerPx * (own + kNearerMarginPx - nearest_other);
  for (const QLineF& other : leaders_) {
    // crossed leaders point each name at the other's part: refused
    if (drawn && leader.intersects(other, nullptr) == QLineF::BoundedIntersection &&
        QLineF(other.p1(), feature).length() >= 1.0)
      return kInfinite;
    if (segment_meets_rect(other, box)) cost += kLeaderThroughLabelCost;
  }
  if (drawn)
    for (const QRectF& other : taken_)
      if (segment_meets_rect(leader, other)) cost += kLeaderThroughLabelCost;
  if (cost >= worst_wanted) return cost;  // the grid count below cannot make it cheaper
  return cost + covered_points(box, style.own_shape) *
                    (style.keep_clear ? kCoveredPointCostClear : kCoveredPointCost);
}

std::optional<LabelPlacer::Placement> LabelPlacer::place_named(
    const QPointF& anchor, const QPointF& feature, const QString& text,
    const QFontMetricsF& metrics, const NamedStyle& style, std::optional<QPointF> previous) {
  const double w = metrics.horizontalAdvance(text), h = metrics.height();
  const auto boxes = [&](const QPointF& baseline) {
    return std::pair{padded_box(baseline, w, metrics), text_box(baseline, w, metrics)};
  };
  // the anchor first, then rings around the point: 16 directions, the text's nearest edge at
  // growing gaps from it
  std::vector<QPointF> candidates{anchor};
  constexpr int kDirections = 16;
  for (const double gap : {4.0, 14.0, 28.0, 46.0, 70.0, 100.0}) {
    for (int k = 0; k < kDirections; ++k) {
      const double angle = 2.0 * M_PI * k / kDirections;
      const double dx = std::cos(angle), dy = std::sin(angle);
      const QPointF centre = feature + QPointF(dx * (gap + 0.5 * w), dy * (gap + 0.5 * h));
      candidates.push_back(QPointF(centre.x() - 0.5 * w, centre.y() - 0.5 * h + metrics.ascent()));
    }
  }
  std::optional<QPointF> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const QPointF& baseline : candidates) {
    const auto [box, text_box] = boxes(baseline);
    const double cost = named_cost(box, text_box, feature, style, best_cost);
    if (cost < best_cost) {
      best_cost = cost;
      best = baseline;
    }
  }
  if (previous && best) {  // (with no free position, neither is the previous one)
    const auto [box, text_box] = boxes(anchor + *previous);
    const double margin = best_cost + kKeepPreviousMarginPx;
    if (named_cost(box, text_box, feature, style, margin + 1.0) <= margin)
      best = anchor + *previous;
  }
  if (!best) return std::nullopt;
  const auto [box, text_box] = boxes(*best);
  taken_.push_back(box);
  Placement placement{*best, text_box, std::nullopt};
  const QLineF leader = leader_to(feature, text_box);
  if (leader.length() > kMinLeaderPx) {
    placement.leader = leader;
    leaders_.push_back(leader);
  }
  return placement;
}

}  // namespace pat::ui

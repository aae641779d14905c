#include "label_placer.h"

#include <iterator>
#include <vector>

namespace pat::ui {

int LabelPlacer::covered_points(const QRectF& box) const {
  constexpr int kColumns = 6, kRows = 3;
  int covered = 0;
  for (int i = 0; i < kColumns; ++i) {
    for (int j = 0; j < kRows; ++j) {
      const QPointF point(box.left() + box.width() * (i + 0.5) / kColumns,
                          box.top() + box.height() * (j + 0.5) / kRows);
      for (const Shape& shape : avoided_) {
        if (shape.bounds.contains(point) && shape.polygon.containsPoint(point, Qt::OddEvenFill)) {
          ++covered;
          break;
        }
      }
    }
  }
  return covered;
}

std::optional<QPointF> LabelPlacer::place(const QPointF& anchor, const QString& text,
                                          const QFontMetricsF& metrics, bool keep_clear) {
  const double w = metrics.horizontalAdvance(text), h = metrics.height();
  // below/above first, then to the sides
  const QPointF near[] = {{0, 0},        {0, h},       {0, -h},       {0, 2 * h},
                          {0, -2 * h},   {w * 0.6, 0}, {-w * 0.6, 0}, {w * 0.6, h},
                          {-w * 0.6, h}, {0, 3 * h},   {0, -3 * h}};
  // a label kept clear of the drawing may also go wholly to the left, or diagonally up
  const QPointF wider[] = {{-w - 6, 0}, {-w - 6, -h}, {-w - 6, h}, {w * 0.6, -h}, {-w * 0.6, -h}};
  std::vector<QPointF> offsets(std::begin(near), std::end(near));
  if (keep_clear) offsets.insert(offsets.end(), std::begin(wider), std::end(wider));
  std::optional<QPointF> best;
  QRectF best_box;
  int best_covered = 0;
  for (const QPointF& offset : offsets) {
    const QPointF baseline = anchor + offset;
    const QRectF box(baseline.x() - 2, baseline.y() - metrics.ascent() - 1, w + 4, h + 2);
    if (!bounds_.contains(box)) continue;
    bool free = true;
    for (const QRectF& other : taken_)
      if (other.intersects(box)) {
        free = false;
        break;
      }
    if (!free) continue;
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

}  // namespace pat::ui

#include "label_placer.h"

namespace pat::ui {

std::optional<QPointF> LabelPlacer::place(const QPointF& anchor, const QString& text,
                                          const QFontMetricsF& metrics) {
  const double w = metrics.horizontalAdvance(text), h = metrics.height();
  // below/above first, then to the sides
  const QPointF offsets[] = {{0, 0},        {0, h},       {0, -h},       {0, 2 * h},
                             {0, -2 * h},   {w * 0.6, 0}, {-w * 0.6, 0}, {w * 0.6, h},
                             {-w * 0.6, h}, {0, 3 * h},   {0, -3 * h}};
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
    taken_.push_back(box);
    return baseline;
  }
  return std::nullopt;
}

}  // namespace pat::ui

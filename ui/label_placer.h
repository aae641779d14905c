// Places text labels of a drawing without overlap: each label tries a few positions around its
// anchor and is left out when all of them collide with labels placed before it (place the most
// important labels first).
#pragma once

#include <QFontMetricsF>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <optional>
#include <vector>

namespace pat::ui {

class LabelPlacer {
 public:
  explicit LabelPlacer(const QRectF& bounds) : bounds_(bounds) {}

  /// Baseline position for `text` near `anchor` (the label's left end, baseline), or nothing.
  std::optional<QPointF> place(const QPointF& anchor, const QString& text,
                               const QFontMetricsF& metrics);
  /// Marks an area as taken (e.g. a readout drawn without placement).
  void reserve(const QRectF& area) { taken_.push_back(area); }

 private:
  QRectF bounds_;
  std::vector<QRectF> taken_;
};

}  // namespace pat::ui

// Places text labels of a drawing without overlap: each label tries a few positions around its
// anchor and is left out when all of them collide with labels placed before it (place the most
// important labels first). A label may also keep off the drawing: of its free positions it takes
// the one that covers least of the shapes marked with avoid() (a rail's name written across the
// hammer shank hides the part the class is looking at).
#pragma once

#include <QFontMetricsF>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QString>
#include <optional>
#include <vector>

namespace pat::ui {

class LabelPlacer {
 public:
  explicit LabelPlacer(const QRectF& bounds) : bounds_(bounds) {}

  /// Baseline position for `text` near `anchor` (the label's left end, baseline), or nothing:
  /// the first free position in the order tried.
  std::optional<QPointF> place(const QPointF& anchor, const QString& text,
                               const QFontMetricsF& metrics) {
    return place(anchor, text, metrics, false);
  }
  /// The same, but the free position that covers least of the avoided shapes (the first tried
  /// of those that cover equally little).
  std::optional<QPointF> place_clear(const QPointF& anchor, const QString& text,
                                     const QFontMetricsF& metrics) {
    return place(anchor, text, metrics, true);
  }
  /// Marks an area as taken (e.g. a readout drawn without placement).
  void reserve(const QRectF& area) { taken_.push_back(area); }
  /// Marks a drawn shape (screen coordinates) that place_clear() keeps off.
  void avoid(const QPolygonF& shape) {
    if (shape.size() >= 3) avoided_.push_back({shape, shape.boundingRect()});
  }

  /// How much of `box` the avoided shapes cover: the number of points of a 6 × 3 grid over it
  /// that lie in one of them (0 … 18).
  int covered_points(const QRectF& box) const;

 private:
  struct Shape {
    QPolygonF polygon;
    QRectF bounds;
  };
  std::optional<QPointF> place(const QPointF& anchor, const QString& text,
                               const QFontMetricsF& metrics, bool keep_clear);

  QRectF bounds_;
  std::vector<QRectF> taken_;
  std::vector<Shape> avoided_;
};

}  // namespace pat::ui

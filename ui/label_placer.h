// Places text labels of a drawing without overlap: each label tries a few positions around its
// anchor and is left out when all of them collide with labels placed before it (place the most
// important labels first). A label may also keep off the drawing: of its free positions it takes
// the one that covers least of the shapes marked with avoid() (a rail's name written across the
// hammer shank hides the part the class is looking at).
//
// A label that names a point of the drawing (place_named: a button, a screw, a force arrow) is
// joined to it by a leader line when it sits away from it. Its position is the free one of least
// cost, in screen pixels: the leader's length, plus penalties for a leader crossing another
// label, and for covering the drawing; crossed leaders and a label nearer another named point
// than its own (the class would read it as that part's name) are refused. A label keeps its
// previous position (the offset from its anchor at the last paint) while that costs little more
// than the best, so the names do not jump between the frames of a moving action.
#pragma once

#include <QFontMetricsF>
#include <QLineF>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QString>
#include <optional>
#include <vector>

namespace pat::ui {

class LabelPlacer {
 public:
  /// Leaders shorter than this are not drawn: the label is next to its point.
  static constexpr double kMinLeaderPx = 10.0;

  struct Placement {
    QPointF baseline;              // the label's left end, baseline
    QRectF text_box;               // where its text is drawn
    std::optional<QLineF> leader;  // from the named point to the nearest point of the text
  };

  /// How a named label may sit: `keep_clear` weighs covering the drawing as rails' names do
  /// (else lightly, as force values); a part's name (`may_cover_point`) may be written over its
  /// own point and its own shape (`own_shape`, the id given to avoid()); `group`: the named
  /// points it must not sit nearer to than its own (those added with the same group).
  struct NamedStyle {
    bool keep_clear = true;
    bool may_cover_point = false;
    int own_shape = -1;
    int group = 0;
  };

  explicit LabelPlacer(const QRectF& bounds) : bounds_(bounds) {}

  /// Baseline position for `text` near `anchor` (the label's left end, baseline), or nothing:
  /// the first free position in the order tried (`previous`, an offset from the anchor, first
  /// when the anchor itself is taken).
  std::optional<QPointF> place(const QPointF& anchor, const QString& text,
                               const QFontMetricsF& metrics,
                               std::optional<QPointF> previous = std::nullopt) {
    return place(anchor, text, metrics, false, previous);
  }
  /// The same, but the free position that covers least of the avoided shapes (the first tried
  /// of those that cover equally little).
  std::optional<QPointF> place_clear(const QPointF& anchor, const QString& text,
                                     const QFontMetricsF& metrics,
                                     std::optional<QPointF> previous = std::nullopt) {
    return place(anchor, text, metrics, true, previous);
  }
  /// A label naming the point `feature`, first tried at `anchor`, then around the feature; the
  /// free position of least cost (see above), or nothing when no position is free.
  std::optional<Placement> place_named(const QPointF& anchor, const QPointF& feature,
                                       const QString& text, const QFontMetricsF& metrics,
                                       const NamedStyle& style,
                                       std::optional<QPointF> previous = std::nullopt);

  /// Marks an area as taken (e.g. a readout drawn without placement).
  void reserve(const QRectF& area) { taken_.push_back(area); }
  /// Marks a drawn shape (screen coordinates) that place_clear() keeps off; `id` names it for
  /// NamedStyle::own_shape.
  void avoid(const QPolygonF& shape, int id = -1) {
    if (shape.size() >= 3) avoided_.push_back({shape, shape.boundingRect(), id});
  }
  /// Marks a point that some label names (all of them, before placing any): a label placed
  /// nearer another such point of its group than its own is refused.
  void add_feature(const QPointF& feature, int group = 0) { features_.push_back({feature, group}); }

  /// How much of `box` the avoided shapes cover (but the shape `own_shape`): the number of
  /// points of a 6 × 3 grid over it that lie in one of them (0 … 18).
  int covered_points(const QRectF& box, int own_shape = -1) const;
  /// The leaders drawn so far.
  const std::vector<QLineF>& leaders() const { return leaders_; }

  /// The leader from `feature` to the nearest point of `box` (a point, inside the box).
  static QLineF leader_to(const QPointF& feature, const QRectF& box);
  /// Where a label's text lies (its left end, baseline, at `baseline`), and the same with the
  /// margin of the white box drawn under it, which other labels keep off.
  static QRectF text_box(const QPointF& baseline, double width, const QFontMetricsF& metrics) {
    return {baseline.x(), baseline.y() - metrics.ascent(), width, metrics.height()};
  }
  static QRectF padded_box(const QPointF& baseline, double width, const QFontMetricsF& metrics) {
    return text_box(baseline, width, metrics).adjusted(-2, -1, 2, 1);
  }

 private:
  struct Shape {
    QPolygonF polygon;
    QRectF bounds;
    int id = -1;
  };
  struct Feature {
    QPointF point;
    int group = 0;
  };
  std::optional<QPointF> place(const QPointF& anchor, const QString& text,
                               const QFontMetricsF& metrics, bool keep_clear,
                               std::optional<QPointF> previous);
  bool is_free(const QRectF& box) const;
  /// The cost of a named label at `box` (text box `text_box`); infinite when not free.
  double named_cost(const QRectF& box, const QRectF& text_box, const QPointF& feature,
                    const NamedStyle& style, double worst_wanted) const;

  QRectF bounds_;
  std::vector<QRectF> taken_;
  std::vector<Shape> avoided_;
  std::vector<Feature> features_;
  std::vector<QLineF> leaders_;
};

}  // namespace pat::ui

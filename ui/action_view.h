// The animated action: every body's outline at its joint angle, the fixtures (rails, let-off
// button, drop screw, string), the contact features (capstan, jack top, backcheck, felts),
// pivots, and each active contact highlighted with an arrow scaled by its normal force.
// Wheel: zoom about the cursor; middle or right drag: pan; double click: fit the action.
// Close-ups (set_focus) frame what a teacher points at: the escapement (knuckle or butt, jack
// top, let-off button) or the checking (hammer head and tail, backcheck, string); they stay
// framed through resizes and a change of action until the whole action is fitted again.
// Left drag on the key front plays the key (keyPlayed); releasing lets it up.
#pragma once

#include <QHash>
#include <QLineF>
#include <QPointF>
#include <QRectF>
#include <QStringList>
#include <QTransform>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "dynamics/action_dynamics.h"
#include "frame.h"
#include "view_focus.h"

class QPainter;

namespace pat::ui {

/// A rectangle of the model plane (m, at the preset's rest drawing).
struct ModelBox {
  Vec2 low = Vec2::Zero(), high = Vec2::Zero();
};

class ActionView : public QWidget {
  Q_OBJECT
 public:
  explicit ActionView(QWidget* parent = nullptr);

  /// Shows a frame (its model may differ from the previous one: a moved adjuster).
  void show_frame(const Frame& frame);
  /// Forgets the view fit (a new action): the next frame is fitted to the widget, with the
  /// current focus.
  void reset_view();
  /// Frames the whole action or a close-up (now, or at the first frame); kept until changed.
  void set_focus(ViewFocus focus);
  ViewFocus focus() const { return focus_; }
  /// The region a close-up frames, from the model's landmark contacts at rest with room for
  /// their motion around it: escapement — the escapement and let-off contacts' features;
  /// checking — the backcheck contact's features, the strike point and the string point.
  /// Empty for ViewFocus::whole or when the model lacks those contacts.
  static std::optional<ModelBox> focus_region(const ActionModel& model, ViewFocus focus);
  void set_labels_visible(bool visible);
  bool labels_visible() const { return labels_; }
  /// Whether the readout gives the hammer–string gap and finger force and the force arrows their
  /// newtons (on by default). Off in a practice exercise, where the technician's tests are the
  /// measurements and these would read the hidden setting off for free: the time and the arrows
  /// stay (what the eye sees of the action).
  void set_measurements_visible(bool visible);
  bool measurements_visible() const { return measurements_; }
  /// Model (m) to widget (px) transform in use.
  QTransform model_to_widget() const;
  /// Screen position of the key front in the frame shown (where a left drag plays the key).
  std::optional<QPointF> key_front_on_screen() const;
  /// Active contacts in the frame shown (those drawn with a force arrow).
  int active_contact_count() const { return active_contacts_; }
  /// The labels the latest paint drew (parts, forces, fixtures, adjusters), for tests.
  const QStringList& drawn_labels() const { return drawn_labels_; }
  struct DrawnLabel {
    QString text;
    QRectF box;                      // where its text is
    std::optional<QPointF> feature;  // the point it names (a part's, a force arrow's tip)
    std::optional<QLineF> leader;    // drawn from that point to the text
    bool names_part = false;         // a part's name (a fixture, an adjuster), not a force
    int body = -1;                   // a body's name: its index (its point is inside it)
  };
  /// A force arrow the latest paint drew: its contact, from the contact point to its tip.
  struct DrawnArrow {
    int contact = -1;  // index into the model's contacts
    QPointF base, tip;
    double normal_force_n = 0.0, friction_force_n = 0.0;
  };
  const std::vector<DrawnArrow>& drawn_arrows() const { return drawn_arrows_; }
  /// What the pointer at `at` (widget px) is over: the contact of the nearest force arrow within
  /// a few pixels, named with its force ("capstan–whippen heel: 4.4 N pressing, 0.2 N friction";
  /// the name alone when measurements are hidden), or "" when it is over none. The view's
  /// tooltip.
  QString arrow_tooltip(const QPointF& at) const;
  /// The time, gap and finger force readout the latest paint drew along the top.
  const QString& readout() const { return readout_; }
  /// The same labels with where they went, for tests.
  const std::vector<DrawnLabel>& drawn_label_details() const { return drawn_label_details_; }
  const Frame* frame() const { return frame_ ? &*frame_ : nullptr; }
  QSize sizeHint() const override { return {640, 420}; }

  /// Height over width of the action drawn at rest (every body outline and fixture): about 0.4
  /// for a grand, 0.7 for an upright, whose action stands above the key's back end.
  static double rest_aspect(const ActionModel& model);

 signals:
  /// The key played with the mouse: angle (rad from rest, positive down).
  void keyPlayed(double angle_rad);
  void keyReleased();
  /// The view finished painting a frame (frame() is the frame painted); the window benchmark
  /// counts these and times the slider-to-visible-change latency with them.
  void framePainted();

 protected:
  bool event(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  void fit();
  void paint_frame(QPainter& painter);
  QPointF to_screen(const Vec2& p) const;
  Vec2 to_model(const QPointF& p) const;
  Vec2 body_point(int body, const Vec2& rest_point);
  /// A point well inside a body's rest outline (body frame, m), where its name goes; computed
  /// once per model.
  const std::optional<Vec2>& inner_point(int body);

  std::optional<Frame> frame_;
  std::shared_ptr<const ActionModel> model_;
  std::unique_ptr<ActionDynamics> dynamics_;
  DynamicsReading reading_;
  bool labels_ = true;
  bool measurements_ = true;
  bool fitted_ = false;
  ViewFocus focus_ = ViewFocus::whole;
  double scale_ = 1000.0;  // px per m
  QPointF offset_;         // widget position of the model origin
  int active_contacts_ = 0;
  std::vector<DrawnArrow> drawn_arrows_;
  QStringList drawn_labels_;
  std::vector<DrawnLabel> drawn_label_details_;
  QString readout_;
  // each label's offset from its anchor at the last paint (kept while it stays good)
  QHash<QString, QPointF> label_offsets_;
  std::vector<std::optional<Vec2>> inner_points_;
  std::shared_ptr<const ActionModel> inner_points_model_;  // the model they were found for
  // panning and key play
  QPointF drag_start_;
  QPointF offset_at_drag_;
  bool panning_ = false;
  bool playing_key_ = false;
  double key_angle_at_press_ = 0.0;
  double key_arm_m_ = 0.2;
  double press_y_m_ = 0.0;
};

}  // namespace pat::ui

// Slow motion between recorded frames (ui/frame_history.h): the frame shown between two recorded
// ones blends their state and their readings alike, so that the readout's gap and the arrows'
// forces belong to the parts drawn.
#include "frame_history.h"

#include <QTest>
#include <memory>

using pat::ui::Frame;
using pat::ui::FrameHistory;

namespace {

Frame recorded(double t, double angle, double gap_mm, double force_n,
               std::shared_ptr<const pat::ActionModel> model) {
  Frame f;
  f.t = t;
  f.q = pat::DofVector::Constant(2, angle);
  f.v = pat::DofVector::Constant(2, 10.0 * angle);
  f.angle_deg = {angle, -angle};
  f.hammer_string_gap_mm = gap_mm;
  f.finger_force_n = force_n;
  f.contact_force_n = {force_n, 2.0 * force_n};
  f.strap_tension_n = {0.5 * force_n};
  f.events = {"impact"};
  f.model = std::move(model);
  return f;
}

}  // namespace

class FrameHistoryTest : public QObject {
  Q_OBJECT
 private slots:
  // a history cleared (a restart while a picture sequence is drawn from it) gives an empty frame,
  // not a read past its end
  void an_empty_history_gives_an_empty_frame() {
    const FrameHistory history;
    const Frame f = history.interpolated(0.5);
    QCOMPARE(f.t, 0.0);
    QVERIFY(f.angle_deg.empty());
    QVERIFY(!f.model);
  }
  void between_frames_the_readings_are_blended_with_the_state() {
    const auto model = std::make_shared<const pat::ActionModel>();
    FrameHistory history;
    history.append(recorded(1.0, 1.0, 10.0, 20.0, model));
    history.append(recorded(3.0, 3.0, 6.0, 40.0, model));
    // a quarter of the way: every value a quarter of the way too (exact in binary)
    const Frame f = history.interpolated(1.5);
    QCOMPARE(f.t, 1.5);
    QCOMPARE(f.q[0], 1.5);
    QCOMPARE(f.v[1], 15.0);
    QCOMPARE(f.angle_deg, (std::vector<double>{1.5, -1.5}));
    QCOMPARE(f.hammer_string_gap_mm, 9.0);
    QCOMPARE(f.finger_force_n, 25.0);
    QCOMPARE(f.contact_force_n, (std::vector<double>{25.0, 50.0}));
    QCOMPARE(f.strap_tension_n, (std::vector<double>{12.5}));
    QVERIFY(f.events.empty());  // an event belongs to its recorded frame only
    // a contact that opens (or closes) between the two frames is not blended: the earlier
    // frame's state holds until the next frame
    FrameHistory opening;
    Frame closed = recorded(1.0, 1.0, 10.0, 20.0, model);
    Frame open = recorded(3.0, 3.0, 6.0, 40.0, model);
    open.contact_force_n = {0.0, 80.0};
    closed.strap_tension_n = {0.0};
    opening.append(closed);
    opening.append(open);
    const Frame between = opening.interpolated(1.5);
    QCOMPARE(between.contact_force_n, (std::vector<double>{20.0, 50.0}));
    QCOMPARE(between.strap_tension_n, (std::vector<double>{0.0}));
    // at a recorded frame: that frame as it is, events included
    const Frame at = history.interpolated(3.0);
    QCOMPARE(at.hammer_string_gap_mm, 6.0);
    QCOMPARE(at.events.size(), std::size_t{1});
  }

  void frames_of_two_models_are_not_blended() {
    FrameHistory history;
    history.append(recorded(1.0, 1.0, 10.0, 20.0, std::make_shared<const pat::ActionModel>()));
    history.append(recorded(3.0, 3.0, 6.0, 40.0, std::make_shared<const pat::ActionModel>()));
    const Frame f = history.interpolated(2.0);
    QCOMPARE(f.q[0], 1.0);
    QCOMPARE(f.hammer_string_gap_mm, 10.0);
    QCOMPARE(f.contact_force_n, (std::vector<double>{20.0, 40.0}));
  }
};

QTEST_MAIN(FrameHistoryTest)
#include "frame_history_test.moc"

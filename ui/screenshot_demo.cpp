#include "screenshot_demo.h"

#include <QPixmap>

#include "main_window.h"
#include "measurement_service.h"
#include "playback_controller.h"
#include "run_controls.h"

namespace pat::ui {
namespace {

constexpr int kPollMs = 20;
constexpr int kMaxPolls = 1500;        // give up after 30 s of wall time
constexpr double kNearStringMm = 2.5;  // shown when the hammer first comes this close
constexpr const char* kDemoBlow = "force:pulse:8:80";

}  // namespace

ScreenshotDemo::ScreenshotDemo(MainWindow* window, const QString& path)
    : QObject(window), window_(window), path_(path) {
  poll_timer_.setInterval(kPollMs);
  connect(&poll_timer_, &QTimer::timeout, this, &ScreenshotDemo::poll);
}

void ScreenshotDemo::start() {
  window_->run_controls()->set_speed_index(3);  // 1/10: escapement takes a visible moment
  window_->start(kDemoBlow);
  poll_timer_.start();
}

void ScreenshotDemo::poll() {
  PlaybackController* c = window_->controller();
  if (++polls_ > kMaxPolls) {
    poll_timer_.stop();
    emit finished(false, tr("the demo hammer did not come near the string within 30 s"));
    return;
  }
  if (c->run_stopped()) {
    poll_timer_.stop();
    capture();
    return;
  }
  // the hammer near the string (the jack at the let-off button), passed by the display
  const FrameHistory& h = c->history();
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (h.at(i).hammer_string_gap_mm > kNearStringMm) continue;
    const double t = h.at(i).t;
    if (c->display_time() < t) return;
    poll_timer_.stop();
    c->pause();
    c->seek(t);
    // let the plots and the view repaint before the grab
    QTimer::singleShot(100, this, &ScreenshotDemo::capture);
    return;
  }
}

void ScreenshotDemo::capture() {
  // the regulation panel's measured column fills in the background (a slow press and a forte
  // blow per setting): a picture taken before it is done shows dashes there
  if (window_->measurements()->busy() && ++polls_ <= kMaxPolls) {
    QTimer::singleShot(kPollMs, this, &ScreenshotDemo::capture);
    return;
  }
  const QPixmap shot = window_->grab();
  if (shot.isNull() || !shot.save(path_, "PNG"))
    emit finished(false, tr("could not write the screenshot %1").arg(path_));
  else
    emit finished(true, path_);
}

}  // namespace pat::ui

#include "window_bench.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSlider>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <optional>
#include <stdexcept>

#include "action_view.h"
#include "core/error.h"
#include "gui_application.h"
#include "main_window.h"
#include "playback_controller.h"
#include "plot_panel.h"
#include "plot_stack.h"
#include "regulation_panel.h"
#include "regulation_row.h"
#include "run_controls.h"

namespace pat::ui {
namespace {

constexpr double kWarmUpS = 1.0;         // playback before counting (layout, first replots)
constexpr int kLatencyTimeoutMs = 2000;  // a slider move not shown by then is an error

/// CPU time of the calling thread, ns.
qint64 thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<qint64>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

double load_average() {
  double load[1] = {0.0};
  return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

/// Runs the event loop for `ms` of wall time (the window keeps animating meanwhile).
void run_events_for(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

/// Times every paintEvent of the view: an event filter sees the Paint event before the view
/// draws, framePainted() comes when it has drawn.
class PaintTimer : public QObject {
 public:
  explicit PaintTimer(ActionView* view) : view_(view) {
    view->installEventFilter(this);
    connect(view, &ActionView::framePainted, this, [this] {
      const qint64 now = clock_.nsecsElapsed();
      paints_.push_back({now, (now - paint_start_ns_) * 1e-6,
                         (thread_cpu_ns() - paint_start_cpu_ns_) * 1e-6, view_->frame()->t,
                         view_->frame()->model.get()});
    });
    clock_.start();
  }
  struct Paint {
    qint64 end_ns;        // wall time when the paint finished
    double paint_ms;      // wall time spent in paintEvent
    double paint_cpu_ms;  // CPU time spent in paintEvent
    double t;             // simulated time of the frame painted
    const void* model;    // the frame's model (a moved adjuster makes a new one)
  };
  const std::vector<Paint>& paints() const { return paints_; }
  qint64 now_ns() const { return clock_.nsecsElapsed(); }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched == view_ && event->type() == QEvent::Paint) {
      paint_start_ns_ = clock_.nsecsElapsed();
      paint_start_cpu_ns_ = thread_cpu_ns();
    }
    return false;
  }

 private:
  ActionView* view_;
  QElapsedTimer clock_;
  qint64 paint_start_ns_ = 0;
  qint64 paint_start_cpu_ns_ = 0;
  std::vector<Paint> paints_;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double at = p * (values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(at);
  const double w = at - i;
  return i + 1 < values.size() ? (1 - w) * values[i] + w * values[i + 1] : values[i];
}

void check_running(const PlaybackController& controller, const MainWindow& window,
                   const std::string& input) {
  if (!controller.run_stopped()) return;
  const std::string cause = window.banner_text().toStdString();
  // a run without a single frame never started: the input SPEC was refused
  if (controller.history().empty()) throw InputError("input '" + input + "': " + cause);
  throw std::runtime_error("the run stopped: " + cause);
}

/// Frame-rate part: counts new frames painted between [from_ns, to_ns).
void summarise_frames(const std::vector<PaintTimer::Paint>& paints, qint64 from_ns, qint64 to_ns,
                      WindowBenchResult& r) {
  std::vector<qint64> shown;  // end of each paint that showed a new instant
  std::vector<double> paint_ms;
  double paint_cpu_ms = 0.0;
  const PaintTimer::Paint* previous = nullptr;
  for (const PaintTimer::Paint& p : paints) {
    if (p.end_ns >= from_ns && p.end_ns < to_ns) {
      ++r.paints;
      paint_ms.push_back(p.paint_ms);
      paint_cpu_ms += p.paint_cpu_ms;
      if (!previous || p.t != previous->t || p.model != previous->model) shown.push_back(p.end_ns);
    }
    previous = &p;
  }
  r.new_frames = static_cast<int>(shown.size());
  r.measured_wall_s = (to_ns - from_ns) * 1e-9;
  r.fps_mean = r.new_frames / r.measured_wall_s;
  std::vector<double> intervals;
  for (std::size_t i = 1; i < shown.size(); ++i)
    intervals.push_back((shown[i] - shown[i - 1]) * 1e-6);
  r.frame_interval_p95_ms = percentile(intervals, 0.95);
  r.frame_interval_max_ms =
      intervals.empty() ? 0.0 : *std::max_element(intervals.begin(), intervals.end());
  // fewest frames in a 1 s window starting at any frame (or at the start) that ends in range
  constexpr qint64 kSecondNs = 1'000'000'000;
  int worst = r.new_frames;
  std::vector<qint64> starts{from_ns};
  starts.insert(starts.end(), shown.begin(), shown.end());
  std::size_t lo = 0, hi = 0;
  for (qint64 s : starts) {
    if (s + kSecondNs > to_ns) break;
    while (lo < shown.size() && shown[lo] < s) ++lo;
    hi = std::max(hi, lo);
    while (hi < shown.size() && shown[hi] < s + kSecondNs) ++hi;
    worst = std::min(worst, static_cast<int>(hi - lo));
  }
  r.fps_worst_second = worst;
  if (!paint_ms.empty()) {
    double sum = 0.0;
    for (double ms : paint_ms) sum += ms;
    r.paint_ms_mean = sum / paint_ms.size();
    r.paint_cpu_ms_mean = paint_cpu_ms / paint_ms.size();
    r.paint_ms_max = *std::max_element(paint_ms.begin(), paint_ms.end());
  }
}

/// Moves the adjuster's slider to `mm` and returns the wall time (ms) until the view has
/// painted a frame whose model has that adjuster position.
double time_slider_move(MainWindow& window, RegulationRow& row, const std::string& name,
                        int adjuster, double mm) {
  ActionView* view = window.view();
  const double wanted_m = mm * 1e-3;
  QEventLoop loop;
  QElapsedTimer since_move;
  std::optional<double> latency_ms;
  QObject::connect(view, &ActionView::framePainted, &loop, [&] {
    const Frame* f = view->frame();
    if (f && f->model && std::abs(f->model->adjusters[adjuster].value - wanted_m) < 1e-9) {
      latency_ms = since_move.nsecsElapsed() * 1e-6;
      loop.quit();
    }
  });
  QTimer::singleShot(kLatencyTimeoutMs, &loop, &QEventLoop::quit);
  since_move.start();
  row.slider()->setValue(static_cast<int>(std::lround(mm * 100.0)));  // 0.01 mm per step
  loop.exec();
  if (!latency_ms && window.controller()->run_stopped())
    throw std::runtime_error("the run stopped after " + name + " moved to " + std::to_string(mm) +
                             " mm: " + window.banner_text().toStdString());
  if (!latency_ms)
    throw std::runtime_error("no frame with the moved " + name + " was painted within " +
                             std::to_string(kLatencyTimeoutMs) + " ms");
  return *latency_ms;
}

}  // namespace

WindowBenchResult run_window_bench(const WindowBenchOptions& options) {
  if (!(options.duration_s > 0.0)) throw InputError("--duration must be positive");
  if (options.latency_trials < 0) throw InputError("latency trials must not be negative");
  const std::unique_ptr<QApplication> app = application_if_none();
  if (app) {
    // the window's settings (layout, last preset) of the user are neither read nor written
    QApplication::setOrganizationName("PianoActionTrainer");
    QApplication::setApplicationName("pianoaction-bench");
  }
  WindowBenchResult r;
  r.load_before = load_average();
  r.platform = QApplication::platformName().toStdString();

  MainWindow window;
  window.resize(1280, 800);
  window.open_action(options.action);
  RegulationRow* row = window.regulation()->row(options.adjuster);
  if (!row) throw InputError("no adjuster '" + options.adjuster + "' in " + options.action);
  const int adjuster = window.model()->adjuster_index(options.adjuster);
  window.show();
  window.run_controls()->set_speed_index(0);  // real time
  window.start(options.input);
  PlaybackController* controller = window.controller();
  PaintTimer timer(window.view());

  run_events_for(static_cast<int>(kWarmUpS * 1000));
  check_running(*controller, window, options.input);
  r.window_width = window.width(), r.window_height = window.height();
  r.view_width = window.view()->width(), r.view_height = window.view()->height();

  // frame rate and real-time factor over the measured span
  int replots = 0;
  double replot_ms = 0.0;
  std::vector<QMetaObject::Connection> replot_counters;
  for (PlotPanel* panel : window.plots()->panels())
    replot_counters.push_back(QObject::connect(panel, &PlotPanel::replotted, [&](double ms) {
      ++replots;
      replot_ms += ms;
    }));
  const qint64 from_ns = timer.now_ns();
  const qint64 cpu_from_ns = thread_cpu_ns();
  const double sim_from = controller->display_time();
  run_events_for(static_cast<int>(options.duration_s * 1000));
  const qint64 to_ns = timer.now_ns();
  r.window_thread_cpu_percent = 100.0 * (thread_cpu_ns() - cpu_from_ns) / (to_ns - from_ns);
  const double sim_to = controller->display_time();
  for (const auto& c : replot_counters) QObject::disconnect(c);
  r.replots_per_s = replots / ((to_ns - from_ns) * 1e-9);
  r.replot_ms_mean = replots > 0 ? replot_ms / replots : 0.0;
  check_running(*controller, window, options.input);
  summarise_frames(timer.paints(), from_ns, to_ns, r);
  r.realtime_factor = (sim_to - sim_from) / ((to_ns - from_ns) * 1e-9);

  // slider to visible change, at gaps that do not lock to the 16 ms redraw timer
  for (int i = 0; i < options.latency_trials; ++i) {
    run_events_for(200 + (i * 7) % 16);
    const double mm = (i % 2 == 0 ? 1.0 : -1.0) * options.adjuster_step_mm;
    r.latency_ms.push_back(time_slider_move(window, *row, options.adjuster, adjuster, mm));
    check_running(*controller, window, options.input);
  }
  if (!r.latency_ms.empty()) {
    r.latency_median_ms = percentile(r.latency_ms, 0.5);
    r.latency_max_ms = *std::max_element(r.latency_ms.begin(), r.latency_ms.end());
  }
  r.load_after = load_average();
  return r;
}

}  // namespace pat::ui

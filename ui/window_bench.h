// Speed of the trainer window (DESIGN.md section 7, issue 5), for `pianoaction bench --window`:
// the real MainWindow plays an input at real time (playback speed 1) while the frames the action
// view paints are counted against the wall clock; then a regulation slider is moved while the
// run goes on, and the wall time from the slider change until the view has painted a frame
// computed with the new adjuster position is measured. Figures only: nothing here passes or
// fails on timing.
#pragma once

#include <string>
#include <vector>

namespace pat::ui {

struct WindowBenchOptions {
  std::string action = "grand";              ///< grand, upright or a preset file
  std::string input = "motion:sine:5:full";  ///< the input SPEC played at real time
  double duration_s = 5.0;                   ///< wall seconds over which frames are counted
  int latency_trials = 10;                   ///< slider moves timed
  std::string adjuster = "hammer_blow";      ///< the adjuster whose slider is moved
  double adjuster_step_mm = 0.1;             ///< slider moves alternate between ±this
};

struct WindowBenchResult {
  std::string platform;  ///< Qt platform plugin (xcb under Xvfb, offscreen, ...)
  int window_width = 0, window_height = 0;
  int view_width = 0, view_height = 0;  ///< the action view's size (px): paint cost grows with it
  double measured_wall_s = 0.0;
  int paints = 0;                      ///< paintEvents of the action view with a frame
  int new_frames = 0;                  ///< paints showing another instant than the paint before
  double fps_mean = 0.0;               ///< new frames painted per wall second
  double fps_worst_second = 0.0;       ///< fewest new frames in any 1 s window (sliding)
  double frame_interval_p95_ms = 0.0;  ///< 95th percentile of the wall time between new frames
  double frame_interval_max_ms = 0.0;
  double paint_ms_mean = 0.0;  ///< wall time of one paintEvent (drawing into the backing store)
  double paint_ms_max = 0.0;
  /// CPU time of one paintEvent, ms: unlike the wall time above, not stretched by other load.
  double paint_cpu_ms_mean = 0.0;
  /// CPU time of the window's thread per wall second, % of one core (paints, replots, playback).
  double window_thread_cpu_percent = 0.0;
  /// Replots of the live plots (all panels) per wall second and the time of one, ms: they share
  /// the window's thread with the action view.
  double replots_per_s = 0.0;
  double replot_ms_mean = 0.0;
  /// Displayed simulated time per wall second over the measurement (1 = keeps real time).
  double realtime_factor = 0.0;
  /// Slider change to the end of the first paint with the new adjuster position, ms.
  std::vector<double> latency_ms;
  double latency_median_ms = 0.0;
  double latency_max_ms = 0.0;
  /// 1-minute load average of the machine before and after (other work shares the cores).
  double load_before = 0.0, load_after = 0.0;
};

/// Runs the benchmark in a window of 1280×800 (creates the QApplication when there is none).
/// Throws InputError for a bad action, input or adjuster, std::runtime_error when the run
/// stops or a slider move never shows.
WindowBenchResult run_window_bench(const WindowBenchOptions& options);

}  // namespace pat::ui

// pianoaction bench --window: frame rate, real-time factor and slider latency of the trainer
// window (DESIGN.md section 7; ui/window_bench.h says what is measured).
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>

#include "command_line.h"
#include "commands.h"
#include "core/error.h"
#include "inputs/key_input.h"
#include "model/preset_loader.h"
#include "plot_output.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"
#ifdef PAT_HAVE_UI
#include "window_bench.h"
#endif

namespace pat::app {

int run_bench_window(const std::vector<std::string>& args) {
#ifdef PAT_HAVE_UI
  const CommandLine cl(args, {"--duration", "--input", "--action", "--trials", "--plot"},
                       {"--window", "--json"});
  ui::WindowBenchOptions options;
  options.duration_s = cl.positive_number_or("--duration", options.duration_s);
  options.input = cl.value_or("--input", options.input);
  options.action = cl.value_or("--action", options.action);
  if (cl.has("--trials")) {
    const double trials = parse_number(cl.value("--trials"), "--trials");
    if (trials < 1 || trials > 1000 || trials != static_cast<int>(trials))
      throw InputError("--trials must be a whole number from 1 to 1000, got " +
                       cl.value("--trials"));
    options.latency_trials = static_cast<int>(trials);
  }
  const PlotOption plot(cl);
  {
    // a bad action or input SPEC is refused before the window opens, where it would only show
    // in the banner of a run that never starts
    const ActionModel model = load_action(options.action);
    parse_input_spec(options.input, input_context(model, find_rest_state(model)));
  }
  const ui::WindowBenchResult r = ui::run_window_bench(options);
  // each slider move's latency, in the order the moves were made
  PlotSpec latency =
      time_plot("Slider to visible change (" + options.adjuster + ")", "latency (ms)");
  latency.x_title = "slider move";
  latency.x_column = "move";
  latency.x_unit = "";
  PlotCurve moves = point_curve("latency", "latency_ms");
  for (std::size_t i = 0; i < r.latency_ms.size(); ++i) {
    moves.add(double(i + 1), r.latency_ms[i]);
  }
  latency.curves.push_back(std::move(moves));
  plot.write({latency}, !cl.has("--json"));
  if (cl.has("--json")) {
    std::cout << nlohmann::json{{"action", options.action},
                                {"input", options.input},
                                {"platform", r.platform},
                                {"window_px", {r.window_width, r.window_height}},
                                {"view_px", {r.view_width, r.view_height}},
                                {"measured_wall_s", r.measured_wall_s},
                                {"paints", r.paints},
                                {"new_frames", r.new_frames},
                                {"fps_mean", r.fps_mean},
                                {"fps_worst_second", r.fps_worst_second},
                                {"frame_interval_p95_ms", r.frame_interval_p95_ms},
                                {"frame_interval_max_ms", r.frame_interval_max_ms},
                                {"paint_ms_mean", r.paint_ms_mean},
                                {"paint_ms_max", r.paint_ms_max},
                                {"paint_cpu_ms_mean", r.paint_cpu_ms_mean},
                                {"window_thread_cpu_percent", r.window_thread_cpu_percent},
                                {"plot_replots_per_s", r.replots_per_s},
                                {"plot_replot_ms_mean", r.replot_ms_mean},
                                {"realtime_factor", r.realtime_factor},
                                {"adjuster", options.adjuster},
                                {"latency_ms", r.latency_ms},
                                {"latency_median_ms", r.latency_median_ms},
                                {"latency_max_ms", r.latency_max_ms},
                                {"load_average", {r.load_before, r.load_after}}}
                     .dump(1)
              << "\n";
    return 0;
  }
  std::cout << std::fixed << std::setprecision(1);
  std::cout << options.action << " window (" << r.window_width << "x" << r.window_height
            << ", action view " << r.view_width << "x" << r.view_height << ", platform "
            << r.platform << "), " << options.input << " at real time, " << r.measured_wall_s
            << " s measured\n";
  std::cout << "  frames painted    " << r.fps_mean << " /s mean, " << r.fps_worst_second
            << " in the worst 1 s; interval p95 " << r.frame_interval_p95_ms << " ms, max "
            << r.frame_interval_max_ms << " ms\n";
  std::cout << "  paintEvent        " << std::setprecision(2) << r.paint_ms_mean << " ms mean, "
            << r.paint_ms_max << " ms max (wall), " << r.paint_cpu_ms_mean << " ms CPU\n";
  std::cout << "  window thread     " << std::setprecision(0) << r.window_thread_cpu_percent
            << " % of one core\n";
  std::cout << "  plot replots      " << std::setprecision(1) << r.replots_per_s
            << " /s (of one panel), " << std::setprecision(2) << r.replot_ms_mean << " ms each\n";
  std::cout << "  real-time factor  " << std::setprecision(3) << r.realtime_factor << "\n";
  std::cout << std::setprecision(1) << "  slider latency    " << options.adjuster << " moved "
            << r.latency_ms.size() << " times: median " << r.latency_median_ms << " ms, worst "
            << r.latency_max_ms << " ms (to the first paint with the new position)\n";
  std::cout << std::setprecision(2) << "  load average      " << r.load_before << " before, "
            << r.load_after << " after\n";
  return 0;
#else
  (void)args;
  throw InputError("--window: this build has no trainer window (configured with PAT_ENGINE_ONLY)");
#endif
}

}  // namespace pat::app

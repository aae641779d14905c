// pianoaction bench: speed and accuracy figures (DESIGN.md section 7).
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>

#include "analysis/bench.h"
#include "command_line.h"
#include "commands.h"
#include "plot_output.h"

namespace pat::app {
namespace {

/// Speed and error of each case side by side (the work–precision comparison of the methods).
std::vector<PlotSpec> bench_plots(const std::vector<BenchCase>& cases) {
  PlotSpec speed = category_plot("Speed", "× real time", "case", "case_index");
  PlotSpec error = category_plot("Error against rodas (rtol 1e-9)",
                                 "max hammer error (% of its range)", "case", "case_index");
  PlotCurve factor = point_curve("real-time factor", "realtime_factor");
  PlotCurve percent = point_curve("error", "max_error_percent_of_range");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const BenchCase& c = cases[i];
    speed.x_categories.push_back(c.action + " " + c.integrator + " " + c.setting);
    factor.add(double(i), c.realtime_factor);
    percent.add(double(i), 100.0 * c.max_error_deg / c.hammer_range_deg);
  }
  error.x_categories = speed.x_categories;
  speed.curves = {std::move(factor)};
  error.curves = {std::move(percent)};
  return {speed, error};
}

}  // namespace

int run_bench(const std::vector<std::string>& args) {
  for (const std::string& a : args)
    if (a == "--window") return run_bench_window(args);
  const CommandLine cl(args, {"--duration", "--input", "--plot"}, {"--json"});
  const PlotOption plot(cl);
  BenchOptions options;
  options.duration_s = cl.positive_number_or("--duration", 1.0);
  options.input = cl.value_or("--input", options.input);
  const std::vector<BenchCase> cases = run_bench(options);
  const std::vector<EqualAccuracy> comparisons = compare_at_equal_accuracy(cases);
  plot.write(bench_plots(cases), !cl.has("--json"));
  if (cl.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (const BenchCase& c : cases)
      list.push_back(
          {{"action", c.action},
           {"integrator", c.integrator},
           {"setting", c.setting},
           {"realtime_factor", c.realtime_factor},
           {"wall_time_s", c.wall_time_s},
           {"steps", c.steps},
           {"max_error_deg", c.max_error_deg},
           {"max_error_percent_of_range", 100.0 * c.max_error_deg / c.hammer_range_deg}});
    nlohmann::json equal = nlohmann::json::array();
    for (const EqualAccuracy& e : comparisons) {
      nlohmann::json item{{"action", e.action},
                          {"w2_realtime_factor", e.w2_realtime_factor},
                          {"w2_max_error_deg", e.w2_error_deg},
                          {"cvode_setting", nullptr},
                          {"cvode_realtime_factor", nullptr},
                          {"cvode_max_error_deg", nullptr},
                          {"w2_over_cvode", nullptr}};
      if (e.cvode) {
        item["cvode_setting"] = e.cvode->setting;
        item["cvode_realtime_factor"] = e.cvode->realtime_factor;
        item["cvode_max_error_deg"] = e.cvode->max_error_deg;
        item["w2_over_cvode"] = e.ratio;
      }
      equal.push_back(item);
    }
    std::cout << nlohmann::json{{"input", options.input},
                                {"duration_s", options.duration_s},
                                {"reference", "rodas rtol=1e-9"},
                                {"cases", list},
                                {"equal_accuracy", equal}}
                     .dump(1)
              << "\n";
    return 0;
  }
  std::cout << "double blow " << options.input << ", " << options.duration_s
            << " s simulated; error = max |hammer angle - rodas(rtol 1e-9)|\n";
  std::cout << std::left << std::setw(9) << "action" << std::setw(8) << "method" << std::setw(12)
            << "setting" << std::right << std::setw(12) << "x realtime" << std::setw(10) << "steps"
            << std::setw(14) << "error (deg)" << std::setw(12) << "% of range"
            << "\n";
  for (const BenchCase& c : cases)
    std::cout << std::left << std::setw(9) << c.action << std::setw(8) << c.integrator
              << std::setw(12) << c.setting << std::right << std::setw(12) << std::fixed
              << std::setprecision(1) << c.realtime_factor << std::setw(10) << c.steps
              << std::setw(14) << std::setprecision(4) << c.max_error_deg << std::setw(12)
              << std::setprecision(2) << 100.0 * c.max_error_deg / c.hammer_range_deg << "\n";
  std::cout << "w2 against the fastest cvode at least as accurate:\n";
  for (const EqualAccuracy& e : comparisons) {
    std::cout << "  " << e.action << ": w2 " << std::setprecision(1) << e.w2_realtime_factor
              << "x (" << std::setprecision(4) << e.w2_error_deg << " deg)";
    if (e.cvode)
      std::cout << ", cvode " << e.cvode->setting << " " << std::setprecision(1)
                << e.cvode->realtime_factor << "x (" << std::setprecision(4)
                << e.cvode->max_error_deg << " deg): w2/cvode = " << std::setprecision(2) << e.ratio
                << "\n";
    else
      std::cout << ", no cvode setting as accurate\n";
  }
  return 0;
}

}  // namespace pat::app

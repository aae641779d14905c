// pianoaction simulate: one run under a key input (DESIGN.md section 5).
#include <iostream>
#include <nlohmann/json.hpp>

#include "action_setup.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"
#include "plot_output.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat::app {

nlohmann::json events_json(const std::vector<SimEvent>& events) {
  nlohmann::json list = nlohmann::json::array();
  for (const SimEvent& e : events) {
    nlohmann::json item{
        {"type", e.type}, {"t_s", e.t}, {"hammer_string_gap_mm", e.hammer_string_gap * 1e3}};
    if (e.type == "impact") item["hammer_velocity_mps"] = e.hammer_velocity;
    list.push_back(item);
  }
  return list;
}

int run_simulate(const std::vector<std::string>& args) {
  const CommandLine cl(args,
                       {"--action", "--input", "--duration", "--integrator", "--step", "--rtol",
                        "--set", "--without", "--effect", "--out", "--plot", "--sample-interval"},
                       {"--json"});
  const ActionModel model = load_configured_action(cl);
  SimulationOptions options;
  options.duration_s = cl.positive_number("--duration");
  options.integrator = cl.value_or("--integrator", "w2");
  make_integrator(options.integrator, options.integrator_options);  // validates the name early
  // each integrator's own accuracy knob: the W-method's fixed step, the adaptive methods'
  // tolerance (the other one would be ignored without a word)
  const bool fixed_step = options.integrator == "w2";
  if (fixed_step && cl.has("--rtol"))
    throw InputError("--rtol sets the tolerance of rodas and cvode; w2 takes a fixed --step");
  if (!fixed_step && cl.has("--step"))
    throw InputError("--step sets w2's fixed step; " + options.integrator +
                     " chooses its own steps (set its tolerance with --rtol)");
  options.integrator_options.fixed_step_s =
      cl.positive_number_or("--step", options.integrator_options.fixed_step_s);
  options.integrator_options.relative_tolerance =
      cl.positive_number_or("--rtol", options.integrator_options.relative_tolerance);
  // beyond these the run's numbers mean nothing although it may end "ok": a felt contact lasts a
  // few milliseconds (w2 at 1 ms already drives the capstan 63 mm into the whippen under 5 N),
  // and a tolerance of more than 10 % lets cvode and rodas step through the felts (each checked
  // where it was given; w2's default step is checked against the duration below)
  constexpr double kLargestStepS = 1e-3, kLargestRtol = 0.1;
  // and below these a run takes hours without telling more: a hundredth of w2's default step
  // already makes a second of the action minutes long, and a tolerance a tenth of the bench's
  // reference (rodas at 1e-9) is as fine as any comparison here needs (rodas at 1e-14 took 21 s
  // for 10 ms; at 1e-20 it did not end)
  constexpr double kSmallestStepS = 1e-7, kSmallestRtol = 1e-10;
  if (cl.has("--step")) {
    if (options.integrator_options.fixed_step_s < kSmallestStepS)
      throw InputError("--step " + cl.value("--step") +
                       ": w2's step must be at least 1e-7 s (1e-5 s is the default; 1e-7 s "
                       "already takes minutes for a second of the action)");
    if (options.integrator_options.fixed_step_s > kLargestStepS)
      throw InputError("--step " + cl.value("--step") +
                       ": w2's step must be at most 0.001 s (1e-5 s is the default; a felt "
                       "contact lasts a few milliseconds)");
  }
  // at least 10 of w2's steps in the run, the default step's too (--duration 1e-9 had run one
  // step of 1e-9 s and reported step_s 1e-5); --step is given only with w2
  const double step = options.integrator_options.fixed_step_s;
  if (fixed_step && step > 0.1 * options.duration_s)
    throw InputError(
        cl.has("--step")
            ? "--step " + cl.value("--step") + ": at least 10 steps must fit in --duration " +
                  cl.value("--duration")
            : "--duration " + cl.value("--duration") + ": w2 steps " + format_number(step) +
                  " s by default and at least 10 steps must fit in a "
                  "run (give at least " +
                  format_number(10.0 * step) + " s, or a smaller --step)");
  if (cl.has("--rtol") && options.integrator_options.relative_tolerance > kLargestRtol)
    throw InputError("--rtol " + cl.value("--rtol") +
                     ": a relative tolerance must be at most 0.1 (1e-6 is the default)");
  if (cl.has("--rtol") && options.integrator_options.relative_tolerance < kSmallestRtol)
    throw InputError("--rtol " + cl.value("--rtol") +
                     ": a relative tolerance must be at least 1e-10 (1e-6 is the default; the "
                     "bench's reference takes 1e-9; rodas at 1e-14 takes half a minute for "
                     "10 ms)");
  // absolute tolerance on angles (rad) and rates (rad/s): a hundredth of the relative one, as
  // the bench's references take it
  options.integrator_options.absolute_tolerance =
      1e-2 * options.integrator_options.relative_tolerance;
  options.sample_interval_s = cl.positive_number_or("--sample-interval", 1e-4);
  options.trace_final_state = true;
  const RestState rest = find_rest_state(model);
  const auto input = parse_input_spec(cl.value("--input"), input_context(model, rest));
  const std::string out_path = cl.output_path("--out");
  const PlotOption plot(cl);

  // a recording shorter than the run: its last value goes on, which the user should know
  const std::string notes = input_notes(*input, options.duration_s);

  SimulationResult result = simulate(model, input.get(), options, &rest);
  // how the trace was made, beyond what the engine records: the accuracy asked for and the
  // effects added to the model
  result.trace.metadata[fixed_step ? "step_s" : "rtol"] =
      format_number(fixed_step ? options.integrator_options.fixed_step_s
                               : options.integrator_options.relative_tolerance,
                    6);
  std::string effects;
  for (const std::string& e : cl.values("--effect")) effects += (effects.empty() ? "" : " ") + e;
  if (!effects.empty()) result.trace.metadata["effects"] = effects;
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(trace_plots(result.trace));
  if (!out_path.empty()) write_csv(out_path, result.trace);

  if (cl.has("--json")) {
    nlohmann::json out{{"status", result.status},
                       {"stop_cause", result.status == "ok" ? nlohmann::json(nullptr)
                                                            : nlohmann::json(result.stop_cause)},
                       {"end_t_s", result.end_time},
                       {"events", events_json(result.events)},
                       {"realtime_factor", result.realtime_factor},
                       {"steps", result.steps},
                       {"rhs_evaluations", result.rhs_evaluations},
                       {"action", model.kind},
                       {"input", input->spec()},
                       {"integrator", options.integrator},
                       {"rest_hammer_string_gap_mm", rest.hammer_string_gap * 1e3}};
    // how the run was made, so that a JSON kept alone says it: the accuracy asked for, the model's
    // changes, and what the user should know of the input
    if (fixed_step)
      out["step_s"] = options.integrator_options.fixed_step_s;
    else
      out["rtol"] = options.integrator_options.relative_tolerance;
    out["set"] = cl.values("--set");
    out["without"] = cl.values("--without");
    out["effects"] = cl.values("--effect");
    out["input_notes"] = notes.empty() ? nlohmann::json(nullptr) : nlohmann::json(notes);
    std::cout << out.dump(1) << "\n";
    if (!notes.empty()) std::cerr << "note: " << notes << "\n";
  } else {
    std::cout << model.name << ", input " << input->spec() << ", " << options.integrator << ": "
              << result.status;
    if (result.status != "ok")
      std::cout << " at t = " << result.end_time << " s (" << result.stop_cause << ")";
    std::cout << "\n";
    if (!notes.empty()) std::cout << "  note: " << notes << "\n";
    for (const SimEvent& e : result.events) {
      std::cout << "  " << e.t * 1e3 << " ms  " << e.type << "  hammer-string gap "
                << e.hammer_string_gap * 1e3 << " mm";
      if (e.type == "impact") std::cout << "  hammer velocity " << e.hammer_velocity << " m/s";
      std::cout << "\n";
    }
    std::cout << "  " << result.steps << " steps, " << result.realtime_factor << "x real time\n";
    if (!out_path.empty()) std::cout << "  trace written to " << out_path << "\n";
    if (plot.given()) std::cout << "  plot written to " << plot.path() << "\n";
  }
  if (result.status != "ok") {
    // a script must see it without reading the output: exit code 3 (2 is bad input, 1 a failure
    // before any result); what was computed up to the stop has been written
    std::cerr << "pianoaction simulate: the run stopped at t = "
              << format_number(result.end_time, 6) << " s: " << result.stop_cause << "\n";
    return kExitRunStopped;
  }
  return 0;
}

}  // namespace pat::app

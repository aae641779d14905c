// Speed of the engine's hot paths and of the analyses whose speed the issues name (Google
// Benchmark; DESIGN.md section 7: speed is measured here and by `pianoaction bench`, never by timed
// tests). Each benchmark reports per-iteration time and, where it simulates, `realtime` (simulated
// seconds per wall-clock second: the figure of the 20x goal).
//
//   build/tests/benchmarks/engine_benchmarks                         all (about half a minute)
//   build/tests/benchmarks/engine_benchmarks --benchmark_filter=Rhs  one family
//
// The states the right-hand side is timed at are those of a real double blow (the cull of apart
// contacts, contact_cull.h, depends on how far consecutive states are from each other, so an
// artificial state would time a different code path).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "analysis/repetition_sweep.h"
#include "analysis/sensitivity.h"
#include "dynamics/action_dynamics.h"
#include "dynamics/force_laws.h"
#include "integrators/small_lu.h"
#include "model/preset_loader.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"
#include "sim/simulator.h"

namespace pat {
namespace {

const char* const kDoubleBlow = "force:double:20:40:60";  // bench's input (analysis/bench.h)

/// One action with its rest state and the double blow, loaded once per benchmark.
struct ActionFixture {
  std::shared_ptr<const ActionModel> model;
  RestState rest;
  std::shared_ptr<const KeyInput> input;

  explicit ActionFixture(const std::string& action)
      : model(std::make_shared<const ActionModel>(load_action(action))),
        rest(find_rest_state(*model)),
        input(parse_input_spec(kDoubleBlow, input_context(*model, rest))) {}
};

const char* action_of(const benchmark::State& state) {
  return state.range(0) == 0 ? "grand" : "upright";
}

/// The integrated states of every w2 step of the first `duration_s` of the double blow.
std::vector<StateVector> double_blow_states(const ActionFixture& fixture, double duration_s) {
  SimulationOptions options;
  options.duration_s = duration_s;
  Simulator simulator(fixture.model, fixture.input, options, &fixture.rest);
  std::vector<StateVector> states;
  while (simulator.time() < duration_s && simulator.step(duration_s))
    states.push_back(simulator.dynamics().compress(simulator.q(), simulator.v()));
  return states;
}

/// One right-hand-side evaluation f(t, y) (positions, contacts, mass matrix, forces, solve), at
/// successive states of the double blow's first 0.2 s (strike, check and second blow).
void BM_Rhs(benchmark::State& state) {
  const ActionFixture fixture(action_of(state));
  const std::vector<StateVector> states = double_blow_states(fixture, 0.2);
  if (states.empty()) {
    state.SkipWithError("the double blow stopped before its first step");
    return;
  }
  ActionDynamics dynamics(*fixture.model, fixture.input.get());
  StateVector dydt(dynamics.dimension());
  std::size_t i = 0;
  for (auto _ : state) {
    dynamics.rhs(1e-5 * static_cast<double>(i), states[i], dydt);
    benchmark::DoNotOptimize(dydt.data());
    if (++i == states.size()) i = 0;
  }
  state.SetLabel(action_of(state));
}
BENCHMARK(BM_Rhs)->Arg(0)->Arg(1);

/// The whole w2 run at 1e-5 s, as `pianoaction bench` times it: 1 s of the double blow (steps,
/// events, penetration checks; no trace).
void BM_DoubleBlowW2(benchmark::State& state) {
  const ActionFixture fixture(action_of(state));
  SimulationOptions options;
  options.duration_s = 1.0;
  options.sample_interval_s = 0.0;
  long steps = 0;
  for (auto _ : state) {
    Simulator simulator(fixture.model, fixture.input, options, &fixture.rest);
    simulator.advance_to(options.duration_s);
    steps += simulator.steps();
    if (simulator.stopped()) state.SkipWithError(simulator.stop_cause().c_str());
  }
  state.counters["realtime"] = benchmark::Counter(
      options.duration_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // wall time per step (shown in seconds: "1.1us")
  state.counters["per_step"] = benchmark::Counter(
      static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(action_of(state));
}
BENCHMARK(BM_DoubleBlowW2)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// The felt law with hysteresis while unloading (two exponentials and a tanh).
void BM_FeltNormalForce(benchmark::State& state) {
  FeltLaw law;
  law.loading = {2e4, 900.0, 1e3};
  law.unloading = {1e4, 1000.0, 5e2};
  law.alpha = 30.0;
  double x = 1e-4;
  for (auto _ : state) {
    benchmark::DoNotOptimize(felt_normal_force(law, x, -0.3));
    x = x < 1e-3 ? x * 1.01 : 1e-4;
  }
}
BENCHMARK(BM_FeltNormalForce);

/// The W-method's 6x6 solve (the grand's Schur complement), twice per step.
void BM_SmallLuSolve6(benchmark::State& state) {
  SmallLu::Matrix a = SmallLu::Matrix::Random();
  a.topLeftCorner(6, 6) += 8.0 * SmallLu::Matrix::Identity().topLeftCorner(6, 6);
  SmallLu lu;
  lu.compute(a, 6);
  SmallLu::Vector b = SmallLu::Vector::Random();
  for (auto _ : state) {
    SmallLu::Vector x = b;
    lu.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_SmallLuSolve6);

/// The full-stroke chirp sweep to 20 Hz on the grand (issue: under 5 s wall time), its segments
/// on the available cores as `pianoaction sweep` runs it.
void BM_FullStrokeChirpSweep(benchmark::State& state) {
  const ActionModel model = load_action("grand");
  SweepOptions options;
  options.stroke = Stroke::full;
  for (auto _ : state) benchmark::DoNotOptimize(run_repetition_sweep(model, options));
}
BENCHMARK(BM_FullStrokeChirpSweep)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

/// The grand's sensitivity table (issue: under 60 s on both cores).
void BM_SensitivityTable(benchmark::State& state) {
  const ActionModel model = load_action("grand");
  for (auto _ : state) benchmark::DoNotOptimize(sensitivity(model, SensitivityOptions{}));
}
BENCHMARK(BM_SensitivityTable)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace pat

BENCHMARK_MAIN();

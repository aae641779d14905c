#include "measured/synth.h"

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "measured/model_trace.h"

namespace pat {

CsvTable synthesize(const ActionModel& base, const std::string& input_spec, const SynthOptions& o) {
  if (!(o.fps > 0) || !std::isfinite(o.fps)) throw InputError("--fps must be a positive number");
  // high-speed cameras film at up to about 100,000 frames a second; more is a slip that would
  // fill the memory with samples
  if (o.fps > 1e5) throw InputError("--fps must be at most 100000 frames per second");
  if (!(o.duration_s > 0)) throw InputError("--duration must be positive");
  // a sensor's noise is a fraction of a degree; more than 10° (a fifth of the hammer's travel)
  // is a slip (1e308 had written inf into the file)
  if (!(o.noise_deg >= 0) || o.noise_deg > 10)
    throw InputError("--noise-deg must be from 0 to 10 degrees");
  if (!std::isfinite(o.time_offset_s) || std::abs(o.time_offset_s) > 0.1)
    throw InputError("--time-offset-ms must be within ±100 ms");
  if (!std::isfinite(o.angle_offset_deg) || std::abs(o.angle_offset_deg) > 10)
    throw InputError("--angle-offset-deg must be within ±10 degrees");
  ActionModel model = base;
  std::string effects_text;
  for (const Effect& e : o.effects) {
    model = with_effect(model, e);
    if (!effects_text.empty()) effects_text += ' ';
    effects_text += describe(e, describe_effect(base, e.name));
  }
  // the model runs past the end of the file by the offset (samples at t − offset)
  const double run_s = o.duration_s + std::max(0.0, -o.time_offset_s) + 1e-3;
  // a fine grid (0.05 ms) so that linear resampling adds no visible error at 2000 fps
  const ModelTrace trace = simulate_trace(model, input_spec, run_s, 5e-5);
  if (!trace.completed) throw std::runtime_error("the synthetic run stopped: " + trace.stop_cause);

  CsvTable table;
  table.metadata["action"] = model.kind;
  table.metadata["input"] = input_spec;
  std::ostringstream settings;
  settings << "fps " << o.fps << ", noise " << o.noise_deg << " deg, time offset "
           << o.time_offset_s * 1e3 << " ms, angle offset " << o.angle_offset_deg << " deg, seed "
           << o.seed;
  table.metadata["synth_settings"] = settings.str();
  table.metadata["synth_effects"] = effects_text.empty() ? "none" : effects_text;
  const bool has_force = !trace.key_force_n.empty();
  table.columns = {"time_s", "hammer_angle_deg", "key_angle_deg"};
  if (has_force) table.columns.push_back("key_force_n");

  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const long samples = static_cast<long>(std::floor(o.duration_s * o.fps + 1e-9)) + 1;
  for (long k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k) / o.fps;
    const double tm = t - o.time_offset_s;  // model time
    std::vector<double> row{t, trace.hammer_at(tm) + o.angle_offset_deg + o.noise_deg * noise(rng),
                            trace.key_at(tm) + o.noise_deg * noise(rng)};
    if (has_force) {
      const std::size_t i = tm <= 0 ? 0 : static_cast<std::size_t>(tm / trace.dt);
      row.push_back(tm < 0 ? 0.0 : trace.key_force_n[std::min(i, trace.key_force_n.size() - 1)]);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace pat

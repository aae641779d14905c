// Measured data and the diagnosis (measured/*.h): reading and checking files, events in a
// trace, the hidden-effect experiment (a reduced set here; the full matrix runs in
// `pianoaction bench-diagnose`), the null test and the shipped real strike.
#include "measured/diagnosis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "core/error.h"
#include "core/format.h"
#include "measured/alignment.h"
#include "measured/diagnosis_report.h"
#include "measured/discrepancies.h"
#include "measured/hidden_effects.h"
#include "measured/measured_data.h"
#include "measured/synth.h"
#include "test_support.h"

namespace pat {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("pat_measured_" + name);
  std::ofstream(path) << text;
  return path.string();
}

// A synthetic measured file of `spec` on `model` (synthesize's `options`), written under `name`
// and read back as diagnose reads a file.
MeasuredTrial synthetic_trial(const ActionModel& model, const std::string& spec,
                              const SynthOptions& options, const std::string& name) {
  const std::string path = write_temp(name, "");
  write_csv(path, synthesize(model, spec, options));
  return read_measured(path, model.kind);
}

std::string read_error(const std::string& text, const std::string& action = "grand") {
  const std::string path = write_temp("bad.csv", text);
  try {
    read_measured(path, action);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string rows(int n, double dt) {
  std::string out;
  for (int i = 0; i < n; ++i) out += std::to_string(i * dt) + ",0.0\n";
  return out;
}

TEST(MeasuredData, BadFilesGetClearMessages) {
  EXPECT_NE(read_error("time_s,key_angle_deg\n" + rows(30, 5e-4))
                .find("missing column 'hammer_angle_deg'"),
            std::string::npos);
  EXPECT_NE(read_error("hammer_angle_deg\n0\n1\n").find("missing column 'time_s'"),
            std::string::npos);
  EXPECT_NE(read_error("time_s,hammer_angle_deg\n" + rows(30, 5e-4) + "0.001,0\n")
                .find("line 32: time_s is not increasing"),
            std::string::npos);
  const std::string nan = read_error("time_s,hammer_angle_deg\n0,0\n0.0005,nan\n" + rows(30, 5e-4));
  EXPECT_NE(nan.find("line 3"), std::string::npos) << nan;
  EXPECT_NE(read_error("# action: upright\ntime_s,hammer_angle_deg\n" + rows(30, 5e-4))
                .find("measured on the upright action ('# action: upright') but the grand"),
            std::string::npos);
  EXPECT_NE(read_error("time_s,hammer_angle_deg\n" + rows(30, 5e-3))
                .find("too slow to resolve the hammer-string impact"),
            std::string::npos);
  EXPECT_NE(read_error("time_s,hammer_angle_deg\n" + rows(5, 5e-4)).find("only 5 samples"),
            std::string::npos);
}

TEST(MeasuredData, SynthWritesTheMeasuredFormatWithItsOffsets) {
  const ActionModel grand = test::shipped("grand");
  SynthOptions o;
  o.duration_s = 0.2;
  o.time_offset_s = 4e-3;
  o.angle_offset_deg = 0.3;
  const CsvTable table = synthesize(grand, "force:pulse:20:80", o);
  EXPECT_EQ(table.metadata.at("action"), "grand");
  EXPECT_EQ(table.metadata.at("input"), "force:pulse:20:80");
  ASSERT_EQ(table.columns, (std::vector<std::string>{"time_s", "hammer_angle_deg", "key_angle_deg",
                                                     "key_force_n"}));
  EXPECT_EQ(table.rows.size(), 401u);  // 0.2 s at 2000 fps, both ends
  // before the input starts (file time < offset) the hammer is at rest + the angle offset,
  // without noise exactly
  EXPECT_DOUBLE_EQ(table.rows[0][1], 0.3);
  EXPECT_DOUBLE_EQ(table.rows[7][1], 0.3);
  // the impact of the synthetic trace comes the offset later than the model's
  const SimulationResult r = test::run(grand, "force:pulse:20:80", 0.2);
  const auto impacts = test::events_of(r, "impact");
  ASSERT_FALSE(impacts.empty());
  const MeasuredTrial trial = measured_from_table(table, "synthetic", "grand");
  const auto events = detect_events(trial.t, trial.hammer_deg, 0.0);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().type, "impact");
  // the sampled peak lies within one frame (0.5 ms) of the contact start + its duration (the
  // peak comes at maximum felt compression, < 1 ms after first contact)
  EXPECT_NEAR(events.front().t, impacts.front()->t + 4e-3, 1.5e-3);
}

TEST(MeasuredData, RealStrikeIsFoundWithin2msOfThePeak) {
  const MeasuredTrial trial = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_fast_strike.csv", "grand");
  const auto peak = std::max_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  const double t_peak = trial.t[static_cast<std::size_t>(peak - trial.hammer_deg.begin())];
  const auto events = detect_events(trial.t, trial.hammer_deg, estimate_noise(trial.hammer_deg));
  const auto impact = std::find_if(events.begin(), events.end(),
                                   [](const MeasuredEvent& e) { return e.type == "impact"; });
  ASSERT_NE(impact, events.end());
  EXPECT_NEAR(impact->t, t_peak, 2e-3);
  // one strike: the shank's ringing after it is not a second impact
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const MeasuredEvent& e) { return e.type == "impact"; }),
            1);
}

TEST(Diagnosis, RealStrikeRunsEndToEnd) {
  const ActionModel grand = test::shipped("grand");
  const MeasuredTrial trial = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_fast_strike.csv", "grand");
  DiagnoseOptions options;
  options.candidates = {"shank_flex", "felt_stiffness.hammer_head_string"};
  const Diagnosis d = diagnose(grand, {trial}, options);
  ASSERT_EQ(d.trials.size(), 1u);
  const TrialReport& r = d.trials.front();
  EXPECT_TRUE(r.input_estimated);
  EXPECT_EQ(r.input_spec.rfind("force:pulse:", 0), 0u) << r.input_spec;
  // the file ends with the hammer still held in check: the estimated key is held past the 0.5 s
  // compared (a release inside it would be the model's alone)
  const double pulse_ms = std::stod(r.input_spec.substr(r.input_spec.rfind(':') + 1));
  EXPECT_GT(pulse_ms, 500.0) << r.input_spec;
  ASSERT_FALSE(r.measured_events.empty());
  EXPECT_EQ(r.measured_events.front().type, "impact");
  // the strike on the model's clock is still the data's peak
  const auto peak = std::max_element(r.data.hammer_deg.begin(), r.data.hammer_deg.end());
  EXPECT_NEAR(r.measured_events.front().t,
              r.data.t[static_cast<std::size_t>(peak - r.data.hammer_deg.begin())], 2e-3);
  // and the report says where that strike is in the file: at its peak, 186 ms
  const auto impact_time =
      std::find_if(r.discrepancies.features.begin(), r.discrepancies.features.end(),
                   [](const FeatureDiscrepancy& f) { return f.feature == "impact_time"; });
  ASSERT_NE(impact_time, r.discrepancies.features.end());
  const auto file_peak = std::max_element(trial.hammer_deg.begin(), trial.hammer_deg.end());
  const double file_peak_ms =
      1e3 * trial.t[static_cast<std::size_t>(file_peak - trial.hammer_deg.begin())];
  const std::size_t at =
      impact_time->text.find("measured ", impact_time->text.find("model's clock"));
  ASSERT_NE(at, std::string::npos) << impact_time->text;
  EXPECT_NEAR(std::stod(impact_time->text.substr(at + 9)), file_peak_ms, 2.0) << impact_time->text;
  // so do the exports: the shift, and each event's time in the file
  EXPECT_NEAR(r.measured_events.front().t + r.file_time_shift_s, file_peak_ms * 1e-3, 2e-3);
  const nlohmann::json json = diagnosis_json(d);
  EXPECT_EQ(json["trials"][0]["file_time_shift_s"].get<double>(), r.file_time_shift_s);
  EXPECT_NEAR(json["measured_events"][0]["file_t_s"].get<double>(), file_peak_ms * 1e-3, 2e-3);
  EXPECT_EQ(trial_traces_table(r).metadata.at("file_time_shift_s"),
            format_number(r.file_time_shift_s, 9));
  EXPECT_FALSE(d.held_out);
  // one trial: leave-one-out is impossible, so no held-out error is given, and the gain says it
  // is measured on the fitted trial itself
  for (const CandidateFit& c : d.ranking) EXPECT_TRUE(std::isnan(c.validated_rms_deg)) << c.effect;
  EXPECT_NE(d.gain_basis.find("one trial"), std::string::npos) << d.gain_basis;
  EXPECT_EQ(d.ranking.size(), 2u);
  EXPECT_FALSE(d.discrepancies.empty());
  EXPECT_GT(d.baseline_rms_deg, 0.0);
  // a cause named on an estimated input says so
  if (d.cause)
    EXPECT_NE(d.verdict.find("the input was estimated from the hammer"), std::string::npos)
        << d.verdict;
  // an offset is named only where the mean carries the residual: the rest phase had read "higher
  // than the model by 0.00 deg" for a residual of 0.22 deg rms swinging about zero
  for (const std::string& line : d.discrepancies)
    EXPECT_EQ(line.find("than the model by 0.00 deg"), std::string::npos) << line;
}

TEST(Diagnosis, RealStrikeWithItsKeyMotionStrikesWhenTheRealHammerDoes) {
  // The recording's own key sensor drives the model (import-raw --key-column; the file's
  // README): no estimated input and no time offset, since both columns share one clock.
  const ActionModel grand = test::shipped("grand");
  const MeasuredTrial trial = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_strike_with_key.csv", "grand");
  ASSERT_EQ(trial.key_deg.size(), trial.t.size());
  DiagnoseOptions options;
  options.candidates = {"repetition_spring"};
  const Diagnosis d = diagnose(grand, {trial}, options);
  ASSERT_EQ(d.trials.size(), 1u);
  const TrialReport& r = d.trials.front();
  EXPECT_FALSE(r.input_estimated);
  EXPECT_EQ(r.input_spec, "csv:" + trial.path);
  EXPECT_EQ(r.baseline_alignment.time_offset_s, 0.0);
  // Validation on real data: the measured impact is the sensor's peak at 186.1 ms (0.5 ms
  // samples); the model strikes at 184.4 ms. Within 3 ms: the rise from the key's first
  // motion to the strike takes about 35 ms, so this is the model's timing within 10 %.
  ASSERT_FALSE(r.measured_events.empty());
  ASSERT_EQ(r.measured_events.front().type, "impact");
  ASSERT_FALSE(r.baseline.impact_t.empty());
  EXPECT_NEAR(r.baseline.impact_t.front(), r.measured_events.front().t, 3e-3);
  // and the backcheck holds the hammer where the real one is held (13.0 deg measured, 12.3
  // modelled, before the angle offset): within 1 deg, 5 % of the 21 deg stroke
  ASSERT_FALSE(r.baseline.check_t.empty());
  const auto check = std::find_if(r.measured_events.begin(), r.measured_events.end(),
                                  [](const MeasuredEvent& e) { return e.type == "check"; });
  ASSERT_NE(check, r.measured_events.end());
  EXPECT_NEAR(r.baseline.hammer_at(r.baseline.check_t.front()), check->angle_deg, 1.0);
}

/// A model's hammer trace as a measured file records it: `samples` + 1 samples at 2000 fps.
MeasuredTrial sampled_at_2000_fps(const ModelTrace& m, const std::string& path, int samples) {
  MeasuredTrial trial;
  trial.path = path;
  for (int i = 0; i <= samples; ++i) {
    trial.t.push_back(i * 5e-4);
    trial.hammer_deg.push_back(m.hammer_at(i * 5e-4));
  }
  return trial;
}

/// The stroke's start (deg, t < 0.09 s): at rest, a rise from 50 ms to the string (21 deg) at
/// 80 ms, caught at 13 deg by 90 ms.
double rise_and_catch_deg(double t) {
  if (t < 0.05) return 0.0;
  if (t < 0.08) return 21.0 * (t - 0.05) / 0.03;
  return 21.0 - 8.0 * (t - 0.08) / 0.01;
}

/// A measured stroke at 2000 fps (0 … 0.6 s): the rise and catch above, held (creeping 2 deg/s)
/// while the key stays down; the key rises from 0.30 s, and the hammer falls back to rest from
/// 0.31 to 0.40 s.
MeasuredTrial measured_stroke() {
  MeasuredTrial trial;
  trial.path = "stroke.csv";
  for (int i = 0; i <= 1200; ++i) {
    const double t = i * 5e-4;
    double a = 0.0;
    if (t < 0.09)
      a = rise_and_catch_deg(t);
    else if (t < 0.31)
      a = 13.0 + 2.0 * (t - 0.09);
    else if (t < 0.40)
      a = 13.44 * (0.40 - t) / 0.09;
    double key = 0.0;
    if (t >= 0.045 && t < 0.07)
      key = 5.0 * (t - 0.045) / 0.025;
    else if (t >= 0.07 && t < 0.30)
      key = 5.0;
    else if (t >= 0.30 && t < 0.36)
      key = 5.0 * (0.36 - t) / 0.06;
    trial.t.push_back(t);
    trial.hammer_deg.push_back(a);
    trial.key_deg.push_back(key);
  }
  return trial;
}

TEST(Discrepancies, PhasesComeFromTheMeasurementAndTheKeyNotFromTheModel) {
  // The model judged follows the measured stroke until the key rises, then its repetition lever
  // throws the hammer up slowly (30 deg/s, 13.4 to 18 deg until 0.45 s): the real Kawai strikes'
  // error. Labelled from the model, that throw was "rebound_and_check" (held: below 50 deg/s)
  // and the check was blamed for the release's error; the key rising means release.
  const MeasuredTrial trial = measured_stroke();
  ModelTrace m;
  m.dt = 1e-4;
  for (int i = 0; i <= 6000; ++i) {
    const double t = i * m.dt;
    double a = 17.92;  // thrown up, then held there
    if (t < 0.09)
      a = rise_and_catch_deg(t);
    else if (t < 0.30)
      a = 13.0 + 2.0 * (t - 0.09);
    else if (t < 0.45)
      a = 13.42 + 30.0 * (t - 0.30);
    m.hammer_deg.push_back(a);
    m.key_deg.push_back(0.0);
  }
  m.escapement_t = {0.078};
  m.impact_t = {0.080};
  m.check_t = {0.090};
  Alignment al;
  al.residual.assign(trial.t.size(), 0.0);
  const auto events = detect_events(trial.t, trial.hammer_deg, 0.01);
  const TrialDiscrepancies d = find_discrepancies(trial, m, al, events, 0.01);
  auto phase_at = [&](double t) {
    return d.phase_of_sample[static_cast<std::size_t>(std::lround(t / 5e-4))];
  };
  EXPECT_EQ(phase_at(0.02), "rest");
  EXPECT_EQ(phase_at(0.055), "acceleration");
  EXPECT_EQ(phase_at(0.0785), "free_flight");  // from the model's let-off; impact 1 ms before
  EXPECT_EQ(phase_at(0.080), "impact");
  EXPECT_EQ(phase_at(0.2), "rebound_and_check");  // held, creeping, the key down
  EXPECT_EQ(phase_at(0.299), "rebound_and_check");
  EXPECT_EQ(phase_at(0.32), "release");  // the key rises: whatever the model does
  EXPECT_EQ(phase_at(0.36), "release");
  EXPECT_EQ(phase_at(0.5), "return");
}

// A key held down is not released: a 1 kg mass presses the key 3.0° into its punching at the
// blow and holds it at 2.7° (an overshoot of a tenth of its travel), and a key read with 0.2°
// of noise scatters by more than the 5 % of its travel that used to mean "rising"; both had
// labelled most of the held key "release". A key that is let up (a 4 Hz sine) still is.
TEST(Discrepancies, AHeldKeyIsNotReleasedByItsOvershootOrItsNoise) {
  const ActionModel grand = test::shipped("grand");
  auto phase_counts = [&](const std::string& spec, double noise_deg, const std::string& name) {
    SynthOptions o;
    o.duration_s = 0.4;
    o.noise_deg = noise_deg;
    o.seed = 5;
    DiagnoseOptions options;
    options.candidates = {"joint_friction.key"};
    const Diagnosis d = diagnose(grand, {synthetic_trial(grand, spec, o, name)}, options);
    std::map<std::string, int> count;
    for (const std::string& phase : d.trials.front().discrepancies.phase_of_sample) ++count[phase];
    return count;
  };
  for (double noise : {0.0, 0.2}) {
    auto held = phase_counts("mass:1kg", noise, "held.csv");
    EXPECT_EQ(held["release"], 0) << "noise " << noise;
    EXPECT_GT(held["rebound_and_check"], 600) << "noise " << noise;  // of 801 samples
    auto let_up = phase_counts("motion:sine:4", noise, "sine.csv");
    // the key is let up at 0.25 s, a quarter-period after the bottom: release, then return
    EXPECT_GT(let_up["release"], 150) << "noise " << noise;
    EXPECT_GT(let_up["rebound_and_check"], 150) << "noise " << noise;
  }
}

TEST(Discrepancies, TheResidualOscillationIsReadOverOneStretchAndOnlyAsAPeak) {
  const MeasuredTrial trial = measured_stroke();
  ModelTrace m;
  m.dt = 1e-4;
  for (int i = 0; i <= 6000; ++i) {
    m.hammer_deg.push_back(0.0);
    m.key_deg.push_back(0.0);
  }
  m.escapement_t = {0.078};
  const auto events = detect_events(trial.t, trial.hammer_deg, 0.01);
  Alignment al;
  al.residual.assign(trial.t.size(), 0.0);
  // phases first (they do not depend on the residual)
  const std::vector<std::string> phases =
      find_discrepancies(trial, m, al, events, 0.01).phase_of_sample;
  auto residual_feature = [](const TrialDiscrepancies& d) {
    for (const FeatureDiscrepancy& f : d.features)
      if (f.feature == "residual_oscillation") return f;
    return FeatureDiscrepancy{};
  };
  // a 150 Hz ringing of 0.5 deg in the check, a drift and a step elsewhere: found at 150 Hz
  // (the search steps by a quarter of 1/0.22 s, about 1.1 Hz; 2 Hz of tolerance) and 0.5 deg
  // (within 10 %: the stretch holds 32 whole periods, the leakage is small)
  for (std::size_t i = 0; i < trial.t.size(); ++i)
    al.residual[i] = phases[i] == "rebound_and_check" ? 0.5 * std::sin(2 * kPi * 150.0 * trial.t[i])
                     : phases[i] == "release"         ? -2.0
                                                      : 0.1 * trial.t[i];
  TrialDiscrepancies d = find_discrepancies(trial, m, al, events, 0.01);
  EXPECT_NEAR(d.residual_oscillation_hz, 150.0, 2.0);
  EXPECT_NEAR(d.residual_oscillation_deg, 0.5, 0.05);
  // a property of the residual alone: nothing measured or modelled to compare
  EXPECT_FALSE(residual_feature(d).measured_known);
  EXPECT_FALSE(residual_feature(d).model_known);
  // a slow curved drift in the check (2 deg over its 0.22 s) is no oscillation: after the
  // detrend and the window it leaves nothing above the noise in the range searched, and nothing
  // is reported (the old transform reported the 10 Hz floor of its search)
  for (std::size_t i = 0; i < trial.t.size(); ++i) {
    const double x = (trial.t[i] - 0.082) / 0.22;
    al.residual[i] = phases[i] == "rebound_and_check" ? 2.0 * x * x : 0.0;
  }
  d = find_discrepancies(trial, m, al, events, 0.01);
  EXPECT_EQ(d.residual_oscillation_hz, 0.0);
  EXPECT_NE(residual_feature(d).text.find("no oscillation"), std::string::npos)
      << residual_feature(d).text;
}

TEST(Diagnosis, EachLeaveOneOutFitNeverSeesItsHeldOutTrial) {
  // Three synthetic trials with the repetition spring at 0.5: the fit that leaves the first out
  // must be the fit on the other two alone, from scratch (it had started from the fit on all
  // three and moved two steps, so it equalled that fit to 16 digits on the real strikes)
  const ActionModel grand = test::shipped("grand");
  const std::vector<MeasuredTrial> trials =
      hidden_effect_trials(grand, Effect{"repetition_spring", 0.5}, 3);
  DiagnoseOptions options;
  options.candidates = {"repetition_spring"};
  const Diagnosis all = diagnose(grand, trials, options);
  const Diagnosis without_first = diagnose(grand, {trials[1], trials[2]}, options);
  ASSERT_EQ(all.ranking.front().fold_values.size(), 3u);
  // the same scan grid and the same local fits on the same two trials: equal to rounding
  EXPECT_NEAR(all.ranking.front().fold_values[0], without_first.ranking.front().value, 1e-9);
  ASSERT_TRUE(all.cause.has_value());
  EXPECT_NE(all.gain_basis.find("held-out"), std::string::npos) << all.gain_basis;
  // each trial's held-out error is reported, under the fit made without it
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(all.trials[j].held_out_effect, "repetition_spring");
    EXPECT_NEAR(all.trials[j].held_out_value, all.ranking.front().fold_values[j], 1e-12);
    EXPECT_TRUE(std::isfinite(all.trials[j].held_out_rms_deg));
    // and the extended model's error phase by phase beside the baseline's
    for (const PhaseResidual& p : all.trials[j].discrepancies.phases) EXPECT_TRUE(p.has_extended);
  }
}

// Two candidates can fit the trials they see about equally well and still predict a trial they
// did not see very differently: a 150 Hz shank flex hidden in a 1 kg blow and a 4 Hz sine is fitted
// by the shank flex to 0.205° and by a backcheck compliance to 0.222° (within the 22 % that makes
// a ranking ambiguous), but held out the compliance leaves 3.8° and the flex 0.20°. The ranking
// and the ambiguity test are on the held-out error, so the flex is named.
TEST(Diagnosis, TheHeldOutErrorTellsApartCandidatesThatFitTheTrialsEqually) {
  const ActionModel grand = test::shipped("grand");
  auto trial = [&](const std::string& spec, double time_offset_s, unsigned long long seed) {
    SynthOptions o;
    o.duration_s = 0.4;
    o.effects = {Effect{"shank_flex", 150.0}};
    o.noise_deg = 0.2;
    o.time_offset_s = time_offset_s;
    o.seed = seed;
    return synthetic_trial(grand, spec, o, "flex_" + std::to_string(seed) + ".csv");
  };
  const std::vector<MeasuredTrial> trials = {trial("mass:1kg", 2e-3, 1),
                                             trial("motion:sine:4", -1e-3, 2)};
  DiagnoseOptions options;
  options.candidates = {"shank_flex", "backcheck_compliance", "repetition_spring"};
  const Diagnosis d = diagnose(grand, trials, options);
  ASSERT_EQ(d.ranking.size(), 3u);
  for (const CandidateFit& c : d.ranking)
    std::printf("%s: training %.3f, held-out %.3f deg\n", c.effect.c_str(), c.training_rms_deg,
                c.validated_rms_deg);
  const CandidateFit& flex = d.ranking[0];
  EXPECT_EQ(flex.effect, "shank_flex");
  // the rival fits the seen trials within the ambiguity margin (rms ratio below √1.5): the
  // training error alone could not tell them apart
  const auto rival = std::find_if(d.ranking.begin(), d.ranking.end(), [](const CandidateFit& c) {
    return c.effect == "backcheck_compliance";
  });
  ASSERT_NE(rival, d.ranking.end());
  EXPECT_LT(rival->training_rms_deg, std::sqrt(kMinRunnerUpRatio) * flex.training_rms_deg);
  // held out, it does not come near
  EXPECT_GT(rival->validated_rms_deg, 3.0 * flex.validated_rms_deg);
  // ranked by the held-out error, best first
  for (std::size_t i = 1; i < d.ranking.size(); ++i)
    EXPECT_LE(d.ranking[i - 1].validated_rms_deg, d.ranking[i].validated_rms_deg);
  ASSERT_TRUE(d.cause.has_value()) << d.verdict;
  EXPECT_FALSE(d.ambiguous);
  EXPECT_EQ(d.cause->name, "shank_flex");
  EXPECT_NEAR(d.cause->value, 150.0, 7.5);  // 5 %: measured 148.9 Hz under 0.2° noise
  EXPECT_NE(d.verdict.find("shank_flex"), std::string::npos) << d.verdict;
}

// Why no cause is named is said: a model within the noise needs none; a model far off that no
// candidate explains is not "within the noise".
TEST(Diagnosis, TheVerdictSaysWhyNoCauseIsNamed) {
  const ActionModel grand = test::shipped("grand");
  auto one_trial = [&](const std::vector<Effect>& hidden, const std::string& name) {
    SynthOptions o;
    o.duration_s = 0.3;
    o.effects = hidden;
    o.noise_deg = 0.2;
    o.seed = 7;
    return synthetic_trial(grand, "force:pulse:10:80", o, name);
  };
  DiagnoseOptions options;
  options.candidates = {"joint_friction.key"};
  const Diagnosis clean = diagnose(grand, {one_trial({}, "clean.csv")}, options);
  EXPECT_FALSE(clean.cause.has_value());
  EXPECT_NE(clean.verdict.find("the model is within the noise"), std::string::npos)
      << clean.verdict;
  // a hammer blow 1 mm off hidden: the key's friction cannot explain it
  const Diagnosis off = diagnose(
      grand, {one_trial({Effect{"regulation_offset.hammer_blow", 1.0}}, "off.csv")}, options);
  EXPECT_FALSE(off.cause.has_value());
  EXPECT_GT(off.baseline_rms_deg, 2.0 * off.noise_deg);
  EXPECT_NE(off.verdict.find("no candidate explains the discrepancy"), std::string::npos)
      << off.verdict;
  EXPECT_NE(off.verdict.find("joint_friction.key"), std::string::npos) << off.verdict;
}

// A file with the finger's measured force (key_force_n) and neither its input line nor the key's
// angle: the force drives the model. It had been left unread and a force pulse estimated
// instead, whose misfit (4.6 deg) was blamed on shank_flex, absent from the data.
TEST(Diagnosis, AMeasuredKeyForceDrivesTheModel) {
  const ActionModel grand = test::shipped("grand");
  SynthOptions o;
  o.duration_s = 0.3;
  o.noise_deg = 0.2;
  o.seed = 5;
  CsvTable table = synthesize(grand, "force:pulse:20:100", o);
  table.metadata.erase("input");
  const int key_angle = table.column_index("key_angle_deg");
  ASSERT_GE(key_angle, 0);
  ASSERT_GE(table.column_index("key_force_n"), 0);
  table.columns.erase(table.columns.begin() + key_angle);
  for (auto& row : table.rows) row.erase(row.begin() + key_angle);
  const std::string path = write_temp("force_only.csv", "");
  write_csv(path, table);
  const MeasuredTrial trial = read_measured(path, "grand");
  EXPECT_TRUE(trial.key_force_measured);
  DiagnoseOptions options;
  options.candidates = {"shank_flex"};
  const Diagnosis d = diagnose(grand, {trial}, options);
  ASSERT_EQ(d.trials.size(), 1u);
  EXPECT_FALSE(d.trials[0].input_estimated);
  EXPECT_EQ(d.trials[0].input_spec, "csv:" + path);
  EXPECT_FALSE(d.cause.has_value()) << d.verdict;
  EXPECT_NE(d.verdict.find("the model is within the noise"), std::string::npos) << d.verdict;
}

// A file 30 ms late on its input's clock (synth allows ±100 ms): the offset search (±10 ms) ends
// at its edge. That had been taken as the offset without a word, and the exact model's misfit
// read as a model error; now the trial, its discrepancies and the verdict say not to trust it.
TEST(Diagnosis, AClockOffsetBeyondTheSearchIsSaid) {
  const ActionModel grand = test::shipped("grand");
  auto trial_late_by = [&](double offset_s, const std::string& name) {
    SynthOptions o;
    o.duration_s = 0.3;
    o.noise_deg = 0.2;
    o.time_offset_s = offset_s;
    return synthetic_trial(grand, "mass:1kg", o, name);
  };
  DiagnoseOptions options;
  options.candidates = {"shank_flex"};
  const Diagnosis late = diagnose(grand, {trial_late_by(0.03, "late.csv")}, options);
  ASSERT_EQ(late.trials.size(), 1u);
  EXPECT_TRUE(late.trials[0].time_offset_at_limit);
  EXPECT_EQ(late.verdict.rfind("Not to be trusted: ", 0), 0u) << late.verdict;
  ASSERT_FALSE(late.discrepancies.empty());
  EXPECT_NE(late.discrepancies.front().find("at the edge of the ±10 ms searched"),
            std::string::npos)
      << late.discrepancies.front();
  // 3 ms late: within the search, nothing said
  const Diagnosis near = diagnose(grand, {trial_late_by(0.003, "near.csv")}, options);
  EXPECT_FALSE(near.trials[0].time_offset_at_limit);
  EXPECT_EQ(near.verdict.find("Not to be trusted"), std::string::npos) << near.verdict;
}

// A cause found among one candidate has no rival: the verdict says it was the only one compared
// (it had read as a decision among candidates).
TEST(Diagnosis, ACauseFromTheOnlyCandidateSaysSo) {
  const ActionModel grand = test::shipped("grand");
  SynthOptions o;
  o.duration_s = 0.3;
  o.noise_deg = 0.1;
  o.effects = {Effect{"repetition_spring", 2.5}};
  DiagnoseOptions options;
  options.candidates = {"repetition_spring"};
  const Diagnosis d =
      diagnose(grand, {synthetic_trial(grand, "mass:1kg", o, "only_candidate.csv")}, options);
  ASSERT_TRUE(d.cause.has_value()) << d.verdict;
  EXPECT_NE(d.verdict.find("it was the only candidate compared"), std::string::npos) << d.verdict;
  EXPECT_EQ(d.verdict.find("estimated"), std::string::npos) << d.verdict;
}

TEST(Discrepancies, AModelComparedWithItsOwnTraceDiffersInNoFeature) {
  // The model's trace, sampled at 2000 fps as a measured file: every feature must read the same
  // on both sides. (The model's impact event is its felt's first touch, the file's impact the
  // felt's deepest point, 1.1 ms later for this 5 N blow: compared directly they differed.)
  const ActionModel grand = test::shipped("grand");
  const ModelTrace m = simulate_trace(grand, "force:pulse:5:40", 0.2);
  ASSERT_TRUE(m.completed) << m.stop_cause;
  ASSERT_FALSE(m.impact_t.empty());
  const MeasuredTrial trial = sampled_at_2000_fps(m, "own_trace.csv", 400);
  Alignment al;
  al.residual.assign(trial.t.size(), 0.0);
  const double noise_deg = 0.01;
  const TrialDiscrepancies d = find_discrepancies(
      trial, m, al, detect_events(trial.t, trial.hammer_deg, noise_deg), noise_deg);
  int compared = 0;
  for (const FeatureDiscrepancy& f : d.features) {
    if (!f.measured_known || f.feature == "residual_oscillation") continue;
    ++compared;
    // the same samples through the same rule: equal to rounding
    EXPECT_NEAR(f.difference, 0.0, 1e-9) << f.text;
  }
  EXPECT_GE(compared, 3);  // impact time, hammer rate before it, check angle, settling level
}

// A model hammer at rest for `rest_s`, then rising at `rate_deg_per_s`: `samples` + 1 points
// on a 0.1 ms grid, the key still.
ModelTrace rest_then_rise(double rest_s, double rate_deg_per_s, int samples) {
  ModelTrace m;
  m.dt = 1e-4;
  for (int i = 0; i <= samples; ++i) {
    const double t = i * m.dt;
    m.hammer_deg.push_back(t < rest_s ? 0.0 : rate_deg_per_s * (t - rest_s));
    m.key_deg.push_back(0.0);
  }
  return m;
}

TEST(Alignment, TheAngleOffsetIsTakenWhereTheActionRests) {
  // a model at rest for 10 ms, then a rise of 20°; the "measurement" reads 0.2° high (its
  // calibration) and, during the rise, a further 3° low (what the model gets wrong there)
  const ModelTrace m = rest_then_rise(0.01, 200.0, 1000);
  MeasuredTrial trial;
  std::vector<bool> at_rest;
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 5e-4;
    trial.t.push_back(t);
    trial.hammer_deg.push_back(m.hammer_at(t) + 0.2 - (t < 0.01 ? 0.0 : 3.0));
    at_rest.push_back(t < 0.01);
  }
  // least squares takes the whole mean: 0.2 − 3·(181/201) = −2.50°, and shows +2.70° at rest
  const Alignment fitted = align(trial, m, 0.0);
  EXPECT_NEAR(fitted.angle_offset_deg, 0.2 - 3.0 * 181.0 / 201.0, 1e-9);
  EXPECT_NEAR(fitted.residual.front(), 3.0 * 181.0 / 201.0, 1e-9);
  // at rest: the calibration's 0.2°, the residual 0 there and the 3° where the model is wrong
  // (exact: no noise, and the model trace is linear between its 0.1 ms points)
  const Alignment shown = referenced_to_rest(fitted, at_rest);
  EXPECT_NEAR(shown.angle_offset_deg, 0.2, 1e-9);
  EXPECT_NEAR(shown.residual.front(), 0.0, 1e-9);
  EXPECT_NEAR(shown.residual.back(), -3.0, 1e-9);
  EXPECT_NEAR(shown.rss, 181.0 * 9.0, 1e-6);
  // too few samples at rest to know the offset from: unchanged
  std::vector<bool> few(at_rest.size(), false);
  for (std::size_t i = 0; i + 1 < kMinRestSamplesForOffset; ++i) few[i] = true;
  EXPECT_EQ(referenced_to_rest(fitted, few).angle_offset_deg, fitted.angle_offset_deg);
}

TEST(Discrepancies, EachPhaseHasItsOwnNoise) {
  // a sensor that scatters ten times more near rest than in flight (the real Kawai files: 0.2 deg
  // against 0.02 deg): each phase's noise is estimated from its own samples. A model at rest for
  // 0.2 s, then rising at 100 deg/s; the measurement is the model plus seeded Gaussian noise of
  // 0.2 deg at rest and 0.02 deg after.
  ModelTrace m = rest_then_rise(0.2, 100.0, 4000);
  m.escapement_t = {0.5};  // after the trace: the rise is all acceleration
  MeasuredTrial trial;
  trial.path = "noisy_rest.csv";
  std::mt19937 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 800; ++i) {  // 0 … 399.5 ms every 0.5 ms
    const double t = i * 5e-4;
    trial.t.push_back(t);
    trial.hammer_deg.push_back(m.hammer_at(t) + (t < 0.2 ? 0.2 : 0.02) * unit(rng));
  }
  Alignment al;
  al.residual.assign(trial.t.size(), 0.0);
  const double whole = estimate_noise(trial.hammer_deg);
  const TrialDiscrepancies d = find_discrepancies(trial, m, al, {}, whole);
  auto noise_of = [&](const std::string& phase) {
    for (const PhaseResidual& p : d.phases)
      if (p.phase == phase) return p.noise_deg;
    return -1.0;
  };
  // about 400 second differences per phase: the MAD estimate scatters by about 8 % there
  // (1.1/√n for a median, more for second differences, which are correlated); 35 % keeps the
  // test far from flaky and still tells 0.2 from 0.02
  EXPECT_NEAR(noise_of("rest"), 0.2, 0.35 * 0.2);
  EXPECT_NEAR(noise_of("acceleration"), 0.02, 0.35 * 0.02);
  // the whole trace's estimate lies between and fits neither phase
  EXPECT_GT(whole, 1.5 * noise_of("acceleration"));
  EXPECT_LT(whole, 0.75 * noise_of("rest"));
}

TEST(Diagnosis, AnglesInRadiansOrOfTheWrongSignAreRefused) {
  // the real strike peaks at the grand's 21 deg contact angle; the same trace in radians, or
  // with its sign reversed, is refused with what looks wrong instead of being fitted
  const MeasuredTrial real = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_fast_strike.csv", "grand");
  auto error_for = [&](double factor) {
    MeasuredTrial t = real;
    for (double& a : t.hammer_deg) a *= factor;
    try {
      diagnose(test::shipped("grand"), {t});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string radians = error_for(kPi / 180.0);
  EXPECT_NE(radians.find("are the angles in radians"), std::string::npos) << radians;
  EXPECT_NE(radians.find("kawai_kg3c_e4_fast_strike.csv"), std::string::npos) << radians;
  const std::string reversed = error_for(-1.0);
  EXPECT_NE(reversed.find("is the sign reversed"), std::string::npos) << reversed;
  // the key's column in radians (the strike with its key, its key angles × π/180): a key that
  // never goes down had driven the model, and the hammer's strike read as the model's error
  MeasuredTrial with_key = read_measured(
      std::string(PAT_ASSET_DIR) + "/measured/kawai_kg3c_e4_strike_with_key.csv", "grand");
  ASSERT_FALSE(with_key.key_deg.empty());
  for (double& a : with_key.key_deg) a *= kPi / 180.0;
  std::string key_radians = "no error";
  try {
    diagnose(test::shipped("grand"), {with_key});
  } catch (const InputError& e) {
    key_radians = e.what();
  }
  EXPECT_NE(key_radians.find("are the key angles in radians"), std::string::npos) << key_radians;
}

TEST(Diagnosis, AStrikeNoForcePulseCanMakeIsRefused) {
  // the hammer pushed up to the string over 0.45 s (a slow press), then rebounding into check:
  // every force pulse that strikes does so within about 0.1 s, so none is fitted to it
  std::string text = "time_s,hammer_angle_deg\n";
  for (int i = 0; i < 2000; ++i) {
    const double t = i * 5e-4;
    double a = 0.0;
    if (t > 0.56)
      a = 13.0;
    else if (t > 0.55)
      a = 21.0 - 8.0 * (t - 0.55) / 0.01;
    else if (t > 0.1)
      a = 21.0 * (t - 0.1) / 0.45;
    text += std::to_string(t) + "," + std::to_string(a) + "\n";
  }
  const MeasuredTrial trial = read_measured(write_temp("slow_press.csv", text), "grand");
  try {
    diagnose(test::shipped("grand"), {trial});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("slow_press.csv"), std::string::npos) << message;
    EXPECT_NE(message.find("a force pulse cannot make this strike"), std::string::npos) << message;
    EXPECT_NE(message.find("softest pulse (3 N)"), std::string::npos) << message;
  }
}

TEST(Diagnosis, MissingInputWithoutAStrikeIsNamed) {
  const std::string path = write_temp("flat.csv", "time_s,hammer_angle_deg\n" + rows(200, 5e-4));
  const MeasuredTrial trial = read_measured(path, "grand");
  try {
    diagnose(test::shipped("grand"), {trial});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no key input is known"), std::string::npos);
  }
}

// The null test: nothing hidden → no cause, for several seeds (a reduced library here: a factor
// and a geometric offset; the whole library runs in bench-diagnose).
class NullDiagnosis : public ::testing::TestWithParam<int> {};
TEST_P(NullDiagnosis, NamesNoCause) {
  const ActionModel grand = test::shipped("grand");
  const HiddenEffectOutcome o =
      run_hidden_effect_case(grand, std::nullopt, static_cast<unsigned long long>(GetParam()),
                             {"joint_friction.hammer", "regulation_offset.let_off"});
  EXPECT_FALSE(o.diagnosis.cause.has_value())
      << "false discovery: " << o.diagnosis.cause->name << " = " << o.diagnosis.cause->value;
  // the baseline error is the noise (0.3°) up to its sampling spread
  EXPECT_NEAR(o.diagnosis.baseline_rms_deg, 0.3, 0.03);
}
INSTANTIATE_TEST_SUITE_P(Seeds, NullDiagnosis, ::testing::Values(101, 102, 103));

// Hidden effects (issue 6, must-show 1): for each family, four seeds, each hiding a random value
// of the family's physical range in the three synthetic trials, diagnosed with the hidden family
// and its closest rival as candidates (to keep the suite's time reasonable; the full library runs
// in `pianoaction bench-diagnose`). A seed passes when the diagnosis names the hidden family,
// estimates its value within 25 % and gains at least 50 % on held-out trials. Required: every
// seed of every family (the must-show; 24 of 24 pass with the held-out fits made from
// scratch, the estimates within 2 %, the lowest held-out gains 54 % (a backcheck seed) and 60 %
// (a repetition spring seed)).
struct HiddenCase {
  std::string effect;
  std::vector<std::string> rivals;
};
class HiddenEffect : public ::testing::TestWithParam<HiddenCase> {};
TEST_P(HiddenEffect, IsNamedEstimatedAndGainsForEverySeed) {
  const ActionModel grand = test::shipped("grand");
  const HiddenCase& c = GetParam();
  HiddenEffectRange range;
  for (const HiddenEffectRange& r : hidden_effect_ranges(grand))
    if (r.effect == c.effect) range = r;
  ASSERT_FALSE(range.effect.empty());
  std::vector<std::string> candidates = c.rivals;
  candidates.push_back(c.effect);
  constexpr unsigned long long kSeeds = 4;
  int passed = 0;
  for (unsigned long long seed = 1; seed <= kSeeds; ++seed) {
    const Effect hidden{c.effect, hidden_value(range, seed)};
    const HiddenEffectOutcome o = run_hidden_effect_case(grand, hidden, seed, candidates);
    std::printf("%s seed %llu: hidden %.4g, named %s = %.4g, error %.0f %%, gain %.0f %%: %s\n",
                c.effect.c_str(), seed, hidden.value,
                o.diagnosis.cause ? o.diagnosis.cause->name.c_str() : "nothing",
                o.diagnosis.cause ? o.diagnosis.cause->value : NAN, 100.0 * o.value_error,
                100.0 * o.diagnosis.gain, o.passed ? "passed" : "failed");
    passed += o.passed ? 1 : 0;
  }
  EXPECT_EQ(passed, static_cast<int>(kSeeds))
      << c.effect << ": " << passed << " of " << kSeeds << " seeds";
}
INSTANTIATE_TEST_SUITE_P(
    Families, HiddenEffect,
    ::testing::Values(HiddenCase{"shank_flex", {"felt_stiffness.hammer_head_string"}},
                      HiddenCase{"backcheck_compliance", {"regulation_offset.checking"}},
                      HiddenCase{"joint_friction.hammer", {"joint_friction.key"}},
                      HiddenCase{"repetition_spring", {"joint_friction.hammer"}},
                      HiddenCase{"felt_stiffness.hammer_head_string",
                                 {"regulation_offset.hammer_blow"}},
                      HiddenCase{"regulation_offset.let_off", {"regulation_offset.drop"}}),
    [](const ::testing::TestParamInfo<HiddenCase>& info) {
      std::string name = info.param.effect;
      std::replace(name.begin(), name.end(), '.', '_');
      return name;
    });

}  // namespace
}  // namespace pat

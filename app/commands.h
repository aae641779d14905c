// The headless subcommands of pianoaction. Each returns the process exit code and throws
// pat::InputError for bad input (main prints it and exits with code 2).
#pragma once

#include <string>
#include <vector>

namespace pat::app {

/// Exit code of a simulation that stopped (unphysical penetration, divergence): its results up to
/// the stop are written, as for a run that ended.
constexpr int kExitRunStopped = 3;

int run_simulate(const std::vector<std::string>& args);
int run_bench(const std::vector<std::string>& args);
/// bench --window: the trainer window's frame rate and slider latency (bench_window_command.cpp)
int run_bench_window(const std::vector<std::string>& args);
int run_regulate(const std::vector<std::string>& args);
/// measure: the regulation settings read on the action as given, nothing adjusted
int run_measure(const std::vector<std::string>& args);
int run_deregulate(const std::vector<std::string>& args);
int run_swing(const std::vector<std::string>& args);
int run_keyfall(const std::vector<std::string>& args);
int run_touchweight(const std::vector<std::string>& args);
/// study double-blow (the word after `study` removed)
int run_study_double_blow(const std::vector<std::string>& args);
/// study sensitivity (the word after `study` removed)
int run_study_sensitivity(const std::vector<std::string>& args);
int run_sweep(const std::vector<std::string>& args);
/// `study WHAT ...`: dispatches on the study name (study_command.cpp).
int run_study(const std::vector<std::string>& args);
int run_study_compare(const std::vector<std::string>& args);
int run_practice(const std::vector<std::string>& args);
int run_synth(const std::vector<std::string>& args);
int run_diagnose(const std::vector<std::string>& args);
int run_bench_diagnose(const std::vector<std::string>& args);
int run_import_raw(const std::vector<std::string>& args);

}  // namespace pat::app

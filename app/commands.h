// The headless subcommands of pianoaction. Each returns the process exit code and throws
// pat::InputError for bad input (main prints it and exits with code 2).
#pragma once

#include <string>
#include <vector>

namespace pat::app {

int run_simulate(const std::vector<std::string>& args);
int run_bench(const std::vector<std::string>& args);
int run_regulate(const std::vector<std::string>& args);
int run_deregulate(const std::vector<std::string>& args);
int run_synth(const std::vector<std::string>& args);
int run_diagnose(const std::vector<std::string>& args);
int run_bench_diagnose(const std::vector<std::string>& args);

}  // namespace pat::app

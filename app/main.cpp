// pianoaction: the Piano Action Trainer. Subcommands run headless work (DESIGN.md section 5).
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"

namespace {

const char* kUsage = R"(Piano Action Trainer: grand and upright piano actions as multibody models.

usage:
  pianoaction simulate  --action grand|upright|FILE --input SPEC --duration S
                        [--integrator w2|rodas|cvode] [--step S] [--set ADJUSTER=MM]...
                        [--without PART]... [--out CSV] [--sample-interval S] [--json]
  pianoaction regulate  --action A [--set ADJUSTER=MM]... [--out PRESET.json] [--json]
  pianoaction deregulate --action A --setting NAME --rate MM_PER_S [--frequency HZ]
                        [--duration S] [--step-interval S] [--set ADJUSTER=MM]... [--out CSV]
                        [--json]
  pianoaction bench     [--json] [--duration S]

input SPEC:
  mass:1kg  force:const:N  force:pulse:N:MS  force:double:N:MS:GAP_MS
  motion:sine:HZ[:full|half]  motion:chirp:F0:F1:SECONDS[:full|half]  csv:PATH

The trainer window is not part of this build yet; the subcommands above are.
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kUsage;
    return 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "simulate") return pat::app::run_simulate(args);
    if (command == "bench") return pat::app::run_bench(args);
    if (command == "regulate") return pat::app::run_regulate(args);
    if (command == "deregulate") return pat::app::run_deregulate(args);
    std::cerr << "pianoaction: unknown subcommand '" << command << "'\n\n" << kUsage;
    return 2;
  } catch (const pat::InputError& e) {
    std::cerr << "pianoaction " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pianoaction " << command << ": " << e.what() << "\n";
    return 1;
  }
}

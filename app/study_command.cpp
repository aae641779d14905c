// pianoaction study WHAT: the studies that compare runs (DESIGN.md section 5), dispatched on the
// second word. Each study lives in its own file (study_compare.cpp, ...).
#include <string>

#include "commands.h"
#include "core/error.h"

namespace pat::app {

int run_study(const std::vector<std::string>& args) {
  const std::string known = "compare, double-blow, sensitivity";
  if (args.empty()) throw InputError("study: name the study (expected one of: " + known + ")");
  const std::string study = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (study == "compare") return run_study_compare(rest);
  if (study == "double-blow") return run_study_double_blow(rest);
  if (study == "sensitivity") return run_study_sensitivity(rest);
  throw InputError("study: unknown study '" + study + "' (expected one of: " + known + ")");
}

}  // namespace pat::app

// Speed and accuracy benchmark (pianoaction bench): for each action, a double blow simulated with
// the W-method at 1e-5 s and with the adaptive references, timed, and compared with the
// tightest-tolerance Rosenbrock reference on the hammer angle.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pat {

struct BenchCase {
  std::string action;            ///< grand, upright
  std::string integrator;        ///< w2, rodas, cvode
  std::string setting;           ///< step or tolerance, e.g. "h=1e-05 s" or "rtol=1e-06"
  double realtime_factor = 0.0;  ///< simulated seconds per wall-clock second
  double wall_time_s = 0.0;
  long steps = 0;
  double max_error_deg = 0.0;     ///< max |hammer angle − reference| over the run
  double hammer_range_deg = 0.0;  ///< hammer angle range of the reference
};

struct BenchOptions {
  double duration_s = 1.0;
  std::string input = "force:double:20:40:60";  ///< the double blow
  std::vector<std::string> actions{"grand", "upright"};
};

/// Runs every case; the reference itself (rodas at rtol 1e-9) is not listed.
std::vector<BenchCase> run_bench(const BenchOptions& options);

/// The W-method against CVODE at equal accuracy on one action: CVODE's fastest setting whose
/// hammer error is at most the W-method's (the cheapest run that is as good), and the ratio of
/// the two real-time factors (> 1: the W-method is faster).
struct EqualAccuracy {
  std::string action;
  double w2_realtime_factor = 0.0;
  double w2_error_deg = 0.0;
  std::optional<BenchCase> cvode;  ///< absent: no CVODE setting was that accurate
  double ratio = 0.0;              ///< w2 / cvode real-time factor (0 without a CVODE case)
};

/// One comparison per action that has a w2 case, in the order of the cases.
std::vector<EqualAccuracy> compare_at_equal_accuracy(const std::vector<BenchCase>& cases);

}  // namespace pat

// pianoaction: the Piano Action Trainer. Subcommands run headless work (DESIGN.md section 5).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "core/error.h"
#include "io/csv.h"
#ifdef PAT_HAVE_UI
#include "trainer_app.h"
#endif

namespace {

const char* kUsage = R"(Piano Action Trainer: grand and upright piano actions as multibody models.

usage:
  pianoaction [--action grand|upright|FILE] [--view whole|escapement|checking]
                        [--size WIDTHxHEIGHT] [--screenshot PNG]      the trainer window
  pianoaction simulate  --action grand|upright|FILE --input SPEC --duration S
                        [--integrator w2|rodas|cvode] [--step S | --rtol X] [--set ADJUSTER=MM]...
                        [--without PART]... [--effect NAME=VALUE]... [--out CSV] [--plot FILE]
                        [--sample-interval S] [--json]
  pianoaction regulate  --action A [--set ADJUSTER=MM]... [--out PRESET.json] [--plot FILE]
                        [--json]
  pianoaction measure   --action A [--set ADJUSTER=MM]... [--without PART]...
                        [--effect NAME=VALUE]... [--plot FILE] [--json]
  pianoaction deregulate --action A --setting NAME --rate MM_PER_S [--frequency HZ]
                        [--duration S] [--step-interval S] [--set ADJUSTER=MM]... [--out CSV]
                        [--plot FILE] [--json]
  pianoaction sweep     --action A --stroke full|half [--mode chirp|steps] [--fmax HZ]
                        [--fstart HZ] [--rate HZ_PER_S] [--step-hz HZ] [--window CYCLES]
                        [--set ADJUSTER=MM]... [--out CSV] [--plot FILE] [--json]
  pianoaction study compare [--input SPEC] [--duration S] [--fmax HZ] [--no-limits] [--out CSV]
                        [--plot FILE] [--json]
  pianoaction study sensitivity --action A [--step MM] [--force N] [--set ADJUSTER=MM]...
                        [--out CSV] [--plot FILE] [--json]
  pianoaction bench     [--input SPEC] [--duration S] [--plot FILE] [--json]
  pianoaction bench --window [--action A] [--input SPEC] [--duration S] [--trials N]
                        [--plot FILE] [--json]
  pianoaction swing     --action A [--release-deg D] [--out CSV] [--plot FILE] [--json]
  pianoaction keyfall   --action A [--duration S] [--out CSV] [--plot FILE] [--json]
  pianoaction touchweight --action A [--spring-factor SPRING=F]... [--key-lead-g G]
                        [--set ADJUSTER=MM]... [--without PART]... [--out CSV] [--plot FILE]
                        [--json]
  pianoaction study double-blow --action upright [--force N] [--pulse-ms MS] [--gap-ms MS]
                        [--duration S] [--out CSV] [--plot FILE] [--json]
  pianoaction practice new   (--action A --seed N [--level 1|2] | --exercise FILE) [--reveal]
                        [--plot FILE] [--json]
  pianoaction practice check (--action A --seed N [--level 1|2] | --exercise FILE)
                        --answer SETTING:more|less[,SETTING:more|less] [--reveal] [--json]
  pianoaction synth     --action A --input SPEC --duration S [--effect NAME=VALUE]...
                        [--noise-deg X] [--fps N] [--time-offset-ms X] [--angle-offset-deg X]
                        [--seed N] --out CSV [--plot FILE]
  pianoaction diagnose  --action A --measured CSV... [--candidate NAME]... [--threads N]
                        [--report DIR] [--plot FILE] [--json]
  pianoaction bench-diagnose [--action A] [--seeds N] [--null-seeds N] [--family NAME]...
                        [--plot FILE] [--json]
  pianoaction import-raw RAW --rate HZ [--column N] [--key-column N] [--calibration CSV]
                        [--action grand|upright] [--from S] [--to S] [--bits N] --out CSV
                        [--plot FILE] [--json]

input SPEC:
  mass:1kg  force:const:N  force:pulse:N:MS  force:double:N:MS:GAP_MS
  motion:sine:HZ[:full|half]  motion:chirp:F0:F1:SECONDS[:full|half]  motion:press:SECONDS
  csv:PATH
  (N newtons down at the key front; MS held, with 1 ms ramps; GAP_MS from the end of the first
  pulse to the start of the second; full: rest to full dip, half: full dip to half release;
  press: the technician's slow press, rest to full dip in SECONDS along a half cosine, then held;
  csv: time_s with key_force_n or key_angle_deg; a file starting after 0 s starts at rest)
--set ADJUSTER=MM turns an adjuster MM mm from its regulated position (the sign as the preset's
  description of it says). grand: key_dip jack_position lever_height hammer_blow let_off drop
  checking; upright: key_dip lost_motion hammer_blow let_off checking bridle damper_lift
--without PART takes a spring or strap out. grand: repetition_spring jack_spring damper_spring;
  upright: jack_spring butt_spring damper_spring bridle
--window CYCLES (sweep): judged cycles in a steady window (8); the maximum is the top of the
  longest run of successful cycles at least that long. Sweep defaults: --fstart 2 Hz, --fmax 20 Hz
  (full stroke) or 25 Hz (half), chirp --rate 1 Hz/s, steps --step-hz 0.5 Hz
--step S (simulate) is w2's fixed step (1e-5 s; 1e-7 s to 1e-3 s, and a tenth of --duration);
  --rtol X the tolerance of rodas and cvode (1e-6; 1e-10 to 0.1; absolute tolerance a hundredth
  of it). An option that takes one value is refused when given twice.

effects (--effect NAME=VALUE): shank_flex=HZ  backcheck_compliance=N_PER_MM
  joint_friction.JOINT=FACTOR  repetition_spring=FACTOR (grand)  butt_spring=FACTOR (upright)
  felt_stiffness.CONTACT=FACTOR  regulation_offset.SETTING=MM

--plot FILE writes the command's plots, stacked (simulate: key and hammer angles, hammer-string
gap, finger force; the others: what they computed, e.g. the measured setting over time, strikes
per cycle against frequency, each setting's effect); the format comes from the extension:
.png .pdf .svg, or .csv for the plotted columns (one table per set of plots with the same x
values; the others go beside FILE as its stem + _<x column>.csv, or + _<plot title>.csv).
--key-column N (import-raw) turns the key's own sensor, column N of the same recording, into
key angles with its rows of the --calibration points (their 'sensor' names the columns in order);
diagnose then drives the model with that key motion instead of an estimated finger force.
--view frames the whole action (default) or a close-up of the escapement (jack, knuckle or
butt, let-off button) or of the checking (hammer head and tail, backcheck); View menu, Ctrl+1-3.
exit codes: 0 done, 2 bad input (the message names the option, file or field), 3 simulate's run
stopped (unphysical or diverging; what it computed up to the stop is written), 1 other failures.
--screenshot PNG opens the window, plays a blow until the hammer is 2.5 mm from the string,
saves a screenshot of the window and exits (works with QT_QPA_PLATFORM=offscreen).
)";

// What a note of kUsage (from "input SPEC:" on) explains, as its entries spell it: "SPEC",
// "--effect", or the option the note starts with ("--plot", "--view", "--screenshot").
std::string note_subject(const std::string& first_line) {
  if (first_line.rfind("input SPEC", 0) == 0) return "SPEC";
  if (first_line.rfind("effects (--effect", 0) == 0) return "--effect";
  return first_line.substr(0, first_line.find(' '));
}

// The subcommand a note of kUsage is for when it says so after its option ("--window CYCLES
// (sweep): ..." is the sweep's, not bench's --window switch; "--step S (simulate)" is w2's step,
// not the sensitivity study's); empty when it does not.
std::string note_command(const std::string& first_line) {
  std::istringstream words(first_line);
  std::string option, argument, third;
  words >> option >> argument >> third;
  if (third.size() < 3 || third.front() != '(') return std::string();
  const auto close = third.find(')');
  if (close == std::string::npos) return std::string();
  return third.substr(1, close - 1);
}

// The usage lines of one subcommand (its entries in kUsage with their continuation lines),
// then those of the shared notes (from "input SPEC:" on) that explain something its entries
// name; empty if kUsage has no entry for it.
std::string subcommand_usage(const std::string& command) {
  std::istringstream in(kUsage);
  std::string line, entries;
  std::vector<std::string> notes;  // each with its continuation lines
  bool in_entry = false, in_notes = false;
  const std::string head = "  pianoaction " + command + " ";
  while (std::getline(in, line)) {
    if (line.rfind("input SPEC:", 0) == 0) in_notes = true;
    if (in_notes) {
      if (line.empty()) continue;
      // a note starts with what it explains; its other lines continue it
      const bool starts_note = line.rfind("input SPEC", 0) == 0 ||
                               line.rfind("effects (--effect", 0) == 0 ||
                               line.rfind("exit codes", 0) == 0 || line.rfind("--", 0) == 0;
      if (starts_note || notes.empty())
        notes.push_back(line + "\n");
      else
        notes.back() += line + "\n";
      continue;
    }
    if (line.rfind("  pianoaction ", 0) == 0)
      in_entry = line.rfind(head, 0) == 0;
    else if (line.rfind("      ", 0) != 0)
      in_entry = false;
    if (in_entry) entries += line + "\n";
  }
  if (entries.empty()) return std::string();
  std::string text = "usage:\n" + entries;
  for (const std::string& note : notes) {
    const std::string first_line = note.substr(0, note.find('\n'));
    const std::string subject = note_subject(first_line);
    const std::string for_command = note_command(first_line);
    if (!for_command.empty() && for_command != command) continue;
    // the exit codes hold for every subcommand
    if (subject == "exit" || entries.find(subject) != std::string::npos) text += "\n" + note;
  }
  return text;
}

bool asks_for_help(const std::vector<std::string>& args) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

// The window needs a display: without one (and no QT_QPA_PLATFORM such as offscreen), Qt would
// abort; say so instead.
bool has_display() {
#ifdef __linux__
  auto set = [](const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0';
  };
  return set("DISPLAY") || set("WAYLAND_DISPLAY") || set("QT_QPA_PLATFORM");
#else
  return true;  // macOS and Windows have their own window systems
#endif
}

// The window: no subcommand, or only --action / --view / --screenshot.
int run_window(int argc, char** argv, const std::vector<std::string>& args) {
#ifdef PAT_HAVE_UI
  const pat::app::CommandLine cl(args, {"--action", "--view", "--screenshot", "--size"}, {});
  if (!has_display())
    throw pat::InputError(
        "no display to open the window on (DISPLAY and WAYLAND_DISPLAY are not set): start it "
        "in a desktop session or under xvfb-run, or use a subcommand (pianoaction --help)");
  pat::ui::TrainerOptions options;
  options.action_given = cl.has("--action");
  options.action = cl.value_or("--action", "grand");
  options.screenshot = cl.value_or("--screenshot", "");
  if (!options.screenshot.empty()) {
    // refused before the window plays its blow, as the subcommands check their outputs first
    const std::string& shot = options.screenshot;
    std::string extension = std::filesystem::path(shot).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png")
      throw pat::InputError("--screenshot " + shot + ": the screenshot is a PNG; name it .png");
    try {
      pat::check_output_path(shot);
    } catch (const pat::InputError& e) {
      throw pat::InputError(std::string("--screenshot ") + e.what());
    }
  }
  if (cl.has("--size")) {
    // WIDTHxHEIGHT in pixels, e.g. 1024x640 (a projector) or 1920x1080
    const std::string size = cl.value("--size");
    const auto x = size.find('x');
    const double w =
        x == std::string::npos ? 0.0 : pat::app::parse_number(size.substr(0, x), "--size");
    const double h =
        x == std::string::npos ? 0.0 : pat::app::parse_number(size.substr(x + 1), "--size");
    if (!(w >= 640 && h >= 400 && w <= 10000 && h <= 10000) || w != std::floor(w) ||
        h != std::floor(h))
      throw pat::InputError(
          "--size: expected WIDTHxHEIGHT in whole pixels, from 640x400 to 10000x10000 (got '" +
          size + "')");
    options.width = static_cast<int>(w);
    options.height = static_cast<int>(h);
  }
  const std::string view = cl.value_or("--view", "whole");
  if (view == "escapement") {
    options.view = pat::ui::ViewFocus::escapement;
  } else if (view == "checking") {
    options.view = pat::ui::ViewFocus::checking;
  } else if (view != "whole") {
    throw pat::InputError("--view: must be whole, escapement or checking (got '" + view + "')");
  }
  return pat::ui::run_trainer(argc, argv, options);
#else
  (void)argc, (void)argv, (void)args;
  std::cerr << "pianoaction: this build has no trainer window (configured with "
               "PAT_ENGINE_ONLY); use a subcommand\n\n"
            << kUsage;
  return 2;
#endif
}

/// `message` without a leading "COMMAND: " (engine messages name their analysis, and the line
/// already starts with "pianoaction COMMAND: ").
std::string without_prefix(const std::string& command, const std::string& message) {
  const std::string prefix = command + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    std::cout << kUsage;
    return 0;
  }
  if (args.empty() || args[0].rfind("--", 0) == 0) {
    try {
      return run_window(argc, argv, args);
    } catch (const pat::InputError& e) {
      std::cerr << "pianoaction: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "pianoaction: " << e.what() << "\n";
      return 1;
    }
  }
  const std::string command = args[0];
  args.erase(args.begin());
  if (asks_for_help(args)) {
    // a study's or practice's own entry ("study sensitivity --help"), else the group's
    std::string usage;
    if ((command == "study" || command == "practice") && !args.empty() &&
        args[0].rfind("--", 0) != 0)
      usage = subcommand_usage(command + " " + args[0]);
    if (usage.empty()) usage = subcommand_usage(command);
    if (!usage.empty()) {
      std::cout << usage;
      return 0;
    }
  }
  try {
    if (command == "simulate") return pat::app::run_simulate(args);
    if (command == "bench") return pat::app::run_bench(args);
    if (command == "regulate") return pat::app::run_regulate(args);
    if (command == "measure") return pat::app::run_measure(args);
    if (command == "deregulate") return pat::app::run_deregulate(args);
    if (command == "sweep") return pat::app::run_sweep(args);
    if (command == "swing") return pat::app::run_swing(args);
    if (command == "keyfall") return pat::app::run_keyfall(args);
    if (command == "touchweight") return pat::app::run_touchweight(args);
    if (command == "study") return pat::app::run_study(args);
    if (command == "practice") return pat::app::run_practice(args);
    if (command == "synth") return pat::app::run_synth(args);
    if (command == "diagnose") return pat::app::run_diagnose(args);
    if (command == "bench-diagnose") return pat::app::run_bench_diagnose(args);
    if (command == "import-raw") return pat::app::run_import_raw(args);
    std::cerr << "pianoaction: unknown subcommand '" << command << "'\n\n" << kUsage;
    return 2;
  } catch (const pat::InputError& e) {
    std::cerr << "pianoaction " << command << ": " << without_prefix(command, e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pianoaction " << command << ": " << without_prefix(command, e.what()) << "\n";
    return 1;
  }
}

// Starts the trainer window: `pianoaction [--action grand|upright|FILE]
// [--view whole|escapement|checking] [--size WIDTHxHEIGHT] [--screenshot PNG]`.
#pragma once

#include <string>

#include "view_focus.h"

namespace pat::ui {

struct TrainerOptions {
  std::string action = "grand";       ///< grand, upright or a preset file
  bool action_given = false;          ///< false: the last preset used (QSettings), else grand
  ViewFocus view = ViewFocus::whole;  ///< what the action view frames at the start
  /// Non-empty: run a short demo until the action is mid-stroke (the hammer near the string), save
  /// a screenshot of the whole window there and exit.
  std::string screenshot;
  /// Window size in pixels (0: the size saved at the last close, or 1280×800 the first time;
  /// a screenshot is taken at 1280×800 unless a size is given).
  int width = 0, height = 0;
};

/// Runs the window; returns the process exit code. Throws InputError for a bad preset.
int run_trainer(int argc, char** argv, const TrainerOptions& options);

}  // namespace pat::ui

// The window's run as a trace table: the columns `pianoaction simulate --out` writes
// (trace_columns: time, every body angle, the hammer–string gap, the finger force, every
// contact's force and every strap's tension), one row per frame the window kept. The plots'
// CSV export holds only the plotted series; this holds all of them.
#pragma once

#include <map>
#include <string>

#include "frame_history.h"
#include "io/csv.h"

namespace pat::ui {

/// The frames of `history` as a trace table with `metadata` (action, preset, settings, input)
/// and a "frames" line saying what the rows are: the frames the window recorded while it
/// played, spaced by the playback speed, not a fixed sample rate. Adjusters whose position
/// changed during the run (a replayed deregulation demo, a slider moved) get a column each,
/// "<adjuster>_mm", and the settings line says so (not when the settings are hidden for an
/// exercise). Throws InputError when the history is empty or a frame lacks the model's bodies,
/// contacts or straps.
CsvTable run_trace_table(const FrameHistory& history, std::map<std::string, std::string> metadata);

}  // namespace pat::ui

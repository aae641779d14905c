// --plot FILE for the headless subcommands: the trace plots exported by the window's export
// code (ui/plot_export.h); the format comes from the extension.
#pragma once

#include <string>

#include "io/csv.h"

namespace pat::app {

/// Throws InputError when the file's extension is not a plot format, or when this build has no
/// plotting (configured without the window).
void check_plot_path(const std::string& path);
/// Writes the plots of a trace. Throws InputError naming the file when it cannot be written.
void write_plot(const std::string& path, const CsvTable& trace);

}  // namespace pat::app

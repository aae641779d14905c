// --plot FILE for the headless subcommands: the plots a command built (plot_spec.h), written by
// the window's export code (ui/plot_export.h); the format comes from the extension (.png .pdf
// .svg, or .csv for the plotted columns).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "command_line.h"
#include "plot_spec.h"

namespace pat::app {

/// Throws InputError when the file's extension is not a plot format, or when this build has no
/// plotting (configured without the window). Commands call it before their work.
void check_plot_path(const std::string& path);
/// Whether this build can draw plots (the window build; not one configured PAT_ENGINE_ONLY).
bool plotting_available();
/// Whether a valid --plot path writes the plotted columns as CSV (the extension, any case).
bool is_csv_plot_path(const std::string& path);
/// A file that a plot's second CSV must not replace, with the words that name it.
using KeptFile = std::pair<std::string, std::string>;  ///< (words, path)

/// Writes the plots, stacked top to bottom (a CSV: one table per set of plots with the same x
/// values, the others beside PATH: ui::plot_csv_files; those names are known only from the
/// plots, so they are checked here, before anything is written, against `keep`: the command's
/// inputs and other outputs). Throws InputError naming the file when it cannot be written, when
/// a second CSV would replace a kept file, or when there is nothing to plot.
void write_plots(const std::string& path, const std::vector<PlotSpec>& plots,
                 const std::vector<KeptFile>& keep = {});

/// The --plot option of a command: reads it and checks its extension at once (before the
/// work), and writes the plots afterwards when it was given.
class PlotOption {
 public:
  /// Reads --plot from the command line (CommandLine::output_path), which must outlive this.
  explicit PlotOption(const CommandLine& command_line);
  PlotOption(const CommandLine&&) = delete;  // it keeps the reference: no temporaries
  bool given() const { return !path_.empty(); }
  const std::string& path() const { return path_; }
  /// A CSV export: one table per set of plots with the same x values (write_plots puts the
  /// others beside it).
  bool writes_csv() const { return given() && is_csv_plot_path(path_); }
  /// Writes when given; returns whether it wrote.
  bool write(const std::vector<PlotSpec>& plots) const;
  /// Writes when given and then, if `announce`, says "plot written to PATH" on stdout (commands
  /// pass false under --json, whose stdout holds only the JSON object).
  void write(const std::vector<PlotSpec>& plots, bool announce) const;

 private:
  const CommandLine& command_line_;
  std::string path_;
};

}  // namespace pat::app

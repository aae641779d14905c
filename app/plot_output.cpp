#include "plot_output.h"

#include "core/error.h"
#ifdef PAT_HAVE_UI
#include <QString>

#include "plot_export.h"
#include "trace_plots.h"
#endif

namespace pat::app {

#ifdef PAT_HAVE_UI
void check_plot_path(const std::string& path) {
  ui::export_format(QString::fromStdString(path));
}

void write_plot(const std::string& path, const CsvTable& trace) {
  ui::write_trace_plot(trace, QString::fromStdString(path));
}
#else
void check_plot_path(const std::string& path) {
  throw InputError("--plot " + path +
                   ": plots need the window build; this build has no plotting (configured with "
                   "PAT_ENGINE_ONLY)");
}

void write_plot(const std::string& path, const CsvTable&) {
  check_plot_path(path);
}
#endif

}  // namespace pat::app

// pianoaction import-raw: a raw hammer-shank sensor trace (the uncalibrated recordings of
// shared/data/kawai-kg3c) turned into the measured-data format (DESIGN.md sections 4 and 5;
// the calibration is described in engine/measured/raw_import.h).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "core/error.h"
#include "core/format.h"
#include "io/csv.h"
#include "measured/raw_import.h"
#include "measured/sensor_calibration.h"
#include "model/preset_loader.h"
#include "plot_output.h"

namespace pat::app {

namespace {

const std::set<std::string> kValueOptions = {
    "--rate", "--column", "--key-column", "--calibration", "--action",
    "--from", "--to",     "--bits",       "--out",         "--plot"};

/// A whole number ≥ `minimum`; names the option.
int whole_number(const CommandLine& cl, const std::string& option, int fallback, int minimum) {
  if (!cl.has(option)) return fallback;
  const double x = parse_number(cl.value(option), option);
  if (x != std::floor(x) || x < minimum || x > 1e9)
    throw InputError(option + ": must be a whole number ≥ " + std::to_string(minimum) + " (got " +
                     cl.value(option) + ")");
  return static_cast<int>(x);
}

/// A calibration holds one recording's sensor offsets and gains: refuses one whose header names
/// another recording, and a column its sensors (in column order) give to another sensor than
/// the hammer shank's.
void check_calibration_fits(const SensorCalibration& cal, const std::string& raw_path, int column) {
  const std::string raw_name = std::filesystem::path(raw_path).filename().string();
  if (!cal.recording.empty() && cal.recording != raw_name)
    throw InputError("--calibration: " + cal.path + " holds the sensor offsets and gains of " +
                     cal.recording + ", not of " + raw_name +
                     " (each recording has its own; without --calibration the hammer's travel "
                     "is estimated from the trace)");
  const auto index = static_cast<std::size_t>(column - 1);
  if (cal.sensors.size() > 1 && index < cal.sensors.size() && cal.sensors[index] != "hammer") {
    std::string order;
    for (const std::string& s : cal.sensors) order += (order.empty() ? "" : ", ") + s;
    throw InputError("--column " + std::to_string(column) + ": in " + cal.path + " column " +
                     std::to_string(column) + " of " + raw_name + " is the '" + cal.sensors[index] +
                     "' sensor (its sensors in column order: " + order +
                     "); import-raw turns the hammer-shank sensor into hammer angles");
  }
}

/// The calibration's sensor for the key's column: the sensor its rows give that column (in
/// column order), which must not be the hammer shank's.
std::string key_sensor_name(const SensorCalibration& cal, int key_column, int hammer_column) {
  if (key_column == hammer_column)
    throw InputError("--key-column " + std::to_string(key_column) +
                     ": the same column as the hammer's (--column)");
  const auto index = static_cast<std::size_t>(key_column - 1);
  if (cal.sensors.size() < 2 || index >= cal.sensors.size())
    throw InputError("--key-column " + std::to_string(key_column) + ": " + cal.path +
                     " has no calibration points for column " + std::to_string(key_column) +
                     " (its rows must name each column's sensor, in column order, in a 'sensor' "
                     "column)");
  if (cal.sensors[index] == "hammer")
    throw InputError("--key-column " + std::to_string(key_column) + ": in " + cal.path +
                     " column " + std::to_string(key_column) +
                     " is the hammer-shank sensor, not the key's");
  return cal.sensors[index];
}

}  // namespace

int run_import_raw(const std::vector<std::string>& args) {
  // the one positional argument: the raw file
  std::vector<std::string> options;
  std::string raw_path;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool takes_value = kValueOptions.count(args[i]) > 0;
    if (args[i].rfind("--", 0) != 0) {
      if (!raw_path.empty())
        throw InputError("one raw trace at a time (got '" + raw_path + "' and '" + args[i] + "')");
      raw_path = args[i];
      continue;
    }
    options.push_back(args[i]);
    if (takes_value && i + 1 < args.size()) options.push_back(args[++i]);
  }
  CommandLine cl(options, kValueOptions, {"--json"});
  if (raw_path.empty())
    throw InputError("missing the raw trace file (import-raw RAW --rate HZ ...)");
  cl.add_input_file("the raw trace", raw_path);
  const std::string out_path = cl.output_path("--out", true);
  const PlotOption plot(cl);

  RawImportOptions o;
  if (!cl.has("--rate")) throw InputError("missing option --rate (samples per second of RAW)");
  o.rate_hz = parse_number(cl.value("--rate"), "--rate");
  if (cl.has("--from")) o.from_s = parse_number(cl.value("--from"), "--from");
  if (cl.has("--to")) o.to_s = parse_number(cl.value("--to"), "--to");
  const int column = whole_number(cl, "--column", 1, 1);
  const int bits = whole_number(cl, "--bits", 24, 1);
  const ActionModel model = load_action(cl.value_or("--action", "grand"));
  o.action = model.kind;
  if (cl.has("--calibration")) {
    o.calibration = read_sensor_calibration(cl.value("--calibration"), "hammer");
    check_calibration_fits(*o.calibration, raw_path, column);
  }
  const RawTrace trace = read_raw_trace(raw_path, column, bits);
  if (cl.has("--bits") && !trace.counts)  // it would be ignored without a word
    throw InputError("--bits " + cl.value("--bits") + ": " + raw_path + " column " +
                     std::to_string(column) +
                     " holds normalized readings in [0, 1], not ADC counts: --bits applies to "
                     "counts only; leave it out");
  if (cl.has("--key-column")) {
    const int key_column = whole_number(cl, "--key-column", 2, 1);
    if (!o.calibration)
      throw InputError(
          "--key-column needs --calibration: the key's sensor is curved, and only "
          "its calibration points turn its reading into a key-front dip");
    const std::string sensor = key_sensor_name(*o.calibration, key_column, column);
    o.key_calibration = read_sensor_calibration(cl.value("--calibration"), sensor);
    o.key_trace = read_raw_trace(raw_path, key_column, bits);
    o.key_front_arm_m = key_front_arm_m(model);
  }
  o.contact_angle_deg = hammer_contact_angle_deg(model);
  const RawImport result = import_raw(trace, o);
  std::vector<PlotSpec> plots;
  PlotSpec angle = table_plot(result.table, "Imported hammer angle", "hammer angle (deg)",
                              {{"hammer_angle_deg", "hammer"}});
  if (result.strike)
    angle.markers.push_back(
        {result.peak_t_s, "peak " + format_number(result.peak_angle_deg) + " deg"});
  add_plot(plots, std::move(angle));
  if (result.key)
    add_plot(plots, table_plot(result.table, "Imported key angle", "key angle (deg)",
                               {{"key_angle_deg", "key"}}));
  add_plot(plots, table_plot(result.table, "Raw sensor reading", "reading (fraction of full scale)",
                             {{"sensor_reading", "hammer sensor"}}));
  if (result.key)
    add_plot(plots,
             table_plot(result.table, "Raw key sensor reading", "reading (fraction of full scale)",
                        {{"key_sensor_reading", "key sensor"}}));
  // the plot first: a plot that cannot be written leaves an existing --out file as it was
  plot.write(plots);
  write_csv(out_path, result.table);

  const std::size_t samples = result.table.rows.size();
  if (cl.has("--json")) {
    nlohmann::json j{{"out", out_path},
                     {"samples", samples},
                     {"first_sample", result.first_sample},
                     {"rate_hz", o.rate_hz},
                     {"column", column},
                     {"counts", trace.counts},
                     {"calibration", o.calibration ? "points" : "estimated"},
                     {"contact_angle_deg", o.contact_angle_deg},
                     {"strike", nullptr}};
    if (result.strike)
      j["strike"] = {{"rest_reading", result.strike->rest_reading},
                     {"peak_reading", result.strike->peak_reading},
                     {"noise", result.strike->noise},
                     {"reversed", result.strike->reversed},
                     {"peak_t_s", result.peak_t_s},
                     {"peak_angle_deg", result.peak_angle_deg}};
    j["key"] = nullptr;
    if (result.key)
      j["key"] = {{"column", o.key_trace->column},
                  {"rest_position_in", result.key->rest_position_in},
                  {"front_arm_mm", 1e3 * result.key->front_arm_m},
                  {"deepest_dip_mm", result.key->deepest_dip_mm},
                  {"smoothing_sigma_ms", 1e3 * kKeySmoothingSigmaS}};
    std::cout << j.dump(1) << "\n";
  } else {
    std::cout << samples << " samples written to " << out_path << " ("
              << result.table.metadata.at("calibration") << ")\n";
    if (result.key)
      std::cout << "key angles from column " << o.key_trace->column << ": deepest key-front dip "
                << format_fixed(result.key->deepest_dip_mm, 2) << " mm ("
                << result.table.metadata.at("key_calibration") << ")\n";
    if (plot.given()) std::cout << "plot written to " << plot.path() << "\n";
  }
  return 0;
}

}  // namespace pat::app

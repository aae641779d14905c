#include "measured/raw_trace.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace pat {

namespace {

/// The fields of one line: comma-separated when it holds a comma (spaces around values
/// ignored), else separated by runs of white space.
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  auto trim = [](const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return std::string();
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
  };
  if (line.find(',') != std::string::npos) {
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) fields.push_back(trim(field));
    if (!line.empty() && line.back() == ',') fields.emplace_back();
  } else {
    std::stringstream in(line);
    std::string field;
    while (in >> field) fields.push_back(field);
  }
  return fields;
}

}  // namespace

RawTrace read_raw_trace(const std::string& path, int column, int bits) {
  if (column < 1)
    throw InputError("--column: columns are counted from 1 (got " + std::to_string(column) + ")");
  if (bits < 1 || bits > 32)
    throw InputError("--bits: an ADC resolution from 1 to 32 bits is expected (got " +
                     std::to_string(bits) + ")");
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(located_message(path, "", "is a folder, not a raw trace file"));
  std::ifstream in(path);
  if (!in) throw InputError(located_message(path, "", "cannot open the raw trace (missing file?)"));
  RawTrace trace;
  trace.path = path;
  trace.column = column;
  trace.bits = bits;
  std::string text;
  int line_number = 0;
  int blank_line = 0;  // the first blank line after a sample (0: none yet)
  while (std::getline(in, text)) {
    ++line_number;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) {
      if (!trace.reading.empty() && blank_line == 0) blank_line = line_number;
      continue;
    }
    if (text[first] == '#') continue;
    // one sample a line at a fixed rate: a blank line between samples is a lost sample, and
    // skipping it would shift every later one by a period (blank lines at the end are fine)
    if (blank_line > 0)
      throw InputError(located_message(
          path, "line " + std::to_string(blank_line),
          "blank line between samples: each line is one sample at the given rate, so a missing "
          "one would shift the rest in time (remove the line or fill in the sample)"));
    const std::vector<std::string> fields = split_fields(text);
    const std::string where = "line " + std::to_string(line_number);
    if (static_cast<int>(fields.size()) < column)
      throw InputError(located_message(
          path, where,
          "column " + std::to_string(column) + " is out of range: the line has " +
              std::to_string(fields.size()) + " column" + (fields.size() == 1 ? "" : "s")));
    const std::string& field = fields[static_cast<std::size_t>(column - 1)];
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc() || end != field.data() + field.size() ||
        !std::isfinite(value))
      throw InputError(located_message(path, where + ", column " + std::to_string(column),
                                       "'" + field + "' is not a finite number"));
    trace.reading.push_back(value);
    trace.line.push_back(line_number);
  }
  if (trace.reading.empty()) throw InputError(located_message(path, "", "no samples in the file"));

  bool normalized = true;
  for (double v : trace.reading) normalized = normalized && v >= 0.0 && v <= 1.0;
  if (normalized) return trace;
  // counts: whole, non-negative, below the ADC's full scale
  const double full_scale = std::ldexp(1.0, bits);
  for (std::size_t i = 0; i < trace.reading.size(); ++i) {
    const double v = trace.reading[i];
    if (v < 0.0 || v != std::floor(v) || v >= full_scale) {
      std::ostringstream problem;
      problem << "the value " << v
              << " is neither a normalized reading in [0, 1] nor a whole ADC count from 0 to 2^"
              << bits << " - 1 (the column holds values above 1, so it was read as counts)";
      throw InputError(located_message(
          path, "line " + std::to_string(trace.line[i]) + ", column " + std::to_string(column),
          problem.str()));
    }
  }
  for (double& v : trace.reading) v /= full_scale;
  trace.counts = true;
  return trace;
}

}  // namespace pat

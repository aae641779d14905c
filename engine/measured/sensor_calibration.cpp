#include "measured/sensor_calibration.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/error.h"

namespace pat {

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)), slope_(x_.size(), 0.0) {
  const std::size_t n = x_.size();
  if (n < 2) return;
  std::vector<double> h(n - 1), secant(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x_[k + 1] - x_[k];
    secant[k] = (y_[k + 1] - y_[k]) / h[k];
  }
  // ends: the adjacent secant; inside: zero at a local extremum or a flat segment, else the
  // weighted harmonic mean (Fritsch & Butland 1984), which never exceeds 3 min(|secants|) and
  // so keeps every Hermite piece monotone (Fritsch & Carlson 1980)
  slope_.front() = secant.front();
  slope_.back() = secant.back();
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double a = secant[k - 1], b = secant[k];
    if (a * b <= 0.0) continue;
    const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
    slope_[k] = (w1 + w2) / (w1 / a + w2 / b);
  }
}

double MonotoneCubic::operator()(double x) const {
  const std::size_t n = x_.size();
  if (n == 0) return 0.0;
  if (n == 1) return y_.front();
  // outside: along the end secants
  if (x <= x_.front()) return y_.front() + (x - x_.front()) * (y_[1] - y_[0]) / (x_[1] - x_[0]);
  if (x >= x_.back())
    return y_.back() + (x - x_.back()) * (y_[n - 1] - y_[n - 2]) / (x_[n - 1] - x_[n - 2]);
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double h = x_[k + 1] - x_[k], s = (x - x_[k]) / h;
  // cubic Hermite basis on [0, 1]
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y_[k] + h10 * h * slope_[k] + h01 * y_[k + 1] + h11 * h * slope_[k + 1];
}

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

bool parse_double(const std::string& text, double& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size() &&
         std::isfinite(value);
}

}  // namespace

SensorCalibration read_sensor_calibration(const std::string& path, const std::string& sensor) {
  std::ifstream in(path);
  if (!in)
    throw InputError(located_message(path, "", "cannot open the calibration file (missing file?)"));
  SensorCalibration cal;
  cal.path = path;
  std::vector<std::string> comments, columns;
  int sensor_col = -1, position_col = -1, reading_col = -1;
  std::vector<int> point_lines;
  std::string text;
  int line_number = 0;
  while (std::getline(in, text)) {
    ++line_number;
    const std::string line = trim(text);
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (columns.empty()) comments.push_back(line);
      continue;
    }
    const std::string where = "line " + std::to_string(line_number);
    const std::vector<std::string> fields = split_commas(line);
    if (columns.empty()) {
      columns = fields;
      for (std::size_t c = 0; c < columns.size(); ++c) {
        if (columns[c] == "sensor") sensor_col = static_cast<int>(c);
        if (columns[c] == "position_in") position_col = static_cast<int>(c);
        if (columns[c] == "normalized_reading") reading_col = static_cast<int>(c);
      }
      for (const auto& [index, name] :
           {std::pair{position_col, "position_in"}, std::pair{reading_col, "normalized_reading"}})
        if (index < 0)
          throw InputError(located_message(
              path, where,
              std::string("missing column '") + name +
                  "' (calibration points need position_in and normalized_reading, and "
                  "optionally sensor; the header is '" +
                  line + "')"));
      if (sensor_col >= 0) cal.sensor = sensor;
      continue;
    }
    if (fields.size() != columns.size())
      throw InputError(located_message(path, where,
                                       std::to_string(fields.size()) + " fields, the header has " +
                                           std::to_string(columns.size())));
    if (sensor_col >= 0) {
      const std::string& name = fields[static_cast<std::size_t>(sensor_col)];
      if (std::find(cal.sensors.begin(), cal.sensors.end(), name) == cal.sensors.end())
        cal.sensors.push_back(name);
      if (name != sensor) continue;
    }
    double position = 0.0, reading = 0.0;
    for (const auto& [index, value] :
         {std::pair{position_col, &position}, std::pair{reading_col, &reading}}) {
      const std::string& field = fields[static_cast<std::size_t>(index)];
      if (!parse_double(field, *value))
        throw InputError(located_message(path,
                                         where + ", " + columns[static_cast<std::size_t>(index)],
                                         "'" + field + "' is not a finite number"));
    }
    cal.position.push_back(position);
    cal.normalized_reading.push_back(reading);
    point_lines.push_back(line_number);
  }
  if (columns.empty())
    throw InputError(located_message(path, "", "no header row (position_in,normalized_reading)"));
  if (cal.position.size() < 2)
    throw InputError(located_message(path, "",
                                     "only " + std::to_string(cal.position.size()) + " " +
                                         (sensor_col >= 0 ? "'" + sensor + "' " : std::string()) +
                                         (cal.position.size() == 1 ? "point" : "points") +
                                         " (at least two are needed)"));

  // the recording named by the header: "... points for NAME.txt ..." (an extension with a
  // letter: "for 1.5 mm" names none)
  const std::regex recording_pattern(R"(\bfor\s+([^\s()]+\.[A-Za-z]\w*))");
  for (const std::string& comment : comments) {
    std::smatch match;
    if (std::regex_search(comment, match, recording_pattern)) {
      cal.recording = match[1].str();
      break;
    }
  }
  // offset and gain from the header: "SENSOR offset X gain Y" (or "offset X gain Y")
  const std::string number = R"([-+]?\d*\.?\d+(?:[eE][-+]?\d+)?)";
  const std::regex pattern("(?:(\\w+)\\s+)?offset\\s+(" + number + ")\\s+gain\\s+(" + number + ")");
  bool found = false;
  for (const std::string& comment : comments) {
    for (auto it = std::sregex_iterator(comment.begin(), comment.end(), pattern);
         it != std::sregex_iterator() && !found; ++it) {
      if (sensor_col >= 0 && (*it)[1].str() != sensor) continue;
      found = parse_double((*it)[2].str(), cal.offset) && parse_double((*it)[3].str(), cal.gain);
    }
    if (found) break;
  }
  if (!found)
    throw InputError(located_message(
        path, "header",
        "no offset and gain for " + (sensor_col >= 0 ? "sensor '" + sensor + "'" : "the sensor") +
            " (expected a '#' line such as '# ... " + (sensor_col >= 0 ? sensor + " " : "") +
            "offset 0.69 gain 0.29', meaning normalized_reading = (reading - offset) / gain)"));
  if (cal.gain == 0.0)
    throw InputError(located_message(path, "header", "the gain of " + sensor + " is zero"));

  // monotone: positions rise, readings rise (or all fall) with them
  const double direction = cal.normalized_reading[1] > cal.normalized_reading[0] ? 1.0 : -1.0;
  for (std::size_t k = 1; k < cal.position.size(); ++k) {
    const std::string where = "line " + std::to_string(point_lines[k]);
    std::ostringstream problem;
    if (!(cal.position[k] > cal.position[k - 1])) {
      problem << "positions must increase from point to point (" << cal.position[k - 1]
              << " in, then " << cal.position[k] << " in)";
      throw InputError(located_message(path, where, problem.str()));
    }
    if (!(direction * (cal.normalized_reading[k] - cal.normalized_reading[k - 1]) > 0.0)) {
      problem << "the calibration is not monotone: the reading " << cal.normalized_reading[k]
              << " at " << cal.position[k] << " in does not continue the "
              << (direction > 0 ? "rise" : "fall") << " from " << cal.normalized_reading[k - 1]
              << " at " << cal.position[k - 1] << " in";
      throw InputError(located_message(path, where, problem.str()));
    }
  }
  std::vector<double> x = cal.normalized_reading, y = cal.position;
  if (direction < 0) {  // the interpolant wants rising x
    std::reverse(x.begin(), x.end());
    std::reverse(y.begin(), y.end());
  }
  cal.position_of_reading = MonotoneCubic(std::move(x), std::move(y));
  return cal;
}

}  // namespace pat

// CSV reading and writing (io/csv.h).
//
// File layout accepted by read_csv, line by line (lines are numbered from 1, counting every
// physical line; a UTF-8 byte-order mark and '\r' line ends are accepted):
//   - blank lines are skipped anywhere;
//   - '#' lines before the header are metadata: "# key: value" (split at the first ':', both
//     parts trimmed); a '#' line without a ':' is stored under its trimmed text with an empty
//     value; an empty '#' line is ignored. A repeated key keeps its last value;
//   - the first other line is the header (comma-separated names, trimmed, surrounding double
//     quotes removed); names must be non-empty and distinct;
//   - every following line is a row of finite numbers, one per column; '#' lines after the
//     header are comments and are ignored.
// format_csv writes metadata with an empty value as "# key", so such keys round-trip.
#include "io/csv.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/error.h"

namespace pat {
namespace {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Splits at commas; the fields are trimmed.
void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(trim(line.substr(start)));
      return;
    }
    fields.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

enum class NumberParse { kOk, kNotANumber, kNotFinite };

// Locale-independent; the whole text must be the number (a leading '+' is accepted).
NumberParse parse_number(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return NumberParse::kNotANumber;
  }
  if (text.empty()) return NumberParse::kNotANumber;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec == std::errc::invalid_argument || ptr != end) return NumberParse::kNotANumber;
  if (ec == std::errc::result_out_of_range) {
    // Too small to represent (1e-400) reads as zero; too large is not finite.
    const bool underflow =
        text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos;
    if (!underflow) return NumberParse::kNotFinite;
    value = text.front() == '-' ? -0.0 : 0.0;
    return NumberParse::kOk;
  }
  return std::isfinite(value) ? NumberParse::kOk : NumberParse::kNotFinite;
}

std::string line_label(int line) {
  return "line " + std::to_string(line);
}

std::string read_whole_file(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    throw InputError(located_message(path, "", "cannot read the file: it does not exist"));
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(located_message(path, "", "cannot read the file: it is a folder"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(located_message(path, "", "cannot open the file for reading"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(located_message(path, "", "error while reading the file"));
  return text;
}

void append_number(std::string& out, double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

bool has_line_break(const std::string& s) {
  return s.find_first_of("\r\n") != std::string::npos;
}

// `target` with `infix` and a random suffix appended: a name beside it that nothing else uses
std::filesystem::path unique_sibling(const std::filesystem::path& target,
                                     const std::string& infix) {
  std::random_device random;
  std::ostringstream suffix;
  suffix << std::hex << random() << random();
  std::filesystem::path sibling = target;
  sibling += infix + suffix.str();
  return sibling;
}

}  // namespace

int CsvTable::column_index(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const int index = column_index(name);
  if (index < 0) {
    std::string list;
    for (const std::string& c : columns) list += (list.empty() ? "" : ", ") + c;
    throw InputError("CSV has no column '" + name + "' (its columns are: " + list + ")");
  }
  std::vector<double> values;
  values.reserve(rows.size());
  for (const std::vector<double>& row : rows) {
    values.push_back(row[static_cast<std::size_t>(index)]);
  }
  return values;
}

CsvTable read_csv(const std::string& path) {
  const std::string text = read_whole_file(path);
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);

  CsvTable table;
  bool have_header = false;
  int line_number = 0;
  std::vector<std::string_view> fields;
  while (!rest.empty()) {
    const std::size_t newline = rest.find('\n');
    const std::string_view raw = rest.substr(0, newline);
    rest.remove_prefix(newline == std::string_view::npos ? rest.size() : newline + 1);
    ++line_number;

    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (have_header) continue;  // comment between rows
      const std::string_view body = line.substr(1);
      const std::size_t colon = body.find(':');
      const std::string_view key = trim(body.substr(0, colon));
      const std::string_view value =
          colon == std::string_view::npos ? std::string_view() : trim(body.substr(colon + 1));
      if (!key.empty()) table.metadata[std::string(key)] = std::string(value);
      continue;
    }

    split_fields(line, fields);
    if (!have_header) {
      bool all_numbers = true;
      std::set<std::string> seen;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        std::string_view name = fields[i];
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
          name = trim(name.substr(1, name.size() - 2));
        }
        double unused = 0.0;
        if (parse_number(name, unused) != NumberParse::kOk) all_numbers = false;
        if (name.empty()) {
          throw InputError(located_message(path, line_label(line_number),
                                           "header column " + std::to_string(i + 1) +
                                               " has no name (expected names such as "
                                               "time_s,key_angle_deg)"));
        }
        if (!seen.insert(std::string(name)).second) {
          throw InputError(
              located_message(path, line_label(line_number),
                              "header column '" + std::string(name) + "' appears more than once"));
        }
        table.columns.emplace_back(name);
      }
      // one header field holding several names: a file separated by semicolons or tabs (a
      // spreadsheet's export in a decimal-comma locale), read here as one column
      if (table.columns.size() == 1) {
        for (const char separator : {';', '\t'}) {
          if (table.columns.front().find(separator) == std::string::npos) continue;
          throw InputError(located_message(
              path, line_label(line_number),
              separator == ';' ? "the columns are separated by semicolons; expected commas "
                                 "(time_s,key_angle_deg) and a decimal point"
                               : "the columns are separated by tabs; expected commas "
                                 "(time_s,key_angle_deg)"));
        }
      }
      if (all_numbers) {
        throw InputError(located_message(path, line_label(line_number),
                                         "expected a header row of column names (such as "
                                         "time_s,key_angle_deg), got numbers"));
      }
      have_header = true;
      continue;
    }

    if (fields.size() != table.columns.size()) {
      throw InputError(located_message(path, line_label(line_number),
                                       "expected " + std::to_string(table.columns.size()) +
                                           " values, got " + std::to_string(fields.size())));
    }
    table.row_lines.push_back(line_number);
    std::vector<double>& row = table.rows.emplace_back(fields.size());
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const NumberParse result = parse_number(fields[i], row[i]);
      if (result == NumberParse::kOk) continue;
      const std::string& column = table.columns[i];
      std::string problem;
      if (fields[i].empty()) {
        problem = "column " + column + " is empty (expected a number)";
      } else {
        // appended piece by piece: GCC 12 warns falsely (-Wrestrict, its bug 105651) about
        // "'" + std::string(...)
        problem = "'";
        problem.append(fields[i]);
        problem += "' in column " + column;
        problem +=
            result == NumberParse::kNotFinite ? " is not a finite number" : " is not a number";
      }
      throw InputError(located_message(path, line_label(line_number), problem));
    }
  }
  if (!have_header) {
    throw InputError(located_message(path, line_label(line_number + 1),
                                     "no header row (expected column names such as "
                                     "time_s,key_angle_deg)"));
  }
  return table;
}

std::string format_csv(const CsvTable& table) {
  if (table.columns.empty()) throw InputError("CSV to write has no columns");
  std::string out;
  for (const auto& [key, value] : table.metadata) {
    if (key.empty() || key.find(':') != std::string::npos || has_line_break(key) ||
        key.front() == ' ' || key.back() == ' ') {
      throw InputError(
          "CSV metadata key '" + key +
          "' must not be empty, start or end with a space, or contain ':' or a line break");
    }
    if (has_line_break(value)) {
      throw InputError("CSV metadata '" + key + "': the value must not contain a line break");
    }
    out += "# " + key;
    if (!value.empty()) out += ": " + value;
    out += '\n';
  }
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    const std::string& name = table.columns[i];
    if (name.empty() || name.find(',') != std::string::npos || has_line_break(name)) {
      throw InputError("CSV column name '" + name +
                       "' must be non-empty and contain no comma or line break");
    }
    if (i > 0) out += ',';
    out += name;
  }
  out += '\n';
  out.reserve(out.size() + table.rows.size() * table.columns.size() * 12);
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<double>& row = table.rows[r];
    if (row.size() != table.columns.size()) {
      throw InputError("CSV row " + std::to_string(r + 1) + " has " + std::to_string(row.size()) +
                       " values, expected " + std::to_string(table.columns.size()) +
                       " (one per column)");
    }
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0) out += ',';
      append_number(out, row[i]);
    }
    out += '\n';
  }
  return out;
}

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("cannot write a file with an empty name");
  const fs::path target(path);
  const fs::path folder = target.parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::is_directory(folder, ec)) {
    throw InputError(located_message(
        path, "", "cannot write the file: the folder '" + folder.string() + "' does not exist"));
  }
  if (fs::is_directory(target, ec)) {
    throw InputError(located_message(path, "", "cannot write the file: it is a folder"));
  }
  // what is there is replaced (through a rename): never a device, pipe or socket (/dev/null
  // would be replaced by a plain file), nor a file its owner made read-only
  const fs::file_status existing = fs::status(target, ec);  // a link's target
  if (fs::exists(existing)) {
    if (!fs::is_regular_file(existing))
      throw InputError(located_message(
          path, "", "cannot write the file: it is not a plain file (a device, pipe or socket)"));
    constexpr fs::perms kWritable =
        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    if ((existing.permissions() & kWritable) == fs::perms::none)
      throw InputError(located_message(path, "", "cannot write the file: it is read-only"));
  }
  // the folder must take a new file (the temporary the file is written through): tried now, so
  // that a command finds out before its work and before it writes its other outputs
  const fs::path probe = unique_sibling(target, ".probe-");
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError(located_message(
          path, "",
          "cannot write the file: the folder '" + (folder.empty() ? "." : folder.string()) +
              "' takes no new file (no permission, or a read-only disk)"));
  }
  fs::remove(probe, ec);
}

void write_csv(const std::string& path, const CsvTable& table) {
  write_file_replacing(path, format_csv(table));
}

std::string csv_quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';  // a quote is doubled
    quoted += c;
  }
  return quoted + "\"";
}

void write_file_replacing(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  check_output_path(path);
  std::error_code ec;
  // a link is followed: the file it points to is replaced, the link stays
  fs::path target(path);
  if (fs::is_symlink(target, ec)) {
    target = fs::canonical(target, ec);
    if (ec) throw InputError(located_message(path, "", "cannot follow the link: " + ec.message()));
  }
  ec.clear();

  // A unique temporary name next to the target, so the rename stays on one file system.
  const fs::path temporary = unique_sibling(target, ".tmp-");

  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError(
          located_message(path, "", "cannot write the file (no permission, or the disk is full?)"));
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      fs::remove(temporary, ec);
      throw InputError(located_message(path, "", "error while writing the file (disk full?)"));
    }
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw InputError(located_message(path, "", "cannot replace the file: " + ec.message()));
  }
}

}  // namespace pat

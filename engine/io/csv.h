// CSV traces (DESIGN.md section 5): optional '#' metadata lines ("# key: value"), one header
// row whose column names carry their units (time_s, key_angle_deg, ...), then numeric rows.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pat {

struct CsvTable {
  std::map<std::string, std::string> metadata;  ///< from "# key: value" lines, key trimmed
  std::vector<std::string> columns;             ///< header names, trimmed
  std::vector<std::vector<double>> rows;        ///< every row has columns.size() values
  std::vector<int> row_lines;  ///< the file line of each row (read_csv); empty when built in memory

  /// Index of a column, or -1.
  int column_index(const std::string& name) const;
  /// The values of one column. Throws InputError if the column is missing.
  std::vector<double> column(const std::string& name) const;
};

/// Reads a CSV file. Separators: commas (spaces around values are ignored). Blank lines are
/// skipped. Throws InputError naming the file and the line number for: a missing file, no header,
/// a row with the wrong number of fields, a value that is not a finite number (NaN, inf, text).
/// Messages name the file by `path` as given.
CsvTable read_csv(const std::string& path);

/// Writes metadata lines, the header and the rows (numbers in the shortest round-trip form,
/// locale-independent). Writes to a temporary file in the same folder and renames it over
/// `path`, so an existing file is never left half-written. Throws InputError if the file cannot
/// be written.
/// Throws InputError (naming the path) unless a file could be written there: a non-empty path
/// whose folder exists and that is not itself a folder. Commands call it before their work.
void check_output_path(const std::string& path);
void write_csv(const std::string& path, const CsvTable& table);

/// The same text as write_csv would write, as a string.
std::string format_csv(const CsvTable& table);

/// A text field for a CSV file: as it is, or in double quotes (quotes doubled) when it holds a
/// comma, a quote or a line break.
std::string csv_quoted(const std::string& text);

/// Writes `text` to `path` through a temporary file (a unique name beside it) renamed over it
/// once whole: an existing file is replaced only by a complete one, and no temporary is left
/// behind. Checks the path first (check_output_path). Throws InputError naming the path. write_csv
/// writes through it.
void write_file_replacing(const std::string& path, const std::string& text);

}  // namespace pat

// Raw sensor traces (the uncalibrated hammer-shank recordings of shared/data/kawai-kg3c): one
// sample per line, one or more columns separated by commas or white space, no header. Lines that
// are blank or start with '#' are skipped.
//
// A column holds either normalized ADC readings in [0, 1] or whole ADC counts (the 24-bit files:
// counts out of 2^24). Counts are converted to normalized readings, reading = count / 2^bits, so
// that everything downstream (calibration offsets and gains, rest and peak levels) works in one
// unit: the fraction of the ADC's full scale.
#pragma once

#include <string>
#include <vector>

namespace pat {

struct RawTrace {
  std::string path;
  int column = 1;               ///< counted from 1
  std::vector<double> reading;  ///< normalized reading (fraction of the ADC's full scale)
  std::vector<int> line;        ///< the file line (from 1) of each sample, for messages
  bool counts = false;          ///< the file held whole counts (converted with 2^bits)
  int bits = 24;                ///< ADC resolution used for counts
};

/// Reads column `column` (from 1) of a raw trace. Values all in [0, 1] are taken as normalized
/// readings; otherwise every value must be a whole, non-negative count below 2^bits, converted
/// to count / 2^bits. Throws InputError naming the file and the problem: missing file, a line
/// with fewer columns than `column` (with its line number), a value that is not a finite number
/// (line number and text), values that are neither readings nor counts, column < 1, bits outside
/// 1..32, an empty file.
RawTrace read_raw_trace(const std::string& path, int column, int bits = 24);

}  // namespace pat

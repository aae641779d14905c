// Numbers in messages and metadata, as a person reads them.
#pragma once

#include <string>

namespace pat {

/// `value` with `precision` significant digits ("0.0998", "45", "1.5e-06").
std::string format_number(double value, int precision = 3);

/// `value` with `decimals` digits after the point ("1.50", "-0.004"); a value that rounds to zero
/// is written without a minus sign ("0.00", not "-0.00").
std::string format_fixed(double value, int decimals = 2);

}  // namespace pat

// Numbers in messages and metadata, as a person reads them.
#pragma once

#include <string>

namespace pat {

/// `value` with `precision` significant digits ("0.0998", "45", "1.5e-06").
std::string format_number(double value, int precision = 3);

}  // namespace pat

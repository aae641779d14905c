#include "core/format.h"

#include <sstream>

namespace pat {

std::string format_number(double value, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

}  // namespace pat

#include "core/error.h"

namespace pat {

std::string located_message(const std::string& source, const std::string& location,
                            const std::string& problem) {
  std::string message;
  if (!source.empty()) message += source + ": ";
  if (!location.empty()) message += location + ": ";
  return message + problem;
}

}  // namespace pat

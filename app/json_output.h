// Small helpers for the subcommands' --json output.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace pat::app {

/// x, or null where it is not a finite number (a quantity that does not exist for this run).
inline nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

/// text, or null where it is empty (no message).
inline nlohmann::json text_or_null(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
}

}  // namespace pat::app

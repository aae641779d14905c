// Reads and writes action presets: schema-versioned JSON with units in the key names
// (DESIGN.md section 1). Every object carries a "source" (one string for all its values, or an
// object mapping value names to sources, "*" for the rest): a publication or "estimate".
#pragma once

#include <exception>
#include <string>

#include "model/action_model.h"

namespace pat {

inline constexpr int kPresetSchema = 1;

/// Loads a preset file. `name_or_path` is "grand", "upright" (the shipped presets, searched in
/// the preset directory) or a path. Throws InputError naming the file, the field (JSON path such
/// as bodies[2].mass_g) and the problem.
ActionModel load_action(const std::string& name_or_path);

/// A JSON library error's text without its id ("[json.exception.parse_error.101] parse error at
/// line 1, …" → "parse error at line 1, …"), for messages that name the file themselves.
std::string json_error_without_id(const std::exception& e);

/// Parses preset text; `source_name` names it in messages.
ActionModel parse_action(const std::string& json_text, const std::string& source_name);

/// Directory of the shipped presets (PAT_PRESET_DIR environment variable, else the build-time
/// location).
std::string preset_directory();

}  // namespace pat

// A key input SPEC (DESIGN.md section 5) told in words for the status line, the run's record and
// the analyses' choices: "force:pulse:20:40" → "a 20 N blow held 40 ms". What a teacher reads to
// a class; the SPEC itself stays in what can be run again (the exports' metadata keeps both).
#pragma once

#include <QString>
#include <string>

namespace pat::ui {

/// The SPEC in words; "" is no finger on the key. A SPEC not understood is returned as it is
/// (the run reports what is wrong with it).
QString input_in_words(const std::string& spec);

}  // namespace pat::ui

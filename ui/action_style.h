// Colours and pens of the action drawing, chosen to read well on a classroom projector: light
// background, saturated fills with dark outlines, thick lines.
#pragma once

#include <QColor>
#include <string>

namespace pat::ui {

/// Fill colour of a body, by its name (key, whippen, jack, lever, hammer, damper...).
QColor body_colour(const std::string& name);
/// Fill colour of a fixture (rails, buttons, string).
QColor fixture_colour(const std::string& name);
/// Colour of contact highlights and force arrows.
QColor contact_colour();

}  // namespace pat::ui

#include "action_style.h"

namespace pat::ui {

QColor body_colour(const std::string& name) {
  if (name == "key") return QColor(222, 184, 135);      // wood
  if (name == "whippen") return QColor(100, 149, 237);  // blue
  if (name == "jack") return QColor(255, 165, 0);       // orange
  if (name == "lever") return QColor(60, 179, 113);     // green
  if (name == "hammer") return QColor(178, 34, 34);     // felt red
  if (name == "damper") return QColor(147, 112, 219);   // violet
  return QColor(160, 160, 160);
}

QColor fixture_colour(const std::string& name) {
  if (name == "string") return QColor(40, 40, 40);
  if (name.find("button") != std::string::npos || name.find("screw") != std::string::npos)
    return QColor(70, 70, 90);
  return QColor(150, 150, 150);
}

QColor contact_colour() {
  return QColor(220, 0, 120);
}

}  // namespace pat::ui

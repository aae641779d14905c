#include "plot_styles.h"

namespace pat::ui {

QColor series_colour(int i) {
  // Okabe–Ito palette, then darker variants
  static const QColor colours[] = {QColor(0, 114, 178),   QColor(213, 94, 0),  QColor(0, 158, 115),
                                   QColor(204, 121, 167), QColor(230, 159, 0), QColor(86, 180, 233),
                                   QColor(0, 0, 0),       QColor(240, 228, 66)};
  const int n = sizeof(colours) / sizeof(colours[0]);
  return i < n ? colours[i] : colours[i % n].darker(150);
}

}  // namespace pat::ui
